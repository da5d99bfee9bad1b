struct Spot {
    vec3 position;      // eye space
    vec3 direction;     // eye space, normalised
    vec3 color;
    float cos_cutoff;
    float exponent;
    vec3 attenuation;   // constant, linear, quadratic
};

const int kSpots = 3;
uniform Spot spots[kSpots];

varying vec3 normal;
varying vec3 position;

// Adds one spot's diffuse and specular terms; returns whether it lit the point.
bool add_spot(in Spot s, vec3 n, vec3 v, inout vec3 diffuse, inout vec3 specular) {
    vec3 l = s.position - position;
    float d = length(l);
    l /= d;
    float spot = dot(-l, s.direction);
    if (spot < s.cos_cutoff) return false;
    float falloff = pow(spot, s.exponent) / (s.attenuation.x + s.attenuation.y * d + s.attenuation.z * d * d);
    float ndotl = max(dot(n, l), 0.0);
    diffuse += s.color * ndotl * falloff;
    if (ndotl > 0.0) {
        vec3 h = normalize(l + v);
        specular += s.color * pow(max(dot(n, h), 0.0), gl_FrontMaterial.shininess) * falloff;
    }
    return true;
}

void main() {
    vec3 n = normalize(normal);
    vec3 v = normalize(-position);
    vec3 diffuse = vec3(0.0), specular = vec3(0.0);
    int lit = 0;
    for (int i = 0; i < kSpots; ++i)
        if (add_spot(spots[i], n, v, diffuse, specular)) ++lit;
    vec3 color = gl_FrontLightModelProduct.sceneColor.rgb
               + gl_FrontMaterial.diffuse.rgb * diffuse + gl_FrontMaterial.specular.rgb * specular;
    // Where no light reaches, a faint blue so the cones' edges show.
    if (lit == 0) color += vec3(0.0, 0.0, 0.05);
    gl_FragColor = vec4(color, gl_FrontMaterial.diffuse.a);
}
