#include "rt/accel/mesh_bvh.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <typeinfo>

#include "rt/core/exercise.h"

namespace rt {

namespace {

using float8 = float __attribute__((vector_size(32)));
using float4 = float __attribute__((vector_size(16)));
using int8   = int __attribute__((vector_size(32)));

// The next float towards +inf or -inf, by its bits (std::nextafter is a library call, and this
// runs a few times per ray). For finite f only.
[[gnu::always_inline]] inline float next_float_up(float f) {
    if (f == 0) return std::numeric_limits<float>::denorm_min();
    const auto bits = std::bit_cast<std::uint32_t>(f);
    return std::bit_cast<float>(f > 0 ? bits + 1 : bits - 1);
}

[[gnu::always_inline]] inline float next_float_down(float f) {
    return -next_float_up(-f);
}

// The float nearest x on the side asked: x itself where it is a float, the largest float where
// x lies beyond them all, an infinity where x is one.
[[gnu::always_inline]] inline float rounded_down(real x) {
    const float f = float(x);
    if (!(real(f) > x)) return f;
    return f == std::numeric_limits<float>::infinity() ? std::numeric_limits<float>::max()
                                                       : next_float_down(f);
}

[[gnu::always_inline]] inline float rounded_up(real x) {
    return -rounded_down(-x);
}

// A ray prepared for float slab tests that bound its exact slab distances from below (where it
// enters a box) and above (where it leaves). Per axis, for the face it meets first (near) and
// last (far): the origin rounded towards the face, so the float difference face - origin is no
// larger in size than the exact one for the near face and no smaller for the far face, and
// 1 / direction in floats, made smaller in size by 4 eps for the near face and larger for the
// far face: that covers the rounding of the difference and the product (eps / 2 each) and of
// 1 / direction itself. Distances below 0 are never used (the traversal asks for t >= 0 only).
struct float_slabs {
    float8 origin_near[3], origin_far[3], inv_near[3], inv_far[3];
    int near[3], far[3];
    int octant  = 0;
    bool usable = true;  // false: a direction or origin the floats cannot bound

