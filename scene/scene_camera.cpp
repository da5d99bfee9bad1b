// The camera and transforms: GLU's gluLookAt/gluPerspective and GL's
// glOrtho/glFrustum/glRotate/glTranslate/glScale, as their specifications
// define them. Everything is computed in double and rounded to float once,
// so the matrices agree with Mesa's GLU + GL to float rounding.
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "scene/scene_reader.h"
#include "scene/trig.h"

namespace glslrun::scene {

namespace detail {

glm::dmat4 gl_look_at(glm::dvec3 eye, glm::dvec3 center, glm::dvec3 up) {
    // gluLookAt: rows side, up', -forward, then glTranslate(-eye).
    glm::dvec3 f = glm::normalize(center - eye);
    glm::dvec3 s = glm::normalize(glm::cross(f, up));
    glm::dvec3 u = glm::cross(s, f);
    glm::dmat4 m(1.0);
    for (int c = 0; c < 3; ++c) {
        m[c][0] = s[c];
        m[c][1] = u[c];
        m[c][2] = -f[c];
    }
    m[3] = m * glm::dvec4(-eye, 1.0);
    return m;
}

glm::dmat4 gl_perspective(double fovy, double aspect, double near, double far) {
    double half = fovy / 2 * std::numbers::pi / 180;
    const auto [sin, cos] = sin_cos(half);
    double cot = cos / sin;
    glm::dmat4 m(0.0);
    m[0][0] = cot / aspect;
    m[1][1] = cot;
    m[2][2] = -(far + near) / (far - near);
    m[2][3] = -1;
    m[3][2] = -2 * near * far / (far - near);
    return m;
}

glm::dmat4 gl_ortho(double l, double r, double b, double t, double n, double f) {
    glm::dmat4 m(1.0);
    m[0][0] = 2 / (r - l);
    m[1][1] = 2 / (t - b);
    m[2][2] = -2 / (f - n);
    m[3] = glm::dvec4(-(r + l) / (r - l), -(t + b) / (t - b), -(f + n) / (f - n), 1);
    return m;
}

glm::dmat4 gl_frustum(double l, double r, double b, double t, double n, double f) {
    glm::dmat4 m(0.0);
    m[0][0] = 2 * n / (r - l);
    m[1][1] = 2 * n / (t - b);
    m[2] = glm::dvec4((r + l) / (r - l), (t + b) / (t - b), -(f + n) / (f - n), -1);
    m[3][2] = -2 * f * n / (f - n);
    return m;
}

namespace {

// sin and cos of an angle in degrees, exact at multiples of 90 degrees, so
// { rotate = [90, 0, 0, 1] } gives exact zeros where the math has them.
std::pair<double, double> sin_cos_degrees(double degrees) {
    double d = std::fmod(degrees, 360.0);
    if (d < 0) d += 360.0;
    if (d == 0) return {0, 1};
    if (d == 90) return {1, 0};
    if (d == 180) return {0, -1};
    if (d == 270) return {-1, 0};
    double rad = degrees * std::numbers::pi / 180;
    return sin_cos(rad);
}

}  // namespace

glm::dmat4 gl_rotate(double degrees, glm::dvec3 axis) {
    // GL 2.1 §2.11.2: R = u u^T + cos(a) (I - u u^T) + sin(a) S.
    auto [s, c] = sin_cos_degrees(degrees);
    glm::dvec3 u = glm::normalize(axis);
    glm::dmat3 uut = glm::outerProduct(u, u);
    glm::dmat3 skew(0, u.z, -u.y, -u.z, 0, u.x, u.y, -u.x, 0);  // column-major
    glm::dmat3 r = uut + c * (glm::dmat3(1.0) - uut) + s * skew;
    return glm::dmat4(r);
}

glm::dmat4 projection_of(const Camera& cam, int width, int height) {
    switch (cam.kind) {
        case Camera::Kind::Perspective: {
            double aspect = cam.aspect > 0 ? double(cam.aspect) : double(width) / double(height);
            return gl_perspective(cam.fovy, aspect, cam.near, cam.far);
        }
        case Camera::Kind::Ortho:
            return gl_ortho(cam.left, cam.right, cam.bottom, cam.top, cam.near, cam.far);
        case Camera::Kind::Frustum:
            return gl_frustum(cam.left, cam.right, cam.bottom, cam.top, cam.near, cam.far);
        case Camera::Kind::Matrix: break;
    }
    return glm::dmat4(1.0);
}

// ---------------------------------------------------------- transform list ---

namespace {

glm::dmat4 rotate_entry(const toml::node& n, const std::string& what) {
    const toml::array* a = n.as_array();
    if (!a || a->size() != 4)
        fail(n, fmt::format("'{}' must be [angle in degrees, x, y, z] (got {})", what, describe(n)));
    std::vector<double> v = numbers(n, what, 4, 4);
    glm::dvec3 axis(v[1], v[2], v[3]);
    if (axis == glm::dvec3(0.0)) fail(n, fmt::format("'{}': the rotation axis must not be (0, 0, 0)", what));
    return gl_rotate(v[0], axis);
}

// gluLookAt, gluPerspective, glOrtho, glFrustum as entries of a list (they
// multiply the current matrix too); defined with the camera below.
glm::dmat4 camera_entry(const Section& s, std::string_view key);

glm::dmat4 transform_entry(const toml::node& n, const std::string& what) {
    Section s(table(n, what), what);
    s.allow({"translate", "rotate", "scale", "matrix", "look_at", "perspective", "ortho", "frustum", "inverse"});
    if (s.table().size() != 1)
        fail(n, fmt::format("'{}' must have exactly one of translate, rotate, scale, matrix, look_at, perspective, "
                            "ortho, frustum, inverse (got {})", what, s.table().size()));
    for (std::string_view key : {"look_at", "perspective", "ortho", "frustum"})
        if (s.get(key)) return camera_entry(s, key);
    if (auto t = s.get("inverse")) {
        // The inverse of a list, as a program multiplies by the inverse of its camera's matrix.
        glm::dmat4 m = transform_list(*t, s.name("inverse"));
        if (glm::determinant(m) == 0) fail(*t, fmt::format("'{}' is singular: it has no inverse", s.name("inverse")));
        return glm::inverse(m);
    }
    if (auto t = s.get("translate")) {
        std::vector<double> v = numbers(*t, s.name("translate"), 3, 3);
        return glm::dmat4(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, v[0], v[1], v[2], 1);
    }
    if (auto t = s.get("scale")) {
        std::vector<double> v = numbers(*t, s.name("scale"), 3, 3);
        return glm::dmat4(v[0], 0, 0, 0, 0, v[1], 0, 0, 0, 0, v[2], 0, 0, 0, 0, 1);
    }
    if (auto t = s.get("rotate")) return rotate_entry(*t, s.name("rotate"));
    return matrix(*s.get("matrix"), s.name("matrix"));
}

}  // namespace

glm::dmat4 transform_list(const toml::node& n, const std::string& what) {
    // Each entry is one glTranslate/glRotate/glScale/glMultMatrix call; GL
    // post-multiplies, so the first entry listed is applied to vertices last.
    const toml::array& list = array(n, what);
    glm::dmat4 m(1.0);
    for (size_t i = 0; i < list.size(); ++i)
        m = m * transform_entry(list[i], fmt::format("{}[{}]", what, i));
    return m;
}

// ------------------------------------------------------------------ camera ---

namespace {

glm::dvec3 vec3_or(const Section& s, std::string_view key, glm::dvec3 fallback) {
    const toml::node* n = s.get(key);
    if (!n) return fallback;
    std::vector<double> v = numbers(*n, s.name(key), 3, 3);
    return {v[0], v[1], v[2]};
}

glm::dmat4 read_look_at(const toml::node& n, const std::string& what) {
    Section s(table(n, what), what);
    s.allow({"eye", "center", "up"});
    // Defaults make the identity view: at the origin, looking down -z, y up.
    glm::dvec3 eye = vec3_or(s, "eye", {0, 0, 0});
    glm::dvec3 center = vec3_or(s, "center", {0, 0, -1});
    glm::dvec3 up = vec3_or(s, "up", {0, 1, 0});
    if (eye == center) fail(n, fmt::format("'{}': eye and center must differ", what));
    if (glm::length(glm::cross(center - eye, up)) == 0)
        fail(n, fmt::format("'{}': up must not be zero or parallel to the viewing direction", what));
    return gl_look_at(eye, center, up);
}

float required(const Section& s, std::string_view key, std::string_view why, const Range& r = {}) {
    const toml::node& n = s.require(key, why);
    double v = number(n, s.name(key));
    check_range(n, s.name(key), v, r);
    return float(v);
}

void read_perspective(const Section& s, Camera& cam) {
    constexpr std::string_view why = "gluPerspective needs fovy, near and far";
    s.allow({"fovy", "aspect", "near", "far"});
    cam.kind = Camera::Kind::Perspective;
    const Range positive{.lo = 0, .lo_open = true};
    cam.fovy = required(s, "fovy", why,
                        {.lo = 0, .hi = 180, .lo_open = true, .hi_open = true, .why = "degrees"});
    cam.near = required(s, "near", why, positive);
    cam.far = required(s, "far", why, positive);
    s.read("aspect", cam.aspect,
           {.lo = 0, .lo_open = true, .why = "width / height; leave it out to follow the size"});
    if (cam.near == cam.far) fail(s.table(), fmt::format("[{}]: near and far must differ", s.path()));
}

void read_box(const Section& s, Camera& cam, Camera::Kind kind) {
    bool frustum = kind == Camera::Kind::Frustum;
    std::string_view why = frustum ? "glFrustum needs left, right, bottom, top, near and far"
                                   : "glOrtho needs left, right, bottom, top, near and far";
    s.allow({"left", "right", "bottom", "top", "near", "far"});
    cam.kind = kind;
    cam.left = required(s, "left", why);
    cam.right = required(s, "right", why);
    cam.bottom = required(s, "bottom", why);
    cam.top = required(s, "top", why);
    Range depth = frustum ? Range{.lo = 0, .lo_open = true, .why = "glFrustum"} : Range{};
    cam.near = required(s, "near", why, depth);
    cam.far = required(s, "far", why, depth);
    auto differ = [&](float a, float b, const char* names) {
        if (a == b) fail(s.table(), fmt::format("[{}]: {} must differ (GL_INVALID_VALUE)", s.path(), names));
    };
    differ(cam.left, cam.right, "left and right");
    differ(cam.bottom, cam.top, "bottom and top");
    differ(cam.near, cam.far, "near and far");
}

glm::dmat4 camera_entry(const Section& s, std::string_view key) {
    const toml::node& n = *s.get(key);
    std::string what = s.name(key);
    if (key == "look_at") return read_look_at(n, what);
    Section sub(table(n, what), what);
    Camera cam;
    if (key == "perspective") {
        read_perspective(sub, cam);
        if (cam.aspect == 0) fail(n, fmt::format("'{}' needs its aspect (width / height) in a transform list", what));
    } else {
        read_box(sub, cam, key == "ortho" ? Camera::Kind::Ortho : Camera::Kind::Frustum);
    }
    return projection_of(cam, 1, 1);
}

// Exactly one of `keys` may be present; returns it, or "" for none.
std::string_view one_of(const Section& s, const std::vector<std::string_view>& keys) {
    std::string_view found;
    for (std::string_view k : keys) {
        if (!s.get(k)) continue;
        if (!found.empty())
            fail(*s.get(k), fmt::format("[{}] has both '{}' and '{}'; give only one", s.path(), found, k));
        found = k;
    }
    return found;
}

void read_projection(const Section& s, Camera& cam, glm::mat4& projection, int width, int height) {
    std::string_view kind = one_of(s, {"perspective", "ortho", "frustum", "projection_matrix"});
    if (kind.empty()) return;
    const toml::node& n = *s.get(kind);
    std::string what = s.name(kind);
    if (kind == "projection_matrix") {
        projection = glm::mat4(matrix(n, what));
        return;
    }
    Section sub(table(n, what), what);
    if (kind == "perspective") read_perspective(sub, cam);
    else read_box(sub, cam, kind == "ortho" ? Camera::Kind::Ortho : Camera::Kind::Frustum);
    projection = glm::mat4(projection_of(cam, width, height));
}

}  // namespace

void read_camera_into(const Section& s, Camera& camera, glm::mat4& view, glm::mat4& projection, int width,
                      int height) {
    s.allow({"look_at", "view_matrix", "perspective", "ortho", "frustum", "projection_matrix"});
    std::string_view v = one_of(s, {"look_at", "view_matrix"});
    if (v == "look_at") view = glm::mat4(read_look_at(*s.get(v), s.name(v)));
    if (v == "view_matrix") view = glm::mat4(matrix(*s.get(v), s.name(v)));
    read_projection(s, camera, projection, width, height);
}

void read_camera(const Section& s, Scene& scene) {
    read_camera_into(s, scene.camera, scene.view, scene.projection, scene.width, scene.height);
}

std::string size_problem(int64_t width, int64_t height) {
    if (width >= 1 && height >= 1 && width <= kMaxImageSide && height <= kMaxImageSide &&
        width * height <= kMaxFramebufferPixels)
        return {};
    return fmt::format("size {}x{} is not allowed: width and height must each be 1..{}, and {}M pixels at most",
                       width, height, kMaxImageSide, kMaxFramebufferPixels >> 20);
}

}  // namespace detail

std::array<LightSetting, 8> default_light_settings() {
    const GLState defaults;
    std::array<LightSetting, 8> lights;
    for (size_t i = 0; i < lights.size(); ++i) lights[i].as_given = defaults.lights[i];
    return lights;
}

std::array<LightState, 8> eye_space_lights(const Scene& scene) {
    // glLightfv transforms GL_POSITION by the modelview and GL_SPOT_DIRECTION
    // by its upper 3x3 (GL 2.1 §2.14.1); parameters the file left out keep
    // their eye-space defaults, which no modelview ever transformed.
    const LightState defaults;
    glm::dmat4 view(scene.view);
    std::array<LightState, 8> eye;
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const LightSetting& l = scene.lights[i];
        bool position = l.has_position || l.as_given.position != defaults.position;
        bool direction = l.has_spot_direction || l.as_given.spot_direction != defaults.spot_direction;
        eye[i] = l.as_given;
        if (l.world_space && position) eye[i].position = glm::vec4(view * glm::dvec4(l.as_given.position));
        if (l.world_space && direction)
            eye[i].spot_direction = glm::vec3(glm::dmat3(view) * glm::dvec3(l.as_given.spot_direction));
    }
    return eye;
}

void derive_eye_space_lights(Scene& scene) {
    scene.gl.modelview = scene.view;
    scene.gl.projection = scene.projection;
    scene.gl.lights = eye_space_lights(scene);
}

Status resize_scene(Scene& scene, int width, int height) {
    if (std::string why = detail::size_problem(width, height); !why.empty()) return Error(why);
    scene.width = width;
    scene.height = height;
    if (scene.camera.kind == Camera::Kind::Perspective && scene.camera.aspect == 0) {
        scene.projection = glm::mat4(detail::projection_of(scene.camera, width, height));
        derive_eye_space_lights(scene);
        // Every state drawn with the scene's camera: the objects' and the passes' copies.
        for (Object& o : scene.objects)
            if (o.state) o.state->projection = scene.projection;
        for (Pass& p : scene.passes) {
            if (p.own_projection) continue;
            p.state.projection = scene.projection;
            for (auto& st : p.object_states)
                if (st) st->projection = scene.projection;
        }
    }
    return Ok{};
}

}  // namespace glslrun::scene
