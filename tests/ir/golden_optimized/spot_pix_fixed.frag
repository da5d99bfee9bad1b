// The lecture's fix for the "Ooops": the light's ambient only where N.L > 0
// inside the cone. `spotAtt != 0` is corrected to `spotAtt != 0.0`.
varying vec3 normal, ecPos;

void main()
{
    vec4 diffuse, ambient, specular, color;
    float intensity, shininess, d, att, spotAtt, spotDot;
    vec3 n, hv, ec, lightDir;

    lightDir = vec3(gl_LightSource[0].position) - ecPos;
    n = normalize(normal);

    d = length(lightDir);
    att = max(1.0, 1.0 / (gl_LightSource[0].constantAttenuation +
        gl_LightSource[0].linearAttenuation * d +
        gl_LightSource[0].quadraticAttenuation * d * d));

    lightDir = normalize(lightDir);
    spotDot = max(0.0, dot(-lightDir, gl_LightSource[0].spotDirection));
    if (spotDot < gl_LightSource[0].spotCosCutoff)
        spotAtt = 0.0;
    else
        spotAtt = pow(spotDot, gl_LightSource[0].spotExponent);

    att *= spotAtt;

    diffuse = gl_LightSource[0].diffuse * gl_FrontMaterial.diffuse;
    ambient = gl_LightSource[0].ambient * gl_FrontMaterial.ambient;

    intensity = max(dot(lightDir,n),0.0);
    color = (diffuse*intensity)*att;
    if ((intensity > 0.0) && (spotAtt != 0.0))
        color += ambient;
    color += gl_FrontMaterial.ambient * gl_LightModel.ambient;
    color += gl_FrontMaterial.emission;
    if (intensity > 0.0) {
        ec = normalize(-ecPos);
        hv = normalize(ec+lightDir);
        shininess = pow(max(dot(hv,n),0.0),gl_FrontMaterial.shininess);
        specular = shininess * gl_LightSource[0].specular * gl_FrontMaterial.specular;
        color += specular * att;
    }

    gl_FragColor = color;
}
