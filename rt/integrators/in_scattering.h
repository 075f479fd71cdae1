// The light that media scatter once towards the eye, aimed at along the whole ray rather than
// from where the ray happens to scatter. Chapter 12's medium lets a ray through thin mist scatter
// at a random point, and only that point (a tenth of the rays, in book 2's final scene) then aims
// at a light. Here every segment through a medium aims at the lights once, from a point chosen
// along it by equiangular sampling (rt/media/equiangular.h), nearer the lights more often:
//   L ~= T(0, s) sigma_s f(wi) Le(wi) V / (pdf_light(wi) pdf(s) P(medium)),
// with T the transmittance up to the point, sigma_s the medium's density times its albedo (in
// f, the phase function), V the transmittance on to the light. The path goes on as before
// (multiple scattering still comes from chapter 12's random hits); at a medium point it reaches
// that way it aims at no light, and counts none that its next segment finds and the light set
// could have aimed at: that light was counted along the segment before. Chapter 17.
//
// Which media: those a light search would find (lists and BVHs, not inside instances); a medium
// placed by an instance keeps chapter 15's way, each point deciding for its own medium.
#pragma once

#include <vector>

#include "rt/integrators/mis_tracer.h"
#include "rt/media/constant_medium.h"

namespace rt {

class in_scattering final : public segment_in_scattering {
  public:
    in_scattering(const hittable& world, const light_set& lights);
    // For mis_choices::aim_along_rays.
    static std::shared_ptr<const segment_in_scattering> make(const hittable& world,
                                                             const light_set& lights) {
        return std::make_shared<in_scattering>(world, lights);
    }

    // Whether hit `rec`, made along r, is a random point of one of these media where it stands
    // (then that point aims at no light: along() did, for the segment that reached it).
    bool covers(const ray& r, const hit_record& rec) const override;

    // The light scattered once towards r's origin along r, for a segment whose nearest hit
    // (if `found`) is `nearest`: up to a surface it found, or through the media's whole stretch
    // when it found a medium's random point or nothing. Draws 6 numbers if it crosses a medium.
    color along(const ray& r, bool found, const hit_record& nearest, sampler& s) const override;

    // The density along the ray's unit direction with which along() takes the point at
    // distance `at` of the stretch [s_min, s_max]: equiangular about each light's center, each
    // light as likely as the light set's choice of it; uniform for a light without one (sky).
    real distance_pdf(const point3& origin, const vec3& unit_direction, real s_min, real s_max,
                      real at) const;
    // Draws that distance from u_light (which light's density) and u_at (where).
    real sample_distance(const point3& origin, const vec3& unit_direction, real s_min, real s_max,
                         real u_light, real u_at) const;

    const std::vector<const constant_medium*>& media() const { return found; }

  private:
    const hittable& world;
    const light_set& lights;
    std::vector<const constant_medium*> found;
    bool all_media_seen = true;  // no medium hides inside an instance
    std::vector<bool> has_center;
    std::vector<point3> centers;
};

}  // namespace rt
