// Tests for triangle_mesh.h (chapter 18): what a mesh refuses (an index beyond its vertices,
// normals or (u, v) that are not one per vertex, no material) and what it drops and counts
// (degenerate triangles, the rest kept in order); that mesh_object's BVH over the triangles finds
// exactly the nearest hit a loop over every triangle finds, the same t to the bit and the same
// triangle, with the mesh's material, boxes around every vertex, and the mesh kept alive by the
// tree alone; and the (u, v) a hit gets, interpolated or the default corners.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "ch03/material_helpers.h"
#include "ch18/mesh_helpers.h"
#include "rt/core/error.h"
#include "rt/core/rng.h"
#include "rt/geometry/triangle_mesh.h"
#include "test_helpers.h"

namespace {

using rt::point3, rt::real, rt::vec3;
using rt_test::exactly, rt_test::log_uniform, rt_test::random_in_cube, rt_test::random_unit,
    rt_test::uniform;

constexpr real eps = std::numeric_limits<real>::epsilon();
const rt::interval forward(0, rt::infinity);

// Three corners of a triangle and a fourth vertex.
rt::mesh_data four_vertices() {
    rt::mesh_data data;
    data.positions = {point3(0, 0, 0), point3(1, 0, 0), point3(0, 1, 0), point3(0, 0, 1)};
    data.triangles = {{0, 1, 2}, {0, 2, 3}};
    return data;
}

bool box_contains(const rt::aabb& box, const point3& p) {
    return box.x.contains(p.x()) && box.y.contains(p.y()) && box.z.contains(p.z());
}

// What a ray finds when every triangle of the mesh is asked with mesh_triangle::hit: the
// nearest t, and every triangle that reports exactly that t (a ray through a shared edge may
// find two at the same t, and then either is right).
struct brute_force_hit {
    bool hit = false;
    real t   = rt::infinity;
    std::vector<const rt::hittable*> at_nearest;
    std::vector<rt::hit_record> records;  // the record of each of them
};

brute_force_hit every_triangle(const rt::triangle_mesh& mesh, const rt::ray& r) {
    brute_force_hit found;
    for (const rt::mesh_triangle& face : mesh.faces()) {
        rt::hit_record rec;
        if (!face.hit(r, forward, rec)) continue;
        if (rec.t < found.t) {
            found.at_nearest.clear();
            found.records.clear();
            found.t = rec.t;
        }
        if (rec.t == found.t) {
            found.hit = true;
            found.at_nearest.push_back(&face);
            found.records.push_back(rec);
        }
    }
    return found;
}

struct comparison {
    long long rays = 0, hits = 0, mismatches = 0;
    std::string first;
};

// Compares mesh_object(mesh)'s answer with the loop's for one ray.
void compare(const rt::bvh& tree, const rt::triangle_mesh& mesh, const rt::ray& r, comparison& c) {
    ++c.rays;
    const brute_force_hit expected = every_triangle(mesh, r);
    rt::hit_record rec;
    const bool hit = tree.hit(r, forward, rec);
    std::ostringstream what;
    what.precision(17);
    what << "origin " << r.origin() << ", direction " << r.direction() << ": ";
    if (hit != expected.hit) {
        what << "BVH " << (hit ? "hit" : "missed") << ", the loop did not";
    } else if (hit) {
        ++c.hits;
        std::size_t k = 0;
        while (k < expected.at_nearest.size() && expected.at_nearest[k] != rec.object) ++k;
        if (rec.t != expected.t) {
            what << "t " << rec.t << " against " << expected.t;
        } else if (k == expected.at_nearest.size()) {
            what << "a triangle the loop did not find at that t";
        } else {
            // The same triangle's own record, field by field.
            const rt::hit_record& own = expected.records[k];
            if (exactly(rec.p, own.p) && exactly(rec.normal, own.normal) &&
                rec.front_face == own.front_face && exactly(rec.local, own.local) &&
                rec.p_error == own.p_error && rec.mat == mesh.surface())
                return;
            what << "a record that differs from the triangle's own";
        }
    } else {
        return;
    }
    if (c.mismatches++ == 0) c.first = what.str();
}

}  // namespace

