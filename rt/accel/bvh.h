// A bounding volume hierarchy: a binary tree of boxes over the scene's objects, so a ray tests
// the objects inside the boxes it crosses instead of every object. Chapter 07.
// Built top-down with the surface area heuristic over binned centroids: a split's cost is
//   C = C_traverse + sum over both sides of (area(side) / area(parent)) * count(side),
// the expected number of object tests, since a random ray that crosses the parent crosses a
// child box with probability area ratio. Traversal visits the nearer child first, and skips any
// box farther than the nearest hit found so far, so it finds exactly the flat list's nearest hit.
// Chapter 17 packs this same tree into wide nodes for speed (wide_bvh.h).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "rt/accel/bounded.h"

namespace rt {

class bvh : public bounded_hittable {
  public:
    // One node of the tree, in depth-first order: an interior node's first child follows it.
    struct node {
        aabb box;
        std::uint32_t offset = 0;  // interior: its second child; leaf: its first object
        std::uint16_t count  = 0;  // objects in a leaf; 0 for an interior node
        std::uint8_t axis    = 0;  // interior: the split axis (0, 1, 2 for x, y, z)
    };

    // Builds the tree over `objects`; deterministic (no random choices).
    explicit bvh(const std::vector<bounded_object>& objects);

    bool hit(const ray& r, interval ray_t, hit_record& rec) const override;
    aabb bounding_box() const override { return tree.empty() ? aabb() : tree[0].box; }

    // [ch14 begin]
    // Every leaf the ray's box test lets through, not only the nearest: a medium in front of
    // a blocker still counts, and any blocker ends the search.
    real transmittance(const ray& r, interval ray_t) const override;
    void visit_parts(part_visitor& visitor) const override {
        for (const auto& object : leaf_objects) visitor.visit(*object);
    }
    // [ch14 end]

    // The tree: its nodes (the root first, none if there are no objects), and the objects of
    // its leaves, a leaf's `count` of them from its `offset` on.
    const std::vector<node>& nodes() const { return tree; }
    const std::vector<std::shared_ptr<hittable>>& objects() const { return leaf_objects; }
    std::size_t node_count() const { return tree.size(); }
    std::size_t object_count() const { return leaf_objects.size(); }
    int depth() const { return levels; }
    // [ch19 begin]
    // The objects in the order they were given (a scene file lists them so, and the same list
    // builds the same tree).
    std::vector<std::shared_ptr<hittable>> objects_as_given() const;
    // [ch19 end]

    // The deepest a tree may be: traversal keeps the second children it has yet to visit on a
    // stack of this size.
    static constexpr int max_depth = 64;

  private:
    struct build_item;
    std::uint32_t build(std::vector<build_item>& items, std::size_t begin, std::size_t end,
                        int level);

    std::vector<node> tree;
    std::vector<std::shared_ptr<hittable>> leaf_objects;
    std::vector<std::uint32_t> given_index;  // [ch19] leaf_objects[k] was given as given_index[k]
    int levels = 0;
};

}  // namespace rt
