// Any scene made fast without touching how it is built: every chapter-07 bvh in its world,
// however deep (in lists, in other BVHs, inside instances), replaced by a wide_bvh of the same
// tree. Chapter 17. The wide BVH finds the same hits in the same order, so the image is the same
// byte for byte; only the time changes.
// Instances are placed again around their faster contents (the same offset, axis and angle, so
// the same numbers); shapes, materials and media are shared, not copied, so the lights a scene's
// integrator finds and every hit record's object and material are those of the world it was
// given. A medium's boundary is left as it is.
// A later chapter may pack trees it knows better itself (a tree_packer): it answers for the same
// hits in the same order too.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "rt/accel/bvh.h"
#include "rt/accel/leaf_shapes.h"
#include "rt/scene/scene.h"

namespace rt {

// A later chapter's own packing of the trees it knows (chapter 18: a mesh's tree of triangles):
// the tree's faster form, a bounded_hittable with the tree's box, or null for a tree it leaves
// to wide_bvh.
using tree_packer =
    std::function<std::shared_ptr<bounded_hittable>(const std::shared_ptr<const bvh>&)>;

// The world with every bvh in it packed: by the first of `packers` that takes it, otherwise as
// a wide_bvh with extra_kinds as wide_bvh's. An object holding no bvh comes back as it is.
std::shared_ptr<hittable> with_wide_bvhs(const std::shared_ptr<hittable>& world,
                                         const std::vector<leaf_shapes_maker>& extra_kinds = {},
                                         const std::vector<tree_packer>& packers           = {});

// The scene with its world so packed: the same camera, sky and settings.
scene with_fast_traversal(scene s, const std::vector<leaf_shapes_maker>& extra_kinds = {},
                          const std::vector<tree_packer>& packers = {});

}  // namespace rt