TEST_CASE(
    "triangle_mesh: a vertex index beyond the vertices throws a user_error naming the "
    "triangle and the index",
    "[ch18]") {
    auto mat = rt_test::any_material();
    {
        rt::mesh_data data = four_vertices();
        data.triangles.push_back({0, 2, 7});
        CHECK_THROWS_AS(rt::triangle_mesh(data, mat), rt::user_error);
        CHECK_THROWS_WITH(rt::triangle_mesh(data, mat), Catch::Contains("mesh triangle 2") &&
                                                            Catch::Contains("got 7") &&
                                                            Catch::Contains("vertex count 4"));
    }
    {
        // The vertex count itself is one too many (indices count from 0); in the first place.
        rt::mesh_data data = four_vertices();
        data.triangles[0]  = {4, 1, 2};
        CHECK_THROWS_WITH(rt::triangle_mesh(data, mat),
                          Catch::Contains("mesh triangle 0") && Catch::Contains("got 4"));
    }
    {
        rt::mesh_data data = four_vertices();
        data.triangles[1]  = {0, 2, 0xFFFFFFFFu};
        CHECK_THROWS_WITH(rt::triangle_mesh(data, mat),
                          Catch::Contains("mesh triangle 1") && Catch::Contains("got 4294967295"));
    }
    // A bad index in a degenerate triangle is still refused, not dropped.
    {
        rt::mesh_data data = four_vertices();
        data.triangles.push_back({9, 9, 9});
        CHECK_THROWS_WITH(rt::triangle_mesh(data, mat),
                          Catch::Contains("mesh triangle 2") && Catch::Contains("got 9"));
    }
    CHECK_NOTHROW(rt::triangle_mesh(four_vertices(), mat));
}

TEST_CASE(
    "triangle_mesh: normals or (u, v) not one per vertex, or no material, throw a "
    "user_error, and none or one per vertex are taken",
    "[ch18]") {
    auto mat = rt_test::any_material();
    for (std::size_t count : {std::size_t(1), std::size_t(3), std::size_t(5)}) {
        INFO("count " << count);
        rt::mesh_data with_normals = four_vertices();
        with_normals.normals.assign(count, vec3(0, 0, 1));
        CHECK_THROWS_AS(rt::triangle_mesh(with_normals, mat), rt::user_error);
        CHECK_THROWS_WITH(rt::triangle_mesh(with_normals, mat),
                          Catch::Contains("normals") && Catch::Contains(std::to_string(count)));
        rt::mesh_data with_uvs = four_vertices();
        with_uvs.uvs.assign(count, rt::surface_uv{0.5, 0.5});
        CHECK_THROWS_AS(rt::triangle_mesh(with_uvs, mat), rt::user_error);
        CHECK_THROWS_WITH(rt::triangle_mesh(with_uvs, mat),
                          Catch::Contains("(u, v)") && Catch::Contains(std::to_string(count)));
    }
    CHECK_THROWS_AS(rt::triangle_mesh(four_vertices(), nullptr), rt::user_error);
    CHECK_THROWS_WITH(rt::triangle_mesh(four_vertices(), nullptr),
                      Catch::Contains("material is missing"));
    CHECK_THROWS_AS(rt::mesh_object(std::shared_ptr<rt::triangle_mesh>()), rt::user_error);

    rt::mesh_data full = four_vertices();
    full.normals.assign(4, vec3(0, 0, 1));
    full.uvs.assign(4, rt::surface_uv{0.5, 0.5});
    const rt::triangle_mesh mesh(full, mat);
    CHECK(mesh.has_normals());
    CHECK(mesh.has_uvs());
    CHECK(mesh.triangle_count() == 2);
    CHECK(mesh.vertex_count() == 4);
    CHECK(mesh.surface() == mat.get());
    const rt::triangle_mesh bare(four_vertices(), mat);
    CHECK_FALSE(bare.has_normals());
    CHECK_FALSE(bare.has_uvs());
}

