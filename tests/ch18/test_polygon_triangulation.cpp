// Tests for polygon_triangulation.h (chapter 18): ear clipping cuts a model's polygon of n
// corners into n - 2 triangles that cover exactly the polygon, convex or concave, in any plane
// and with either winding, and keep that winding. A fan from one corner would do for a convex
// polygon only: for an L, a star, a comb or a ring drawn as a keyhole it covers the notches
// too, so each concave shape is checked to be one (its fan covers more than its area), and
// points sampled in every triangle must lie inside the polygon. Corners in a line, and the
// repeated corners of a keyhole's bridge, must not stop the clipping; a polygon whose edges
// cross must be reported (fanned), so that the loader can warn about it.
// Areas and normals are computed here in double from the corners the triangulation was given,
// so the checks hold in the float build too.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "rt/core/vec3.h"
#include "rt/models/polygon_triangulation.h"

namespace {

using rt::point3, rt::real;

struct p2 {
    double x, y;
};
using d3 = std::array<double, 3>;

d3 minus(const point3& a, const point3& b) {
    return {double(a.x()) - double(b.x()), double(a.y()) - double(b.y()),
            double(a.z()) - double(b.z())};
}
d3 cross3(const d3& a, const d3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot3(const d3& a, const d3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
double length3(const d3& a) {
    return std::sqrt(dot3(a, a));
}

// Newell's normal of the corners: twice the polygon's vector area, for any simple polygon in a
// plane (its length is twice the area).
d3 newell(const std::vector<point3>& c) {
    d3 n{0, 0, 0};
    for (std::size_t i = 0; i < c.size(); ++i) {
        const point3& a = c[i];
        const point3& b = c[(i + 1) % c.size()];
        const double ax = a.x(), ay = a.y(), az = a.z(), bx = b.x(), by = b.y(), bz = b.z();
        n[0] += (ay - by) * (az + bz);
        n[1] += (az - bz) * (ax + bx);
        n[2] += (ax - bx) * (ay + by);
    }
    return n;
}

// Twice the signed area of (a, b, c) in the plane: positive counter-clockwise.
double turn(const p2& a, const p2& b, const p2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// The shoelace area of a polygon in the plane, signed (positive counter-clockwise).
double shoelace(const std::vector<p2>& s) {
    double twice = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const p2& a = s[i];
        const p2& b = s[(i + 1) % s.size()];
        twice += a.x * b.y - b.x * a.y;
    }
    return twice / 2;
}

// The area a fan from corner 0 covers: the sum of its triangles' unsigned areas. It equals the
// polygon's area only when corner 0 sees every other corner.
double fan_area(const std::vector<p2>& s) {
    double sum = 0;
    for (std::size_t k = 1; k + 1 < s.size(); ++k) sum += std::fabs(turn(s[0], s[k], s[k + 1])) / 2;
    return sum;
}

// Whether q is inside the polygon, by the even-odd rule (edges walked there and back, as a
// keyhole's bridge, cancel out).
bool inside(const p2& q, const std::vector<p2>& s) {
    bool in = false;
    for (std::size_t i = 0, j = s.size() - 1; i < s.size(); j = i++) {
        const p2 &a = s[i], &b = s[j];
        if ((a.y > q.y) != (b.y > q.y) && q.x < (b.x - a.x) * (q.y - a.y) / (b.y - a.y) + a.x)
            in = !in;
    }
    return in;
}

// A plane to draw a polygon in: an origin and two orthonormal axes, the polygon's
// counter-clockwise side facing e1 x e2.
struct frame {
    std::string name;
    d3 origin, e1, e2;
};

d3 unit(d3 v) {
    const double l = length3(v);
    return {v[0] / l, v[1] / l, v[2] / l};
}

// A frame facing the unit normal n: e1 = unit(n x hint), e2 = n x e1, so e1 x e2 = n.
frame facing(const std::string& name, const d3& n, const d3& hint, const d3& origin) {
    const d3 u  = unit(n);
    const d3 e1 = unit(cross3(u, hint));
    return {name, origin, e1, cross3(u, e1)};
}

// Planes facing +-x, +-y and +-z, through the origin and off it, and three tilted ones: one
// with the normal's three components equal (the projection's choice of axis is a tie), one
// close to -y, one close to +x.
std::vector<frame> frames() {
    return {
        {"+z", {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
        {"-z", {0, 0, 2}, {0, 1, 0}, {1, 0, 0}},
        {"+x", {-3, 1, 0}, {0, 1, 0}, {0, 0, 1}},
        {"-x", {0, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {"+y", {1, 5, -2}, {0, 0, 1}, {1, 0, 0}},
        {"-y", {0, 0, 0}, {1, 0, 0}, {0, 0, 1}},
        facing("tilted (1, -1, 1)", {1, -1, 1}, {0, 0, 1}, {0.5, 0.25, -1}),
        facing("tilted near -y", {0.3, -0.9, 0.2}, {0, 0, 1}, {3, -2, 5}),
        facing("tilted near +x", {0.95, 0.2, -0.25}, {0, 1, 0}, {-1, 2, 0.5}),
    };
}

// The polygon s (in the frame's coordinates) as corners in space, rounded to real.
std::vector<point3> embed(const std::vector<p2>& s, const frame& f) {
    std::vector<point3> c;
    for (const p2& q : s) {
        const double x = f.origin[0] + q.x * f.e1[0] + q.y * f.e2[0];
        const double y = f.origin[1] + q.x * f.e1[1] + q.y * f.e2[1];
        const double z = f.origin[2] + q.x * f.e1[2] + q.y * f.e2[2];
        c.emplace_back(real(x), real(y), real(z));
    }
    return c;
}

std::vector<p2> reversed(std::vector<p2> s) {
    return {s.rbegin(), s.rend()};
}

// s starting at its corner k.
std::vector<p2> rotated(const std::vector<p2>& s, std::size_t k) {
    std::vector<p2> r;
    for (std::size_t i = 0; i < s.size(); ++i) r.push_back(s[(k + i) % s.size()]);
    return r;
}

// The distance from q to the segment (a, b).
double distance_to_segment(const p2& q, const p2& a, const p2& b) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double t =
        std::clamp(((q.x - a.x) * dx + (q.y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    return std::hypot(q.x - (a.x + t * dx), q.y - (a.y + t * dy));
}

// Whether q is inside the polygon or on its boundary (within `tolerance`).
bool inside_or_on(const p2& q, const std::vector<p2>& s, double tolerance) {
    if (inside(q, s)) return true;
    for (std::size_t i = 0; i < s.size(); ++i)
        if (distance_to_segment(q, s[i], s[(i + 1) % s.size()]) <= tolerance) return true;
    return false;
}

// Checks what every triangulation of a simple polygon must give: n - 2 triangles of distinct
// corners whose areas sum to the polygon's, each facing the polygon's normal, and points
// sampled in each lying inside the polygon. A triangle of no area (a needle: three corners in a
// line, up to rounding) covers nothing and faces nowhere: it must only lie within the polygon or
// on its edges. Ear clipping makes none from corners exactly in a line (the
// planes facing an axis, where the shapes' corners are exact); in a tilted plane, rounding moves
// such corners off their line by an ulp, and a needle may be cut off as an ear.
void check_cover(const std::vector<p2>& shape, const frame& f) {
    const std::vector<point3> corners = embed(shape, f);
    const rt::polygon_triangles cut   = rt::triangulate_polygon(corners);
    const d3 normal                   = newell(corners);
    const double area                 = length3(normal) / 2;
    const bool exact_plane            = f.name.size() == 2;  // "+x" ... "-z"
    INFO("plane " << f.name << ", " << shape.size() << " corners, area " << area);
    REQUIRE(std::fabs(area - std::fabs(shoelace(shape))) <= 1e-5 * area);  // the embedding
    CHECK_FALSE(cut.fanned);
    REQUIRE(cut.triangles.size() == shape.size() - 2);
    double sum  = 0;
    int against = 0, outside = 0, needles = 0;
    // Rounding moves a corner off its line by about an ulp of real at the coordinates' scale
    // (10 here): a needle's area is that times its length (at most 7), far below this.
    const double needle_area = 256 * double(std::numeric_limits<real>::epsilon()) * area;
    for (const auto& t : cut.triangles) {
        REQUIRE(t[0] < shape.size());
        REQUIRE(t[1] < shape.size());
        REQUIRE(t[2] < shape.size());
        REQUIRE(t[0] != t[1]);
        REQUIRE(t[1] != t[2]);
        REQUIRE(t[0] != t[2]);
        const d3 n =
            cross3(minus(corners[t[1]], corners[t[0]]), minus(corners[t[2]], corners[t[0]]));
        sum += length3(n) / 2;
        const bool needle = length3(n) / 2 <= needle_area;
        needles += needle;
        against += !needle && !(dot3(n, normal) > 0);
        // The centroid and a point near each corner.
        const double weights[4][3] = {
            {1.0 / 3, 1.0 / 3, 1.0 / 3}, {0.8, 0.1, 0.1}, {0.1, 0.8, 0.1}, {0.1, 0.1, 0.8}};
        for (const auto& w : weights) {
            const p2 q{w[0] * shape[t[0]].x + w[1] * shape[t[1]].x + w[2] * shape[t[2]].x,
                       w[0] * shape[t[0]].y + w[1] * shape[t[1]].y + w[2] * shape[t[2]].y};
            outside += needle ? !inside_or_on(q, shape, 1e-9) : !inside(q, shape);
        }
    }
    CHECK(against == 0);
    CHECK(outside == 0);
    if (exact_plane) CHECK(needles == 0);
    CHECK(std::fabs(sum - area) <= 1e-6 * area);
}

// Convex polygons of n corners on an ellipse, at angles spaced unevenly (no two triangles of
// the same shape) but in order, so the polygon is convex.
std::vector<p2> convex_polygon(int n) {
    const double two_pi = 6.283185307179586;
    std::vector<p2> s;
    for (int k = 0; k < n; ++k) {
        const double step = two_pi / n;
        const double a    = k * step + 0.35 * step * std::sin(1.7 * k + 0.4);
        s.push_back({2 * std::cos(a), 1.3 * std::sin(a)});
    }
    return s;
}

// An L of area 3, corner 0 at the tip of its foot, from where the notch hides the top of its
// upright.
const std::vector<p2> l_shape = {{2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 0}};

// A five-pointed star: 10 corners, tips at radius 1 and notches at 0.4, corner 0 a tip.
std::vector<p2> star() {
    const double two_pi = 6.283185307179586;
    std::vector<p2> s;
    for (int k = 0; k < 10; ++k) {
        const double r = k % 2 == 0 ? 1.0 : 0.4, a = two_pi * k / 10 + two_pi / 4;
        s.push_back({r * std::cos(a), r * std::sin(a)});
    }
    return s;
}

// A comb: a bar 7 wide and 1 high with four teeth 1 wide rising 2 above it (area 15),
// corner 0 at the bar's right end.
const std::vector<p2> comb = {{7, 0}, {7, 3}, {6, 3}, {6, 1}, {5, 1}, {5, 3}, {4, 3}, {4, 1},
                              {3, 1}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}, {0, 0}};

// A ring as one polygon: the outer circle (radius 2, 16 corners) counter-clockwise, back to its
// first corner, across a bridge to the inner circle (radius 1, 12 corners) walked clockwise, and
// back over the bridge: corners o0 o1 ... o15 o0 i0 i11 ... i1 i0, two of them repeated.
std::vector<p2> keyhole_ring() {
    const double two_pi = 6.283185307179586;
    std::vector<p2> s;
    for (int k = 0; k < 16; ++k)
        s.push_back({2 * std::cos(two_pi * k / 16), 2 * std::sin(two_pi * k / 16)});
    s.push_back(s[0]);
    s.push_back({1, 0});
    for (int k = 11; k >= 1; --k)
        s.push_back({std::cos(two_pi * k / 12), std::sin(two_pi * k / 12)});
    s.push_back({1, 0});
    return s;
}

}  // namespace

TEST_CASE(
    "triangulate_polygon: a convex polygon of 3 to 12 corners gives n - 2 triangles "
    "covering it, facing its way, in any plane and either winding",
    "[ch18]") {
    for (const frame& f : frames()) {
        for (int n = 3; n <= 12; ++n) {
            const std::vector<p2> s = convex_polygon(n);
            REQUIRE(shoelace(s) > 0);
            check_cover(s, f);
            check_cover(reversed(s), f);
        }
    }
}

TEST_CASE(
    "triangulate_polygon: the concave shapes used here are ones a fan from corner 0 "
    "would cover wrongly",
    "[ch18]") {
    // A guard for the tests below: a fan's triangles cover more than these polygons, so the
    // shapes really are concave where it matters.
    for (const auto& [name, s] : std::vector<std::pair<std::string, std::vector<p2>>>{
             {"L", l_shape}, {"star", star()}, {"comb", comb}}) {
        INFO(name);
        CHECK(shoelace(s) > 0);
        CHECK(fan_area(s) > 1.05 * shoelace(s));
    }
    CHECK(shoelace(l_shape) == 3);
    CHECK(shoelace(comb) == 15);
}

TEST_CASE(
    "triangulate_polygon: an L, a star and a comb are covered exactly, never beyond "
    "their edges, from any starting corner",
    "[ch18]") {
    for (const auto& [name, s] : std::vector<std::pair<std::string, std::vector<p2>>>{
             {"L", l_shape}, {"star", star()}, {"comb", comb}}) {
        INFO(name);
        for (const frame& f : frames()) {
            for (std::size_t k = 0; k < s.size(); ++k) {
                INFO("starting at corner " << k);
                check_cover(rotated(s, k), f);
                check_cover(reversed(rotated(s, k)), f);
            }
        }
    }
}

TEST_CASE(
    "triangulate_polygon: a ring drawn as a keyhole, corners repeated at the bridge, is "
    "covered exactly and its hole left open",
    "[ch18]") {
    const std::vector<p2> s = keyhole_ring();
    REQUIRE(s.size() == 30);
    // The ring's area: the outer 16-gon's less the inner 12-gon's (the bridge adds nothing).
    const double outer = 0.5 * 16 * 4 * std::sin(6.283185307179586 / 16);
    const double inner = 0.5 * 12 * 1 * std::sin(6.283185307179586 / 12);
    REQUIRE(std::fabs(shoelace(s) - (outer - inner)) <= 1e-12);
    CHECK(fan_area(s) > 1.05 * shoelace(s));
    CHECK_FALSE(inside({0, 0}, s));  // the hole
    CHECK(inside({1.5, 0.3}, s));
    for (const frame& f : frames()) {
        check_cover(s, f);
        check_cover(reversed(s), f);
        check_cover(rotated(s, 5), f);
        check_cover(rotated(s, 20), f);
    }
}

TEST_CASE(
    "triangulate_polygon: corners in a line along an edge do not stop the clipping, and make "
    "no triangle of zero area where they are exactly in a line",
    "[ch18]") {
    const std::vector<std::pair<std::string, std::vector<p2>>> shapes = {
        {"square with its edges' midpoints",
         {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}}},
        {"triangle with three more corners on its base",
         {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {2, 3}}},
        {"strip with corners along both long sides",
         {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {2, 1}, {1, 1}, {0, 1}}},
        {"L with a corner in the middle of every edge",
         {{0, 0},
          {1, 0},
          {2, 0},
          {2, 0.5},
          {2, 1},
          {1.5, 1},
          {1, 1},
          {1, 1.5},
          {1, 2},
          {0.5, 2},
          {0, 2},
          {0, 1}}},
    };
    for (const auto& [name, s] : shapes) {
        INFO(name);
        for (const frame& f : frames()) {
            for (std::size_t k = 0; k < s.size(); ++k) {
                INFO("starting at corner " << k);
                check_cover(rotated(s, k), f);
                check_cover(reversed(rotated(s, k)), f);
            }
        }
    }
}

TEST_CASE("triangulate_polygon: a bowtie, two of its four edges crossing, is reported as fanned",
          "[ch18]") {
    // A cut into two triangles, one of them facing backwards, is no cover of it: the result must
    // say so, for the loader to warn that the polygon is not simple.
    const std::vector<std::pair<std::string, std::vector<p2>>> bowties = {
        {"symmetric", {{0, 0}, {1, 1}, {1, 0}, {0, 1}}},
        {"one lobe larger", {{0, 0}, {2, 2}, {2, 0}, {0, 1}}},
        {"long", {{0, 0}, {3, 1}, {3, 0}, {0, 1}}},
    };
    for (const auto& [name, s] : bowties) {
        for (const frame& f : frames()) {
            INFO(name << " bowtie, plane " << f.name);
            const rt::polygon_triangles cut = rt::triangulate_polygon(embed(s, f));
            CHECK(cut.fanned);
            CHECK(cut.triangles.size() == 2);
        }
    }
}

TEST_CASE(
    "triangulate_polygon: a pentagram, each edge crossing two others, is reported as "
    "fanned",
    "[ch18]") {
    const double two_pi = 6.283185307179586;
    std::vector<p2> s;
    for (int k = 0; k < 5; ++k) {
        const double a = two_pi * (2 * k % 5) / 5;
        s.push_back({std::cos(a), std::sin(a)});
    }
    for (const frame& f : frames()) {
        INFO("plane " << f.name);
        const rt::polygon_triangles cut = rt::triangulate_polygon(embed(s, f));
        CHECK(cut.fanned);
        CHECK(cut.triangles.size() == 3);
    }
}

TEST_CASE("triangulate_polygon: a figure eight of six corners is reported as fanned", "[ch18]") {
    // A 1 x 2 rectangle and a unit square, wound opposite ways, joined where the edge
    // (1, 2)-(1, -1) crosses the edge (0, 0)-(2, 0).
    const std::vector<p2> s = {{0, 0}, {2, 0}, {2, 2}, {1, 2}, {1, -1}, {0, -1}};
    for (const frame& f : frames()) {
        INFO("plane " << f.name);
        const rt::polygon_triangles cut = rt::triangulate_polygon(embed(s, f));
        CHECK(cut.fanned);
        CHECK(cut.triangles.size() == 4);
        for (const auto& t : cut.triangles) CHECK((t[0] < 6 && t[1] < 6 && t[2] < 6));
    }
}

TEST_CASE("triangulate_polygon: fewer than three corners give no triangle", "[ch18]") {
    for (std::size_t n = 0; n < 3; ++n) {
        INFO(n << " corners");
        std::vector<point3> c;
        for (std::size_t i = 0; i < n; ++i) c.emplace_back(real(i), real(i * i), 1);
        const rt::polygon_triangles cut = rt::triangulate_polygon(c);
        CHECK(cut.triangles.empty());
        CHECK_FALSE(cut.fanned);
    }
}
