// dir_pix.frag with the texel modulating the lit colour, as GL_MODULATE
// does, and the specular highlight added after the texture (the effect of
// GL_SEPARATE_SPECULAR_COLOR), so highlights stay white on dark texels.
uniform sampler2D tex;
varying vec3 normal, lightDir, ecPos;

void main()
{
    vec4 diffuse, ambient, specular, color, texel;
    float intensity, shininess;
    vec3 n, hv, ec;

    n = normalize(normal);
    intensity = max(dot(lightDir, n), 0.0);

    diffuse = gl_LightSource[0].diffuse * gl_FrontMaterial.diffuse;
    ambient = gl_LightSource[0].ambient * gl_FrontMaterial.ambient;

    color = ambient + diffuse*intensity;
    color += gl_FrontMaterial.ambient * gl_LightModel.ambient;
    color += gl_FrontMaterial.emission;

    texel = texture2D(tex, gl_TexCoord[0].st);
    color *= texel;

    if (intensity > 0.0) {
        ec = normalize(-ecPos);
        hv = normalize(ec+lightDir);
        shininess = pow(max(dot(hv,n),0.0),gl_FrontMaterial.shininess);
        specular = shininess * gl_LightSource[0].specular * gl_FrontMaterial.specular;
        color += specular;
    }

    gl_FragColor = color;
}