    explicit float_slabs(const ray& r) {
        for (int axis = 0; axis < 3; ++axis) {
            // [exercise float_slabs begin]
            constexpr real eps = std::numeric_limits<float>::epsilon();
            const real o = r.origin()[axis], inv = 1 / r.direction()[axis];
            const float smaller = float(inv * (1 - 4 * eps)), larger = float(inv * (1 + 4 * eps));
            // A tiny direction component whose inverse overflows float would make a finite
            // distance infinite; an origin beyond float's range has no float to round to.
            if (std::isnan(inv) || (std::isfinite(inv) && !std::isfinite(larger)) ||
                !(std::fabs(o) < real(std::numeric_limits<float>::max() / 2)))
                usable = false;
            const bool negative = inv < 0;
            const float up = rounded_up(o), down = rounded_down(o);
            origin_near[axis] = (float8{} + (negative ? down : up));
            origin_far[axis]  = (float8{} + (negative ? up : down));
            inv_near[axis]    = (float8{} + smaller);
            inv_far[axis]     = (float8{} + larger);
            near[axis]        = negative ? 3 + axis : axis;
            far[axis]         = negative ? axis : 3 + axis;
            octant |= negative ? 1 << axis : 0;
            // [exercise float_slabs end]
        }
    }
};

[[gnu::always_inline]] inline unsigned lane_bits(const int8& inside) {
    const auto lanes = (float8)inside;  // a vector cast keeps the bits
#if defined(__x86_64__)
    const float4 low  = __builtin_shufflevector(lanes, lanes, 0, 1, 2, 3);
    const float4 high = __builtin_shufflevector(lanes, lanes, 4, 5, 6, 7);
    return unsigned(__builtin_ia32_movmskps(low)) | unsigned(__builtin_ia32_movmskps(high)) << 4;
#else
    unsigned bits = 0;
    for (int k = 0; k < 8; ++k) bits |= unsigned(inside[k] & 1) << k;
    return bits;
#endif
}

// The eight boxes' slab test, bounding the exact one (float_slabs). A NaN distance (0 * inf: a
// ray in a face's plane) is no constraint, as in aabb::hit. The far bound is padded by float's
// smallest normal number: a product in the subnormal range is rounded by an absolute amount far
// below it, which the relative margins do not cover.
[[gnu::always_inline]] inline unsigned hit_eight(const float8 bounds[6], const float_slabs& r,
                                                 const float8& t_min_down, const float8& t_max_up,
                                                 float8& t_enter) {
    float8 t_near = t_min_down;
    float8 t_far  = t_max_up;
    for (int axis = 0; axis < 3; ++axis) {
        const float8 t0 = (bounds[r.near[axis]] - r.origin_near[axis]) * r.inv_near[axis];
        const float8 t1 = (bounds[r.far[axis]] - r.origin_far[axis]) * r.inv_far[axis];
        t_near          = t0 > t_near ? t0 : t_near;
        t_far           = t1 < t_far ? t1 : t_far;
    }
    t_enter = t_near;
    return lane_bits(t_near <= t_far + (float8{} + std::numeric_limits<float>::min()));
}

// One step down the binary tree: to the node's first (0) or second (1) child, and the node's
// split axis.
struct step {
    int side, axis;
};
using path = std::vector<step>;

// The order in which the binary tree visits the subtrees these paths lead to (from one node),
// for rays of an octant (bit k: the ray runs towards smaller coordinates on axis k): at each
// level the first child first, unless the ray runs the other way on that level's split axis. So
// a subtree's rank is its path with each side flipped so, read as a word. Entry i is the index
// of the i-th visited; equal paths (triangles of one binary leaf) keep their given order.
std::vector<std::size_t> visiting_order(const std::vector<path>& paths, int octant) {
    auto word = [&](std::size_t k) {
        std::vector<int> w;
        for (const step& st : paths[k]) w.push_back(st.side ^ (octant >> st.axis & 1));
        return w;
    };
    std::vector<std::size_t> order(paths.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t x, std::size_t y) { return word(x) < word(y); });
    return order;
}

}  // namespace

bool mesh_bvh::packs(const bvh& tree) {
    const triangle_mesh* first = nullptr;
    for (const auto& object : tree.objects()) {
        if (!object) return false;
        const hittable& shape = *object;
        if (typeid(shape) != typeid(mesh_triangle)) return false;
        const auto& t = static_cast<const mesh_triangle&>(shape);
        if (first && &t.mesh() != first) return false;
        first = &t.mesh();
    }
    return first != nullptr;
}

tree_packer mesh_bvh::packer() {
    return [](const std::shared_ptr<const bvh>& tree) -> std::shared_ptr<bounded_hittable> {
        if (!tree || !packs(*tree)) return nullptr;
        return std::make_shared<mesh_bvh>(tree);
    };
}

mesh_bvh::mesh_bvh(std::shared_ptr<const bvh> tree) : binary(std::move(tree)) {
    if (!binary || !packs(*binary))
        throw std::invalid_argument("mesh_bvh: a tree of one mesh's triangles is required");
    mesh = &static_cast<const mesh_triangle&>(*binary->objects()[0]).mesh();
    // The triangles under each binary node (a node's children come after it).
    const std::vector<bvh::node>& nodes_of = binary->nodes();
    below.resize(nodes_of.size());
    for (std::size_t i = nodes_of.size(); i-- > 0;) {
        const bvh::node& b = nodes_of[i];
        below[i]           = b.count > 0 ? b.count : below[i + 1] + below[b.offset];
    }
    root = pack(0);
    // Their room doubled as they grew; a tree is kept for as long as its scene.
    nodes.shrink_to_fit();
    leaves.shrink_to_fit();
}

