// Tests for instance.h (chapter 11): translate and rotate about x, y and z. An instance moves the
// ray into the object's space, hits the object there and carries the hit back, so the tests
// compare instanced hits with hits computed directly in either space: the rotation and its
// inverse, nested rotations that cancel, rotated boxes seen from every face, bounding boxes,
// a translated sphere against a shifted ray, a whole translated scene against a moved camera,
// the surface coordinates of an instanced sphere (those of the object's own frame), and rays
// spawned off instanced surfaces at many scales.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "ch03/material_helpers.h"
#include "rt/accel/bvh.h"
#include "rt/camera/thin_lens_camera.h"
#include "rt/core/error.h"
#include "rt/core/rng.h"
#include "rt/geometry/box.h"
#include "rt/geometry/instance.h"
#include "rt/geometry/quad.h"
#include "rt/geometry/spawn_ray.h"
#include "rt/geometry/sphere.h"
#include "rt/integrators/path_tracer.h"
#include "rt/materials/dielectric.h"
#include "rt/materials/lambertian.h"
#include "rt/materials/textured_lambertian.h"
#include "rt/render/film.h"
#include "rt/render/render.h"
#include "rt/samplers/independent_sampler.h"
#include "rt/textures/texture.h"
#include "test_helpers.h"

namespace {

using rt::axis, rt::color, rt::point3, rt::real, rt::vec3;

constexpr real eps = std::numeric_limits<real>::epsilon();
const rt::interval forward(0, rt::infinity);
const axis all_axes[]      = {axis::x, axis::y, axis::z};
const real listed_angles[] = {0, 45, 90, 180, -18, 15, 137.5};

using rt_test::any_material, rt_test::exactly, rt_test::log_uniform, rt_test::random_in_cube,
    rt_test::random_in_hemisphere, rt_test::random_tangent, rt_test::random_unit, rt_test::uniform;

const char* name(axis a) {
    return a == axis::x ? "x" : (a == axis::y ? "y" : "z");
}

axis random_axis(rt::pcg32& rng) {
    return all_axes[rng.next_u32() % 3];
}

// A box [lo, hi] and one of its faces, in the box's own space.
struct box_face {
    vec3 normal;    // outward
    point3 middle;  // center of the face
};

std::array<box_face, 6> faces_of(const point3& lo, const point3& hi) {
    point3 c = 0.5 * (lo + hi);
    return {{{vec3(1, 0, 0), point3(hi.x(), c.y(), c.z())},
             {vec3(-1, 0, 0), point3(lo.x(), c.y(), c.z())},
             {vec3(0, 1, 0), point3(c.x(), hi.y(), c.z())},
             {vec3(0, -1, 0), point3(c.x(), lo.y(), c.z())},
             {vec3(0, 0, 1), point3(c.x(), c.y(), hi.z())},
             {vec3(0, 0, -1), point3(c.x(), c.y(), lo.z())}}};
}

// A box turned about x, then y, then z and then moved: the instance and its transform.
struct placed_box {
    point3 lo, hi;
    std::shared_ptr<rt::rotate> rx, ry, rz;
    std::shared_ptr<rt::translate> world;
    vec3 offset;

    placed_box(const point3& a, const point3& b, real ax, real ay, real az, const vec3& off)
        : lo(a), hi(b), offset(off) {
        rx    = std::make_shared<rt::rotate>(rt::box(a, b, any_material()), axis::x, ax);
        ry    = std::make_shared<rt::rotate>(rx, axis::y, ay);
        rz    = std::make_shared<rt::rotate>(ry, axis::z, az);
        world = std::make_shared<rt::translate>(rz, off);
    }
    vec3 direction_to_world(const vec3& v) const {
        return rz->to_world(ry->to_world(rx->to_world(v)));
    }
    point3 to_world(const point3& p) const { return direction_to_world(p) + offset; }
};

}  // namespace

TEST_CASE("instance: rotate follows the header's right-handed formulas about x, y and z",
          "[ch11]") {
    auto obj = rt::box(point3(-1, -1, -1), point3(1, 1, 1), any_material());
    // A quarter turn counterclockwise seen from the positive axis: y -> z about x, z -> x about
    // y, x -> y about z. sin and cos of 90 degrees are 1 and ~6e-17, so compare to a few ulps.
    struct quarter {
        axis about;
        vec3 from, to;
    };
    for (const quarter& q : {quarter{axis::x, vec3(0, 1, 0), vec3(0, 0, 1)},
                             quarter{axis::y, vec3(0, 0, 1), vec3(1, 0, 0)},
                             quarter{axis::z, vec3(1, 0, 0), vec3(0, 1, 0)}}) {
        INFO("about " << name(q.about));
        rt::rotate r(obj, q.about, 90);
        CHECK((r.to_world(q.from) - q.to).length() <= 4 * eps);
        CHECK((r.to_object(q.to) - q.from).length() <= 4 * eps);
    }
    // The general formulas, evaluated here independently, for an angle with sin, cos != 0, 1.
    const real deg = 137.5, th = rt::degrees_to_radians(deg);
    const real c = std::cos(th), s = std::sin(th);
    const vec3 v(real(0.3), real(-1.7), real(2.9));
    const vec3 about_x(v.x(), c * v.y() - s * v.z(), s * v.y() + c * v.z());
    const vec3 about_y(c * v.x() + s * v.z(), v.y(), -s * v.x() + c * v.z());
    const vec3 about_z(c * v.x() - s * v.y(), s * v.x() + c * v.y(), v.z());
    // Two products and a sum per coordinate, in possibly another order: a few ulps of |v|.
    const real tol = 8 * eps * v.length();
    CHECK((rt::rotate(obj, axis::x, deg).to_world(v) - about_x).length() <= tol);
    CHECK((rt::rotate(obj, axis::y, deg).to_world(v) - about_y).length() <= tol);
    CHECK((rt::rotate(obj, axis::z, deg).to_world(v) - about_z).length() <= tol);
    CHECK_THROWS_AS(rt::rotate(obj, axis::x, rt::infinity), rt::user_error);
    CHECK_THROWS_WITH(rt::rotate(obj, axis::y, rt::infinity),
                      Catch::Contains("rotation angle must be finite, got inf"));
    CHECK_THROWS_AS(rt::rotate(obj, axis::z, std::numeric_limits<real>::quiet_NaN()),
                    rt::user_error);
    CHECK_THROWS_AS(rt::rotate(std::shared_ptr<rt::bvh>(), axis::x, 10), rt::user_error);
    CHECK_THROWS_AS(rt::translate(std::shared_ptr<rt::sphere>(), vec3(1, 0, 0)), rt::user_error);
}

