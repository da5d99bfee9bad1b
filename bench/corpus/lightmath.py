"""4x4 matrices (row-major lists) for the corpus's generated scenes: gluLookAt, gluPerspective,
glOrtho and the [0, 1] bias, as the fixed-function programs of the time built their texture
matrices."""
import math


def mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def apply(m, v):
    return [sum(m[i][k] * v[k] for k in range(4)) for i in range(4)]


def normalize(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def look_at(eye, center, up):
    f = normalize([c - e for c, e in zip(center, eye)])
    s = normalize(cross(f, up))
    u = cross(s, f)
    m = [s + [0], u + [0], [-c for c in f] + [0], [0, 0, 0, 1]]
    t = [[1, 0, 0, -eye[0]], [0, 1, 0, -eye[1]], [0, 0, 1, -eye[2]], [0, 0, 0, 1]]
    return mul(m, t)


def perspective(fovy, aspect, near, far):
    f = 1 / math.tan(math.radians(fovy) / 2)
    return [[f / aspect, 0, 0, 0], [0, f, 0, 0], [0, 0, (far + near) / (near - far), 2 * far * near / (near - far)],
            [0, 0, -1, 0]]


def ortho(l, r, b, t, n, f):
    return [[2 / (r - l), 0, 0, -(r + l) / (r - l)], [0, 2 / (t - b), 0, -(t + b) / (t - b)],
            [0, 0, -2 / (f - n), -(f + n) / (f - n)], [0, 0, 0, 1]]


BIAS = [[0.5, 0, 0, 0.5], [0, 0.5, 0, 0.5], [0, 0, 0.5, 0.5], [0, 0, 0, 1]]


def inverse_rigid(m):
    """The inverse of a rotation + translation (a view matrix)."""
    r = [[m[j][i] for j in range(3)] for i in range(3)]
    t = [-sum(r[i][k] * m[k][3] for k in range(3)) for i in range(3)]
    return [r[0] + [t[0]], r[1] + [t[1]], r[2] + [t[2]], [0, 0, 0, 1]]


def columns(m):
    """TOML: a list of 4 columns."""
    return "[" + ", ".join("[" + ", ".join(f"{m[i][j]:.7g}" for i in range(4)) + "]" for j in range(4)) + "]"