// A binary subtree of up to four triangles: one leaf, tested at once. Its triangles are kept in
// the order the binary tree lists them, and, per octant of ray directions, the order in which
// it would visit them (each one's path from here, with each side flipped where the ray runs
// towards smaller coordinates on that level's split axis, as the wide nodes' order): of several
// at the same nearest t, the first visited wins, as in the binary tree.
std::uint32_t mesh_bvh::pack_leaf(std::uint32_t index) {
    const std::vector<bvh::node>& tree = binary->nodes();
    std::vector<std::uint32_t> items;  // the triangles, in the binary tree's order
    std::vector<path> paths;           // and the way to each from here
    auto collect = [&](auto&& self, std::uint32_t i, const path& to) -> void {
        const bvh::node& b = tree[i];
        if (b.count > 0) {
            for (std::uint32_t k = b.offset; k < b.offset + b.count; ++k) {
                items.push_back(static_cast<const mesh_triangle&>(*binary->objects()[k]).index());
                paths.push_back(to);
            }
            return;
        }
        path first = to, second = to;
        first.push_back({0, b.axis});
        second.push_back({1, b.axis});
        self(self, i + 1, first);
        self(self, b.offset, second);
    };
    collect(collect, index, {});
    if (items.empty() || items.size() > 4)
        throw std::logic_error("mesh_bvh: a leaf of none or more than four triangles");
    leaf packed{};
    for (int octant = 0; octant < 8; ++octant) {
        const std::vector<std::size_t> lane_of = visiting_order(paths, octant);
        for (std::size_t i = 0; i < lane_of.size(); ++i)
            packed.visit_order |= std::uint64_t(lane_of[i]) << (8 * octant + 2 * int(i));
    }
    const point3* p = mesh->data().positions.data();
    for (std::size_t lane = 0; lane < 4; ++lane) {
        const std::uint32_t triangle = items[lane < items.size() ? lane : 0];
        packed.triangle[lane]        = triangle;
        const auto& v                = mesh->triangle(triangle);
        for (int vertex = 0; vertex < 3; ++vertex)
            for (int axis = 0; axis < 3; ++axis)
                packed.corner[3 * vertex + axis][lane] = p[v[std::size_t(vertex)]][axis];
    }
    const auto first = std::uint32_t(leaves.size());
    leaves.push_back(packed);
    return leaf_bit | first << 2 | std::uint32_t(items.size() - 1);
}

std::uint32_t mesh_bvh::pack(std::uint32_t index) {
    const std::vector<bvh::node>& tree = binary->nodes();
    const bvh::node& b                 = tree[index];
    if (below[index] <= 4) return pack_leaf(index);

    // The lanes: up to eight nodes of the binary subtree below this one, none inside another, as
    // chapter 17's wide_bvh::pack chooses four: the interior lane with the largest box gives
    // way to its two children while there is room. Each keeps its path, which orders the visits.
    struct lane {
        std::uint32_t binary;
        path to;
    };
    std::vector<lane> lanes = {{index + 1, {{0, b.axis}}}, {b.offset, {{1, b.axis}}}};
    while (lanes.size() < 8) {
        int widest       = -1;
        real widest_area = 0;
        for (std::size_t k = 0; k < lanes.size(); ++k) {
            const bvh::node& c = tree[lanes[k].binary];
            if (below[lanes[k].binary] > 4 && (widest < 0 || !(c.box.half_area() <= widest_area))) {
                widest      = int(k);
                widest_area = c.box.half_area();
            }
        }
        if (widest < 0) break;
        const lane parent  = lanes[std::size_t(widest)];
        const bvh::node& c = tree[parent.binary];
        lane first = parent, second = parent;
        first.binary  = parent.binary + 1;
        second.binary = c.offset;
        first.to.push_back({0, c.axis});
        second.to.push_back({1, c.axis});
        lanes[std::size_t(widest)] = first;
        lanes.insert(lanes.begin() + widest + 1, second);
    }

    const auto here = std::uint32_t(nodes.size());
    nodes.push_back({});
    std::uint32_t child[8] = {};
    for (std::size_t k = 0; k < lanes.size(); ++k) child[k] = pack(lanes[k].binary);

    node& n = nodes[here];
    for (int axis = 0; axis < 3; ++axis)
        for (std::size_t k = 0; k < 8; ++k) {
            // Unused lanes: an empty box (lower above upper), which every ray misses.
            float lower = std::numeric_limits<float>::infinity(), upper = -lower;
            if (k < lanes.size()) {
                const interval side = tree[lanes[k].binary].box.axis_interval(axis);
                lower               = rounded_down(side.min);
                upper               = rounded_up(side.max);
            }
            n.bounds[axis][k]     = lower;
            n.bounds[3 + axis][k] = upper;
        }
    for (int k = 0; k < 8; ++k) n.child[k] = child[k];
    // Unused lanes are visited last (their empty boxes are never hit).
    std::vector<path> paths;
    paths.reserve(lanes.size());
    for (const lane& l : lanes) paths.push_back(l.to);
    for (int octant = 0; octant < 8; ++octant) {
        std::vector<std::size_t> lane_of = visiting_order(paths, octant);
        lane_of.reserve(8);
        for (std::size_t k = lanes.size(); k < 8; ++k) lane_of.push_back(k);
        std::uint32_t order = 0;
        for (std::size_t i = 0; i < 8; ++i) order |= std::uint32_t(lane_of[i]) << (3 * i);
        n.order[octant] = order;
    }
    return here;
}

