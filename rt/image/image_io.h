// Writing and reading images. Chapter 01.
// .png: 8-bit sRGB-encoded RGB (display_encoding.h), written with stb_image_write.
// .pfm: exact linear float32 RGB, the Portable Float Map: header "PF\n<w> <h>\n-1.0\n" (negative
//       scale = little-endian), then rows from the BOTTOM of the image to the top.
// Every write goes to a temporary file beside the target and is renamed over it only when
// complete (output_set.h), so a failed or interrupted write never leaves a partial or truncated
// file; a run puts all its images in one output_set, so it replaces all of them or none.
#pragma once

#include <string>

#include "rt/files/output_set.h"
#include "rt/image/image.h"

namespace rt {

// Empty when `path` can be written (known extension, existing folder); else the reason.
std::string output_path_problem(const std::string& path);

// Writes img into `outputs`, in the format named by path's extension: complete in its temporary
// file now, onto `path` at outputs.commit(). Throws user_error naming path and the reason.
void write_image(output_set& outputs, const std::string& path, const image& img);

// One image on its own: written and renamed onto path at once. Throws user_error on failure.
void write_image(const std::string& path, const image& img);

// Reads a little- or big-endian RGB PFM. Throws user_error on a missing or malformed file.
image read_pfm(const std::string& path);

}  // namespace rt
