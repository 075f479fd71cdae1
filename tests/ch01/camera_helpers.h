// Helpers shared by the camera tests of chapters 01, 06 and 07: the book's film, exact vector
// equality, and the message a camera's initialize() throws. Included as "ch01/camera_helpers.h".
#pragma once

#include <catch2/catch.hpp>
#include <limits>
#include <string>

#include "rt/core/error.h"
#include "rt/render/film.h"
#include "test_helpers.h"

namespace rt_test {

inline constexpr rt::real eps = std::numeric_limits<rt::real>::epsilon();

// The book's film: 400 x 225.
inline const rt::film book_film = rt::film::for_aspect(400, 16.0 / 9);

// The message of the user_error that initialize() throws on the book's film, or "" (and a failed
// check) if none.
template <typename Camera>
std::string initialize_error(Camera cam) {
    try {
        cam.initialize(book_film);
    } catch (const rt::user_error& e) {
        return e.what();
    }
    FAIL_CHECK("initialize() accepted invalid settings");
    return "";
}

}  // namespace rt_test
