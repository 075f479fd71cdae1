// A texture from an image file, looked up at the nearest texel. Chapter 08.
// u runs left to right, v bottom to top (image rows are stored top first, so row = (1 - v) H);
// u and v are clamped to [0, 1]. Texels are kept as the file's 8-bit sRGB bytes, 3 bytes a
// texel, and decoded to linear light at lookup through a 256-entry table (the book divides by
// 255 without decoding, which makes textures look washed out once the output is sRGB-encoded).
//
// Hostile files: the header is read (stbi_info) before anything is decoded or allocated, and an
// image of more than max_texels = 2^26 texels (8192 x 8192; 192 MiB of texels) is refused
// there, as film.h refuses a render of more than 2^26 pixels. So a small PNG that claims to be
// 100000 x 100000 costs nothing. Only PNG, JPEG and binary PPM/PGM files reach stb_image, the
// formats the fuzz target (fuzz/fuzz_texture.cpp) covers, and no file with a fault it found in
// stb 2.27: a PNG that inflates to far more than its size needs (png_guard.h), a JPEG table that
// overflows stb's arrays (jpeg_guard.h), a PPM header number that overflows or texel data cut
// short (pnm_guard.h).
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "rt/textures/texture.h"

namespace rt {

// How a texel's bytes become light: decoded as sRGB (ours), or divided by 255 as the book does
// (to compare with a render of the book's code).
enum class texel_decoding { srgb, bytes_over_255 };

// The decoding of a texture loaded without one: srgb, unless a program's --texture-decoding
// chose the book's before it built its scene (chapters/ch08_textures/texture_decoding_option.h).
texel_decoding default_texel_decoding();
void set_default_texel_decoding(texel_decoding decoding);

class image_texture : public texture {
  public:
    // The most texels a texture may have: 2^26, 192 MiB of 8-bit RGB.
    static constexpr std::int64_t max_texels = std::int64_t(1) << 26;

    // Loads a PNG, JPEG or binary PPM/PGM file with stb_image. Throws user_error, one line
    // naming the file, when it is missing, not a regular file, empty, of another format,
    // truncated or damaged, or larger than texel_limit texels (tests and the fuzz target pass a
    // smaller limit to reach the refusal with small files).
    explicit image_texture(const std::string& path, std::int64_t texel_limit = max_texels,
                           texel_decoding decoding = default_texel_decoding());

    color value(real u, real v, const point3& p) const override;
    bool uses_uv() const override { return true; }

    int width() const { return w; }
    int height() const { return h; }

    // [ch19 begin]
    // What it was made with, for a scene file (rt/scene_files).
    const std::string& path() const { return given_path; }
    texel_decoding decoding_used() const { return decoding; }
    // [ch19 end]

  private:
    struct stb_free {
        void operator()(unsigned char* pixels) const;
    };

    int w = 0, h = 0;
    texel_decoding decoding;
    std::string given_path;  // [ch19] the path as given
    // 8-bit sRGB RGB, row 0 at the top: the buffer stb_image decoded into, kept as it is.
    std::unique_ptr<unsigned char, stb_free> texels;
};

}  // namespace rt
