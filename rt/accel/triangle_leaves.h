// A mesh's triangles kept in chapter 17's wide BVH leaves by type (leaf_shapes.h): a run of
// triangles is tested in one loop, the ray's turn and shear computed once for the run, and the
// hit record filled once, for the nearest. Chapter 18.
// Each triangle is kept as its three vertex indices and its mesh's vertex array, so the
// vertices stay stored once; the answers are mesh_triangle::hit's, so the image is the one
// chapter 07's tree gives, byte for byte.
#pragma once

#include "rt/accel/leaf_shapes.h"
#include "rt/geometry/triangle_mesh.h"

namespace rt {

class triangle_leaves final : public leaf_shapes {
  public:
    std::optional<std::uint32_t> add(const hittable& object) override;
    bool hit(std::uint32_t first, std::uint32_t count, const ray& r, interval& ray_t,
             hit_record& rec) const override;

    // What with_fast_traversal() and wide_bvh take to make one per tree.
    static leaf_shapes_maker maker();

  private:
    struct one {
        const point3* positions;  // the mesh's vertices
        std::array<std::uint32_t, 3> vertex;
        const mesh_triangle* object;
    };
    std::vector<one> fields;
};

}  // namespace rt
