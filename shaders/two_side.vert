// Two-sided lighting per vertex (GL_VERTEX_PROGRAM_TWO_SIDE): the front colour
// lights the front material with the normal, the back colour the back material
// with the reversed normal; GL picks one per primitive by its facing.
vec4 lit(vec3 n, vec3 l, gl_MaterialParameters m) {
    float intensity = max(dot(l, n), 0.0);
    vec4 color = m.emission + m.ambient * gl_LightModel.ambient
               + gl_LightSource[0].ambient * m.ambient
               + gl_LightSource[0].diffuse * m.diffuse * intensity;
    if (intensity > 0.0) {
        float s = max(dot(vec3(gl_LightSource[0].halfVector), n), 0.0);
        color += gl_LightSource[0].specular * m.specular * pow(s, m.shininess);
    }
    return color;
}

void main()
{
    vec3 n = normalize(gl_NormalMatrix * gl_Normal);
    vec3 l = normalize(vec3(gl_LightSource[0].position));
    gl_FrontColor = lit(n, l, gl_FrontMaterial);
    gl_BackColor = lit(-n, l, gl_BackMaterial);
    gl_Position = ftransform();
}
