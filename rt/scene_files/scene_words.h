// The words a scene file uses for settings that are enums in the code, both ways round, so that
// the reader and the writer cannot disagree. Chapter 19.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rt/materials/dielectric.h"

namespace rt {

// A dielectric's Fresnel term: "schlick", "exact", "book-schlick" (chapter 05).
std::vector<std::string_view> fresnel_names();
std::optional<fresnel_model> fresnel_named(std::string_view name);
std::string_view fresnel_name(fresnel_model model);

// An aspect ratio written "W:H" (whole numbers from 1 to 100000): W / H, computed as the code
// computes 16.0 / 9. Nothing for any other text.
std::optional<double> aspect_ratio_named(const std::string& text);
// "W:H" for a ratio that is exactly W / H with small whole numbers (up to 64), else nothing.
std::optional<std::string> aspect_ratio_name(double ratio);

}  // namespace rt
