// A texture: a color that varies over a surface, looked up by the hit's surface coordinates
// (u, v) and/or its position p. Chapter 08.
#pragma once

#include <cmath>
#include <memory>

#include "rt/core/exercise.h"
#include "rt/core/vec3.h"
#include "rt/geometry/hittable.h"

namespace rt {

class texture {
  public:
    virtual ~texture() = default;

    // The linear RGB value at surface coordinates (u, v) of the point p: a reflectance in [0, 1]
    // when it is an albedo, a radiance (any value >= 0) when a light emits it.
    virtual color value(real u, real v, const point3& p) const = 0;

    // Whether value() reads (u, v). Every texture must say (there is no default), so a new one
    // cannot forget and silently get (0, 0): a hit's (u, v) are computed only when asked for.
    virtual bool uses_uv() const = 0;

    // The value at a hit, computing the hit's (u, v) only if this texture reads them.
    color value_at(const hit_record& rec) const {
        if (!uses_uv()) return value(0, 0, rec.p);
        surface_uv uv = rec.uv();
        return value(uv.u, uv.v, rec.p);
    }
};

// The same color everywhere.
class solid_color : public texture {
  public:
    explicit solid_color(const color& c) : albedo(c) {}
    color value(real, real, const point3&) const override { return albedo; }
    bool uses_uv() const override { return false; }

    const color& color_value() const { return albedo; }  // [ch19]

  private:
    color albedo;
};

// A 3D checkerboard of cubes of side `scale` filling space (a solid texture: it needs no
// surface coordinates). The floor rule of book 2:
//   n = floor(x / scale) + floor(y / scale) + floor(z / scale),  even n -> even, odd n -> odd.
// Cells are half-open, [k scale, (k + 1) scale), so a point on a cell face belongs to the cell
// on its positive side: a floor lying in the plane y = 0 still shows the pattern.
class checker_texture : public texture {
  public:
    checker_texture(real scale, std::shared_ptr<texture> even, std::shared_ptr<texture> odd);
    checker_texture(real scale, const color& even_color, const color& odd_color)
        : checker_texture(scale, std::make_shared<solid_color>(even_color),
                          std::make_shared<solid_color>(odd_color)) {}

    color value(real u, real v, const point3& p) const override {
        // Divide, not multiply by 1 / scale: 1 / 3 is rounded, and x * (1 / 3) can round the
        // largest float below a boundary 3k up to k, into the wrong cell.
        // [exercise checker_texture::value begin]
        auto cell   = [this](real x) { return static_cast<long long>(std::floor(x / cell_size)); };
        long long n = cell(p.x()) + cell(p.y()) + cell(p.z());
        return (n % 2 == 0 ? even : odd)->value(u, v, p);
        // [exercise checker_texture::value end]
    }
    bool uses_uv() const override { return even->uses_uv() || odd->uses_uv(); }

    // [ch19 begin]
    // What it was made with, for a scene file (rt/scene_files).
    real scale() const { return cell_size; }
    const std::shared_ptr<texture>& even_texture() const { return even; }
    const std::shared_ptr<texture>& odd_texture() const { return odd; }
    // [ch19 end]

  private:
    real cell_size;
    std::shared_ptr<texture> even, odd;
};

// The sign rule of book 1 (v3) and of many student ray tracers, kept to compare with the floor
// rule: cubes of side `scale` colored by the sign of
//   s = sin(pi x / scale) sin(pi y / scale) sin(pi z / scale),  s >= 0 -> even, s < 0 -> odd.
// (scale = pi / 10 gives the book's sin(10 x) sin(10 y) sin(10 z).) Inside the cell
// [k scale, (k + 1) scale) the sine has the sign (-1)^k, so away from the cell faces both rules
// give the same pattern. On a face a sine is 0 (or, for k != 0, a rounding error of either
// sign): a surface lying in a face plane, such as a floor at y = 0, shows one color instead of
// the pattern. It also costs three sines per lookup where the floor rule needs three floors.
class sine_checker_texture : public texture {
  public:
    sine_checker_texture(real scale, std::shared_ptr<texture> even, std::shared_ptr<texture> odd);
    sine_checker_texture(real scale, const color& even_color, const color& odd_color)
        : sine_checker_texture(scale, std::make_shared<solid_color>(even_color),
                               std::make_shared<solid_color>(odd_color)) {}

    color value(real u, real v, const point3& p) const override {
        real sines =
            std::sin(frequency * p.x()) * std::sin(frequency * p.y()) * std::sin(frequency * p.z());
        return (sines < 0 ? odd : even)->value(u, v, p);
    }
    bool uses_uv() const override { return even->uses_uv() || odd->uses_uv(); }

    // [ch19 begin]
    // What it was made with, for a scene file (rt/scene_files).
    real scale() const { return given_scale; }
    const std::shared_ptr<texture>& even_texture() const { return even; }
    const std::shared_ptr<texture>& odd_texture() const { return odd; }
    // [ch19 end]

  private:
    real frequency;        // pi / scale: a half period of each sine is one cell
    real given_scale = 0;  // [ch19] as given: pi / frequency need not give it back
    std::shared_ptr<texture> even, odd;
};

}  // namespace rt