TEST_CASE(
    "triangle_mesh: degenerate triangles (zero area, a vertex repeated, NaN or infinity) "
    "are dropped and counted, the others kept in order",
    "[ch18]") {
    const real nan_value = std::numeric_limits<real>::quiet_NaN();
    rt::mesh_data data;
    data.positions = {point3(0, 0, 0),         point3(1, 0, 0),
                      point3(0, 1, 0),         point3(2, 0, 0),  // on the line of vertices 0 and 1
                      point3(nan_value, 0, 0), point3(rt::infinity, 0, 0),
                      point3(0, 0, 1)};
    data.triangles = {
        {0, 1, 2},  // kept
        {0, 1, 3},  // collinear
        {0, 2, 6},  // kept
        {1, 1, 2},  // a vertex repeated
        {0, 4, 2},  // NaN
        {5, 1, 2},  // infinity
        {2, 1, 6},  // kept
        {3, 0, 1},  // collinear, in another order
        {6, 6, 6},  // one point
    };
    auto mat  = rt_test::any_material();
    auto mesh = std::make_shared<rt::triangle_mesh>(data, mat);
    CHECK(mesh->dropped_triangles() == 6);
    REQUIRE(mesh->triangle_count() == 3);
    CHECK(mesh->triangle(0) == rt_test::triangle_indices{0, 1, 2});
    CHECK(mesh->triangle(1) == rt_test::triangle_indices{0, 2, 6});
    CHECK(mesh->triangle(2) == rt_test::triangle_indices{2, 1, 6});
    CHECK(mesh->vertex_count() == 7);  // vertices stay, even those no triangle uses now
    REQUIRE(mesh->faces().size() == 3);
    for (std::uint32_t i = 0; i < 3; ++i) {
        CHECK(mesh->faces()[i].index() == i);
        CHECK(&mesh->faces()[i].mesh() == mesh.get());
    }
    // The kept triangles are the ones rays find: from below, z = 0 first; from above, the
    // face x + y + z = 1.
    auto object = rt::mesh_object(mesh);
    CHECK(object->object_count() == 3);
    rt::hit_record rec;
    REQUIRE(object->hit(rt::ray(point3(0.25, 0.25, -5), vec3(0, 0, 1)), forward, rec));
    CHECK(rec.object == &mesh->faces()[0]);
    CHECK(rec.t == 5);
    REQUIRE(object->hit(rt::ray(point3(0.25, 0.25, 5), vec3(0, 0, -1)), forward, rec));
    CHECK(rec.object == &mesh->faces()[2]);
    CHECK(rec.t == real(4.5));

    // Nothing left: a tree over nothing, which no ray hits.
    rt::mesh_data none = data;
    none.triangles     = {{0, 1, 3}, {1, 1, 2}, {0, 4, 2}};
    auto empty         = std::make_shared<rt::triangle_mesh>(none, mat);
    CHECK(empty->triangle_count() == 0);
    CHECK(empty->dropped_triangles() == 3);
    auto empty_object = rt::mesh_object(empty);
    CHECK_FALSE(empty_object->hit(rt::ray(point3(0.25, 0.25, 5), vec3(0, 0, -1)), forward, rec));
}

TEST_CASE(
    "triangle_mesh: bytes() counts at least the vertices, normals, (u, v) and indices it "
    "holds",
    "[ch18]") {
    std::vector<vec3> directions;
    rt::mesh_data data = rt_test::icosphere(point3(0, 0, 0), 1, 2, &directions);
    data.normals       = directions;
    data.uvs.assign(data.positions.size(), rt::surface_uv{0.5, 0.5});
    const std::size_t held = data.positions.size() * sizeof(point3) +
                             data.normals.size() * sizeof(vec3) +
                             data.uvs.size() * sizeof(rt::surface_uv) +
                             data.triangles.size() * 3 * sizeof(std::uint32_t);
    const rt::triangle_mesh mesh(data, rt_test::any_material());
    CHECK(mesh.bytes() >= held);
    // And it is the mesh's own count, not a constant: the same mesh without normals and (u, v)
    // is smaller by at least what they held.
    data.normals.clear();
    data.uvs.clear();
    const rt::triangle_mesh bare(data, rt_test::any_material());
    CHECK(bare.bytes() + directions.size() * (sizeof(vec3) + sizeof(rt::surface_uv)) <=
          mesh.bytes());
    CHECK(bare.bytes() >= held - directions.size() * (sizeof(vec3) + sizeof(rt::surface_uv)));
}

TEST_CASE(
    "mesh_object: its nearest hit on an icosphere is the loop over every triangle's, the "
    "same t to the bit and the same triangle",
    "[ch18]") {
    auto mesh = std::make_shared<rt::triangle_mesh>(
        rt_test::icosphere(point3(0.5, -0.25, 2), real(1.5), 3), rt_test::any_material());
    auto tree = rt::mesh_object(mesh);
    rt::pcg32 rng(20250118, 11);
    comparison c;
    for (int i = 0; i < 6000; ++i) {
        // Half from anywhere around (some inside), in any direction; half aimed at a vertex or
        // a point of the surface, so that many rays cross shared edges and vertices.
        const point3 origin = point3(0.5, -0.25, 2) + random_in_cube(rng, 4);
        vec3 direction;
        if (i % 2 == 0) {
            direction = random_unit(rng);
        } else {
            const auto& data = mesh->data();
            const std::size_t f =
                std::min(data.triangles.size() - 1,
                         static_cast<std::size_t>(rng.uniform() * real(data.triangles.size())));
            const point3 aim = i % 4 == 1 ? data.positions[data.triangles[f][0]]
                                          : rt_test::random_point_in(data, f, rng);
            direction        = aim - origin;
        }
        compare(*tree, *mesh, rt::ray(origin, log_uniform(rng, -2, 2) * direction), c);
    }
    INFO(c.mismatches << " of " << c.rays << " rays differ (first: " << c.first << ")");
    CHECK(c.mismatches == 0);
    CHECK(c.hits > c.rays / 2);
}

