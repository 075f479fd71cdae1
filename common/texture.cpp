#include "texture.h"

#include "validate.h"

namespace rt {

checker_texture::checker_texture(real scale, std::shared_ptr<texture> even_texture,
                                 std::shared_ptr<texture> odd_texture)
    : cell_size(scale), even(std::move(even_texture)), odd(std::move(odd_texture)) {
    require_in_range(scale, std::numeric_limits<real>::min(), std::numeric_limits<real>::max(),
                     "checker scale");
    if (!even || !odd) throw user_error("checker texture needs two textures");
}

}  // namespace rt
