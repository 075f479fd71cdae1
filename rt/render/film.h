// The image's size in pixels: the one owner of width and height, which the camera and the
// renderer ask. Chapter 01. The height follows from the width and the camera's aspect ratio,
// rounded down (400 wide at 16:9 is 225 rows, as in the book), and is at least 1.
#pragma once

#include <algorithm>
#include <cmath>
#include <sstream>

#include "rt/core/validate.h"

namespace rt {

struct film {
    // The most pixels an image may have: a render holds its mean and its variance, 24 bytes a
    // pixel, so this caps them at 1.5 GiB, checked before anything is allocated.
    static constexpr double max_pixels = double(1 << 26);

    int width  = 0;
    int height = 0;

    // Throws user_error for a width below 1, an aspect ratio that is not positive and finite,
    // or more than max_pixels pixels.
    static film for_aspect(int width, double aspect_ratio) {
        require(width >= 1, "image width", "be at least 1", width);
        require(aspect_ratio > 0 && std::isfinite(aspect_ratio), "aspect ratio",
                "be positive and finite", aspect_ratio);
        // In double whatever real is, so that both builds round to the same height.
        double rows = std::max(1.0, std::floor(double(width) / aspect_ratio));
        if (double(width) * rows > max_pixels) {
            std::ostringstream size;
            size << width << " x " << rows;
            require(false, "image size (width x height)", "be at most 2^26 pixels", size.str());
        }
        return {width, int(rows)};
    }
};

}  // namespace rt
