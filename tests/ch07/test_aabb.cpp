// Tests for aabb.h (chapter 07): the slab test against a reference computed in long double, rays
// along faces and parallel to axes (where 1 / direction is infinite and 0 * inf is NaN), rays that
// touch only an edge or a corner (which the far-distance factor must keep), flat boxes (zero
// thickness, not padded) at every scale and far from the origin, the empty box, and the small
// helpers the BVH builder uses (union, centroid, half_area, longest_axis).
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "rt/accel/aabb.h"
#include "rt/core/rng.h"
#include "test_helpers.h"

namespace {

using rt::aabb, rt::interval, rt::point3, rt::real, rt::vec3;

const interval forward       = interval(0, rt::infinity);
constexpr real negative_zero = -real(0);
constexpr real eps           = std::numeric_limits<real>::epsilon();

// The slab test as the BVH calls it: with 1 / direction computed once per ray.
bool hits(const aabb& box, const point3& origin, const vec3& direction, interval ray_t = forward) {
    const vec3 inv_dir(1 / direction.x(), 1 / direction.y(), 1 / direction.z());
    return box.hit(origin, inv_dir, ray_t);
}

using rt_test::random_in_cube, rt_test::random_unit, rt_test::uniform;

// A random integer in [lo, hi].
int random_int(rt::pcg32& rng, int lo, int hi) {
    return lo + int(rng.next_u32() % std::uint32_t(hi - lo + 1));
}

// The exact answer, from the definition: the t where the ray is inside each slab, intersected
// with ray_t. long double carries 64 bits where real carries at most 53, and the caller only
// trusts it when the overlap is clearly positive or clearly negative.
struct slab_reference {
    long double enter, exit;  // the ray is inside the box for t in [enter, exit] (empty if >)
};

slab_reference reference_overlap(const aabb& box, const point3& o, const vec3& d, interval ray_t) {
    long double enter = ray_t.min, exit = ray_t.max;
    for (int axis = 0; axis < 3; ++axis) {
        const interval& slab = box.axis_interval(axis);
        const long double lo = slab.min, hi = slab.max, oa = o[axis], da = d[axis];
        if (da == 0) {
            if (oa < lo || oa > hi) return {1, 0};  // parallel and outside: never inside
            continue;
        }
        long double t0 = (lo - oa) / da, t1 = (hi - oa) / da;
        if (t0 > t1) std::swap(t0, t1);
        enter = std::max(enter, t0);
        exit  = std::min(exit, t1);
    }
    return {enter, exit};
}

const aabb unit_box(point3(0, 0, 0), point3(1, 1, 1));

}  // namespace

TEST_CASE("aabb: rays through the box hit, rays beside or pointing away miss", "[ch07]") {
    const aabb box(point3(1, -1, 0.5), point3(2, 3, 4));
    // Straight through the middle, from each side.
    CHECK(hits(box, point3(-5, 1, 2), vec3(1, 0, 0)));
    CHECK(hits(box, point3(8, 1, 2), vec3(-1, 0, 0)));
    CHECK(hits(box, point3(1.5, 1, -3), vec3(0, 0.125, 1)));
    // From inside, in any direction: inside for t in [negative, positive], which contains 0.
    CHECK(hits(box, point3(1.5, 1, 2), vec3(0.375, -0.75, 0.25)));
    // Beside it, and the box behind the origin.
    CHECK_FALSE(hits(box, point3(-5, 3.5, 2), vec3(1, 0, 0)));
    CHECK_FALSE(hits(box, point3(-5, 1, 2), vec3(-1, 0, 0)));
    CHECK_FALSE(hits(box, point3(-5, 1, 2), vec3(1, 1, 0)));  // passes above: y = 7 at x = 1
    // The ray is inside for t in [6, 7]: ray_t must overlap it, and the test is closed at both
    // ends (a box touched at t = ray_t.max may still hold the nearest hit).
    const point3 o(-5, 1, 2);
    const vec3 d(1, 0, 0);
    CHECK(hits(box, o, d, interval(0, 6)));
    CHECK(hits(box, o, d, interval(7, 100)));
    CHECK(hits(box, o, d, interval(6.5, 6.5)));
    CHECK_FALSE(hits(box, o, d, interval(0, 5.875)));
    CHECK_FALSE(hits(box, o, d, interval(7.125, 100)));
    CHECK_FALSE(hits(box, o, d, interval::empty()));
}