TEST_CASE("instance: to_object(to_world(v)) == v about x, y and z, for 1e5 vectors and angles",
          "[ch11]") {
    // Each turn computes cos v_a - s v_b and s v_a + c v_b: a rounding of ~2 ulps of |v| per
    // coordinate; and c^2 + s^2 differs from 1 by ~2 ulps (each correctly rounded to 1/2 ulp).
    // Both turns together: ~6 ulps of |v|. 16 ulps (3.6e-15 in double, far inside the 1e-12
    // this must hold to) also leaves room for a libm whose sin and cos are 1 ulp off.
    auto obj = rt::box(point3(-1, -1, -1), point3(1, 1, 1), any_material());
    rt::pcg32 rng(21, 0);
    const int n    = 100000;
    real worst     = 0;  // relative to |v|
    real worst_len = 0;  // | |to_world(v)| - |v| | / |v|: a rotation keeps lengths
    int failures   = 0;
    std::string first;
    for (int k = 0; k < n; ++k) {
        axis about = all_axes[k % 3];
        // Half the cases take the listed angles, half random ones in (-720, 720).
        real deg = k % 2 == 0 ? listed_angles[(k / 2) % 7] : uniform(rng, -720, 720);
        rt::rotate r(obj, about, deg);
        vec3 v       = log_uniform(rng, -3, 3) * random_unit(rng);
        vec3 back    = r.to_object(r.to_world(v));
        vec3 forth   = r.to_world(r.to_object(v));
        real error   = std::max((back - v).length(), (forth - v).length()) / v.length();
        real len_err = std::fabs(r.to_world(v).length() - v.length()) / v.length();
        worst        = std::max(worst, error);
        worst_len    = std::max(worst_len, len_err);
        if ((error > 16 * eps || len_err > 16 * eps) && failures++ == 0) {
            std::ostringstream what;
            what.precision(17);
            what << "about " << name(about) << " by " << deg << ": v " << v << " came back as "
                 << back;
            first = what.str();
        }
    }
    INFO("worst relative round-trip error " << worst << ", worst length change " << worst_len);
    INFO(failures << " of " << n << " failed; first: " << first);
    CHECK(failures == 0);
    // The bound the chapter promises, for the double build (float's own ulp is 1.2e-7).
    if constexpr (std::numeric_limits<real>::digits >= 53) CHECK(worst <= real(1e-12));
}

TEST_CASE("instance: rotating by theta and then by -theta gives the object's own hits", "[ch11]") {
    // The box [-0.5, 1.5] x [1, 2.5] x [-2, -1.25], off the origin so the rotations move it.
    const point3 lo(-0.5, 1, -2), hi(1.5, 2.5, -1.25);
    auto b         = rt::box(lo, hi, any_material());
    const point3 c = 0.5 * (lo + hi);
    rt::pcg32 rng(22, 0);
    int hits = 0, failures = 0;
    std::string first;
    for (axis about : all_axes) {
        for (real deg : listed_angles) {
            auto there_and_back = std::make_shared<rt::rotate>(
                std::make_shared<rt::rotate>(b, about, deg), about, -deg);
            for (int k = 0; k < 1000; ++k) {
                // From 10 away toward a random point inside the box: always a hit.
                point3 origin = c + 10 * random_unit(rng);
                point3 target = point3(uniform(rng, lo.x(), hi.x()), uniform(rng, lo.y(), hi.y()),
                                       uniform(rng, lo.z(), hi.z()));
                rt::ray r(origin, target - origin);
                rt::hit_record want, got;
                bool hw = b->hit(r, forward, want), hg = there_and_back->hit(r, forward, got);
                hits += hw;
                // The turned ray's origin and direction are off by ~6 ulps of their size (see
                // the round-trip test): the ray moves sideways by at most 6 eps (|o| + t |d|),
                // which moves the hit along it by that over the cosine of incidence. 16 eps
                // leaves room; the normal is the same unit vector turned twice (~6 eps).
                bool ok = hw && hg && want.front_face == got.front_face;
                if (ok) {
                    real cos_in   = std::fabs(dot(rt::unit_vector(r.direction()), want.normal));
                    real scale    = origin.length() + want.t * r.direction().length();
                    real along    = 16 * eps * scale / cos_in;
                    real travel_d = std::fabs(got.t - want.t) * r.direction().length();
                    ok            = travel_d <= along &&
                         (got.p - want.p).length() <= along + 16 * eps * scale &&
                         (got.normal - want.normal).length() <= 16 * eps;
                }
                if (!ok && failures++ == 0) {
                    std::ostringstream what;
                    what.precision(17);
                    what << "about " << name(about) << " by " << deg << ": t " << want.t << " vs "
                         << got.t << ", normal " << want.normal << " vs " << got.normal;
                    first = what.str();
                }
            }
        }
    }
    INFO(failures << " failures; first: " << first);
    CHECK(hits == 3 * 7 * 1000);
    CHECK(failures == 0);
}

