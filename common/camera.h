// The camera: where rays start and which way they go. Chapter 01 (pinhole), chapter 06
// (positionable, thin lens), chapter 07 (shutter interval).
// Pixel (i, j), (0, 0) at the top left, looks through pixel00 + (i + dx) du + (j + dy) dv with a
// jitter (dx, dy) uniform in [-0.5, 0.5)^2: a box filter over the pixel, which anti-aliases edges.
#pragma once

#include "ray.h"
#include "sampler.h"

namespace rt {

class camera {
  public:
    double aspect_ratio = 16.0 / 9;          // Ideal width over height; height is rounded down
    int image_width     = 400;               // Rendered image width in pixels
    real vfov           = 90;                // Vertical field of view in degrees
    point3 lookfrom     = point3(0, 0, 0);   // Where the camera is
    point3 lookat       = point3(0, 0, -1);  // The point it looks at
    vec3 vup            = vec3(0, 1, 0);     // Which way is up in the scene
    real aperture       = 0;                 // Lens diameter in scene units; 0 is a pinhole
    real focus_dist     = 0;  // Distance to the sharp plane; 0 means |lookfrom-lookat|
    real shutter_open   = 0;  // Rays get a time uniform in [open, close),
    real shutter_close  = 1;  // within [0, 1], where motion is defined

    // Checks the settings (throws user_error naming the bad value) and derives the viewport.
    void initialize();

    int image_height() const { return height; }

    // A camera ray through pixel (i, j). Draws sampler dimensions 0-4: jitter (2), lens (2),
    // time (1), always all five, so later dimensions stay put whatever the camera settings.
    ray get_ray(int i, int j, sampler& s) const;

  private:
    int height = 0;
    point3 center, pixel00;
    vec3 pixel_du, pixel_dv;  // offsets from one pixel to the next, right and down
    vec3 lens_u, lens_v;      // the lens disk's radius vectors
};

}  // namespace rt
