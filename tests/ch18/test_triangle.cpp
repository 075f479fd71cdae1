// Tests for the triangle test of triangle.h and mesh_triangle::hit (chapter 18): exact hits on
// dyadic numbers (t, the barycentric weights, the point, the normal by the winding and its side),
// misses just outside the edges and vertices, in the plane, behind the origin, outside ray_t, on
// zero-area triangles and with NaN; then what the chapter claims for it. Watertight: rays aimed
// exactly at the shared vertices and edges of closed meshes (and of a flat grid) never pass
// between the triangles, over all triangles tried one by one (no BVH), while a Möller-Trumbore
// test with its usual epsilon, written here as a reference, does lose some of those same rays
// (so the rays really probe the edges). Error bound: rays spawned from a hit never find the same
// triangle again, at edges 1e-4..1e4 and 1e3 away, like chapter 03's spheres and quads.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "ch03/material_helpers.h"
#include "ch18/mesh_helpers.h"
#include "rt/core/rng.h"
#include "rt/geometry/spawn_ray.h"
#include "rt/geometry/triangle.h"
#include "rt/geometry/triangle_mesh.h"
#include "test_helpers.h"

namespace {

using rt::point3, rt::real, rt::vec3;
using rt_test::exactly, rt_test::log_uniform, rt_test::random_in_cube,
    rt_test::random_in_hemisphere, rt_test::random_tangent, rt_test::random_unit, rt_test::uniform;

constexpr real eps       = std::numeric_limits<real>::epsilon();
constexpr bool is_double = std::numeric_limits<real>::digits >= 53;
const rt::interval forward(0, rt::infinity);
const real not_a_number = std::numeric_limits<real>::quiet_NaN();

using rt_test::tally;

// The triangle of the exact cases: in the plane z = 2, legs of 4 along x and y from (1, 1, 2),
// so cross(p1 - p0, p2 - p0) = (0, 0, 16), twice its area, and every weight of a point with
// integer or half-integer x and y is a multiple of 1/64.
const point3 q0(1, 1, 2), q1(5, 1, 2), q2(1, 5, 2);

// The point of the plane z = 2 at (x, y), and a ray straight down onto it from z = 7.
rt::ray down_onto(real x, real y) {
    return rt::ray(point3(x, y, 7), vec3(0, 0, -1));
}

bool hits(const rt::ray& r, const point3& a, const point3& b, const point3& c,
          rt::interval ray_t = forward) {
    rt::triangle_hit h;
    return rt::intersect_triangle(rt::sheared_ray(r), a, b, c, ray_t, h);
}

// A mesh of the one triangle (a, b, c).
std::shared_ptr<rt::triangle_mesh> one_triangle(const point3& a, const point3& b, const point3& c) {
    rt::mesh_data data;
    data.positions = {a, b, c};
    data.triangles = {{0, 1, 2}};
    return std::make_shared<rt::triangle_mesh>(std::move(data), rt_test::any_material());
}

// The Möller-Trumbore test (1997) as it is usually written, with its epsilon on the determinant
// and on t: the reference that is not watertight. Its two triangles at an edge compute the
// edge's weight by different formulas, each rounded its own way.
bool moller_trumbore(const rt::ray& r, const point3& v0, const point3& v1, const point3& v2) {
    const real epsilon = real(1e-7);
    const vec3 e1 = v1 - v0, e2 = v2 - v0;
    const vec3 pvec = cross(r.direction(), e2);
    const real det  = dot(e1, pvec);
    if (det > -epsilon && det < epsilon) return false;
    const real inv_det = 1 / det;
    const vec3 tvec    = r.origin() - v0;
    const real u       = dot(tvec, pvec) * inv_det;
    if (u < 0 || u > 1) return false;
    const vec3 qvec = cross(tvec, e1);
    const real v    = dot(r.direction(), qvec) * inv_det;
    if (v < 0 || u + v > 1) return false;
    return dot(e2, qvec) * inv_det > epsilon;
}

bool moller_trumbore_hits_any(const rt::mesh_data& m, const std::vector<std::uint32_t>& faces,
                              const rt::ray& r) {
    for (std::uint32_t i : faces) {
        const auto p = rt_test::corners(m, i);
        if (moller_trumbore(r, p[0], p[1], p[2])) return true;
    }
    return false;
}

// How many times the whole line of r crosses the mesh, hits at one t (an edge or a vertex,
// where the triangles around it all answer) counted once. A line through a closed mesh crosses
// it an even number of times; an odd count is a gap between triangles.
int crossings(const rt::mesh_data& m, const rt::ray& r) {
    const rt::sheared_ray sr(r);
    std::vector<real> ts;
    for (std::size_t i = 0; i < m.triangles.size(); ++i) {
        const auto p = rt_test::corners(m, i);
        rt::triangle_hit h;
        if (rt::intersect_triangle(sr, p[0], p[1], p[2], rt::interval::universe(), h))
            ts.push_back(h.t);
    }
    std::sort(ts.begin(), ts.end());
    int count = 0;
    for (std::size_t k = 0; k < ts.size(); ++k)
        if (k == 0 || !(ts[k] - ts[k - 1] <= 64 * eps * std::fabs(ts[k]))) ++count;
    return count;
}

std::string ray_text(const rt::ray& r) {
    std::ostringstream text;
    text.precision(17);
    text << "origin " << r.origin() << ", direction " << r.direction();
    return text.str();
}

// The rays of the watertightness tests, and what became of them.
struct watertight_result {
    tally vertex, edge, interior, grazing;           // rays that hit no triangle
    tally naive_vertex, naive_edge, naive_interior;  // the same, for Möller-Trumbore
    tally aim;  // rays that hit first somewhere else than the point they were aimed at
};

// Shoots `n_rays` rays at `m` from random points outside, a quarter each aimed exactly at a
// vertex, at a point of an edge a + s (b - a) (s uniform, computed in real), at a random interior
// point (weights at least 1e-3: the reference's own rounding, 1e-4 of a triangle in float, must
// not reach an edge), and along an edge at a grazing angle; only at vertices and edges that two
// triangles share. A closed mesh is shot at from outside (in front of every triangle at the aim, by
// 0.1 at least in cosine); an open one from either side. From 0.01 to 100 sizes away.
watertight_result probe_watertight(const rt::mesh_data& m, bool closed, real size, rt::pcg32& rng,
                                   int n_rays) {
    const std::vector<rt_test::mesh_edge> all_edges = rt_test::edges_of(m);
    std::vector<rt_test::mesh_edge> shared;
    std::vector<bool> vertex_on_border(m.positions.size(), false);
    for (const auto& e : all_edges) {
        if (e.faces.size() == 2) {
            shared.push_back(e);
        } else {
            vertex_on_border[e.a] = true;
            vertex_on_border[e.b] = true;
        }
    }
    const auto around = rt_test::faces_around_vertices(m);
    std::vector<std::uint32_t> inner_vertices;
    for (std::uint32_t v = 0; v < m.positions.size(); ++v)
        if (!vertex_on_border[v] && !around[v].empty()) inner_vertices.push_back(v);
    REQUIRE(!shared.empty());
    REQUIRE(!inner_vertices.empty());
    std::vector<vec3> normals(m.triangles.size());
    for (std::size_t i = 0; i < m.triangles.size(); ++i) normals[i] = rt_test::face_normal(m, i);

    // Grazing: the ray's angle to one of the edge's planes, 10^-8..10^-1 (float: 10^-4..10^-1).
    const real lo_graze = is_double ? -8 : -4;
    auto pick           = [&rng](std::size_t count) {
        return std::min(count - 1, static_cast<std::size_t>(rng.uniform() * real(count)));
    };

    watertight_result result;
    for (int k = 0; k < n_rays; ++k) {
        const int kind = k % 4;  // vertex, edge, interior, grazing
        const int side = closed || rng.uniform() < real(0.5) ? 1 : -1;
        point3 aim;
        std::vector<std::uint32_t> at_aim;  // the triangles that have the aim
        if (kind == 0) {
            const std::uint32_t v = inner_vertices[pick(inner_vertices.size())];
            aim                   = m.positions[v];
            at_aim                = around[v];
        } else if (kind == 2) {
            const std::size_t f = pick(m.triangles.size());
            aim                 = rt_test::random_point_in(m, f, rng, real(1e-3));
            at_aim              = {static_cast<std::uint32_t>(f)};
        }
        const rt_test::mesh_edge* edge = nullptr;
        if (kind == 1 || kind == 3) {
            edge         = &shared[pick(shared.size())];
            const real s = rng.uniform();
            aim          = m.positions[edge->a] + s * (m.positions[edge->b] - m.positions[edge->a]);
            at_aim       = edge->faces;
        }
        std::vector<vec3> facing;  // their normals, on the ray's side
        for (std::uint32_t f : at_aim) facing.push_back(real(side) * normals[f]);
        vec3 from;  // the unit direction from the aim to the ray's origin
        if (kind == 3) {
            // Along the plane of one of the two triangles, away from it across the edge (so over
            // the other one), tilted towards that plane's front by a tiny angle.
            const std::size_t one = rng.uniform() < real(0.5) ? 0 : 1;
            const vec3 along      = rt::unit_vector(m.positions[edge->b] - m.positions[edge->a]);
            const auto p          = rt_test::corners(m, at_aim[one]);
            vec3 away             = rt::unit_vector(cross(along, facing[one]));
            if (dot(away, (p[0] + p[1] + p[2]) / 3 - aim) > 0) away = -away;
            const real skew = uniform(rng, -1, 1);
            from =
                rt::unit_vector(away + skew * along + log_uniform(rng, lo_graze, -1) * facing[one]);
        }
        if (kind != 3) from = rt_test::random_direction_facing(rng, facing, real(0.1));
        const real distance = size * log_uniform(rng, -2, 2);
        const point3 origin = aim + distance * from;
        const rt::ray r(origin, aim - origin);

        tally& misses = kind == 0   ? result.vertex
                        : kind == 1 ? result.edge
                        : kind == 2 ? result.interior
                                    : result.grazing;
        ++misses.cases;
        rt::triangle_hit nearest;
        std::size_t index = 0;
        const bool hit    = rt_test::nearest_triangle_hit(m, r, forward, nearest, index);
        // A grazing ray sees the shared edge on the mesh's silhouette. In float, the sheared
        // vertices' rounding (relative to an origin up to 100 sizes away) moves the silhouette
        // by ~1e-5 of the mesh, so a ray that the exact line takes just inside can pass just
        // outside (4 of 25,000 on the icosphere): a tangent, not a gap. There a closed mesh is
        // judged by what a gap would do: a line that crosses it an odd number of times.
        const bool tangent = kind == 3 && !is_double && closed && crossings(m, r) % 2 == 0;
        if (!hit && !tangent) misses.fail(ray_text(r));
        if (kind == 3) continue;

        // The aim is where the ray enters (the mesh is convex or flat, and the ray comes from in
        // front of every triangle there): t = 1 up to the rounding of the aim and the direction,
        // seen at a cosine of 0.1 at least.
        ++result.aim.cases;
        const real tolerance = 64 * eps * (1 + rt::max_abs_component(aim) / distance) / real(0.1);
        if (hit && !(std::fabs(nearest.t - 1) <= tolerance))
            result.aim.fail(ray_text(r) + ": t " + std::to_string(nearest.t));

        tally& naive = kind == 0   ? result.naive_vertex
                       : kind == 1 ? result.naive_edge
                                   : result.naive_interior;
        ++naive.cases;
        // Möller-Trumbore over the triangles at the aim (a closed mesh's far side would hide a
        // ray that passed through a crack).
        if (!moller_trumbore_hits_any(m, at_aim, r)) naive.fail(ray_text(r));
    }
    return result;
}

void check_watertight(const watertight_result& r) {
    INFO("rays at shared vertices that hit nothing: " << r.vertex);
    INFO("rays at points of shared edges that hit nothing: " << r.edge);
    INFO("rays at interior points that hit nothing: " << r.interior);
    INFO("grazing rays at shared edges that hit nothing: " << r.grazing);
    INFO("rays whose nearest hit is not their aim: " << r.aim);
    INFO("Moller-Trumbore misses at vertices: " << r.naive_vertex);
    INFO("Moller-Trumbore misses at edges: " << r.naive_edge);
    INFO("Moller-Trumbore misses at interior points: " << r.naive_interior);
    CHECK(r.vertex.failures == 0);
    CHECK(r.edge.failures == 0);
    CHECK(r.interior.failures == 0);
    CHECK(r.grazing.failures == 0);
    CHECK(r.aim.failures == 0);
    // The rays are fine enough to find the cracks of a test that has them, and the reference is
    // right away from the edges.
    CHECK(r.naive_edge.failures > 0);
    CHECK(r.naive_vertex.failures > 0);
    CHECK(r.naive_interior.failures == 0);
}

}  // namespace