TEST_CASE("aabb: the slab test agrees with the exact overlap on random rays", "[ch07]") {
    // Random boxes and rays, unit and non-unit directions, some with zero components, random
    // ray intervals. Cases whose exact overlap is within 1e-9 (in distance along the ray, in a
    // scene of size ~10) of touching are left out: those are for the edge and corner test below.
    rt::pcg32 rng(21, 5);
    int checked = 0, wrong_hits = 0, wrong_misses = 0, expected_hits = 0;
    for (int i = 0; i < 100000; ++i) {
        const point3 corner = random_in_cube(rng, 4);
        const aabb box(corner, random_in_cube(rng, 4));
        const point3 o = random_in_cube(rng, 8);
        // Half the rays aim near the box (so that about half of all rays hit it).
        vec3 d = random_unit(rng);
        if (i % 2 == 0) {
            const real ax = uniform(rng, -1, 1), ay = uniform(rng, -1, 1), az = uniform(rng, -1, 1);
            const vec3 spread(ax * box.x.size(), ay * box.y.size(), az * box.z.size());
            d = rt::unit_vector(box.centroid() + real(0.6) * spread - o);
        }
        d *= uniform(rng, real(0.01), 100);
        if (i % 5 == 0) d[i / 5 % 3] = 0;
        if (i % 25 == 0) d[(i / 5 + 1) % 3] = (i % 2 ? real(0) : negative_zero);
        interval ray_t = forward;
        if (i % 3 == 0) {
            real a = uniform(rng, -2, 2), b = uniform(rng, -2, 2);
            ray_t = interval(std::min(a, b), std::max(a, b));
        }
        const auto ref           = reference_overlap(box, o, d, ray_t);
        const long double margin = 1e-9L * (1 + 1 / d.length());  // t per unit of distance
        const bool clear_hit     = ref.exit - ref.enter > margin;
        const bool clear_miss    = ref.exit - ref.enter < -margin;
        if (!clear_hit && !clear_miss) continue;
        ++checked;
        expected_hits += clear_hit;
        const bool hit = hits(box, o, d, ray_t);
        if (clear_hit && !hit) ++wrong_misses;
        if (clear_miss && hit) ++wrong_hits;
    }
    INFO(checked << " rays checked, " << expected_hits << " of them hits: " << wrong_misses
                 << " hits reported as misses, " << wrong_hits << " misses reported as hits");
    CHECK(checked > 99000);
    CHECK(expected_hits > 10000);  // both answers are well represented
    CHECK(checked - expected_hits > 10000);
    CHECK(wrong_misses == 0);
    CHECK(wrong_hits == 0);
}

TEST_CASE("aabb: a ray lying in a face plane hits when it crosses the face, misses outside it",
          "[ch07]") {
    // The origin is exactly on the plane of a face and the direction is parallel to it, so on
    // that axis (min - A) * inv_dir is 0 * inf = NaN. The box is closed: the face belongs to it.
    // Both zeros: 1 / +0 = +inf and 1 / -0 = -inf take different paths through the test.
    int tested = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
        for (real face : {real(0), real(1)}) {
            for (real zero : {real(0), negative_zero}) {
                for (real sign : {real(1), real(-1)}) {
                    CAPTURE(axis, face, zero, sign);
                    // Along the face, crossing it: from outside the face's extent on axis a1.
                    point3 o;
                    o[axis] = face;
                    o[a1]   = sign > 0 ? real(-2) : real(3);
                    o[a2]   = real(0.5);
                    vec3 d;
                    d[axis] = zero;
                    d[a1]   = sign;
                    d[a2]   = real(0.25);
                    CHECK(hits(unit_box, o, d));
                    // Along an edge of the face (two coordinates on face planes).
                    point3 on_edge = o;
                    on_edge[a2]    = face;
                    vec3 along     = d;
                    along[a2]      = zero;
                    CHECK(hits(unit_box, on_edge, along));
                    // In the face plane but passing beside the face (a2 outside [0, 1]).
                    point3 beside = o;
                    beside[a2]    = real(1.5);
                    vec3 flat     = d;
                    flat[a2]      = zero;
                    CHECK_FALSE(hits(unit_box, beside, flat));
                    // In the face plane, crossing, but the box lies behind the origin.
                    vec3 away = d;
                    away[a1]  = -sign;
                    CHECK_FALSE(hits(unit_box, o, away));
                    tested += 4;
                }
            }
        }
    }
    CHECK(tested == 96);
}

