#include "rt/accel/bvh.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <utility>

#include "rt/core/exercise.h"

namespace rt {

namespace {

constexpr int bin_count        = 12;  // SAH candidates per axis; more buys little
constexpr int max_leaf_objects = 4;
constexpr real traversal_cost  = 1;   // relative to one object test
constexpr int max_sah_depth    = 40;  // below it, median splits: at most log2(n) more levels

}  // namespace

// What build() sorts: an object's box, its centre, and where it is in the input.
struct bvh::build_item {
    aabb box;
    point3 centroid;
    std::uint32_t object;
};

bvh::bvh(const std::vector<bounded_object>& input) {
    std::vector<build_item> items(input.size());
    for (std::size_t i = 0; i < input.size(); ++i) {
        const aabb& b = input[i].box;
        items[i]      = {b, b.centroid(), std::uint32_t(i)};
    }
    tree.reserve(2 * input.size());
    if (!items.empty()) build(items, 0, items.size(), 1);
    // The leaves' objects, in the order build() left them: leaf by leaf.
    for (const build_item& item : items) leaf_objects.push_back(input[item.object].object);
    // [ch19 begin]
    given_index.reserve(items.size());
    for (const build_item& item : items) given_index.push_back(item.object);
    // [ch19 end]

    // Traversal keeps pending second children on a fixed stack: the tree must fit it (build()
    // bounds the depth by about 40 + log2(n), so this can only fail beyond ~2^23 pathological
    // objects).
    if (levels > max_depth)
        throw std::logic_error("bvh: tree depth " + std::to_string(levels) + " exceeds the stack");
}

// Makes the node for items [begin, end) at depth `level` (the root is level 1), and the nodes
// below it right after it, depth first. Returns its index.
std::uint32_t bvh::build(std::vector<build_item>& items, std::size_t begin, std::size_t end,
                         int level) {
    levels           = std::max(levels, level);
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
    auto make_interior = [&](std::size_t mid, int axis) {
        build(items, begin, mid, level + 1);
        const std::uint32_t second = build(items, mid, end, level + 1);
        tree[index]                = {bounds, second, 0, std::uint8_t(axis)};
        return index;
    };
    if (count <= 1) return make_leaf();

    // Bin the centroids along the axis where they spread most.
    const int axis        = centroid_bounds.longest_axis();
    const interval extent = centroid_bounds.axis_interval(axis);
    if (!(extent.size() > 0)) {
        // All centroids coincide: no split can separate them; halve by index if too many.
        if (count <= max_leaf_objects) return make_leaf();
        return make_interior(begin + count / 2, axis);
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

    // [exercise bvh::build begin]
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
    // sees only the two halves' boxes. Split all the way, though, a few objects end up each in a
    // box of its own, and a ray tests an object only when it crosses that object's box: about
    // one box test plus the objects whose own boxes it crosses. That is far cheaper when the
    // objects' boxes are much smaller than their union: the walls of a room, each a flat box,
    // whose union is the whole room.
    if (count <= max_leaf_objects) {
        real own_boxes = 0;
        for (std::size_t i = begin; i < end; ++i) own_boxes += items[i].box.half_area();
        const real singles = traversal_cost + own_boxes / parent_area;
        if (std::min(best_cost, singles) >= real(count)) return make_leaf();
    }

    auto first = items.begin() + std::ptrdiff_t(begin), last = items.begin() + std::ptrdiff_t(end);
    if (level < max_sah_depth && best_cost < infinity) {
        auto middle = std::partition(
            first, last, [&](const build_item& item) { return bin_of(item) < best_split; });
        return make_interior(std::size_t(middle - items.begin()), axis);
    }
    // A pathological spread (say, exponentially spaced objects) could make SAH splits peel off
    // one object at a time; deep down, split at the median to bound the depth. Also when no bin
    // split separates anything (centroids too far apart for the bin arithmetic).
    const std::size_t mid = begin + count / 2;
    std::nth_element(first, items.begin() + std::ptrdiff_t(mid), last,
                     [&](const build_item& a, const build_item& b) {
                         return a.centroid[axis] < b.centroid[axis];
                     });
    return make_interior(mid, axis);
    // [exercise bvh::build end]
}

// [ch19 begin]
std::vector<std::shared_ptr<hittable>> bvh::objects_as_given() const {
    std::vector<std::shared_ptr<hittable>> given(leaf_objects.size());
    for (std::size_t k = 0; k < leaf_objects.size(); ++k) given[given_index[k]] = leaf_objects[k];
    return given;
}
// [ch19 end]

bool bvh::hit(const ray& r, interval ray_t, hit_record& rec) const {
    // [exercise bvh::hit begin]
    if (tree.empty()) return false;
    const vec3& d = r.direction();
    const vec3 inv_dir(1 / d.x(), 1 / d.y(), 1 / d.z());
    std::uint32_t farther[max_depth];  // second children still to visit, the next on top
    int waiting           = 0;
    std::uint32_t current = 0;
    bool hit_anything     = false;
    while (true) {
        const node& n = tree[current];
        // ray_t.max is the nearest hit so far: a box that begins beyond it is skipped.
        if (n.box.hit(r.origin(), inv_dir, ray_t)) {
            if (n.count == 0) {
                // The nearer child first: the first one holds the lower coordinates on the split
                // axis, so it is nearer unless the ray runs towards lower coordinates there.
                std::uint32_t near = current + 1, far = n.offset;
                if (inv_dir[n.axis] < 0) std::swap(near, far);
                farther[waiting++] = far;
                current            = near;
                continue;
            }
            for (std::uint32_t i = n.offset; i < n.offset + n.count; ++i) {
                if (leaf_objects[i]->hit(r, ray_t, rec)) {
                    hit_anything = true;
                    ray_t.max    = rec.t;
                }
            }
        }
        if (waiting == 0) return hit_anything;
        current = farther[--waiting];
    }
    // [exercise bvh::hit end]
}

// [ch14 begin]
real bvh::transmittance(const ray& r, interval ray_t) const {
    if (tree.empty()) return 1;
    const vec3& d = r.direction();
    const vec3 inv_dir(1 / d.x(), 1 / d.y(), 1 / d.z());
    // Every node whose box the ray crosses, first child first whatever the ray's direction, so
    // that the fractions multiply in one order.
    std::uint32_t second[max_depth];
    int waiting           = 0;
    std::uint32_t current = 0;
    real fraction         = 1;
    while (true) {
        const node& n = tree[current];
        if (n.box.hit(r.origin(), inv_dir, ray_t)) {
            if (n.count == 0) {
                second[waiting++] = n.offset;
                current           = current + 1;
                continue;
            }
            for (std::uint32_t i = n.offset; i < n.offset + n.count; ++i) {
                fraction *= leaf_objects[i]->transmittance(r, ray_t);
                if (fraction == 0) return 0;
            }
        }
        if (waiting == 0) return fraction;
        current = second[--waiting];
    }
}
// [ch14 end]

}  // namespace rt
