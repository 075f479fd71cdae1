// Tests for a mesh's shading normals (triangle_mesh::shade, through mesh_triangle::hit; chapter
// 18). Whatever the model's vertex normals (bent, inverted, zero, NaN), the normal a hit reports
// is unit, within 78 degrees of the true (geometric) normal on the ray's side and facing the
// viewer, and exactly the interpolation where that already holds; on a smooth icosphere it is
// close to the sphere's own normal. Rays leave from the true surface: p_error grows so that the
// offset along the shading normal clears the plane, a ray leaving on its side never finds the
// triangle again, and one a material sends below the plane meets it again at once from the
// front, so no light passes through. Then the two claims whole renders make: the furnace (a
// mesh of albedo 1 in a background of 1 returns exactly 1 on every path, whatever its normals:
// no black spots) and no leak (a closed mesh with wild normals lets no light in or out).
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "ch03/furnace.h"
#include "ch03/material_helpers.h"
#include "ch18/mesh_helpers.h"
#include "rt/camera/camera.h"
#include "rt/core/rng.h"
#include "rt/geometry/spawn_ray.h"
#include "rt/geometry/sphere.h"
#include "rt/geometry/triangle_mesh.h"
#include "rt/integrators/path_tracer.h"
#include "rt/materials/dielectric.h"
#include "rt/materials/diffuse_light.h"
#include "rt/materials/lambertian.h"
#include "rt/materials/metal.h"
#include "rt/materials/optics.h"
#include "rt/render/film.h"
#include "rt/samplers/independent_sampler.h"
#include "rt/scene/background.h"
#include "rt/scene/hittable_list.h"
#include "statistics.h"
#include "test_helpers.h"

namespace {

using rt::point3, rt::real, rt::vec3;
using rt_test::exactly, rt_test::log_uniform, rt_test::random_in_cube,
    rt_test::random_in_hemisphere, rt_test::random_tangent, rt_test::random_unit, rt_test::uniform;

constexpr real eps = std::numeric_limits<real>::epsilon();
const rt::interval forward(0, rt::infinity);
// What triangle_mesh.cpp promises: the shading normal's cosine to the geometric one.
constexpr real min_shading_cos = real(0.2);
// Rounding slack on a unit vector's length and on cosines.
constexpr real tiny = 16 * eps;

using rt_test::tally;

// A triangle near the origin, edges 0.5..2 long and not a sliver.
std::array<point3, 3> random_triangle(rt::pcg32& rng) {
    const point3 p0    = random_in_cube(rng, 2);
    const real length1 = uniform(rng, real(0.5), 2);
    const point3 p1    = p0 + length1 * random_unit(rng);
    point3 p2;
    do {
        const real length2 = uniform(rng, real(0.5), 2);
        p2                 = p0 + length2 * random_unit(rng);
    } while (cross(rt::unit_vector(p1 - p0), rt::unit_vector(p2 - p0)).length() < real(0.3));
    return {p0, p1, p2};
}

// A mesh of one triangle with the given vertex normals (none if empty).
std::shared_ptr<rt::triangle_mesh> one_triangle(const std::array<point3, 3>& p,
                                                std::vector<vec3> normals) {
    rt::mesh_data data;
    data.positions = {p[0], p[1], p[2]};
    data.normals   = std::move(normals);
    data.triangles = {{0, 1, 2}};
    return std::make_shared<rt::triangle_mesh>(std::move(data), rt_test::any_material());
}

// The geometric normal unit(cross(p1 - p0, p2 - p0)), turned to face the ray.
vec3 geometric_facing(const std::array<point3, 3>& p, const rt::ray& r) {
    const vec3 g = rt::unit_vector(cross(p[1] - p[0], p[2] - p[0]));
    return dot(r.direction(), g) < 0 ? g : -g;
}

// A ray from either side of triangle p at a random point of it (weights at least `margin`),
// from 0.5 to 5 away; half of them graze the plane (cosine 1e-3..1e-1).
rt::ray random_ray_at(const std::array<point3, 3>& p, rt::pcg32& rng, real margin = 0) {
    rt::mesh_data data;
    data.positions   = {p[0], p[1], p[2]};
    data.triangles   = {{0, 1, 2}};
    const point3 aim = rt_test::random_point_in(data, 0, rng, margin);
    const vec3 n     = rt::unit_vector(cross(p[1] - p[0], p[2] - p[0]));
    const vec3 side  = rng.uniform() < real(0.5) ? n : -n;
    vec3 from;
    if (rng.uniform() < real(0.5)) {
        from = random_in_hemisphere(rng, side, real(1e-3));
    } else {
        const vec3 along = random_tangent(rng, side);
        from             = rt::unit_vector(along + log_uniform(rng, -3, -1) * side);
    }
    const point3 origin = aim + uniform(rng, real(0.5), 5) * from;
    return rt::ray(origin, log_uniform(rng, -1, 1) * (aim - origin));
}

std::string case_text(const std::array<point3, 3>& p, const std::vector<vec3>& normals,
                      const rt::ray& r, const rt::hit_record& rec) {
    std::ostringstream text;
    text.precision(17);
    text << "p " << p[0] << " " << p[1] << " " << p[2] << ", normals";
    for (const vec3& n : normals) text << " " << n;
    text << ", ray " << r.origin() << " + t " << r.direction() << ", shading normal " << rec.normal
         << " (length " << rec.normal.length() << "), p_error " << rec.p_error;
    return text.str();
}

// The model's normals interpolated at the hit's weights (rec.local), turned round for a hit from
// behind, unit: what the shading normal is before its two rules act (zero if they cancel); and
// a bound on its rounding, relative to its length: a few ulps of the normals, since a weight is
// known to an ulp of 1 (b0 here is 1 - b1 - b2, the mesh's e0 / det).
struct interpolation {
    vec3 normal;
    real error;
};

interpolation interpolated(const std::vector<vec3>& normals, const rt::hit_record& rec) {
    const real b1 = rec.local.x(), b2 = rec.local.y(), b0 = 1 - b1 - b2;
    vec3 n = b0 * normals[0] + b1 * normals[1] + b2 * normals[2];
    if (!rec.front_face) n = -n;
    const real length = n.length();
    const real sizes  = normals[0].length() + normals[1].length() + normals[2].length();
    if (!(length > 0)) return {vec3(0, 0, 0), rt::infinity};
    return {n / length, 64 * eps * sizes / length};
}

// What every shading normal must be, against the same hit without normals (`flat`): unit,
// within min_shading_cos of the geometric normal on the ray's side, facing the viewer, with the
// same front_face, t and p, and p_error grown by 1 / cos to the geometric normal; and where the
// interpolation `raw` already keeps both rules (with a margin), the interpolation itself.
struct shading_checks {
    tally unit, hemisphere, viewer, same_hit, p_error, untouched;
    long long leaned_too_far = 0, turned_from_viewer = 0;  // hits where each rule had to act