// Up to four triangles as four lanes, each lane intersect_triangle's arithmetic, operation for
// operation (chapter 18's layer fuses no multiply-add), so each lane's answer is bit for bit
// the one that triangle gives alone.
[[gnu::always_inline]] inline bool mesh_bvh::hit_leaf(std::uint32_t leaf_index, int octant,
                                                      const sheared_ray& sr, interval& ray_t,
                                                      triangle_hit& nearest,
                                                      leaf_lane& nearest_at) const {
    const leaf& l             = leaves[(leaf_index & ~leaf_bit) >> 2];
    const std::uint32_t count = (leaf_index & 3u) + 1;
    // Each lane's vertex minus the origin, as intersect_triangle's vec3 subtraction, turned as
    // sheared_ray says (z along the ray's largest direction component). (Written into `out`:
    // a vector returned by value would change with the processor's vector width.)
    auto lanes = [&](int vertex, int axis, real4& out) {
        const real o = sr.origin[axis];
        out          = l.corner[3 * vertex + axis] - real4{o, o, o, o};
    };
    real4 ax, ay, az, bx, by, bz, cx, cy, cz;
    lanes(0, sr.kx, ax), lanes(0, sr.ky, ay), lanes(0, sr.kz, az);
    lanes(1, sr.kx, bx), lanes(1, sr.ky, by), lanes(1, sr.kz, bz);
    lanes(2, sr.kx, cx), lanes(2, sr.ky, cy), lanes(2, sr.kz, cz);
    const real4 x0 = ax - sr.sx * az, y0 = ay - sr.sy * az;
    const real4 x1 = bx - sr.sx * bz, y1 = by - sr.sy * bz;
    const real4 x2 = cx - sr.sx * cz, y2 = cy - sr.sy * cz;
    const real4 e0   = x1 * y2 - y1 * x2;
    const real4 e1   = x2 * y0 - y2 * x0;
    const real4 e2   = x0 * y1 - y0 * x1;
    const real4 zero = {0, 0, 0, 0};
    const auto mixed =
        ((e0 < zero) | (e1 < zero) | (e2 < zero)) & ((e0 > zero) | (e1 > zero) | (e2 > zero));
    const real4 det = e0 + e1 + e2;
    // Most leaves are passed by: no lane's edges let the ray through, and no division is needed.
    const auto through = ~mixed & (det != zero);
    if (!(through[0] | through[1] | through[2] | through[3])) return false;
    const real4 scaled_t = e0 * (sr.sz * az) + e1 * (sr.sz * bz) + e2 * (sr.sz * cz);
    const real4 inv_det  = 1 / det;
    const real4 t        = scaled_t * inv_det;
    const auto ok        = through & (t > ray_t.min) & (t < ray_t.max);
    // In the binary tree's visiting order for this ray: of equal distances, the first wins.
    const auto order = unsigned(l.visit_order >> (8 * octant));
    int chosen       = -1;
    for (std::uint32_t i = 0; i < count; ++i) {
        const unsigned j = order >> (2 * i) & 3u;
        if (ok[j] && t[j] < ray_t.max) {
            ray_t.max = t[j];
            chosen    = int(j);
        }
    }
    if (chosen < 0) return false;
    nearest    = {t[chosen], e0[chosen] * inv_det[chosen], e1[chosen] * inv_det[chosen],
                  e2[chosen] * inv_det[chosen]};
    nearest_at = {&l, int(chosen)};
    return true;
}