TEST_CASE("instance: a rotated, moved box is hit on every face with its outward normal", "[ch11]") {
    // Angles past 45 and 90 degrees about all three axes, the book's 15 and -18, and 0.
    const real angle_sets[][3] = {{50, 100, 137.5}, {-18, 15, 91},   {180, 45, -120},
                                  {0, 0, 0},        {270, -135, 60}, {real(89.9), 90, real(90.1)}};
    const point3 lo(1, -2, 0.5), hi(3, 1, 1.25);
    for (const auto& a : angle_sets) {
        placed_box pb(lo, hi, a[0], a[1], a[2], vec3(-3, 7, 2));
        const point3 center = pb.to_world(0.5 * (lo + hi));
        for (const box_face& f : faces_of(lo, hi)) {
            const point3 p = pb.to_world(f.middle);
            const vec3 n   = pb.direction_to_world(f.normal);
            INFO("angles " << a[0] << ", " << a[1] << ", " << a[2] << "; face " << f.normal
                           << " -> world " << n);
            // Straight in, and at a tilt: either way the first hit is this face.
            for (const vec3& tilt : {vec3(0, 0, 0), vec3(0.25, -0.375, 0.125)}) {
                point3 origin = p + 3 * n + tilt;
                rt::hit_record rec;
                REQUIRE(pb.world->hit(rt::ray(origin, p - origin), forward, rec));
                CHECK(rec.front_face);
                // Turned three times: a few ulps from unit and from the face's turned normal.
                CHECK(std::fabs(rec.normal.length() - 1) <= 8 * eps);
                CHECK((rec.normal - n).length() <= 16 * eps);
                CHECK(dot(rec.normal, rec.p - center) > 0);
                // On target: the coordinates are ~10, rounded in each of four transforms.
                CHECK((rec.p - p).length() <= 64 * eps * 10);
            }
            // From the center, every face is hit from behind.
            rt::hit_record rec;
            REQUIRE(pb.world->hit(rt::ray(center, p - center), forward, rec));
            CHECK_FALSE(rec.front_face);
            CHECK((rec.normal + n).length() <= 16 * eps);
        }
    }
}

