// Writing a scene as a scene file, the form scene_reader.h reads back: every number written
// exactly (the shortest decimal that reads back as the same double), every object in the order
// the scene holds it, every BVH's objects in the order it was built from, so that the file's
// scene renders byte for byte as the scene it was written from. Chapter 19.
// Materials and textures get names ("lambertian3"); a group, and an object the scene holds in
// two places, becomes a named object. A box (chapter 11's six quads) is written as its corners,
// a chain of instances as one object's transform list.
#pragma once

#include <string>

#include "rt/scene_files/described_scene.h"

namespace rt {

// The file's text. Paths of texture and model files are written relative to `folder`, the
// folder the file will be in. `title` becomes the first comment line. Throws user_error for a
// scene the format cannot say (a mesh made in code rather than read from a model file).
std::string scene_file_text(const described_scene& scene, const std::string& folder,
                            const std::string& title);

// The text written to `path`, all or nothing (rt/files/output_set.h): a failed write leaves any
// old file as it was. Throws user_error naming the file and the reason.
void write_scene_file(const described_scene& scene, const std::string& path,
                      const std::string& title);

// A number as the file writes it: the shortest decimal that reads back as exactly x (an integer
// when it is one below 2^53, "-0.0" for negative zero).
std::string number_text(double x);

}  // namespace rt
