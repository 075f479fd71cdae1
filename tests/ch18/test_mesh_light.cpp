// Tests for mesh_light.h and the light set's light_part hook (chapter 18): an emitting triangle
// mesh is ONE light, which picks a triangle by its share of the area and a uniform point on it,
// so that a point of the mesh has density 1 / A per unit area and, per solid angle from ref,
//   pdf(wi) = d^2 / (|cos theta_geometric| A).
// - choose(): on a fine uniform grid of u, each triangle is chosen exactly as often as its share
//   of the area says (to one grid step), its stretched u is the affine map of its share onto
//   [0, 1), u just below 1 stays on the mesh, and a triangle whose share rounds to nothing is
//   never chosen.
// - sample(): points on the triangle the sample names, with the material's radiance from either
//   face, and a pdf that is pdf() of the direction, the closed form above (geometric normal), and
//   light_set::pdf_of_hit of the hit; edge-on and degenerate references give no NaN or infinity.
// - Distribution, by chi-square: the points fall into every triangle's equal-area barycentric
//   cells with probability cell area / A (exact expected counts; a mesh of 2048 triangles of
//   sizes 4000 apart, a closed one seen from inside, one with tilted shading normals), and the
//   directions follow pdf() (ch14/direction_checks.h), which is the density of the directions
//   drawn even where a direction crosses the mesh twice.
// - The light set: an emitting mesh is one light, however often it is placed, none inside an
//   instance (whose hits then have pdf_of_hit 0), and pdf_of_hit of any triangle's hit is the
//   mesh light's density over the number of lights.
// - Unbiasedness (ch14/estimator_scenes.h): the MIS tracer, book 3's mixture and the path tracer
//   agree within 5 standard errors, and with a closed form where there is one (Lambert's polygon
//   formula over the triangles a floor point sees); and next-event estimation cuts the noise of a
//   small light of 20,480 triangles.
// Everything holds with float scalars too: the tolerances are stated per scalar type.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "ch03/sampling_checks.h"
#include "ch14/direction_checks.h"
#include "ch14/estimator_scenes.h"
#include "rt/core/rng.h"
#include "rt/geometry/instance.h"
#include "rt/geometry/quad.h"
#include "rt/geometry/sphere.h"
#include "rt/geometry/triangle_mesh.h"
#include "rt/integrators/mis_tracer.h"
#include "rt/integrators/mixture_tracer.h"
#include "rt/integrators/path_tracer.h"
#include "rt/lights/light_set.h"
#include "rt/lights/mesh_light.h"
#include "rt/materials/dielectric.h"
#include "rt/materials/diffuse_light.h"
#include "rt/materials/lambertian.h"
#include "rt/materials/metal.h"
#include "rt/scene/hittable_list.h"
#include "statistics.h"
#include "test_helpers.h"

