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
// xi comes from hashing the ray's random key (drawn from the sampler per path segment) with
// this medium's own id, so each medium a segment crosses makes an independent choice, and the
// render stays deterministic. The id is a hash of the medium's box and density. One medium placed
// twice by instances (translate, rotate) also chooses independently in each placement, because an
// instance hands its object a key of its own (instance.h).
#pragma once

#include <cstdint>
#include <memory>

#include "hittable.h"
#include "texture.h"

namespace rt {

class constant_medium : public hittable {
  public:
    // density > 0 and finite; throws user_error otherwise.
    constant_medium(std::shared_ptr<hittable> boundary, real density, const color& albedo);
    constant_medium(std::shared_ptr<hittable> boundary, real density,
                    std::shared_ptr<texture> albedo);

    // A hit is a scattering event inside: p on the ray, no surface, so the record's normal is
    // arbitrary and p_error 0 (new rays start exactly at p).
    bool hit(const ray& r, interval ray_t, hit_record& rec) const override;
    aabb bounding_box() const override { return boundary->bounding_box(); }

  private:
    std::shared_ptr<hittable> boundary;
    real neg_inv_density;
    std::shared_ptr<material> phase_function;
    std::uint64_t id;
};

}  // namespace rt