    void check(const rt::hit_record& rec, const rt::hit_record& flat, const rt::ray& r,
               const interpolation& interpolation, const std::string& where) {
        const vec3& raw = interpolation.normal;
        const vec3& n   = rec.normal;
        const vec3& g   = flat.normal;
        const vec3 wo   = -rt::unit_vector(r.direction());
        const real c    = dot(n, g);
        ++unit.cases;
        if (!(std::fabs(n.length() - 1) <= tiny)) unit.fail(where);
        ++hemisphere.cases;
        if (!(c >= min_shading_cos - tiny))
            hemisphere.fail(where + ", cos to g " + std::to_string(c));
        ++viewer.cases;
        if (!(dot(n, wo) > 0)) viewer.fail(where + ", cos to viewer " + std::to_string(dot(n, wo)));
        // The same t and side; p moved along the plane by p_error tan(theta) against the lean,
        // so that p + p_error n is the geometric offset p + p_error_flat g.
        ++same_hit.cases;
        const vec3 expected_p = flat.p + (flat.p_error / c) * (c * g - n);
        if (rec.front_face != flat.front_face || rec.t != flat.t ||
            !((rec.p - expected_p).length() <= 8 * eps * (rt::max_abs_component(flat.p) + 1)) ||
            !((rec.p + rec.p_error * n - (flat.p + flat.p_error * g)).length() <=
              8 * eps * (rt::max_abs_component(flat.p) + 1)))
            same_hit.fail(where);
        ++p_error.cases;
        if (!(rec.p_error > 0 && std::fabs(rec.p_error * c - flat.p_error) <= tiny * flat.p_error))
            p_error.fail(where);
        // The mirror rule: the reflection of wo about the normal leaves the true plane by at
        // least 0.01 of wo's own cosine to it.
        const real margin = real(1e-3);
        const real g_wo   = dot(g, wo);
        const real clears = 2 * dot(wo, raw) * dot(raw, g) - g_wo - real(0.01) * g_wo;
        if (dot(raw, g) < min_shading_cos - margin) {
            ++leaned_too_far;
        } else if (dot(raw, g) >= min_shading_cos && clears < 0) {
            ++turned_from_viewer;
        } else if (dot(raw, g) >= min_shading_cos + margin && clears >= margin) {
            ++untouched.cases;
            if (!((n - raw).length() <= interpolation.error)) untouched.fail(where);
        }
    }
};

std::ostream& operator<<(std::ostream& out, const shading_checks& s) {
    return out << "not unit: " << s.unit
               << "; beyond the geometric hemisphere's 0.2: " << s.hemisphere
               << "; facing away from the viewer: " << s.viewer
               << "; another t, p or front_face: " << s.same_hit
               << "; p_error not the flat one / cos: " << s.p_error
               << "; not the interpolation where it kept both rules: " << s.untouched;
}

void require_all_held(const shading_checks& s) {
    INFO(s);
    CHECK(s.unit.failures == 0);
    CHECK(s.hemisphere.failures == 0);
    CHECK(s.viewer.failures == 0);
    CHECK(s.same_hit.failures == 0);
    CHECK(s.p_error.failures == 0);
    CHECK(s.untouched.failures == 0);
}

// The vertex directions of an icosphere turned by a random angle up to max_degrees each.
std::vector<vec3> perturbed(const std::vector<vec3>& directions, real max_degrees, rt::pcg32& rng) {
    std::vector<vec3> turned;
    for (const vec3& d : directions) {
        const real angle = uniform(rng, 0, max_degrees) * rt::pi / 180;
        turned.push_back(std::cos(angle) * d + std::sin(angle) * random_tangent(rng, d));
    }
    return turned;
}

// What the paths of a 40-degree view from the origin down -z bring back (the camera of
// ch03/furnace.h), sorted by whether the camera ray hits the world; `unexpected` counts the paths
// whose radiance is not exactly `expected` in every channel.
struct path_result {
    rt_test::running_mean on_object, off_object;
    long long on_count = 0, unexpected = 0, non_finite = 0;
    std::string first;
};

path_result trace_view(const std::shared_ptr<rt::hittable>& world, const rt::color& sky, int width,
                       int samples, real expected, int max_depth = 50) {
    const rt::film f = rt::film::for_aspect(width, 1);
    rt::camera cam;
    cam.aspect_ratio = 1;
    cam.vfov         = 40;
    cam.initialize(f);
    const rt::path_tracer tracer(world, rt::background::uniform(sky));
    path_result result;
    rt::independent_sampler s(1234);
    for (int j = 0; j < f.height; ++j) {
        for (int i = 0; i < f.width; ++i) {
            for (int k = 0; k < samples; ++k) {
                s.start_pixel_sample(i, j, k);
                const rt::ray r = cam.get_ray(i, j, s);
                rt::hit_record rec;
                const bool on     = world->hit(r, forward, rec);
                const rt::color L = tracer.radiance(r, s, max_depth);
                if (!std::isfinite(L.x()) || !std::isfinite(L.y()) || !std::isfinite(L.z()))
                    ++result.non_finite;
                if (!exactly(L, rt::color(expected, expected, expected)) &&
                    result.unexpected++ == 0) {
                    std::ostringstream text;
                    text << "pixel (" << i << ", " << j << ") sample " << k << ": " << L;
                    result.first = text.str();
                }
                (on ? result.on_object : result.off_object).add(double(L.x()));
                if (on) ++result.on_count;
            }
        }
    }
    return result;
}

// The triangle of m whose normal points most along `towards`.
std::size_t facing_most(const rt::mesh_data& m, const vec3& towards) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < m.triangles.size(); ++i)
        if (dot(rt_test::face_normal(m, i), towards) > dot(rt_test::face_normal(m, best), towards))
            best = i;
    return best;
}

