#include "rt/scene_files/described_scene.h"

#include <array>
#include <utility>

namespace rt {

namespace {

constexpr std::array<std::pair<integrator_kind, std::string_view>, 5> integrators{{
    {integrator_kind::sky, "sky"},
    {integrator_kind::normals, "normals"},
    {integrator_kind::path, "path"},
    {integrator_kind::light, "light"},
    {integrator_kind::mis, "mis"},
}};

}  // namespace

std::string_view integrator_name(integrator_kind kind) {
    for (const auto& [k, name] : integrators)
        if (k == kind) return name;
    return "path";
}

std::optional<integrator_kind> integrator_named(std::string_view name) {
    for (const auto& [kind, n] : integrators)
        if (n == name) return kind;
    return std::nullopt;
}

std::string integrator_names() {
    std::string names;
    for (std::size_t i = 0; i < integrators.size(); ++i) {
        if (i > 0) names += i + 1 == integrators.size() ? " or " : ", ";
        names += integrators[i].second;
    }
    return names;
}

}  // namespace rt