TEST_CASE(
    "intersect_triangle: a ray through a dyadic interior point gives t, the weights and "
    "the point exactly",
    "[ch18]") {
    // (2, 3) is p0 + 1/4 (p1 - p0) + 1/2 (p2 - p0): weights 1/4, 1/4, 1/2.
    rt::triangle_hit h;
    REQUIRE(rt::intersect_triangle(rt::sheared_ray(down_onto(2, 3)), q0, q1, q2, forward, h));
    CHECK(h.t == 5);
    CHECK(h.b0 == real(0.25));
    CHECK(h.b1 == real(0.25));
    CHECK(h.b2 == real(0.5));
    // The same point along a tilted direction of length 4.58..., all of it dyadic: t = 1.
    const rt::ray tilted(point3(3, 1, 6), vec3(-1, 2, -4));
    REQUIRE(rt::intersect_triangle(rt::sheared_ray(tilted), q0, q1, q2, forward, h));
    CHECK(h.t == 1);
    CHECK(h.b0 == real(0.25));
    CHECK(h.b1 == real(0.25));
    CHECK(h.b2 == real(0.5));
    // A longer direction: t scales down.
    REQUIRE(rt::intersect_triangle(rt::sheared_ray(rt::ray(point3(2, 3, 7), vec3(0, 0, -4))), q0,
                                   q1, q2, forward, h));
    CHECK(h.t == real(1.25));
    // The weights follow the vertices: listed the other way round, b1 and b2 trade places.
    REQUIRE(rt::intersect_triangle(rt::sheared_ray(down_onto(2, 3)), q0, q2, q1, forward, h));
    CHECK(h.b1 == real(0.5));
    CHECK(h.b2 == real(0.25));
}

