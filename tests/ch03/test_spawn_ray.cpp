// Tests for spawn_ray (spawn_ray.h): rays leaving a surface never hit it again by
// mistake, at any scale (chapter 03). After pbrt-v4's robustness tests, which re-intersect
// spawned rays over radii 1e-4..1e4 and expect zero self-hits.
//
// The strategy under test. A shape's hit() stores the hit point p already projected back onto
// its surface, and p_error (spheres: 8 eps (radius + |p|); quads: 64 eps (|p| + |D|)), a bound
// on how far p can still be from the true surface after rounding. spawn_ray moves the new ray's
// origin by p_error along the normal, to the side the new direction leaves by (the side of
// dot(direction, normal)). So an outgoing ray starts strictly outside a convex surface and moves
// away from it: it cannot hit it again. A ray going in starts strictly inside: the root near p is
// behind it (t < 0), and the only hit ahead is the far side of the sphere. No t > epsilon constant
// is involved, so the same code works for a sphere of radius 1e-4 and one of 1e4, near the origin
// or 1e3 away.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <string>

#include "ch03/material_helpers.h"
#include "rt/core/rng.h"
#include "rt/geometry/quad.h"
#include "rt/geometry/spawn_ray.h"
#include "rt/geometry/sphere.h"
#include "test_helpers.h"

namespace {

using rt::point3, rt::real, rt::vec3;

const rt::interval forward(0, rt::infinity);

using rt_test::log_uniform, rt_test::random_in_cube, rt_test::random_in_hemisphere,
    rt_test::random_tangent, rt_test::random_unit, rt_test::uniform;

using rt_test::tally;

// The scales a precision can take: double the full range (radii or edges 1e-4..1e4, centers or
// corners up to 1e4 sizes or 1e3 away), float its own (sizes 1e-2..1e2, up to 1e2 sizes or 1e2
// away; its ulp at 1e4 is 1e-3, a hundred times a 1e-2 sphere's offset from a point 1e3 away).
struct spawn_scales {
    real log_size;       // radii or edges from 10^-log_size to 10^log_size
    real sizes_away;     // half the shapes within this many of their sizes of the origin
    real absolute_away;  // the other half within this distance
};
constexpr spawn_scales sphere_scales_of_this_precision() {
    if constexpr (std::numeric_limits<real>::digits >= 53) return {4, 1e4, 1e3};
    return {2, 1e2, 1e2};
}
// Quads: float's corners go only 1e1 away. A primary ray may start 0.01 sizes from its aim at 87
// degrees, 5e-4 sizes above the plane: 5e-6 for a 1e-2 quad, which float's rounding near 1e2
// (ulp 7.6e-6) puts on either side (one such miss in 1e5 cases); up to 17 away (ulp 1.9e-6) it
// stays 2.6 ulps above (no miss in 8 seeds of 1e5 cases). Double: 5e-8 above a 1e-4 quad up to
// 1.7e3 away, where its ulp is 2.3e-13.
constexpr spawn_scales quad_scales_of_this_precision() {
    if constexpr (std::numeric_limits<real>::digits >= 53) return {4, 1e4, 1e3};
    return {2, 1e2, 1e1};
}

}  // namespace

