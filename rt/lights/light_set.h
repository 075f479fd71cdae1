// The lights of a scene, found in the scene itself: every sphere and quad whose material is a
// diffuse_light, reached through lists and BVHs, and the sky when it is not black. There is no
// second, hand-kept list that could disagree with the geometry. Chapter 14.
// One light is chosen per light sample, each with the same probability 1 / count.
// Not found (so only hit, never aimed at, and then counted with full weight, which keeps every
// estimate unbiased): emitters inside instances, moving spheres that emit, textured emitters'
// dark parts are still sampled.
// Chapter 18 adds lights of many parts (light_part): a mesh's emitting triangles are one light,
// chosen like any other, which picks among its triangles itself (rt/lights/mesh_light.h).
#pragma once

#include <memory>
#include <unordered_map>
#include <vector>

#include "rt/lights/light.h"
#include "rt/scene/background.h"

namespace rt {

// [ch18 begin]
// A shape that is one part of a larger light (a mesh's triangle): the light set makes one light
// for all the parts of a group, and a hit on any part leads to it.
class light_part {
  public:
    virtual bool emits() const = 0;
    // What the parts of one light share.
    virtual const void* light_group() const = 0;
    // The group's light, made once, when its first emitting part is found.
    virtual std::unique_ptr<light> make_group_light() const = 0;

  protected:
    ~light_part() = default;
};
// [ch18 end]

// [ch17 begin]
class quad;
// [ch17 end]

class light_set {
  public:
    light_set(const hittable& world, const background& sky);

    // [ch17 begin]
    // Makes the light of each emitting quad instead of a quad_light (rectangle_light::make draws
    // rectangles by solid angle); nullptr: quad_light.
    using quad_light_maker = std::unique_ptr<light> (*)(const quad&);
    light_set(const hittable& world, const background& sky, quad_light_maker make_quad);
    // [ch17 end]

    bool empty() const { return lights.empty(); }
    std::size_t size() const { return lights.size(); }
    const light& operator[](std::size_t i) const { return *lights[i]; }  // [ch17]

    // Chooses a light with pick (uniform in [0, 1)) and samples it from ref; out.pdf includes
    // the probability of the choice.
    bool sample(const point3& ref, real pick, sample2 u, light_sample& out) const;

    // The density sample() gives unit wi from ref, over every light (for book 3's mixture,
    // which must know how likely any direction was, whichever light it came from).
    real pdf(const point3& ref, const vec3& wi) const;

    // The density of drawing wi from ref by aiming at the light that `hit` lies on (0 when that
    // object is not one of the lights, or is a copy of one placed by an instance), choice
    // included: the light's share of an MIS weight. ref must be the origin of the ray that made
    // `hit` (not the surface point it was spawned from), so the shape, asked again, agrees.
    real pdf_of_hit(const point3& ref, const vec3& wi, const hit_record& hit) const;

    // The same for a ray that escaped to the sky.
    real pdf_of_sky(const point3& ref, const vec3& wi) const;

    // [ch17 begin]
    // The first of the lights made of one sphere or one quad that r meets within ray_t, asked
    // of those shapes alone (whatever else stands in the way): the shape, with its hit in `hit`,
    // or nullptr. Lights of many parts (a mesh's triangles) and the sky are not searched.
    const hittable* first_light_on(const ray& r, interval ray_t, hit_record& hit) const;
    // [ch17 end]

    // Whether `hit`, made along r, is the same point of `shape` as `direct`, the shape's own
    // hit along r: false for a copy of the shape that an instance placed elsewhere.
    static bool same_point(const ray& r, const hit_record& hit, const hit_record& direct);

  private:
    // Finds the lights of world and sky (both constructors).
    void find(const hittable& world, const background& sky);

    quad_light_maker make_quad = nullptr;  // [ch17]
    std::vector<std::unique_ptr<light>> lights;
    std::unordered_map<const hittable*, const light*> light_of_shape;
    std::vector<const hittable*> single_shapes;  // [ch17] of the lights of one sphere or quad
    const light* sky = nullptr;
};

}  // namespace rt