namespace {

using rt::color, rt::point3, rt::real, rt::vec3;
using rt_test::direction_checks::direction_bins;
using rt_test::sampling_checks::next_sample2;
using indices = std::array<std::uint32_t, 3>;

constexpr real eps       = std::numeric_limits<real>::epsilon();
constexpr bool is_double = std::numeric_limits<real>::digits >= 53;
// Two computations of one density (the sample's, pdf()'s after hitting the mesh again, the light
// set's, the closed form in double) agree to this, relative: the point found again along the
// rounded direction moves by a few ulps.
const double pdf_tolerance = is_double ? 1e-9 : 1e-4;
// The chi-square's accepted probability of a false failure (every seed is fixed).
constexpr double alpha = 1e-3;
const rt::interval forward(0, rt::infinity);
const rt::background black = rt::background::uniform(color(0, 0, 0));
const color radiance(4, 2, 1);

std::shared_ptr<rt::material> emitter(const color& c = radiance) {
    return std::make_shared<rt::diffuse_light>(c);
}

std::shared_ptr<rt::triangle_mesh> mesh_of(rt::mesh_data data,
                                           std::shared_ptr<rt::material> mat = emitter()) {
    return std::make_shared<rt::triangle_mesh>(std::move(data), std::move(mat));
}

bool relatively_close(double a, double b, double tolerance) {
    return std::fabs(a - b) <= tolerance * std::fmax(std::fabs(a), std::fabs(b));
}

bool finite(const vec3& v) {
    return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

// ---- Geometry in double, independent of the library's arithmetic ----

struct d3 {
    double x = 0, y = 0, z = 0;
};
d3 to_d(const vec3& v) {
    return {double(v.x()), double(v.y()), double(v.z())};
}
d3 operator-(const d3& a, const d3& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
d3 operator+(const d3& a, const d3& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
d3 operator*(double s, const d3& a) {
    return {s * a.x, s * a.y, s * a.z};
}
double dot(const d3& a, const d3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
d3 cross(const d3& a, const d3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double length(const d3& a) {
    return std::sqrt(dot(a, a));
}
d3 unit(const d3& a) {
    return (1 / length(a)) * a;
}

std::array<d3, 3> corners(const rt::triangle_mesh& m, std::size_t i) {
    const indices& v = m.triangle(i);
    return {to_d(m.position(v[0])), to_d(m.position(v[1])), to_d(m.position(v[2]))};
}

double area_of(const rt::triangle_mesh& m, std::size_t i) {
    const auto p = corners(m, i);
    return 0.5 * length(cross(p[1] - p[0], p[2] - p[0]));
}

// The unit normal of triangle i's plane, by its winding.
d3 plane_normal(const rt::triangle_mesh& m, std::size_t i) {
    const auto p = corners(m, i);
    return unit(cross(p[1] - p[0], p[2] - p[0]));
}

double total_area(const rt::triangle_mesh& m) {
    double sum = 0;
    for (std::size_t i = 0; i < m.triangle_count(); ++i) sum += area_of(m, i);
    return sum;
}

// The density, per solid angle at ref, of the point p on triangle i of a mesh of total area A:
// d^2 / (|cos| A), with the cosine at the triangle's geometric normal.
double density_at(const rt::triangle_mesh& m, std::size_t i, const point3& ref, const point3& p,
                  double A) {
    const d3 to    = to_d(p) - to_d(ref);
    const double d = length(to);
    return d * d / (std::fabs(dot(plane_normal(m, i), (1 / d) * to)) * A);
}

// The integral of cos theta about the unit normal n at o over the directions that meet the
// triangle: Lambert's formula for a polygon, 1/2 |sum_k angle(v_k, v_k+1) n . unit(v_k x v_k+1)|
// with v_k the unit directions to the corners. The triangle must lie wholly above o's horizon.
double cosine_integral(const d3& o, const d3& n, const std::array<d3, 3>& p) {
    double sum = 0;
    for (int k = 0; k < 3; ++k) {
        const d3 a = unit(p[k] - o), b = unit(p[(k + 1) % 3] - o);
        const double angle = std::atan2(length(cross(a, b)), dot(a, b));
        sum += angle * dot(n, unit(cross(a, b)));
    }
    return std::fabs(sum) / 2;
}

// The same over the triangles of a convex mesh wound outwards that face o (which see it, none
// hiding another), or over all the triangles of a flat one.
double cosine_integral(const d3& o, const d3& n, const rt::mesh_data& m, bool facing_only) {
    double sum = 0;
    for (const indices& v : m.triangles) {
        const std::array<d3, 3> p = {to_d(m.positions[v[0]]), to_d(m.positions[v[1]]),
                                     to_d(m.positions[v[2]])};
        if (facing_only && dot(cross(p[1] - p[0], p[2] - p[0]), o - p[0]) <= 0) continue;
        sum += cosine_integral(o, n, p);
    }
    return sum;
}

// ---- Meshes ----

// Right triangles with legs (a, b) along x and y, each in the plane z = 0 at its own place, with
// areas ab/2; the legs are dyadic, so every area is exact in float and double alike.
// A leg of 0 asks for a triangle of area 2^-61 (legs 2^-30) near the origin: beside the others'
// total of about 100 its share is below half an ulp, so the running sum does not change.
rt::mesh_data right_triangles(const std::vector<std::pair<double, double>>& legs) {
    rt::mesh_data m;
    int placed = 0, tiny = 0;
    for (const auto& [a, b] : legs) {
        point3 at;
        real ra = real(a), rb = real(b);
        if (a == 0) {
            at = point3(0, 0, real(++tiny));
            ra = rb = real(0x1p-30);
        } else {
            at = point3(real(100 * ++placed), 0, 0);
        }
        const auto first = static_cast<std::uint32_t>(m.positions.size());
        m.positions.push_back(at);
        m.positions.push_back(at + vec3(ra, 0, 0));
        m.positions.push_back(at + vec3(0, rb, 0));
        m.triangles.push_back({first, first + 1, first + 2});
    }
    return m;
}

// A height field over an n x n grid, center + s half_u + t half_v + h(s, t) up for s, t in
// [-1, 1], whose lines crowd towards s = -1 and t = 1 (the cells' sides go from 2/n^2 to 4/n, so
// their areas from 4/n^4 to 16/n^2), with h = amplitude sin(2s + 0.3) cos(3t - 0.2). Each cell
// is cut along alternating diagonals into two right triangles wound like half_u x half_v.
// Their slopes stay below 3.7 amplitude (half_u and half_v unit and perpendicular to up), so a
// line from a point whose direction is steeper than that crosses the mesh at most once.
rt::mesh_data height_field(const point3& center, const vec3& half_u, const vec3& half_v,
                           const vec3& up, int n, double amplitude) {
    rt::mesh_data m;
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            const double a = double(i) / n, b = double(j) / n;
            const double s = -1 + 2 * a * a, t = 1 - 2 * (1 - b) * (1 - b);
            const double h = amplitude * std::sin(2 * s + 0.3) * std::cos(3 * t - 0.2);
            m.positions.push_back(center + real(s) * half_u + real(t) * half_v + real(h) * up);
        }
    }
    const auto at = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            if ((i + j) % 2 == 0) {
                m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
                m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
            } else {
                m.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
                m.triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
            }
        }
    }
    return m;
}

// The square [-1, 1]^2 of the plane z = 0 as a flat grid: the height field without height.
rt::mesh_data flat_square(int n) {
    return height_field(point3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1), n, 0);
}

// An open four-sided pyramid (a tent) over [-1, 1]^2 with its apex at height 0.8, wound upwards:
// 5 vertices, 4 triangles, every face's slope 0.8. With `tilted_normals`, vertex normals that
// lean far from the faces' own (the shading clamps them, the density must not see them).
rt::mesh_data tent(bool tilted_normals) {
    rt::mesh_data m;
    m.positions = {point3(-1, -1, 0), point3(1, -1, 0), point3(1, 1, 0), point3(-1, 1, 0),
                   point3(0, 0, real(0.8))};
    m.triangles = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
    if (tilted_normals)
        m.normals = {rt::unit_vector(vec3(1, 0.2, 0.3)), rt::unit_vector(vec3(-0.3, 1, 0.2)),
                     rt::unit_vector(vec3(0.6, -0.7, 0.4)), rt::unit_vector(vec3(-1, -0.4, 0.5)),
                     rt::unit_vector(vec3(0.9, 0.9, 0.1))};
    return m;
}

// Flips triangles so that each one's winding normal points away from center (a closed mesh
// star-shaped about it).
void wind_outwards(rt::mesh_data& m, const point3& center) {
    for (indices& v : m.triangles) {
        const d3 p0 = to_d(m.positions[v[0]]), p1 = to_d(m.positions[v[1]]),
                 p2 = to_d(m.positions[v[2]]);
        if (dot(cross(p1 - p0, p2 - p0), (1.0 / 3) * (p0 + p1 + p2) - to_d(center)) < 0)
            std::swap(v[1], v[2]);
    }
}

// The octahedron with corners center +- radius along the axes: 8 triangles wound outwards.
rt::mesh_data octahedron(const point3& center, real radius) {
    rt::mesh_data m;
    for (const vec3& a : {vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0),
                          vec3(0, 0, 1), vec3(0, 0, -1)})
        m.positions.push_back(center + radius * a);
    for (std::uint32_t x : {0u, 1u})
        for (std::uint32_t y : {2u, 3u})
            for (std::uint32_t z : {4u, 5u}) m.triangles.push_back({x, y, z});
    wind_outwards(m, center);
    return m;
}

// The icosahedron inscribed in the sphere (center, radius), each triangle cut into four
// `subdivisions` times with the new vertices pushed out onto the sphere: 20 * 4^n triangles,
// wound outwards, each vertex stored once.
rt::mesh_data icosphere(const point3& center, double radius, int subdivisions) {
    const double g    = (1 + std::sqrt(5.0)) / 2;
    std::vector<d3> u = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                         {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
    for (d3& d : u) d = unit(d);
    std::vector<indices> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                  {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                  {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                  {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (int level = 0; level < subdivisions; ++level) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
        auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            const auto key = std::minmax(a, b);
            if (auto found = midpoints.find(key); found != midpoints.end()) return found->second;
            const auto index = static_cast<std::uint32_t>(u.size());
            u.push_back(unit(u[a] + u[b]));
            midpoints.emplace(key, index);
            return index;
        };
        std::vector<indices> finer;
        for (const indices& f : faces) {
            const std::uint32_t ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]),
                                ca = midpoint(f[2], f[0]);
            finer.push_back({f[0], ab, ca});
            finer.push_back({f[1], bc, ab});
            finer.push_back({f[2], ca, bc});
            finer.push_back({ab, bc, ca});
        }
        faces = std::move(finer);
    }
    rt::mesh_data m;
    const d3 c = to_d(center);
    for (const d3& d : u) {
        const d3 p = c + radius * d;
        m.positions.push_back(point3(real(p.x), real(p.y), real(p.z)));
    }
    m.triangles = std::move(faces);
    wind_outwards(m, center);
    return m;
}

// ---- The area-cell chi-square ----

