// Tests for chapter 14's additions to material.h: a material with an evaluable lobe (lambertian,
// textured_lambertian, isotropic) gives f |cos| for any direction (eval) and the solid-angle
// density with which its scatter() draws a direction (pdf). So for the direction scatter() drew,
// its weight must be eval / pdf, and the density the sample brings must be pdf()'s; its
// directions must follow pdf() (chi-square over the whole sphere of directions,
// ch14/direction_checks.h), and pdf() must integrate to 1. A diffuse reflector sends nothing
// below its surface (eval and pdf 0 there). Metal, glass and lights are only sampled, and say so
// before and in every sample.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "ch03/material_helpers.h"
#include "ch14/direction_checks.h"
#include "rt/materials/dielectric.h"
#include "rt/materials/diffuse_light.h"
#include "rt/materials/lambertian.h"
#include "rt/materials/metal.h"
#include "rt/materials/textured_lambertian.h"
#include "rt/media/isotropic.h"
#include "rt/samplers/independent_sampler.h"
#include "rt/textures/texture.h"
#include "test_helpers.h"

namespace {

using rt::color, rt::point3, rt::real, rt::vec3;
using rt_test::hit_at;
using rt_test::direction_checks::direction_bins;

constexpr double pi = rt_test::sampling_checks::pi;

struct named_material {
    std::string name;
    std::shared_ptr<rt::material> mat;
    bool has_surface;  // false for a medium's phase function: no hemisphere
};

std::vector<named_material> evaluable_materials() {
    return {
        {"lambertian", std::make_shared<rt::lambertian>(color(0.2, 0.5, 0.9)), true},
        {"textured_lambertian",
         std::make_shared<rt::textured_lambertian>(std::make_shared<rt::checker_texture>(
             real(0.3), color(0.9, 0.1, 0.4), color(0.05, 0.6, 0.3))),
         true},
        {"isotropic", std::make_shared<rt::isotropic>(color(0.7, 0.35, 0.1)), false},
    };
}

// Normals on the axes (where a frame is most easily built wrong) and off them; both faces.
std::vector<rt::hit_record> hits() {
    std::vector<rt::hit_record> recs;
    const vec3 normals[] = {vec3(0, 0, 1), vec3(0, 0, -1), vec3(0, 1, 0),
                            rt::unit_vector(vec3(0.3, -0.8, 0.52)),
                            rt::unit_vector(vec3(-0.9, 0.1, -0.2))};
    int k                = 0;
    for (const vec3& n : normals) {
        const point3 p(real(0.1) * real(k), real(-0.45) + real(0.2) * real(k), real(0.37));
        recs.push_back(hit_at(p, n, k % 2 == 0));
        ++k;
    }
    return recs;
}

rt::ray incoming(const rt::hit_record& rec) {
    return rt::ray(rec.p + rec.normal, -rec.normal);
}

bool close(const color& a, const color& b) {
    const real tolerance = 16 * std::numeric_limits<real>::epsilon();
    for (int i = 0; i < 3; ++i) {
        if (!(std::fabs(a[i] - b[i]) <= tolerance * std::fabs(b[i]))) return false;
    }
    return true;
}

}  // namespace

TEST_CASE("evaluable materials: the sampled weight is eval / pdf of the direction drawn",
          "[ch14]") {
    for (const auto& m : evaluable_materials()) {
        INFO(m.name);
        REQUIRE(m.mat->lobe_kind() == rt::lobe::evaluable);
        rt::independent_sampler s(61);
        int wrong = 0, no_density = 0, other_density = 0, n = 0;
        for (const rt::hit_record& rec : hits()) {
            const rt::ray r_in = incoming(rec);
            for (int k = 0; k < 4000; ++k, ++n) {
                s.start_pixel_sample(n, 5, 0);
                const auto sample = m.mat->scatter(r_in, rec, s);
                REQUIRE(sample);
                const vec3 wi = rt::unit_vector(sample->scattered.direction());
                const real p  = m.mat->pdf(r_in, rec, wi);
                if (!(p > 0)) {
                    ++no_density;
                    continue;
                }
                // The density the sample brings is pdf()'s for its direction, to rounding: it
                // comes from the sampled cosine in the local frame, pdf() from a dot product
                // with the normal, whose error is absolute (a few eps), not relative.
                const real eps = std::numeric_limits<real>::epsilon();
                if (sample->from != rt::lobe::evaluable ||
                    !(std::fabs(sample->pdf - p) <= 16 * eps * (p + 1 / real(pi))))
                    ++other_density;
                const color weight = m.mat->eval(r_in, rec, wi) / p;
                if (!close(sample->weight, weight)) {
                    if (wrong < 3)
                        UNSCOPED_INFO("normal " << rec.normal << ", wi " << wi << ": weight "
                                                << sample->weight << ", eval / pdf " << weight);
                    ++wrong;
                }
            }
        }
        CHECK(no_density == 0);  // scatter() drew a direction pdf() says it never draws
        CHECK(other_density == 0);
        CHECK(wrong == 0);
    }
}