TEST_CASE("aabb: axis-parallel rays (infinite 1 / direction) give no wrong answer", "[ch07]") {
    // Two zero components: only one slab gives finite distances; the other two are +-inf or
    // NaN. Inside both parallel slabs: a hit exactly when the box is ahead; outside one: a miss.
    for (int axis = 0; axis < 3; ++axis) {
        const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
        for (real zero : {real(0), negative_zero}) {
            for (real along : {real(-1), real(1)}) {
                CAPTURE(axis, zero, along);
                vec3 d(zero, zero, zero);
                d[axis] = along;
                point3 o;
                o[axis] = along > 0 ? real(-3) : real(4);
                for (real c1 : {real(-0.5), real(0), real(0.25), real(1), real(1.5)}) {
                    for (real c2 : {real(-1e-300), real(0), real(0.75), real(1), real(2)}) {
                        o[a1]             = c1;
                        o[a2]             = c2;
                        const bool inside = c1 >= 0 && c1 <= 1 && c2 >= 0 && c2 <= 1;
                        CAPTURE(c1, c2);
                        CHECK(hits(unit_box, o, d) == inside);
                        CHECK_FALSE(hits(unit_box, o, -d));  // the box is behind
                        // Starting inside the box on the moving axis: a hit both ways.
                        point3 in = o;
                        in[axis]  = real(0.5);
                        CHECK(hits(unit_box, in, d) == inside);
                        CHECK(hits(unit_box, in, -d) == inside);
                    }
                }
            }
        }
    }
}

TEST_CASE("aabb: rays that touch only an edge or a corner count as hits despite rounding",
          "[hardcase][ch07]") {
    // The closed box holds its edges, and so can the objects inside (a quad's corner lies on its
    // box). Each ray here passes exactly through a point P of an edge or a corner and touches the
    // box nowhere else: the exact slab intervals meet in the single point t = p / q. P, the
    // origin o = P - p c and the direction d = q c have small integer coordinates, so the ray is
    // exact; but p / q is not a float, and each axis rounds (P - o) * (1 / d) = p c_a / (q c_a)
    // its own way. When the far end of one axis falls an ulp below the near end of another, only
    // the far-distance factor 1 + 4 eps keeps the hit. (Without it, 9% of these rays are lost.)
    const aabb box(point3(-1, 0, 1), point3(2, 3, 5));
    rt::pcg32 rng(8, 3);
    const int denominators[] = {3, 5, 7, 11, 13};
    const real offset        = std::max(real(1e-6), 4096 * std::numeric_limits<real>::epsilon());
    int rays = 0, missed = 0, false_hits = 0;
    for (int i = 0; i < 20000; ++i) {
        // P: each coordinate at the box's min or max (a corner), or, on an edge, one of them an
        // interior integer.
        point3 p;
        int outward[3];  // +1 at max, -1 at min, 0 strictly inside the slab
        const int free_axis = i % 2 == 0 ? random_int(rng, 0, 2) : -1;
        for (int a = 0; a < 3; ++a) {
            const interval& slab = box.axis_interval(a);
            if (a == free_axis) {
                p[a]       = real(random_int(rng, int(slab.min) + 1, int(slab.max) - 1));
                outward[a] = 0;
            } else {
                outward[a] = random_int(rng, 0, 1) ? 1 : -1;
                p[a]       = outward[a] > 0 ? slab.max : slab.min;
            }
        }
        // c touches only P when, on the bounded axes, it moves outward on one and inward on
        // another (so before P the ray is outside the one slab, after P outside the other).
        vec3 c;
        bool in = false, out = false;
        for (int a = 0; a < 3; ++a) {
            const int size = random_int(rng, 1, 9);
            const int ca   = size * (random_int(rng, 0, 1) ? 1 : -1);
            c[a]           = real(ca);
            if (outward[a] != 0) (outward[a] * ca > 0 ? out : in) = true;
        }
        if (!(in && out)) continue;
        const int q    = denominators[random_int(rng, 0, 4)];
        const vec3 d   = real(q) * c;
        const point3 o = p - real(random_int(rng, 1, 16)) * c;
        ++rays;
        if (!hits(box, o, d)) {
            UNSCOPED_INFO("missed: origin " << o << ", direction " << d << ", touching " << p);
            ++missed;
        }
        // Moved outward on both bounded axes by 1e-6 (4e-4 for a float, 32 of its ulps at the
        // origins' ~150), the same ray misses: the factor is a few ulps, not a fudge.
        vec3 shift;
        for (int a = 0; a < 3; ++a) shift[a] = offset * real(outward[a]);
        if (hits(box, o + shift, d)) {
            UNSCOPED_INFO("hit " << offset << " outside: origin " << o + shift << ", direction "
                                 << d);
            ++false_hits;
        }
    }
    CHECK(rays > 5000);
    CHECK(missed == 0);
    CHECK(false_hits == 0);
}

