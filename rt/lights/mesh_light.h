// A mesh that emits, as one light: a triangle chosen by its share of the mesh's area, then a
// uniform point on it. Chapter 18.
// With every triangle chosen with probability A_i / A and a point of it with density 1 / A_i,
// a point of the mesh has density 1 / A per unit area, whichever triangle it lies on, and per
// solid angle from ref, as a quad light's,
//   pdf(wi) = d^2 / (|cos theta_light| A),
// with theta_light taken at the true (geometric) normal of the triangle hit. So the density of a
// hit needs neither the triangle's own area nor a loop over the triangles: what the light set
// needs for thousands of them. Choosing by area is choosing by power, the radiance being one
// for the whole mesh (a textured light's dark parts are still chosen).
// Both faces emit, as book 2's lights do.
#pragma once

#include <memory>
#include <vector>

#include "rt/accel/mesh_bvh.h"
#include "rt/geometry/triangle_mesh.h"
#include "rt/lights/light.h"

namespace rt {

class mesh_light : public light {
  public:
    // mesh must outlive this light (the scene owns both).
    explicit mesh_light(const triangle_mesh& mesh);

    bool sample(const point3& ref, sample2 u, light_sample& out) const override;
    real pdf(const point3& ref, const vec3& wi) const override;
    real pdf_at(const point3& ref, const vec3& wi, const hit_record& hit) const override;

    real area() const { return total_area; }

    // The triangle a number in [0, 1) chooses, by area, and the number stretched over that
    // triangle's share, again in [0, 1): one number does both.
    std::size_t choose(real& u) const;

  private:
    const triangle_mesh* mesh;
    std::vector<double> cumulative;  // area of triangles 0..i, summed in double
    real total_area = 0;
    // The mesh's triangles, packed as the fast traversal packs a mesh (the same hits as chapter
    // 07's tree), for pdf(): which ones a direction crosses.
    std::shared_ptr<mesh_bvh> tree;
};

}  // namespace rt
