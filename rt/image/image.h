// A linear-light RGB framebuffer of 32-bit floats, row 0 at the top. Chapter 01.
#pragma once

#include <cstddef>
#include <vector>

#include "rt/core/vec3.h"

namespace rt {

class image {
  public:
    image() = default;
    image(int width, int height)
        : w(width), h(height), pixels(std::size_t(width) * std::size_t(height) * 3, 0.0f) {}

    int width() const { return w; }
    int height() const { return h; }

    color get(int x, int y) const {
        const float* p = &pixels[index(x, y)];
        return color(p[0], p[1], p[2]);
    }
    void set(int x, int y, const color& c) {
        float* p = &pixels[index(x, y)];
        p[0]     = float(c.x());
        p[1]     = float(c.y());
        p[2]     = float(c.z());
    }

    // Interleaved RGB, row by row from the top.
    const std::vector<float>& data() const { return pixels; }

  private:
    std::size_t index(int x, int y) const { return (std::size_t(y) * std::size_t(w) + x) * 3; }

    int w = 0, h = 0;
    std::vector<float> pixels;
};

}  // namespace rt
