// Tests for instance.h as chapter 12's media need it: a medium draws its random number by hashing
// the ray it is handed (constant_medium.h), so what matters is which ray an instance hands its
// object. It must keep the world ray's time, be exactly the world ray in the object's frame, be
// the same ray every time (or renders would not be deterministic), and differ between
// placements (or one medium placed twice would make one choice for both).
#include <catch2/catch.hpp>
#include <cstdint>
#include <iterator>
#include <memory>
#include <vector>

#include "ch03/material_helpers.h"
#include "rt/core/rng.h"
#include "rt/geometry/box.h"
#include "rt/geometry/instance.h"
#include "rt/media/constant_medium.h"
#include "test_helpers.h"

namespace {

using rt::axis, rt::point3, rt::real, rt::vec3;

const rt::interval forward(0, rt::infinity);

using rt_test::any_material, rt_test::exactly, rt_test::uniform;

// Records the rays it is asked about, and hits nothing.
class ray_recorder : public rt::bounded_hittable {
  public:
    bool hit(const rt::ray& r, rt::interval, rt::hit_record&) const override {
        rays.push_back(r);
        return false;
    }
    rt::aabb bounding_box() const override { return rt::aabb(point3(-1, -1, -1), point3(1, 1, 1)); }
    mutable std::vector<rt::ray> rays;
};

bool same_ray(const rt::ray& a, const rt::ray& b) {
    return exactly(a.origin(), b.origin()) && exactly(a.direction(), b.direction()) &&
           a.time() == b.time();
}

}  // namespace

TEST_CASE(
    "instance: the ray passed in keeps its time, is the world ray in the object's frame, "
    "and is its own for each placement",
    "[ch12]") {
    auto recorder = std::make_shared<ray_recorder>();
    auto turned_x = std::make_shared<rt::rotate>(recorder, axis::x, 30);
    auto turned_y = std::make_shared<rt::rotate>(recorder, axis::y, 30);
    auto back_y   = std::make_shared<rt::rotate>(recorder, axis::y, -30);
    const std::shared_ptr<rt::hittable> placements[] = {
        std::make_shared<rt::translate>(recorder, vec3(0, 0, 2)),
        std::make_shared<rt::translate>(recorder, vec3(0, 0, 4)),
        std::make_shared<rt::translate>(recorder, vec3(0, 0, 0)),
        turned_x,
        turned_y,
        back_y,
        std::make_shared<rt::translate>(std::make_shared<rt::translate>(recorder, vec3(0, 0, 2)),
                                        vec3(0, 0, 3)),
    };
    const std::size_t count = std::size(placements);
    // A medium's number for each ray: equal rays would make equal choices.
    auto medium = std::make_shared<rt::constant_medium>(
        rt::box(point3(-1, -1, -1), point3(1, 1, 1), any_material()), real(0.7),
        rt::color(1, 1, 1));
    rt::pcg32 rng(26, 0);
    int not_kept = 0, not_frame = 0, repeated = 0, unstable = 0;
    for (int k = 0; k < 1000; ++k) {
        const real x = uniform(rng, -1, 1), y = uniform(rng, -1, 1);
        const rt::ray r(point3(x, y, -3), vec3(0.125, 0, 1), uniform(rng, 0, 1));
        rt::hit_record rec;
        recorder->rays.clear();
        for (const auto& p : placements) p->hit(r, forward, rec);
        for (const auto& p : placements) p->hit(r, forward, rec);  // again: the same rays
        REQUIRE(recorder->rays.size() == 2 * count);
        const std::vector<rt::ray>& seen = recorder->rays;
        // The object's frame: the origin moved back by the offset; origin and direction turned
        // back by the rotation (each placement's own to_object).
        const rt::ray expected[] = {
            r.continued(r.origin() - vec3(0, 0, 2), r.direction()),
            r.continued(r.origin() - vec3(0, 0, 4), r.direction()),
            r.continued(r.origin() - vec3(0, 0, 0), r.direction()),
            r.continued(turned_x->to_object(r.origin()), turned_x->to_object(r.direction())),
            r.continued(turned_y->to_object(r.origin()), turned_y->to_object(r.direction())),
            r.continued(back_y->to_object(r.origin()), back_y->to_object(r.direction())),
            r.continued(r.origin() - vec3(0, 0, 3) - vec3(0, 0, 2), r.direction()),
        };
        for (std::size_t i = 0; i < count; ++i) {
            not_kept += seen[i].time() != r.time();
            not_frame += !same_ray(seen[i], expected[i]);
            unstable += !same_ray(seen[i], seen[i + count]);
            const real u = medium->random_for(seen[i]);
            for (std::size_t j = 0; j < i; ++j) {
                repeated += same_ray(seen[i], seen[j]);
                repeated += u == medium->random_for(seen[j]);
            }
        }
    }
    CHECK(not_kept == 0);
    CHECK(not_frame == 0);
    CHECK(unstable == 0);
    CHECK(repeated == 0);
}
