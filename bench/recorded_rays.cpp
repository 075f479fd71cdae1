#include "recorded_rays.h"

#include <cmath>
#include <limits>

#include "rt/integrators/path_tracer.h"
#include "rt/media/isotropic.h"
#include "single_precision.h"

namespace rt_bench {

namespace {

bool same(const rt::vec3& a, const rt::vec3& b) {
    return a.x() == b.x() && a.y() == b.y() && a.z() == b.z();
}

// Stands between the path tracer and the world: answers as the world does, and writes down
// each ray.
class ray_recorder : public rt::hittable {
  public:
    explicit ray_recorder(std::shared_ptr<rt::hittable> w) : world(std::move(w)) {}

    bool hit(const rt::ray& r, rt::interval ray_t, rt::hit_record& rec) const override {
        bool found = world->hit(r, ray_t, rec);
        rays.push_back(float_origin(r));
        last       = rec;
        last_found = found;
        return found;
    }

    mutable std::vector<rt::ray> rays;
    mutable std::size_t respawned = 0;

  private:
    // A ray spawned from the previous hit starts at p +- p_error * normal (hittable.h); it gets
    // the float offset on the same side. Any other ray (a camera ray) keeps its origin.
    rt::ray float_origin(const rt::ray& r) const {
        if (last_found) {
            const rt::vec3 offset = last.p_error * last.normal;
            const rt::real sign   = same(r.origin(), last.p + offset)   ? 1
                                    : same(r.origin(), last.p - offset) ? -1
                                                                        : 0;
            if (sign != 0) {
                ++respawned;
                rt::point3 origin = last.p + sign * float_spawn_offset(last.p_error) * last.normal;
                return to_float(rt::ray(origin, r.direction()));
            }
        }
        return to_float(r);
    }

    std::shared_ptr<rt::hittable> world;
    mutable rt::hit_record last;
    mutable bool last_found = false;
};

}  // namespace

recorded_rays record_rays(const rt::scene& sc, int samples_per_pixel, std::size_t max_rays) {
    auto recorder                = std::make_shared<ray_recorder>(sc.world);
    rt::render_settings settings = sc.settings;
    settings.samples_per_pixel   = samples_per_pixel;
    settings.threads             = 1;  // the recorder is not thread-safe, and the order is fixed
    rt::film f                   = rt::film::for_aspect(settings.width, sc.cam->aspect_ratio);
    sc.cam->initialize(f);
    rt::render(f, *sc.cam, rt::path_tracer(recorder, sc.sky), settings);

    recorded_rays out;
    out.recorded  = recorder->rays.size();
    out.respawned = recorder->respawned;
    if (recorder->rays.size() <= max_rays) {
        out.rays = std::move(recorder->rays);
    } else {
        // Every k-th ray in render order, k fractional: the kept rays cover the whole image.
        const double step = double(recorder->rays.size()) / double(max_rays);
        for (std::size_t i = 0; i < max_rays; ++i)
            out.rays.push_back(recorder->rays[std::size_t(double(i) * step)]);
    }

    // The real scene's answer for each kept ray (as moved and rounded): a copy of its shapes
    // must find the same surface hits.
    constexpr rt::real nan = std::numeric_limits<rt::real>::quiet_NaN();
    for (const rt::ray& r : out.rays) {
        rt::hit_record rec;
        bool on_surface = sc.world->hit(r, rt::interval(0, rt::infinity), rec) &&
                          dynamic_cast<const rt::isotropic*>(rec.mat) == nullptr;
        out.surface_hits.push_back(
            on_surface ? recorded_rays::surface_hit{rec.p, float_spawn_offset(rec.p_error)}
                       : recorded_rays::surface_hit{rt::point3(nan, nan, nan), 0});
    }
    return out;
}

}  // namespace rt_bench