// A random unit normal for every vertex: a model whose normals mean nothing.
std::vector<vec3> wild_normals(std::size_t count, rt::pcg32& rng) {
    std::vector<vec3> normals;
    for (std::size_t i = 0; i < count; ++i) normals.push_back(random_unit(rng));
    return normals;
}

}  // namespace

TEST_CASE(
    "triangle_mesh::shade: where the interpolated normal is within the geometric "
    "hemisphere and faces the viewer, it is the shading normal, and p_error grows by 1 / cos",
    "[ch18]") {
    // The dyadic triangle of test_triangle.cpp in z = 2 (normal +z), hit at (2, 3): weights
    // 1/4, 1/4, 1/2.
    const std::array<point3, 3> p   = {point3(1, 1, 2), point3(5, 1, 2), point3(1, 5, 2)};
    const std::vector<vec3> normals = {rt::unit_vector(vec3(0.5, 0, 1)),
                                       rt::unit_vector(vec3(0, -0.25, 1)),
                                       rt::unit_vector(vec3(0.125, 0.25, 1))};
    const vec3 expected =
        rt::unit_vector(real(0.25) * normals[0] + real(0.25) * normals[1] + real(0.5) * normals[2]);
    auto mesh = one_triangle(p, normals);
    auto flat = one_triangle(p, {});
    for (int side : {1, -1}) {
        INFO((side == 1 ? "from the front" : "from behind"));
        const rt::ray r(point3(2, 3, 2 + 5 * side), vec3(0, 0, -side));
        rt::hit_record rec, geometric;
        REQUIRE(mesh->faces()[0].hit(r, forward, rec));
        REQUIRE(flat->faces()[0].hit(r, forward, geometric));
        // From behind the model's normals are turned round, as the geometric one is.
        const vec3 n = real(side) * expected;
        CHECK((rec.normal - n).length() <= 4 * eps);
        CHECK(rec.front_face == (side == 1));
        CHECK(rec.t == 5);
        // p moves along the plane, by p_error tan(theta) against the normal's lean, so that the
        // spawn offset along the normal is the geometric one (triangle_mesh.cpp).
        CHECK(rec.p.z() == 2);
        CHECK((rec.p - point3(2, 3, 2)).length() <=
              geometric.p_error * std::sqrt(1 - n.z() * n.z()) / std::fabs(n.z()) * (1 + 8 * eps));
        CHECK(exactly(rec.local, vec3(0.25, 0.5, 0)));
        CHECK(std::fabs(rec.p_error - geometric.p_error / std::fabs(n.z())) <=
              4 * eps * rec.p_error);
        CHECK(rec.p_error > geometric.p_error);
    }
}

