// A guard against PNG decompression bombs, run before stb_image decodes a texture (chapter
// 08's image_texture).
// A PNG's pixels are one zlib stream, and stb_image inflates all of it, however long, before it
// looks at how much the image needs: a 1 MB PNG that claims 1 x 1 texels inflates to 1 GiB of
// memory (stb stops only at 2 GiB), which the texel limit (image_texture.h) never sees. So the
// stream is inflated here first into a buffer of bounded size: what the header's image needs,
//   R = sum over rows (and over the 7 passes of an interlaced image) of 1 + ceil(w bits / 8),
// twice over plus 1 MiB (stb accepts data after the image; some encoders leave some), and a
// stream that would need more is refused. Memory stays within a small multiple of R.
#pragma once

#include <cstdio>
#include <string>

namespace rt {

// Empty when `file` is not a PNG, or is one whose chunks fit in the file and whose image data
// inflates to at most 2 R + 1 MiB bytes, and whose first IDAT chunk is not empty; else the
// reason, to show after the file's name. Other faults are left to stb_image. Reads the file from
// its start and leaves it rewound.
std::string png_data_problem(std::FILE* file);

}  // namespace rt
