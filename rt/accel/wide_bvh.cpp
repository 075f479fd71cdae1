#include "rt/accel/wide_bvh.h"

#include <algorithm>
#include <array>
#include <bit>
#include <limits>
#include <stdexcept>
#include <string>
#include <typeinfo>

namespace rt {

namespace {

constexpr int bin_count           = 12;  // SAH candidates per axis; more buys little
constexpr int max_leaf_objects    = 4;
constexpr real traversal_cost     = 1;   // relative to one object test
constexpr int max_traversal_depth = 64;  // stack size: above what build() can make
constexpr int max_sah_depth       = 40;  // below it, median splits: at most log2(n) more levels

}  // namespace

// The binary tree as build() makes it, depth first: a node's first child follows it, its second
// child is at `offset`. pack() then turns it into the nodes and leaves that traversal reads.
struct bvh::build_node {
    aabb box;
    std::uint32_t offset;  // leaf: index of its first item; interior: its second child
    std::uint16_t count;   // items in a leaf; 0 for an interior node
    std::uint8_t axis;     // interior: the split axis
};

struct bvh::build_item {
    aabb box;
    point3 centroid;
    std::uint32_t object;
};

namespace {

// The depth of the binary tree (an iterative walk, so a deep tree cannot overflow the stack).
template <typename Node>
int depth_of(const std::vector<Node>& tree) {
    int deepest = 0;
    std::vector<std::pair<std::uint32_t, int>> pending;
    if (!tree.empty()) pending.push_back({0, 1});
    while (!pending.empty()) {
        auto [index, level] = pending.back();
        pending.pop_back();
        deepest = std::max(deepest, level);
        if (tree[index].count == 0) {
            pending.push_back({index + 1, level + 1});
            pending.push_back({tree[index].offset, level + 1});
        }
    }
    return deepest;
}

}  // namespace

bvh::bvh(const std::vector<bounded_object>& input) {
    std::vector<build_item> items(input.size());
    for (std::size_t i = 0; i < input.size(); ++i) {
        const aabb& b = input[i].box;
        items[i]      = {b, b.centroid(), std::uint32_t(i)};
    }
    std::vector<build_node> tree;
    tree.reserve(2 * input.size());
    if (!items.empty()) build(tree, items, 0, items.size(), 1);

    // Traversal keeps pending siblings on a fixed stack: the tree must fit it (build() bounds the
    // depth by about 40 + log2(n), so this can only fail beyond ~2^23 pathological objects).
    levels        = depth_of(tree);
    boxes_in_tree = tree.size();
    if (levels > max_traversal_depth)
        throw std::logic_error("bvh: tree depth " + std::to_string(levels) + " exceeds the stack");
    if (tree.empty()) return;

    box  = tree[0].box;
    root = pack(tree, 0, input, items);
}

std::uint32_t bvh::build(std::vector<build_node>& tree, std::vector<build_item>& items,
                         std::size_t begin, std::size_t end, int level) {
    const auto index = std::uint32_t(tree.size());
    tree.push_back({});
    aabb bounds, centroid_bounds;
    for (std::size_t i = begin; i < end; ++i) {
        bounds          = aabb(bounds, items[i].box);
        centroid_bounds = aabb(centroid_bounds, aabb(items[i].centroid, items[i].centroid));
    }
    const std::size_t count = end - begin;
    auto make_leaf          = [&] {
        tree[index] = {bounds, std::uint32_t(begin), std::uint16_t(count), 0};
        return index;
    };
    if (count <= 1) return make_leaf();

    // Bin the centroids along the axis where they spread most.
    const int axis        = centroid_bounds.longest_axis();
    const interval extent = centroid_bounds.axis_interval(axis);
    if (!(extent.size() > 0)) {
        // All centroids coincide: no split can separate them; halve by index if too many.
        if (count <= max_leaf_objects) return make_leaf();
        std::size_t mid = begin + count / 2;
        build(tree, items, begin, mid, level + 1);
        const std::uint32_t second = build(tree, items, mid, end, level + 1);
        tree[index]                = {bounds, second, 0, std::uint8_t(axis)};
        return index;
    }
    auto bin_of = [&](const build_item& item) {
        // The comparison also sends NaN (an infinite extent) to bin 0.
        real f = (item.centroid[axis] - extent.min) / extent.size();
        return f > 0 ? std::min(int(std::min(f, real(1)) * bin_count), bin_count - 1) : 0;
    };
    std::array<aabb, bin_count> bin_box;
    std::array<std::size_t, bin_count> bin_objects{};
    for (std::size_t i = begin; i < end; ++i) {
        int b      = bin_of(items[i]);
        bin_box[b] = aabb(bin_box[b], items[i].box);
        ++bin_objects[b];
    }

    // Sweep from the right to know each suffix's box, then from the left to price each split.
    std::array<real, bin_count> right_area{};
    std::array<std::size_t, bin_count> right_count{};
    aabb right;
    std::size_t right_n = 0;
    for (int b = bin_count - 1; b > 0; --b) {
        right = aabb(right, bin_box[b]);
        right_n += bin_objects[b];
        right_area[b]  = right.half_area();
        right_count[b] = right_n;
    }
    // Boxes may have zero thickness (quads in a coordinate plane), so a parent may have zero
    // area (all its boxes points, or points on one line): then every cost is 0 / 0 = NaN, no
    // split beats infinity, and the node becomes a leaf or is split at the median below.
    aabb left;
    std::size_t left_n     = 0;
    real best_cost         = infinity;
    int best_split         = 1;  // objects in bins < best_split go left
    const real parent_area = bounds.half_area();
    for (int b = 1; b < bin_count; ++b) {
        left = aabb(left, bin_box[b - 1]);
        left_n += bin_objects[b - 1];
        if (left_n == 0 || right_count[b] == 0) continue;
        real cost =
            traversal_cost +
            (left.half_area() * real(left_n) + right_area[b] * real(right_count[b])) / parent_area;
        if (cost < best_cost) {
            best_cost  = cost;
            best_split = b;
        }
    }
    // A leaf costs one test per object: keep it when no split is cheaper. The split's price above
    // sees only the two halves' boxes; split further, though, a few objects end up each in its
    // own box of one wide node (bvh.h), which costs one node test and a test of each object
    // whose own box the ray crosses. That is far cheaper when the objects' boxes are much smaller
    // than their union: the walls of a room, each a flat box, whose union is the whole room.
    if (count <= max_leaf_objects) {
        real own_boxes = 0;
        for (std::size_t i = begin; i < end; ++i) own_boxes += items[i].box.half_area();
        const real singles = traversal_cost + own_boxes / parent_area;
        if (std::min(best_cost, singles) >= real(count)) return make_leaf();
    }

    auto first = items.begin() + std::ptrdiff_t(begin), last = items.begin() + std::ptrdiff_t(end);
    std::size_t mid;
    if (level < max_sah_depth && best_cost < infinity) {
        auto middle = std::partition(
            first, last, [&](const build_item& item) { return bin_of(item) < best_split; });
        mid = std::size_t(middle - items.begin());
    } else {
        // A pathological spread (say, exponentially spaced objects) could make SAH splits peel
        // off one object at a time; deep down, split at the median to bound the depth. Also
        // when no bin split separates anything (centroids too far apart for the bin arithmetic).
        mid = begin + count / 2;
        std::nth_element(first, items.begin() + std::ptrdiff_t(mid), last,
                         [&](const build_item& a, const build_item& b) {
                             return a.centroid[axis] < b.centroid[axis];
                         });
    }
    build(tree, items, begin, mid, level + 1);
    std::uint32_t second = build(tree, items, mid, end, level + 1);
    tree[index]          = {bounds, second, 0, std::uint8_t(axis)};
    return index;
}

std::uint32_t bvh::pack_leaf(const build_node& b, const std::vector<bounded_object>& input,
                             const std::vector<build_item>& items) {
    // Sort the leaf's objects by type. Exactly these types (typeid, not dynamic_cast): a class
    // derived from sphere may hit differently, and is asked through hit() instead.
    leaf l{};
    l.first        = std::uint32_t(objects.size());
    l.first_sphere = std::uint32_t(spheres.size());
    l.first_moving = std::uint32_t(moving_spheres.size());
    l.first_quad   = std::uint32_t(quads.size());
    l.first_other  = std::uint32_t(others.size());
    std::vector<std::shared_ptr<hittable>> moving, flat, other;
    for (std::uint32_t i = b.offset; i < b.offset + b.count; ++i) {
        const std::shared_ptr<hittable>& object = input[items[i].object].object;
        const hittable& o                       = *object;
        if (typeid(o) == typeid(sphere)) {
            const auto& s = static_cast<const sphere&>(o);
            spheres.push_back({s.center(), s.radius(), s.surface().get(), &s});
            objects.push_back(object);
            ++l.sphere_count;
        } else if (typeid(o) == typeid(moving_sphere)) {
            const auto& m = static_cast<const moving_sphere&>(o);
            moving_spheres.push_back({m.path(), m.radius(), m.surface().get(), &m});
            moving.push_back(object);
            ++l.moving_count;
        } else if (typeid(o) == typeid(quad)) {
            const auto& q = static_cast<const quad&>(o);
            quads.push_back({q.shape(), q.surface().get(), &q});
            flat.push_back(object);
            ++l.quad_count;
        } else {
            others.push_back(&o);
            other.push_back(object);
            ++l.other_count;
        }
    }
    objects.insert(objects.end(), moving.begin(), moving.end());
    objects.insert(objects.end(), flat.begin(), flat.end());
    objects.insert(objects.end(), other.begin(), other.end());
    for (std::size_t i = l.first; i < objects.size(); ++i) leaf_objects.push_back(objects[i].get());
    leaves.push_back(l);
    return leaf_bit | std::uint32_t(leaves.size() - 1);
}

std::uint32_t bvh::pack(const std::vector<build_node>& tree, std::uint32_t index,
                        const std::vector<bounded_object>& input,
                        const std::vector<build_item>& items) {
    const build_node& b = tree[index];
    if (b.count > 0) return pack_leaf(b, input, items);

    // The lanes: up to four nodes of the binary subtree below this one, none inside another (a
    // cut). It starts at the two children; while there is room, the interior lane with the
    // largest box, the one a ray is likeliest to enter (as in build()'s cost), gives way to its
    // two children. Folding a fixed two levels instead would leave lanes empty where a child is
    // a leaf, and make deeper wide trees (the walls of a room: four box tests per ray, not
    // three). Each lane keeps its path from here, which orders the visits below.
    struct step {
        int side;  // 0: the binary node's first child, 1: its second
        int axis;  // the binary node's split axis
    };
    struct lane {
        std::uint32_t binary;    // index in tree
        std::vector<step> path;  // from this node down, one step per binary level
    };
    std::vector<lane> lanes = {{index + 1, {{0, b.axis}}}, {b.offset, {{1, b.axis}}}};
    while (lanes.size() < 4) {
        int widest       = -1;
        real widest_area = 0;
        for (std::size_t k = 0; k < lanes.size(); ++k) {
            const build_node& c = tree[lanes[k].binary];
            // A NaN area (an unbounded box) is taken too: !(a <= b) rather than a > b.
            if (c.count == 0 && (widest < 0 || !(c.box.half_area() <= widest_area))) {
                widest      = int(k);
                widest_area = c.box.half_area();
            }
        }
        if (widest < 0) break;  // every lane a leaf
        const lane parent   = lanes[std::size_t(widest)];
        const build_node& c = tree[parent.binary];
        lane first = parent, second = parent;
        first.binary  = parent.binary + 1;
        second.binary = c.offset;
        first.path.push_back({0, c.axis});
        second.path.push_back({1, c.axis});
        lanes[std::size_t(widest)] = first;
        lanes.insert(lanes.begin() + widest + 1, second);
    }

    wide_node_area += b.box.half_area();
    const auto here = std::uint32_t(nodes.size());
    nodes.push_back({});
    std::uint32_t child[4] = {0, 0, 0, 0};
    for (std::size_t k = 0; k < lanes.size(); ++k)
        child[k] = pack(tree, lanes[k].binary, input, items);

    node& n = nodes[here];
    const aabb nothing;  // unused lanes: an empty box, which every ray misses
    for (int axis = 0; axis < 3; ++axis) {
        real lower[4], upper[4];
        for (std::size_t k = 0; k < 4; ++k) {
            const aabb& box_k = k < lanes.size() ? tree[lanes[k].binary].box : nothing;
            lower[k]          = box_k.axis_interval(axis).min;
            upper[k]          = box_k.axis_interval(axis).max;
        }
        n.bounds[axis]     = real4{lower[0], lower[1], lower[2], lower[3]};
        n.bounds[3 + axis] = real4{upper[0], upper[1], upper[2], upper[3]};
    }
    for (int k = 0; k < 4; ++k) n.child[k] = child[k];
    // The binary tree's visiting order: at each level the first child first, unless the ray runs
    // towards smaller coordinates on that level's split axis. So a lane's rank is its path with
    // each side flipped so, read as a word; no path begins another's (the lanes are disjoint
    // subtrees), so comparing words orders them. Unused lanes go last.
    for (int octant = 0; octant < 8; ++octant) {
        auto rank = [&](std::size_t k) {
            std::vector<int> word;
            for (const step& st : lanes[k].path) word.push_back(st.side ^ (octant >> st.axis & 1));
            return word;
        };
        std::array<std::size_t, 4> lane_of{0, 1, 2, 3};
        std::sort(lane_of.begin(), lane_of.end(), [&](std::size_t x, std::size_t y) {
            if (x >= lanes.size() || y >= lanes.size()) return x < y;  // unused lanes are last
            return rank(x) < rank(y);
        });
        n.order[octant] =
            std::uint8_t(lane_of[0] | lane_of[1] << 2 | lane_of[2] << 4 | lane_of[3] << 6);
    }
    return here;
}

namespace {

// A ray prepared for slab tests against a wide node's boxes (node::bounds): per axis, the
// origin and 1 / direction in every lane, and which bound the ray meets first (the lower one
// unless it runs towards smaller coordinates), as an index into bounds, so the test needs no
// branch on it; and the ray's octant, which picks the visiting order.
template <typename real4>
struct slab_ray {
    real4 origin[3], inv_dir[3];
    int near[3], far[3];
    int octant = 0;