// The n^2 cells of equal area into which the lines b0, b1, b2 = k / n cut a triangle, numbered
// 0 .. n^2 - 1 by the barycentric weights (b1, b2) of a point of it.
class barycentric_cells {
  public:
    explicit barycentric_cells(int n_) : n(n_), number(std::size_t(2 * n * n), -1) {
        int next = 0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; i + j < n; ++j) {
                number[slot(i, j, false)] = next++;
                if (i + j <= n - 2) number[slot(i, j, true)] = next++;
            }
    }
    int count() const { return n * n; }
    int of(double b1, double b2) const {
        const double x = std::clamp(b1, 0.0, 1.0) * n, y = std::clamp(b2, 0.0, 1.0) * n;
        const int i = std::min(int(x), n - 1);
        const int j = std::max(0, std::min(int(y), n - 1 - i));
        // The square (i, j)'s lower-left triangle, or its upper-right one where the triangle
        // holds it.
        const bool upper = i + j <= n - 2 && (x - i) + (y - j) > 1;
        return number[slot(i, j, upper)];
    }

  private:
    std::size_t slot(int i, int j, bool upper) const {
        return std::size_t(((i * n) + j) * 2 + (upper ? 1 : 0));
    }
    int n;
    std::vector<int> number;
};

struct area_test {
    rt_test::chi_square_result chi_square;
    long long draws    = 0;
    long long refused  = 0;  // draws sample() declined
    long long off_mesh = 0;  // samples not on the triangle they name, or with a bad pdf
};

// Draws n samples of light from ref, bins each point by its triangle and its cell, and tests
// the counts against the cells' share of the mesh's area (one extra bin, expected empty, for
// refused draws). Each sample must also lie on the triangle it names, within its p_error of the
// plane, with the density d^2 / (|cos| A) of the geometric normal.
area_test test_area_cells(const rt::triangle_mesh& mesh, const rt::mesh_light& light,
                          const point3& ref, int cells_side, int n, std::uint64_t sequence) {
    const barycentric_cells cells(cells_side);
    const std::size_t per = std::size_t(cells.count()), bins = mesh.triangle_count() * per;
    std::vector<double> observed(bins + 1, 0), expected(bins + 1, 0);
    const double total = total_area(mesh);
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
        for (std::size_t c = 0; c < per; ++c)
            expected[t * per + c] = double(n) * area_of(mesh, t) / total / double(per);
    area_test result;
    result.draws = n;
    rt::pcg32 rng(sequence, 5);
    for (int k = 0; k < n; ++k) {
        rt::light_sample out;
        if (!light.sample(ref, next_sample2(rng), out)) {
            // A point drawn on an edge that rounding puts outside its own triangle's test is
            // refused (light.h allows it: the estimate stays unbiased): in float, rarely.
            ++result.refused;
            if (is_double) observed[bins] += 1;
            continue;
        }
        const auto* face = dynamic_cast<const rt::mesh_triangle*>(out.on_light.object);
        if (!face || &face->mesh() != &mesh) {
            ++result.off_mesh;
            observed[bins] += 1;
            continue;
        }
        const std::size_t t = face->index();
        const auto p        = corners(mesh, t);
        const double b1 = double(out.on_light.local.x()), b2 = double(out.on_light.local.y());
        const double slack = 16 * double(eps);
        const bool ok =
            std::fabs(dot(to_d(out.on_light.p) - p[0], plane_normal(mesh, t))) <=
                double(out.on_light.p_error) &&
            b1 >= -slack && b2 >= -slack && b1 + b2 <= 1 + slack &&
            relatively_close(double(out.pdf), density_at(mesh, t, ref, out.on_light.p, total),
                             pdf_tolerance);
        if (!ok && result.off_mesh < 3)
            UNSCOPED_INFO("sample at " << out.on_light.p << " (b1 " << b1 << ", b2 " << b2
                                       << ") of triangle " << t << ", pdf " << out.pdf
                                       << ", expected "
                                       << density_at(mesh, t, ref, out.on_light.p, total));
        result.off_mesh += !ok;
        observed[t * per + std::size_t(cells.of(b1, b2))] += 1;
    }
    // Float's rare refusals are left out of the test (no bin): the expected counts are those of
    // the draws that gave a sample.
    if (!is_double)
        for (double& e : expected) e *= double(n - result.refused) / double(n);
    result.chi_square = rt_test::chi_square_test(observed, expected, alpha);
    return result;
}

void check_area_cells(const area_test& t) {
    INFO(t.chi_square.summary << "; " << t.refused << " refused, " << t.off_mesh
                              << " off the mesh or with a wrong pdf");
    CHECK(t.chi_square.passed);
    // Double refuses none; float at most one draw in 10,000 (measured: 1 in 200,000).
    CHECK(t.refused <= (is_double ? 0 : t.draws / 10000));
    CHECK(t.off_mesh == 0);
}

// Bins about the direction from ref to the mesh's vertices' mean, wide enough (1.25 times the
// largest 1 - cos theta of a vertex) that the whole mesh lies inside them.
direction_bins bins_around(const rt::mesh_data& m, const point3& ref, int nx = 12, int nphi = 16) {
    vec3 mean(0, 0, 0);
    for (const point3& p : m.positions) mean += p;
    const vec3 axis = mean / real(m.positions.size()) - ref;
    const direction_bins probe(axis, 2, 1, 1);
    double widest = 0;
    for (const point3& p : m.positions) widest = std::fmax(widest, probe.x_of(p - ref));
    return direction_bins(axis, std::fmin(2.0, 1.25 * widest), nx, nphi);
}

rt_test::direction_checks::direction_test test_directions(const rt::mesh_light& light,
                                                          const direction_bins& bins,
                                                          const point3& ref, int n,
                                                          std::uint64_t sequence) {
    auto draw = [&](rt::pcg32& rng, vec3& wi, real& pdf) {
        rt::light_sample out;
        if (!light.sample(ref, next_sample2(rng), out)) return false;
        wi  = out.wi;
        pdf = out.pdf;
        return true;
    };
    auto pdf = [&](const vec3& wi) { return light.pdf(ref, wi); };
    return rt_test::direction_checks::test_directions(bins, draw, pdf, n, sequence,
                                                      1000 * double(eps));
}

// The verdict of ch14/direction_checks.h at this file's alpha: the chi-square's p-value, the pdf
// integrating to 1, no draw refused, every reported pdf pdf() of its direction.
void check_direction_test(const rt_test::direction_checks::direction_test& t) {
    INFO(t.summary << " (required: p-value >= " << alpha << ")");
    CHECK(t.chi_square.p_value >= alpha);
    CHECK(std::fabs(t.total - 1) <= 1e-3);
    CHECK(t.refused == 0);
    CHECK(t.mismatch == 0);
}

struct refusal_test {
    rt_test::chi_square_result chi_square;
    std::string summary;
    double covered = 0;  // pdf() integrated over all directions
};

