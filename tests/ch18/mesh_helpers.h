// Meshes that chapter 18's tests build in code, with what the tests need to know about them: the
// closed octahedron and icosphere (every vertex and edge shared, wound outwards), a flat grid of
// quads cut into triangles over shared vertices, and a closed box; the edges and the faces around
// each vertex, so that a test can aim rays at them; and a brute-force nearest hit over all
// triangles with intersect_triangle, which isolates the triangle test from any BVH. Included as
// "ch18/mesh_helpers.h".
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "rt/core/rng.h"
#include "rt/geometry/triangle.h"
#include "rt/geometry/triangle_mesh.h"
#include "test_helpers.h"

namespace rt_test {

using triangle_indices = std::array<std::uint32_t, 3>;

// Triangle i's vertices.
inline std::array<rt::point3, 3> corners(const rt::mesh_data& m, std::size_t i) {
    const triangle_indices& v = m.triangles[i];
    return {m.positions[v[0]], m.positions[v[1]], m.positions[v[2]]};
}

// Triangle i's normal by its winding, as record_triangle_hit computes it.
inline rt::vec3 face_normal(const rt::mesh_data& m, std::size_t i) {
    const auto p = corners(m, i);
    return rt::unit_vector(cross(p[1] - p[0], p[2] - p[0]));
}

// Turns every triangle of a closed mesh around `center` (star-shaped about it) so that its
// winding's normal points away from center.
inline void wind_outwards(rt::mesh_data& m, const rt::point3& center) {
    for (std::size_t i = 0; i < m.triangles.size(); ++i) {
        const auto p              = corners(m, i);
        const rt::point3 centroid = (p[0] + p[1] + p[2]) / 3;
        if (dot(cross(p[1] - p[0], p[2] - p[0]), centroid - center) < 0)
            std::swap(m.triangles[i][1], m.triangles[i][2]);
    }
}

// The octahedron with vertices center +- radius along each axis: 6 vertices, 8 triangles.
inline rt::mesh_data octahedron(const rt::point3& center, rt::real radius) {
    rt::mesh_data m;
    const rt::vec3 axes[] = {rt::vec3(1, 0, 0),  rt::vec3(-1, 0, 0), rt::vec3(0, 1, 0),
                             rt::vec3(0, -1, 0), rt::vec3(0, 0, 1),  rt::vec3(0, 0, -1)};
    for (const rt::vec3& a : axes) m.positions.push_back(center + radius * a);
    for (std::uint32_t x : {0u, 1u})
        for (std::uint32_t y : {2u, 3u})
            for (std::uint32_t z : {4u, 5u}) m.triangles.push_back({x, y, z});
    wind_outwards(m, center);
    return m;
}

// The icosahedron subdivided `subdivisions` times (each triangle into four, the new vertices
// pushed out onto the sphere), around center: 20 * 4^n triangles, each vertex stored once.
// Its directions from center, unit, are in `unit_directions` when asked for (smooth normals).
inline rt::mesh_data icosphere(const rt::point3& center, rt::real radius, int subdivisions,
                               std::vector<rt::vec3>* unit_directions = nullptr) {
    const rt::real t        = (1 + std::sqrt(rt::real(5))) / 2;
    std::vector<rt::vec3> u = {rt::vec3(-1, t, 0),  rt::vec3(1, t, 0),   rt::vec3(-1, -t, 0),
                               rt::vec3(1, -t, 0),  rt::vec3(0, -1, t),  rt::vec3(0, 1, t),
                               rt::vec3(0, -1, -t), rt::vec3(0, 1, -t),  rt::vec3(t, 0, -1),
                               rt::vec3(t, 0, 1),   rt::vec3(-t, 0, -1), rt::vec3(-t, 0, 1)};
    for (rt::vec3& d : u) d = rt::unit_vector(d);
    std::vector<triangle_indices> faces = {
        {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
        {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int level = 0; level < subdivisions; ++level) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
        auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            const auto key   = std::minmax(a, b);
            const auto found = midpoints.find(key);
            if (found != midpoints.end()) return found->second;
            const auto index = static_cast<std::uint32_t>(u.size());
            u.push_back(rt::unit_vector(u[a] + u[b]));
            midpoints.emplace(key, index);
            return index;
        };
        std::vector<triangle_indices> finer;
        for (const triangle_indices& f : faces) {
            const std::uint32_t ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]),
                                ca = midpoint(f[2], f[0]);
            finer.push_back({f[0], ab, ca});
            finer.push_back({f[1], bc, ab});
            finer.push_back({f[2], ca, bc});
            finer.push_back({ab, bc, ca});
        }
        faces = std::move(finer);
    }
    rt::mesh_data m;
    for (const rt::vec3& d : u) m.positions.push_back(center + radius * d);
    m.triangles = std::move(faces);
    wind_outwards(m, center);
    if (unit_directions) *unit_directions = u;
    return m;
}