TEST_CASE(
    "triangle_mesh::shade: whatever the vertex normals, the shading normal is unit, within "
    "cosine 0.2 of the geometric normal on the ray's side, and faces the viewer",
    "[ch18]") {
    rt::pcg32 rng(20250118, 21);
    shading_checks checks;
    long long hits = 0, rays = 0;
    for (int i = 0; i < 40000; ++i) {
        const auto p = random_triangle(rng);
        // Any direction, any length (a model's normals need not be unit).
        std::vector<vec3> normals;
        for (int k = 0; k < 3; ++k) {
            const vec3 d = random_unit(rng);
            normals.push_back(log_uniform(rng, -3, 3) * d);
        }
        auto mesh       = one_triangle(p, normals);
        auto flat       = one_triangle(p, {});
        const rt::ray r = random_ray_at(p, rng);
        ++rays;
        rt::hit_record rec, geometric;
        if (!flat->faces()[0].hit(r, forward, geometric)) continue;
        ++hits;
        REQUIRE(mesh->faces()[0].hit(r, forward, rec));
        checks.check(rec, geometric, r, interpolated(normals, rec), case_text(p, normals, r, rec));
    }
    require_all_held(checks);
    CHECK(hits > rays * 99 / 100);
    // Each rule acted on many hits, and left many alone: the checks above covered all three.
    INFO("leaned too far: " << checks.leaned_too_far
                            << ", turned from the viewer: " << checks.turned_from_viewer
                            << ", left alone: " << checks.untouched.cases);
    CHECK(checks.leaned_too_far > 1000);
    CHECK(checks.turned_from_viewer > 1000);
    CHECK(checks.untouched.cases > 1000);
}

TEST_CASE(
    "triangle_mesh::shade: vertex normals exactly opposite the geometric normal (a flat "
    "model with its normals inverted) give a unit normal that does not point into the "
    "surface",
    "[ch18]") {
    // The interpolated normal is then antiparallel to the geometric one up to its rounding; the
    // turn towards the geometric normal must not take its direction from that rounding.
    rt::pcg32 rng(20250118, 22);
    shading_checks checks;
    for (int i = 0; i < 20000; ++i) {
        const auto p                    = random_triangle(rng);
        const vec3 n                    = rt::unit_vector(cross(p[1] - p[0], p[2] - p[0]));
        const std::vector<vec3> normals = {-n, -n, -n};
        auto mesh                       = one_triangle(p, normals);
        auto flat                       = one_triangle(p, {});
        const rt::ray r                 = random_ray_at(p, rng);
        rt::hit_record rec, geometric;
        if (!flat->faces()[0].hit(r, forward, geometric)) continue;
        REQUIRE(mesh->faces()[0].hit(r, forward, rec));
        checks.check(rec, geometric, r, interpolated(normals, rec), case_text(p, normals, r, rec));
    }
    require_all_held(checks);
    CHECK(checks.leaned_too_far > 19000);
    // Exactly antiparallel, without rounding (a triangle in z = 2, normals -z): the geometric
    // normal itself, and p_error unchanged.
    const std::array<point3, 3> q = {point3(1, 1, 2), point3(5, 1, 2), point3(1, 5, 2)};
    auto mesh = one_triangle(q, {vec3(0, 0, -1), vec3(0, 0, -1), vec3(0, 0, -1)});
    auto flat = one_triangle(q, {});
    rt::hit_record rec, geometric;
    const rt::ray down(point3(2, 3, 7), vec3(0, 0, -1));
    REQUIRE(mesh->faces()[0].hit(down, forward, rec));
    REQUIRE(flat->faces()[0].hit(down, forward, geometric));
    CHECK(exactly(rec.normal, vec3(0, 0, 1)));
    CHECK(rec.p_error == geometric.p_error);
}

TEST_CASE(
    "triangle_mesh::shade: zero, NaN or infinite vertex normals, or normals that cancel at "
    "the hit, give the geometric normal and its p_error",
    "[ch18]") {
    const std::array<point3, 3> q = {point3(1, 1, 2), point3(5, 1, 2), point3(1, 5, 2)};
    const real nan_value          = std::numeric_limits<real>::quiet_NaN();
    const vec3 up(0, 0, 1), zero(0, 0, 0);
    const std::vector<vec3> cases[] = {
        {zero, zero, zero},
        {vec3(nan_value, 0, 1), up, up},
        {up, up, vec3(0, nan_value, 0)},
        {vec3(rt::infinity, 0, 1), up, up},
        {up, vec3(0, 0, -rt::infinity), up},
    };
    auto flat = one_triangle(q, {});
    for (const auto& normals : cases) {
        auto mesh = one_triangle(q, normals);
        for (int side : {1, -1}) {
            // Through (2, 3, 2), tilted.
            const rt::ray r(point3(0.75, 0.5, 2 + 5 * side), vec3(0.25, 0.5, -side));
            rt::hit_record rec, geometric;
            REQUIRE(mesh->faces()[0].hit(r, forward, rec));
            REQUIRE(flat->faces()[0].hit(r, forward, geometric));
            INFO(case_text(q, normals, r, rec));
            CHECK(exactly(rec.normal, geometric.normal));
            CHECK(rec.p_error == geometric.p_error);
            CHECK(rec.front_face == geometric.front_face);
        }
    }
    // +z and -z at the ends of edge p0 p1, hit at its middle (3, 1): weights 1/2, 1/2, 0, so the
    // interpolation is exactly 0.
    auto cancelling = one_triangle(q, {up, -up, rt::unit_vector(vec3(1, 1, 1))});
    rt::hit_record rec;
    REQUIRE(cancelling->faces()[0].hit(rt::ray(point3(3, 1, 7), vec3(0, 0, -1)), forward, rec));
    CHECK(exactly(rec.normal, up));
    // A little inside, the same normals interpolate to something usable: the cancel was real.
    REQUIRE(cancelling->faces()[0].hit(rt::ray(point3(3, 1.5, 7), vec3(0, 0, -1)), forward, rec));
    CHECK_FALSE(exactly(rec.normal, up));
}

