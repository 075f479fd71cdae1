// A scene as a scene file describes it: the scene itself (objects, sky, camera, its default
// settings, sampler included) and the integrator it is rendered with, which a chapter's program
// otherwise chooses in code. Chapter 19.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "rt/scene/scene.h"

namespace rt {

// The estimators of chapters 01-15, by the chapter that teaches each.
enum class integrator_kind {
    sky,      // chapter 01: the sky along each camera ray, nothing hit
    normals,  // chapter 02: the normal at the first hit
    path,     // chapter 03: the path tracer
    light,    // chapter 14: book 3's mixture of material and light sampling
    mis,      // chapter 15: next-event estimation with multiple importance sampling
};

// The name a scene file gives it ("path") and back; nothing for an unknown name.
std::string_view integrator_name(integrator_kind kind);
std::optional<integrator_kind> integrator_named(std::string_view name);
// Every name, for messages: "sky, normals, path, light or mis".
std::string integrator_names();

struct described_scene {
    rt::scene scene;
    integrator_kind integrator = integrator_kind::path;
};

}  // namespace rt
