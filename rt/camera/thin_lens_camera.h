// A camera that stands anywhere and focuses like a thin lens. Chapter 06; chapter 07 adds the
// shutter. It stands at lookfrom, looks at lookat, and vup says which way is up:
//   w = unit(lookfrom - lookat), u = unit(vup x w), v = w x u.
// Rays start at a random point of the lens disk (diameter `aperture`) and pass through the point
// of the focus plane that the pinhole ray would hit, so only that plane is sharp: a point at
// distance d images to a circle of confusion of diameter aperture * |d - focus| / d on it.
#pragma once

#include "rt/camera/camera.h"

namespace rt {

class thin_lens_camera : public camera {
  public:
    point3 lookfrom = point3(0, 0, 0);   // Where the camera is
    point3 lookat   = point3(0, 0, -1);  // The point it looks at
    vec3 vup        = vec3(0, 1, 0);     // Which way is up in the scene
    real aperture   = 0;                 // Lens diameter in scene units; 0 is a pinhole
    real focus_dist = 0;                 // Distance to the sharp plane; 0 means |lookfrom - lookat|
    // [ch07 begin]
    real shutter_open  = 0;  // Rays get an instant uniform in [open, close) within [0, 1],
    real shutter_close = 0;  // where motion is defined; open == close: one instant, no sample
    // [ch07 end]

    void initialize(const film& f) override;

    // Draws 2 sampler dimensions (the jitter), then 2 for the lens if aperture > 0, then 1 for
    // the instant if the shutter is open: a scene pays only for what its camera has.
    ray get_ray(int i, int j, sampler& s) const override;

  private:
    vec3 lens_u, lens_v;  // the lens disk's radius vectors
};

}  // namespace rt