// Draws n directions from ref, bins them about the mesh, with one more bin for the draws
// refused, and compares with n times pdf() integrated over each bin (the rest of n for the
// refused): a test of pdf() as the density of the directions drawn that also holds for a sampler
// that refuses some draws.
refusal_test test_with_refusals(const rt::light& light, const rt::mesh_data& data,
                                const point3& ref, int n, std::uint64_t sequence) {
    const direction_bins bins = bins_around(data, ref, 8, 12);
    std::vector<double> observed(std::size_t(bins.count()) + 1, 0);
    direction_bins::hints drawn(std::size_t(bins.count()));
    rt::pcg32 rng(sequence, 7);
    for (int k = 0; k < n; ++k) {
        rt::light_sample out;
        if (!light.sample(ref, next_sample2(rng), out)) {
            observed.back() += 1;
            continue;
        }
        const std::size_t b = bins.index(out.wi);
        observed[b] += 1;
        drawn[b].push_back({bins.x_of(out.wi), bins.phi_of(out.wi)});
    }
    auto pdf                            = [&](const vec3& wi) { return light.pdf(ref, wi); };
    const std::vector<double> integrals = bins.integrate(pdf, drawn);
    double covered                      = 0;
    for (double v : integrals) covered += v;
    // The integration is good to about 1e-4 (direction_checks.h): a pdf() that integrates to
    // 1 may come out a hair above it, and is then taken as 1.
    std::vector<double> expected(observed.size(), 0);
    for (std::size_t b = 0; b < integrals.size(); ++b)
        expected[b] = n * integrals[b] / std::fmax(1.0, covered);
    expected.back() = n * std::fmax(0.0, 1 - covered);
    refusal_test result{rt_test::chi_square_test(observed, expected, alpha), "", covered};
    result.summary = result.chi_square.summary + "; pdf() integrates to " +
                     std::to_string(covered) + ", " + std::to_string(observed.back() / n) +
                     " of the draws refused";
    return result;
}

// ---- Estimator scenes ----

using rt_test::estimator_scenes::test_scene;
constexpr double rho = rt_test::estimator_scenes::floor_albedo;
constexpr double pi  = rt_test::estimator_scenes::pi;

std::shared_ptr<rt::hittable_list> floor_world() {
    auto world = std::make_shared<rt::hittable_list>();
    world->add(rt_test::estimator_scenes::floor_quad());
    return world;
}

// What the floor at the origin sends up, lit by Le over directions whose cosines integrate to
// `cosines`: rho / pi Le cosines (one bounce: the floor cannot see itself).
double floor_radiance(double Le, double cosines) {
    return rho / pi * Le * cosines;
}

const d3 floor_point{0, 0, 0}, floor_up{0, 1, 0};

// The square of half-side 1 at height 1 of estimator_scenes' quad light, as two triangles.
rt::mesh_data square_of_two_triangles() {
    rt::mesh_data m;
    m.positions = {point3(-1, 1, -1), point3(1, 1, -1), point3(1, 1, 1), point3(-1, 1, 1)};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    return m;
}

test_scene floor_scene(const std::string& name, std::shared_ptr<rt::hittable_list> world,
                       double expected) {
    return {name, world, black, point3(3, 0.4, 0), point3(0, 0, 0), 0, 5, expected};
}

struct three_runs {
    rt_test::estimator_scenes::run path, mixture, mis;
};

three_runs run_all(const test_scene& sc, std::uint64_t seed, int n_path = 40000,
                   int n_mixture = 20000, int n_mis = 40000) {
    using rt_test::estimator_scenes::estimate;
    return {estimate(rt::path_tracer(sc.world, sc.sky), sc, n_path, seed),
            estimate(rt::mixture_tracer(sc.world, sc.sky), sc, n_mixture, seed + 1),
            estimate(rt::mis_tracer(sc.world, sc.sky), sc, n_mis, seed + 2)};
}

void check_all(const three_runs& r, const test_scene& sc) {
    using rt_test::estimator_scenes::check_run, rt_test::estimator_scenes::check_same_mean;
    INFO(sc.name);
    {
        INFO("path tracer");
        check_run(r.path, sc);
    }
    {
        INFO("mixture");
        check_run(r.mixture, sc);
    }
    {
        INFO("mis");
        check_run(r.mis, sc);
    }
    {
        INFO("mis against the path tracer");
        check_same_mean(r.mis, r.path);
    }
    {
        INFO("mixture against the path tracer");
        check_same_mean(r.mixture, r.path);
    }
}

}  // namespace

// ---- choose() ----

TEST_CASE(
    "mesh_light: a uniform grid of u chooses each triangle by its share of the area, "
    "and stretches u affinely over that share",
    "[ch18]") {
    // Areas 1/2, 64, (zero share), 1/128, 3, 10, 1/64, (zero share), 20, 1/4: ratios up to 8192.
    auto mesh = mesh_of(right_triangles({{1, 1},
                                         {16, 8},
                                         {0, 0},
                                         {0.125, 0.125},
                                         {2, 3},
                                         {4, 5},
                                         {0.25, 0.125},
                                         {0, 0},
                                         {8, 5},
                                         {1, 0.5}}));
    REQUIRE(mesh->triangle_count() == 10);
    rt::mesh_light light(*mesh);
    // The running sums of the areas, in double, as the shares are: the tiny triangles' shares
    // vanish in them.
    std::vector<double> before(mesh->triangle_count()), share(mesh->triangle_count());
    double sum = 0;
    for (std::size_t i = 0; i < mesh->triangle_count(); ++i) {
        before[i] = sum;
        sum += area_of(*mesh, i);
        share[i] = sum - before[i];
    }
    REQUIRE(share[2] == 0);
    REQUIRE(share[7] == 0);
    CHECK(double(light.area()) == Approx(sum).epsilon(1e-6));

    // u = k / N exactly, in float too (N = 2^20).
    const std::uint32_t N = 1u << 20;
    std::vector<long long> chosen(mesh->triangle_count(), 0);
    long long outside = 0, off_map = 0;
    for (std::uint32_t k = 0; k < N; ++k) {
        const real u        = real(k) * real(0x1p-20);
        real stretched      = u;
        const std::size_t i = light.choose(stretched);
        if (i >= mesh->triangle_count()) {
            ++outside;
            continue;
        }
        ++chosen[i];
        // The affine map of the triangle's share [before, before + share) onto [0, 1).
        const double exact     = share[i] > 0 ? (double(u) * sum - before[i]) / share[i] : 0;
        const double tolerance = 2 * double(eps) + 64 * 0x1p-53 * sum / std::fmax(share[i], 1e-300);
        const bool ok =
            stretched >= 0 && stretched < 1 && std::fabs(double(stretched) - exact) <= tolerance;
        if (!ok && off_map < 3)
            UNSCOPED_INFO("u " << u << " chose " << i << " and became " << stretched << ", not "
                               << exact);
        off_map += !ok;
    }
    CHECK(outside == 0);
    CHECK(off_map == 0);
    for (std::size_t i = 0; i < mesh->triangle_count(); ++i) {
        INFO("triangle " << i << " of area " << area_of(*mesh, i) << ": chosen " << chosen[i]
                         << " times of " << N << ", expected " << N * share[i] / sum);
        CHECK(std::fabs(double(chosen[i]) - N * share[i] / sum) <= 1 + 1e-9);
    }
    CHECK(chosen[2] == 0);
    CHECK(chosen[7] == 0);
}

