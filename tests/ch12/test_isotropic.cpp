// Tests for isotropic.h (chapter 12): the phase function of a medium that scatters equally in
// all directions, p(w) = 1 / (4 pi). Sampled exactly, its weight is just the albedo; the new ray
// starts at the scattering point itself (a medium has no surface to leave) and keeps the time.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "rt/core/error.h"
#include "rt/core/rng.h"
#include "rt/media/isotropic.h"
#include "rt/samplers/independent_sampler.h"
#include "rt/samplers/sampling.h"
#include "statistics.h"
#include "test_helpers.h"

namespace {

using rt::color, rt::point3, rt::real, rt::vec3;

constexpr real eps = std::numeric_limits<real>::epsilon();

using rt_test::exactly;

}  // namespace

TEST_CASE("isotropic: scattered directions are uniform on the sphere, weighted by the albedo",
          "[ch12]") {
    const color albedo(0.25, 0.5, 0.75);
    rt::isotropic phase(albedo);
    rt::independent_sampler s(10);
    rt::pcg32 incoming(11, 0);
    // 10 bins of z = cos(theta) (equal areas, by Archimedes) times 20 of the azimuth: under the
    // uniform sphere each bin expects n / 200.
    const int z_bins = 10, phi_bins = 20, n = 100000;
    std::vector<double> observed(z_bins * phi_bins, 0);
    int wrong = 0;
    for (int k = 0; k < n; ++k) {
        s.start_pixel_sample(0, 0, k);
        // Any incoming direction and time: the phase function ignores the direction.
        real u      = incoming.uniform();
        vec3 in_dir = rt::sample_uniform_sphere({u, incoming.uniform()});
        rt::ray r_in(point3(0, 0, 0), 3 * in_dir, 0.625);
        rt::hit_record rec;
        rec.p                          = point3(1, -2, 3);
        rt::independent_sampler replay = s;
        const auto sample              = phase.scatter(r_in, rec, s);
        if (!sample) {
            ++wrong;
            continue;
        }
        const rt::ray& out       = sample->scattered;
        const color& attenuation = sample->weight;
        // It starts exactly at the scattering point (a medium has no surface to leave), keeps
        // the time, is unit length to rounding and weighs exactly the albedo. It draws 2
        // dimensions: the sampler is left where two draws leave it.
        const vec3& d = out.direction();
        replay.next_2d();
        if (!exactly(out.origin(), rec.p) || out.time() != r_in.time() ||
            !exactly(attenuation, albedo) || std::fabs(d.length() - 1) > 4 * eps ||
            s.next_1d() != replay.next_1d())
            ++wrong;
        real z   = std::clamp(d.z(), real(-1), real(1));
        real phi = std::atan2(d.y(), d.x()) + rt::pi;  // in [0, 2 pi]
        int iz   = std::min(int((z + 1) / 2 * z_bins), z_bins - 1);
        int ip   = std::min(int(phi / (2 * rt::pi) * phi_bins), phi_bins - 1);
        observed[std::size_t(iz * phi_bins + ip)] += 1;
    }
    std::vector<double> expected(observed.size(), double(n) / double(observed.size()));
    auto result = rt_test::chi_square_test(observed, expected, 0.01);
    INFO(result.summary);
    CHECK(wrong == 0);
    CHECK(result.passed);

    CHECK_THROWS_AS(rt::isotropic(color(real(1.1), 0, 0)), rt::user_error);
    CHECK_THROWS_AS(rt::isotropic(std::shared_ptr<rt::texture>()), rt::user_error);
}