TEST_CASE(
    "mesh_triangle: a hit records t, the point, the winding's normal facing the ray, "
    "front_face, (b1, b2), the material and itself",
    "[ch18]") {
    auto mesh                     = one_triangle(q0, q1, q2);
    const rt::mesh_triangle& face = mesh->faces().at(0);
    rt::hit_record rec;
    REQUIRE(face.hit(down_onto(2, 3), forward, rec));
    CHECK(rec.t == 5);
    CHECK(exactly(rec.p, point3(2, 3, 2)));
    CHECK(exactly(rec.normal, vec3(0, 0, 1)));  // unit(cross(p1 - p0, p2 - p0))
    CHECK(rec.front_face);
    CHECK(exactly(rec.local, vec3(0.25, 0.5, 0)));
    CHECK(rec.mat == mesh->surface());
    CHECK(rec.object == &face);
    CHECK(rec.p_error > 0);
    CHECK(rec.p_error <= rt::spawn_offset_scale * 5);  // relative to the largest coordinate, 5

    // From behind: the same t, point and weights; the normal turned to face the ray.
    rt::hit_record back;
    REQUIRE(face.hit(rt::ray(point3(2, 3, -3), vec3(0, 0, 1)), forward, back));
    CHECK(back.t == 5);
    CHECK(exactly(back.p, point3(2, 3, 2)));
    CHECK(exactly(back.normal, vec3(0, 0, -1)));
    CHECK_FALSE(back.front_face);
    CHECK(exactly(back.local, vec3(0.25, 0.5, 0)));
    CHECK(back.mat == mesh->surface());

    // The winding decides the front: the same triangle listed (p0, p2, p1) faces down.
    auto flipped = one_triangle(q0, q2, q1);
    REQUIRE(flipped->faces().at(0).hit(down_onto(2, 3), forward, rec));
    CHECK(exactly(rec.normal, vec3(0, 0, 1)));  // facing the ray still
    CHECK_FALSE(rec.front_face);
    CHECK(exactly(rec.local, vec3(0.5, 0.25, 0)));
}

