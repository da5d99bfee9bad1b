"""The extreme-value cases of issue #5, one table shared by glslrun and Mesa.

Each case is one expression evaluated by a fragment shader from uniforms (so
neither compiler can fold it) and classified into a colour that survives an
RGBA8 framebuffer; see CLASSIFY in extremes.py. `expect` is what glslrun does
today (pinned by ctest); `mesa` is what llvmpipe does where it differs
(measured by `extremes.py compare`, checked by run_on_mesa.sh).

Expectations: 'nan', '+inf', '-inf', '+0', '-0', or a number (a finite,
non-zero result within `tol` relative to it).
"""

from dataclasses import dataclass, field

# Bit patterns, written as hex so that shader_runner and glslrun read the
# exact float (piglit's strtof_hex).
NAN = "0x7fc00000"
INF = "0x7f800000"
NINF = "0xff800000"
NZERO = "0x80000000"
DENORM_MIN = "0x00000001"   # 2^-149, the smallest denormal
DENORM_BIG = "0x00400000"   # 2^-127, a denormal with a finite reciprocal (2^127)
FLT_MAX = "0x7f7fffff"


@dataclass
class Case:
    name: str
    expr: str                      # GLSL float expression of x, y, z (floats) and i, j (ints)
    expect: object                 # glslrun's pinned result
    x: str = "0.0"
    y: str = "0.0"
    z: str = "0.0"
    i: int = 0
    j: int = 0
    mesa: object = None            # llvmpipe's result where it differs from `expect`
    mesa_tol: float = None         # tolerance for a numeric `mesa` (default: tol)
    tol: float = 1e-5
    note: str = ""


@dataclass
class Group:
    name: str
    title: str
    cases: list
    helpers: str = ""              # GLSL functions the expressions may call
    extra: dict = field(default_factory=dict)


def C(name, expr, expect, **kw):
    return Case(name, expr, expect, **kw)


# ---------------------------------------------------------------- issue list
ISSUE = Group("builtins_issue", "the built-in cases named in issue #5", [
    C("normalize(vec3(0))", "normalize(vec3(x, y, z)).x", "nan"),
    C("length(vec3(1e20,0,0))", "length(vec3(x, y, z))", "+inf", x="1e20", note="x*x overflows"),
    C("length(vec2(1e20,1e20))", "length(vec2(x, y))", "+inf", x="1e20", y="1e20"),
    C("length(vec3(1e-25,0,0))", "length(vec3(x, y, z)) * 1e25", "+0", x="1e-25", note="x*x underflows"),
    C("distance(1e20,-1e20)", "distance(vec3(x), vec3(y))", "+inf", x="1e20", y="-1e20"),
    C("pow(0,0)", "pow(x, y)", 1.0, mesa="+0"),
    C("pow(-2,2)", "pow(x, y)", 4.0, x="-2.0", y="2.0", mesa="nan"),
    C("pow(-8,1/3)", "pow(x, y)", "nan", x="-8.0", y="0.33333334"),
    C("pow(0,-1)", "pow(x, y)", "+inf", y="-1.0", mesa="+0"),
    C("pow(0,2)", "pow(x, y)", "+0", y="2.0"),
    C("1.0/0.0", "1.0 / x", "+inf"),
    C("1.0/-0.0", "1.0 / x", "-inf", x=NZERO),
    C("0.0/0.0", "x / y", "nan"),
    C("exp(100)", "exp(x)", "+inf", x="100.0"),
    C("exp(-100)", "exp(x)", "+0", x="-100.0"),
    C("log(0)", "log(x)", "-inf"),
    C("log(-1)", "log(x)", "nan", x="-1.0"),
    C("log2(0)", "log2(x)", "-inf"),
    C("sqrt(-1)", "sqrt(x)", "nan", x="-1.0"),
    C("sqrt(-0)", "sqrt(x)", "-0", x=NZERO),
    C("inversesqrt(0)", "inversesqrt(x)", "+inf"),
    C("inversesqrt(-1)", "inversesqrt(x)", "nan", x="-1.0"),
    C("asin(1.0000001)", "asin(x)", "nan", x="1.0000001"),
    C("acos(1.0000001)", "acos(x)", "nan", x="1.0000001"),
    C("asin(1)", "asin(x)", 1.5707964, x="1.0"),
    C("atan(0,0)", "atan(x, y)", "+0", mesa=2.3561945, mesa_tol=1e-3),
    C("atan(0,-0)", "atan(x, y)", 3.1415927, y=NZERO, mesa=2.3561945, mesa_tol=1e-3),
    C("atan(1,0)", "atan(x, y)", 1.5707964, x="1.0"),
    C("clamp(x,2,1) x=0", "clamp(x, y, z)", 1.0, x="0.0", y="2.0", z="1.0"),
    C("clamp(x,2,1) x=3", "clamp(x, y, z)", 1.0, x="3.0", y="2.0", z="1.0"),
    C("mod(1.5,0)", "mod(x, y)", "nan", x="1.5"),
    C("mod(-1.5,0)", "mod(x, y)", "nan", x="-1.5"),
    C("smoothstep(1,1,1)", "smoothstep(y, z, x)", "+0", x="1.0", y="1.0", z="1.0"),
    C("smoothstep(1,1,2)", "smoothstep(y, z, x)", 1.0, x="2.0", y="1.0", z="1.0"),
    C("smoothstep(1,1,0)", "smoothstep(y, z, x)", "+0", x="0.0", y="1.0", z="1.0"),
    C("exp2(128)", "exp2(x)", "+inf", x="128.0"),
    C("exp2(-150)", "exp2(x)", "+0", x="-150.0"),
    C("tan(pi/2)", "tan(x)", -22877332.0, x="1.5707964", tol=1e-3, note="fp32 pi/2 is below pi/2"),
])


