// A fragment-shader ray tracer in the style of the GL 2.0 era's demos:
// structs, `inout` struct parameters, function calls, a bounce loop. It
// exists to measure the JIT's compile cost (docs/limits.md): written out in
// place, its calls made its code many times its source; trace() and shade()
// are now compiled once each.
#version 120
struct Ray { vec3 origin; vec3 dir; };
struct Hit { float t; vec3 normal; vec3 color; float reflect; bool found; };
struct Sphere { vec3 center; float radius; vec3 color; float reflect; };
struct Light { vec3 pos; vec3 color; };

uniform vec2 resolution;
uniform float time;
varying vec2 uv;

Sphere sphere(int i) {
    if (i == 0) return Sphere(vec3(0.0, 0.0, -3.0), 1.0, vec3(0.9, 0.2, 0.2), 0.3);
    if (i == 1) return Sphere(vec3(1.8, -0.3, -3.5), 0.7, vec3(0.2, 0.9, 0.3), 0.5);
    if (i == 2) return Sphere(vec3(-1.7, -0.2, -2.8), 0.8, vec3(0.2, 0.3, 0.9), 0.1);
    return Sphere(vec3(0.0, -101.0, -3.0), 100.0, vec3(0.8, 0.8, 0.7), 0.2);
}

void intersect_sphere(in Ray r, in Sphere s, inout Hit h) {
    vec3 oc = r.origin - s.center;
    float b = dot(oc, r.dir);
    float c = dot(oc, oc) - s.radius * s.radius;
    float disc = b * b - c;
    if (disc < 0.0) return;
    float t = -b - sqrt(disc);
    if (t > 0.001 && (!h.found || t < h.t)) {
        h.t = t;
        h.normal = normalize(r.origin + t * r.dir - s.center);
        h.color = s.color;
        h.reflect = s.reflect;
        h.found = true;
    }
}

void trace(in Ray r, inout Hit h) {
    h.found = false;
    h.t = 1e30;
    intersect_sphere(r, sphere(0), h);
    intersect_sphere(r, sphere(1), h);
    intersect_sphere(r, sphere(2), h);
    intersect_sphere(r, sphere(3), h);
}

float shadow(vec3 p, vec3 to_light) {
    Ray r = Ray(p, normalize(to_light));
    Hit h;
    trace(r, h);
    return h.found && h.t < length(to_light) ? 0.3 : 1.0;
}

vec3 shade(in Ray r, in Hit h, in Light l) {
    vec3 p = r.origin + h.t * r.dir;
    vec3 to_light = l.pos - p;
    vec3 ld = normalize(to_light);
    float diff = max(dot(h.normal, ld), 0.0);
    vec3 hv = normalize(ld - r.dir);
    float spec = pow(max(dot(h.normal, hv), 0.0), 32.0);
    return shadow(p, to_light) * (h.color * diff + vec3(spec)) * l.color;
}

void bounce(inout Ray r, in Hit h) {
    vec3 p = r.origin + h.t * r.dir;
    r.dir = reflect(r.dir, h.normal);
    r.origin = p + 0.001 * h.normal;
}

void main() {
    vec2 p = (uv * 2.0 - 1.0) * vec2(resolution.x / resolution.y, 1.0);
    Ray r = Ray(vec3(0.0, 0.3, 1.0), normalize(vec3(p, -1.5)));
    Light l1 = Light(vec3(3.0 * cos(time), 4.0, 0.0), vec3(1.0, 0.95, 0.9));
    Light l2 = Light(vec3(-3.0, 2.0, 1.0), vec3(0.3, 0.3, 0.4));
    vec3 color = vec3(0.0);
    float weight = 1.0;
    for (int i = 0; i < 3; ++i) {
        Hit h;
        trace(r, h);
        if (!h.found) {
            color += weight * mix(vec3(0.6, 0.7, 0.9), vec3(0.1, 0.2, 0.5), r.dir.y);
            break;
        }
        color += weight * (1.0 - h.reflect) * (shade(r, h, l1) + shade(r, h, l2) + 0.05 * h.color);
        weight *= h.reflect;
        bounce(r, h);
    }
    gl_FragColor = vec4(color, 1.0);
}