TEST_CASE(
    "intersect_triangle: on tilted triangles the weights sum to 1 and give the hit point, "
    "and the normal is unit(cross(p1 - p0, p2 - p0)), turned from behind",
    "[ch18]") {
    rt::pcg32 rng(20250118, 1);
    tally sums, points, weights, normals;
    for (int i = 0; i < 20000; ++i) {
        const point3 p0    = random_in_cube(rng, 2);
        const real length1 = uniform(rng, real(0.5), 2);
        const point3 p1    = p0 + length1 * random_unit(rng);
        point3 p2;
        do {
            const real length2 = uniform(rng, real(0.5), 2);
            p2                 = p0 + length2 * random_unit(rng);
        } while (cross(rt::unit_vector(p1 - p0), rt::unit_vector(p2 - p0)).length() < real(0.2));
        auto mesh           = one_triangle(p0, p1, p2);
        const vec3 n        = rt::unit_vector(cross(p1 - p0, p2 - p0));
        const real a        = uniform(rng, real(0.01), real(0.98));
        const real b        = uniform(rng, real(0.01), real(0.99) - a);
        const point3 aim    = p0 + a * (p1 - p0) + b * (p2 - p0);
        const bool in_front = rng.uniform() < real(0.5);
        const vec3 from     = random_in_hemisphere(rng, in_front ? n : -n, real(0.1));
        const point3 origin = aim + uniform(rng, real(0.5), 10) * from;
        const rt::ray r(origin, aim - origin);

        rt::triangle_hit h;
        rt::hit_record rec;
        ++sums.cases;
        if (!rt::intersect_triangle(rt::sheared_ray(r), p0, p1, p2, forward, h) ||
            !mesh->faces()[0].hit(r, forward, rec)) {
            sums.fail("missed: " + ray_text(r));
            continue;
        }
        if (!(std::fabs(h.b0 + h.b1 + h.b2 - 1) <= 4 * eps))
            sums.fail(std::to_string(h.b0 + h.b1 + h.b2 - 1));
        ++points.cases;
        // The aim and the hit are both rounded at the coordinates' scale (up to 4), and the ray
        // misses the aim by the rounding of its direction (up to 10 long) seen at cosine 0.1.
        if (!((rec.p - aim).length() <= 4 * eps * (4 + 10 / real(0.1)))) points.fail(ray_text(r));
        ++weights.cases;
        const real weight_error = is_double ? real(1e-10) : real(1e-3);
        if (!(std::fabs(h.b1 - a) <= weight_error && std::fabs(h.b2 - b) <= weight_error))
            weights.fail(ray_text(r));
        ++normals.cases;
        if (!exactly(rec.normal, in_front ? n : -n) || rec.front_face != in_front ||
            !exactly(rec.local, vec3(h.b1, h.b2, 0)) || rec.t != h.t)
            normals.fail(ray_text(r));
    }
    INFO("weights not summing to 1 (or misses): " << sums);
    INFO("hit points off the aim: " << points);
    INFO("weights off the aim's: " << weights);
    INFO("normals, sides or records not as computed: " << normals);
    CHECK(sums.failures == 0);
    CHECK(points.failures == 0);
    CHECK(weights.failures == 0);
    CHECK(normals.failures == 0);
}

