// Tests for hittable_list.h: the nearest hit among several objects (chapter 02) and the box
// around them all (chapter 07), which the BVH builder and nested lists rely on.
#include <catch2/catch.hpp>
#include <memory>

#include "common/hittable_list.h"
#include "common/normal_shading.h"
#include "common/quad.h"
#include "common/sphere.h"

namespace {

using rt::point3, rt::real, rt::vec3;

std::shared_ptr<rt::material> own_material() {
    return std::make_shared<rt::normal_shading>();
}

}  // namespace

TEST_CASE("hittable_list: the nearest of several hits wins, whatever the order", "[ch02]") {
    auto near_sphere = std::make_shared<rt::sphere>(point3(0, 0, -3), 1, own_material());
    auto far_sphere  = std::make_shared<rt::sphere>(point3(0, 0, -10), 2, own_material());
    const rt::ray r(point3(0, 0, 0), vec3(0, 0, -1));
    for (bool near_first : {true, false}) {
        rt::hittable_list list;
        list.add(near_first ? near_sphere : far_sphere);
        list.add(near_first ? far_sphere : near_sphere);
        rt::hit_record rec;
        REQUIRE(list.hit(r, rt::interval(0, rt::infinity), rec));
        CHECK(rec.t == 2);
        // Beyond the near sphere (t in (4.5, inf)), the far one is what is left.
        REQUIRE(list.hit(r, rt::interval(4.5, rt::infinity), rec));
        CHECK(rec.t == 8);
    }
    rt::hittable_list empty;
    rt::hit_record rec;
    CHECK_FALSE(empty.hit(r, rt::interval::universe(), rec));
}

TEST_CASE("hittable_list: the bounding box is the union of the objects' boxes", "[ch07]") {
    rt::hittable_list list;
    CHECK(list.bounding_box().empty());  // nothing to bound

    list.add(std::make_shared<rt::sphere>(point3(1, 2, 3), 0.5, own_material()));
    rt::aabb box = list.bounding_box();
    CHECK(box.x.min == 0.5);
    CHECK(box.x.max == 1.5);
    CHECK(box.z.max == 3.5);

    // A moving sphere (both ends count), a quad in y = -4 (padded), and an empty list, which
    // adds nothing.
    list.add(std::make_shared<rt::sphere>(point3(-2, 0, 0), point3(-2, 0, 6), 1, own_material()));
    list.add(
        std::make_shared<rt::quad>(point3(0, -4, 0), vec3(5, 0, 0), vec3(0, 0, 2), own_material()));
    list.add(std::make_shared<rt::hittable_list>());
    box = list.bounding_box();
    CHECK(box.x.min == -3);
    CHECK(box.x.max == 5);
    CHECK(box.y.min < -4);  // the quad's padding, a fraction of 1e-4
    CHECK(box.y.min > -4 - real(1e-4));
    CHECK(box.y.max == 2.5);
    CHECK(box.z.min == -1);
    CHECK(box.z.max == 7);

    // A list inside a list gives the same box.
    rt::hittable_list outer;
    outer.add(std::make_shared<rt::hittable_list>(list));
    const rt::aabb nested = outer.bounding_box();
    for (int axis = 0; axis < 3; ++axis) {
        CHECK(nested.axis_interval(axis).min == box.axis_interval(axis).min);
        CHECK(nested.axis_interval(axis).max == box.axis_interval(axis).max);
    }
}
