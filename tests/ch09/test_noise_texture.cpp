// Tests for noise_texture.h (chapter 09): marble is gray = (1 + sin(s.z + 10 turbulence(s))) / 2
// with s = scale p, a gray (r = g = b) in [0, 1] that takes its whole range, fixed by its seed.
#include <catch2/catch.hpp>
#include <cmath>

#include "rt/core/rng.h"
#include "rt/textures/noise_texture.h"
#include "test_helpers.h"

namespace {

using rt::color, rt::point3, rt::real;

using rt_test::uniform;

}  // namespace

TEST_CASE("noise_texture: marble is gray, within 0..1, and follows its formula", "[ch09]") {
    const real scale = 4;
    const rt::noise_texture marble(scale, 21);
    const rt::perlin noise(21);  // the same seed: the same turbulence
    rt::pcg32 rng(96, 1);
    int not_gray = 0, outside = 0, not_formula = 0;
    real darkest = 1, brightest = 0;
    for (int i = 0; i < 20000; ++i) {
        const real reach = i % 2 ? real(5) : real(1e4);
        const real x = uniform(rng, -reach, reach), y = uniform(rng, -reach, reach);
        const point3 p(x, y, uniform(rng, -reach, reach));
        // u and v play no part (a solid texture).
        const real u = rng.uniform(), v = rng.uniform();
        const color c = marble.value(u, v, p);
        if (!(c.x() == c.y() && c.y() == c.z())) ++not_gray;
        if (!(c.x() >= 0 && c.x() <= 1)) ++outside;
        const point3 s  = scale * p;
        const real gray = real(0.5) * (1 + std::sin(s.z() + 10 * noise.turbulence(s, 7)));
        if (c.x() != gray) ++not_formula;
        darkest   = std::min(darkest, c.x());
        brightest = std::max(brightest, c.x());
    }
    // A solid texture: a hit's (u, v) are never computed for it.
    CHECK_FALSE(marble.uses_uv());
    CHECK(not_gray == 0);
    CHECK(outside == 0);
    CHECK(not_formula == 0);
    // sin takes all its values along the stripes: 20000 points reach both ends of the range.
    CHECK(darkest < real(0.01));
    CHECK(brightest > real(0.99));
}

TEST_CASE("noise_texture: the same seed gives the same marble, another seed another", "[ch09]") {
    const rt::noise_texture a(4, 5), b(4, 5), c(4, 6);
    rt::pcg32 rng(97, 2);
    int differ_same = 0, differ_other = 0;
    for (int i = 0; i < 1000; ++i) {
        const real x = uniform(rng, -5, 5), y = uniform(rng, -5, 5);
        const point3 p(x, y, uniform(rng, -5, 5));
        if (a.value(0, 0, p).x() != b.value(0, 0, p).x()) ++differ_same;
        if (a.value(0, 0, p).x() != c.value(0, 0, p).x()) ++differ_other;
    }
    CHECK(differ_same == 0);
    CHECK(differ_other > 900);
}