TEST_CASE("mesh_light: u just below 1 chooses the last triangle with a share, and stays below 1",
          "[ch18][hardcase]") {
    const real below_one = std::nextafter(real(1), real(0));
    // The last triangle has a share; then it has none (a tiny one after it), then the mesh is
    // one triangle (u unchanged but for rounding).
    auto ordinary  = mesh_of(right_triangles({{1, 1}, {0.125, 0.125}, {4, 2}, {0.0625, 0.125}}));
    auto tiny_last = mesh_of(right_triangles({{1, 1}, {4, 2}, {0.0625, 0.125}, {0, 0}}));
    auto single    = mesh_of(right_triangles({{2, 3}}));
    struct probe {
        const rt::triangle_mesh* mesh;
        std::size_t last_with_share;
    };
    for (const probe& pr :
         {probe{ordinary.get(), 3}, probe{tiny_last.get(), 2}, probe{single.get(), 0}}) {
        rt::mesh_light light(*pr.mesh);
        INFO(pr.mesh->triangle_count() << " triangles");
        for (real u : {below_one, std::nextafter(below_one, real(0)), real(1) - 16 * eps}) {
            real stretched      = u;
            const std::size_t i = light.choose(stretched);
            INFO("u = 1 - " << 1 - double(u) << ": triangle " << i << ", stretched to 1 - "
                            << 1 - double(stretched));
            CHECK(i == pr.last_with_share);
            CHECK(stretched >= 0);
            CHECK(stretched < 1);
        }
        real zero = 0;
        CHECK(light.choose(zero) == 0);
        CHECK(zero == 0);
    }
    // Random u never choose a triangle without a share.
    rt::mesh_light light(*tiny_last);
    rt::pcg32 rng(3, 9);
    long long tiny = 0;
    for (int k = 0; k < 100000; ++k) {
        real u = rng.uniform();
        tiny += light.choose(u) == 3;
    }
    CHECK(tiny == 0);
}

// ---- sample() ----

TEST_CASE(
    "mesh_light: a sample lies on its triangle, has pdf() of its direction, the light "
    "set's pdf_of_hit and the material's radiance, from either face",
    "[ch18]") {
    // A height field of 512 triangles of areas 1000 apart, slopes below 0.45: every reference
    // below sees it along directions steeper than that, so each direction meets it once.
    auto mesh = mesh_of(
        height_field(point3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1), 16, 0.12));
    rt::mesh_light light(*mesh);
    const double A = total_area(*mesh);
    auto world     = std::make_shared<rt::hittable_list>();
    world->add(rt::mesh_object(mesh));
    rt::light_set lights(*world, black);
    REQUIRE(lights.size() == 1);

    const point3 refs[] = {point3(0.3, -0.2, 2.5), point3(-0.4, 0.6, 1.2), point3(0.5, 0.5, -1.8),
                           point3(-0.1, -0.3, -0.9)};
    rt::pcg32 rng(17, 1);
    long long wrong = 0, front = 0, back = 0;
    for (const point3& ref : refs) {
        for (int k = 0; k < 5000; ++k) {
            rt::light_sample out;
            REQUIRE(light.sample(ref, next_sample2(rng), out));
            const auto* face = dynamic_cast<const rt::mesh_triangle*>(out.on_light.object);
            REQUIRE(face != nullptr);
            REQUIRE(&face->mesh() == mesh.get());
            const std::size_t t = face->index();
            const auto p        = corners(*mesh, t);
            const d3 to         = to_d(out.on_light.p) - to_d(ref);
            const double b1 = double(out.on_light.local.x()), b2 = double(out.on_light.local.y());
            const double slack = 16 * double(eps);
            rt::hit_record rec;
            const bool hit_again = world->hit(rt::ray(ref, out.wi), forward, rec);
            const double again   = double(light.pdf(ref, out.wi));
            const double by_set  = hit_again ? double(lights.pdf_of_hit(ref, out.wi, rec)) : 0;
            const bool ok =
                !out.at_infinity && rt_test::exactly(out.radiance, radiance) &&
                // On the triangle's plane and inside it.
                std::fabs(dot(to_d(out.on_light.p) - p[0], plane_normal(*mesh, t))) <=
                    double(out.on_light.p_error) &&
                b1 >= -slack && b2 >= -slack && b1 + b2 <= 1 + slack &&
                // wi is the unit direction to it, and the point's normal faces ref.
                std::fabs(double(out.wi.length()) - 1) <= 8 * double(eps) &&
                length(to_d(out.wi) - unit(to)) <= 16 * double(eps) &&
                dot(out.on_light.normal, out.wi) < 0 &&
                // One density four ways: the sample's, pdf()'s, the light set's, the formula.
                relatively_close(double(out.pdf), again, pdf_tolerance) &&
                relatively_close(double(out.pdf), by_set, pdf_tolerance) &&
                relatively_close(double(out.pdf), density_at(*mesh, t, ref, out.on_light.p, A),
                                 pdf_tolerance);
            if (!ok && wrong < 3)
                UNSCOPED_INFO("ref " << ref << ": sample at " << out.on_light.p << " of triangle "
                                     << t << " (b1 " << b1 << ", b2 " << b2 << "), radiance "
                                     << out.radiance << ", pdf " << out.pdf << ", pdf() " << again
                                     << ", pdf_of_hit " << by_set << ", formula "
                                     << density_at(*mesh, t, ref, out.on_light.p, A));
            wrong += !ok;
            (out.on_light.front_face ? front : back) += 1;
        }
    }
    CHECK(wrong == 0);
    // Seen from above the winding's face, from below the other: both emit.
    CHECK(front == 10000);
    CHECK(back == 10000);
}

TEST_CASE(
    "mesh_light: seen edge-on, from a triangle's plane, edge or corner, a sample is "
    "refused or finite, and pdf() is finite",
    "[ch18][hardcase]") {
    // A flat square of 8 triangles in z = 0 over [-1, 1]^2, and a tent whose faces slope; refs in
    // their planes (outside, on an edge, on a corner, on a shared diagonal, inside), a hair off
    // them, and a denormal whisker above: |cos| is 0 or nearly, d^2 / (|cos| A) would overflow.
    // Samples must be refused, or carry a finite direction, point, radiance and positive pdf;
    // pdf() must be finite and not negative.
    const real tiny = real(1e-12), whisker = 1000 * std::numeric_limits<real>::denorm_min();
    struct setting {
        rt::mesh_data data;
        std::vector<point3> refs;
    };
    const std::vector<setting> settings = {
        {flat_square(2),
         {point3(3, 0, 0), point3(1, 0, 0), point3(1, 1, 0), point3(0, 0, 0), point3(-1, -1, 0),
          point3(0.5, 0.5, 0), point3(3, 0, tiny), point3(1, 0, eps), point3(0, 0.5, -eps),
          point3(1e8, 0, 1e8), point3(1.5, 0.2, whisker), point3(-3, -2, -whisker)}},
        // The tent's face (0, 1, 4) lies in the plane through (-1, -1, 0), (1, -1, 0) and the
        // apex: y = -1 + z / 0.8; a ref beyond its edge in that plane, the apex, a base corner.
        {tent(false),
         {point3(0, -2, real(-0.8)), point3(3, -1, 0), point3(0, 0, real(0.8)), point3(1, -1, 0),
          point3(0, -0.5, real(0.4)), point3(0, 0, real(0.8) + eps), point3(-1, -1, -whisker)}}};
    rt::pcg32 rng(13, 4);
    long long bad_samples = 0, bad_pdfs = 0, refused = 0, drawn = 0;
    for (const setting& s : settings) {
        auto mesh = mesh_of(s.data);
        rt::mesh_light light(*mesh);
        for (const point3& ref : s.refs) {
            auto check_pdf = [&](const vec3& wi) {
                const real p = light.pdf(ref, wi);
                if (!(std::isfinite(p) && p >= 0)) {
                    if (bad_pdfs < 3)
                        UNSCOPED_INFO("ref " << ref << ", wi " << wi << ": pdf " << p);
                    ++bad_pdfs;
                }
            };
            rt_test::sampling_checks::for_edge_and_random_samples([&](rt::sample2 u) {
                rt::light_sample out;
                if (!light.sample(ref, u, out)) {
                    ++refused;
                    return;
                }
                ++drawn;
                const bool ok = finite(out.wi) && std::isfinite(out.pdf) && out.pdf > 0 &&
                                finite(out.radiance) && finite(out.on_light.p) &&
                                finite(out.on_light.normal);
                if (!ok && bad_samples < 3)
                    UNSCOPED_INFO("ref " << ref << ", u " << u.u << " " << u.v << ": wi " << out.wi
                                         << ", pdf " << out.pdf);
                bad_samples += !ok;
                check_pdf(out.wi);
            });
            for (int k = 0; k < 2000; ++k) check_pdf(rt_test::random_unit(rng));
            for (const point3& corner : s.data.positions)
                if ((corner - ref).length_squared() > 0) check_pdf(rt::unit_vector(corner - ref));
            check_pdf(vec3(1, 0, 0));
            check_pdf(vec3(0, -1, 0));
        }
    }
    INFO(drawn << " samples drawn, " << refused << " refused");
    CHECK(bad_samples == 0);
    CHECK(bad_pdfs == 0);
    CHECK(drawn > 0);
}