TEST_CASE(
    "triangle_mesh::shade: on an icosphere with the sphere's normals at its vertices, the "
    "shading normal is the sphere's normal in the hit's direction, where the geometric one "
    "is degrees off",
    "[ch18]") {
    // The vertices are c + r u_i with u_i unit, so the hit b0 p0 + b1 p1 + b2 p2 lies in the
    // direction sum b_i u_i from c: the interpolation of the u_i, normalized, is exactly the
    // sphere's normal there, up to rounding. The facets' own normals are up to ~5 degrees off.
    const point3 center(0.5, -1, 2);
    const real radius = 2;
    std::vector<vec3> directions;
    rt::mesh_data data       = rt_test::icosphere(center, radius, 3, &directions);
    data.normals             = directions;
    auto tree                = rt::mesh_object(data, rt_test::any_material());
    rt::mesh_data no_normals = data;
    no_normals.normals.clear();
    auto flat_tree = rt::mesh_object(no_normals, rt_test::any_material());
    rt::pcg32 rng(20250118, 23);
    real worst_shading   = 0;  // the largest |shading normal - sphere normal|
    real worst_geometric = 1;  // the smallest cosine of the geometric normal to the sphere's
    int seen             = 0;
    for (int i = 0; i < 20000; ++i) {
        const real distance = uniform(rng, 3, 8);
        const point3 origin = center + distance * random_unit(rng);
        const point3 aim    = center + radius * random_unit(rng);
        const rt::ray r(origin, aim - origin);
        rt::hit_record rec, geometric;
        if (!tree->hit(r, forward, rec)) continue;
        REQUIRE(flat_tree->hit(r, forward, geometric));
        const vec3 sphere_normal = rt::unit_vector(rec.p - center);
        // Away from the silhouette, where the viewer rule leaves the interpolation alone.
        if (dot(sphere_normal, -rt::unit_vector(r.direction())) < real(0.3)) continue;
        ++seen;
        CHECK(rec.front_face);
        worst_shading   = std::fmax(worst_shading, (rec.normal - sphere_normal).length());
        worst_geometric = std::fmin(worst_geometric, dot(geometric.normal, sphere_normal));
    }
    const real geometric_degrees = std::acos(std::fmin(worst_geometric, real(1))) * 180 / rt::pi;
    INFO("largest distance of the shading normal from the sphere normal: "
         << worst_shading << "; worst angle of the geometric one: " << geometric_degrees
         << " degrees");
    CHECK(seen > 5000);
    // Rounding of p, relative to its distance from c, and of two normalizations.
    CHECK(worst_shading <= 64 * eps * (1 + rt::max_abs_component(center) / radius));
    CHECK(geometric_degrees > 3);
}

TEST_CASE(
    "triangle_mesh::shade: inverted vertex normals on a closed mesh are turned back into "
    "the geometric hemisphere, outwards for rays from outside and inwards from inside",
    "[ch18]") {
    const point3 center(0, 0, -4);
    std::vector<vec3> directions;
    rt::mesh_data data = rt_test::icosphere(center, 1, 3, &directions);
    for (const vec3& d : directions) data.normals.push_back(-d);
    auto tree = rt::mesh_object(data, rt_test::any_material());
    rt::pcg32 rng(20250118, 24);
    tally outward, inward;
    for (int i = 0; i < 20000; ++i) {
        const bool outside  = i % 2 == 0;
        const real distance = outside ? uniform(rng, 2, 5) : uniform(rng, 0, real(0.9));
        const point3 origin = center + distance * random_unit(rng);
        // From outside towards the sphere, from inside anywhere.
        const vec3 d =
            outside ? center + random_in_cube(rng, real(0.9)) - origin : random_unit(rng);
        const rt::ray r(origin, d);
        rt::hit_record rec;
        if (!tree->hit(r, forward, rec)) continue;
        const vec3 radial = rt::unit_vector(rec.p - center);
        tally& t          = outside ? outward : inward;
        ++t.cases;
        const real c = outside ? dot(rec.normal, radial) : -dot(rec.normal, radial);
        if (rec.front_face != outside || !(c > 0) ||
            !(std::fabs(rec.normal.length() - 1) <= tiny)) {
            std::ostringstream text;
            text.precision(17);
            text << "ray " << r.origin() << " + t " << r.direction() << ": normal " << rec.normal
                 << ", radial " << radial;
            t.fail(text.str());
        }
    }
    INFO("from outside, not pointing out: " << outward);
    INFO("from inside, not pointing in: " << inward);
    CHECK(outward.cases > 8000);
    CHECK(inward.cases > 9000);
    CHECK(outward.failures == 0);
    CHECK(inward.failures == 0);
}