# ------------------------------------------------ NaN and Inf into built-ins
def _special_inputs(fn, expects, arity_expr):
    """One case per special input (NaN, +Inf, -Inf) for a built-in."""
    out = []
    for (label, bits), want in zip((("NaN", NAN), ("+Inf", INF), ("-Inf", NINF)), expects):
        out.append(C(f"{fn}({label})", arity_expr, want, x=bits))
    return out


_UNARY = {  # built-in: results for NaN, +Inf, -Inf (IEEE / C99 Annex F where it says)
    "radians": ("nan", "+inf", "-inf"),
    "degrees": ("nan", "+inf", "-inf"),
    "sin": ("nan", "nan", "nan"),
    "cos": ("nan", "nan", "nan"),
    "tan": ("nan", "nan", "nan"),
    "asin": ("nan", "nan", "nan"),
    "acos": ("nan", "nan", "nan"),
    "atan": ("nan", 1.5707964, -1.5707964),
    "exp": ("nan", "+inf", "+0"),
    "log": ("nan", "+inf", "nan"),
    "exp2": ("nan", "+inf", "+0"),
    "log2": ("nan", "+inf", "nan"),
    "sqrt": ("nan", "+inf", "nan"),
    "inversesqrt": ("nan", "+0", "nan"),
    "abs": ("nan", "+inf", "+inf"),
    "sign": ("+0", 1.0, -1.0),
    "floor": ("nan", "+inf", "-inf"),
    "ceil": ("nan", "+inf", "-inf"),
    "fract": ("nan", "nan", "nan"),
}

_NAN_INF_CASES = []
for _fn, _want in _UNARY.items():
    _NAN_INF_CASES += _special_inputs(_fn, _want, f"{_fn}(x)")