TEST_CASE(
    "mesh_object: its nearest hit on a soup of 2000 random triangles is the loop over "
    "every triangle's, the same t to the bit and the same triangle",
    "[ch18]") {
    rt::pcg32 rng(20250118, 12);
    const rt::mesh_data data = rt_test::triangle_soup(rng, 2000, 10, -1, real(0.5));
    auto mesh                = std::make_shared<rt::triangle_mesh>(data, rt_test::any_material());
    REQUIRE(mesh->triangle_count() == 2000);
    auto tree = rt::mesh_object(mesh);
    comparison c;
    for (int i = 0; i < 5000; ++i) {
        const point3 origin = random_in_cube(rng, 12);
        vec3 direction      = random_unit(rng);
        if (i % 2 == 1) {
            const std::size_t f = std::min(std::size_t(1999), std::size_t(rng.uniform() * 2000));
            direction           = rt_test::random_point_in(data, f, rng) - origin;
        }
        compare(*tree, *mesh, rt::ray(origin, direction), c);
    }
    INFO(c.mismatches << " of " << c.rays << " rays differ (first: " << c.first << ")");
    CHECK(c.mismatches == 0);
    CHECK(c.hits > c.rays / 2);
}

TEST_CASE(
    "mesh_object: a hit's object is the mesh's triangle and its material the mesh's, and "
    "every box holds its vertices",
    "[ch18]") {
    auto mat = std::make_shared<rt::lambertian>(rt::color(0.25, 0.5, 0.75));
    auto mesh =
        std::make_shared<rt::triangle_mesh>(rt_test::icosphere(point3(-1, 2, 0.5), 3, 2), mat);
    auto tree       = rt::mesh_object(mesh);
    const auto& all = mesh->faces();
    rt::pcg32 rng(20250118, 13);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const point3 origin = point3(-1, 2, 0.5) + 5 * random_unit(rng);
        const point3 aim    = point3(-1, 2, 0.5) + random_in_cube(rng, 2);
        rt::hit_record rec;
        if (!tree->hit(rt::ray(origin, aim - origin), forward, rec)) continue;
        ++hits;
        const auto* face = dynamic_cast<const rt::mesh_triangle*>(rec.object);
        REQUIRE(face != nullptr);
        CHECK(&face->mesh() == mesh.get());
        CHECK(face == &all[face->index()]);
        CHECK(rec.mat == mat.get());
        CHECK(rec.front_face);  // from outside
    }
    CHECK(hits > 1000);

    // Each triangle's box holds its corners, and is tight: a few ulps wider at most.
    rt::aabb all_vertices;
    for (const point3& p : mesh->data().positions)
        all_vertices = rt::aabb(all_vertices, rt::aabb(p, p));
    for (const rt::mesh_triangle& face : all) {
        const rt::aabb box = face.bounding_box();
        const auto& v      = mesh->triangle(face.index());
        const rt::aabb corners(rt::aabb(mesh->position(v[0]), mesh->position(v[1])),
                               rt::aabb(mesh->position(v[2]), mesh->position(v[2])));
        for (int k = 0; k < 3; ++k) CHECK(box_contains(box, mesh->position(v[k])));
        const real slack = 16 * eps * corners.magnitude();
        CHECK(box.x.min >= corners.x.min - slack);
        CHECK(box.x.max <= corners.x.max + slack);
        CHECK(box.y.min >= corners.y.min - slack);
        CHECK(box.y.max <= corners.y.max + slack);
        CHECK(box.z.min >= corners.z.min - slack);
        CHECK(box.z.max <= corners.z.max + slack);
    }
    for (const point3& p : mesh->data().positions) CHECK(box_contains(tree->bounding_box(), p));
    CHECK(tree->bounding_box().x.size() <= all_vertices.x.size() * (1 + 64 * eps));
}