TEST_CASE(
    "spawn_ray: rays spawned from a sphere, radii 1e-4..1e4 (float: 1e-2..1e2) and centers up "
    "to 1e3 away (float: 1e2), never re-hit it near t = 0",
    "[hardcase][ch03]") {
    constexpr spawn_scales range = sphere_scales_of_this_precision();
    auto mat                     = rt_test::any_material();
    rt::pcg32 rng(20240601, 1);
    const int n_cases = 100000;

    tally primary, outward, inward, tangent_out, tangent_in;
    real worst_chord_error = 0;  // relative, over inward rays with cos >= 0.1
    for (int i = 0; i < n_cases; ++i) {
        const real radius = log_uniform(rng, -range.log_size, range.log_size);
        // Half the spheres sit up to 1e4 radii from the origin, half up to 1e3 in absolute terms
        // (a 1e-4 sphere there is 1e7 radii out: the offset must follow the coordinates' scale).
        const point3 center = i % 2 == 0 ? random_in_cube(rng, range.sizes_away * radius)
                                         : random_in_cube(rng, range.absolute_away);
        rt::sphere s(center, radius, mat);

        // A ray from outside, from 0.01 to 100 radii off the surface, aimed at a surface point
        // it can see (the angle to the normal below 87 degrees, so the aim is not lost to
        // rounding), with a direction of random length.
        vec3 n         = random_unit(rng);
        point3 aim     = center + radius * n;
        real away      = radius * log_uniform(rng, -2, 2);
        point3 origin  = aim + away * random_in_hemisphere(rng, n, real(0.05));
        vec3 direction = log_uniform(rng, -3, 3) * (aim - origin);
        const rt::ray incoming(origin, direction);
        rt::hit_record rec;
        ++primary.cases;
        if (!s.hit(incoming, forward, rec) || !rec.front_face) {
            primary.fail("radius " + std::to_string(radius));
            continue;
        }

        auto where = [&] {  // the case in words, built only for a failure
            std::ostringstream text;
            text.precision(17);
            text << "radius " << radius << ", center " << center << ", p " << rec.p << ", normal "
                 << rec.normal << ", p_error " << rec.p_error;
            return text.str();
        };
        const real scale = log_uniform(rng, -3, 3);  // spawned directions need not be unit
        rt::hit_record again;

        // Out: convex, so never again.
        vec3 out = scale * random_in_hemisphere(rng, rec.normal);
        ++outward.cases;
        if (s.hit(rt::spawn_ray(rec, incoming, out), forward, again))
            outward.fail(where() + ": re-hit at t " + std::to_string(again.t));

        // In: only the far side, at the chord's length 2 r cos(theta). Its error budget is the
        // origin's offset p_error into the sphere, p's own distance from the surface and the
        // rounding of the far hit (each below p_error), every one of them lengthening or
        // shortening the path by (its size) / cos(theta): tolerance 3 p_error / cos. Relative to
        // the chord that is 1.5 p_error / (r cos^2): 2e-8 for a sphere 1e4 radii out seen at
        // cos = 0.1, but 2e-5 for one 1e7 radii out; no one relative bound like 1e-6 fits both.
        // The 1e-9 relative term covers the rounding of the chord itself.
        vec3 in        = scale * random_in_hemisphere(rng, -rec.normal);
        real cos_theta = -dot(rt::unit_vector(in), rec.normal);
        real chord     = 2 * radius * cos_theta;
        real tolerance = real(1e-9) * chord + 3 * rec.p_error / cos_theta;
        ++inward.cases;
        if (!s.hit(rt::spawn_ray(rec, incoming, in), forward, again)) {
            inward.fail(where() + ": went in and never came out");
        } else {
            real travelled = again.t * in.length();
            // Once the tolerance is below half the chord, a hit at t ~ 0 cannot pass: ask for it
            // explicitly too, so the intent does not hide in the tolerance.
            bool near_zero = tolerance < chord / 2 && travelled < chord / 2;
            if (std::fabs(travelled - chord) > tolerance || near_zero || again.front_face) {
                std::ostringstream what;
                what.precision(17);
                what << where() << ", cos " << cos_theta << ": hit at " << travelled << ", chord "
                     << chord;
                inward.fail(what.str());
            }
            if (cos_theta >= real(0.1) && i % 2 == 0)
                worst_chord_error = std::fmax(worst_chord_error, std::fabs(travelled / chord - 1));
        }

        // Along the tangent plane: the sign of dot(direction, normal), a few ulps either way,
        // picks the side. Outside, the ray moves away and misses. Inside at depth ~p_error, it
        // crosses the thin cap to the surface sqrt(2 r p_error) ahead (the half chord at that
        // depth); the depth and the discriminant are each known to some percent, so [0.5, 2]
        // times that is a safe band, and a self-hit near t = 0 falls far below it.
        vec3 along = scale * random_tangent(rng, rec.normal);
        if (dot(along, rec.normal) > 0) {
            ++tangent_out.cases;
            if (s.hit(rt::spawn_ray(rec, incoming, along), forward, again))
                tangent_out.fail(where() + ": tangent ray re-hit");
        } else {
            ++tangent_in.cases;
            real half_chord = std::sqrt(2 * radius * rec.p_error);
            if (!s.hit(rt::spawn_ray(rec, incoming, along), forward, again)) {
                tangent_in.fail(where() + ": tangent ray went in and never came out");
            } else {
                real ratio = again.t * along.length() / half_chord;
                if (!(ratio >= real(0.5) && ratio <= 2))
                    tangent_in.fail(where() + ": tangent ray hit at " + std::to_string(ratio) +
                                    " of the half chord");
            }
        }
    }

    INFO("primary rays that missed or hit from inside: " << primary);
    INFO("outward spawned rays that hit the sphere again: " << outward);
    INFO("inward spawned rays not hitting the far side at the chord: " << inward);
    INFO("tangent rays on the outside that hit: " << tangent_out);
    INFO("tangent rays on the inside not crossing the cap: " << tangent_in);
    INFO("worst relative chord error, cos >= 0.1, centers up to 1e4 radii: " << worst_chord_error);
    CHECK(primary.failures == 0);
    CHECK(outward.failures == 0);
    CHECK(inward.failures == 0);
    CHECK(tangent_out.failures == 0);
    CHECK(tangent_in.failures == 0);
    // Both sides of the tangent plane were exercised, so the two checks above were not empty.
    CHECK(tangent_out.cases > n_cases / 10);
    CHECK(tangent_in.cases > n_cases / 10);
    // For spheres near the origin in their own units, the offset (sphere.cpp: 8 eps (r + |p|))
    // changes the chord by at most 1.5 * 8 eps (2 + 1e4) / 0.01 = 3e-9 relative in double:
    // 1e-6 holds with a wide margin. Float: 1.5 * 8 eps (2 + 1e2) / 0.01 = 1.5e-2, so 0.05.
    CHECK(worst_chord_error < (std::numeric_limits<real>::digits >= 53 ? real(1e-6) : real(0.05)));
}

