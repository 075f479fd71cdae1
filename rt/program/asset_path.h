// The files that ship with the project in assets/ (the globe texture, made by
// tools/make-globe-texture), found where the build was configured. The folder's absolute path is
// compiled into asset_path.cpp alone, so that the chapters' programs hold no path of the checkout
// and compile to the same objects in any copy of it (ccache finds them again).
#pragma once

#include <string>

namespace rt {

// assets/NAME of this checkout: asset_path("globe.png").
std::string asset_path(const std::string& name);

}  // namespace rt