TEST_CASE("mesh_object: the tree alone keeps the mesh alive", "[ch18]") {
    auto mat  = rt_test::any_material();
    auto mesh = std::make_shared<rt::triangle_mesh>(rt_test::octahedron(point3(0, 0, -3), 1), mat);
    const std::weak_ptr<rt::triangle_mesh> watch = mesh;
    const rt::triangle_mesh* where               = mesh.get();
    auto tree                                    = rt::mesh_object(mesh);
    mesh.reset();
    REQUIRE_FALSE(watch.expired());
    rt::hit_record rec;
    REQUIRE(tree->hit(rt::ray(point3(0.125, 0.25, 0), vec3(0, 0, -1)), forward, rec));
    CHECK(rec.t == real(2.375));  // its face x + y + (z + 3) = 1
    CHECK(rec.mat == mat.get());
    CHECK(&dynamic_cast<const rt::mesh_triangle*>(rec.object)->mesh() == where);
    tree.reset();
    CHECK(watch.expired());  // and it goes with the tree

    // The overload that makes the mesh itself.
    auto own = rt::mesh_object(rt_test::octahedron(point3(0, 0, -3), 1), mat);
    REQUIRE(own->hit(rt::ray(point3(0.125, 0.25, 0), vec3(0, 0, -1)), forward, rec));
    CHECK(rec.t == real(2.375));
    CHECK(rec.mat == mat.get());
}

TEST_CASE("mesh_triangle: uv_at interpolates the vertices' (u, v) at the hit's weights", "[ch18]") {
    rt::mesh_data data;
    data.positions = {point3(1, 1, 2), point3(5, 1, 2), point3(1, 5, 2)};
    data.triangles = {{0, 1, 2}};
    data.uvs       = {{0.5, 0.25}, {1, 0.75}, {0.25, 1}};
    auto mesh      = std::make_shared<rt::triangle_mesh>(data, rt_test::any_material());
    auto tree      = rt::mesh_object(mesh);
    rt::hit_record rec;
    // (2, 3): weights 1/4, 1/4, 1/2, so u = 1/8 + 1/4 + 1/8 and v = 1/16 + 3/16 + 1/2.
    REQUIRE(tree->hit(rt::ray(point3(2, 3, 7), vec3(0, 0, -1)), forward, rec));
    CHECK(rec.uv().u == real(0.5));
    CHECK(rec.uv().v == real(0.75));
    // At the corners, each vertex's own.
    const real corners_xy[3][2] = {{1, 1}, {5, 1}, {1, 5}};
    for (int k = 0; k < 3; ++k) {
        REQUIRE(tree->hit(rt::ray(point3(corners_xy[k][0], corners_xy[k][1], 7), vec3(0, 0, -1)),
                          forward, rec));
        CHECK(rec.uv().u == data.uvs[std::size_t(k)].u);
        CHECK(rec.uv().v == data.uvs[std::size_t(k)].v);
    }
    // Anywhere: the interpolation at the weights the hit recorded, from either side.
    rt::pcg32 rng(20250118, 14);
    for (int i = 0; i < 200; ++i) {
        const point3 aim    = rt_test::random_point_in(data, 0, rng);
        const real distance = uniform(rng, 1, 3);
        const point3 origin = aim + distance * rt_test::random_unit(rng);
        if (!tree->hit(rt::ray(origin, aim - origin), forward, rec)) continue;
        const real b1 = rec.local.x(), b2 = rec.local.y(), b0 = 1 - b1 - b2;
        const rt::surface_uv uv = rec.uv();
        CHECK(std::fabs(uv.u - (b0 * real(0.5) + b1 * 1 + b2 * real(0.25))) <= 4 * eps);
        CHECK(std::fabs(uv.v - (b0 * real(0.25) + b1 * real(0.75) + b2 * 1)) <= 4 * eps);
    }
}

TEST_CASE(
    "mesh_triangle: without (u, v), uv_at gives (0, 0), (1, 0) and (1, 1) at the corners: "
    "(b1 + b2, b2)",
    "[ch18]") {
    auto mesh = std::make_shared<rt::triangle_mesh>(
        [] {
            rt::mesh_data data;
            data.positions = {point3(1, 1, 2), point3(5, 1, 2), point3(1, 5, 2)};
            data.triangles = {{0, 1, 2}};
            return data;
        }(),
        rt_test::any_material());
    auto tree = rt::mesh_object(mesh);
    rt::hit_record rec;
    const real expected[][4] = {// x, y, u, v
                                {1, 1, 0, 0},      {5, 1, 1, 0},   {1, 5, 1, 1},
                                {2, 3, 0.75, 0.5}, {3, 1, 0.5, 0}, {3, 3, 1, 0.5}};
    for (const auto& e : expected) {
        INFO("x = " << e[0] << ", y = " << e[1]);
        REQUIRE(tree->hit(rt::ray(point3(e[0], e[1], 7), vec3(0, 0, -1)), forward, rec));
        CHECK(rec.uv().u == e[2]);
        CHECK(rec.uv().v == e[3]);
    }
}
