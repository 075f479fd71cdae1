// Comparing our numbers with numbers the book's own code printed. The book computes in double,
// as the release build does (a few ulps apart where the operations' order differs); a float
// build is held to float's precision of the same sums, with a margin for values near 0.
#pragma once

#include <catch2/catch.hpp>
#include <type_traits>

#include "rt/core/scalar.h"
#include "rt/core/vec3.h"

inline Approx book_value(double expected) {
    if (std::is_same_v<rt::real, float>) return Approx(expected).epsilon(1e-5).margin(1e-6);
    return Approx(expected).epsilon(1e-13).margin(1e-15);
}

inline void check_book_vector(const rt::vec3& v, double x, double y, double z) {
    CAPTURE(v.x(), v.y(), v.z(), x, y, z);
    CHECK(v.x() == book_value(x));
    CHECK(v.y() == book_value(y));
    CHECK(v.z() == book_value(z));
}
