#include "texture.h"

#include "validate.h"

namespace rt {

checker_texture::checker_texture(real scale, std::shared_ptr<texture> even_texture,
                                 std::shared_ptr<texture> odd_texture)
    : cell_size(scale), even(std::move(even_texture)), odd(std::move(odd_texture)) {
    require_positive(scale, "checker scale");
    require_given(even, "checker even texture");
    require_given(odd, "checker odd texture");
}

}  // namespace rt
