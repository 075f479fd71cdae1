// film (rt/render/film.h): the one owner of the image's size. The height follows from the width
// and the aspect ratio, rounded down as in the book, and is at least 1. Chapter 01.
#include <algorithm>
#include <catch2/catch.hpp>
#include <limits>
#include <string>

#include "rt/core/error.h"
#include "rt/render/film.h"

using Catch::Matchers::Contains;

namespace {

// The message of the user_error that for_aspect throws, or "" (and a failed check) if none.
std::string for_aspect_error(int width, double aspect) {
    try {
        rt::film::for_aspect(width, aspect);
    } catch (const rt::user_error& e) {
        return e.what();
    }
    FAIL_CHECK("for_aspect(" << width << ", " << aspect << ") accepted invalid settings");
    return "";
}

}  // namespace

TEST_CASE("film: the book's 400 wide at 16:9 is 225 rows", "[film][ch01]") {
    // The aspect ratio is a double in every build, so 400 / (16/9) is 225 rows as in the book
    // (in float, 16/9 rounds up and the quotient would fall to 224.99998).
    const rt::film book = rt::film::for_aspect(400, 16.0 / 9);
    CHECK(book.width == 400);
    CHECK(book.height == 225);
}

TEST_CASE("film: the height is width / aspect rounded down, at least 1", "[film][ch01]") {
    struct size_case {
        int width;
        double aspect;
    };
    for (size_case c :
         {size_case{400, 16.0 / 9}, size_case{1920, 16.0 / 9}, size_case{401, 2}, size_case{7, 1},
          size_case{1, 16.0 / 9}, size_case{10, 100}, size_case{3, 0.5}}) {
        const rt::film f = rt::film::for_aspect(c.width, c.aspect);
        CAPTURE(c.width, c.aspect);
        CHECK(f.width == c.width);
        CHECK(f.height == std::max(1, int(double(c.width) / c.aspect)));
    }
    CHECK(rt::film::for_aspect(1, 16.0 / 9).height == 1);  // int(0.5625) = 0, kept at one row
    CHECK(rt::film::for_aspect(10, 100).height == 1);
    CHECK(rt::film::for_aspect(1920, 16.0 / 9).height == 1080);
    CHECK(rt::film::for_aspect(3, 0.5).height == 6);  // taller than wide
}

TEST_CASE("film: a width below 1 or a bad aspect ratio throws a user_error naming it",
          "[film][ch01]") {
    CHECK(for_aspect_error(0, 16.0 / 9) == "image width must be at least 1, got 0");
    CHECK_THAT(for_aspect_error(-3, 1), Contains("image width") && Contains("got -3"));

    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    CHECK_THAT(for_aspect_error(400, nan), Contains("aspect ratio") && Contains("got nan"));
    CHECK_THAT(for_aspect_error(400, -1.5), Contains("aspect ratio") && Contains("got -1.5"));
    CHECK_THAT(for_aspect_error(400, 0), Contains("aspect ratio") && Contains("got 0"));
    CHECK_THAT(for_aspect_error(400, inf), Contains("aspect ratio") && Contains("got inf"));

    // The valid extremes are accepted.
    CHECK_NOTHROW(rt::film::for_aspect(1, 1));
}

TEST_CASE("film: more than 2^26 pixels is refused before anything is allocated", "[film][ch01]") {
    // 8192 x 8192 is exactly 2^26 pixels (1.5 GiB for the mean and the variance): allowed.
    CHECK(rt::film::for_aspect(8192, 1).height == 8192);
    CHECK(for_aspect_error(8193, 1) ==
          "image size (width x height) must be at most 2^26 pixels, got 8193 x 8193");
    CHECK_THAT(for_aspect_error(16384, 1), Contains("16384 x 16384"));
    // A tiny aspect ratio asks for an absurd height: refused, not converted to int.
    CHECK_THAT(for_aspect_error(400, 1e-300), Contains("400 x 4e+302"));
}
