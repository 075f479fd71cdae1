#include "lambertian.h"

#include <sstream>

#include "error.h"
#include "onb.h"
#include "sampling.h"

namespace rt {

lambertian::lambertian(const color& a) : albedo(a) {
    for (int i = 0; i < 3; ++i) {
        if (!(a[i] >= 0 && a[i] <= 1)) {
            std::ostringstream message;
            message << "lambertian albedo must be in [0, 1] per channel, got " << a;
            throw user_error(message.str());
        }
    }
}

bool lambertian::scatter(const ray& r_in, const hit_record& rec, sampler& s, color& attenuation,
                         ray& scattered) const {
    // The book's normal + random_unit_vector() has this same cosine density; sampling it in a
    // local frame needs no rejection loop and no degenerate-direction fix-up.
    vec3 direction = onb(rec.normal).to_world(sample_cosine_hemisphere(s.next_2d()));
    scattered      = rec.spawn_ray(direction, r_in.time());
    attenuation    = albedo;
    return true;
}

}  // namespace rt
