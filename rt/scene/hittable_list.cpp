#include "rt/scene/hittable_list.h"

#include "rt/core/exercise.h"

namespace rt {

bool hittable_list::hit(const ray& r, interval ray_t, hit_record& rec) const {
    // [exercise hittable_list::hit begin]
    bool hit_anything = false;
    for (const auto& object : objects) {
        if (object->hit(r, ray_t, rec)) {
            hit_anything = true;
            ray_t.max    = rec.t;
        }
    }
    return hit_anything;
    // [exercise hittable_list::hit end]
}

// [ch14 begin]
real hittable_list::transmittance(const ray& r, interval ray_t) const {
    real fraction = 1;
    for (const auto& object : objects) {
        fraction *= object->transmittance(r, ray_t);
        if (fraction == 0) break;
    }
    return fraction;
}
// [ch14 end]

}  // namespace rt