_NAN_INF_CASES += [
    # two-argument built-ins with a NaN or Inf operand (y, z are ordinary)
    C("pow(NaN,2)", "pow(x, y)", "nan", x=NAN, y="2.0", mesa="+0"),
    C("pow(2,NaN)", "pow(y, x)", "nan", x=NAN, y="2.0"),
    C("pow(+Inf,2)", "pow(x, y)", "+inf", x=INF, y="2.0"),
    C("pow(2,-Inf)", "pow(y, x)", "+0", x=NINF, y="2.0"),
    C("atan(NaN,1)", "atan(x, y)", "nan", x=NAN, y="1.0", mesa="+0"),
    C("atan(+Inf,+Inf)", "atan(x, x)", 0.7853982, x=INF),
    C("mod(NaN,2)", "mod(x, y)", "nan", x=NAN, y="2.0"),
    C("mod(2,+Inf)", "mod(y, x)", "nan", x=INF, y="2.0", note="y - inf*floor(y/inf) = 2 - inf*0"),
    C("min(NaN,2)", "min(x, y)", 2.0, x=NAN, y="2.0"),
    C("min(2,NaN)", "min(y, x)", 2.0, x=NAN, y="2.0"),
    C("max(NaN,2)", "max(x, y)", 2.0, x=NAN, y="2.0"),
    C("max(2,NaN)", "max(y, x)", 2.0, x=NAN, y="2.0"),
    C("clamp(NaN,0,1)", "clamp(x, y, z)", "+0", x=NAN, y="0.0", z="1.0"),
    C("clamp(+Inf,0,1)", "clamp(x, y, z)", 1.0, x=INF, y="0.0", z="1.0"),
    C("mix(1,2,NaN)", "mix(y, z, x)", "nan", x=NAN, y="1.0", z="2.0"),
    C("mix(0,1,+Inf)", "mix(y, z, x)", "nan", x=INF, y="0.0", z="1.0", mesa="+inf"),
    C("mix(+Inf,1,0)", "mix(x, z, y)", "+inf", x=INF, y="0.0", z="1.0", note="spec: x*(1-a) + y*a", mesa="nan"),
    C("step(0,NaN)", "step(y, x)", 1.0, x=NAN, note="x < edge is false for NaN", mesa="+0"),
    C("step(NaN,0)", "step(x, y)", 1.0, x=NAN, mesa="+0"),
    C("smoothstep(0,1,NaN)", "smoothstep(y, z, x)", "+0", x=NAN, z="1.0"),
    C("smoothstep(0,1,+Inf)", "smoothstep(y, z, x)", 1.0, x=INF, z="1.0"),
    C("length(vec2(NaN,1))", "length(vec2(x, z))", "nan", x=NAN, z="1.0"),
    C("length(vec2(+Inf,1))", "length(vec2(x, z))", "+inf", x=INF, z="1.0"),
    C("distance(+Inf,+Inf)", "distance(x, y)", "nan", x=INF, y=INF),
    C("dot(vec2(+Inf,1),vec2(0,1))", "dot(vec2(x, z), vec2(y, z))", "nan", x=INF, z="1.0"),
    C("normalize(vec2(+Inf,1)).x", "normalize(vec2(x, z)).x", "nan", x=INF, z="1.0"),
    C("normalize(vec2(NaN,1)).y", "normalize(vec2(x, z)).y", "nan", x=NAN, z="1.0"),
    C("cross(NaN..).z", "cross(vec3(x, 0.0, 0.0), vec3(0.0, z, 0.0)).z", "nan", x=NAN, z="1.0"),
    C("reflect(I,N=NaN).x", "reflect(vec3(z, 0.0, 0.0), vec3(x, 0.0, 0.0)).x", "nan", x=NAN, z="1.0"),
    C("refract(eta=+Inf).x", "refract(vec3(z, 0.0, 0.0), vec3(-z, 0.0, 0.0), x).x", "nan", x=INF, z="1.0"),
    C("faceforward(N,I=NaN,Nref).x", "faceforward(vec3(z), vec3(x), vec3(z)).x", -1.0, x=NAN, z="1.0",
      note="dot(Nref, I) < 0 is false for NaN, so -N is returned"),
]
_NAN_INF_CASES[[c.name for c in _NAN_INF_CASES].index("atan(NaN)")].mesa = "+0"
# Two files: llvmpipe keeps at most 80 nested conditionals (gallivm's
# LP_MAX_TGSI_NESTING), so an else-if chain of 88 cases loses its last ones.
_N_UNARY = 3 * len(_UNARY)
NAN_INF = Group("builtins_nan_inf", "NaN and infinities into the one-argument built-ins",
                _NAN_INF_CASES[:_N_UNARY])
