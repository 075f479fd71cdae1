// Tests for sky_light.h (chapter 14): the sky's brightness (the mean of its channels) is linear
// in the height y of a direction, so sky_light draws y with density (a + b y) / (2 a) and the
// azimuth uniformly: pdf(wi) = (a + b y) / (4 pi a), in proportion to the light each direction
// brings. Checked by chi-square against pdf() integrated over bins of directions about +y
// (ch14/direction_checks.h) for a gradient sky, a uniform sky and skies black at one end, by
// the pdf integrating to 1, by every sample reporting pdf() of its direction and the sky's
// radiance along it, and by pdf() being proportional to that radiance's brightness. Hard cases:
// u = 0 and u just below 1, at the black end of a sky that fades to black.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>

#include "ch03/sampling_checks.h"
#include "ch14/direction_checks.h"
#include "ch14/light_checks.h"
#include "rt/lights/sky_light.h"
#include "rt/scene/background.h"
#include "test_helpers.h"

namespace {

using rt::color, rt::point3, rt::real, rt::vec3;
using rt_test::direction_checks::direction_bins;

struct named_sky {
    const char* name;
    rt::background sky;
};

// Chapter 01's sky (white below, light blue above), a uniform gray, skies black at the bottom
// and at the top, and one whose channels run in opposite directions.
const named_sky skies[] = {
    {"gradient", rt::background::sky()},
    {"uniform", rt::background::uniform(color(0.3, 0.3, 0.3))},
    {"black at the bottom", {color(0, 0, 0), color(1, 1, 1)}},
    {"black at the top", {color(2, 1, 0.5), color(0, 0, 0)}},
    {"crossed channels", {color(1, 0, 0.2), color(0, 1, 0.4)}},
};

double brightness(const color& c) {
    return (double(c.x()) + double(c.y()) + double(c.z())) / 3;
}

bool finite(const vec3& v) {
    return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

}  // namespace

TEST_CASE("sky_light: directions follow the sky's brightness, and the pdf integrates to 1",
          "[ch14]") {
    std::uint64_t sequence = 31;
    const point3 ref(1, -2, 3);  // the sky is at infinity: ref does not matter
    const direction_bins bins(vec3(0, 1, 0), 2, 10, 8);
    for (const auto& [name, sky] : skies) {
        INFO(name << " sky");
        rt::sky_light light(sky);
        rt_test::direction_checks::check_directions(rt_test::direction_checks::test_light(
            light, bins, ref, sequence++, 64 * double(std::numeric_limits<real>::epsilon())));
    }
}

TEST_CASE("sky_light: pdf is the brightness of the sky in that direction over its total",
          "[ch14]") {
    // The sky's brightness integrated over the sphere is 4 pi a (a = the mean of the two
    // ends' brightness, the integral of y over the sphere being 0): pdf = brightness / 4 pi a.
    rt::pcg32 rng(12, 3);
    int wrong = 0;
    for (const auto& [name, sky] : skies) {
        rt::sky_light light(sky);
        const double total =
            4 * rt_test::sampling_checks::pi * (brightness(sky.top) + brightness(sky.bottom)) / 2;
        for (int k = 0; k < 1000; ++k) {
            const vec3 wi         = rt_test::random_unit(rng);
            const double expected = brightness(sky.radiance(wi)) / total;
            const double p        = double(light.pdf(point3(0, 0, 0), wi));
            if (!(std::fabs(p - expected) <= 1e-5 * expected + 1e-6)) {
                if (wrong < 3)
                    UNSCOPED_INFO(name << ": wi " << wi << " pdf " << p << " vs " << expected);
                ++wrong;
            }
        }
    }
    CHECK(wrong == 0);
}

TEST_CASE("sky_light: a sample carries the sky's radiance, at infinity", "[ch14]") {
    rt::pcg32 rng(13, 3);
    int wrong = 0;
    for (const auto& [name, sky] : skies) {
        rt::sky_light light(sky);
        for (int k = 0; k < 1000; ++k) {
            rt::light_sample out;
            if (!light.sample(point3(0, 0, 0), rt_test::sampling_checks::next_sample2(rng), out))
                continue;
            const bool ok = out.at_infinity &&
                            rt_test::exactly(out.radiance, sky.radiance(out.wi)) &&
                            std::fabs(out.wi.length() - 1) < 1e-5 && out.pdf > 0;
            wrong += !ok;
        }
    }
    CHECK(wrong == 0);
}

TEST_CASE("sky_light: height_for inverts the brightness below a height", "[ch14]") {
    // The share of the sky's brightness below height y is
    // F(y) = (a (y + 1) + b (y^2 - 1) / 2) / (2 a); height_for(F(y)) must give y back, run
    // from -1 at u = 0 to 1 at u = 1, and never decrease.
    for (const auto& [name, sky] : skies) {
        INFO(name << " sky");
        rt::sky_light light(sky);
        const double a = (brightness(sky.top) + brightness(sky.bottom)) / 2;
        const double b = (brightness(sky.top) - brightness(sky.bottom)) / 2;
        int wrong = 0, decreasing = 0;
        real last = -2;
        for (int k = 0; k <= 1000; ++k) {
            const double y  = -1 + 2.0 * k / 1000;
            const double F  = (a * (y + 1) + b * (y * y - 1) / 2) / (2 * a);
            const real back = light.height_for(real(F));
            wrong += !(std::fabs(double(back) - y) <= 2e-3);  // float: F rounds; flat ends
            const real at = light.height_for(real(k) / 1000);
            decreasing += at < last;
            last = at;
        }
        CHECK(wrong == 0);
        CHECK(decreasing == 0);
        // At a black end the cdf is flat (quadratic in y), so a rounding of the discriminant
        // moves y by about sqrt(eps): 3e-4 in a float build (measured: height_for(1) = 0.9997
        // for the sky black at the top), 1e-8 in double. The sliver it leaves out holds a share
        // of the brightness of order eps.
        const double flat_end = 4 * std::sqrt(double(std::numeric_limits<real>::epsilon()));
        CHECK(std::fabs(double(light.height_for(0)) + 1) <= flat_end);
        CHECK(std::fabs(double(light.height_for(1)) - 1) <= flat_end);
    }
}

TEST_CASE("sky_light: only a sky that sends light emits", "[ch14]") {
    CHECK(rt::sky_light::emits(rt::background::sky()));
    CHECK(rt::sky_light::emits({color(0, 0, 0), color(0, 0, 1e-3)}));
    CHECK(rt::sky_light::emits({color(0.5, 0, 0), color(0, 0, 0)}));
    CHECK_FALSE(rt::sky_light::emits(rt::background::uniform(color(0, 0, 0))));
}

TEST_CASE("sky_light: u = 0, u just below 1 and a black end give no NaN", "[ch14][hardcase]") {
    // The ends of height_for (y = -1 and 1, where the azimuth circle shrinks to a point), and
    // skies black at one end, where the density is 0: a sample there must be refused, and a
    // sample taken must be finite with pdf > 0; pdf() finite and >= 0 everywhere.
    const real below_one   = std::nextafter(real(1), real(0));
    const named_sky hard[] = {
        skies[0],
        skies[2],
        skies[3],
        {"a trace of light at the bottom", {color(0, 0, 1e-30), color(1, 1, 1)}},
        {"a trace of light at the top", {color(1, 1, 1), color(1e-30, 0, 0)}},
        {"one channel only", {color(0, 0, 0), color(0, 0, 1)}},
    };
    int bad = 0, refused = 0;
    for (const auto& [name, sky] : hard) {
        rt::sky_light light(sky);
        auto check_sample = [&](rt::sample2 u) {
            rt::light_sample out;
            if (!light.sample(point3(0, 0, 0), u, out)) {
                ++refused;
                return;
            }
            const bool ok = finite(out.wi) && std::isfinite(out.pdf) && out.pdf > 0 &&
                            finite(out.radiance) && std::fabs(out.wi.length() - 1) < 1e-5;
            if (!ok) {
                UNSCOPED_INFO(name << ": u " << u.u << " " << u.v << ": wi " << out.wi << " pdf "
                                   << out.pdf);
                ++bad;
            }
        };
        for (real u : {real(0), real(1e-30), below_one, real(0.5)}) {
            for (real v : {real(0), real(0.5), below_one}) check_sample({u, v});
        }
        rt_test::sampling_checks::for_edge_and_random_samples(check_sample);
        for (const vec3& wi : {vec3(0, 1, 0), vec3(0, -1, 0), vec3(1, 0, 0), vec3(0, -1e-30, 1)}) {
            const real p = light.pdf(point3(0, 0, 0), wi);
            if (!(std::isfinite(p) && p >= 0)) {
                UNSCOPED_INFO(name << ": pdf(" << wi << ") = " << p);
                ++bad;
            }
        }
    }
    INFO(refused << " samples refused");
    CHECK(bad == 0);
}