// ---- Distribution ----

TEST_CASE(
    "mesh_light: sampled points fill each triangle's equal-area cells with probability "
    "cell area / A",
    "[ch18]") {
    SECTION("triangles of areas 8192 apart, 16 cells each") {
        auto mesh = mesh_of(right_triangles(
            {{1, 1}, {16, 8}, {0.125, 0.125}, {2, 3}, {4, 5}, {0.25, 0.125}, {8, 5}, {1, 0.5}}));
        rt::mesh_light light(*mesh);
        check_area_cells(test_area_cells(*mesh, light, point3(0.37, -3.1, 7.3), 4, 200000, 31));
    }
    SECTION("a height field of 2048 triangles of areas 4000 apart, 4 cells each") {
        auto mesh = mesh_of(
            height_field(point3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1), 32, 0.12));
        REQUIRE(mesh->triangle_count() == 2048);
        rt::mesh_light light(*mesh);
        check_area_cells(test_area_cells(*mesh, light, point3(0.2, 0.1, 3), 2, 300000, 32));
    }
    SECTION("a closed icosphere of 320 triangles, from inside, 16 cells each") {
        auto mesh = mesh_of(icosphere(point3(0.5, -0.2, 1), 1.5, 2));
        rt::mesh_light light(*mesh);
        check_area_cells(test_area_cells(*mesh, light, point3(0.7, 0.1, 0.8), 4, 200000, 33));
    }
    SECTION("a tent with tilted shading normals, 16 cells each") {
        auto mesh = mesh_of(tent(true));
        REQUIRE(mesh->has_normals());
        rt::mesh_light light(*mesh);
        check_area_cells(test_area_cells(*mesh, light, point3(0.2, -0.1, 2.5), 4, 50000, 34));
    }
}

TEST_CASE(
    "mesh_light: directions follow pdf(), which integrates to 1 and takes the geometric "
    "normal, not the shading one",
    "[ch18]") {
    // A tent whose vertex normals lean far from its faces: the shading normal of a hit is not the
    // plane's, and a density taken at it would not be the density of the directions drawn.
    // Each reference sees every face along directions steeper than the faces' slope (0.8), so
    // no direction meets the mesh twice; below, it sees the tent's inside.
    auto shaded = mesh_of(tent(true));
    rt::mesh_light light(*shaded);
    std::uint64_t sequence = 40;
    for (const point3& ref : {point3(0.2, -0.1, 2.5), point3(0.5, 0.6, 3.2), point3(0, 0, -0.4)}) {
        INFO("tent, ref " << ref);
        check_direction_test(
            test_directions(light, bins_around(shaded->data(), ref), ref, 100000, sequence++));
        // The shading normals do differ from the faces' own where the samples land: their
        // cosine with the direction is more than 10 % off for most of them.
        rt::pcg32 rng(sequence, 8);
        int differ = 0;
        for (int k = 0; k < 1000; ++k) {
            rt::light_sample out;
            REQUIRE(light.sample(ref, next_sample2(rng), out));
            const auto* face = dynamic_cast<const rt::mesh_triangle*>(out.on_light.object);
            REQUIRE(face != nullptr);
            const double geometric =
                std::fabs(dot(plane_normal(*shaded, face->index()), to_d(out.wi)));
            const double shading = std::fabs(double(dot(out.on_light.normal, out.wi)));
            differ += std::fabs(shading / geometric - 1) > 0.1;
        }
        CHECK(differ > 500);
    }
    // A small height field: 18 triangles, each at its own slant, from above and below.
    auto field = mesh_of(
        height_field(point3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1), 3, 0.12));
    rt::mesh_light field_light(*field);
    for (const point3& ref : {point3(0.1, 0.2, 1.6), point3(-0.5, 0.3, -2)}) {
        INFO("height field, ref " << ref);
        check_direction_test(
            test_directions(field_light, bins_around(field->data(), ref), ref, 60000, sequence++));
    }
}

TEST_CASE(
    "mesh_light: pdf() is the density of the directions drawn also where a direction "
    "crosses the mesh twice",
    "[ch18]") {
    // A closed octahedron seen from outside: every direction that meets it crosses it twice,
    // and sample() picks points of the far side as often as their area says. light.h asks pdf()
    // to be the density of the directions sample() draws (book 3's mixture divides by it, and
    // its scattered ray goes on to the NEAR side whichever point was picked), so over the
    // directions it must add up to the fraction of draws that are not refused: either pdf()
    // counts both crossings, or sample() refuses a point the mesh itself hides.
    // The test bins the directions drawn, with one more bin for the draws refused, and compares
    // with n times pdf() integrated over each bin (the rest for the refused).
    auto mesh = mesh_of(octahedron(point3(0, 0, 0), 1));
    rt::mesh_light light(*mesh);
    std::uint64_t sequence = 60;
    for (const point3& ref : {point3(2.5, 1.7, 1.3), point3(-0.4, -3, 0.5)}) {
        INFO("ref " << ref);
        const auto result = test_with_refusals(light, mesh->data(), ref, 60000, sequence++);
        INFO(result.summary);
        CHECK(result.chi_square.passed);
        CHECK(result.covered <= 1 + 1e-3);
    }
}

// ---- The light set ----

