// A guard against binary PPM/PGM files that Debian 12's stb_image (2.27) reads unsafely, run
// before it decodes a texture (chapter 08's image_texture). Found by the fuzz target
// fuzz/fuzz_texture.cpp and by reading the decoder it pointed at:
//   - a number in the header beyond 2^31 - 1: stb adds up its digits in an int, which overflows
//     (undefined behaviour; stb 2.28 added the check);
//   - texel data shorter than the header's size: stb ignores the short read and hands back a
//     buffer partly never written, whose old heap contents would become texels;
//   - a 16-bit PGM (gray): stb converts its samples to RGB as if they were 8-bit, then reads
//     twice as many bytes from the result as it holds (a heap buffer overflow; fixed in 2.28).
//     16-bit PPMs (RGB) need no conversion and load.
#pragma once

#include <cstdio>
#include <string>

namespace rt {

// Empty when `file` is not a binary PPM (P6) or PGM (P5), or is one whose header numbers fit in
// an int, that is not a 16-bit PGM and, when check_data is set, whose texel data is all there;
// else the reason, to show after the file's name. Leaves the file rewound.
std::string pnm_problem(std::FILE* file, bool check_data);

}  // namespace rt