TEST_CASE(
    "spawn_ray with shading normals: a ray that moves away from the triangle's plane never "
    "finds it again, and one that crosses the plane finds it at once on the other side",
    "[ch18][hardcase]") {
    // spawn_ray picks the side by the shading normal n; p_error / cos(n, g) along n is p_error
    // along the geometric normal g. So the origin is p_error off the plane, on the side that the
    // direction's sign against n picks, and the ray then either moves away (no hit) or crosses
    // the plane at p_error / |cos(direction, g)| (a hit from the side it started on). Crossings at
    // a cosine below 0.05 are not checked: they may leave the triangle before they reach the plane.
    rt::pcg32 rng(20250118, 25);
    tally away, crossing;
    long long skipped = 0;
    for (int i = 0; i < 25000; ++i) {
        const auto p = random_triangle(rng);
        std::vector<vec3> normals;
        for (int k = 0; k < 3; ++k) normals.push_back(random_unit(rng));
        auto mesh                     = one_triangle(p, normals);
        const rt::mesh_triangle& face = mesh->faces()[0];
        const rt::ray r               = random_ray_at(p, rng, real(0.05));
        rt::hit_record rec;
        if (!face.hit(r, forward, rec)) continue;
        const vec3 g            = geometric_facing(p, r);
        const real p_error_on_g = rec.p_error * dot(rec.normal, g);
        for (int k = 0; k < 4; ++k) {
            const real length       = log_uniform(rng, -3, 3);
            const vec3 d            = length * random_unit(rng);
            const real starts_front = dot(d, rec.normal) > 0 ? 1 : -1;
            const real cos_g        = dot(rt::unit_vector(d), g);
            const rt::ray spawned   = rt::spawn_ray(rec, r, d);
            rt::hit_record again;
            const bool hit = face.hit(spawned, forward, again);
            std::ostringstream where;
            where.precision(17);
            where << case_text(p, normals, r, rec) << ", spawned " << d << ", cos to g " << cos_g;
            if (starts_front * cos_g >= 0) {
                ++away.cases;
                if (hit) away.fail(where.str() + ": hit at t " + std::to_string(again.t));
                continue;
            }
            if (std::fabs(cos_g) < real(0.05)) {
                ++skipped;
                continue;
            }
            ++crossing.cases;
            const real expected = p_error_on_g / std::fabs(cos_g);
            if (!hit) {
                crossing.fail(where.str() + ": went through");
            } else if (!(again.t * d.length() >= expected / 2 &&
                         again.t * d.length() <= 2 * expected) ||
                       again.front_face != (rec.front_face == (starts_front > 0))) {
                where << ": hit at distance " << again.t * d.length() << ", expected " << expected
                      << ", front_face " << again.front_face;
                crossing.fail(where.str());
            }
        }
    }
    INFO("spawned rays moving away from the plane that hit: " << away);
    INFO("spawned rays crossing the plane not hit at p_error / cos from their side: " << crossing);
    INFO("crossings too grazing to check: " << skipped);
    CHECK(away.failures == 0);
    CHECK(crossing.failures == 0);
    CHECK(away.cases > 50000);
    CHECK(crossing.cases > 5000);
}

TEST_CASE(
    "spawn_reflected_ray with shading normals: a reflection below the geometric plane hits "
    "the same triangle at once, from the front",
    "[ch18]") {
    std::vector<vec3> directions;
    rt::mesh_data data = rt_test::icosphere(point3(0, 0, 0), 1, 3, &directions);
    rt::pcg32 rng(20250118, 26);
    data.normals = perturbed(directions, 60, rng);
    auto mesh    = std::make_shared<rt::triangle_mesh>(data, rt_test::any_material());
    auto tree    = rt::mesh_object(mesh);
    tally below;
    for (int i = 0; i < 20000; ++i) {
        const std::size_t f =
            std::min(data.triangles.size() - 1,
                     static_cast<std::size_t>(rng.uniform() * real(data.triangles.size())));
        const point3 aim    = rt_test::random_point_in(data, f, rng, real(0.1));
        const vec3 g        = rt_test::face_normal(data, f);
        const real distance = uniform(rng, real(0.5), 3);
        const point3 origin =
            aim + distance * rt_test::random_direction_facing(rng, {g}, real(0.3));
        const rt::ray r(origin, aim - origin);
        rt::hit_record rec;
        REQUIRE(tree->hit(r, forward, rec));
        REQUIRE(rec.object == &mesh->faces()[f]);
        // A direction on the shading normal's side and below the geometric plane, if the normal
        // leans enough for one.
        vec3 d;
        bool found = false;
        for (int tries = 0; tries < 200 && !found; ++tries) {
            d     = random_in_hemisphere(rng, rec.normal);
            found = dot(d, g) < real(-0.05);
        }
        if (!found) continue;
        d *= log_uniform(rng, -3, 3);
        const real expected = rec.p_error * dot(rec.normal, g) / -dot(rt::unit_vector(d), g);
        rt::hit_record again;
        ++below.cases;
        std::ostringstream where;
        where.precision(17);
        where << "hit " << rec.p << ", shading normal " << rec.normal << ", g " << g
              << ", reflected " << d;
        if (!tree->hit(rt::spawn_reflected_ray(rec, r, d), forward, again)) {
            below.fail(where.str() + ": left the sphere");
        } else if (again.object != rec.object || !again.front_face ||
                   !(again.t * d.length() >= expected / 2 &&
                     again.t * d.length() <= 2 * expected)) {
            where << ": hit " << again.p << " at distance " << again.t * d.length() << ", expected "
                  << expected << ", front_face " << again.front_face;
            below.fail(where.str());
        }
    }
    INFO(
        "reflections below the plane not hitting their triangle at once from the front: " << below);
    CHECK(below.cases > 2000);
    CHECK(below.failures == 0);
}