TEST_CASE(
    "intersect_triangle: points exactly on its edges and at its vertices hit (the test is "
    "closed)",
    "[ch18]") {
    const real on_boundary[][2] = {{3, 1}, {1, 3}, {3, 3}, {2, 4}, {1, 1}, {5, 1}, {1, 5}};
    for (const auto& xy : on_boundary) {
        INFO("x = " << xy[0] << ", y = " << xy[1]);
        rt::triangle_hit h;
        REQUIRE(rt::intersect_triangle(rt::sheared_ray(down_onto(xy[0], xy[1])), q0, q1, q2,
                                       forward, h));
        CHECK(h.t == 5);
        CHECK(exactly(h.b0 * q0 + h.b1 * q1 + h.b2 * q2, point3(xy[0], xy[1], 2)));
        // At least one weight is exactly 0 on an edge.
        CHECK((h.b0 == 0 || h.b1 == 0 || h.b2 == 0));
    }
}

TEST_CASE(
    "intersect_triangle: points just outside an edge or beyond a vertex miss, and just "
    "inside hit (1e-9 relative, float 1e-4)",
    "[ch18]") {
    const real margin = is_double ? real(1e-9) : real(1e-4);
    // The dyadic triangle, straight down: outside by 4 margin (its legs are 4 long).
    const real d            = 4 * margin;
    const real outside[][2] = {{3, 1 - d},     {1 - d, 3},     {3 + d, 3 + d},  // edges
                               {1 - d, 1 - d}, {5 + d, 1 - d}, {1 - d, 5 + d},  // vertices
                               {5 + d, 1},     {1, 5 + d}};
    for (const auto& xy : outside) {
        INFO("x = " << xy[0] << ", y = " << xy[1]);
        CHECK_FALSE(hits(down_onto(xy[0], xy[1]), q0, q1, q2));
    }

    // Tilted triangles, rays from random directions: a point of each edge moved out of the
    // triangle in its plane, and each vertex moved away from the centroid, by margin times the
    // size; moved the other way, in by as much, they hit.
    rt::pcg32 rng(20250118, 2);
    tally out_missed, in_hit;
    for (int i = 0; i < 3000; ++i) {
        const point3 p[3] = {random_in_cube(rng, 2), random_in_cube(rng, 2),
                             random_in_cube(rng, 2)};
        const vec3 n      = cross(p[1] - p[0], p[2] - p[0]);
        if (n.length() < real(0.5)) continue;
        const vec3 unit_n     = rt::unit_vector(n);
        const point3 centroid = (p[0] + p[1] + p[2]) / 3;
        for (int k = 0; k < 6; ++k) {
            point3 on;
            vec3 out;
            real size;
            if (k < 3) {  // a point of edge (k, k + 1), and the edge's outward normal in the plane
                const point3 &a = p[k], &b = p[(k + 1) % 3];
                on  = a + uniform(rng, real(0.1), real(0.9)) * (b - a);
                out = rt::unit_vector(cross(b - a, unit_n));
                if (dot(out, centroid - on) > 0) out = -out;
                size = (b - a).length();
            } else {
                on   = p[k - 3];
                out  = rt::unit_vector(on - centroid);
                size = (on - centroid).length();
            }
            for (int sign : {1, -1}) {
                const point3 aim = on + real(sign) * margin * size * out;
                const vec3 from  = random_in_hemisphere(
                     rng, rng.uniform() < real(0.5) ? unit_n : -unit_n, real(0.2));
                const point3 origin = aim + uniform(rng, real(0.5), 5) * from;
                const rt::ray r(origin, aim - origin);
                tally& t = sign == 1 ? out_missed : in_hit;
                ++t.cases;
                if (hits(r, p[0], p[1], p[2]) != (sign == -1))
                    t.fail((k < 3 ? "edge " : "vertex ") + std::to_string(k % 3) + ": " +
                           ray_text(r));
            }
        }
    }
    INFO("points just outside that hit: " << out_missed);
    INFO("points just inside that missed: " << in_hit);
    CHECK(out_missed.cases > 10000);
    CHECK(out_missed.failures == 0);
    CHECK(in_hit.failures == 0);
}

