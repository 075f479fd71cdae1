// The path tracer: the one place that turns a camera ray into radiance. Chapter 03.
// It evaluates the rendering equation one path at a time,
//   L(x, wo) = Le(x, wo) + attenuation * L(x', wi),
// following at most max_depth ray segments; a path that runs out of depth brings back nothing.
#pragma once

#include "ray.h"
#include "sampler.h"
#include "scene.h"

namespace rt {

color trace_path(const scene& sc, ray r, sampler& s, int max_depth);

}  // namespace rt