TEST_CASE("instance: bounding boxes of rotated and translated objects contain the object",
          "[ch11]") {
    rt::pcg32 rng(23, 0);
    int outside = 0, loose = 0, checked = 0;
    for (int k = 0; k < 300; ++k) {
        // A random box, moved, turned about one axis (k % 3 == 0, 1, 2) or about all three
        // (k % 4 == 3); its surface sampled at 100 points.
        point3 lo = point3(0, 0, 0) + random_in_cube(rng, 5);
        vec3 size(log_uniform(rng, -1, 1), log_uniform(rng, -1, 1), log_uniform(rng, -1, 1));
        real angle[3]        = {0, 0, 0};
        const bool all_three = k % 4 == 3;
        for (int a = 0; a < 3; ++a) {
            real deg = uniform(rng, -360, 360);
            if (all_three || a == k % 3) angle[a] = deg;
        }
        placed_box pb(lo, lo + size, angle[0], angle[1], angle[2], random_in_cube(rng, 10));
        rt::aabb bb = pb.world->bounding_box();
        // Containment holds exactly: a point is turned by the same to_world as the corners,
        // off by at most sqrt(2) eps M from its exact place, and each rotate widens its box by
        // 4 eps M; the move rounds points and box ends alike (rounding is monotonic).
        for (int i = 0; i < 100; ++i) {
            // A random face, a random point on it.
            int axis_n = int(rng.next_u32() % 3);
            point3 q(uniform(rng, lo.x(), lo.x() + size.x()),
                     uniform(rng, lo.y(), lo.y() + size.y()),
                     uniform(rng, lo.z(), lo.z() + size.z()));
            q[axis_n] = rng.uniform() < 0.5 ? lo[axis_n] : lo[axis_n] + size[axis_n];
            point3 w  = pb.to_world(q);
            ++checked;
            outside += !(w.x() >= bb.x.min && w.x() <= bb.x.max && w.y() >= bb.y.min &&
                         w.y() <= bb.y.max && w.z() >= bb.z.min && w.z() <= bb.z.max);
        }
        if (all_three) continue;
        // One real turn (the other two by 0 are exact identities): the box's corners are on the
        // object, so the box of its turned corners is the tight bounding box. Only rotate's own
        // widening may loosen it: 4 eps M a side per rotate, M the largest |coordinate| of its
        // object's box (below 30 here), grown by at most sqrt(2) in each later turn, plus the
        // rounding of the move: under 4 eps 30 (1 + sqrt(2) + 2) + 64 eps < 600 eps a side.
        // A box built from the wrong corners, or turned the wrong way, is off by a good part of
        // the box (>= 0.1 here); the book's padding of flat boxes (1e-4) would be off by 5e-5.
        rt::aabb corners;
        for (int c = 0; c < 8; ++c) {
            point3 q(c & 1 ? lo.x() + size.x() : lo.x(), c & 2 ? lo.y() + size.y() : lo.y(),
                     c & 4 ? lo.z() + size.z() : lo.z());
            point3 w = pb.to_world(q);
            corners  = rt::aabb(corners, rt::aabb(w, w));
        }
        const real widening = 600 * eps;
        for (int a = 0; a < 3; ++a) {
            const rt::interval& got  = bb.axis_interval(a);
            const rt::interval& want = corners.axis_interval(a);
            if (got.min < want.min - widening || got.max > want.max + widening) ++loose;
        }
    }
    INFO(outside << " of " << checked << " surface points outside the bounding box; " << loose
                 << " bounding-box sides looser than the turned corners");
    CHECK(outside == 0);
    CHECK(loose == 0);

    // A sphere turned twice and moved: its surface stays inside too (the box of the turned box
    // of a sphere is looser than needed, but must contain it), exactly: the first turn's
    // widening covers the ulp by which a computed surface point can pass center + radius.
    const point3 c(2, -1, 0.5);
    const vec3 offset(100, -50, 7);
    auto ball  = std::make_shared<rt::sphere>(c, 0.75, any_material());
    auto inner = std::make_shared<rt::rotate>(ball, axis::x, 33);
    auto outer = std::make_shared<rt::rotate>(inner, axis::z, -71);
    rt::translate moved(outer, offset);
    rt::aabb bb        = moved.bounding_box();
    int sphere_outside = 0;
    for (int i = 0; i < 1000; ++i) {
        point3 w = outer->to_world(inner->to_world(c + real(0.75) * random_unit(rng))) + offset;
        sphere_outside += !(w.x() >= bb.x.min && w.x() <= bb.x.max && w.y() >= bb.y.min &&
                            w.y() <= bb.y.max && w.z() >= bb.z.min && w.z() <= bb.z.max);
    }
    CHECK(sphere_outside == 0);
}

TEST_CASE("instance: turning or moving an object with an empty box gives an empty box", "[ch11]") {
    // An empty bvh bounds nothing: its box is empty (min = +inf > max = -inf). Turning its
    // corners would give NaN (cos inf - sin (-inf) is inf - NaN at 0 degrees), so rotate keeps
    // the box empty, at every angle, and widens nothing; translate keeps it empty too.
    auto nothing = std::make_shared<rt::bvh>(std::vector<rt::bounded_object>{});
    REQUIRE(nothing->bounding_box().empty());
    for (axis about : all_axes) {
        for (real degrees : listed_angles) {
            CAPTURE(name(about), degrees);
            auto turned         = std::make_shared<rt::rotate>(nothing, about, degrees);
            const rt::aabb box  = turned->bounding_box();
            const rt::aabb left = rt::translate(turned, vec3(1, 2, 3)).bounding_box();
            CHECK(box.empty());
            CHECK(left.empty());
            for (int a = 0; a < 3; ++a) {
                CHECK_FALSE(std::isnan(box.axis_interval(a).min));
                CHECK_FALSE(std::isnan(box.axis_interval(a).max));
            }
            rt::hit_record rec;
            CHECK_FALSE(turned->hit(rt::ray(point3(0, 0, 0), vec3(1, 1, 1)), forward, rec));
        }
    }
}

TEST_CASE("instance: a translated sphere is hit where the shifted ray hits the sphere", "[ch11]") {
    const point3 center(0.5, -1, 2);
    const vec3 offset(7.25, -3.5, 100.125);
    auto ball  = std::make_shared<rt::sphere>(center, 1.5, any_material());
    auto moved = std::make_shared<rt::translate>(ball, offset);
    rt::sphere there(center + offset, 1.5, any_material());
    rt::pcg32 rng(24, 0);
    int hits = 0, not_same = 0, not_close = 0;
    for (int k = 0; k < 10000; ++k) {
        point3 origin = center + offset + 5 * random_unit(rng);
        point3 target = center + offset + 2 * random_in_cube(rng, 1);
        rt::ray r(origin, target - origin);
        rt::hit_record a, b, c;
        bool ha = moved->hit(r, forward, a);
        // translate computes the shifted ray's origin as origin - offset: the same ray here
        // gives the very same hit, with p moved back by the offset.
        bool hb = ball->hit(rt::ray(origin - offset, r.direction()), forward, b);
        if (ha != hb || (ha && (a.t != b.t || !exactly(a.p, b.p + offset) ||
                                !exactly(a.normal, b.normal) || a.front_face != b.front_face)))
            ++not_same;
        // A sphere built at center + offset rounds differently: the two rays differ by the
        // rounding of coordinates of size ~100 (a few ulps of 100) and the two solves by a few
        // ulps of |origin - center| (~5), which moves the hit along the ray by that over the
        // cosine of incidence. 64 ulps of 100 over the cosine bounds both; grazing hits
        // (cos < 0.01), where the root's own conditioning takes over, are left out.
        bool hc = there.hit(r, forward, c);
        if (ha && hc) {
            ++hits;
            const real length = r.direction().length();
            const real cos_in = std::fabs(dot(r.direction(), c.normal)) / length;
            if (cos_in >= real(0.01) && std::fabs(a.t - c.t) * length > 64 * eps * 100 / cos_in)
                ++not_close;
        }
    }
    CHECK(hits > 2000);
    CHECK(not_same == 0);
    CHECK(not_close == 0);
    // Its bounding box is the sphere's, moved, and widened by 4 eps of its magnitude against the
    // rounding of the move (instance.cpp).
    rt::aabb moved_box = moved->bounding_box(), ball_box = rt::bounding_box(*ball);
    const real margin = 4 * eps * moved_box.magnitude();
    CHECK(moved_box.x.min <= ball_box.x.min + offset.x());
    CHECK(moved_box.x.min >= ball_box.x.min + offset.x() - 2 * margin);
    CHECK(moved_box.z.max >= ball_box.z.max + offset.z());
    CHECK(moved_box.z.max <= ball_box.z.max + offset.z() + 2 * margin);
}

