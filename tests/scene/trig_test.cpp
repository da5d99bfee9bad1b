// scene/trig.h: the scene's own double sin/cos against long double libm
// (which is far more precise than a double), and exact at the quarter turns.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "scene/trig.h"

using glslrun::scene::sin_cos;

namespace {

// Distance in units of the last place of `exact` rounded to double.
double ulp_error(double got, long double exact) {
    const double e = double(exact);
    const double ulp = std::nextafter(std::fabs(e), std::numeric_limits<double>::infinity()) - std::fabs(e);
    return double(std::fabs((long double)got - exact) / ulp);
}

}  // namespace

TEST_CASE("scene sin_cos is within 2 ULP of a double over scene angles") {
    double worst = 0;
    uint64_t checked = 0;
    for (double x = -1000.0; x <= 1000.0; x += 0.0123456789) {
        const auto [s, c] = sin_cos(x);
        const long double lx = x;
        const long double es = std::sin(lx), ec = std::cos(lx);
        // Near a zero of sin or cos the relative ULP blows up; measure those
        // absolutely against the magnitude of the reduced argument instead.
        if (std::fabs((double)es) > 1e-3) worst = std::max(worst, ulp_error(s, es));
        else CHECK(std::fabs((long double)s - es) < 1e-18L);
        if (std::fabs((double)ec) > 1e-3) worst = std::max(worst, ulp_error(c, ec));
        else CHECK(std::fabs((long double)c - ec) < 1e-18L);
        ++checked;
    }
    CHECK(checked > 100000);
    CHECK(worst <= 2.0);
}

TEST_CASE("scene sin_cos is exact where the answer is 0 or +-1, and odd/even") {
    CHECK(sin_cos(0.0) == std::pair<double, double>{0.0, 1.0});
    const auto [s90, c90] = sin_cos(std::numbers::pi / 2);
    CHECK(s90 == 1.0);
    CHECK(std::fabs(c90) < 1e-16);
    for (double x : {0.1, 0.7, 1.3, 2.9, 4.4, 100.25}) {
        const auto [sp, cp] = sin_cos(x);
        const auto [sn, cn] = sin_cos(-x);
        CHECK(sn == -sp);
        CHECK(cn == cp);
    }
}