TEST_CASE(
    "light_set: an emitting mesh of 2048 triangles is one light, and a hit on any of "
    "them has the mesh light's pdf_at over the number of lights",
    "[ch18]") {
    auto mesh = mesh_of(
        height_field(point3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1), 32, 0.12));
    REQUIRE(mesh->triangle_count() == 2048);
    // Besides it: a quad light to the side, and a tent that does not emit, below.
    rt::mesh_data below = tent(false);
    for (point3& p : below.positions) p += vec3(0, 0, -2);
    auto dull  = mesh_of(below, std::make_shared<rt::lambertian>(color(0.5, 0.5, 0.5)));
    auto world = std::make_shared<rt::hittable_list>();
    world->add(rt::mesh_object(mesh));
    world->add(
        std::make_shared<rt::quad>(point3(4, -1, 0), vec3(0, 2, 0), vec3(0, 0, 2), emitter()));
    world->add(rt::mesh_object(dull));
    rt::light_set lights(*world, black);
    CHECK(lights.size() == 2);
    rt::mesh_light own(*mesh);
    const double A = total_area(*mesh);

    // Aim from above at a random point of every triangle in turn (a margin from its edges).
    const point3 ref(0.2, -0.3, 2.5);
    rt::pcg32 rng(71, 3);
    long long wrong = 0, missed = 0;
    for (std::size_t t = 0; t < mesh->triangle_count(); ++t) {
        const auto p = corners(*mesh, t);
        double a = 0.05 + 0.9 * double(rng.uniform()), b = 0.05 + 0.9 * double(rng.uniform());
        if (a + b > 1) {
            a = 1 - a;
            b = 1 - b;
        }
        const d3 target = (1 - a - b) * p[0] + a * p[1] + b * p[2];
        const d3 to     = target - to_d(ref);
        const vec3 wi   = rt::unit_vector(vec3(real(to.x), real(to.y), real(to.z)));
        rt::hit_record rec;
        if (!world->hit(rt::ray(ref, wi), forward, rec) || rec.object != &mesh->faces()[t]) {
            ++missed;
            continue;
        }
        const double by_hit  = double(lights.pdf_of_hit(ref, wi, rec));
        const double by_mesh = double(own.pdf_at(ref, wi, rec));
        const bool ok =
            by_mesh > 0 && relatively_close(by_hit, by_mesh / 2, pdf_tolerance) &&
            relatively_close(by_hit, double(lights.pdf(ref, wi)), pdf_tolerance) &&
            relatively_close(by_mesh, density_at(*mesh, t, ref, rec.p, A), pdf_tolerance);
        if (!ok && wrong < 3)
            UNSCOPED_INFO("triangle " << t << ": pdf_of_hit " << by_hit << ", pdf_at " << by_mesh
                                      << ", set's pdf() " << lights.pdf(ref, wi) << ", formula "
                                      << density_at(*mesh, t, ref, rec.p, A));
        wrong += !ok;
    }
    CHECK(missed == 0);
    CHECK(wrong == 0);

    // The set's samples, of either light, report pdf_of_hit of the point their direction meets.
    long long differ = 0, of_mesh = 0;
    for (int k = 0; k < 4000; ++k) {
        rt::light_sample out;
        const real pick = rng.uniform();
        REQUIRE(lights.sample(ref, pick, next_sample2(rng), out));
        rt::hit_record rec;
        REQUIRE(world->hit(rt::ray(ref, out.wi), forward, rec));
        of_mesh += dynamic_cast<const rt::mesh_triangle*>(rec.object) != nullptr;
        differ += !relatively_close(double(lights.pdf_of_hit(ref, out.wi, rec)), double(out.pdf),
                                    pdf_tolerance);
    }
    CHECK(differ == 0);
    CHECK(of_mesh > 1800);
    CHECK(of_mesh < 2200);

    // The dull mesh's hits are no light's.
    rt::hit_record rec;
    REQUIRE(world->hit(rt::ray(point3(0, 0, -3), vec3(0, 0, 1)), forward, rec));
    REQUIRE(rec.mat == dull->surface());
    CHECK(lights.pdf_of_hit(point3(0, 0, -3), vec3(0, 0, 1), rec) == 0);
}

TEST_CASE(
    "light_set: a mesh placed twice is one light, one inside an instance is none (its hits' "
    "pdf_of_hit is 0), and a mesh that does not emit is none",
    "[ch18]") {
    auto mesh = mesh_of(
        height_field(point3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1), 8, 0.12));
    const point3 above(0.1, 0.2, 2.5);
    const vec3 down(0, 0, -1);
    rt::mesh_light own(*mesh);

    SECTION("two mesh_objects of one triangle_mesh") {
        auto world = std::make_shared<rt::hittable_list>();
        world->add(rt::mesh_object(mesh));
        world->add(rt::mesh_object(mesh));
        rt::light_set lights(*world, black);
        CHECK(lights.size() == 1);
        rt::hit_record rec;
        REQUIRE(world->hit(rt::ray(above, down), forward, rec));
        CHECK(double(lights.pdf_of_hit(above, down, rec)) ==
              Approx(double(own.pdf_at(above, down, rec))).epsilon(pdf_tolerance));
        CHECK(lights.pdf_of_hit(above, down, rec) > 0);
    }
    SECTION("inside a translate, beside a quad light") {
        auto world = std::make_shared<rt::hittable_list>();
        world->add(std::make_shared<rt::translate>(rt::mesh_object(mesh), vec3(0, 0, -1)));
        world->add(
            std::make_shared<rt::quad>(point3(4, -1, 0), vec3(0, 2, 0), vec3(0, 0, 2), emitter()));
        rt::light_set lights(*world, black);
        CHECK(lights.size() == 1);  // the quad
        rt::hit_record rec;
        REQUIRE(world->hit(rt::ray(above, down), forward, rec));
        CHECK(dynamic_cast<const rt::mesh_triangle*>(rec.object) != nullptr);
        CHECK(rec.p.z() < 0);  // the translated copy
        CHECK(lights.pdf_of_hit(above, down, rec) == 0);
        CHECK(lights.pdf(above, down) == 0);
    }
    SECTION("placed directly and, the same mesh_object, through a translate") {
        // The copy's hits name the same triangles (rec.object is the shape), but it is not
        // where the light stands: pdf_of_hit 0 for it, the light's density for the mesh itself.
        auto object = rt::mesh_object(mesh);
        auto world  = std::make_shared<rt::hittable_list>();
        world->add(object);
        world->add(std::make_shared<rt::translate>(object, vec3(0, 0, -5)));
        rt::light_set lights(*world, black);
        CHECK(lights.size() == 1);
        const point3 between(0.1, 0.2, -2.5);
        rt::hit_record rec;
        REQUIRE(world->hit(rt::ray(between, -down), forward, rec));
        CHECK(lights.pdf_of_hit(between, -down, rec) > 0);
        CHECK(double(lights.pdf_of_hit(between, -down, rec)) ==
              Approx(double(own.pdf_at(between, -down, rec))).epsilon(pdf_tolerance));
        REQUIRE(world->hit(rt::ray(between, down), forward, rec));
        CHECK(rec.p.z() < -4);
        CHECK(dynamic_cast<const rt::mesh_triangle*>(rec.object) != nullptr);
        CHECK(lights.pdf_of_hit(between, down, rec) == 0);
    }
    SECTION("a mesh of a material that does not emit, and an emitting one turned by rotate") {
        auto dull  = mesh_of(tent(false), std::make_shared<rt::lambertian>(color(0.5, 0.5, 0.5)));
        auto world = std::make_shared<rt::hittable_list>();
        world->add(rt::mesh_object(dull));
        world->add(std::make_shared<rt::rotate>(rt::mesh_object(mesh), rt::axis::y, 30));
        rt::light_set lights(*world, black);
        CHECK(lights.empty());
        rt::hit_record rec;
        REQUIRE(world->hit(rt::ray(point3(0.1, 0.2, -3), -down), forward, rec));
        CHECK(lights.pdf_of_hit(point3(0.1, 0.2, -3), -down, rec) == 0);
    }
}

