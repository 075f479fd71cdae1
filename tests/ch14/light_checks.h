// direction_checks.h's test for a light (included as "ch14/light_checks.h"): directions drawn by
// light.sample() against light.pdf(), from one point.
#pragma once

#include <cstdint>

#include "ch03/sampling_checks.h"
#include "ch14/direction_checks.h"
#include "rt/lights/light.h"

namespace rt_test::direction_checks {

// test_directions for a light: n directions drawn by light.sample() from ref, each from the next
// two numbers of its sequence, against light.pdf() from ref.
inline direction_test test_light(const rt::light& light, const direction_bins& bins,
                                 const rt::point3& ref, std::uint64_t sequence,
                                 double pdf_tolerance, int n = 100000) {
    auto draw = [&](rt::pcg32& rng, vec3& wi, real& pdf) {
        rt::light_sample out;
        if (!light.sample(ref, sampling_checks::next_sample2(rng), out)) return false;
        wi  = out.wi;
        pdf = out.pdf;
        return true;
    };
    auto pdf = [&](const vec3& wi) { return light.pdf(ref, wi); };
    return test_directions(bins, draw, pdf, n, sequence, pdf_tolerance);
}

}  // namespace rt_test::direction_checks
