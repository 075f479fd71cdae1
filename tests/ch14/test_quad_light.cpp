// Tests for quad_light.h (chapter 14): a quad light sampled by area, seen from a point ref, draws
// directions with the solid-angle density pdf(wi) = d^2 / (|cos theta_light| A), from either
// side (book 2's lights emit on both faces). Checked by chi-square against pdf() integrated over
// bins of directions (ch14/direction_checks.h), by the pdf integrating to 1 over the directions
// the quad covers, and by every drawn sample reporting pdf() of its own direction. Hard cases:
// ref in the quad's plane, on its edge or corner, or a hair above it (grazing): no NaN, no
// infinity, a pdf that is finite or 0.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>

#include "ch03/sampling_checks.h"
#include "ch14/direction_checks.h"
#include "ch14/quad_checks.h"
#include "rt/geometry/quad.h"
#include "rt/lights/quad_light.h"
#include "rt/materials/diffuse_light.h"
#include "test_helpers.h"

namespace {

using rt::color, rt::point3, rt::real, rt::vec3;
using rt_test::direction_checks::direction_bins;
using rt_test::quad_checks::bins_around, rt_test::quad_checks::center_of;

const color radiance(4, 2, 1);

std::shared_ptr<rt::quad> tilted_quad() {
    return rt_test::quad_checks::tilted_quad(radiance);
}

// The drawn direction and the one pdf() re-intersects differ by the rounding of wi: a few ulps
// of d^2 / cos.
rt_test::direction_checks::direction_test test_from(const rt::quad_light& light,
                                                    const direction_bins& bins, const point3& ref,
                                                    std::uint64_t sequence) {
    return rt_test::direction_checks::test_light(
        light, bins, ref, sequence, 1000 * double(std::numeric_limits<real>::epsilon()));
}

bool finite(const vec3& v) {
    return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

}  // namespace

TEST_CASE("quad_light: directions follow pdf() = d^2 / (|cos| A), which integrates to 1",
          "[ch14]") {
    auto q = tilted_quad();
    rt::quad_light light(*q);
    // Near and oblique, straight below, far away, and from behind (the side the normal
    // u x v does not face): every one must give the same kind of density.
    const point3 refs[]    = {point3(0.3, 0, 0.2), point3(0.2, 1.5, 0.1), point3(-6, -4, 9),
                              point3(0.5, 3.5, -2)};
    std::uint64_t sequence = 1;
    for (const point3& ref : refs) {
        INFO("ref " << ref << ", normal side "
                    << dot(ref - q->corner(), cross(q->edge_u(), q->edge_v())));
        rt_test::direction_checks::check_directions(
            test_from(light, bins_around(*q, ref), ref, sequence++));
    }
}

TEST_CASE("quad_light: the density straight below the center is h^2 / A", "[ch14]") {
    // A 2 x 3 horizontal quad at height h above ref: the direction straight up meets it at
    // distance h, perpendicularly.
    const real h = real(1.5);
    auto q       = std::make_shared<rt::quad>(point3(-1, h, -1.5), vec3(2, 0, 0), vec3(0, 0, 3),
                                        std::make_shared<rt::diffuse_light>(radiance));
    rt::quad_light light(*q);
    const real expected = h * h / 6;
    CHECK(light.pdf(point3(0, 0, 0), vec3(0, 1, 0)) == Approx(expected).epsilon(1e-6));
    // From above, through the back face, the same.
    CHECK(light.pdf(point3(0, 2 * h, 0), vec3(0, -1, 0)) == Approx(expected).epsilon(1e-6));
    // Directions that miss it have no density.
    CHECK(light.pdf(point3(0, 0, 0), vec3(0, -1, 0)) == 0);
    CHECK(light.pdf(point3(0, 0, 0), rt::unit_vector(vec3(1, 0.1, 0))) == 0);
}

TEST_CASE("quad_light: a sample carries the light's radiance, from either face, and lies on it",
          "[ch14]") {
    auto q = tilted_quad();
    rt::quad_light light(*q);
    const vec3 n = rt::unit_vector(cross(q->edge_u(), q->edge_v()));
    rt::pcg32 rng(5, 2);
    int wrong = 0;
    for (const point3& ref : {point3(0.3, 0, 0.2), point3(0.5, 3.5, -2)}) {
        for (int k = 0; k < 2000; ++k) {
            rt::light_sample out;
            REQUIRE(light.sample(ref, rt_test::sampling_checks::next_sample2(rng), out));
            const vec3 from_corner = out.on_light.p - q->corner();
            const bool ok          = rt_test::exactly(out.radiance, radiance) && !out.at_infinity &&
                            std::fabs(out.wi.length() - 1) < 1e-5 &&
                            // The point is on the quad's plane, and the direction reaches it.
                            std::fabs(dot(from_corner, n)) <= 1e-5 &&
                            dot(out.wi, out.on_light.p - ref) > 0 &&
                            // Its normal faces ref, as a scattered ray would see it.
                            dot(out.on_light.normal, out.wi) < 0 && out.on_light.mat != nullptr;
            wrong += !ok;
        }
    }
    CHECK(wrong == 0);
}

TEST_CASE("quad_light: grazing and degenerate points give no NaN and no infinite pdf",
          "[ch14][hardcase]") {
    // ref in the quad's plane (outside it, on an edge, on a corner, inside it) or a hair above:
    // the quad is seen edge-on, a direction to it has |cos| = 0 and the density would be d^2/0.
    // A sample must then be refused, or be finite with a finite positive pdf; pdf() must be
    // finite or 0, never NaN.
    auto q = std::make_shared<rt::quad>(point3(-1, 1, -1), vec3(2, 0, 0), vec3(0, 0, 2),
                                        std::make_shared<rt::diffuse_light>(radiance));
    rt::quad_light light(*q);
    const real tiny = real(1e-12), eps = std::numeric_limits<real>::epsilon();
    const point3 refs[] = {point3(3, 1, 0),         point3(1, 1, 0),         point3(1, 1, 1),
                           point3(0, 1, 0),         point3(-1, 1, -1),       point3(3, 1 + tiny, 0),
                           point3(1, 1 + eps, 0),   point3(0, 1 - eps, 0.5), point3(1e8, 1, 1e8),
                           point3(0.25, 1, 1 + eps)};
    rt::pcg32 rng(11, 4);
    int bad_samples = 0, bad_pdfs = 0, refused = 0;
    for (const point3& ref : refs) {
        auto check_pdf = [&](const vec3& wi) {
            const real p = light.pdf(ref, wi);
            if (std::isnan(p) || !std::isfinite(p) || p < 0) {
                UNSCOPED_INFO("ref " << ref << ", wi " << wi << ": pdf " << p);
                ++bad_pdfs;
            }
        };
        rt_test::sampling_checks::for_edge_and_random_samples([&](rt::sample2 u) {
            rt::light_sample out;
            if (!light.sample(ref, u, out)) {
                ++refused;
                return;
            }
            const bool ok = finite(out.wi) && std::isfinite(out.pdf) && out.pdf > 0 &&
                            finite(out.radiance) && finite(out.on_light.p) &&
                            finite(out.on_light.normal);
            if (!ok) {
                UNSCOPED_INFO("ref " << ref << ", u " << u.u << " " << u.v << ": wi " << out.wi
                                     << ", pdf " << out.pdf);
                ++bad_samples;
            }
            check_pdf(out.wi);
        });
        for (int k = 0; k < 2000; ++k) check_pdf(rt_test::random_unit(rng));
        // Along the plane, and at the corners and edges themselves.
        check_pdf(vec3(1, 0, 0));
        check_pdf(vec3(-1, 0, 0));
        for (const point3& target : {q->corner(), q->corner() + q->edge_u(), point3(0, 1, 1)}) {
            if ((target - ref).length_squared() > 0) check_pdf(rt::unit_vector(target - ref));
        }
    }
    INFO(refused << " samples refused");
    CHECK(bad_samples == 0);
    CHECK(bad_pdfs == 0);
}

TEST_CASE("quad_light: a whisker above the plane, d^2 / |cos| overflows: pdf 0, not inf",
          "[ch14][hardcase]") {
    // ref a denormal height (1000 times the smallest) above the plane of a 2 x 2 quad, beside
    // it: |cos theta_light| of every direction to the quad is a denormal too, and
    // d^2 / (|cos| A) overflows. sample() refuses such a direction (its pdf is not finite);
    // pdf() must then give it no density either, as light.h's contract says, or MIS would
    // weigh the light that a scattered ray finds there with 0 (power_heuristic(p, inf)) while
    // no light sample ever finds it.
    const real whisker = 1000 * std::numeric_limits<real>::denorm_min();
    auto q             = std::make_shared<rt::quad>(point3(-1, 0, -1), vec3(2, 0, 0), vec3(0, 0, 2),
                                        std::make_shared<rt::diffuse_light>(radiance));
    rt::quad_light light(*q);
    int bad = 0, hits = 0;
    for (const point3& ref : {point3(1.5, whisker, 0.2), point3(-3, -whisker, -2)}) {
        rt_test::sampling_checks::for_edge_and_random_samples([&](rt::sample2 u) {
            const point3 target = q->corner() + u.u * q->edge_u() + u.v * q->edge_v();
            const vec3 wi       = rt::unit_vector(target - ref);
            const real p        = light.pdf(ref, wi);
            hits += p != 0;
            if (std::isnan(p) || std::isinf(p) || p < 0) {
                if (bad < 3) UNSCOPED_INFO("ref " << ref << ", wi " << wi << ": pdf " << p);
                ++bad;
            }
        });
    }
    INFO(hits << " directions with a density");
    CHECK(bad == 0);
}
