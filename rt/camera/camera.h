// The camera: where rays start and which way they go. Chapter 01: a pinhole at the origin
// looking down -z (chapter 06's thin_lens_camera can stand anywhere and has a lens).
// Pixel (i, j), (0, 0) at the top left, looks through pixel00 + (i + dx) du + (j + dy) dv with a
// jitter (dx, dy) uniform in [-0.5, 0.5)^2: a box filter over the pixel, which anti-aliases edges.
// The viewport, `distance` in front of the eye, is 2 tan(vfov / 2) * distance high.
#pragma once

#include "rt/core/ray.h"
#include "rt/render/film.h"
#include "rt/samplers/sampler.h"

namespace rt {

class camera {
  public:
    double aspect_ratio = 16.0 / 9;  // Ideal width over height; the film's height follows
    real vfov           = 90;        // Vertical field of view in degrees

    virtual ~camera() = default;

    // Checks the settings (throws user_error naming a bad one) and lays the pixel grid over f.
    virtual void initialize(const film& f);

    // A camera ray through pixel (i, j). Draws 2 sampler dimensions: the jitter.
    virtual ray get_ray(int i, int j, sampler& s) const;

  protected:
    // Lays the pixel grid for an eye at `eye` with the orthonormal frame u (right), v (up),
    // w (backwards: the camera looks down -w), the viewport `distance` in front of it.
    void place_viewport(const film& f, const point3& eye, const vec3& u, const vec3& v,
                        const vec3& w, real distance);

    // A jittered point of pixel (i, j) on the viewport. Draws 2 sampler dimensions.
    point3 pixel_sample(int i, int j, sampler& s) const;

    point3 center;  // the eye

  private:
    point3 pixel00;
    vec3 pixel_du, pixel_dv;  // offsets from one pixel to the next, right and down
};

}  // namespace rt
