// ARB_texture_rectangle (on without #extension): unnormalized lookups, the
// projective forms divide by the last component, the shadow forms take r.
uniform sampler2DRect image;
uniform sampler2DRectShadow depth;

void main() {
    vec4 p = gl_TexCoord[0];
    gl_FragColor = texture2DRect(image, p.xy) + texture2DRectProj(image, p.xyz)
                 + shadow2DRectProj(depth, p);
}