TEST_CASE("aabb: a flat box stays flat, and is hit from both sides and at grazing angles",
          "[ch07]") {
    // The box of a quad in the plane y = 0: zero thickness, exactly as given (no padding).
    const aabb flat(point3(0, 0, 0), point3(1, 0, 1));
    CHECK(flat.y.min == 0);
    CHECK(flat.y.max == 0);
    CHECK(flat.x.min == 0);
    CHECK(flat.x.max == 1);
    CHECK_FALSE(flat.empty());
    CHECK(flat.half_area() == 1);  // the area of its one face
    CHECK(flat.centroid().y() == 0);
    // A thin box keeps its thickness, however small: nothing is widened.
    const aabb thin(interval(0, 1), interval(2, 2 + real(1e-5)), interval(0, 1));
    CHECK(thin.y.min == 2);
    CHECK(thin.y.max == 2 + real(1e-5));

    rt::pcg32 rng(4, 4);
    int missed = 0, false_hits = 0;
    // Crossing the plane 4096 ulps of 1 outside the square (9e-13 for a double), steeply: the
    // ray leaves the zero-thickness slab at once, so only rounding (a few ulps of the
    // coordinates and of t) could make it hit.
    const real beside = 4096 * eps;
    for (int i = 0; i < 20000; ++i) {
        // Cross the plane y = 0 at a point of the square, from above or below, at an angle to
        // the plane from 1 down to 1e-8 radians.
        const real x = uniform(rng, 0, 1), z = uniform(rng, 0, 1);
        const real angle   = std::pow(real(10), uniform(rng, -8, 0));
        const real heading = uniform(rng, 0, 2 * rt::pi);
        const real side    = i % 2 == 0 ? 1 : -1;
        const vec3 d(std::cos(angle) * std::cos(heading), -side * std::sin(angle),
                     std::cos(angle) * std::sin(heading));
        const point3 target(x, 0, z);
        const real back = uniform(rng, real(0.001), 10);
        if (!hits(flat, target - back * d, d)) ++missed;
        // Crossing just outside the square, at least 45 degrees to the plane.
        const real steep = uniform(rng, rt::pi / 4, rt::pi / 2);
        const vec3 s(std::cos(steep) * std::cos(heading), -side * std::sin(steep),
                     std::cos(steep) * std::sin(heading));
        const point3 outside(i % 4 < 2 ? -beside : 1 + beside, 0, z);
        if (hits(flat, outside - back * s, s)) ++false_hits;
    }
    CHECK(missed == 0);
    CHECK(false_hits == 0);
    // Exactly parallel to the plane: inside the flat slab only when the ray lies in the plane
    // (0 * inf = NaN there, with either zero as the direction's y); off the plane by any amount,
    // even the smallest a real holds (a denormal), it misses.
    for (real zero : {real(0), negative_zero}) {
        CAPTURE(zero);
        CHECK(hits(flat, point3(-1, 0, 0.5), vec3(1, zero, 0)));
        CHECK(hits(flat, point3(-1, negative_zero, 0.5), vec3(1, zero, 0.25)));
        CHECK(hits(flat, point3(0.5, 0, 0.5), vec3(0, zero, -1)));  // starting on the face
        for (real off : {std::numeric_limits<real>::denorm_min(), eps, real(4e-5)}) {
            CAPTURE(off);
            CHECK_FALSE(hits(flat, point3(-1, off, 0.5), vec3(1, zero, 0)));
            CHECK_FALSE(hits(flat, point3(-1, -off, 0.5), vec3(1, zero, 0)));
        }
    }
}