TEST_CASE("evaluable materials: directions follow pdf(), which integrates to 1 over the sphere",
          "[ch14]") {
    std::uint64_t sequence = 71;
    for (const auto& m : evaluable_materials()) {
        for (const rt::hit_record& rec : {hits()[1], hits()[3]}) {
            INFO(m.name << ", normal " << rec.normal);
            const rt::ray r_in = incoming(rec);
            // Whole sphere, about the normal: a diffuse direction below the surface falls
            // where pdf() is 0 and fails the test outright.
            const direction_bins bins(rec.normal, 2, 10, 12);
            rt::independent_sampler s(sequence);
            int k     = 0;
            auto draw = [&](rt::pcg32&, vec3& wi, real& pdf) {
                s.start_pixel_sample(k++, 0, 0);
                const auto sample = m.mat->scatter(r_in, rec, s);
                if (!sample) return false;
                wi  = rt::unit_vector(sample->scattered.direction());
                pdf = m.mat->pdf(r_in, rec, wi);
                return true;
            };
            auto pdf = [&](const vec3& wi) { return m.mat->pdf(r_in, rec, wi); };
            rt_test::direction_checks::check_directions(
                rt_test::direction_checks::test_directions(bins, draw, pdf, 50000, sequence++, 0));
        }
    }
}

TEST_CASE("evaluable materials: eval is f |cos|, and a diffuse surface sends nothing below it",
          "[ch14]") {
    rt::pcg32 rng(81, 1);
    int wrong = 0;
    for (const auto& m : evaluable_materials()) {
        for (const rt::hit_record& rec : hits()) {
            const rt::ray r_in = incoming(rec);
            // The albedo the material reports through scatter() at this hit.
            rt::independent_sampler s(3);
            s.start_pixel_sample(0, 0, 0);
            const auto sample = m.mat->scatter(r_in, rec, s);
            REQUIRE(sample);
            const color albedo = sample->weight;
            for (int k = 0; k < 500; ++k) {
                const vec3 wi  = rt_test::random_unit(rng);
                const double c = double(dot(wi, rec.normal));
                const color f  = m.mat->eval(r_in, rec, wi);
                const double p = double(m.mat->pdf(r_in, rec, wi));
                // f |cos|: albedo cos / pi above a surface and 0 below; a medium's
                // albedo / (4 pi) in every direction. The density: cos / pi, or 1 / (4 pi).
                const double expected_p = m.has_surface ? std::fmax(0.0, c) / pi : 1 / (4 * pi);
                bool ok                 = std::fabs(p - expected_p) <= 1e-6 * expected_p + 1e-12;
                for (int i = 0; i < 3; ++i)
                    ok = ok && std::fabs(double(f[i]) - double(albedo[i]) * expected_p) <=
                                   1e-6 * double(albedo[i]) * expected_p + 1e-12;
                if (m.has_surface && c < 0)
                    ok = ok && f[0] == 0 && f[1] == 0 && f[2] == 0 && p == 0;
                if (!ok) {
                    if (wrong < 3)
                        UNSCOPED_INFO(m.name << ", normal " << rec.normal << ", wi " << wi
                                             << ": eval " << f << ", pdf " << p);
                    ++wrong;
                }
            }
        }
    }
    CHECK(wrong == 0);
}

TEST_CASE("metal, glass and lights cannot be evaluated: they are only sampled, and say so",
          "[ch14]") {
    const rt::metal mirror(color(0.8, 0.8, 0.8), 0), fuzzy(color(0.8, 0.6, 0.2), real(0.3));
    const rt::dielectric glass(real(1.5));
    const rt::diffuse_light lamp(color(4, 4, 4));
    const rt::hit_record rec = hit_at(point3(0, 0, 0), vec3(0, 0, 1), true);
    const rt::ray r_in(point3(0, 0, 1), vec3(0, 0, -1));
    for (const rt::material* m :
         {static_cast<const rt::material*>(&mirror), static_cast<const rt::material*>(&fuzzy),
          static_cast<const rt::material*>(&glass), static_cast<const rt::material*>(&lamp)}) {
        CHECK(m->lobe_kind() == rt::lobe::sampled_only);
        // Their samples say the same, with no density.
        rt::independent_sampler s(62);
        for (int k = 0; k < 100; ++k) {
            s.start_pixel_sample(k, 0, 0);
            if (const auto sample = m->scatter(r_in, rec, s)) {
                CHECK(sample->from == rt::lobe::sampled_only);
                CHECK(sample->pdf == 0);
            }
        }
        // What they would answer if asked anyway: nothing, not garbage.
        CHECK(m->pdf(r_in, rec, vec3(0, 0, 1)) == 0);
        CHECK(rt_test::exactly(m->eval(r_in, rec, vec3(0, 0, 1)), color(0, 0, 0)));
    }
}