NAN_INF2 = Group("builtins_nan_inf2", "NaN and infinities into the other built-ins",
                 _NAN_INF_CASES[_N_UNARY:])


# ------------------------------------------ comparisons, branches and loops
BRANCH_HELPERS = """
float if_greater(float v) { if (v > 0.0) return 1.0; else return 2.0; }
float if_not_le(float v) { if (!(v <= 0.0)) return 1.0; else return 2.0; }
float ternary(float v) { return v < 1.0 ? 1.0 : 2.0; }
// Counts loop iterations with a NaN/Inf-dependent condition; the `n < 100`
// bound keeps an infinite trip count finite on every implementation.
float loop_count(float limit) {
    float n = 0.0;
    for (float t = 0.0; t < limit && n < 100.0; t += 1.0) n += 1.0;
    return n;
}
float while_count(float v) {
    float n = 0.0;
    while (!(v < n) && n < 100.0) n += 1.0;
    return n;
}
"""
COMPARE = Group("compare_branch", "NaN and infinities in comparisons, branches and loops", [
    C("NaN < 1", "float(x < y)", "+0", x=NAN, y="1.0"),
    C("NaN <= 1", "float(x <= y)", "+0", x=NAN, y="1.0"),
    C("NaN > 1", "float(x > y)", "+0", x=NAN, y="1.0"),
    C("NaN >= 1", "float(x >= y)", "+0", x=NAN, y="1.0"),
    C("NaN == NaN", "float(x == x)", "+0", x=NAN),
    C("NaN != NaN", "float(x != x)", 1.0, x=NAN),
    C("!(NaN < 1)", "float(!(x < y))", 1.0, x=NAN, y="1.0"),
    C("+Inf == +Inf", "float(x == x)", 1.0, x=INF),
    C("-Inf < FLT_MAX", "float(x < y)", 1.0, x=NINF, y="-3.4028235e38"),
    C("-0 == +0", "float(x == y)", 1.0, x=NZERO),
    C("lessThan(NaN)", "float(any(lessThan(vec2(x), vec2(y))))", "+0", x=NAN, y="1.0"),
    C("equal(NaN,NaN)", "float(all(equal(vec2(x), vec2(x))))", "+0", x=NAN),
    C("notEqual(NaN,NaN)", "float(all(notEqual(vec2(x), vec2(x))))", 1.0, x=NAN),
    C("vec == vec (NaN)", "float(vec2(x, y) == vec2(x, y))", "+0", x=NAN, y="1.0"),
    C("if (NaN > 0)", "if_greater(x)", 2.0, x=NAN),
    C("if (!(NaN <= 0))", "if_not_le(x)", 1.0, x=NAN),
    C("NaN < 1 ? 1 : 2", "ternary(x)", 2.0, x=NAN),
    C("for (t < NaN)", "loop_count(x)", "+0", x=NAN),
    C("for (t < +Inf)", "loop_count(x)", 100.0, x=INF),
    C("while (!(NaN < n))", "while_count(x)", 100.0, x=NAN),
    C("bool(NaN)", "float(bool(x))", 1.0, x=NAN, note="bool(f) is f != 0.0"),
    C("float(bool(-0))", "float(bool(x))", "+0", x=NZERO),
], helpers=BRANCH_HELPERS)