TEST_CASE("intersect_triangle: a ray in the triangle's plane, or parallel to it, misses",
          "[ch18]") {
    // In the plane z = 2, across the triangle; above it; through a vertex along an edge.
    CHECK_FALSE(hits(rt::ray(point3(0, 2, 2), vec3(1, 0, 0)), q0, q1, q2));
    CHECK_FALSE(hits(rt::ray(point3(0, 2, 2), vec3(1, 1, 0)), q0, q1, q2));
    CHECK_FALSE(hits(rt::ray(point3(0, 1, 2), vec3(1, 0, 0)), q0, q1, q2));
    CHECK_FALSE(hits(rt::ray(point3(0, 2, 3), vec3(1, 0.5, 0)), q0, q1, q2));
    // A tilted plane x + y + z = 1, with a dyadic ray in it across the triangle's inside.
    const point3 t0(1, 0, 0), t1(0, 1, 0), t2(0, 0, 1);
    CHECK_FALSE(hits(rt::ray(point3(-0.75, 1.5, 0.25), vec3(1, -1, 0)), t0, t1, t2));
    CHECK_FALSE(hits(rt::ray(point3(-0.75, 1.5, 0.25), vec3(1, -1, 0)), t0, t1, t2,
                     rt::interval::universe()));
    // The same triangle, crossed: the test works there.
    CHECK(hits(rt::ray(point3(0.25, 0.25, 2), vec3(0, 0, -1)), t0, t1, t2));
}

TEST_CASE("intersect_triangle: hits behind the origin or outside ray_t (open) are not reported",
          "[ch18]") {
    // The triangle is 5 behind this ray.
    CHECK_FALSE(hits(rt::ray(point3(2, 3, -3), vec3(0, 0, -1)), q0, q1, q2));
    rt::triangle_hit h;
    REQUIRE(rt::intersect_triangle(rt::sheared_ray(rt::ray(point3(2, 3, -3), vec3(0, 0, -1))), q0,
                                   q1, q2, rt::interval::universe(), h));
    CHECK(h.t == -5);
    // Ahead at t = 5: not in (0, 5), (5, inf) or (0, 4.9); in (4.9, 5.1) and (0, 5 + 1e-9).
    const rt::ray r = down_onto(2, 3);
    CHECK_FALSE(hits(r, q0, q1, q2, rt::interval(0, 5)));
    CHECK_FALSE(hits(r, q0, q1, q2, rt::interval(5, rt::infinity)));
    CHECK_FALSE(hits(r, q0, q1, q2, rt::interval(0, real(4.9))));
    CHECK(hits(r, q0, q1, q2, rt::interval(real(4.9), real(5.1))));
    CHECK(hits(r, q0, q1, q2, rt::interval(0, 5 + 64 * eps)));
    auto mesh = one_triangle(q0, q1, q2);
    rt::hit_record rec;
    CHECK_FALSE(mesh->faces()[0].hit(r, rt::interval(0, 5), rec));
    CHECK(mesh->faces()[0].hit(r, rt::interval(0, 6), rec));
}

TEST_CASE(
    "intersect_triangle: a zero-area triangle (collinear vertices, a vertex repeated) is "
    "never hit",
    "[ch18]") {
    const point3 c0(1, 1, 2), c1(3, 3, 2), c2(5, 5, 2);  // on the line x = y of the plane z = 2
    const rt::ray rays[] = {down_onto(3, 3),
                            down_onto(2, 2),
                            down_onto(1, 1),
                            rt::ray(point3(2, 2, 4), vec3(0.5, 0.5, -1)),
                            rt::ray(point3(0, 4, 2), vec3(1, -1, 0)),
                            rt::ray(point3(4, 0, 4), vec3(-1, 1, -2))};
    for (const rt::ray& r : rays) {
        INFO(ray_text(r));
        CHECK_FALSE(hits(r, c0, c1, c2));
        CHECK_FALSE(hits(r, c1, c0, c2));
        CHECK_FALSE(hits(r, c0, c0, c2));  // a vertex repeated
        CHECK_FALSE(hits(r, c0, c2, c2));
        CHECK_FALSE(hits(r, c1, c1, c1));  // a point
    }
    // The repeated vertex of a real triangle: the ray at (1, 3), on its edge p0 p2, misses the
    // triangle (p0, p0, p2) and hits (p0, p1, p2).
    CHECK_FALSE(hits(down_onto(1, 3), q0, q0, q2));
    CHECK_FALSE(hits(down_onto(2, 2), q0, q0, q2));
    CHECK(hits(down_onto(1, 3), q0, q1, q2));
}

