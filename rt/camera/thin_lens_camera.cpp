#include "rt/camera/thin_lens_camera.h"

#include <sstream>

#include "rt/core/exercise.h"
#include "rt/core/validate.h"
#include "rt/samplers/sampling.h"

namespace rt {

void thin_lens_camera::initialize(const film& f) {
    require(vfov > 0 && vfov < 180, "camera vfov", "be in (0, 180) degrees", vfov);
    require_non_negative(aperture, "camera aperture");
    require_non_negative(focus_dist, "camera focus distance");
    // [ch07 begin]
    // Moving objects are bounded (and defined) for times in [0, 1] only.
    if (!(0 <= shutter_open && shutter_open <= shutter_close && shutter_close <= 1)) {
        std::ostringstream shutter;
        shutter << "open " << shutter_open << ", close " << shutter_close;
        require(false, "camera shutter", "satisfy 0 <= open <= close <= 1", shutter.str());
    }
    // [ch07 end]

    // [exercise thin_lens_camera::initialize begin]
    vec3 view = lookfrom - lookat;
    require(view.length() > 0, "camera lookfrom", "differ from lookat", lookfrom);
    vec3 w    = unit_vector(view);
    vec3 side = cross(vup, w);
    require(side.length() > 1e-6 * vup.length(), "camera vup",
            "not be parallel to the view direction", vup);
    vec3 u = unit_vector(side);
    vec3 v = cross(w, u);

    place_viewport(f, lookfrom, u, v, w, focus_dist > 0 ? focus_dist : view.length());
    real lens_radius = aperture / 2;
    lens_u           = lens_radius * u;
    lens_v           = lens_radius * v;
    // [exercise thin_lens_camera::initialize end]
}

ray thin_lens_camera::get_ray(int i, int j, sampler& s) const {
    point3 target = pixel_sample(i, j, s);
    point3 origin = center;
    if (aperture > 0) {
        // [exercise thin_lens_camera::get_ray begin]
        vec3 disk = sample_uniform_disk(s.next_2d());
        origin    = center + disk.x() * lens_u + disk.y() * lens_v;
        // [exercise thin_lens_camera::get_ray end]
    }
    // [ch07 begin]
    if (shutter_close > shutter_open) {
        real instant = shutter_open + s.next_1d() * (shutter_close - shutter_open);
        return ray(origin, target - origin, instant);
    }
    // A shutter open for one instant (open == close) draws nothing, but its rays are at it.
    if (shutter_open > 0) return ray(origin, target - origin, shutter_open);
    // [ch07 end]
    return ray(origin, target - origin);
}

}  // namespace rt
