// An emitting quad whose edges are perpendicular, sampled by solid angle (spherical_rectangle)
// where that pays: every direction towards it equally likely, so a point close beside the lamp
// (a ceiling around it), to which drawing by area hands directions of very uneven density
// (d^2 / |cos| grows without bound towards the lamp's far edge), gets as little noise from it as
// a point far below. From afar the area's density hardly varies across the lamp and the solid
// angle's trigonometry costs more than it saves: points farther from the lamp's plane than
// near_share of its longer edge draw by area, as quad_light does (measured on the Cornell box
// and the smoke: 0.5 gave the least error per second of 0.1, 0.25, 0.5, 1, 3 and everywhere;
// report/speed_against_error.md), and so do points that see it too small for the solid angle's
// digits. Both choices depend only on the lit point, so sample() and pdf_at() always agree.
// `--quad-lights solid-angle` of chapter 17's program makes every rectangular lamp one of
// these (light_set's quad_light_maker). Chapter 17.
#pragma once

#include <memory>

#include "rt/lights/quad_light.h"

namespace rt {

class rectangle_light : public quad_light {
  public:
    // shape must outlive this light and be a rectangle (is_rectangle).
    explicit rectangle_light(const quad& shape);

    // Whether the quad's edges are perpendicular, to the last bits of their lengths.
    static bool is_rectangle(const quad& q);
    // A rectangle_light for a rectangle, a quad_light for any other quad.
    static std::unique_ptr<light> make(const quad& q);

    bool sample(const point3& ref, sample2 u, light_sample& out) const override;
    real pdf_at(const point3& ref, const vec3& wi, const hit_record& hit) const override;

    // Nearer to the lamp's plane than this share of its longer edge, by solid angle.
    static constexpr real near_share = 0.5;
    // Whether ref is that near.
    bool near(const point3& ref) const;

  private:
    vec3 unit_normal;
    real longer_edge;
};

}  // namespace rt
