// onb (rt/core/onb.h): an orthonormal frame about a unit normal, so that directions sampled about
// +z can be turned about any surface normal. Chapter 03.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "rt/core/onb.h"
#include "rt/core/rng.h"
#include "rt/samplers/sampling.h"

using rt::real;
using rt::vec3;

namespace {

constexpr real eps = std::numeric_limits<real>::epsilon();

// Duff et al. report errors of a few ulps for every unit input, including near n = (0, 0, -1)
// where Frisvad's original construction loses all precision. Each component here comes from at
// most four roundings of terms of magnitude <= 2, and the input itself is unit only to about
// 2 eps, so lengths and dot products are off by no more than about 8 eps; 16 eps leaves a factor
// of two and still fails for an error of 1e-13 (double) or 2e-6 (float).
constexpr real tolerance = 16 * eps;

// Checks that (u, v, n) is a right-handed orthonormal frame with w == n; counts failures.
int frame_errors(const vec3& n) {
    const rt::onb frame(n);
    const vec3 &u = frame.u(), &v = frame.v(), &w = frame.w();
    const bool ok = std::fabs(u.length() - 1) <= tolerance &&
                    std::fabs(v.length() - 1) <= tolerance && std::fabs(dot(u, v)) <= tolerance &&
                    std::fabs(dot(u, w)) <= tolerance && std::fabs(dot(v, w)) <= tolerance &&
                    (cross(u, v) - w).length() <= tolerance && w.x() == n.x() && w.y() == n.y() &&
                    w.z() == n.z();
    if (!ok) {
        UNSCOPED_INFO("n = " << n << ": u = " << u << ", v = " << v
                             << ", |u|-1 = " << u.length() - 1 << ", |v|-1 = " << v.length() - 1
                             << ", u.v = " << dot(u, v) << ", u.w = " << dot(u, w)
                             << ", v.w = " << dot(v, w));
    }
    return ok ? 0 : 1;
}

// Unit normals at and around the poles, where the construction's 1 / (sign + z) is most delicate.
std::vector<vec3> polar_normals() {
    std::vector<vec3> normals = {vec3(0, 0, 1), vec3(0, 0, -1), vec3(real(-0.0), real(-0.0), -1)};
    for (real t : {real(1e-30), real(1e-12), real(1e-8), real(1e-4), real(1e-2), real(0.3)}) {
        for (real z : {real(1), real(-1)}) {
            normals.push_back(rt::unit_vector(vec3(t, 0, z)));
            normals.push_back(rt::unit_vector(vec3(0, -t, z)));
            normals.push_back(rt::unit_vector(vec3(t, t, z)));
        }
    }
    // The equator, where z changes sign.
    for (real z : {real(0), real(-0.0), real(1e-9), real(-1e-9)}) {
        normals.push_back(rt::unit_vector(vec3(1, 0, z)));
        normals.push_back(rt::unit_vector(vec3(0, 1, z)));
    }
    return normals;
}

}  // namespace

TEST_CASE("onb: the frame is orthonormal and right-handed at and near the poles", "[onb][ch03]") {
    int errors = 0;
    for (const vec3& n : polar_normals()) errors += frame_errors(n);
    CHECK(errors == 0);
}

TEST_CASE("onb: the frame is orthonormal for many random normals", "[onb][ch03]") {
    rt::pcg32 rng(31, 7);
    int errors = 0;
    for (int i = 0; i < 100000; ++i) {
        real u = rng.uniform();
        errors += frame_errors(rt::unit_vector(rt::sample_uniform_sphere({u, rng.uniform()})));
    }
    CHECK(errors == 0);
}

TEST_CASE("onb: to_world maps the local axes onto the frame", "[onb][ch03]") {
    rt::pcg32 rng(5, 5);
    std::vector<vec3> normals = polar_normals();
    for (int i = 0; i < 100; ++i) {
        real u = rng.uniform();
        normals.push_back(rt::unit_vector(rt::sample_uniform_sphere({u, rng.uniform()})));
    }
    for (const vec3& n : normals) {
        const rt::onb frame(n);
        CAPTURE(n);
        // 0 * u + 0 * v adds only zeros, so the local +z comes out as n bit for bit.
        const vec3 up = frame.to_world(vec3(0, 0, 1));
        CHECK((up.x() == n.x() && up.y() == n.y() && up.z() == n.z()));
        const vec3 x = frame.to_world(vec3(1, 0, 0)), y = frame.to_world(vec3(0, 1, 0));
        CHECK((x.x() == frame.u().x() && x.y() == frame.u().y() && x.z() == frame.u().z()));
        CHECK((y.x() == frame.v().x() && y.y() == frame.v().y() && y.z() == frame.v().z()));
        // A rotation keeps lengths: a local unit direction stays unit in the world.
        const vec3 d = frame.to_world(rt::unit_vector(vec3(1, -2, 3)));
        CHECK(std::fabs(d.length() - 1) <= tolerance);
        CHECK(std::fabs(dot(d, n) - real(3) / std::sqrt(real(14))) <= tolerance);
    }
}
