// A bounding volume hierarchy: a tree of boxes over the scene's objects, so a ray tests the
// objects inside the boxes it crosses instead of every object. Chapter 07.
// Built top-down with the surface area heuristic over binned centroids: a split's cost is
//   C = C_traverse + sum over both sides of (area(side) / area(parent)) * count(side),
// the expected number of object tests, since a random ray that crosses the parent crosses a
// child box with probability area ratio. Traversal visits the nearer child first, and skips any
// box farther than the nearest hit found so far.
// Stored for speed, as the same binary tree with levels folded into their parents: a wide node
// holds up to four descendants' boxes side by side (the widest expanded first), tested together by
// vector instructions, and is visited in the binary tree's own order, so the BVH tests the same
// objects in the same order as a binary one would. The leaves keep their spheres and quads by type,
// as plain arrays of fields, so testing one is an inlined hit_sphere() or hit_quad() instead of a
// virtual call; any other object is asked through hittable::hit.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "rt/accel/bounded.h"
#include "rt/geometry/moving_sphere.h"
#include "rt/geometry/quad.h"

namespace rt {

class bvh : public bounded_hittable {
  public:
    // Builds the tree over `objects`; deterministic (no random choices).
    explicit bvh(const std::vector<bounded_object>& objects);

    bool hit(const ray& r, interval ray_t, hit_record& rec) const override;
    aabb bounding_box() const override { return box; }

    // [ch14 begin]
    // Every leaf the ray's box test lets through, not only the nearest: a medium in front of
    // a blocker still counts, and any blocker ends the search.
    real transmittance(const ray& r, interval ray_t) const override;
    void visit_parts(part_visitor& visitor) const override {
        for (const auto* object : leaf_objects) visitor.visit(*object);
    }
    // [ch14 end]

    // The binary tree's shape: its boxes (interior nodes and leaves) and its levels.
    std::size_t node_count() const { return boxes_in_tree; }
    std::size_t object_count() const { return objects.size(); }
    int depth() const { return levels; }
    // The surface area heuristic's measure of the stored tree, as build() prices splits: a ray
    // that crosses the root's box crosses a box inside it with probability area ratio, so a
    // random ray tests on average this many wide nodes. Fewer is faster.
    real expected_node_tests() const { return wide_node_area / box.half_area(); }

  private:
    struct build_node;
    struct build_item;

    // Four reals side by side, one per child of a wide node. GCC and Clang compile arithmetic on
    // such a vector to SIMD instructions: two SSE2 instructions for four doubles on any x86-64,
    // one with AVX2 (bvh::hit is also compiled for AVX2, chosen at run time).
    using real4 = real __attribute__((vector_size(4 * sizeof(real))));

    // A wide node: the binary tree's node with up to four of its descendants pulled up, so that
    // one test covers up to four boxes. The binary tree's inner boxes are then never tested: they
    // contain their children's, so a ray that misses one misses its children too. Each lane is a
    // child: a wide node's index, or leaf_bit | a leaf index; unused lanes hold an empty box.
    // Aligned to a real4 on purpose: GCC gives a 32-byte vector only 16-byte alignment where
    // the build does not enable AVX, and the AVX2 version's aligned loads would then fault.
    struct alignas(sizeof(real4)) node {
        real4 bounds[6];  // the children's box bounds: lower x, y, z, then upper x, y, z
        std::uint32_t child[4];
        // The order in which the binary tree would visit the children, nearer child first at
        // each of its two levels, for each octant of ray directions (bit k set: the ray runs
        // towards smaller coordinates on axis k): lane of the i-th visit in bits 2i and 2i + 1.
        std::uint8_t order[8];
    };
    static constexpr std::uint32_t leaf_bit = 0x80000000u;

    // A leaf: its objects from `first` on in `objects` (static spheres, then moving spheres, then
    // quads, then the rest), and where each kind starts in its typed array.
    struct leaf {
        std::uint32_t first, first_sphere, first_moving, first_quad, first_other;
        std::uint16_t sphere_count, moving_count, quad_count, other_count;
    };
    // A sphere's fields, copied from it: tested as sphere::hit() tests it (same hit_sphere()).
    struct static_sphere {
        point3 center;
        real radius;
        const material* mat;
        const hittable* object;
    };
    // A moving sphere's fields, tested as moving_sphere::hit() tests it.
    struct moving_sphere_fields {
        center_path path;
        real radius;
        const material* mat;
        const hittable* object;
    };

    // A quad's fields, tested as quad::hit() tests it (same hit_quad()).
    struct quad_fields {
        quad_shape shape;
        const material* mat;
        const hittable* object;
    };

    std::uint32_t build(std::vector<build_node>& tree, std::vector<build_item>& items,
                        std::size_t begin, std::size_t end, int level);
    std::uint32_t pack(const std::vector<build_node>& tree, std::uint32_t index,
                       const std::vector<bounded_object>& input,
                       const std::vector<build_item>& items);
    std::uint32_t pack_leaf(const build_node& b, const std::vector<bounded_object>& input,
                            const std::vector<build_item>& items);
    bool hit_leaf(const leaf& l, const ray& r, interval& ray_t, hit_record& rec) const;
    bool closest_hit(const ray& r, interval ray_t, hit_record& rec) const;
    // [ch14] transmittance(), compiled twice as closest_hit() is (a virtual function cannot be).
    real shadow_fraction(const ray& r, interval ray_t) const;

    aabb box;
    std::size_t boxes_in_tree = 0;
    real wide_node_area       = 0;  // the wide nodes' half areas, summed (the measure above)
    int levels                = 0;
    std::uint32_t root = leaf_bit;  // where traversal starts: a node, or a leaf (none if empty)
    std::vector<node> nodes;
    std::vector<leaf> leaves;
    // Each leaf's objects, contiguous, in the order its typed arrays list them: static spheres,
    // then moving spheres, then quads, then the rest.
    std::vector<std::shared_ptr<hittable>> objects;
    std::vector<const hittable*> leaf_objects;  // the same, as plain pointers
    std::vector<static_sphere> spheres;
    std::vector<moving_sphere_fields> moving_spheres;
    std::vector<quad_fields> quads;
    std::vector<const hittable*> others;
};

}  // namespace rt
