// Shapes a wide BVH's leaves keep by type: an array of what testing one needs, tested in a loop
// the compiler sees whole, instead of one virtual hit() call per shape. Chapter 17.
// Spheres, moving spheres and quads are built in (wide_bvh.cpp dispatches to them directly). A
// later chapter's shape (a triangle) becomes one by implementing leaf_shapes and handing its
// maker to the wide BVH (wide_bvh.h, fast_traversal.h): the leaves then test it one virtual call
// per run of such shapes, not per shape, and nothing here changes.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "rt/geometry/moving_sphere.h"
#include "rt/geometry/quad.h"
#include "rt/geometry/sphere.h"

namespace rt {

class leaf_shapes {
  public:
    virtual ~leaf_shapes() = default;

    // Takes `object` if it is exactly of this kind (a derived class may hit differently, so it
    // is asked through its own hit()): keeps what testing it needs, and returns its index
    // among this kind's shapes. Nothing when the object is of another kind.
    virtual std::optional<std::uint32_t> add(const hittable& object) = 0;

    // Tests shapes first, first + 1, ..., first + count - 1 in that order, each for hits nearer
    // than the nearest so far (ray_t.max, which each hit narrows), filling rec exactly as the
    // shape's own hit() would. Whether any was hit.
    virtual bool hit(std::uint32_t first, std::uint32_t count, const ray& r, interval& ray_t,
                     hit_record& rec) const = 0;
};

// Makes an empty leaf_shapes of one kind for each wide BVH that is built.
using leaf_shapes_maker = std::function<std::unique_ptr<leaf_shapes>()>;

// What every kind's loop does at a hit, in one place: the shape's own fields of the record.
inline bool record_hit(bool found, const material* mat, const hittable* object, interval& ray_t,
                       hit_record& rec) {
    if (!found) return false;
    rec.mat    = mat;
    rec.object = object;
    ray_t.max  = rec.t;
    return true;
}

// Spheres, tested as sphere::hit() tests them (the same hit_sphere()).
class sphere_leaves final : public leaf_shapes {
  public:
    std::optional<std::uint32_t> add(const hittable& object) override {
        if (typeid(object) != typeid(sphere)) return std::nullopt;
        const auto& s = static_cast<const sphere&>(object);
        fields.push_back({s.center(), s.radius(), s.surface().get(), &s});
        return std::uint32_t(fields.size() - 1);
    }
    bool hit(std::uint32_t first, std::uint32_t count, const ray& r, interval& ray_t,
             hit_record& rec) const override {
        bool hit_anything = false;
        for (std::uint32_t i = first; i < first + count; ++i) {
            const one& s = fields[i];
            hit_anything |= record_hit(hit_sphere(s.center, s.radius, r, ray_t, rec), s.mat,
                                       s.object, ray_t, rec);
        }
        return hit_anything;
    }

  private:
    struct one {
        point3 center;
        real radius;
        const material* mat;
        const hittable* object;
    };
    std::vector<one> fields;
};

// Moving spheres, tested as moving_sphere::hit() tests them.
class moving_sphere_leaves final : public leaf_shapes {
  public:
    std::optional<std::uint32_t> add(const hittable& object) override {
        if (typeid(object) != typeid(moving_sphere)) return std::nullopt;
        const auto& m = static_cast<const moving_sphere&>(object);
        fields.push_back({m.path(), m.radius(), m.surface().get(), &m});
        return std::uint32_t(fields.size() - 1);
    }
    bool hit(std::uint32_t first, std::uint32_t count, const ray& r, interval& ray_t,
             hit_record& rec) const override {
        bool hit_anything = false;
        for (std::uint32_t i = first; i < first + count; ++i) {
            const one& m = fields[i];
            hit_anything |= record_hit(hit_sphere(m.path.at(r.time()), m.radius, r, ray_t, rec),
                                       m.mat, m.object, ray_t, rec);
        }
        return hit_anything;
    }

  private:
    struct one {
        center_path path;
        real radius;
        const material* mat;
        const hittable* object;
    };
    std::vector<one> fields;
};

// Quads, tested as quad::hit() tests them (the same hit_quad()).
class quad_leaves final : public leaf_shapes {
  public:
    std::optional<std::uint32_t> add(const hittable& object) override {
        if (typeid(object) != typeid(quad)) return std::nullopt;
        const auto& q = static_cast<const quad&>(object);
        fields.push_back({q.shape(), q.surface().get(), &q});
        return std::uint32_t(fields.size() - 1);
    }
    bool hit(std::uint32_t first, std::uint32_t count, const ray& r, interval& ray_t,
             hit_record& rec) const override {
        bool hit_anything = false;
        for (std::uint32_t i = first; i < first + count; ++i) {
            const one& q = fields[i];
            hit_anything |=
                record_hit(hit_quad(q.shape, r, ray_t, rec), q.mat, q.object, ray_t, rec);
        }
        return hit_anything;
    }

  private:
    struct one {
        quad_shape shape;
        const material* mat;
        const hittable* object;
    };
    std::vector<one> fields;
};

}  // namespace rt
