#include "hittable_list.h"

namespace rt {

bool hittable_list::hit(const ray& r, interval ray_t, hit_record& rec) const {
    bool hit_anything = false;
    for (const auto& object : objects) {
        if (object->hit(r, ray_t, rec)) {
            hit_anything = true;
            ray_t.max    = rec.t;
        }
    }
    return hit_anything;
}

}  // namespace rt
