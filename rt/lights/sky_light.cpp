#include "rt/lights/sky_light.h"

#include <algorithm>
#include <cmath>

#include "rt/core/exercise.h"

namespace rt {

namespace {
real brightness(const color& c) {
    return (c.x() + c.y() + c.z()) / 3;
}
}  // namespace

sky_light::sky_light(const background& s)
    : sky(s),
      a((brightness(s.top) + brightness(s.bottom)) / 2),
      b((brightness(s.top) - brightness(s.bottom)) / 2) {}

bool sky_light::emits(const background& s) {
    return brightness(s.top) + brightness(s.bottom) > 0;
}

real sky_light::height_for(real u) const {
    // [exercise sky_light::height_for begin]
    // The cdf F(y) = (a (y + 1) + b (y^2 - 1) / 2) / (2 a) = u is the quadratic
    // (b/2) y^2 + a y + c = 0 with c = a - b/2 - 2 a u. Its root in [-1, 1], written as
    // -2c / (a + sqrt(a^2 - 2 b c)) so that it does not cancel as b goes to 0 (a >= |b|, since
    // the brightness is >= 0 at both ends, keeps the denominator positive).
    real c            = a - b / 2 - 2 * a * u;
    real discriminant = std::fmax(real(0), a * a - 2 * b * c);
    real y            = -2 * c / (a + std::sqrt(discriminant));
    return std::clamp(y, real(-1), real(1));
    // [exercise sky_light::height_for end]
}

bool sky_light::sample(const point3& /*ref*/, sample2 u, light_sample& out) const {
    real y   = height_for(u.u);
    real r   = std::sqrt(std::fmax(real(0), 1 - y * y));
    real phi = 2 * pi * u.v;
    out.wi   = vec3(r * std::cos(phi), y, r * std::sin(phi));
    out.pdf  = pdf_at(point3(), out.wi, hit_record());
    if (!(out.pdf > 0)) return false;  // the black end of a sky that fades to black
    out.radiance    = sky.radiance(out.wi);
    out.at_infinity = true;
    return true;
}

real sky_light::pdf(const point3& ref, const vec3& wi) const {
    return pdf_at(ref, wi, hit_record());
}

real sky_light::pdf_at(const point3&, const vec3& wi, const hit_record&) const {
    real y = wi.y() / wi.length();
    return std::fmax(real(0), a + b * y) / (4 * pi * a);
}

}  // namespace rt