TEST_CASE(
    "spawn_ray: rays spawned from a quad, edges 1e-4..1e4 (float: 1e-2..1e2) and corners up to "
    "1e3 away (float: 1e1), never re-hit it",
    "[hardcase][ch03]") {
    constexpr spawn_scales range = quad_scales_of_this_precision();
    auto mat                     = rt_test::any_material();
    rt::pcg32 rng(20240602, 2);
    const int n_cases = 100000;

    // A plane is crossed once: a ray leaving the quad on either side, or along it, starts
    // p_error off the plane on the side it moves to, and so can never reach the quad again.
    tally primary, same_side, through, along_plane;
    for (int i = 0; i < n_cases; ++i) {
        const real size     = log_uniform(rng, -range.log_size, range.log_size);
        const point3 corner = i % 2 == 0 ? random_in_cube(rng, range.sizes_away * size)
                                         : random_in_cube(rng, range.absolute_away);
        vec3 u_dir          = random_unit(rng);
        vec3 v_dir          = random_unit(rng);
        while (cross(u_dir, v_dir).length() < real(0.2)) v_dir = random_unit(rng);
        vec3 u = size * uniform(rng, real(0.5), 2) * u_dir;
        vec3 v = size * uniform(rng, real(0.5), 2) * v_dir;
        rt::quad q(corner, u, v, mat);
        vec3 n = rt::unit_vector(cross(u, v));

        // A ray from either side, aimed at a point at least 1% of an edge inside the quad.
        real a        = uniform(rng, real(0.01), real(0.99));
        real b        = uniform(rng, real(0.01), real(0.99));
        point3 aim    = corner + a * u + b * v;
        vec3 from     = random_in_hemisphere(rng, rng.uniform() < 0.5 ? n : -n, real(0.05));
        point3 origin = aim + size * log_uniform(rng, -2, 2) * from;
        const rt::ray incoming(origin, log_uniform(rng, -3, 3) * (aim - origin));
        rt::hit_record rec;
        ++primary.cases;
        if (!q.hit(incoming, forward, rec)) {
            primary.fail("size " + std::to_string(size));
            continue;
        }

        auto where = [&] {
            std::ostringstream text;
            text.precision(17);
            text << "size " << size << ", corner " << corner << ", p " << rec.p << ", normal "
                 << rec.normal << ", p_error " << rec.p_error;
            return text.str();
        };
        const real scale = log_uniform(rng, -3, 3);
        rt::hit_record again;

        ++same_side.cases;
        if (q.hit(rt::spawn_ray(rec, incoming, scale * random_in_hemisphere(rng, rec.normal)),
                  forward, again))
            same_side.fail(where() + ": re-hit at t " + std::to_string(again.t));
        ++through.cases;
        if (q.hit(rt::spawn_ray(rec, incoming, scale * random_in_hemisphere(rng, -rec.normal)),
                  forward, again))
            through.fail(where() + ": re-hit at t " + std::to_string(again.t));
        ++along_plane.cases;
        if (q.hit(rt::spawn_ray(rec, incoming, scale * random_tangent(rng, rec.normal)), forward,
                  again))
            along_plane.fail(where() + ": re-hit at t " + std::to_string(again.t));
    }

    INFO("primary rays that missed: " << primary);
    INFO("spawned rays back to the side they came from that hit the quad again: " << same_side);
    INFO("spawned rays through to the other side that hit the quad again: " << through);
    INFO("spawned rays along the plane that hit the quad again: " << along_plane);
    CHECK(primary.failures == 0);
    CHECK(same_side.failures == 0);
    CHECK(through.failures == 0);
    CHECK(along_plane.failures == 0);
}

