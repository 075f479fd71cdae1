// Chapter 07's BVH, packed for speed: the same binary tree, with levels folded into their
// parents. Chapter 17.
// - A wide node holds up to four descendants' boxes side by side (the widest expanded first),
//   tested together by vector instructions, and is visited in the binary tree's own order, so
//   the wide BVH tests the same objects in the same order as chapter 07's, and finds the same
//   hits, equal-t ties included (the first found wins in both).
// - The leaves keep their spheres, moving spheres and quads by type, as plain arrays of fields
//   (leaf_shapes.h), so testing one is an inlined hit_sphere() or hit_quad() instead of a
//   virtual call. A leaf is a list of runs, each a stretch of its objects of one kind, so the
//   objects are still tested in the leaf's own order; any other object is asked through
//   hittable::hit, and a later chapter's shapes through the leaf_shapes makers it hands over.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "rt/accel/bvh.h"
#include "rt/accel/leaf_shapes.h"

namespace rt {

class wide_bvh : public bounded_hittable {
  public:
    // What a leaf object becomes in the wide BVH (by default itself). Its box must stay the
    // same: the tree's boxes are the binary tree's.
    using object_map = std::function<std::shared_ptr<hittable>(const std::shared_ptr<hittable>&)>;

    // Packs `tree`, its leaf objects passed through `map` (if given); `extra_kinds` make the
    // leaf_shapes of shapes beyond the built-in ones.
    explicit wide_bvh(const bvh& tree, const object_map& map = {},
                      const std::vector<leaf_shapes_maker>& extra_kinds = {});
    // Builds chapter 07's tree over `objects`, then packs it.
    explicit wide_bvh(const std::vector<bounded_object>& objects);

    bool hit(const ray& r, interval ray_t, hit_record& rec) const override;
    aabb bounding_box() const override { return box; }

    // As chapter 07's bvh: every leaf the ray's box test lets through, in the binary tree's
    // first-child-first order, so that the fractions multiply in the same order.
    real transmittance(const ray& r, interval ray_t) const override;
    void visit_parts(part_visitor& visitor) const override {
        for (const auto& object : objects) visitor.visit(*object);
    }

    // The surface area heuristic's measure of the stored tree, as bvh's build prices splits: a
    // ray that crosses the root's box crosses a box inside it with probability area ratio, so
    // a random ray tests on average this many wide nodes. Fewer is faster.
    real expected_node_tests() const {
        return box.half_area() > 0 ? wide_node_area / box.half_area() : 0;
    }
    std::size_t wide_node_count() const { return nodes.size(); }

  private:
    // Four reals side by side, one per child of a wide node. GCC and Clang compile arithmetic on
    // such a vector to SIMD instructions: two SSE2 instructions for four doubles on any x86-64,
    // one with AVX2 (hit() is also compiled for AVX2, chosen at run time).
    using real4 = real __attribute__((vector_size(4 * sizeof(real))));

    // A wide node: the binary tree's node with up to four of its descendants pulled up, so that
    // one test covers up to four boxes. The binary tree's inner boxes are then never tested: they
    // contain their children's, so a ray that misses one misses its children too. Each lane is a
    // child: a wide node's index, or leaf_bit | the index of a leaf's first run; unused lanes
    // hold an empty box.
    // Aligned to a real4 on purpose: GCC gives a 32-byte vector only 16-byte alignment where
    // the build does not enable AVX, and the AVX2 version's aligned loads would then fault.
    struct alignas(sizeof(real4)) node {
        real4 bounds[6];  // the children's box bounds: lower x, y, z, then upper x, y, z
        std::uint32_t child[4];
        // The order in which the binary tree would visit the children, nearer child first at
        // each of its levels, for each octant of ray directions (bit k set: the ray runs towards
        // smaller coordinates on axis k): lane of the i-th visit in bits 2i and 2i + 1.
        std::uint8_t order[8];
    };
    static constexpr std::uint32_t leaf_bit = 0x80000000u;

    // The kinds of a run: the built-in shapes, anything else (asked through hit()), then the
    // extra kinds in the order given.
    enum kind : std::uint8_t {
        spheres_kind,
        moving_spheres_kind,
        quads_kind,
        others_kind,
        extra_kind
    };
    // `count` consecutive objects of a leaf, of one kind: that kind's shapes from `first` on,
    // objects from `first_object` on. A leaf is its runs, one after the other in `runs` up to
    // the one marked last, so a lane leads to them with no leaf record in between.
    struct run {
        std::uint32_t first, first_object;
        std::uint16_t count;
        std::uint8_t kind;
        bool last;
    };

    std::uint32_t pack(const bvh& tree, std::uint32_t index);
    std::uint32_t pack_leaf(const bvh::node& b);
    bool hit_leaf(std::uint32_t first_run, const ray& r, interval& ray_t, hit_record& rec) const;
    bool closest_hit(const ray& r, interval ray_t, hit_record& rec) const;
    // transmittance(), compiled twice as closest_hit() is (a virtual function cannot be).
    real shadow_fraction(const ray& r, interval ray_t) const;

    aabb box;
    real wide_node_area = 0;         // the wide nodes' half areas, summed (the measure above)
    std::uint32_t root  = leaf_bit;  // where traversal starts: a node, or a leaf (none if empty)
    std::vector<node> nodes;
    std::vector<run> runs;
    // Every leaf's objects, leaf by leaf, in the binary tree's order (after the object map).
    std::vector<std::shared_ptr<hittable>> objects;
    std::vector<const hittable*> leaf_objects;  // the same, as plain pointers
    sphere_leaves spheres;
    moving_sphere_leaves moving_spheres;
    quad_leaves quads;
    std::vector<const hittable*> others;
    std::vector<std::unique_ptr<leaf_shapes>> extras;
};

}  // namespace rt
