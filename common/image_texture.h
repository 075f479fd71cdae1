// A texture from an image file, looked up at the nearest texel. Chapter 08.
// u runs left to right, v bottom to top (image rows are stored top first, so row = (1 - v) H);
// u and v are clamped to [0, 1]. Texels are 8-bit sRGB, decoded to linear light on load (the
// book divides by 255 without decoding, which makes textures look washed out once the output
// is sRGB-encoded).
#pragma once

#include <string>
#include <vector>

#include "texture.h"

namespace rt {

class image_texture : public texture {
  public:
    // Loads PNG, JPEG, BMP, TGA, ... with stb_image. Throws user_error naming the file and the
    // reason when it is missing, empty, truncated or not an image.
    explicit image_texture(const std::string& path);

    color value(real u, real v, const point3& p) const override;
    bool uses_uv() const override { return true; }

    int width() const { return w; }
    int height() const { return h; }

  private:
    int w = 0, h = 0;
    std::vector<color> texels;  // linear RGB, row 0 at the top
};

}  // namespace rt