// An n x n grid of quads, corner + i u + j v for i, j in 0..n, each quad cut along a diagonal
// into two triangles wound like u x v; vertex (i, j) is index j (n + 1) + i.
inline rt::mesh_data quad_grid(const rt::point3& corner, const rt::vec3& u, const rt::vec3& v,
                               int n) {
    rt::mesh_data m;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            m.positions.push_back(corner + rt::real(i) * u + rt::real(j) * v);
    const auto at = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            // Alternate the diagonal, so that vertices have 4 or 8 triangles around them.
            if ((i + j) % 2 == 0) {
                m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
                m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
            } else {
                m.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
                m.triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
            }
        }
    }
    return m;
}

// The closed box [lo, hi]: 8 vertices, 12 triangles wound outwards.
inline rt::mesh_data box_mesh(const rt::point3& lo, const rt::point3& hi) {
    rt::mesh_data m;
    for (int k = 0; k < 8; ++k)
        m.positions.push_back(
            rt::point3(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z()));
    // Each face as a quad of corner indices, cut into two triangles.
    const std::uint32_t quads[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        m.triangles.push_back({q[0], q[1], q[2]});
        m.triangles.push_back({q[0], q[2], q[3]});
    }
    wind_outwards(m, (lo + hi) / 2);
    return m;
}

// An edge of a mesh, its vertices a < b, and the triangles that have it.
struct mesh_edge {
    std::uint32_t a, b;
    std::vector<std::uint32_t> faces;
};

inline std::vector<mesh_edge> edges_of(const rt::mesh_data& m) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> found;
    for (std::size_t i = 0; i < m.triangles.size(); ++i)
        for (int k = 0; k < 3; ++k)
            found[std::minmax(m.triangles[i][k], m.triangles[i][(k + 1) % 3])].push_back(
                static_cast<std::uint32_t>(i));
    std::vector<mesh_edge> edges;
    for (auto& [key, faces] : found) edges.push_back({key.first, key.second, faces});
    return edges;
}

// The triangles around each vertex.
inline std::vector<std::vector<std::uint32_t>> faces_around_vertices(const rt::mesh_data& m) {
    std::vector<std::vector<std::uint32_t>> around(m.positions.size());
    for (std::size_t i = 0; i < m.triangles.size(); ++i)
        for (std::uint32_t v : m.triangles[i]) around[v].push_back(static_cast<std::uint32_t>(i));
    return around;
}

// The nearest hit of r with any triangle of m inside ray_t, by trying every one of them with
// intersect_triangle (no BVH); `index` is the first triangle at the nearest t.
inline bool nearest_triangle_hit(const rt::mesh_data& m, const rt::ray& r, rt::interval ray_t,
                                 rt::triangle_hit& nearest, std::size_t& index) {
    const rt::sheared_ray sr(r);
    bool any = false;
    for (std::size_t i = 0; i < m.triangles.size(); ++i) {
        const auto p = corners(m, i);
        rt::triangle_hit h;
        if (rt::intersect_triangle(sr, p[0], p[1], p[2], ray_t, h)) {
            any       = true;
            nearest   = h;
            index     = i;
            ray_t.max = h.t;
        }
    }
    return any;
}

// `count` triangles, each vertex stored for it alone: a corner uniform in the cube of half side
// `half_side` about the origin, and the two others at distances log-uniform in
// [10^lo_exponent, 10^hi_exponent] from it, in uniform directions.
inline rt::mesh_data triangle_soup(rt::pcg32& rng, std::uint32_t count, rt::real half_side,
                                   rt::real lo_exponent, rt::real hi_exponent) {
    rt::mesh_data data;
    for (std::uint32_t i = 0; i < count; ++i) {
        const rt::point3 p0    = random_in_cube(rng, half_side);
        const rt::real length1 = log_uniform(rng, lo_exponent, hi_exponent);
        const rt::point3 p1    = p0 + length1 * random_unit(rng);
        const rt::real length2 = log_uniform(rng, lo_exponent, hi_exponent);
        const rt::point3 p2    = p0 + length2 * random_unit(rng);
        data.positions.insert(data.positions.end(), {p0, p1, p2});
        data.triangles.push_back({3 * i, 3 * i + 1, 3 * i + 2});
    }
    return data;
}

// A point of triangle i at barycentric weights drawn uniformly over it, each weight at least
// `margin` (margin < 1/3): three draws.
inline rt::point3 random_point_in(const rt::mesh_data& m, std::size_t i, rt::pcg32& rng,
                                  rt::real margin = 0) {
    const auto p = corners(m, i);
    for (;;) {
        rt::real a = rng.uniform();
        rt::real b = rng.uniform();
        if (a + b > 1) {
            a = 1 - a;
            b = 1 - b;
        }
        const rt::real c = 1 - a - b;
        if (a >= margin && b >= margin && c >= margin) return c * p[0] + a * p[1] + b * p[2];
    }
}

// A unit direction u with dot(u, n) >= min_cos for every n in normals (all of them on one side),
// by rejection from the sphere; side -1 asks for dot(u, n) <= -min_cos instead.
inline rt::vec3 random_direction_facing(rt::pcg32& rng, const std::vector<rt::vec3>& normals,
                                        rt::real min_cos, int side = 1) {
    for (;;) {
        const rt::vec3 u = random_unit(rng);
        bool ok          = true;
        for (const rt::vec3& n : normals) ok = ok && rt::real(side) * dot(u, n) >= min_cos;
        if (ok) return u;
    }
}

}  // namespace rt_test
