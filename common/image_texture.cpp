#include "image_texture.h"

#include <stb/stb_image.h>

#include <algorithm>
#include <array>
#include <memory>

#include "display_encoding.h"
#include "error.h"

namespace rt {

image_texture::image_texture(const std::string& path) {
    int channels = 0;
    std::unique_ptr<stbi_uc, void (*)(void*)> pixels(stbi_load(path.c_str(), &w, &h, &channels, 3),
                                                     stbi_image_free);
    if (!pixels) {
        // stb gives no reason for some broken files (a PNG cut just before its end chunk).
        const char* reason = stbi_failure_reason();
        throw user_error("cannot read texture '" + path +
                         "': " + (reason && *reason ? reason : "not a readable image"));
    }
    std::array<real, 256> to_linear{};
    for (int i = 0; i < 256; ++i) to_linear[std::size_t(i)] = real(srgb_to_linear(i / 255.0));
    texels.resize(std::size_t(w) * std::size_t(h));
    for (std::size_t i = 0; i < texels.size(); ++i) {
        const stbi_uc* t = pixels.get() + 3 * i;
        texels[i]        = color(to_linear[t[0]], to_linear[t[1]], to_linear[t[2]]);
    }
}

color image_texture::value(real u, real v, const point3&) const {
    // Clamp to [0, 1]; the negated comparisons also send NaN to 0.
    u       = !(u > 0) ? 0 : std::min(u, real(1));
    v       = !(v > 0) ? 0 : std::min(v, real(1));
    int col = std::min(int(u * real(w)), w - 1);
    int row = std::min(int((1 - v) * real(h)), h - 1);
    return texels[std::size_t(row) * std::size_t(w) + std::size_t(col)];
}

}  // namespace rt
