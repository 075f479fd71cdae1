// A participating medium of constant density inside a boundary (smoke, fog, mist). Chapter 12.
// A ray crossing it scatters in a small step dL with probability density * dL, so the distance it
// travels before scattering is exponential: d = -ln(xi) / density. If d is shorter than the
// ray's path inside the boundary, the ray scatters there (isotropically); otherwise it passes.
//
// The boundary must be convex: the ray's path inside is taken as [entry, exit] of its first
// two boundary hits. A concave boundary (or two disjoint pieces) is treated as filled between
// its first entry and the next exit only: a ray that leaves and re-enters sees just the first
// stretch. Rays that start inside (after scattering, or inside a glass sphere that holds the
// medium) work: the entry then lies behind them and the path starts at t = 0.
//
// xi comes from hashing the ray itself (the bits of its origin, direction and instant) with this
// medium's own id, not from the sampler: hit() has no sampler, and so scenes without media pay
// nothing for them (no sampler dimensions, no extra field in every ray). A path's rays are
// random, so their hashes are too; the render stays deterministic. Each medium a segment crosses
// makes its own choice (the id hashes the medium's box and density), and one medium placed twice
// by instances chooses independently in each placement, since each sees the ray in its own frame.
#pragma once

#include <cstdint>
#include <memory>

#include "rt/accel/bounded.h"
#include "rt/textures/texture.h"

namespace rt {

class constant_medium : public bounded_hittable {
  public:
    // density > 0 and finite; throws user_error otherwise.
    constant_medium(const bounded_object& boundary, real density, const color& albedo);
    constant_medium(const bounded_object& boundary, real density, std::shared_ptr<texture> albedo);

    // A hit is a scattering event inside: p on the ray, no surface, so the record's normal is
    // arbitrary and p_error 0 (new rays start exactly at p).
    bool hit(const ray& r, interval ray_t, hit_record& rec) const override;
    aabb bounding_box() const override { return box; }

    // [ch14 begin]
    // exp(-density * length of r's path inside the boundary within ray_t): the probability that
    // hit() lets the ray through, given exactly rather than drawn.
    real transmittance(const ray& r, interval ray_t) const override;
    // [ch14 end]

    // The uniform number in (0, 1] this medium draws for ray r.
    real random_for(const ray& r) const;

    // [ch17 begin]
    // What it was made with: for aiming at the lights along a ray through it
    // (rt/integrators/in_scattering.h), and for a scene file (rt/scene_files).
    real density() const { return given_density; }
    const material& phase() const { return *phase_function; }
    // The stretch [t_in, t_out) of r inside the boundary and within ray_t; false if none.
    bool stretch(const ray& r, interval ray_t, real& t_in, real& t_out) const {
        return inside_stretch(r, ray_t, t_in, t_out);
    }
    // [ch17 end]

    // [ch19 begin]
    const std::shared_ptr<hittable>& boundary_object() const { return boundary; }
    // [ch19 end]

  private:
    // The stretch [t_in, t_out) of r inside the boundary and within ray_t; false if none.
    bool inside_stretch(const ray& r, interval ray_t, real& t_in, real& t_out) const;

    std::shared_ptr<hittable> boundary;
    aabb box;
    real neg_inv_density;
    std::shared_ptr<material> phase_function;
    std::uint64_t id;
    real given_density = 0;  // [ch17] as given: -1 / neg_inv_density need not give it back
};

}  // namespace rt