TEST_CASE(
    "intersect_triangle and mesh_triangle: NaN or infinity in the ray or a vertex, or a "
    "zero direction, give no hit and leave the record untouched",
    "[ch18]") {
    const rt::ray bad_rays[] = {
        rt::ray(point3(not_a_number, 3, 7), vec3(0, 0, -1)),
        rt::ray(point3(2, 3, not_a_number), vec3(0, 0, -1)),
        rt::ray(point3(2, 3, 7), vec3(not_a_number, 0, -1)),
        rt::ray(point3(2, 3, 7), vec3(0, 0, not_a_number)),
        rt::ray(point3(2, 3, 7), vec3(not_a_number, not_a_number, not_a_number)),
        rt::ray(point3(2, 3, 7), vec3(0, 0, 0)),
        rt::ray(point3(rt::infinity, 3, 7), vec3(0, 0, -1)),
        rt::ray(point3(2, 3, 7), vec3(0, rt::infinity, -1))};
    auto mesh = one_triangle(q0, q1, q2);
    for (const rt::ray& r : bad_rays) {
        INFO(ray_text(r));
        rt::triangle_hit h{-7, -7, -7, -7};
        CHECK_FALSE(rt::intersect_triangle(rt::sheared_ray(r), q0, q1, q2, forward, h));
        CHECK((h.t == -7 && h.b0 == -7 && h.b1 == -7 && h.b2 == -7));
        rt::hit_record rec;
        rec.t       = -7;
        rec.p       = point3(9, 9, 9);
        rec.p_error = -7;
        CHECK_FALSE(mesh->faces()[0].hit(r, forward, rec));
        CHECK(rec.t == -7);
        CHECK(exactly(rec.p, point3(9, 9, 9)));
        CHECK(rec.p_error == -7);
        CHECK(rec.object == nullptr);
        CHECK(rec.mat == nullptr);
    }
    // A vertex with NaN or infinity (a mesh drops such triangles; the test must not hit them).
    for (real bad : {not_a_number, rt::infinity, -rt::infinity}) {
        INFO("vertex coordinate " << bad);
        rt::triangle_hit h{-7, -7, -7, -7};
        for (int k = 0; k < 3; ++k) {
            point3 p[3] = {q0, q1, q2};
            p[k][k % 2] = bad;  // x or y
            CHECK_FALSE(rt::intersect_triangle(rt::sheared_ray(down_onto(2, 3)), p[0], p[1], p[2],
                                               forward, h));
            p[k] = point3(bad, bad, bad);
            CHECK_FALSE(rt::intersect_triangle(rt::sheared_ray(down_onto(2, 3)), p[0], p[1], p[2],
                                               forward, h));
        }
        CHECK(h.t == -7);
    }
}

TEST_CASE(
    "intersect_triangle: rays at the shared vertices and edges of a closed octahedron never "
    "pass between its triangles",
    "[ch18]") {
    rt::pcg32 rng(20250118, 3);
    const rt::mesh_data m = rt_test::octahedron(point3(0.25, -0.5, 1), 1);
    check_watertight(probe_watertight(m, true, 1, rng, 100000));
}

TEST_CASE(
    "intersect_triangle: rays at the shared vertices and edges of an icosphere (3 "
    "subdivisions) never pass between its triangles",
    "[ch18][hardcase]") {
    rt::pcg32 rng(20250118, 4);
    const rt::mesh_data m = rt_test::icosphere(point3(0.3, 0.2, -0.7), real(1.3), 3);
    REQUIRE(m.triangles.size() == 1280);
    check_watertight(probe_watertight(m, true, real(1.3), rng, 100000));
}

TEST_CASE(
    "intersect_triangle: rays at the shared vertices and edges of a tilted 20 x 20 grid "
    "never pass between its triangles, from either side",
    "[ch18]") {
    rt::pcg32 rng(20250118, 5);
    // Edges that are not dyadic and a plane that is not a coordinate plane: vertices rounded.
    const vec3 u(0.9, 0.3, -0.2), v(-0.25, 0.7, 0.6);
    const rt::mesh_data m = rt_test::quad_grid(point3(-9.1, -2.3, 4.7), u, v, 20);
    REQUIRE(m.triangles.size() == 800);
    check_watertight(probe_watertight(m, false, 1, rng, 100000));
}

