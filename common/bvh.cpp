#include "bvh.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

namespace rt {

namespace {

constexpr int bin_count           = 12;  // SAH candidates per axis; more buys little
constexpr int max_leaf_objects    = 4;
constexpr real traversal_cost     = 1;   // relative to one object test
constexpr int max_traversal_depth = 64;  // stack size: above what build() can make
constexpr int max_sah_depth       = 40;  // below it, median splits: at most log2(n) more levels

}  // namespace

struct bvh::build_item {
    aabb box;
    point3 centroid;
    std::uint32_t object;
};

bvh::bvh(const std::vector<bounded_object>& input) {
    std::vector<build_item> items(input.size());
    for (std::size_t i = 0; i < input.size(); ++i) {
        const aabb& box = input[i].box;
        items[i]        = {box, box.centroid(), std::uint32_t(i)};
    }
    nodes.reserve(2 * input.size());
    if (!items.empty()) build(items, 0, items.size(), 1);

    // Traversal keeps pending siblings on a fixed stack: the tree must fit it (build() bounds the
    // depth by about 40 + log2(n), so this can only fail beyond ~2^23 pathological objects).
    if (depth() > max_traversal_depth)
        throw std::logic_error("bvh: tree depth " + std::to_string(depth()) + " exceeds the stack");

    objects.reserve(items.size());
    for (const auto& item : items) objects.push_back(input[item.object].object);
    for (const auto& object : objects) leaf_objects.push_back(object.get());
}

std::uint32_t bvh::build(std::vector<build_item>& items, std::size_t begin, std::size_t end,
                         int level) {
    const auto index = std::uint32_t(nodes.size());
    nodes.push_back({});
    aabb bounds, centroid_bounds;
    for (std::size_t i = begin; i < end; ++i) {
        bounds          = aabb(bounds, items[i].box);
        centroid_bounds = aabb(centroid_bounds, aabb(items[i].centroid, items[i].centroid));
    }
    const std::size_t count = end - begin;
    auto make_leaf          = [&] {
        nodes[index] = {bounds, std::uint32_t(begin), std::uint16_t(count), 0};
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
        build(items, begin, mid, level + 1);
        nodes[index] = {bounds, build(items, mid, end, level + 1), 0, std::uint8_t(axis)};
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
    // A leaf costs one test per object: keep it when no split is cheaper.
    if (count <= max_leaf_objects && best_cost >= real(count)) return make_leaf();

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
    build(items, begin, mid, level + 1);
    std::uint32_t second = build(items, mid, end, level + 1);
    nodes[index]         = {bounds, second, 0, std::uint8_t(axis)};
    return index;
}

bool bvh::hit(const ray& r, interval ray_t, hit_record& rec) const {
    if (nodes.empty()) return false;
    const vec3& d = r.direction();
    const vec3 inv_dir(1 / d.x(), 1 / d.y(), 1 / d.z());
    const bool dir_negative[3] = {inv_dir.x() < 0, inv_dir.y() < 0, inv_dir.z() < 0};

    std::uint32_t stack[max_traversal_depth];
    int top               = 0;
    std::uint32_t current = 0;
    bool hit_anything     = false;
    while (true) {
        const node& n = nodes[current];
        if (n.box.hit(r.origin(), inv_dir, ray_t)) {
            if (n.count > 0) {
                for (std::uint32_t i = n.offset; i < n.offset + n.count; ++i) {
                    if (leaf_objects[i]->hit(r, ray_t, rec)) {
                        hit_anything = true;
                        ray_t.max    = rec.t;  // only nearer hits matter from now on
                    }
                }
            } else if (dir_negative[n.axis]) {
                // The ray runs towards smaller coordinates: the second (upper) child is nearer.
                stack[top++] = current + 1;
                current      = n.offset;
                continue;
            } else {
                stack[top++] = n.offset;
                current      = current + 1;
                continue;
            }
        }
        if (top == 0) break;
        current = stack[--top];
    }
    return hit_anything;
}

// [ch14 begin]
real bvh::transmittance(const ray& r, interval ray_t) const {
    if (nodes.empty()) return 1;
    const vec3& d = r.direction();
    const vec3 inv_dir(1 / d.x(), 1 / d.y(), 1 / d.z());
    std::uint32_t stack[max_traversal_depth];
    int top               = 0;
    std::uint32_t current = 0;
    real fraction         = 1;
    while (true) {
        const node& n = nodes[current];
        if (n.box.hit(r.origin(), inv_dir, ray_t)) {
            if (n.count > 0) {
                for (std::uint32_t i = n.offset; i < n.offset + n.count; ++i) {
                    fraction *= leaf_objects[i]->transmittance(r, ray_t);
                    if (fraction == 0) return 0;
                }
            } else {
                stack[top++] = n.offset;
                current      = current + 1;
                continue;
            }
        }
        if (top == 0) break;
        current = stack[--top];
    }
    return fraction;
}
// [ch14 end]

aabb bvh::bounding_box() const {
    return nodes.empty() ? aabb() : nodes[0].box;
}

int bvh::depth() const {
    // Iterative walk with explicit depths, the same order as traversal.
    int deepest = 0;
    std::vector<std::pair<std::uint32_t, int>> pending;
    if (!nodes.empty()) pending.push_back({0, 1});
    while (!pending.empty()) {
        auto [index, level] = pending.back();
        pending.pop_back();
        deepest = std::max(deepest, level);
        if (nodes[index].count == 0) {
            pending.push_back({index + 1, level + 1});
            pending.push_back({nodes[index].offset, level + 1});
        }
    }
    return deepest;
}

}  // namespace rt
