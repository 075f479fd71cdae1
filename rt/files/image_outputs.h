// Images as the outputs of a run: each written in full beside its target, and put in place with
// the run's other files all or none (output_set.h), in the format its extension names
// (rt/image/image_io.h), or OpenEXR for ".exr" (exr_file.h).
#pragma once

#include <string>

#include "rt/files/exr_file.h"
#include "rt/files/output_set.h"
#include "rt/image/image.h"

namespace rt {

// Empty when `path` can be written (a known extension, an existing folder); else the reason.
std::string output_path_problem(const std::string& path);

// Writes img into `outputs`: complete in its temporary file now, onto `path` at
// outputs.commit(); an OpenEXR file's pixels as `exr` says. Throws user_error naming path and
// the reason.
void write_image(output_set& outputs, const std::string& path, const image& img,
                 exr_pixels exr = exr_pixels::float32);

// One image on its own: written and renamed onto path at once. Throws user_error on failure.
void write_image(const std::string& path, const image& img, exr_pixels exr = exr_pixels::float32);

// Reads a linear image written as .pfm or as a 32-bit float .exr: the exact floats a run wrote
// (a half-float EXR is refused: it no longer holds them). Throws user_error naming path.
image read_exact_image(const std::string& path);

}  // namespace rt
