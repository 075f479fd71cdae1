#include "integrator.h"

#include "material.h"

namespace rt {

color trace_path(const scene& sc, ray r, sampler& s, int max_depth) {
    color radiance(0, 0, 0);
    color throughput(1, 1, 1);  // product of the attenuations along the path so far
    for (int segment = 0; segment < max_depth; ++segment) {
        hit_record rec;
        r.set_random_key(s.next_key());
        // Spawned rays start off their surface (hit_record::spawn_ray), so any t > 0 is a real hit.
        if (!sc.world.hit(r, interval(0, infinity), rec)) {
            radiance += throughput * sc.sky.radiance(r.direction());
            break;
        }
        radiance += throughput * rec.mat->emitted(r, rec);
        color attenuation;
        ray scattered;
        if (!rec.mat->scatter(r, rec, s, attenuation, scattered)) break;
        throughput = throughput * attenuation;
        r          = scattered;
    }
    return radiance;
}

}  // namespace rt
