// The image's size in pixels: the one owner of width and height, which the camera and the
// renderer ask. Chapter 01. The height follows from the width and the camera's aspect ratio,
// rounded down (400 wide at 16:9 is 225 rows, as in the book), and is at least 1.
#pragma once

#include <algorithm>

#include "validate.h"

namespace rt {

struct film {
    int width  = 0;
    int height = 0;

    // Throws user_error for a width below 1 or an aspect ratio that is not positive and finite.
    static film for_aspect(int width, double aspect_ratio) {
        require(width >= 1, "image width", "be at least 1", width);
        require(aspect_ratio > 0 && std::isfinite(aspect_ratio), "aspect ratio",
                "be positive and finite", aspect_ratio);
        // In double whatever real is, so that both builds round to the same height.
        return {width, std::max(1, int(double(width) / aspect_ratio))};
    }
};

}  // namespace rt