# ----------------------------------------------------------------- denormals
DENORMALS = Group("denormals", "denormal inputs and results", [
    C("denorm > 0", "float(x > 0.0)", "+0", x=DENORM_MIN, note="flushed on input (DAZ)"),
    C("denorm == 0", "float(x == 0.0)", 1.0, x=DENORM_MIN),
    C("denorm * 2^100", "x * y", "+0", x=DENORM_BIG, y="1.2676506e30"),
    C("1 / 2^-127", "1.0 / x", "+inf", x=DENORM_BIG),
    C("sqrt(2^-127)", "sqrt(x) * 1e19", "+0", x=DENORM_BIG),
    C("inversesqrt(2^-127)", "inversesqrt(x)", "+inf", x=DENORM_BIG),
    # libm works on the bits, so DAZ alone does not reach it: glslrun flushes
    # the operands of its libm calls (ir/scalar_ops.h ftz), as llvmpipe does.
    C("log2(2^-127)", "log2(x)", "-inf", x=DENORM_BIG, note="the input is flushed"),
    C("log(2^-127)", "log(x)", "-inf", x=DENORM_BIG, note="the input is flushed"),
    C("abs(-2^-127) > 0", "float(abs(-x) > 0.0)", "+0", x=DENORM_BIG),
    C("sign(2^-127)", "sign(x)", "+0", x=DENORM_BIG),
    C("2^-63 * 2^-64", "(x * y) * z", "+0", x="1.0842022e-19", y="5.421011e-20", z="1e38",
      note="the product 2^-127 is flushed (FTZ)"),
    C("FLT_MIN / 2", "(x * y) * z", "+0", x="1.1754944e-38", y="0.5", z="1e38"),
    C("exp2(-127)", "exp2(x) * 1e38", "+0", x="-127.0"),
    C("FLT_MAX * 2", "x * 2.0", "+inf", x=FLT_MAX),
    C("FLT_MAX + FLT_MAX - FLT_MAX", "(x + y) - z", "+inf", x=FLT_MAX, y=FLT_MAX, z=FLT_MAX),
])


# ------------------------------------------------------------------ integers
INTEGERS = Group("integers", "integer overflow, division by zero, float to int", [
    C("INT_MAX + 1", "float(i + 1)", -2147483648.0, i=2147483647, tol=0),
    C("INT_MIN - 1", "float(i - 1)", 2147483647.0, i=-2147483648, tol=0),
    C("INT_MAX * 2", "float(i * 2)", -2.0, i=2147483647, tol=0),
    C("-INT_MIN", "float(-i)", -2147483648.0, i=-2147483648, tol=0),
    C("INT_MIN / -1", "float(i / j)", -2147483648.0, i=-2147483648, j=-1, tol=0),
    C("7 / 0", "float(i / j)", "+0", i=7),
    C("-7 / 0", "float(i / j)", "+0", i=-7),
    C("0 / 0 (int)", "float(i / j)", "+0"),
    C("-7 / 2", "float(i / j)", -3.0, i=-7, j=2, tol=0),
    C("int(1e30)", "float(int(x))", 2147483647.0, x="1e30", tol=0, mesa=1e30),
    C("int(-1e30)", "float(int(x))", -2147483648.0, x="-1e30", tol=0, mesa=-1e30),
    C("int(3e9)", "float(int(x))", 2147483647.0, x="3e9", tol=0, mesa=3e9),
    C("int(NaN)", "float(int(x))", "+0", x=NAN, mesa="nan"),
    C("int(+Inf)", "float(int(x))", 2147483647.0, x=INF, tol=0, mesa="+inf"),
    C("int(-Inf)", "float(int(x))", -2147483648.0, x=NINF, tol=0, mesa="-inf"),
    C("int(-2.5)", "float(int(x))", -2.0, x="-2.5", tol=0),
    # float(int(x)) alone is folded to trunc(x) by Mesa; adding the uniform i (0) keeps the int.
    C("int(1e30) + 0", "float(int(x) + i)", 2147483647.0, x="1e30", tol=0, mesa=-2147483648.0),
    C("int(-1e30) + 0", "float(int(x) + i)", -2147483648.0, x="-1e30", tol=0),
    C("int(NaN) + 0", "float(int(x) + i)", "+0", x=NAN, mesa=-2147483648.0),
    C("int(+Inf) + 0", "float(int(x) + i)", 2147483647.0, x=INF, tol=0, mesa=-2147483648.0),
    C("ivec2(1e30).y", "float(ivec2(vec2(x)).y)", 2147483647.0, x="1e30", tol=0, mesa=1e30),
    C("bool(int 0)", "float(bool(i))", "+0"),
    C("float(INT_MAX)", "float(i)", 2147483648.0, i=2147483647, tol=0),
])

GROUPS = [ISSUE, NAN_INF, NAN_INF2, COMPARE, DENORMALS, INTEGERS]
