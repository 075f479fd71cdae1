// A guard against JPEG files that Debian 12's stb_image (2.27) decodes unsafely, run before it
// decodes a texture (chapter 08's image_texture). Found by the fuzz target fuzz/fuzz_texture.cpp:
//   - a Huffman table (DHT segment) whose 16 code counts add up to more than 256: stb 2.27
//     writes that many code lengths and symbols into arrays of 257 and 256 bytes (a heap
//     buffer overflow; stb 2.28 added the check). A valid table has at most 256 codes.
//   - a scan that decodes with a Huffman table no DHT segment before it defined: stb decodes
//     with the uninitialized table (its assertion fails, or garbage). A valid file defines every
//     table before the first scan that uses it.
#pragma once

#include <cstdio>
#include <string>

namespace rt {

// Empty when `file` is not a JPEG, or is one with none of the faults above; else the reason, to
// show after the file's name. Walks every segment, those between the scans of a progressive JPEG
// included. Reads the file from its start and leaves it rewound.
std::string jpeg_table_problem(std::FILE* file);

}  // namespace rt
