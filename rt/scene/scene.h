// A scene: the objects, what surrounds them, the camera that looks, and the settings it is
// rendered with by default (its report settings; flags override them). Chapter 02.
// A chapter's program turns it into a render_job with the estimator it teaches:
// show_normals() in chapter 02, path_trace() from chapter 03 on.
#pragma once

#include <memory>

#include "rt/camera/camera.h"
#include "rt/geometry/hittable.h"
#include "rt/render/render.h"
#include "rt/scene/background.h"

namespace rt {

struct scene {
    std::shared_ptr<hittable> world;  // any hittable: a list, a BVH, a single sphere
    background sky;                   // chapter 01's sky unless the scene says otherwise
    std::shared_ptr<camera> cam = std::make_shared<camera>();
    render_settings settings;
};

}  // namespace rt