TEST_CASE(
    "aabb: a flat box is hit by every ray through it, at scales 1e-4 to 1e4 and far from the "
    "origin",
    "[hardcase][ch07]") {
    // Exact rays through exact points, so the answer is known. Everything lies on a grid of step
    // h = 2^e (e in [-14, 13]: boxes of 1e-4 .. 1e4) around a center B that is the origin or
    // 2^(digits - 8) steps from it on each axis, of either sign (2^45 h for a double, where an
    // ulp is h / 128; 2^16 h for a float). The box is a rectangle of the grid in the plane
    // x_k = const; P is one of its corners, a point of an edge, an inner point, or (to check that
    // the test can fail) a point one step outside it. The ray runs from o = P - m h c to P along
    // d = q c: c has integer components up to 2^20 (2^6 for a float), so the angle to the plane
    // goes from 90 degrees down to 1e-6 (0.01), some components are +0 or -0 (1 / d infinite),
    // and a tenth of the rays lie in the plane. q is 3, 5, 7, 11 or 13 so that 1 / d is not
    // exact: every slab distance is rounded.
    constexpr int digits = std::numeric_limits<real>::digits;
    const int c_bits     = digits / 2 - 6;
    const real far_steps = std::ldexp(real(1), digits - 8);
    const int qs[]       = {3, 5, 7, 11, 13};
    rt::pcg32 rng(14, 2);
    long long through = 0, missed = 0, beside = 0, false_hits = 0, behind_hits = 0, in_plane = 0;
    for (int i = 0; i < 200000; ++i) {
        const real h = std::ldexp(real(1), random_int(rng, -14, 13));
        point3 center;
        for (int a = 0; a < 3; ++a) center[a] = real(random_int(rng, -1, 1)) * far_steps * h;
        if (i % 4 == 0) center = point3(0, 0, 0);
        const int k = i % 3, a1 = (k + 1) % 3, a2 = (k + 2) % 3;
        // The rectangle, in steps: the plane at `level`, [lo, hi] on a1 and a2.
        const int level = random_int(rng, -32, 32);
        int lo[3], hi[3], at[3];
        for (int a : {a1, a2}) {
            lo[a] = random_int(rng, -32, 31);
            hi[a] = random_int(rng, lo[a] + 1, 32);
        }
        // P, in steps: on a corner, an edge, inside, or one step outside along one axis.
        const int kind = i % 4;
        for (int a : {a1, a2}) {
            const bool end = kind == 0 || (kind == 1 && a == a1);
            at[a] = end ? (random_int(rng, 0, 1) ? hi[a] : lo[a]) : random_int(rng, lo[a], hi[a]);
        }
        if (kind == 3) at[a1] = random_int(rng, 0, 1) ? hi[a1] + 1 : lo[a1] - 1;
        at[k] = level;
        point3 box_lo, box_hi, p;
        box_lo[k] = box_hi[k] = p[k] = center[k] + h * real(level);
        for (int a : {a1, a2}) {
            box_lo[a] = center[a] + h * real(lo[a]);
            box_hi[a] = center[a] + h * real(hi[a]);
            p[a]      = center[a] + h * real(at[a]);
        }
        const aabb flat(box_lo, box_hi);
        // The direction: each component 0 (of either sign) or an integer of 1 .. 2^c_bits.
        vec3 c;
        for (int a = 0; a < 3; ++a) {
            const int magnitude = int(std::ldexp(1.0, random_int(rng, 0, c_bits)));
            const int size      = random_int(rng, (magnitude + 1) / 2, magnitude);
            c[a]                = real(random_int(rng, 0, 1) ? size : -size);
        }
        const bool lies_in_plane = i % 10 == 9;
        if (lies_in_plane) c[k] = 0;
        if (i % 7 == 0) c[a1] = 0;
        if (c[k] == 0 && c[a1] == 0 && c[a2] == 0) c[a2] = 1;
        const real q = real(qs[random_int(rng, 0, 4)]);
        vec3 d       = q * c;
        for (int a = 0; a < 3; ++a) {
            if (d[a] == 0 && random_int(rng, 0, 1)) d[a] = negative_zero;
        }
        const point3 o = p - real(random_int(rng, 1, 16)) * h * c;
        CAPTURE(h, center, k, p, o, d);
        if (kind == 3) {
            if (lies_in_plane) continue;  // along the plane it may still cross the rectangle
            ++beside;
            if (hits(flat, o, d)) ++false_hits;
            continue;
        }
        ++through;
        in_plane += lies_in_plane;
        if (!hits(flat, o, d)) {
            if (++missed <= 5) UNSCOPED_INFO("missed: origin " << o << ", direction " << d);
        }
        // Turned around, the ray leaves the plane behind it (unless it lies in it).
        if (!lies_in_plane && hits(flat, o, -d)) ++behind_hits;
    }
    INFO(through << " rays through the box (" << in_plane << " in its plane), " << beside
                 << " beside it");
    CHECK(through > 100000);
    CHECK(in_plane > 5000);
    CHECK(beside > 20000);
    CHECK(missed == 0);
    CHECK(false_hits == 0);
    CHECK(behind_hits == 0);
}