TEST_CASE("instance: translating the whole world and the camera together leaves the image alone",
          "[ch11]") {
    // A glass sphere on a Lambertian floor under the sky, 32 x 32 pixels at 8 samples. The same
    // scene moved by `offset`, seen from a camera moved by `offset`, is the same picture: the
    // sky depends on directions only. Only rounding differs (directions and hit points to
    // ~1e-15 relative), so almost every path follows the same choices and the pixel differs
    // by far less than 1e-4 (the image stores floats, 6e-8 relative). A path diverges only if
    // a random number falls within rounding of a decision threshold (a Fresnel choice, a
    // silhouette): then its pixel changes by ~(difference of two paths) / 8, far above 1e-4.
    // That should happen to no pixel, so 1% of the pixels (10) is a generous allowance.
    const vec3 offset(real(3.3), real(-0.7), real(1.9));
    rt::render_settings settings;
    settings.samples_per_pixel = 8;
    settings.max_depth         = 20;
    settings.seed              = 5;
    const rt::film film        = rt::film::for_aspect(32, 1);
    auto render_at             = [&](const vec3* shift) {
        std::vector<rt::bounded_object> objects;
        objects.push_back(std::make_shared<rt::quad>(
            point3(-10, 0, -10), vec3(20, 0, 0), vec3(0, 0, 20),
            std::make_shared<rt::lambertian>(color(real(0.5), real(0.6), real(0.4)))));
        objects.push_back(std::make_shared<rt::sphere>(point3(0, 1, 0), 1,
                                                       std::make_shared<rt::dielectric>(1.5)));
        std::shared_ptr<rt::hittable> world = std::make_shared<rt::bvh>(objects);
        point3 from(0, 1.5, 4), at(0, 1, 0);
        if (shift) {
            world = std::make_shared<rt::translate>(std::make_shared<rt::bvh>(objects), *shift);
            from += *shift;
            at += *shift;
        }
        rt::thin_lens_camera cam;
        cam.aspect_ratio = 1;
        cam.vfov         = 40;
        cam.lookfrom     = from;
        cam.lookat       = at;
        cam.initialize(film);
        const rt::path_tracer tracer(world, rt::background::sky());
        return rt::render(film, cam, tracer, settings).mean;
    };
    auto here     = render_at(nullptr);
    auto there    = render_at(&offset);
    int differing = 0;
    double worst = 0, worst_agreeing = 0;
    for (int j = 0; j < here.height(); ++j) {
        for (int i = 0; i < here.width(); ++i) {
            color d    = here.get(i, j) - there.get(i, j);
            double big = double(std::max({std::fabs(d.x()), std::fabs(d.y()), std::fabs(d.z())}));
            worst      = std::max(worst, big);
            if (big >= 1e-4)
                ++differing;
            else
                worst_agreeing = std::max(worst_agreeing, big);
        }
    }
    INFO(differing << " of " << here.width() * here.height()
                   << " pixels differ by 1e-4 or more; largest difference " << worst
                   << ", largest among the others " << worst_agreeing);
    CHECK(differing <= here.width() * here.height() / 100);
}

namespace {

// A texture that shows the (u, v) it is asked about.
class uv_texture : public rt::texture {
  public:
    color value(real u, real v, const point3&) const override { return color(u, v, 0); }
    bool uses_uv() const override { return true; }
};

}  // namespace

