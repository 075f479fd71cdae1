// A mesh's own tree, packed for triangles: chapter 07's BVH over one mesh's triangles, with up to
// eight of its boxes side by side in a node, kept in single precision, and the triangles of a
// leaf tested four at a time. Chapter 18.
// - Eight boxes in floats take 256 bytes with their children and visiting orders, where chapter
//   17's four in doubles take 224: about two thirds of the node visits of a four-wide tree, each
//   loading about as much. A box is rounded outwards to floats, and the ray's slab distances are
//   bounded below and above (the origin rounded towards each face, 1 / direction made smaller or
//   larger by the roundings' worst), so a box is missed only where the ray misses it in exact
//   arithmetic. So every leaf chapter 07's tree tests is tested, in the same order (the binary
//   tree's, nearer child first at each of its levels), and the nearest hit is the same triangle
//   at the same t, ties included. One difference, the other way: chapter 07's box test widens
//   where a ray leaves a box but not where it enters, so where a ray grazes a box (it ends on a
//   triangle, or passes through a vertex on the box's face) it can lose a hit, or of two at the
//   same t the one it visits first (3 of 75,552 rays aimed at vertices, edges and faces in
//   tests/ch18/test_mesh_bvh.cpp; 6 of 87,552 in float); here it is found, as every triangle
//   asked alone finds it.
// - A leaf's triangles (one to four) are tested as four lanes of doubles, each lane the very
//   arithmetic of intersect_triangle, so each triangle's answer is the one it gives alone; the
//   nearest is taken in leaf order, the first of equal distances winning, as the loop does. The
//   leaf holds its own copy of its corners, lane by lane (about 70 bytes a triangle more than
//   indices into the mesh): read in one run of cache lines instead of twelve vertices found
//   through their indices, which costs a miss after a miss once the mesh outgrows the caches.
//   The nearest hit's record is made from that copy too, read moments before, not from the
//   mesh's vertices (about a sixth more rays a second on meshes of 10^5 triangles and more).
// - A ray the float slabs cannot bound (a direction component below float's range, an origin
//   beyond it, an interval starting below 0) is traced through the binary tree itself.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "rt/accel/bvh.h"
#include "rt/accel/fast_traversal.h"
#include "rt/geometry/triangle_mesh.h"

namespace rt {

class mesh_bvh final : public bounded_hittable {
  public:
    // Packs `tree`, a BVH whose objects are all triangles of one mesh (as mesh_object() builds
    // it); throws std::invalid_argument for any other. Keeps the tree (and so the mesh) alive.
    explicit mesh_bvh(std::shared_ptr<const bvh> tree);

    // Whether `tree` holds only triangles of one mesh, so that it can be packed so.
    static bool packs(const bvh& tree);
    // What with_fast_traversal() takes to pack each mesh's tree so (and leave other trees).
    static tree_packer packer();

    bool hit(const ray& r, interval ray_t, hit_record& rec) const override;
    aabb bounding_box() const override { return binary->bounding_box(); }
    // The binary tree's (a shadow ray needs no nearest hit, and meshes seldom cast them here).
    real transmittance(const ray& r, interval ray_t) const override {
        return binary->transmittance(r, ray_t);
    }
    void visit_parts(part_visitor& visitor) const override { binary->visit_parts(visitor); }

    std::size_t node_count() const { return nodes.size(); }

  private:
    using float8 = float __attribute__((vector_size(32)));
    using real4  = real __attribute__((vector_size(4 * sizeof(real))));

    struct alignas(32) node {
        float8 bounds[6];  // the children's box bounds: lower x, y, z, then upper x, y, z
        // A node's index, or leaf_bit | (leaf's index << 2) | (its triangles - 1).
        std::uint32_t child[8];
        // Per octant of ray directions (bit k: the ray runs towards smaller coordinates on axis
        // k), the lane of the i-th visit in bits 3i to 3i + 2.
        std::uint32_t order[8];
    };
    // A leaf's triangles, side by side as the four lanes test them (the copy of their corners
    // the header's comment explains). Lanes past the leaf's triangles repeat its first.
    struct alignas(32) leaf {
        real4 corner[9];  // corner[3 * vertex + axis][lane]
        // Per octant of ray directions, the lane of the i-th visit in bits 8 * octant + 2i and
        // the next.
        std::uint64_t visit_order;
        std::uint32_t triangle[4];  // the mesh's indices of the lanes' triangles
    };
    static constexpr std::uint32_t leaf_bit = 0x80000000u;
    // A triangle as traversal finds it: its leaf and lane.
    struct leaf_lane {
        const leaf* in = nullptr;
        int lane       = 0;
    };

    std::uint32_t pack(std::uint32_t index);
    std::uint32_t pack_leaf(std::uint32_t index);
    bool hit_leaf(std::uint32_t leaf_index, int octant, const sheared_ray& sr, interval& ray_t,
                  triangle_hit& nearest, leaf_lane& nearest_at) const;
    void record(const leaf_lane& at, const triangle_hit& found, const ray& r,
                hit_record& rec) const;
    bool closest_hit(const ray& r, interval ray_t, hit_record& rec) const;

    std::shared_ptr<const bvh> binary;
    const triangle_mesh* mesh = nullptr;
    std::uint32_t root        = leaf_bit;
    std::vector<node> nodes;
    std::vector<leaf> leaves;
    std::vector<std::uint32_t> below;  // per binary node, the triangles under it
};

}  // namespace rt