TEST_CASE("aabb: a flat box far from the origin, where an ulp is 2.4e-4, is hit by crossing rays",
          "[hardcase][ch07]") {
    // At |y| = 2^40 an ulp is 2^-12 = 2.4e-4 (the book's 1e-4 padding would round away there).
    // On a crossing ray both y distances are equal, and the far-distance factor keeps the
    // interval non-empty. Random, inexact rays: above and below the plane, on either side of
    // the origin.
    // Float's ulp is 2^-12 already at |y| = 2^11 (24 bits against double's 53): the same ulp
    // against the same box and rays, so the same case, at the height where float has it. At
    // 2^40 float's ulp is 2^17: rays 1 to 100 away would start in the plane itself.
    const int height = std::numeric_limits<real>::digits - 13;  // 40 (double), 11 (float)
    for (const real y : {std::ldexp(real(1), height), -std::ldexp(real(1), height)}) {
        CAPTURE(y);
        const aabb flat(point3(-1, y, -1), point3(1, y, 1));
        CHECK(flat.y.min == y);
        CHECK(flat.y.max == y);
        CHECK_FALSE(flat.empty());
        rt::pcg32 rng(6, 6);
        int missed = 0;
        for (int i = 0; i < 10000; ++i) {
            const point3 target(uniform(rng, real(-0.99), real(0.99)), y,
                                uniform(rng, real(-0.99), real(0.99)));
            const real side = i % 2 == 0 ? 1 : -1;
            vec3 d          = random_unit(rng);
            d[1]            = -side * (std::fabs(d[1]) + real(0.1));
            const point3 o  = target - uniform(rng, 1, 100) * d;
            if (!hits(flat, o, d)) ++missed;
        }
        CHECK(missed == 0);
    }
}

TEST_CASE("aabb: the empty box is missed by every ray", "[ch07]") {
    // Empty means min > max on an axis: +inf > -inf by default. Whatever the ray, there is no t
    // inside it. Also an empty box built from intervals, and the union of two empty boxes.
    const aabb boxes[] = {aabb(), aabb(interval::empty(), interval(0, 1), interval(0, 1)),
                          aabb(interval(0, 1), interval(0, 1), interval(3, 2)),
                          aabb(aabb(), aabb())};
    rt::pcg32 rng(2, 9);
    for (const aabb& box : boxes) {
        CHECK(box.empty());
        CHECK(box.half_area() == 0);
        int hit = 0;
        for (int i = 0; i < 2000; ++i) {
            const point3 o = i % 10 == 0 ? point3(0, 0, 0) : random_in_cube(rng, 10);
            vec3 d         = random_unit(rng);
            if (i % 7 == 0) d[i % 3] = 0;
            if (i % 11 == 0) d = vec3(0, 0, i % 2 ? real(1) : real(-1));
            if (hits(box, o, d, interval::universe())) ++hit;
            if (hits(box, o, d)) ++hit;
        }
        CHECK(hit == 0);
    }
}