TEST_CASE("instance: a textured sphere turned and moved keeps the (u, v) of its own frame",
          "[ch11]") {
    // (u, v) stick to the object, not to the world: a sphere inside rotate and translate
    // reports, bit for bit, the local normal and (u, v) of the un-moved sphere hit by the ray
    // the instances hand it (origin - offset, then turned back), and its texture is looked up
    // there. Those coordinates are the spherical coordinates of the hit point carried back into
    // the object's frame; the world normal's would be others (the test would see a rotation
    // that forgot to keep rec.local).
    auto texture      = std::make_shared<uv_texture>();
    auto mat          = std::make_shared<rt::textured_lambertian>(texture);
    const point3 c    = point3(0.5, -1, 2);
    const real radius = 1.5;
    auto ball         = std::make_shared<rt::sphere>(c, radius, mat);
    const vec3 offset(7.25, -3.5, 10.125);
    rt::pcg32 rng(27, 0);
    rt::independent_sampler s(27);
    int hits = 0, not_own = 0, elsewhere = 0, wrong_color = 0, world_differs = 0, turned = 0;
    for (axis about : all_axes) {
        for (real deg : listed_angles) {
            auto spun = std::make_shared<rt::rotate>(ball, about, deg);
            const rt::translate placed(spun, offset);
            const point3 world_center = spun->to_world(c) + offset;
            for (int k = 0; k < 500; ++k) {
                const point3 origin = world_center + 5 * random_unit(rng);
                const point3 target = world_center + real(1.4) * random_in_cube(rng, 1);
                const rt::ray r(origin, target - origin);
                rt::hit_record rec, own;
                if (!placed.hit(r, forward, rec)) continue;
                ++hits;
                const rt::ray in_object(spun->to_object(r.origin() - offset),
                                        spun->to_object(r.direction()));
                REQUIRE(ball->hit(in_object, forward, own));
                const rt::surface_uv uv = rec.uv(), own_uv = own.uv();
                if (rec.object != ball.get() || !exactly(rec.local, own.local) ||
                    uv.u != own_uv.u || uv.v != own_uv.v)
                    ++not_own;
                // The hit point, carried back into the sphere's frame, has these coordinates
                // (to rounding; within 1e-3 of the poles u is ill-conditioned, and left out).
                const vec3 n = rt::unit_vector(spun->to_object(rec.p - offset) - c);
                const rt::surface_uv at_point = rt::sphere::uv_from_normal(n);
                const real sin_theta          = std::sqrt(n.x() * n.x() + n.z() * n.z());
                const real du                 = std::fabs(at_point.u - uv.u);
                // Turning and moving p rounds it by a few ulps of its size (~20), a hundred
                // ulps of the radius at most; an ulp of the normal moves u and v by up to
                // 1 / (pi sin theta) ulps. 4096 ulps over sin theta allow for both.
                const real tolerance = 4096 * eps / sin_theta;
                if (sin_theta > real(1e-3) &&
                    (std::min(du, 1 - du) > tolerance || std::fabs(at_point.v - uv.v) > tolerance))
                    ++elsewhere;
                // The material looks its texture up at those coordinates.
                s.start_pixel_sample(k, 0, 0);
                const auto sample = rec.mat->scatter(r, rec, s);
                if (!sample || !exactly(sample->weight, color(uv.u, uv.v, 0))) ++wrong_color;
                // Coordinates taken in the world frame would differ wherever the turn moves the
                // point (not for a turn by 0, nor on the axis of the turn).
                if (deg != 0) {
                    ++turned;
                    const vec3 world_n            = (rec.p - world_center) / radius;
                    const rt::surface_uv world_uv = rt::sphere::uv_from_normal(world_n);
                    if (std::fabs(world_uv.u - uv.u) + std::fabs(world_uv.v - uv.v) > real(1e-3))
                        ++world_differs;
                }
            }
        }
    }
    INFO(hits << " hits; " << world_differs << " of " << turned
              << " turned hits have other world-frame coordinates");
    CHECK(hits > 3 * 7 * 300);
    CHECK(not_own == 0);
    CHECK(elsewhere == 0);
    CHECK(wrong_color == 0);
    CHECK(world_differs > turned * 9 / 10);
}

