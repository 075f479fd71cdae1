#include "rt/models/polygon_triangulation.h"

#include <cmath>

#include "rt/core/exercise.h"

namespace rt {

namespace {

struct point2 {
    double x, y;
};

// Twice the signed area of (a, b, c): positive when they turn counter-clockwise.
double turn(const point2& a, const point2& b, const point2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

bool same(const point2& a, const point2& b) {
    return a.x == b.x && a.y == b.y;
}

// p strictly inside the counter-clockwise triangle (a, b, c), or on its edge: a corner there
// would be cut off with the ear. A corner at one of its vertices (a keyhole's bridge repeats
// corners) is not in the way.
bool in_the_way(const point2& p, const point2& a, const point2& b, const point2& c) {
    if (same(p, a) || same(p, b) || same(p, c)) return false;
    return turn(a, b, p) >= 0 && turn(b, c, p) >= 0 && turn(c, a, p) >= 0;
}

}  // namespace

polygon_triangles triangulate_polygon(const std::vector<point3>& corners) {
    polygon_triangles result;
    const std::size_t n = corners.size();
    if (n < 3) return result;
    // The plane the polygon faces most: Newell's normal, robust for concave polygons; the
    // corners are projected by dropping its largest coordinate.
    vec3 normal(0, 0, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const point3& a = corners[i];
        const point3& b = corners[(i + 1) % n];
        normal += vec3((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()),
                       (a.x() - b.x()) * (a.y() + b.y()));
    }
    const double ax = std::fabs(normal.x()), ay = std::fabs(normal.y()), az = std::fabs(normal.z());
    const int drop = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
    const int u = drop == 0 ? 1 : 0, v = drop == 2 ? 1 : 2;
    // Counter-clockwise in the projection: flip v when the normal points down the dropped axis.
    const double flip = normal[drop] < 0 ? -1 : 1;
    std::vector<point2> p(n);
    for (std::size_t i = 0; i < n; ++i) p[i] = {corners[i][u], flip * corners[i][v]};
    if (drop == 1) {
        // Dropping y keeps (x, z), a left-handed pair: swap the sense so that counter-clockwise
        // still means facing the normal.
        for (point2& q : p) q.y = -q.y;
    }

    // [exercise triangulate_polygon begin]
    std::vector<std::uint32_t> left(n);
    for (std::size_t i = 0; i < n; ++i) left[i] = std::uint32_t(i);
    std::size_t at = 0, misses = 0;
    while (left.size() > 3) {
        const std::size_t m   = left.size();
        const std::uint32_t a = left[(at + m - 1) % m], b = left[at % m], c = left[(at + 1) % m];
        bool ear = turn(p[a], p[b], p[c]) > 0;
        for (std::size_t k = 0; ear && k < m; ++k) {
            const std::uint32_t q = left[k];
            if (q != a && q != b && q != c && in_the_way(p[q], p[a], p[b], p[c])) ear = false;
        }
        if (ear) {
            result.triangles.push_back({a, b, c});
            left.erase(left.begin() + std::ptrdiff_t(at % m));
            misses = 0;
            continue;
        }
        at = (at + 1) % m;
        if (++misses == m) {
            // A whole round without an ear: not a simple polygon. Fan what is left.
            result.fanned = true;
            for (std::size_t k = 1; k + 1 < left.size(); ++k)
                result.triangles.push_back({left[0], left[k], left[k + 1]});
            return result;
        }
    }
    // The last three corners turn the wrong way only if the polygon crossed itself.
    if (!(turn(p[left[0]], p[left[1]], p[left[2]]) > 0)) result.fanned = true;
    result.triangles.push_back({left[0], left[1], left[2]});
    return result;
    // [exercise triangulate_polygon end]
}

}  // namespace rt
