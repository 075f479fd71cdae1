#include "book1_rays.h"

#include <cmath>

#include "ch06_defocus/random_spheres.h"
#include "rt/core/onb.h"
#include "rt/samplers/independent_sampler.h"
#include "rt/samplers/sampling.h"
#include "single_precision.h"

namespace rt_bench {

std::vector<rt::bounded_object> book1_objects() {
    std::vector<rt::bounded_object> objects;
    for (auto& s : random_spheres()) objects.emplace_back(s);
    return objects;
}

rt::film book1_film() {
    return rt::film::for_aspect(400, 16.0 / 9);
}

std::shared_ptr<rt::thin_lens_camera> book1_camera(const rt::film& f) {
    // As ch06_defocus's final_scene(): the book's defocus angle of 0.6 degrees at focus
    // distance 10 is a lens of diameter 2 * 10 * tan(0.3 degrees).
    auto cam        = std::make_shared<rt::thin_lens_camera>();
    cam->vfov       = 20;
    cam->lookfrom   = rt::point3(13, 2, 3);
    cam->lookat     = rt::point3(0, 0, 0);
    cam->focus_dist = 10;
    cam->aperture   = 2 * cam->focus_dist * std::tan(rt::degrees_to_radians(0.3));
    cam->initialize(f);
    return cam;
}

std::vector<rt::ray> camera_rays(const rt::camera& cam, const rt::film& f, int samples_per_pixel,
                                 std::uint64_t seed) {
    std::vector<rt::ray> rays;
    rays.reserve(std::size_t(f.width) * std::size_t(f.height) * std::size_t(samples_per_pixel));
    rt::independent_sampler s(seed);
    for (int j = 0; j < f.height; ++j) {
        for (int i = 0; i < f.width; ++i) {
            for (int k = 0; k < samples_per_pixel; ++k) {
                s.start_pixel_sample(i, j, k);
                rays.push_back(cam.get_ray(i, j, s));
            }
        }
    }
    return rays;
}

std::vector<rt::ray> diffuse_bounce_rays(const rt::hittable& world, const std::vector<rt::ray>& in,
                                         std::uint64_t seed) {
    std::vector<rt::ray> rays;
    rays.reserve(in.size());
    rt::pcg32 rng(/*sequence=*/11, seed);
    for (const rt::ray& r : in) {
        rt::hit_record rec;
        if (!world.hit(r, rt::interval(0, rt::infinity), rec)) continue;
        rt::real u = rng.uniform(), v = rng.uniform();
        rt::vec3 direction = rt::onb(rec.normal).to_world(rt::sample_cosine_hemisphere({u, v}));
        rays.push_back(spawn_float_ray(rec, direction));
    }
    return rays;
}

}  // namespace rt_bench