TEST_CASE(
    "instance: rays spawned off rotated and translated boxes, at many angles, scales and "
    "distances (float: up to 1e2 sizes), never re-hit them near t = 0",
    "[hardcase][ch11]") {
    // Boxes of 1e-2..1e2, half of them up to 1e3 from the origin before turning (so a turn
    // swings them far), all moved up to 1e3 afterwards, turned about two random axes by listed
    // or random angles. A ray hits a face at least 1% of an edge from its sides; new rays then
    // leave outwards (must miss: the box is convex), inwards and along the face from inside
    // (must first reach another face, at least the distance to the nearest other face plane),
    // or along the face from outside (must miss).
    // Float: up to 1e2 of the box's sizes s, before turning and after, instead of 1e3. Rounding
    // moves a hit along the face by ~eps |p| (|p| <= 350 s, so 4e-5 s), which must stay well
    // inside the half-distance checked below (at least 2.5e-3 s) and the 1% of an edge the aim
    // keeps from the sides: 60 times. A 1e-2 box 1e3 away is 1e5 sizes out, where float's ulp
    // (6e-5, so 6e-3 s) is already beyond both; double's eps |p| is 1e-10 s at most.
    const bool is_double = std::numeric_limits<real>::digits >= 53;
    rt::pcg32 rng(25, 0);
    const int n_cases      = 100000;
    long long primary_fail = 0, out_fail = 0, in_fail = 0, tangent_fail = 0, tangent_in = 0;
    std::string first;
    auto fail = [&](long long& count, const std::string& what) {
        if (count++ == 0 && first.empty()) first = what;
    };
    const real angles[] = {0, 15, -18, 45, 90, 137.5, 180, -90, 270};
    for (int i = 0; i < n_cases; ++i) {
        const real s   = log_uniform(rng, -2, 2);
        const real far = is_double ? real(1e3) : real(1e2) * s;
        vec3 size(s * uniform(rng, 0.5, 2), s * uniform(rng, 0.5, 2), s * uniform(rng, 0.5, 2));
        point3 lo = i % 2 == 0 ? point3(0, 0, 0) + random_in_cube(rng, far)
                               : point3(0, 0, 0) + random_in_cube(rng, 2 * s);
        point3 hi = lo + size;
        axis a1 = random_axis(rng), a2 = random_axis(rng);
        real d1     = rng.uniform() < 0.5 ? angles[rng.next_u32() % 9] : uniform(rng, -360, 360);
        real d2     = rng.uniform() < 0.5 ? angles[rng.next_u32() % 9] : uniform(rng, -360, 360);
        vec3 offset = random_in_cube(rng, far);
        auto r1     = std::make_shared<rt::rotate>(rt::box(lo, hi, any_material()), a1, d1);
        auto r2     = std::make_shared<rt::rotate>(r1, a2, d2);
        rt::translate object(r2, offset);

        // A point on a random face, 1% to 99% along each of its edges.
        int f  = int(rng.next_u32() % 6);
        int k  = f / 2;  // the face's normal axis
        int e1 = (k + 1) % 3, e2 = (k + 2) % 3;
        real fa      = uniform(rng, real(0.01), real(0.99));
        real fb      = uniform(rng, real(0.01), real(0.99));
        point3 local = lo;
        local[k]     = f % 2 == 0 ? hi[k] : lo[k];
        local[e1]    = lo[e1] + fa * size[e1];
        local[e2]    = lo[e2] + fb * size[e2];
        vec3 n_local(0, 0, 0);
        n_local[k] = f % 2 == 0 ? 1 : -1;
        // The distance from the point to the nearest other face plane: any ray from the point
        // into the box travels at least this far before it can leave.
        real nearest = std::min(
            {fa * size[e1], (1 - fa) * size[e1], fb * size[e2], (1 - fb) * size[e2], size[k]});

        point3 aim = r2->to_world(r1->to_world(local)) + offset;
        vec3 n     = r2->to_world(r1->to_world(n_local));
        point3 origin =
            aim + s * log_uniform(rng, -2, 2) * random_in_hemisphere(rng, n, real(0.05));
        rt::hit_record rec;
        auto where = [&] {
            std::ostringstream text;
            text.precision(17);
            text << "box " << lo << " + " << size << " about " << name(a1) << " " << d1 << ", "
                 << name(a2) << " " << d2 << ", moved " << offset << ", p " << rec.p << ", n "
                 << rec.normal << ", p_error " << rec.p_error;
            return text.str();
        };
        const rt::ray primary(origin, log_uniform(rng, -3, 3) * (aim - origin));
        if (!object.hit(primary, forward, rec) || !rec.front_face ||
            (rec.normal - n).length() > real(1e-6)) {
            fail(primary_fail, where() + ": primary ray missed its face");
            continue;
        }
        const real scale = log_uniform(rng, -3, 3);  // spawned directions need not be unit
        rt::hit_record again;

        vec3 out = scale * random_in_hemisphere(rng, rec.normal);
        if (object.hit(rt::spawn_ray(rec, primary, out), forward, again))
            fail(out_fail, where() + ": outward ray re-hit at t " + std::to_string(again.t));

        vec3 in = scale * random_in_hemisphere(rng, -rec.normal);
        if (!object.hit(rt::spawn_ray(rec, primary, in), forward, again) ||
            again.t * in.length() < nearest / 2)
            fail(in_fail, where() + ": inward ray hit at t " + std::to_string(again.t) +
                              ", nearest other face " + std::to_string(nearest));

        vec3 along = scale * random_tangent(rng, rec.normal);
        bool hit   = object.hit(rt::spawn_ray(rec, primary, along), forward, again);
        if (dot(along, rec.normal) > 0) {
            if (hit) fail(tangent_fail, where() + ": outside tangent ray re-hit");
        } else {
            ++tangent_in;
            if (!hit || again.t * along.length() < nearest / 2)
                fail(tangent_fail, where() + ": inside tangent ray hit at t " +
                                       std::to_string(again.t) + ", nearest other face " +
                                       std::to_string(nearest));
        }
    }
    INFO("primary " << primary_fail << ", outward " << out_fail << ", inward " << in_fail
                    << ", tangent " << tangent_fail << " failures of " << n_cases
                    << "; first: " << first);
    CHECK(primary_fail == 0);
    CHECK(out_fail == 0);
    CHECK(in_fail == 0);
    CHECK(tangent_fail == 0);
    CHECK(tangent_in > n_cases / 10);
}