TEST_CASE("aabb: union, centroid, half_area and longest_axis", "[ch07]") {
    const aabb a(point3(1, -2, 0), point3(3, 2, 8));  // corners in any order:
    const aabb b(point3(3, 2, 0), point3(1, -2, 8));
    for (int axis = 0; axis < 3; ++axis) {
        CHECK(a.axis_interval(axis).min == b.axis_interval(axis).min);
        CHECK(a.axis_interval(axis).max == b.axis_interval(axis).max);
    }
    CHECK(a.x.min == 1);
    CHECK(a.x.max == 3);
    CHECK(&a.axis_interval(0) == &a.x);
    CHECK(&a.axis_interval(1) == &a.y);
    CHECK(&a.axis_interval(2) == &a.z);

    const point3 c = a.centroid();
    CHECK(c.x() == 2);
    CHECK(c.y() == 0);
    CHECK(c.z() == 4);
    // Faces 2 x 4, 4 x 8 and 8 x 2.
    CHECK(a.half_area() == 56);
    CHECK(a.longest_axis() == 2);
    CHECK(aabb(point3(0, 0, 0), point3(5, 1, 2)).longest_axis() == 0);
    CHECK(aabb(point3(0, 0, 0), point3(1, 5, 2)).longest_axis() == 1);
    CHECK(aabb(point3(0, 0, 0), point3(1, 2, 2)).longest_axis() == 2);  // ties go to the later
    CHECK(aabb(point3(0, 0, 0), point3(2, 2, 1)).longest_axis() == 1);  // axis
    CHECK(aabb(point3(0, 0, 0), point3(2, 2, 2)).longest_axis() == 2);

    // The union holds both, exactly: min and max lose nothing.
    const aabb d(point3(-1, 5, 2), point3(0, 6, 3));
    const aabb u(a, d);
    CHECK(u.x.min == -1);
    CHECK(u.x.max == 3);
    CHECK(u.y.min == -2);
    CHECK(u.y.max == 6);
    CHECK(u.z.min == 0);
    CHECK(u.z.max == 8);
    // The empty box is the identity of the union, on both sides.
    for (const aabb& e : {aabb(aabb(), a), aabb(a, aabb())}) {
        for (int axis = 0; axis < 3; ++axis) {
            CHECK(e.axis_interval(axis).min == a.axis_interval(axis).min);
            CHECK(e.axis_interval(axis).max == a.axis_interval(axis).max);
        }
    }
    // A point's box is the point: zero size and zero area, not empty. A ray through the point
    // still hits it (every axis puts the point at t = 3, each with its own rounding, and the
    // far-distance factor keeps them overlapping); the same ray moved 1/1024 aside misses.
    const point3 point(1, 2, 3);
    const aabb point_box(point, point);
    for (int axis = 0; axis < 3; ++axis) {
        CHECK(point_box.axis_interval(axis).min == real(axis + 1));
        CHECK(point_box.axis_interval(axis).max == real(axis + 1));
    }
    CHECK_FALSE(point_box.empty());
    CHECK(point_box.half_area() == 0);
    // A line (two flat axes) has zero area too.
    const aabb line(point3(0, 2, 3), point3(4, 2, 3));
    CHECK(line.half_area() == 0);
    CHECK(line.longest_axis() == 0);
    for (const vec3& dir : {vec3(3, 5, 7), vec3(-7, 11, 13), vec3(13, -3, -11), vec3(0, -5, 3)}) {
        CAPTURE(dir);
        CHECK(hits(point_box, point - 3 * dir, dir));
        CHECK(hits(line, point - 3 * dir, dir));
        CHECK_FALSE(hits(point_box, point - 3 * dir + vec3(real(1) / 1024, 0, 0), dir));
        CHECK_FALSE(hits(line, point - 3 * dir + vec3(0, real(1) / 1024, 0), dir));
    }
}