// ---- Unbiasedness ----

TEST_CASE(
    "mesh_light: under a square of two emitting triangles, MIS, the mixture and the path "
    "tracer give the square light's closed form",
    "[ch18]") {
    const rt::mesh_data square = square_of_two_triangles();
    // The closed form of estimator_scenes' quad light of the same size and place; Lambert's
    // formula over the two triangles must say the same (a check of the helper used below).
    const test_scene as_quad = rt_test::estimator_scenes::quad_light_over_floor();
    const double cosines     = cosine_integral(floor_point, floor_up, square, false);
    REQUIRE(floor_radiance(rt_test::estimator_scenes::light_radiance, cosines) ==
            Approx(as_quad.expected).epsilon(1e-12));

    auto world = floor_world();
    world->add(rt::mesh_object(square, rt_test::estimator_scenes::lamp()));
    const test_scene sc =
        floor_scene("a square of two triangles over a floor", world, as_quad.expected);
    check_all(run_all(sc, 800), sc);
}

TEST_CASE(
    "mesh_light: under an emitting icosphere, MIS, the mixture and the path tracer give "
    "the closed form of the faces the floor sees",
    "[ch18]") {
    // 320 triangles inscribed in the sphere of radius 1 whose center is 2 above the floor point:
    // the closed form sums Lambert's formula over the triangles that face it (a convex mesh).
    // Every light-sampled direction towards it crosses it twice, and the scattered ray finds the
    // near crossing whichever point was picked: book 3's mixture weighs the direction by
    // light_set::pdf(), which must then be the density of the direction (both crossings counted,
    // or hidden points refused by sample()); MIS weighs the point, by pdf_at.
    const rt::mesh_data ball = icosphere(point3(0, 2, 0), 1, 2);
    const double Le          = rt_test::estimator_scenes::light_radiance;
    auto world               = floor_world();
    world->add(rt::mesh_object(ball, rt_test::estimator_scenes::lamp(Le)));
    const test_scene sc =
        floor_scene("an icosphere light over a floor", world,
                    floor_radiance(Le, cosine_integral(floor_point, floor_up, ball, true)));
    // Just below the sphere's own rho Le R^2 / h^2 (the inscribed mesh is a little smaller).
    CHECK(sc.expected < rho * Le / 4);
    CHECK(sc.expected > 0.98 * rho * Le / 4);
    check_all(run_all(sc, 810), sc);
}

TEST_CASE("mesh_light: seen through glass, MIS, the mixture and the path tracer agree", "[ch18]") {
    // estimator_scenes' glass and metal spheres on a floor, under a slanted height field of 72
    // triangles instead of its quad: light reaches the floor through the glass only by sampling.
    auto world = floor_world();
    world->add(rt::mesh_object(height_field(point3(0, 2.5, 0), vec3(0.75, 0, 0), vec3(0, 0.2, 0.73),
                                            vec3(0, 0.96, -0.27), 6, 0.05),
                               rt_test::estimator_scenes::lamp(6)));
    world->add(std::make_shared<rt::sphere>(point3(0, 0.6, 0), real(0.5),
                                            std::make_shared<rt::dielectric>(real(1.5))));
    world->add(
        std::make_shared<rt::sphere>(point3(1.2, 0.5, 0.2), real(0.4),
                                     std::make_shared<rt::metal>(color(0.8, 0.7, 0.6), real(0.3))));
    const test_scene sc{"a mesh light over glass and metal",
                        world,
                        black,
                        point3(0.5, 2, 3),
                        point3(0.3, 0.1, 0.3),
                        real(0.6),
                        8,
                        rt_test::estimator_scenes::no_closed_form};
    check_all(run_all(sc, 820), sc);
}

TEST_CASE(
    "mesh_light: a mesh light inside an instance, found by scattering alone, keeps MIS, "
    "the mixture and the path tracer on the closed form",
    "[ch18]") {
    // A quad light, which the light set aims at, and an icosphere of 80 triangles moved into
    // place by a translate, which it does not: a path that finds the icosphere must count it
    // with full weight. The floor point sees both, neither in front of the other.
    const double Le = rt_test::estimator_scenes::light_radiance;
    const point3 q(-2, 2, -0.5);
    const vec3 u(1, 0, 0), v(0, 0, 1);
    const vec3 offset(1.5, 2, 0);
    const rt::mesh_data ball = icosphere(point3(0, 0, 0), 0.6, 1);
    auto world               = floor_world();
    world->add(std::make_shared<rt::quad>(q, u, v, rt_test::estimator_scenes::lamp(Le)));
    world->add(std::make_shared<rt::translate>(
        rt::mesh_object(ball, rt_test::estimator_scenes::lamp(Le)), offset));
    REQUIRE(rt::light_set(*world, black).size() == 1);
    // The quad as two triangles, and the ball where the instance puts it.
    rt::mesh_data quad_corners;
    quad_corners.positions = {q, q + u, q + u + v, q + v};
    quad_corners.triangles = {{0, 1, 2}, {0, 2, 3}};
    rt::mesh_data placed   = ball;
    for (point3& p : placed.positions) p += offset;
    const double cosines = cosine_integral(floor_point, floor_up, quad_corners, false) +
                           cosine_integral(floor_point, floor_up, placed, true);
    const test_scene sc = floor_scene("a quad light and an instanced mesh light over a floor",
                                      world, floor_radiance(Le, cosines));
    check_all(run_all(sc, 830), sc);
}

TEST_CASE(
    "mis_tracer: under a small mesh light of 20,480 triangles, far less noise than the "
    "path tracer",
    "[ch18]") {
    // An icosphere of radius 0.1 whose center is 2 above the floor point, of radiance 100 (as
    // chapter 15's small sphere light): a cosine-sampled direction finds it once in about 400
    // tries, a light sample on every try (half of which land on its far side, hidden by the
    // near one, so the gain is below chapter 15's 45 for a sphere). Measured ratio of the
    // standard errors, path / mis: 15 (0.0180 / 0.00120); required: more than 3.
    const double Le          = 100;
    const rt::mesh_data ball = icosphere(point3(0, 2, 0), 0.1, 5);
    REQUIRE(ball.triangles.size() == 20480);
    auto world = floor_world();
    world->add(rt::mesh_object(ball, rt_test::estimator_scenes::lamp(Le)));
    const test_scene sc =
        floor_scene("a small icosphere light", world,
                    floor_radiance(Le, cosine_integral(floor_point, floor_up, ball, true)));
    using rt_test::estimator_scenes::estimate;
    const auto by_path = estimate(rt::path_tracer(sc.world, sc.sky), sc, 20000, 901);
    const auto by_mis  = estimate(rt::mis_tracer(sc.world, sc.sky), sc, 20000, 902);
    rt_test::estimator_scenes::check_run(by_mis, sc);
    rt_test::estimator_scenes::check_same_mean(by_path, by_mis);
    const double path_se = by_path.radiance.estimate().standard_error;
    const double mis_se  = by_mis.radiance.estimate().standard_error;
    INFO("standard errors: path " << path_se << ", mis " << mis_se << ", ratio "
                                  << path_se / mis_se);
    CHECK(mis_se * 3 < path_se);
}
