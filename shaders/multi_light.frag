// GL's lighting equation per pixel for lights 0..2 (directional, positional
// and spot alike), from the derived built-in state: light products, scene
// colour, attenuation and the spot cone.
varying vec3 normal, ecPos;

const int kLights = 3;

vec4 light(int i, vec3 n, vec3 v) {
    vec4 p = gl_LightSource[i].position;
    vec3 l = p.w == 0.0 ? vec3(p) : vec3(p) - ecPos;
    float d = length(l);
    l = normalize(l);
    float att = p.w == 0.0 ? 1.0 : 1.0 / (gl_LightSource[i].constantAttenuation +
                                          gl_LightSource[i].linearAttenuation * d +
                                          gl_LightSource[i].quadraticAttenuation * d * d);
    if (gl_LightSource[i].spotCutoff != 180.0) {
        float spot = dot(-l, normalize(gl_LightSource[i].spotDirection));
        att *= spot < gl_LightSource[i].spotCosCutoff ? 0.0 : pow(spot, gl_LightSource[i].spotExponent);
    }
    float nl = max(dot(n, l), 0.0);
    vec4 color = gl_FrontLightProduct[i].ambient + gl_FrontLightProduct[i].diffuse * nl;
    if (nl > 0.0)
        color += gl_FrontLightProduct[i].specular *
                 pow(max(dot(n, normalize(l + v)), 0.0), gl_FrontMaterial.shininess);
    return color * att;
}

void main()
{
    vec3 n = normalize(normal);
    vec3 v = normalize(-ecPos);
    vec4 color = gl_FrontLightModelProduct.sceneColor;
    for (int i = 0; i < kLights; ++i)
        color += light(i, n, v);
    gl_FragColor = color;
}