// The record mesh_triangle::hit fills, for the nearest hit, once: from the corners its leaf
// holds (the mesh's own, copied), which the traversal has just read.
void mesh_bvh::record(const leaf_lane& at, const triangle_hit& found, const ray& r,
                      hit_record& rec) const {
    point3 p[3];
    for (int vertex = 0; vertex < 3; ++vertex)
        p[vertex] =
            point3(at.in->corner[3 * vertex][at.lane], at.in->corner[3 * vertex + 1][at.lane],
                   at.in->corner[3 * vertex + 2][at.lane]);
    const std::uint32_t index = at.in->triangle[at.lane];
    record_triangle_hit(found, p[0], p[1], p[2], r, rec);
    mesh->shade(index, found, r, rec);
    rec.mat    = mesh->surface();
    rec.object = &mesh->faces()[index];
}

#if defined(__x86_64__)
#define RT_ALSO_FOR_AVX2 [[gnu::target_clones("avx2", "default")]]
#else
#define RT_ALSO_FOR_AVX2
#endif
RT_ALSO_FOR_AVX2 bool mesh_bvh::closest_hit(const ray& r, interval ray_t, hit_record& rec) const {
    const sheared_ray sr(r);
    triangle_hit nearest;
    leaf_lane nearest_at;
    if (root & leaf_bit) {
        int octant = 0;
        for (int axis = 0; axis < 3; ++axis) octant |= 1 / r.direction()[axis] < 0 ? 1 << axis : 0;
        if (!hit_leaf(root, octant, sr, ray_t, nearest, nearest_at)) return false;
        record(nearest_at, nearest, r, rec);
        return true;
    }
    const float_slabs fs(r);
    if (!fs.usable || !(ray_t.min >= 0)) return binary->hit(r, ray_t, rec);

    struct pending {
        std::uint32_t child;
        float t_enter;
    };
    pending stack[7 * bvh::max_depth + 1];
    int top               = 0;
    std::uint32_t current = root;
    bool hit_anything     = false;
    const float8 t_min    = (float8{} + rounded_down(ray_t.min));
    float8 t_max          = (float8{} + rounded_up(ray_t.max));
    while (true) {
        if (current & leaf_bit) {
            if (hit_leaf(current, fs.octant, sr, ray_t, nearest, nearest_at)) {
                hit_anything = true;
                t_max        = (float8{} + rounded_up(ray_t.max));
            }
        } else {
            const node& n = nodes[current];
            float8 t_enter;
            const unsigned hits = hit_eight(n.bounds, fs, t_min, t_max, t_enter);
            if ((hits & (hits - 1)) == 0 && hits != 0) {
                current = n.child[std::countr_zero(hits)];
                continue;
            }
            if (hits != 0) {
                const std::uint32_t order = n.order[fs.octant];
                for (int i = 7; i >= 0; --i) {
                    const unsigned k = order >> (3 * i) & 7u;
                    stack[top]       = {n.child[k], t_enter[k]};
                    top += int(hits >> k & 1u);
                }
                current = stack[--top].child;
                continue;
            }
        }
        do {
            if (top == 0) {
                if (hit_anything) record(nearest_at, nearest, r, rec);
                return hit_anything;
            }
            --top;
        } while (real(stack[top].t_enter) > ray_t.max);
        current = stack[top].child;
    }
}

bool mesh_bvh::hit(const ray& r, interval ray_t, hit_record& rec) const {
    return closest_hit(r, ray_t, rec);
}

}  // namespace rt