TEST_CASE(
    "instance: the box of a rotated box or thin quad holds every ray the object answers, at its "
    "edges and corners, at scales 1e-4 to 1e4 and far from the origin",
    "[hardcase][ch11]") {
    // A BVH tests an object only if the ray hits its box, so a box that misses a ray the object
    // answers loses that hit. Boxes (six quads) and thin quads (a quad in a coordinate plane: a
    // flat box) of size s = 1e-4 .. 1e4, half of them at the origin and half 1 to 1e5 sizes
    // from it (a turn about the origin then swings them far), turned once or twice by listed or
    // random angles. Rays from 0.01 s to 100 s away aim at a corner or an edge point of the
    // object, turned into the world and moved by up to 4 ulps on each axis, so that they pass
    // just inside or just outside the edge: a turned corner rounds a few ulps inside the exact
    // turned box, and only rotate's widening keeps such rays. Some directions are parallel to a
    // world axis plane (a zero component) or to an axis, some to one of the object's own faces.
    // The translate that usually follows is left out: its box is its object's box moved.
    rt::pcg32 rng(26, 0);
    const real angles[]  = {0, 15, -18, 45, 90, 137.5, 180, -90, 270};
    const bool is_double = std::numeric_limits<real>::digits >= 53;
    const real far_exp   = is_double ? 5 : 3;  // a float's 24 bits: 1e3 sizes out at most
    long long rays = 0, answered = 0, corner_answered = 0, outside_box = 0;
    std::string first;
    for (int i = 0; i < 200000; ++i) {
        const real s = log_uniform(rng, -4, 4);
        point3 lo    = point3(0, 0, 0) + random_in_cube(rng, 2 * s);
        if (i % 2 == 1) lo += log_uniform(rng, 0, far_exp) * s * random_unit(rng);
        const vec3 size(s * uniform(rng, 0.5, 2), s * uniform(rng, 0.5, 2),
                        s * uniform(rng, 0.5, 2));
        const bool thin           = i % 4 >= 2;
        const int flat            = int(rng.next_u32() % 3);  // the thin quad's normal axis
        rt::bounded_object object = rt::box(lo, lo + size, any_material());
        if (thin) {
            vec3 u(0, 0, 0), v(0, 0, 0);
            u[(flat + 1) % 3] = size[(flat + 1) % 3];
            v[(flat + 2) % 3] = size[(flat + 2) % 3];
            object            = std::make_shared<rt::quad>(lo, u, v, any_material());
        }
        const rt::aabb own = object.box;  // in the object's space
        auto angle         = [&] {
            return rng.uniform() < 0.5 ? angles[rng.next_u32() % 9] : uniform(rng, -360, 360);
        };
        const axis a1   = random_axis(rng);
        const real d1   = angle();
        auto first_turn = std::make_shared<rt::rotate>(object, a1, d1);
        std::shared_ptr<rt::rotate> second_turn;
        if (i % 3 == 0)
            second_turn = std::make_shared<rt::rotate>(first_turn, random_axis(rng), angle());
        const rt::rotate& turned = second_turn ? *second_turn : *first_turn;
        auto to_world            = [&](const vec3& v) {
            vec3 w = first_turn->to_world(v);
            return second_turn ? second_turn->to_world(w) : w;
        };
        const rt::aabb box = turned.bounding_box();

        // A corner (each coordinate at its min or max) or an edge point (one of them inside).
        const int free_axis = i % 5 < 2 ? -1 : int(rng.next_u32() % 3);
        point3 corner;
        for (int a = 0; a < 3; ++a) {
            const rt::interval& side = own.axis_interval(a);
            corner[a]                = a == free_axis ? uniform(rng, side.min, side.max)
                                                      : (rng.uniform() < 0.5 ? side.min : side.max);
        }
        point3 target = to_world(corner);
        for (int a = 0; a < 3; ++a) {
            const int steps = int(rng.next_u32() % 9) - 4;
            for (int n = 0; n < std::abs(steps); ++n)
                target[a] = std::nextafter(target[a], steps > 0 ? rt::infinity : -rt::infinity);
        }
        vec3 d = random_unit(rng);
        switch (i % 6) {
            case 0:
                d[rng.next_u32() % 3] = 0;
                break;  // parallel to a world axis plane
            case 1: {   // along a world axis
                const int a = int(rng.next_u32() % 3);
                d           = vec3(0, 0, 0);
                d[a]        = rng.uniform() < 0.5 ? 1 : -1;
                break;
            }
            case 2: {  // in the plane of one of the object's faces, turned
                vec3 local                = random_unit(rng);
                local[rng.next_u32() % 3] = 0;
                d                         = to_world(local);
                break;
            }
            default:
                break;
        }
        if (d.length() == 0) continue;
        const point3 origin = target - s * log_uniform(rng, -2, 2) * rt::unit_vector(d);
        const rt::ray r(origin, d);
        ++rays;
        rt::hit_record rec;
        if (!turned.hit(r, forward, rec)) continue;
        ++answered;
        corner_answered += free_axis < 0;
        const vec3 inv_dir(1 / d.x(), 1 / d.y(), 1 / d.z());
        if (!box.hit(origin, inv_dir, forward)) {
            if (outside_box++ == 0) {
                std::ostringstream text;
                text.precision(17);
                text << (thin ? "quad" : "box") << " " << lo << " + " << size << " about "
                     << name(a1) << " " << d1 << (second_turn ? " and again" : "") << "; ray "
                     << origin << " + t " << d << " hits at t = " << rec.t;
                first = text.str();
            }
        }
    }
    INFO(answered << " of " << rays << " rays answered (" << corner_answered << " at corners), "
                  << outside_box << " of them missing the box; first: " << first);
    // Enough rays meet the object to mean something (the aim points come from the widened box,
    // so a few percent of them fall just outside the object).
    CHECK(answered > rays / 6);
    CHECK(corner_answered > answered / 10);
    CHECK(outside_box == 0);
}
