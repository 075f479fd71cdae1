// An orthonormal basis built around one unit vector, to turn directions sampled about +z into
// world directions about a surface normal. Chapter 03.
// Branchless construction of Duff et al., "Building an Orthonormal Basis, Revisited" (2017).
#pragma once

#include <cmath>

#include "rt/core/exercise.h"
#include "rt/core/vec3.h"

namespace rt {

class onb {
  public:
    // n must be a unit vector; it becomes the basis' w (local +z) axis.
    explicit onb(const vec3& n) : axis{vec3(), vec3(), n} {
        // [exercise onb::onb begin]
        real sign = std::copysign(real(1), n.z());
        real a    = -1 / (sign + n.z());
        real b    = n.x() * n.y() * a;
        axis[0]   = vec3(1 + sign * n.x() * n.x() * a, sign * b, -sign * n.x());
        axis[1]   = vec3(b, sign + n.y() * n.y() * a, -n.y());
        // [exercise onb::onb end]
    }

    const vec3& u() const { return axis[0]; }
    const vec3& v() const { return axis[1]; }
    const vec3& w() const { return axis[2]; }

    vec3 to_world(const vec3& local) const {
        return local.x() * axis[0] + local.y() * axis[1] + local.z() * axis[2];
    }

  private:
    vec3 axis[3];
};

}  // namespace rt
