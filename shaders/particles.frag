#version 120
// A soft disc from gl_PointCoord, or, where the pass sets `textured`, the
// spark texture through the sprite's own gl_TexCoord[0] (GL_COORD_REPLACE).
// Colours are premultiplied by alpha, as particle systems blend them.
uniform bool textured;
uniform sampler2D spark;

void main() {
    if (textured) {
        vec4 c = gl_Color * texture2D(spark, gl_TexCoord[0].st);
        gl_FragColor = vec4(c.rgb * c.a, c.a);
        return;
    }
    vec2 p = gl_PointCoord * 2.0 - 1.0;
    float r2 = dot(p, p);
    if (r2 > 1.0) discard;
    float soft = (1.0 - r2) * (1.0 - r2);
    float a = gl_Color.a * soft;
    gl_FragColor = vec4(gl_Color.rgb * a, a);
}
