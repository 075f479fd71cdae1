#include "diffuse_light.h"

#include <cmath>
#include <sstream>

#include "error.h"

namespace rt {

diffuse_light::diffuse_light(const color& c) : radiance(std::make_shared<solid_color>(c)) {
    for (int i = 0; i < 3; ++i) {
        if (!(c[i] >= 0) || !std::isfinite(c[i])) {
            std::ostringstream message;
            message << "light radiance must be >= 0 and finite, got " << c;
            throw user_error(message.str());
        }
    }
}

diffuse_light::diffuse_light(std::shared_ptr<texture> t) : radiance(std::move(t)) {
    if (!radiance) throw user_error("diffuse_light needs a texture");
}

}  // namespace rt
