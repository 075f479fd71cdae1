#include "rt/camera/camera.h"

#include <cmath>

#include "rt/core/exercise.h"
#include "rt/core/validate.h"

namespace rt {

void camera::initialize(const film& f) {
    require(vfov > 0 && vfov < 180, "camera vfov", "be in (0, 180) degrees", vfov);
    place_viewport(f, point3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1), 1);
}

void camera::place_viewport(const film& f, const point3& eye, const vec3& u, const vec3& v,
                            const vec3& w, real distance) {
    // [exercise camera::place_viewport begin]
    center            = eye;
    real vp_height    = 2 * std::tan(degrees_to_radians(vfov) / 2) * distance;
    real vp_width     = vp_height * (real(f.width) / real(f.height));
    vec3 viewport_u   = vp_width * u;    // across the top edge, left to right
    vec3 viewport_v   = -vp_height * v;  // down the left edge
    pixel_du          = viewport_u / real(f.width);
    pixel_dv          = viewport_v / real(f.height);
    point3 upper_left = center - distance * w - viewport_u / 2 - viewport_v / 2;
    pixel00           = upper_left + real(0.5) * (pixel_du + pixel_dv);
    // [exercise camera::place_viewport end]
}

point3 camera::pixel_sample(int i, int j, sampler& s) const {
    sample2 jitter = s.next_2d();
    return pixel00 + (real(i) + jitter.u - real(0.5)) * pixel_du +
           (real(j) + jitter.v - real(0.5)) * pixel_dv;
}

ray camera::get_ray(int i, int j, sampler& s) const {
    return ray(center, pixel_sample(i, j, s) - center);
}

}  // namespace rt
