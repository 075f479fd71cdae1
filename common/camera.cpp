#include "camera.h"

#include <cmath>
#include <sstream>

#include "error.h"
#include "sampling.h"

namespace rt {

namespace {

template <typename T>
void require(bool ok, const char* what, const T& value) {
    if (ok) return;
    std::ostringstream message;
    message << "camera " << what << ", got " << value;
    throw user_error(message.str());
}

}  // namespace

void camera::initialize() {
    require(image_width >= 1, "image width must be at least 1", image_width);
    require(aspect_ratio > 0 && std::isfinite(aspect_ratio), "aspect ratio must be positive",
            aspect_ratio);
    require(vfov > 0 && vfov < 180, "vfov must be in (0, 180) degrees", vfov);
    require(aperture >= 0 && std::isfinite(aperture), "aperture must be >= 0", aperture);
    require(focus_dist >= 0 && std::isfinite(focus_dist), "focus distance must be >= 0",
            focus_dist);
    // Moving objects are bounded (and defined) for times in [0, 1] only.
    require(0 <= shutter_open && shutter_open <= shutter_close && shutter_close <= 1,
            "shutter must satisfy 0 <= open <= close <= 1", shutter_open);

    vec3 view = lookfrom - lookat;
    require(view.length() > 0, "lookfrom must differ from lookat", lookfrom);
    vec3 w    = unit_vector(view);
    vec3 side = cross(vup, w);
    require(side.length() > 1e-6 * vup.length(), "vup must not be parallel to the view direction",
            vup);
    vec3 u = unit_vector(side);
    vec3 v = cross(w, u);

    // In double whatever real is, so 400 / (16/9) is 225 rows in both builds, as in the book.
    height = std::max(1, int(double(image_width) / aspect_ratio));
    center = lookfrom;

    real focus        = focus_dist > 0 ? focus_dist : view.length();
    real vp_height    = 2 * std::tan(degrees_to_radians(vfov) / 2) * focus;
    real vp_width     = vp_height * (real(image_width) / real(height));
    vec3 viewport_u   = vp_width * u;    // across the top edge, left to right
    vec3 viewport_v   = -vp_height * v;  // down the left edge
    pixel_du          = viewport_u / real(image_width);
    pixel_dv          = viewport_v / real(height);
    point3 upper_left = center - focus * w - viewport_u / 2 - viewport_v / 2;
    pixel00           = upper_left + real(0.5) * (pixel_du + pixel_dv);

    real lens_radius = aperture / 2;
    lens_u           = lens_radius * u;
    lens_v           = lens_radius * v;
}

ray camera::get_ray(int i, int j, sampler& s) const {
    sample2 jitter = s.next_2d();
    sample2 lens   = s.next_2d();
    real time_u    = s.next_1d();

    point3 pixel_sample = pixel00 + (real(i) + jitter.u - real(0.5)) * pixel_du +
                          (real(j) + jitter.v - real(0.5)) * pixel_dv;
    vec3 disk     = sample_uniform_disk(lens);
    point3 origin = center + disk.x() * lens_u + disk.y() * lens_v;  // == center for a pinhole
    real time     = shutter_open + time_u * (shutter_close - shutter_open);
    return ray(origin, pixel_sample - origin, time);
}

}  // namespace rt
