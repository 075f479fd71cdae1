// A test double for the medium tests of chapter 12: it wraps an object, records every ray that
// asks it for a hit, and answers as the object would. Included as "ch12/ray_recorder.h".
#pragma once

#include <memory>
#include <vector>

#include "rt/accel/bounded.h"

namespace rt_test {

class ray_recorder : public rt::bounded_hittable {
  public:
    explicit ray_recorder(const rt::bounded_object& o) : object(o.object), box(o.box) {}
    bool hit(const rt::ray& r, rt::interval ray_t, rt::hit_record& rec) const override {
        rays.push_back(r);
        return object->hit(r, ray_t, rec);
    }
    rt::aabb bounding_box() const override { return box; }
    mutable std::vector<rt::ray> rays;

  private:
    std::shared_ptr<rt::hittable> object;
    rt::aabb box;
};

}  // namespace rt_test