    explicit slab_ray(const ray& r) {
        for (int axis = 0; axis < 3; ++axis) {
            const real o = r.origin()[axis], inv = 1 / r.direction()[axis];
            origin[axis]        = real4{o, o, o, o};
            inv_dir[axis]       = real4{inv, inv, inv, inv};
            const bool negative = inv < 0;
            near[axis]          = negative ? 3 + axis : axis;
            far[axis]           = negative ? axis : 3 + axis;
            octant |= negative ? 1 << axis : 0;
        }
    }
};

// Bit k set where lane k of a comparison's result is true (all bits set). On x86-64 by SSE's
// movemask, one instruction per two doubles (or four floats) instead of one extraction per lane:
// a few percent of a whole render, as every box test ends here. SSE2 is part of x86-64 itself,
// so this serves both versions of the traversal (below).
template <typename mask4>
[[gnu::always_inline]] inline unsigned lane_bits(const mask4& inside) {
#if defined(__x86_64__) && defined(RT_SCALAR_FLOAT)
    using float4 = float __attribute__((vector_size(16)));
    return unsigned(__builtin_ia32_movmskps((float4)inside));  // a vector cast keeps the bits
#elif defined(__x86_64__)
    using double4      = double __attribute__((vector_size(32)));
    using double2      = double __attribute__((vector_size(16)));
    const auto lanes   = (double4)inside;  // a vector cast keeps the bits
    const double2 low  = __builtin_shufflevector(lanes, lanes, 0, 1);
    const double2 high = __builtin_shufflevector(lanes, lanes, 2, 3);
    return unsigned(__builtin_ia32_movmskpd(low)) | unsigned(__builtin_ia32_movmskpd(high)) << 2;
#else
    return unsigned(inside[0] & 1) | unsigned(inside[1] & 2) | unsigned(inside[2] & 4) |
           unsigned(inside[3] & 8);
#endif
}

// aabb::hit()'s slab test on four boxes at once. Returns which boxes the ray overlaps within
// ray_t (bit k: lane k) and where it enters each. The same answers as aabb::hit(), box by box:
// - a NaN slab distance (0 * inf, a ray on a slab face) is no constraint: `t > acc ? t : acc`
//   keeps acc when t is NaN, as aabb::hit's comparisons do;
// - the far distance is widened by robust_factor; widening is increasing, so widening the
//   nearest far distance gives the same as aabb::hit's widening each before taking the minimum;
// - aabb::hit stops at the first empty overlap; taking all three axes first rejects the same
//   boxes, since the overlap only shrinks.
template <typename real4>
[[gnu::always_inline]] inline unsigned hit_four(const real4 bounds[6], const slab_ray<real4>& r,
                                                const interval& ray_t, real t_enter[4]) {
    constexpr real widen = 1 + 4 * std::numeric_limits<real>::epsilon();  // aabb's robust_factor
    real4 t_min          = {ray_t.min, ray_t.min, ray_t.min, ray_t.min};
    real4 t_far          = {infinity, infinity, infinity, infinity};
    for (int axis = 0; axis < 3; ++axis) {
        const real4 t0 = (bounds[r.near[axis]] - r.origin[axis]) * r.inv_dir[axis];
        const real4 t1 = (bounds[r.far[axis]] - r.origin[axis]) * r.inv_dir[axis];
        t_min          = t0 > t_min ? t0 : t_min;
        t_far          = t1 < t_far ? t1 : t_far;
    }
    const real4 zero = {0, 0, 0, 0};
    t_far *= t_far > zero ? real4{widen, widen, widen, widen}
                          : real4{2 - widen, 2 - widen, 2 - widen, 2 - widen};
    const real4 t_max = {ray_t.max, ray_t.max, ray_t.max, ray_t.max};
    t_far             = t_far < t_max ? t_far : t_max;
    const auto inside = t_min <= t_far;  // each lane: all bits set (-1) or none
    for (int k = 0; k < 4; ++k) t_enter[k] = t_min[k];
    return lane_bits(inside);
}

}  // namespace

// Inlined into the traversal (always_inline), where it runs once or twice per ray.
[[gnu::always_inline]] inline bool bvh::hit_leaf(const leaf& l, const ray& r, interval& ray_t,
                                                 hit_record& rec) const {
    bool hit_anything = false;
    // Each test asks only for hits nearer than the nearest found so far (ray_t.max).
    for (std::uint32_t i = l.first_sphere; i < l.first_sphere + l.sphere_count; ++i) {
        const static_sphere& s = spheres[i];
        if (hit_sphere(s.center, s.radius, r, ray_t, rec)) {  // as sphere::hit
            rec.mat      = s.mat;
            rec.object   = s.object;  // [ch08]
            ray_t.max    = rec.t;
            hit_anything = true;
        }
    }
    for (std::uint32_t i = l.first_moving; i < l.first_moving + l.moving_count; ++i) {
        const moving_sphere_fields& m = moving_spheres[i];
        if (hit_sphere(m.path.at(r.time()), m.radius, r, ray_t, rec)) {  // as moving_sphere::hit
            rec.mat      = m.mat;
            rec.object   = m.object;  // [ch08]
            ray_t.max    = rec.t;
            hit_anything = true;
        }
    }
    for (std::uint32_t i = l.first_quad; i < l.first_quad + l.quad_count; ++i) {
        const quad_fields& q = quads[i];
        if (hit_quad(q.shape, r, ray_t, rec)) {  // as quad::hit
            rec.mat      = q.mat;
            rec.object   = q.object;  // [ch08]
            ray_t.max    = rec.t;
            hit_anything = true;
        }
    }
    for (std::uint32_t i = l.first_other; i < l.first_other + l.other_count; ++i) {
        if (others[i]->hit(r, ray_t, rec)) {
            ray_t.max    = rec.t;
            hit_anything = true;
        }
    }
    return hit_anything;
}

// Compiled twice, for any x86-64 and for AVX2, the faster chosen when the program starts (GCC's
// function multiversioning, which a virtual function cannot have: hence hit(), below, calls
// this). AVX2 tests four double boxes in one instruction. The two give the same answers: the box
// test only subtracts, multiplies and compares, and AVX2 has no fused multiply-add that could
// round differently (that is the separate FMA extension, deliberately not targeted).
#if defined(__x86_64__)
#define RT_ALSO_FOR_AVX2 [[gnu::target_clones("avx2", "default")]]
#else
#define RT_ALSO_FOR_AVX2  // other processors: one version, whatever vectors the build targets
#endif
RT_ALSO_FOR_AVX2 bool bvh::closest_hit(const ray& r, interval ray_t, hit_record& rec) const {
    // The root's own box is not tested: its children's boxes lie inside it, so a ray that misses
    // it misses them too (their slab distances are rounded the same way), and a root that is a
    // leaf is just its objects, which answer for themselves.
    if (root & leaf_bit)
        return !leaves.empty() && hit_leaf(leaves[root & ~leaf_bit], r, ray_t, rec);
    const slab_ray<real4> sr(r);

    // Children still to visit, with where the ray enters them: when one comes up, a hit found
    // since then may already be nearer, and the child is skipped without another test.
    // A wide node leaves at most 3 of its children waiting, and the wide tree has no more levels
    // than the binary tree.
    struct pending {
        std::uint32_t child;
        real t_enter;
    };
    pending stack[3 * max_traversal_depth];
    int top               = 0;
    std::uint32_t current = root;
    bool hit_anything     = false;
    while (true) {
        if (current & leaf_bit) {
            if (hit_leaf(leaves[current & ~leaf_bit], r, ray_t, rec)) hit_anything = true;
        } else {
            const node& n = nodes[current];
            real t_enter[4];
            const unsigned hits = hit_four(n.bounds, sr, ray_t, t_enter);
            if ((hits & (hits - 1)) == 0 && hits != 0) {
                current = n.child[std::countr_zero(hits)];  // one child: go there
                continue;
            }
            if (hits != 0) {
                // Several: wait for them in reverse visiting order, then take the first.
                const unsigned order = n.order[sr.octant];
                for (int i = 3; i >= 0; --i) {
                    const unsigned k = order >> (2 * i) & 3u;
                    if (hits >> k & 1u) stack[top++] = {n.child[k], t_enter[k]};
                }
                current = stack[--top].child;
                continue;
            }
        }
        do {
            if (top == 0) return hit_anything;
            --top;
        } while (stack[top].t_enter > ray_t.max);
        current = stack[top].child;
    }
}

bool bvh::hit(const ray& r, interval ray_t, hit_record& rec) const {
    return closest_hit(r, ray_t, rec);
}

// [ch14 begin]
RT_ALSO_FOR_AVX2 real bvh::shadow_fraction(const ray& r, interval ray_t) const {
    if (leaves.empty()) return 1;
    // Every child the box test lets through, in the binary tree's first-child-first order (octant
    // 0), so that the fractions multiply in the same order whatever the ray's direction.
    const slab_ray<real4> sr(r);
    std::uint32_t stack[3 * max_traversal_depth + 1];  // as closest_hit's, and the one popped
    int top               = 0;
    std::uint32_t current = root;
    real fraction         = 1;
    while (true) {
        if (current & leaf_bit) {
            const leaf& l = leaves[current & ~leaf_bit];
            const auto count =
                std::uint32_t(l.sphere_count + l.moving_count + l.quad_count + l.other_count);
            for (std::uint32_t i = l.first; i < l.first + count; ++i) {
                fraction *= leaf_objects[i]->transmittance(r, ray_t);
                if (fraction == 0) return 0;
            }
        } else {
            const node& n = nodes[current];
            real t_enter[4];
            const unsigned hits = hit_four(n.bounds, sr, ray_t, t_enter);
            for (int i = 3; i >= 0; --i) {
                const unsigned k = unsigned(n.order[0]) >> (2 * i) & 3u;
                if (hits >> k & 1u) stack[top++] = n.child[k];
            }
        }
        if (top == 0) break;
        current = stack[--top];
    }
    return fraction;
}

// After shadow_fraction: Clang wants a multiversioned function declared so before its first use.
real bvh::transmittance(const ray& r, interval ray_t) const {
    return shadow_fraction(r, ray_t);
}
// [ch14 end]

}  // namespace rt