TEST_CASE(
    "furnace: a closed icosphere mesh of albedo 1 returns exactly 1 on every path, with "
    "smooth, bent (up to 60 degrees) or inverted vertex normals",
    "[ch18]") {
    std::vector<vec3> directions;
    const rt::mesh_data sphere = rt_test::icosphere(rt_test::furnace_center, 1, 3, &directions);
    rt::pcg32 rng(20250118, 27);
    std::vector<vec3> inverted;
    for (const vec3& d : directions) inverted.push_back(-d);
    const std::vector<vec3> normal_sets[] = {directions, perturbed(directions, 60, rng), inverted};
    const char* names[]                   = {"smooth", "bent up to 60 degrees", "inverted"};
    for (int k = 0; k < 3; ++k) {
        INFO(names[k] << " normals");
        rt::mesh_data data = sphere;
        data.normals       = normal_sets[k];
        auto world = rt::mesh_object(data, std::make_shared<rt::lambertian>(rt::color(1, 1, 1)));
        const path_result result = trace_view(world, rt::color(1, 1, 1), 48, 32, 1);
        INFO("paths not bringing back exactly 1: " << result.unexpected
                                                   << " (first: " << result.first << ")");
        CHECK(result.non_finite == 0);
        CHECK(result.on_count > 48 * 48 * 32 / 4);
        CHECK(result.unexpected == 0);
        rt_test::check_furnace_mean(result.on_object, 1.0);
        rt_test::check_furnace_mean(result.off_object, 1.0);
    }
}

TEST_CASE("furnace: a glass icosphere mesh with smooth normals neither loses nor gains energy",
          "[ch18]") {
    std::vector<vec3> directions;
    rt::mesh_data data = rt_test::icosphere(rt_test::furnace_center, 1, 3, &directions);
    data.normals       = directions;
    auto world         = rt::mesh_object(data, std::make_shared<rt::dielectric>(1.5));
    const rt_test::furnace_result result = rt_test::run_furnace(world);
    CHECK(result.non_finite == 0);
    rt_test::check_furnace_mean(result.on_object, 1.0);
    rt_test::check_furnace_mean(result.off_object, 1.0);
}

TEST_CASE(
    "furnace: a mirror icosphere mesh (metal of albedo 1, no fuzz) with smooth normals "
    "returns exactly 1 on every path",
    "[ch18]") {
    // A mirror's reflection below the geometric plane meets the surface again at once; it must
    // then leave, not stay under the plane reflection after reflection until the path's depth
    // runs out (a path that returns 0: a dark rim on a smooth glass or metal model).
    std::vector<vec3> directions;
    rt::mesh_data data = rt_test::icosphere(rt_test::furnace_center, 1, 3, &directions);
    data.normals       = directions;
    auto world         = rt::mesh_object(data, std::make_shared<rt::metal>(rt::color(1, 1, 1), 0));
    const path_result result = trace_view(world, rt::color(1, 1, 1), 48, 32, 1);
    INFO("paths not bringing back exactly 1: " << result.unexpected << " (first: " << result.first
                                               << ")");
    CHECK(result.non_finite == 0);
    CHECK(result.unexpected == 0);
    rt_test::check_furnace_mean(result.on_object, 1.0);
}

TEST_CASE(
    "mesh_triangle with shading normals: a mirror reflection about the shading normal leaves "
    "above the geometric plane, even at a silhouette",
    "[ch18]") {
    // The case of the mirror furnace above, on one triangle: the plane z = 2 (normal +z), every
    // vertex normal unit(0.5, 0, 1), leaning away from a viewer who looks along +x, 5.7 degrees
    // above the plane. Reflected about that normal, the ray would point below the plane, meet
    // the triangle again from the front, reflect lower still, and never leave (a shading rule
    // that only made the viewer see the normal's side did that, ten times in a row here). The
    // normal is bent until the mirror image leaves above the plane: the first reflection does.
    const std::array<point3, 3> q = {point3(1, 1, 2), point3(5, 1, 2), point3(1, 5, 2)};
    const vec3 lean               = rt::unit_vector(vec3(0.5, 0, 1));
    auto mesh                     = one_triangle(q, {lean, lean, lean});
    const rt::mesh_triangle& face = mesh->faces()[0];
    rt::ray r(point3(-8, 3, 3), vec3(10, 0, -1));  // through (2, 3, 2)
    rt::hit_record rec;
    REQUIRE(face.hit(r, forward, rec));
    REQUIRE(rec.front_face);
    // Reflected about the model's own normal, the ray would go below the plane: the case is the
    // one described.
    REQUIRE(rt::reflect(rt::unit_vector(r.direction()), lean).z() < 0);
    vec3 reflected = rt::unit_vector(rt::reflect(r.direction(), rec.normal));
    CHECK(reflected.z() > 0);
    REQUIRE(dot(reflected, rec.normal) > 0);
    int rehits = 0;
    for (; rehits < 10; ++rehits) {
        r = rt::spawn_ray(rec, r, reflected);  // as metal::scatter spawns it
        rt::hit_record again;
        if (!face.hit(r, forward, again)) break;
        INFO("re-hit " << rehits << " at t " << again.t << ", direction " << r.direction());
        CHECK(again.front_face);  // never through the surface
        rec       = again;
        reflected = rt::unit_vector(rt::reflect(r.direction(), rec.normal));
    }
    INFO("the reflected ray met the triangle again " << rehits << " times in a row, last going "
                                                     << reflected);
    CHECK(rehits == 0);
}

