// A 3-vector of `real`s: points, directions and linear RGB colors. Chapter 01.
// Key formulas: dot(a,b) = |a||b|cos(theta); |cross(a,b)| = |a||b|sin(theta).
#pragma once

#include <cmath>
#include <ostream>
#include <type_traits>

#include "rt/core/scalar.h"

namespace rt {

class vec3 {
  public:
    real e[3];

    constexpr vec3() : e{0, 0, 0} {}
    // From any three numbers: scenes are written with double literals and ints (0.1 is a
    // double), and the float build rounds them to real here, once and on purpose.
    template <typename X, typename Y, typename Z>
    requires std::is_arithmetic_v<X> && std::is_arithmetic_v<Y> && std::is_arithmetic_v<Z>
    constexpr vec3(X x, Y y, Z z)
        : e{static_cast<real>(x), static_cast<real>(y), static_cast<real>(z)} {}

    constexpr real x() const { return e[0]; }
    constexpr real y() const { return e[1]; }
    constexpr real z() const { return e[2]; }

    constexpr vec3 operator-() const { return vec3(-e[0], -e[1], -e[2]); }
    constexpr real operator[](int i) const { return e[i]; }
    constexpr real& operator[](int i) { return e[i]; }

    constexpr vec3& operator+=(const vec3& v) {
        e[0] += v.e[0];
        e[1] += v.e[1];
        e[2] += v.e[2];
        return *this;
    }
    constexpr vec3& operator*=(real t) {
        e[0] *= t;
        e[1] *= t;
        e[2] *= t;
        return *this;
    }
    constexpr vec3& operator/=(real t) { return *this *= 1 / t; }

    constexpr real length_squared() const { return e[0] * e[0] + e[1] * e[1] + e[2] * e[2]; }
    real length() const { return std::sqrt(length_squared()); }

    // True when every component is within s of zero: such a direction is degenerate.
    bool near_zero(real s = real(1e-8)) const {
        return std::fabs(e[0]) < s && std::fabs(e[1]) < s && std::fabs(e[2]) < s;
    }
};

using point3 = vec3;  // a position in space
using color  = vec3;  // linear RGB radiance or reflectance

inline std::ostream& operator<<(std::ostream& out, const vec3& v) {
    return out << '(' << v.e[0] << ", " << v.e[1] << ", " << v.e[2] << ')';
}

constexpr vec3 operator+(const vec3& u, const vec3& v) {
    return vec3(u.e[0] + v.e[0], u.e[1] + v.e[1], u.e[2] + v.e[2]);
}
constexpr vec3 operator-(const vec3& u, const vec3& v) {
    return vec3(u.e[0] - v.e[0], u.e[1] - v.e[1], u.e[2] - v.e[2]);
}
// Component-wise product: how a reflectance filters a color.
constexpr vec3 operator*(const vec3& u, const vec3& v) {
    return vec3(u.e[0] * v.e[0], u.e[1] * v.e[1], u.e[2] * v.e[2]);
}
constexpr vec3 operator*(real t, const vec3& v) {
    return vec3(t * v.e[0], t * v.e[1], t * v.e[2]);
}
constexpr vec3 operator*(const vec3& v, real t) {
    return t * v;
}
constexpr vec3 operator/(const vec3& v, real t) {
    return (1 / t) * v;
}

constexpr real dot(const vec3& u, const vec3& v) {
    return u.e[0] * v.e[0] + u.e[1] * v.e[1] + u.e[2] * v.e[2];
}
constexpr vec3 cross(const vec3& u, const vec3& v) {
    return vec3(u.e[1] * v.e[2] - u.e[2] * v.e[1], u.e[2] * v.e[0] - u.e[0] * v.e[2],
                u.e[0] * v.e[1] - u.e[1] * v.e[0]);
}
inline vec3 unit_vector(const vec3& v) {
    return v / v.length();
}

// The largest absolute component: the scale that floating-point error in a point grows with.
// The value of std::fmax(|x|, std::fmax(|y|, |z|)) for every v, NaN and infinity included, but
// by comparisons: fmax is a library call the compiler cannot inline (it must ignore a NaN), and
// quads and instances ask this at every hit.
inline real max_abs_component(const vec3& v) {
    // fmax of two numbers that are not negative: the larger one, or the one that is not NaN.
    auto larger = [](real a, real b) { return a > b || std::isnan(b) ? a : b; };
    return larger(std::fabs(v.e[0]), larger(std::fabs(v.e[1]), std::fabs(v.e[2])));
}

}  // namespace rt
