#include "rt/geometry/triangle_mesh.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "rt/core/error.h"
#include "rt/core/exercise.h"
#include "rt/core/validate.h"
#include "rt/lights/mesh_light.h"
#include "rt/materials/diffuse_light.h"

namespace rt {

namespace {

// How far a shading normal may lean from the geometric one: cos 78 degrees. Its p_error is
// divided by this cosine at most, so the spawn offset stays a few hundred ulps.
constexpr real min_shading_cos = real(0.2);
// How far above the true plane the mirror image of the incoming ray about the shading normal
// must leave, as a fraction of the incoming ray's own cosine to the plane: a mirror or glass
// reflection that stayed below it would meet the surface again and again (a silhouette of a
// smooth mesh turns dark).
constexpr real min_mirror_fraction = real(0.01);

// Whether the mirror image of wo about the unit normal n leaves above the plane of g:
// dot(2 dot(wo, n) n - wo, g) >= min_mirror_fraction * dot(wo, g).
bool mirror_clears(const vec3& n, const vec3& g, const vec3& wo, real g_facing) {
    return 2 * dot(wo, n) * dot(n, g) - g_facing >= min_mirror_fraction * g_facing;
}

bool finite(const point3& p) {
    return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
}

// Zero area, a vertex repeated, or a coordinate that is not finite: nothing a ray can hit.
bool degenerate(const mesh_data& d, const std::array<std::uint32_t, 3>& v) {
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) return true;
    const point3 &p0 = d.positions[v[0]], &p1 = d.positions[v[1]], &p2 = d.positions[v[2]];
    if (!finite(p0) || !finite(p1) || !finite(p2)) return true;
    const real area = cross(p1 - p0, p2 - p0).length();
    return !(area > 0) || !std::isfinite(area);
}

void refuse_count(std::size_t count, std::size_t limit, const char* what) {
    if (count <= limit) return;
    std::ostringstream rule;
    rule << "be at most " << limit;
    require(false, what, rule.str().c_str(), count);
}

}  // namespace

triangle_mesh::triangle_mesh(mesh_data data, std::shared_ptr<material> mat)
    : data_(std::move(data)), mat_(std::move(mat)) {
    require_given(mat_, "mesh material");
    emits_              = dynamic_cast<const diffuse_light*>(mat_.get()) != nullptr;
    const std::size_t n = data_.positions.size();
    refuse_count(n, max_vertices, "mesh vertex count");
    refuse_count(data_.triangles.size(), max_triangles, "mesh triangle count");
    require(data_.normals.empty() || data_.normals.size() == n, "mesh normals",
            "be one per vertex or none", data_.normals.size());
    require(data_.uvs.empty() || data_.uvs.size() == n, "mesh (u, v) coordinates",
            "be one per vertex or none", data_.uvs.size());
    std::vector<std::array<std::uint32_t, 3>> kept;
    kept.reserve(data_.triangles.size());
    for (std::size_t i = 0; i < data_.triangles.size(); ++i) {
        const auto& v = data_.triangles[i];
        for (std::uint32_t index : v) {
            if (index < n) continue;
            std::ostringstream what;
            what << "mesh triangle " << i << "'s vertex index";
            std::ostringstream rule;
            rule << "be below the vertex count " << n;
            require(false, what.str().c_str(), rule.str().c_str(), index);
        }
        if (degenerate(data_, v)) {
            ++dropped_;
            continue;
        }
        kept.push_back(v);
    }
    kept.shrink_to_fit();
    data_.triangles = std::move(kept);
    faces_.reserve(data_.triangles.size());
    for (std::size_t i = 0; i < data_.triangles.size(); ++i)
        faces_.emplace_back(this, std::uint32_t(i));
}

std::size_t triangle_mesh::bytes() const {
    return data_.positions.capacity() * sizeof(point3) + data_.normals.capacity() * sizeof(vec3) +
           data_.uvs.capacity() * sizeof(surface_uv) +
           data_.triangles.capacity() * sizeof(data_.triangles[0]) +
           faces_.capacity() * sizeof(mesh_triangle) + sizeof(*this);
}