TEST_CASE(
    "mesh_triangle: rays spawned from a hit, edges 1e-4..1e4 (float: 1e-2..1e2) and "
    "vertices up to 1e3 away (float: 1e2), never hit the triangle again",
    "[ch18][hardcase]") {
    // The scales as in tests/ch03/test_spawn_ray.cpp. Float's primary rays start at least 0.1
    // sizes from their aim (double: 0.01): at 1e2 a float's ulp is 7.6e-6, and a ray 0.01 sizes
    // from a 1e-2 triangle at a cosine of 0.05 would start 5e-6 above its plane.
    struct scales {
        real log_size, sizes_away, absolute_away, log_min_distance;
    };
    constexpr scales range = is_double ? scales{4, 1e4, 1e3, -2} : scales{2, 1e2, 1e2, -1};
    rt::pcg32 rng(20250118, 6);
    const int n_cases = 100000;
    tally primary, out_spawn, out_reflected, through, tangent, tangent_reflected;
    for (int i = 0; i < n_cases; ++i) {
        const real size  = log_uniform(rng, -range.log_size, range.log_size);
        const point3 p0  = i % 2 == 0 ? random_in_cube(rng, range.sizes_away * size)
                                      : random_in_cube(rng, range.absolute_away);
        const vec3 u_dir = random_unit(rng);
        vec3 v_dir       = random_unit(rng);
        while (cross(u_dir, v_dir).length() < real(0.2)) v_dir = random_unit(rng);
        const point3 p1               = p0 + size * uniform(rng, real(0.5), 2) * u_dir;
        const point3 p2               = p0 + size * uniform(rng, real(0.5), 2) * v_dir;
        auto mesh                     = one_triangle(p0, p1, p2);
        const rt::mesh_triangle& face = mesh->faces().at(0);
        const vec3 n                  = rt::unit_vector(cross(p1 - p0, p2 - p0));

        // The aim at least `margin` of the triangle inside every edge: in float a vertex 1e2
        // away is rounded by 7.6e-6, which at a cosine of 0.05 moves a 1e-2 triangle's hit by
        // 1.5e-4 of an edge's length (a primary ray missed, 1 in 100,000, at margin 0.01).
        const real margin = is_double ? real(0.01) : real(0.05);
        const real a      = uniform(rng, margin, 1 - 2 * margin);
        const real b      = uniform(rng, margin, 1 - margin - a);
        const point3 aim  = p0 + a * (p1 - p0) + b * (p2 - p0);
        const vec3 from = random_in_hemisphere(rng, rng.uniform() < real(0.5) ? n : -n, real(0.05));
        const point3 origin = aim + size * log_uniform(rng, range.log_min_distance, 2) * from;
        const rt::ray incoming(origin, log_uniform(rng, -3, 3) * (aim - origin));
        rt::hit_record rec;
        ++primary.cases;
        if (!face.hit(incoming, forward, rec)) {
            primary.fail("size " + std::to_string(size) + ", " + ray_text(incoming));
            continue;
        }
        auto where = [&] {
            std::ostringstream text;
            text.precision(17);
            text << "p0 " << p0 << ", p1 " << p1 << ", p2 " << p2 << ", p " << rec.p << ", normal "
                 << rec.normal << ", p_error " << rec.p_error;
            return text.str();
        };
        const real scale = log_uniform(rng, -3, 3);
        rt::hit_record again;
        const vec3 out = scale * random_in_hemisphere(rng, rec.normal);
        ++out_spawn.cases;
        if (face.hit(rt::spawn_ray(rec, incoming, out), forward, again))
            out_spawn.fail(where() + ": re-hit at t " + std::to_string(again.t));
        ++out_reflected.cases;
        if (face.hit(rt::spawn_reflected_ray(rec, incoming, out), forward, again))
            out_reflected.fail(where() + ": re-hit at t " + std::to_string(again.t));
        ++through.cases;
        if (face.hit(rt::spawn_ray(rec, incoming, scale * random_in_hemisphere(rng, -rec.normal)),
                     forward, again))
            through.fail(where() + ": re-hit at t " + std::to_string(again.t));
        // Along the plane: the rounded sign of dot(direction, normal) picks the side; either
        // way the ray starts off the plane on the side it moves to, or along it.
        const vec3 along = scale * random_tangent(rng, rec.normal);
        ++tangent.cases;
        if (face.hit(rt::spawn_ray(rec, incoming, along), forward, again))
            tangent.fail(where() + ": re-hit at t " + std::to_string(again.t));
        ++tangent_reflected.cases;
        if (face.hit(rt::spawn_reflected_ray(rec, incoming, along), forward, again))
            tangent_reflected.fail(where() + ": re-hit at t " + std::to_string(again.t));
    }
    INFO("primary rays that missed: " << primary);
    INFO("spawn_ray back to the side they came from that re-hit: " << out_spawn);
    INFO("spawn_reflected_ray back to that side that re-hit: " << out_reflected);
    INFO("spawn_ray through to the other side that re-hit: " << through);
    INFO("spawn_ray along the plane that re-hit: " << tangent);
    INFO("spawn_reflected_ray along the plane that re-hit: " << tangent_reflected);
    CHECK(primary.failures == 0);
    CHECK(out_spawn.failures == 0);
    CHECK(out_reflected.failures == 0);
    CHECK(through.failures == 0);
    CHECK(tangent.failures == 0);
    CHECK(tangent_reflected.failures == 0);
}
