// A list of hittables that reports the nearest hit among them. Chapter 02.
#pragma once

#include <memory>
#include <vector>

#include "rt/geometry/hittable.h"

namespace rt {

class hittable_list : public hittable {
  public:
    std::vector<std::shared_ptr<hittable>> objects;

    hittable_list() = default;

    void add(std::shared_ptr<hittable> object) { objects.push_back(std::move(object)); }

    // Each object is asked only for hits nearer than the nearest found so far.
    bool hit(const ray& r, interval ray_t, hit_record& rec) const override;

    // [ch14 begin]
    real transmittance(const ray& r, interval ray_t) const override;
    void visit_parts(part_visitor& visitor) const override {
        for (const auto& object : objects) visitor.visit(*object);
    }
    // [ch14 end]
};

}  // namespace rt
