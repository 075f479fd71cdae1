// A bounding volume hierarchy: a tree of boxes over the scene's objects, so a ray tests the
// objects inside the boxes it crosses instead of every object. Chapter 07.
// Built top-down with the surface area heuristic over binned centroids: a split's cost is
//   C = C_traverse + sum over both sides of (area(side) / area(parent)) * count(side),
// the expected number of object tests, since a random ray that crosses the parent crosses a
// child box with probability area ratio. Stored flat, depth first: a node's first child follows
// it, its second child is at `offset`. Traversal visits the nearer child first, and skips any
// box farther than the nearest hit found so far.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "bounded.h"

namespace rt {

class bvh : public bounded_hittable {
  public:
    // Builds the tree over `objects`; deterministic (no random choices).
    explicit bvh(const std::vector<bounded_object>& objects);

    bool hit(const ray& r, interval ray_t, hit_record& rec) const override;
    aabb bounding_box() const override;

    // [ch14 begin]
    // Every leaf the ray's box test lets through, not only the nearest: a medium in front of
    // a blocker still counts, and any blocker ends the search.
    real transmittance(const ray& r, interval ray_t) const override;
    void visit_parts(part_visitor& visitor) const override {
        for (const auto* object : leaf_objects) visitor.visit(*object);
    }
    // [ch14 end]

    std::size_t node_count() const { return nodes.size(); }
    std::size_t object_count() const { return objects.size(); }
    int depth() const;

  private:
    struct node {
        aabb box;
        std::uint32_t offset;  // leaf: index of its first object; interior: its second child
        std::uint16_t count;   // objects in a leaf; 0 for an interior node
        std::uint8_t axis;     // interior: the split axis, to choose the nearer child first
    };
    struct build_item;

    std::uint32_t build(std::vector<build_item>& items, std::size_t begin, std::size_t end,
                        int level);

    std::vector<std::shared_ptr<hittable>> objects;  // reordered so every leaf is contiguous
    std::vector<const hittable*> leaf_objects;       // the same, as plain pointers for traversal
    std::vector<node> nodes;
};

}  // namespace rt