TEST_CASE("spawn_ray: the origin moves p_error along the normal, to the side the ray leaves by",
          "[ch03]") {
    // The rule itself, on a hand-made record: p = (1, 2, 3), normal +z, p_error 1/64 (exact).
    rt::hit_record rec;
    rec.p       = point3(1, 2, 3);
    rec.normal  = vec3(0, 0, 1);
    rec.p_error = real(1) / 64;
    const rt::ray incoming(point3(1, 2, 10), vec3(0, 0, -1));
    const point3 above(1, 2, 3 + real(1) / 64), below(1, 2, 3 - real(1) / 64);

    const rt::ray out = rt::spawn_ray(rec, incoming, vec3(1, 0, 1));
    CHECK(rt_test::exactly(out.origin(), above));
    CHECK(rt_test::exactly(out.direction(), vec3(1, 0, 1)));  // as given, not normalized
    const rt::ray in = rt::spawn_ray(rec, incoming, vec3(0, -1, -3));
    CHECK(rt_test::exactly(in.origin(), below));
    CHECK(rt_test::exactly(in.direction(), vec3(0, -1, -3)));
    // Exactly in the tangent plane the ray is taken to go in: it may only leave by reflecting.
    CHECK(rt_test::exactly(rt::spawn_ray(rec, incoming, vec3(1, 1, 0)).origin(), below));

    // spawn_reflected_ray trusts the caller: on the normal's side even when the direction says
    // otherwise by a rounding error (a reflection that grazes the surface).
    CHECK(rt_test::exactly(rt::spawn_reflected_ray(rec, incoming, vec3(1, 0, 0)).origin(), above));
    CHECK(rt_test::exactly(
        rt::spawn_reflected_ray(rec, incoming, vec3(1, 0, real(-1e-17))).origin(), above));
    CHECK(rt_test::exactly(rt::spawn_reflected_ray(rec, incoming, vec3(1, 0, 1)).origin(), above));
}
