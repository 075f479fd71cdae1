#include "rt/textures/texture.h"

#include <limits>

#include "rt/core/validate.h"

namespace rt {

checker_texture::checker_texture(real scale, std::shared_ptr<texture> even_texture,
                                 std::shared_ptr<texture> odd_texture)
    : cell_size(scale), even(std::move(even_texture)), odd(std::move(odd_texture)) {
    require_positive(scale, "checker scale");
    // A subnormal scale would send every cell index x / scale to infinity, out of the range of
    // the integer cast in value().
    require(scale >= std::numeric_limits<real>::min(), "checker scale", "not be subnormal", scale);
    require_given(even, "checker even texture");
    require_given(odd, "checker odd texture");
}

sine_checker_texture::sine_checker_texture(real scale, std::shared_ptr<texture> even_texture,
                                           std::shared_ptr<texture> odd_texture)
    : frequency(pi / scale), even(std::move(even_texture)), odd(std::move(odd_texture)) {
    given_scale = scale;  // [ch19]
    require_positive(scale, "checker scale");
    // A subnormal scale would make pi / scale infinite, and every sine NaN.
    require(scale >= std::numeric_limits<real>::min(), "checker scale", "not be subnormal", scale);
    require_given(even, "checker even texture");
    require_given(odd, "checker odd texture");
}

}  // namespace rt
