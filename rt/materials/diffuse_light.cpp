#include "rt/materials/diffuse_light.h"

#include "rt/core/validate.h"

namespace rt {

diffuse_light::diffuse_light(const color& c) : radiance(std::make_shared<solid_color>(c)) {
    require_radiance(c, "light radiance");
}

diffuse_light::diffuse_light(std::shared_ptr<texture> t) : radiance(std::move(t)) {
    require_given(radiance, "light radiance texture");
}

}  // namespace rt
