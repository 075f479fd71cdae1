// Everything a chapter renders: the objects, what surrounds them, and the camera that looks.
#pragma once

#include "background.h"
#include "camera.h"
#include "hittable_list.h"

namespace rt {

struct scene {
    hittable_list world;
    background sky;
    camera cam;
};

}  // namespace rt
