// Image files. Chapter 01.
// .png: 8-bit sRGB-encoded RGB (display_encoding.h), encoded by stb_image_write.
// .pfm: exact linear float32 RGB, the Portable Float Map: header "PF\n<w> <h>\n-1.0\n" (negative
//       scale = little-endian), then rows from the BOTTOM of the image to the top.
// The encoder hands its bytes to a sink rather than to a file, so that the program can write
// every output of a run all or none (rt/files/image_outputs.h) with these same bytes.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "rt/image/image.h"

namespace rt {

enum class image_format { png, pfm };

// The format a file name's extension names (".png", ".pfm"); none for any other.
std::optional<image_format> format_of(const std::string& path);

// Receives an encoded image in pieces, in order.
using byte_sink = std::function<void(const void* data, std::size_t size)>;

// Encodes img in the given format into sink. False only when the PNG encoder could not get the
// memory it needs.
bool encode_image(const image& img, image_format format, const byte_sink& sink);

// Reads a little- or big-endian RGB PFM. Throws user_error on a missing or malformed file.
image read_pfm(const std::string& path);

}  // namespace rt