void triangle_mesh::shade(std::size_t i, const triangle_hit& hit, const ray& r,
                          hit_record& rec) const {
    if (!has_normals()) return;
    // [exercise triangle_mesh::shade begin]
    const auto& v = data_.triangles[i];
    vec3 n =
        hit.b0 * data_.normals[v[0]] + hit.b1 * data_.normals[v[1]] + hit.b2 * data_.normals[v[2]];
    if (!rec.front_face) n = -n;  // the model's normals point out, as its winding does
    const real length = n.length();
    if (!(length > 0) || !std::isfinite(length)) return;  // no usable normal: the geometric one
    n /= length;
    const vec3& g = rec.normal;
    // Within min_shading_cos of the geometric normal: a normal that leans further, or points
    // into the surface, is turned towards it in the plane of the two.
    const real c = dot(n, g);
    if (!(c >= min_shading_cos)) {
        vec3 tangent    = n - c * g;
        tangent         = tangent - dot(tangent, g) * g;  // what rounding left along g
        const real sine = tangent.length();
        // A normal (anti)parallel to g has no direction to lean in: its tangent part is
        // rounding noise (a model whose normals point inwards; fuzz/regressions/obj keeps one).
        if (!(sine > real(1e-3))) return;
        n = min_shading_cos * g +
            std::sqrt(1 - min_shading_cos * min_shading_cos) * (tangent / sine);
    }
    // Facing the viewer, and its mirror reflection leaving the surface: where it does not, the
    // normal is blended towards the geometric one ((1 - t) n + t g; at t = 1 the reflection
    // leaves as from a flat surface), t found by bisection: the least blend that clears, to
    // 2^-20. This also keeps the viewer on the shading normal's side (dot(wo, n) > 0).
    const vec3 wo       = -unit_vector(r.direction());
    const real g_facing = dot(g, wo);
    if (!mirror_clears(n, g, wo, g_facing)) {
        const vec3 shading = n;
        real low = 0, high = 1;
        for (int step = 0; step < 20; ++step) {
            const real t = (low + high) / 2;
            if (mirror_clears(unit_vector((1 - t) * shading + t * g), g, wo, g_facing))
                high = t;
            else
                low = t;
        }
        n = high < 1 ? unit_vector((1 - high) * shading + high * g) : g;
    }
    // A new ray leaving on n's side starts at p + p_error n (spawn_ray.h). That must be the
    // geometric offset p + p_error g: an offset along a leaning n would also move sideways by
    // p_error tan(theta), and beside a concave corner (a room's walls) sideways can be through
    // the next wall. So p_error grows by 1 / cos and p moves within the plane by the opposite of
    // the sideways part: p + (p_error / cos) n is then exactly p + p_error g.
    const real cos_g = dot(n, g);
    rec.p            = rec.p + (rec.p_error / cos_g) * (cos_g * g - n);
    rec.p_error /= cos_g;
    rec.normal = n;
    // [exercise triangle_mesh::shade end]
}

bool mesh_triangle::hit(const ray& r, interval ray_t, hit_record& rec) const {
    const auto& v    = mesh_->triangle(index_);
    const point3& p0 = mesh_->position(v[0]);
    const point3& p1 = mesh_->position(v[1]);
    const point3& p2 = mesh_->position(v[2]);
    triangle_hit found;
    if (!intersect_triangle(sheared_ray(r), p0, p1, p2, ray_t, found)) return false;
    record_triangle_hit(found, p0, p1, p2, r, rec);
    mesh_->shade(index_, found, r, rec);
    rec.mat    = mesh_->surface();
    rec.object = this;
    return true;
}

aabb mesh_triangle::bounding_box() const {
    const auto& v    = mesh_->triangle(index_);
    const point3& p0 = mesh_->position(v[0]);
    const point3& p1 = mesh_->position(v[1]);
    const point3& p2 = mesh_->position(v[2]);
    const aabb corners(aabb(p0, p1), aabb(p2, p2));
    // The test decides an edge by the signs of rounded edge functions, so it may answer a ray
    // an ulp or so outside the vertices' exact box, as a quad does (bounded.cpp).
    return corners.widened(4 * std::numeric_limits<real>::epsilon() * corners.magnitude());
}

surface_uv mesh_triangle::uv_at(const vec3& local) const {
    const real b1 = local.x(), b2 = local.y(), b0 = 1 - b1 - b2;
    if (!mesh_->has_uvs()) return {b1 + b2, b2};
    const auto& v                      = mesh_->triangle(index_);
    const std::vector<surface_uv>& uvs = mesh_->data().uvs;
    return {b0 * uvs[v[0]].u + b1 * uvs[v[1]].u + b2 * uvs[v[2]].u,
            b0 * uvs[v[0]].v + b1 * uvs[v[1]].v + b2 * uvs[v[2]].v};
}

std::shared_ptr<bvh> mesh_object(const std::shared_ptr<triangle_mesh>& mesh) {
    require_given(mesh, "mesh");
    std::vector<bounded_object> objects;
    objects.reserve(mesh->triangle_count());
    // Each triangle shares the mesh's ownership (the aliasing constructor): no allocation per
    // triangle, and the mesh lives as long as any tree that holds one of them.
    for (mesh_triangle& face : mesh->faces_)
        objects.emplace_back(std::shared_ptr<mesh_triangle>(mesh, &face));
    return std::make_shared<bvh>(objects);
}

std::shared_ptr<bvh> mesh_tree(const triangle_mesh& mesh) {
    std::vector<bounded_object> objects;
    objects.reserve(mesh.triangle_count());
    // Pointers that own nothing (an empty owner): the mesh is kept alive by whoever holds it.
    // The tree asks only const members of them.
    for (const mesh_triangle& face : mesh.faces_)
        objects.emplace_back(std::shared_ptr<mesh_triangle>(std::shared_ptr<void>(),
                                                            const_cast<mesh_triangle*>(&face)));
    return std::make_shared<bvh>(objects);
}

bool mesh_triangle::emits() const {
    return mesh_->emits();
}

std::unique_ptr<light> mesh_triangle::make_group_light() const {
    return std::make_unique<mesh_light>(*mesh_);
}

std::shared_ptr<bvh> mesh_object(mesh_data data, std::shared_ptr<material> mat) {
    return mesh_object(std::make_shared<triangle_mesh>(std::move(data), std::move(mat)));
}

}  // namespace rt
