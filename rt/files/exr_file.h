// OpenEXR files of the linear image, through Debian's OpenEXR library: the format the tools
// renderer users already have open (tev, Blender, Nuke, oiiotool). A scan-line file of three
// channels R, G and B, losslessly compressed (ZIP, 16 lines a block), 32-bit floats by default:
// the same floats as the PFM (rt/image/image_io.h), bit for bit.
// - Written with the library's C++ interface into memory, then handed to a byte sink, so that a
//   run's outputs are written all or none (output_set.h) like every other image.
// - Read with its core C interface, which checks the header and refuses a size beyond the
//   caller's limit before it allocates anything for the pixels: a hostile file costs no memory
//   (fuzz/fuzz_exr.cpp).
#pragma once

#include <cstddef>
#include <string>

#include "rt/image/image.h"
#include "rt/image/image_io.h"

namespace rt {

enum class exr_pixels {
    float32,  // the image's floats as they are
    half16,   // 16-bit floats: about 3 decimal digits; a value beyond half's largest finite
              // one (65504) is written as 65504 (and its negative), never as an infinity
};

// The largest half float: what half16 writes for anything brighter.
inline constexpr float largest_half = 65504.0f;

// Encodes img as an OpenEXR file into sink. Throws user_error if the library refuses.
void encode_exr(const image& img, exr_pixels pixels, const byte_sink& sink);

// What a read found: the image (its floats; half ones converted exactly) and how it was stored.
struct exr_image {
    image pixels;
    exr_pixels stored = exr_pixels::float32;
};

// The largest image read_exr accepts by default: the renderer's largest (16384 wide, at most
// 16384 high).
inline constexpr long long max_exr_pixels = 16384LL * 16384LL;

// Reads the R, G and B channels of a single-part scan-line OpenEXR file (the data window's
// pixels, row 0 at its top). Throws user_error naming `name` and the problem: not an OpenEXR
// file, damaged or truncated, tiled or deep or of several parts, without R, G or B, channels
// of integers or subsampled, or more than max_pixels pixels (refused before any pixel memory
// is allocated).
exr_image read_exr(const std::string& path, long long max_pixels = max_exr_pixels);
exr_image read_exr_bytes(const void* data, std::size_t size, const std::string& name,
                         long long max_pixels = max_exr_pixels);

}  // namespace rt