TEST_CASE("leak: a light inside a closed mesh with wild vertex normals sends nothing out",
          "[ch18]") {
    // A box of 12 triangles and an icosphere around a small light, seen from outside against a
    // black background: a path brings light back only through the surface.
    rt::pcg32 rng(20250118, 28);
    const point3 c               = rt_test::furnace_center;
    const rt::mesh_data shells[] = {
        rt_test::box_mesh(c - vec3(1.5, 1.5, 1.5), c + vec3(1.5, 1.5, 1.5)),
        rt_test::icosphere(c, real(1.5), 2)};
    const char* names[] = {"box", "icosphere"};
    for (int k = 0; k < 2; ++k) {
        INFO(names[k]);
        rt::mesh_data data = shells[k];
        data.normals       = wild_normals(data.positions.size(), rng);
        auto light         = std::make_shared<rt::sphere>(
            c, real(0.5), std::make_shared<rt::diffuse_light>(rt::color(4, 4, 4)));
        auto gray = std::make_shared<rt::lambertian>(rt::color(0.5, 0.5, 0.5));

        auto world = std::make_shared<rt::hittable_list>();
        world->add(rt::mesh_object(data, gray));
        world->add(light);
        const path_result closed = trace_view(world, rt::color(0, 0, 0), 32, 16, 0);
        INFO("paths bringing back light: " << closed.unexpected << " (first: " << closed.first
                                           << ")");
        CHECK(closed.non_finite == 0);
        CHECK(closed.on_count > 32 * 32 * 16 / 2);
        CHECK(closed.unexpected == 0);

        // With the triangle that faces the camera taken out, the light shows: the scene can
        // bring light back, and it is the surface that stops it.
        data.triangles.erase(data.triangles.begin() +
                             std::ptrdiff_t(facing_most(data, vec3(0, 0, 1))));
        auto open = std::make_shared<rt::hittable_list>();
        open->add(rt::mesh_object(data, gray));
        open->add(light);
        const path_result holed = trace_view(open, rt::color(0, 0, 0), 32, 16, 0);
        CHECK(holed.unexpected > 100);
    }
}

TEST_CASE("leak: a closed room mesh with wild vertex normals lets no light in from outside",
          "[ch18]") {
    // The camera inside a box of 12 triangles and inside an icosphere, the light outside
    // beyond the wall it looks at, the background black.
    rt::pcg32 rng(20250118, 29);
    const rt::mesh_data rooms[] = {rt_test::box_mesh(point3(-3, -3, -3), point3(3, 3, 3)),
                                   rt_test::icosphere(point3(0, 0, 0), 3, 2)};
    const char* names[]         = {"box", "icosphere"};
    for (int k = 0; k < 2; ++k) {
        INFO(names[k]);
        rt::mesh_data data = rooms[k];
        data.normals       = wild_normals(data.positions.size(), rng);
        auto light         = std::make_shared<rt::sphere>(
            point3(0, 0, -5), 1, std::make_shared<rt::diffuse_light>(rt::color(4, 4, 4)));
        auto gray = std::make_shared<rt::lambertian>(rt::color(0.5, 0.5, 0.5));

        auto world = std::make_shared<rt::hittable_list>();
        world->add(rt::mesh_object(data, gray));
        world->add(light);
        const path_result closed = trace_view(world, rt::color(0, 0, 0), 24, 8, 0);
        INFO("paths bringing back light: " << closed.unexpected << " (first: " << closed.first
                                           << ")");
        CHECK(closed.non_finite == 0);
        CHECK(closed.on_count == 24 * 24 * 8);  // every camera ray meets the room
        CHECK(closed.unexpected == 0);

        // A hole in the wall towards the light lets it in.
        data.triangles.erase(data.triangles.begin() +
                             std::ptrdiff_t(facing_most(data, vec3(0, 0, -1))));
        auto open = std::make_shared<rt::hittable_list>();
        open->add(rt::mesh_object(data, gray));
        open->add(light);
        const path_result holed = trace_view(open, rt::color(0, 0, 0), 24, 8, 0);
        CHECK(holed.unexpected > 20);
    }
}
