// What one pixel sample computes: an estimate of the radiance arriving along a camera ray.
// Chapter 01. Each chapter's way of seeing the scene is one of these: the sky alone (chapter
// 01), the normals of the nearest hit (chapter 02), the path tracer (chapter 03 on).
#pragma once

#include <string_view>

#include "rt/core/ray.h"
#include "rt/samplers/sampler.h"

namespace rt {

class radiance_estimator {
  public:
    virtual ~radiance_estimator() = default;

    // Radiance arriving at the camera along r (towards its origin), drawing any random numbers
    // from s; a path follows at most max_depth ray segments. Must be finite and >= 0.
    virtual color radiance(const ray& r, sampler& s, int max_depth) const = 0;

    // A short name of the method ("sky", "normals", "path"), for the record of a run
    // (--stats-out) and so for the tools that compare methods.
    virtual std::string_view name() const = 0;
};

}  // namespace rt
