#version 120
// A small ray tracer: three spheres and a checkered plane, one directional
// light with shadow rays, and two reflection bounces. Structs for rays, hits
// and spheres, a loop over a uniform array of spheres, and the closest hit
// kept in an inout struct parameter.
struct Ray { vec3 origin; vec3 direction; };
struct Sphere { vec3 center; float radius; vec3 color; float reflectivity; };
struct Hit { float t; vec3 position; vec3 normal; vec3 color; float reflectivity; };

const int SPHERES = 3;
const float FAR = 1.0e4;
uniform Sphere spheres[SPHERES];
uniform vec3 camera_position;
uniform vec3 light_direction;   // toward the light, normalized
uniform float aspect;
varying vec2 screen;

void intersect_sphere(Ray ray, Sphere s, inout Hit hit) {
    vec3 oc = ray.origin - s.center;
    float b = dot(oc, ray.direction);
    float c = dot(oc, oc) - s.radius * s.radius;
    float disc = b * b - c;
    if (disc < 0.0) return;
    float t = -b - sqrt(disc);
    if (t > 0.001 && t < hit.t) {
        hit.t = t;
        hit.position = ray.origin + t * ray.direction;
        hit.normal = normalize(hit.position - s.center);
        hit.color = s.color;
        hit.reflectivity = s.reflectivity;
    }
}

void intersect_plane(Ray ray, inout Hit hit) {
    if (ray.direction.y >= -0.0001) return;
    float t = (-1.0 - ray.origin.y) / ray.direction.y;
    if (t > 0.001 && t < hit.t) {
        hit.t = t;
        hit.position = ray.origin + t * ray.direction;
        hit.normal = vec3(0.0, 1.0, 0.0);
        vec2 cell = floor(hit.position.xz * 0.5);
        float checker = mod(cell.x + cell.y, 2.0);
        hit.color = mix(vec3(0.85), vec3(0.25, 0.3, 0.35), checker);
        hit.reflectivity = 0.2;
    }
}

Hit trace(Ray ray) {
    Hit hit = Hit(FAR, vec3(0.0), vec3(0.0), vec3(0.0), 0.0);
    for (int i = 0; i < SPHERES; ++i)
        intersect_sphere(ray, spheres[i], hit);
    intersect_plane(ray, hit);
    return hit;
}

vec3 sky(vec3 direction) {
    return mix(vec3(0.9, 0.9, 1.0), vec3(0.3, 0.5, 0.9), clamp(direction.y * 1.5, 0.0, 1.0));
}

vec3 shade(Hit hit, vec3 view) {
    Hit blocker = trace(Ray(hit.position + hit.normal * 0.002, light_direction));
    float lit = blocker.t < FAR ? 0.0 : 1.0;
    float diffuse = max(dot(hit.normal, light_direction), 0.0) * lit;
    vec3 h = normalize(light_direction - view);
    float specular = lit * pow(max(dot(hit.normal, h), 0.0), 40.0);
    return hit.color * (0.15 + 0.85 * diffuse) + vec3(specular * 0.6);
}

void main() {
    Ray ray = Ray(camera_position, normalize(vec3(screen.x * aspect, screen.y, -2.0)));
    vec3 color = vec3(0.0);
    float weight = 1.0;
    for (int bounce = 0; bounce < 3; ++bounce) {
        Hit hit = trace(ray);
        if (hit.t >= FAR) {
            color += weight * sky(ray.direction);
            break;
        }
        color += weight * (1.0 - hit.reflectivity) * shade(hit, ray.direction);
        weight *= hit.reflectivity;
        if (weight < 0.01) break;
        ray = Ray(hit.position + hit.normal * 0.002, reflect(ray.direction, hit.normal));
    }
    gl_FragColor = vec4(color, 1.0);
}
