// A triangle mesh: each vertex stored once, each triangle as the indices of its three vertices,
// with a normal and a (u, v) per vertex when the model has them. Chapter 18.
// A mesh is one object of a scene: a BVH over its own triangles (mesh_object), placed in the
// scene's BVH like a sphere. Two levels, as instancing renderers build them: the mesh's tree is
// built once, whatever the scene around it. Its triangles are views into the mesh (the mesh and
// an index), so the vertices are never copied per triangle.
// Shading normals: where the model gives vertex normals, a hit's normal is their interpolation,
// kept within 78 degrees of the true (geometric) normal on the ray's side (a normal that points
// into the surface would make a black spot), and blended towards it until the mirror image of
// the incoming ray leaves above the true plane (a mirror or glass reflection below it would meet
// the surface again and again: a dark rim at a silhouette).
// A new ray still leaves from the true surface, on its true side: p_error is scaled so that the
// offset along the shading normal clears the plane as the geometric one would, and a direction
// a material picks below the plane meets the surface again at once and scatters there, so no
// light passes through (tests/ch18/test_shading_normals.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "rt/accel/bounded.h"
#include "rt/accel/bvh.h"
#include "rt/geometry/triangle.h"
#include "rt/lights/light_set.h"

namespace rt {

class material;

// What a model holds: vertices, and triangles as vertex indices (counted from 0).
struct mesh_data {
    std::vector<point3> positions;
    std::vector<vec3> normals;    // one per vertex, or none
    std::vector<surface_uv> uvs;  // one per vertex, or none
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

class triangle_mesh;

// One triangle of a mesh, as a shape: its mesh and its index. A triangle of an emitting mesh
// is a part of the mesh's one light (rt/lights/mesh_light.h).
class mesh_triangle final : public bounded_hittable, public light_part {
  public:
    mesh_triangle(const triangle_mesh* mesh, std::uint32_t index) : mesh_(mesh), index_(index) {}

    bool emits() const override;
    const void* light_group() const override { return mesh_; }
    std::unique_ptr<light> make_group_light() const override;

    bool hit(const ray& r, interval ray_t, hit_record& rec) const override;
    aabb bounding_box() const override;
    // The vertices' (u, v) interpolated; without them, (0, 0), (1, 0) and (1, 1) at the three
    // corners.
    surface_uv uv_at(const vec3& local) const override;

    const triangle_mesh& mesh() const { return *mesh_; }
    std::uint32_t index() const { return index_; }

  private:
    const triangle_mesh* mesh_;
    std::uint32_t index_;
};

class triangle_mesh {
  public:
    // The most triangles and vertices a mesh may hold (a model is refused before it is read
    // if it declares more: obj_model.h).
    static constexpr std::size_t max_triangles = std::size_t(1) << 27;
    static constexpr std::size_t max_vertices  = std::size_t(1) << 27;

    // Throws user_error for an index beyond the vertices, normals or (u, v) not one per vertex,
    // too many triangles or vertices, or no material. Drops degenerate triangles (zero area, a
    // vertex repeated, a coordinate not finite): dropped_triangles() counts them, for the one
    // warning a loader prints.
    triangle_mesh(mesh_data data, std::shared_ptr<material> mat);
    // Its triangles point at it: it stays where it was made.
    triangle_mesh(const triangle_mesh&)            = delete;
    triangle_mesh& operator=(const triangle_mesh&) = delete;

    std::size_t triangle_count() const { return faces_.size(); }
    std::size_t vertex_count() const { return data_.positions.size(); }
    std::size_t dropped_triangles() const { return dropped_; }
    bool has_normals() const { return !data_.normals.empty(); }
    bool has_uvs() const { return !data_.uvs.empty(); }

    // Triangle i's vertex indices and positions.
    const std::array<std::uint32_t, 3>& triangle(std::size_t i) const { return data_.triangles[i]; }
    const point3& position(std::uint32_t vertex) const { return data_.positions[vertex]; }
    const mesh_data& data() const { return data_; }
    const material* surface() const { return mat_.get(); }
    bool emits() const { return emits_; }  // its material is a diffuse_light
    const std::vector<mesh_triangle>& faces() const { return faces_; }

    // The bytes the mesh holds: vertices, indices, triangles.
    std::size_t bytes() const;

    // Turns rec's normal (the geometric one, facing the ray) into triangle i's shading normal at
    // the hit's barycentric weights, as the comment at the top says. No-op without normals.
    void shade(std::size_t i, const triangle_hit& hit, const ray& r, hit_record& rec) const;

  private:
    friend std::shared_ptr<bvh> mesh_object(const std::shared_ptr<triangle_mesh>& mesh);
    friend std::shared_ptr<bvh> mesh_tree(const triangle_mesh& mesh);

    mesh_data data_;
    std::shared_ptr<material> mat_;
    std::vector<mesh_triangle> faces_;
    std::size_t dropped_ = 0;
    bool emits_          = false;
};

// The mesh as one object of a scene: chapter 07's BVH over its triangles (chapter 17's fast
// traversal packs it with mesh_bvh::packer(): mesh_bvh.h). The BVH's objects share the mesh's
// ownership.
std::shared_ptr<bvh> mesh_object(const std::shared_ptr<triangle_mesh>& mesh);
std::shared_ptr<bvh> mesh_object(mesh_data data, std::shared_ptr<material> mat);
// The same tree over a mesh held elsewhere, which must outlive it (a mesh light's own).
std::shared_ptr<bvh> mesh_tree(const triangle_mesh& mesh);

}  // namespace rt
