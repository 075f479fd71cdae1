#include "rt/accel/wide_bvh.h"

#include <algorithm>
#include <array>
#include <bit>
#include <limits>

#include "rt/core/exercise.h"

namespace rt {

wide_bvh::wide_bvh(const bvh& tree, const object_map& map,
                   const std::vector<leaf_shapes_maker>& extra_kinds) {
    for (const auto& make : extra_kinds) extras.push_back(make());
    for (const auto& object : tree.objects()) objects.push_back(map ? map(object) : object);
    for (const auto& object : objects) leaf_objects.push_back(object.get());
    if (tree.nodes().empty()) return;
    box  = tree.nodes()[0].box;
    root = pack(tree, 0);
}

wide_bvh::wide_bvh(const std::vector<bounded_object>& input) : wide_bvh(bvh(input)) {}

std::uint32_t wide_bvh::pack_leaf(const bvh::node& b) {
    // Each object goes to the first kind that takes it, and runs of one kind are merged, so a
    // leaf of one kind (most leaves) is one run.
    const auto first_run = std::uint32_t(runs.size());
    for (std::uint32_t i = b.offset; i < b.offset + b.count; ++i) {
        const hittable& object = *objects[i];
        std::uint8_t of_kind   = others_kind;
        std::optional<std::uint32_t> index;
        if ((index = spheres.add(object))) {
            of_kind = spheres_kind;
        } else if ((index = moving_spheres.add(object))) {
            of_kind = moving_spheres_kind;
        } else if ((index = quads.add(object))) {
            of_kind = quads_kind;
        } else {
            for (std::size_t k = 0; k < extras.size() && !index; ++k)
                if ((index = extras[k]->add(object))) of_kind = std::uint8_t(extra_kind + k);
        }
        if (!index) {
            others.push_back(&object);
            index = std::uint32_t(others.size() - 1);
        }
        if (runs.size() > first_run && runs.back().kind == of_kind) {
            ++runs.back().count;  // consecutive in its kind's array too: added in leaf order
        } else {
            runs.push_back({*index, i, 1, of_kind, false});
        }
    }
    runs.back().last = true;  // a bvh's leaf holds at least one object
    return leaf_bit | first_run;
}

std::uint32_t wide_bvh::pack(const bvh& tree, std::uint32_t index) {
    const std::vector<bvh::node>& binary = tree.nodes();
    const bvh::node& b                   = binary[index];
    if (b.count > 0) return pack_leaf(b);

    // The lanes: up to four nodes of the binary subtree below this one, none inside another (a
    // cut). It starts at the two children; while there is room, the interior lane with the
    // largest box, the one a ray is likeliest to enter (as in bvh's build), gives way to its
    // two children. Folding a fixed two levels instead would leave lanes empty where a child is
    // a leaf, and make deeper wide trees (the walls of a room: four box tests per ray, not
    // three). Each lane keeps its path from here, which orders the visits below.
    struct step {
        int side;  // 0: the binary node's first child, 1: its second
        int axis;  // the binary node's split axis
    };
    struct lane {
        std::uint32_t binary;    // index in the binary tree
        std::vector<step> path;  // from this node down, one step per binary level
    };
    std::vector<lane> lanes = {{index + 1, {{0, b.axis}}}, {b.offset, {{1, b.axis}}}};
    // [exercise wide_bvh::pack begin]
    while (lanes.size() < 4) {
        int widest       = -1;
        real widest_area = 0;
        for (std::size_t k = 0; k < lanes.size(); ++k) {
            const bvh::node& c = binary[lanes[k].binary];
            // A NaN area (an unbounded box) is taken too: !(a <= b) rather than a > b.
            if (c.count == 0 && (widest < 0 || !(c.box.half_area() <= widest_area))) {
                widest      = int(k);
                widest_area = c.box.half_area();
            }
        }
        if (widest < 0) break;  // every lane a leaf
        const lane parent  = lanes[std::size_t(widest)];
        const bvh::node& c = binary[parent.binary];
        lane first = parent, second = parent;
        first.binary  = parent.binary + 1;
        second.binary = c.offset;
        first.path.push_back({0, c.axis});
        second.path.push_back({1, c.axis});
        lanes[std::size_t(widest)] = first;
        lanes.insert(lanes.begin() + widest + 1, second);
    }
    // [exercise wide_bvh::pack end]

    wide_node_area += b.box.half_area();
    const auto here = std::uint32_t(nodes.size());
    nodes.push_back({});
    std::uint32_t child[4] = {0, 0, 0, 0};
    for (std::size_t k = 0; k < lanes.size(); ++k) child[k] = pack(tree, lanes[k].binary);

    node& n = nodes[here];
    const aabb nothing;  // unused lanes: an empty box, which every ray misses
    for (int axis = 0; axis < 3; ++axis) {
        real lower[4], upper[4];
        for (std::size_t k = 0; k < 4; ++k) {
            const aabb& box_k = k < lanes.size() ? binary[lanes[k].binary].box : nothing;
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
    // [exercise wide_bvh::visit_order begin]
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
    // [exercise wide_bvh::visit_order end]
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
    // [exercise hit_four begin]
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
    // [exercise hit_four end]
}

}  // namespace

// Inlined into the traversal (always_inline), where it runs once or twice per ray. The kinds are
// told apart by comparisons, not a switch: a jump table's indirect branch is harder to predict.
[[gnu::always_inline]] inline bool wide_bvh::hit_leaf(std::uint32_t first_run, const ray& r,
                                                      interval& ray_t, hit_record& rec) const {
    bool hit_anything = false;
    // Each test asks only for hits nearer than the nearest found so far (ray_t.max).
    for (std::uint32_t k = first_run;; ++k) {
        const run& here = runs[k];
        if (here.kind == spheres_kind) {
            hit_anything |= spheres.hit(here.first, here.count, r, ray_t, rec);
        } else if (here.kind == quads_kind) {
            hit_anything |= quads.hit(here.first, here.count, r, ray_t, rec);
        } else if (here.kind == moving_spheres_kind) {
            hit_anything |= moving_spheres.hit(here.first, here.count, r, ray_t, rec);
        } else if (here.kind == others_kind) {
            for (std::uint32_t i = here.first; i < here.first + here.count; ++i) {
                if (others[i]->hit(r, ray_t, rec)) {
                    ray_t.max    = rec.t;
                    hit_anything = true;
                }
            }
        } else {
            hit_anything |=
                extras[here.kind - extra_kind]->hit(here.first, here.count, r, ray_t, rec);
        }
        if (here.last) return hit_anything;
    }
}

#if defined(__x86_64__)
#define RT_ALSO_FOR_AVX2 [[gnu::target_clones("avx2", "default")]]
#else
#define RT_ALSO_FOR_AVX2  // other processors: one version, whatever vectors the build targets
#endif
RT_ALSO_FOR_AVX2 bool wide_bvh::closest_hit(const ray& r, interval ray_t, hit_record& rec) const {
    // The root's own box is not tested: its children's boxes lie inside it, so a ray that misses
    // it misses them too (their slab distances are rounded the same way), and a root that is a
    // leaf is just its objects, which answer for themselves.
    if (root & leaf_bit) return !runs.empty() && hit_leaf(root & ~leaf_bit, r, ray_t, rec);
    // [exercise wide_bvh::closest_hit begin]
    const slab_ray<real4> sr(r);

    // Children still to visit, with where the ray enters them: when one comes up, a hit found
    // since then may already be nearer, and the child is skipped without another test.
    // A wide node leaves at most 3 of its children waiting, and the wide tree has no more levels
    // than the binary tree.
    struct pending {
        std::uint32_t child;
        real t_enter;
    };
    pending stack[3 * bvh::max_depth];
    int top               = 0;
    std::uint32_t current = root;
    bool hit_anything     = false;
    while (true) {
        if (current & leaf_bit) {
            if (hit_leaf(current & ~leaf_bit, r, ray_t, rec)) hit_anything = true;
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
    // [exercise wide_bvh::closest_hit end]
}

bool wide_bvh::hit(const ray& r, interval ray_t, hit_record& rec) const {
    return closest_hit(r, ray_t, rec);
}

RT_ALSO_FOR_AVX2 real wide_bvh::shadow_fraction(const ray& r, interval ray_t) const {
    if (runs.empty()) return 1;
    // Every child the box test lets through, in the binary tree's first-child-first order (octant
    // 0), so that the fractions multiply in the same order whatever the ray's direction.
    const slab_ray<real4> sr(r);
    std::uint32_t stack[3 * bvh::max_depth + 1];  // as closest_hit's, and the one popped
    int top               = 0;
    std::uint32_t current = root;
    real fraction         = 1;
    while (true) {
        if (current & leaf_bit) {
            for (std::uint32_t k = current & ~leaf_bit;; ++k) {
                const run& here = runs[k];
                for (std::uint32_t i = here.first_object; i < here.first_object + here.count; ++i) {
                    fraction *= leaf_objects[i]->transmittance(r, ray_t);
                    if (fraction == 0) return 0;
                }
                if (here.last) break;
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
real wide_bvh::transmittance(const ray& r, interval ray_t) const {
    return shadow_fraction(r, ray_t);
}

}  // namespace rt
