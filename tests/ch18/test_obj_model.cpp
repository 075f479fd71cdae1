// Tests for obj_model.h (chapter 18): parse_obj on texts written here, read_obj and obj_mesh on
// files in a fresh temporary folder. What a model may hold becomes what the header promises:
// triangles from faces of any form (v, v/vt, v//vn, v/vt/vn; 1-based and negative indices),
// polygons cut into triangles, one vertex per distinct (position, uv, normal) triple, normals and
// texture coordinates kept only when every corner names them; points and lines, materials, and
// lines of other kinds ignored with one warning each. What it may not hold is refused with a
// message that names the file and, for a bad index or a face too large, the line and column a
// text editor shows (checked exactly, in every line-ending style). read_obj refuses a missing
// file, a folder and a file too large before reading it (the large file is sparse: nothing big
// is written). The committed Stanford bunny is read whole, against the counts and box its header
// states.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "ch03/material_helpers.h"
#include "rt/core/error.h"
#include "rt/models/obj_model.h"
#include "rt/program/asset_path.h"
#include "test_helpers.h"

namespace {

namespace fs = std::filesystem;
using rt::point3, rt::real, rt::vec3;
using rt_test::temp_folder, rt_test::write_bytes;
using triangle_indices = std::array<std::uint32_t, 3>;

rt::obj_model load(const std::string& text) {
    return rt::parse_obj(text, "model.obj");
}

// The message of the user_error that parsing `text` throws, or a note that it loaded.
std::string refusal(const std::string& text) {
    try {
        const rt::obj_model m = load(text);
        return "(loaded " + std::to_string(m.mesh.triangles.size()) +
               " triangles without an error)";
    } catch (const rt::user_error& e) {
        return e.what();
    }
}

std::string read_refusal(const std::string& path) {
    try {
        const rt::obj_model m = rt::read_obj(path);
        return "(loaded " + std::to_string(m.mesh.triangles.size()) +
               " triangles without an error)";
    } catch (const rt::user_error& e) {
        return e.what();
    }
}

// The lines joined, each ended by `end`.
std::string text_of(const std::vector<std::string>& lines, const std::string& end = "\n") {
    std::string t;
    for (const std::string& line : lines) t += line + end;
    return t;
}

// Three vertices of a right triangle in z = 0: lines 1 to 3 of most texts here.
const std::vector<std::string> three_vertices = {"v 0 0 0", "v 1 0 0", "v 0 1 0"};

std::vector<std::string> plus(std::vector<std::string> lines,
                              const std::vector<std::string>& more) {
    lines.insert(lines.end(), more.begin(), more.end());
    return lines;
}

// Whether the value read from a decimal in the file is that decimal's: within 4 ulps of real.
// tinyobjloader's reading of decimals is not correctly rounded ("0.75" reads as
// 0.75000000000000011 in double), so an exact comparison would test it rather than us.
bool read_as(real read, double written) {
    return std::fabs(double(read) - written) <=
           4 * double(std::numeric_limits<real>::epsilon()) * std::max(1.0, std::fabs(written));
}

bool same(const vec3& a, double x, double y, double z) {
    return read_as(a.x(), x) && read_as(a.y(), y) && read_as(a.z(), z);
}

bool same_uv(const rt::surface_uv& a, double u, double v) {
    return read_as(a.u, u) && read_as(a.v, v);
}

bool same_positions(const std::vector<point3>& a, const std::vector<point3>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!rt_test::exactly(a[i], b[i])) return false;
    return true;
}

// Corner k of triangle t of the model: its position.
const point3& corner(const rt::obj_model& m, std::size_t t, int k) {
    return m.mesh.positions[m.mesh.triangles[t][std::size_t(k)]];
}

double triangle_area(const rt::mesh_data& d, const triangle_indices& t) {
    const point3 &a = d.positions[t[0]], &b = d.positions[t[1]], &c = d.positions[t[2]];
    const double ux = double(b.x()) - a.x(), uy = double(b.y()) - a.y(), uz = double(b.z()) - a.z();
    const double vx = double(c.x()) - a.x(), vy = double(c.y()) - a.y(), vz = double(c.z()) - a.z();
    const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    return std::sqrt(nx * nx + ny * ny + nz * nz) / 2;
}

double total_area(const rt::mesh_data& d) {
    double sum = 0;
    for (const auto& t : d.triangles) sum += triangle_area(d, t);
    return sum;
}

// The z component of triangle t's normal (for triangles in a plane z = constant).
double normal_z(const rt::mesh_data& d, const triangle_indices& t) {
    const point3 &a = d.positions[t[0]], &b = d.positions[t[1]], &c = d.positions[t[2]];
    return (double(b.x()) - a.x()) * (double(c.y()) - a.y()) -
           (double(b.y()) - a.y()) * (double(c.x()) - a.x());
}

const std::string material_warning =
    "materials (mtllib, usemtl) ignored: the scene gives the mesh its material";
const std::string normals_warning =
    "normals (vn) on only some face corners: all ignored, the triangles are flat";
const std::string uvs_warning = "texture coordinates (vt) on only some face corners: all ignored";

}  // namespace

TEST_CASE("parse_obj: one triangle gives its three vertices in file order and no warning",
          "[ch18]") {
    const rt::obj_model m =
        load(text_of({"# a comment", "", "o thing", "g group", "s 1", "v 0.5 -1.25 2",
                      "v 3 0.125 -4", "v -0.75 8 16", "f 1 2 3"}));
    REQUIRE(m.mesh.positions.size() == 3);
    CHECK(same(m.mesh.positions[0], 0.5, -1.25, 2));
    CHECK(same(m.mesh.positions[1], 3, 0.125, -4));
    CHECK(same(m.mesh.positions[2], -0.75, 8, 16));
    REQUIRE(m.mesh.triangles.size() == 1);
    CHECK(m.mesh.triangles[0] == triangle_indices{0, 1, 2});
    CHECK(m.mesh.normals.empty());
    CHECK(m.mesh.uvs.empty());
    CHECK(m.warnings.empty());
}

TEST_CASE(
    "parse_obj: a negative index counts back from the last element declared before its "
    "face",
    "[ch18]") {
    const rt::obj_model m = load(text_of({"v 0 0 0", "v 1 0 0", "v 0 1 0",  //
                                          "f -3 -2 -1",                     // vertices 1, 2, 3
                                          "v 0 0 1",                        //
                                          "f -1 -4 -3",                     // vertices 4, 1, 2
                                          "f 4 1 2"}));
    REQUIRE(m.mesh.triangles.size() == 3);
    CHECK(same(corner(m, 0, 0), 0, 0, 0));
    CHECK(same(corner(m, 0, 1), 1, 0, 0));
    CHECK(same(corner(m, 0, 2), 0, 1, 0));
    CHECK(same(corner(m, 1, 0), 0, 0, 1));
    CHECK(same(corner(m, 1, 1), 0, 0, 0));
    CHECK(same(corner(m, 1, 2), 1, 0, 0));
    // The same corners, written 1-based: the same vertices, each stored once.
    CHECK(m.mesh.triangles[2] == m.mesh.triangles[1]);
    CHECK(m.mesh.positions.size() == 4);

    // Texture coordinates and normals count back from their own last one.
    const rt::obj_model t =
        load(text_of(plus(three_vertices, {"vt 0.25 0.5", "vt 0.75 0.5", "vn 0 0 1", "vn 0 1 0",
                                           "f -3/-2/-1 -2/-1/-2 -1/-2/-1"})));
    REQUIRE(t.mesh.triangles.size() == 1);
    REQUIRE(t.mesh.normals.size() == 3);
    REQUIRE(t.mesh.uvs.size() == 3);
    const triangle_indices& v = t.mesh.triangles[0];
    CHECK(same(t.mesh.positions[v[0]], 0, 0, 0));
    CHECK(read_as(t.mesh.uvs[v[0]].u, 0.25));
    CHECK(same(t.mesh.normals[v[0]], 0, 1, 0));
    CHECK(read_as(t.mesh.uvs[v[1]].u, 0.75));
    CHECK(same(t.mesh.normals[v[1]], 0, 0, 1));
    CHECK(same(t.mesh.positions[v[2]], 0, 1, 0));
    CHECK(read_as(t.mesh.uvs[v[2]].u, 0.25));
    CHECK(same(t.mesh.normals[v[2]], 0, 1, 0));
    CHECK(t.warnings.empty());
}

TEST_CASE(
    "parse_obj: v/vt/vn, v//vn and v/vt corners give every vertex its normal and texture "
    "coordinates",
    "[ch18]") {
    const std::vector<std::string> elements =
        plus(three_vertices,
             {"vt 0.25 0.5", "vt 0.75 0.125", "vt 0.5 1", "vn 0 0 1", "vn 0 1 0", "vn 1 0 0"});
    SECTION("v/vt/vn") {
        const rt::obj_model m = load(text_of(plus(elements, {"f 1/3/2 2/1/3 3/2/1"})));
        REQUIRE(m.mesh.triangles.size() == 1);
        REQUIRE(m.mesh.normals.size() == 3);
        REQUIRE(m.mesh.uvs.size() == 3);
        const triangle_indices& v = m.mesh.triangles[0];
        CHECK(same(m.mesh.positions[v[0]], 0, 0, 0));
        CHECK(same(m.mesh.normals[v[0]], 0, 1, 0));
        CHECK(same_uv(m.mesh.uvs[v[0]], 0.5, 1));
        CHECK(same(m.mesh.positions[v[1]], 1, 0, 0));
        CHECK(same(m.mesh.normals[v[1]], 1, 0, 0));
        CHECK(same_uv(m.mesh.uvs[v[1]], 0.25, 0.5));
        CHECK(same(m.mesh.positions[v[2]], 0, 1, 0));
        CHECK(same(m.mesh.normals[v[2]], 0, 0, 1));
        CHECK(same_uv(m.mesh.uvs[v[2]], 0.75, 0.125));
        CHECK(m.warnings.empty());
    }
    SECTION("v//vn") {
        const rt::obj_model m = load(text_of(plus(elements, {"f 1//3 2//2 3//1"})));
        REQUIRE(m.mesh.triangles.size() == 1);
        REQUIRE(m.mesh.normals.size() == 3);
        const triangle_indices& v = m.mesh.triangles[0];
        CHECK(same(m.mesh.normals[v[0]], 1, 0, 0));
        CHECK(same(m.mesh.normals[v[1]], 0, 1, 0));
        CHECK(same(m.mesh.normals[v[2]], 0, 0, 1));
        CHECK(m.mesh.uvs.empty());
        // The file's texture coordinates are named by no corner: unused, so no warning.
        CHECK(m.warnings.empty());
    }
    SECTION("v/vt") {
        const rt::obj_model m = load(text_of(plus(elements, {"f 1/2 2/3 3/1"})));
        REQUIRE(m.mesh.triangles.size() == 1);
        REQUIRE(m.mesh.uvs.size() == 3);
        const triangle_indices& v = m.mesh.triangles[0];
        CHECK(same_uv(m.mesh.uvs[v[0]], 0.75, 0.125));
        CHECK(same_uv(m.mesh.uvs[v[1]], 0.5, 1));
        CHECK(same_uv(m.mesh.uvs[v[2]], 0.25, 0.5));
        CHECK(m.mesh.normals.empty());
        CHECK(m.warnings.empty());  // no corner names a normal: nothing was dropped
    }
}

TEST_CASE(
    "parse_obj: a vertex used by several faces is stored once per distinct (position, uv, "
    "normal) triple",
    "[ch18]") {
    const std::vector<std::string> square =
        plus(three_vertices,
             {"v 1 1 0", "vt 0 0", "vt 1 0", "vt 1 1", "vt 0 1", "vn 0 0 1", "vn 0 0 -1"});
    SECTION("two triangles sharing an edge, corners alike: four vertices") {
        const rt::obj_model m =
            load(text_of(plus(square, {"f 1/1/1 2/2/1 4/3/1", "f 1/1/1 4/3/1 3/4/1"})));
        REQUIRE(m.mesh.triangles.size() == 2);
        CHECK(m.mesh.positions.size() == 4);
        CHECK(m.mesh.normals.size() == 4);
        CHECK(m.mesh.uvs.size() == 4);
        CHECK(m.mesh.triangles[1][0] == m.mesh.triangles[0][0]);
        CHECK(m.mesh.triangles[1][1] == m.mesh.triangles[0][2]);
    }
    SECTION("the shared corners with another normal: six vertices") {
        const rt::obj_model m =
            load(text_of(plus(square, {"f 1/1/1 2/2/1 4/3/1", "f 1/1/2 4/3/2 3/4/2"})));
        CHECK(m.mesh.positions.size() == 6);
        CHECK(m.mesh.normals.size() == 6);
    }
    SECTION("one shared corner with another texture coordinate: five vertices") {
        const rt::obj_model m =
            load(text_of(plus(square, {"f 1/1/1 2/2/1 4/3/1", "f 1/2/1 4/3/1 3/4/1"})));
        CHECK(m.mesh.positions.size() == 5);
        CHECK(m.mesh.uvs.size() == 5);
        CHECK(m.mesh.triangles[1][0] != m.mesh.triangles[0][0]);
        CHECK(m.mesh.triangles[1][1] == m.mesh.triangles[0][2]);
    }
    SECTION("positions only: a cube's 12 triangles share its 8 corners") {
        const rt::obj_model m = load(text_of(
            {"v 0 0 0", "v 1 0 0", "v 1 1 0", "v 0 1 0", "v 0 0 1", "v 1 0 1", "v 1 1 1", "v 0 1 1",
             "f 1 4 3 2", "f 5 6 7 8", "f 1 2 6 5", "f 2 3 7 6", "f 3 4 8 7", "f 4 1 5 8"}));
        CHECK(m.mesh.triangles.size() == 12);
        CHECK(m.mesh.positions.size() == 8);
        CHECK(total_area(m.mesh) == Approx(6).epsilon(1e-12));
    }
    SECTION("two position lines at the same point: two vertices, the file's own") {
        const rt::obj_model m =
            load(text_of({"v 0 0 0", "v 1 0 0", "v 0 1 0", "v 0 0 0", "f 1 2 3", "f 4 2 3"}));
        CHECK(m.mesh.positions.size() == 4);
        CHECK(m.mesh.triangles[0][0] != m.mesh.triangles[1][0]);
    }
}

TEST_CASE(
    "parse_obj: quads and polygons are cut into n - 2 triangles that cover them, facing "
    "as they do",
    "[ch18]") {
    struct face_case {
        const char* what;
        std::vector<std::string> lines;
        std::size_t triangles;
        double area;
        double facing;  // +1: the face's normal is +z; -1: -z
    };
    const std::vector<face_case> cases = {
        {"a quad", {"v 0 0 0", "v 2 0 0", "v 2 1 0", "v 0 1 0", "f 1 2 3 4"}, 2, 2, 1},
        {"a quad wound the other way",
         {"v 0 0 0", "v 2 0 0", "v 2 1 0", "v 0 1 0", "f 4 3 2 1"},
         2,
         2,
         -1},
        {"a convex pentagon",
         {"v 0 0 0", "v 2 0 0", "v 3 1 0", "v 1 2 0", "v -1 1 0", "f 1 2 3 4 5"},
         3,
         5,
         1},
        {"an L, counted back from the last vertex",
         {"v 2 0 0", "v 2 1 0", "v 1 1 0", "v 1 2 0", "v 0 2 0", "v 0 0 0", "f -6 -5 -4 -3 -2 -1"},
         4,
         3,
         1},
        {"a comb of 16 corners",
         {"v 7 0 0", "v 7 3 0", "v 6 3 0", "v 6 1 0", "v 5 1 0", "v 5 3 0", "v 4 3 0", "v 4 1 0",
          "v 3 1 0", "v 3 3 0", "v 2 3 0", "v 2 1 0", "v 1 1 0", "v 1 3 0", "v 0 3 0", "v 0 0 0",
          "f 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16"},
         14,
         15,
         1},
    };
    for (const face_case& c : cases) {
        INFO(c.what);
        const rt::obj_model m = load(text_of(c.lines));
        REQUIRE(m.mesh.triangles.size() == c.triangles);
        CHECK(total_area(m.mesh) == Approx(c.area).epsilon(1e-12));
        for (const auto& t : m.mesh.triangles) CHECK(normal_z(m.mesh, t) * c.facing > 0);
        CHECK(m.warnings.empty());
    }
    // A polygon's normals and texture coordinates go with its corners.
    const rt::obj_model m =
        load(text_of({"v 0 0 0", "v 2 0 0", "v 2 1 0", "v 0 1 0", "vt 0 0", "vt 1 0", "vt 1 1",
                      "vt 0 1", "vn 0 0 1", "vn 0 1 0", "f 1/1/1 2/2/2 3/3/1 4/4/2"}));
    REQUIRE(m.mesh.triangles.size() == 2);
    REQUIRE(m.mesh.positions.size() == 4);
    for (std::uint32_t i = 0; i < 4; ++i) {
        const point3& p = m.mesh.positions[i];
        INFO("vertex at " << p);
        const int file_index = p.x() == 0 ? (p.y() == 0 ? 1 : 4) : (p.y() == 0 ? 2 : 3);
        CHECK(m.mesh.uvs[i].u == real(file_index == 2 || file_index == 3 ? 1 : 0));
        CHECK(m.mesh.uvs[i].v == real(file_index >= 3 ? 1 : 0));
        CHECK(m.mesh.normals[i].z() == real(file_index % 2 == 1 ? 1 : 0));
    }
}

TEST_CASE(
    "parse_obj: a polygon whose edges cross is cut as a fan, with a warning that it is not "
    "simple",
    "[ch18]") {
    // A figure eight: the edge from corner 4 to 5 crosses the one from 1 to 2.
    const rt::obj_model m = load(text_of(
        {"v 0 0 0", "v 2 0 0", "v 2 2 0", "v 1 2 0", "v 1 -1 0", "v 0 -1 0", "f 1 2 3 4 5 6"}));
    CHECK(m.mesh.triangles.size() == 4);
    CHECK(m.warnings ==
          std::vector<std::string>{"1 polygon is not simple (edges cross, or not flat): cut as "
                                   "fans, which may cover more than they do"});
}

TEST_CASE(
    "parse_obj: normals or texture coordinates on only some corners are all dropped, with "
    "one warning each",
    "[ch18]") {
    const std::vector<std::string> elements =
        plus(three_vertices, {"v 1 1 0", "vt 0 0", "vt 1 0", "vn 0 0 1"});
    SECTION("normals") {
        const rt::obj_model m =
            load(text_of(plus(elements, {"f 1//1 2//1 3//1", "f 2//1 4//1 3//1", "f 3 2 4"})));
        CHECK(m.mesh.normals.empty());
        CHECK(m.mesh.triangles.size() == 3);
        CHECK(m.mesh.positions.size() == 4);  // the vertices no longer differ by normal
        // The file's texture coordinates are named by no corner: unused, no warning of theirs.
        CHECK(m.warnings == std::vector<std::string>{normals_warning});
    }
    SECTION("texture coordinates") {
        const rt::obj_model m =
            load(text_of(plus(elements, {"f 1/1/1 2/2/1 3/1/1", "f 2//1 4//1 3//1"})));
        CHECK(m.mesh.uvs.empty());
        CHECK(m.mesh.normals.size() == 4);
        CHECK(m.mesh.positions.size() == 4);
        CHECK(m.warnings == std::vector<std::string>{uvs_warning});
    }
}

TEST_CASE("parse_obj: points and lines are ignored, with one warning that counts them", "[ch18]") {
    const rt::obj_model m = load(
        text_of(plus(three_vertices, {"p 1 2", "l 1 2 3", "f 1 2 3", "p 3", "l 2 3", "l 3 1"})));
    CHECK(m.mesh.triangles.size() == 1);
    CHECK(m.warnings ==
          std::vector<std::string>{"3 points and 3 lines ignored (no surface for a ray to hit)"});
}

TEST_CASE(
    "parse_obj: materials (mtllib, usemtl) are ignored, with one warning however many "
    "lines name them",
    "[ch18]") {
    // The library named is not looked for: no file beside a model is ever read.
    const rt::obj_model m =
        load(text_of(plus(three_vertices, {"mtllib no_such_file.mtl", "usemtl red", "f 1 2 3",
                                           "usemtl blue", "f 3 2 1"})));
    CHECK(m.mesh.triangles.size() == 2);
    CHECK(m.warnings == std::vector<std::string>{material_warning});
}

TEST_CASE(
    "parse_obj: lines of kinds it does not read (free-form curves, skin weights) are "
    "ignored, with one warning that counts them",
    "[ch18]") {
    const rt::obj_model m =
        load(text_of(plus(three_vertices, {"vp 0.5 0.5", "cstype bspline", "deg 3",
                                           "curv 0 1 1 2 3", "end", "vw 1 2 0.5", "s off", "o one",
                                           "g two", "  # indented comment", "f 1 2 3"})));
    CHECK(m.mesh.triangles.size() == 1);
    CHECK(m.warnings == std::vector<std::string>{"6 lines of other kinds ignored (only v, vn, vt, "
                                                 "f, l, p, o, g, s, mtllib and usemtl are read)"});
}

TEST_CASE(
    "parse_obj: a UTF-8 byte order mark is skipped, and columns on line 1 count from "
    "after it",
    "[ch18]") {
    const std::string bom = "\xEF\xBB\xBF";
    const rt::obj_model m = load(bom + text_of(plus(three_vertices, {"f 1 2 3"})));
    CHECK(m.mesh.triangles.size() == 1);
    CHECK(m.mesh.positions.size() == 3);
    CHECK(m.warnings.empty());
    CHECK(refusal(bom + "f 1 2 3\n") ==
          "model.obj:1:3: vertex index 1 is outside the 0 vertices declared");
}

TEST_CASE(
    "parse_obj: CRLF, a lone CR and a missing final newline end lines as LF does, and "
    "lines are counted alike",
    "[ch18]") {
    const std::vector<std::string> good = plus(three_vertices, {"v 1 1 0", "f 1 2 4 3"});
    const rt::obj_model lf              = load(text_of(good));
    REQUIRE(lf.mesh.triangles.size() == 2);
    const std::vector<std::string> bad = plus(three_vertices, {"v 1 1 0", "f 1 2 5 3"});
    for (const std::string end : {"\n", "\r\n", "\r"}) {
        for (const bool final_end : {true, false}) {
            std::string text = text_of(good, end), bad_text = text_of(bad, end);
            if (!final_end) {
                text.resize(text.size() - end.size());
                bad_text.resize(bad_text.size() - end.size());
            }
            INFO("line end " << (end == "\n"     ? "LF"
                                 : end == "\r\n" ? "CRLF"
                                                 : "CR")
                             << (final_end ? "" : ", none after the last line"));
            const rt::obj_model m = load(text);
            CHECK(same_positions(m.mesh.positions, lf.mesh.positions));
            CHECK(m.mesh.triangles == lf.mesh.triangles);
            CHECK(m.warnings.empty());
            CHECK(refusal(bad_text) ==
                  "model.obj:5:7: vertex index 5 is outside the 4 vertices declared");
        }
    }
    // All three in one file.
    CHECK(refusal("v 0 0 0\r\nv 1 0 0\rv 0 1 0\n\r\nf 1 2 3\rf 1 2 4") ==
          "model.obj:6:7: vertex index 4 is outside the 3 vertices declared");
}

TEST_CASE("parse_obj: UTF-16 text is refused, from either byte order mark", "[ch18]") {
    const std::string utf16_note =
        "model.obj: UTF-16 text; an OBJ model is ASCII or UTF-8 (save it as UTF-8)";
    // "v 0" in UTF-16, little and big endian.
    CHECK(refusal(std::string("\xFF\xFEv\0 \0000\0", 8)) == utf16_note);
    CHECK(refusal(std::string("\xFE\xFF\0v\0 \0000", 8)) == utf16_note);
    // Without a byte order mark, its NUL bytes give it away.
    CHECK_THAT(refusal(std::string("v\0 \0000\0", 6)),
               Catch::StartsWith("model.obj: a NUL byte at byte 2: not a text file"));
}

TEST_CASE("parse_obj: a NUL byte is refused, naming the byte (counted from 1)", "[ch18]") {
    std::string text = text_of(plus(three_vertices, {"f 1 2 3"}));
    REQUIRE(refusal(text) == "(loaded 1 triangles without an error)");
    std::string inside = text;
    inside.insert(12, 1, '\0');  // in "v 1 0 0", after "v 1 "
    CHECK(refusal(inside) ==
          "model.obj: a NUL byte at byte 13: not a text file (an OBJ model is "
          "ASCII or UTF-8; UTF-16 is not read)");
    CHECK_THAT(refusal(text + std::string(1, '\0')),
               Catch::StartsWith("model.obj: a NUL byte at byte " +
                                 std::to_string(text.size() + 1) + ":"));
}

TEST_CASE("parse_obj: a bad index is refused at the line and column where it is written",
          "[ch18]") {
    struct bad_case {
        std::vector<std::string> lines;
        std::string message;
    };
    const std::vector<bad_case> cases = {
        {plus(three_vertices, {"f 1 2 4"}),
         "model.obj:4:7: vertex index 4 is outside the 3 vertices declared"},
        {plus(three_vertices, {"f 1 2 0"}),
         "model.obj:4:7: vertex index 0 (an OBJ file counts from 1, or back from -1)"},
        {plus(three_vertices, {"f -4 1 2"}),
         "model.obj:4:3: vertex index -4 is outside the 3 vertices declared before it"},
        // A negative index counts only what came before its line.
        {{"v 0 0 0", "v 1 0 0", "f -3 -2 -1", "v 0 1 0"},
         "model.obj:3:3: vertex index -3 is outside the 2 vertices declared before it"},
        // Tabs and runs of spaces: the column is the byte's, from 1.
        {plus(three_vertices, {"\t f  1\t2   9"}),
         "model.obj:4:12: vertex index 9 is outside the 3 vertices declared"},
        {plus(three_vertices, {"f 1 2 3.0"}),
         "model.obj:4:7: '3.0' is no vertex index (an integer)"},
        {plus(three_vertices, {"f 1 x 3"}), "model.obj:4:5: 'x' is no vertex index (an integer)"},
        {plus(three_vertices, {"vt 0 0", "f 1/1 2/2 3/1"}),
         "model.obj:5:9: texture coordinate index 2 is outside the 1 texture coordinates "
         "declared"},
        {plus(three_vertices, {"vt 0 0", "f 1/1 2/a 3/1"}),
         "model.obj:5:9: 'a' is no texture coordinate index (an integer)"},
        {plus(three_vertices, {"vn 0 0 1", "f 1//1 2//1 3//2"}),
         "model.obj:5:16: normal index 2 is outside the 1 normals declared"},
        {plus(three_vertices, {"vn 0 0 1", "f 1//1 2//0 3//1"}),
         "model.obj:5:11: normal index 0 (an OBJ file counts from 1, or back from -1)"},
        // The first bad index of the file is the one named.
        {plus(three_vertices, {"", "f 1 2 3", "# f 1 2 7", "f 1 2 3 8", "f 9 1 2"}),
         "model.obj:7:9: vertex index 8 is outside the 3 vertices declared"},
    };
    for (const bad_case& c : cases) {
        const std::string text = text_of(c.lines);
        INFO(text);
        CHECK(refusal(text) == c.message);
    }
}

TEST_CASE(
    "parse_obj: a face of 255 corners is cut into 253 triangles, one of 256 is refused "
    "naming its corner count",
    "[ch18]") {
    // 256 vertices on a circle (lines 1 to 256), then the face (line 257).
    std::vector<std::string> lines;
    std::vector<std::array<double, 2>> circle;
    for (int k = 0; k < 256; ++k) {
        char line[64];
        const double a = 6.283185307179586 * k / 256;
        std::snprintf(line, sizeof line, "v %.9f %.9f 0", std::cos(a), std::sin(a));
        lines.push_back(line);
        double x = 0, y = 0;
        REQUIRE(std::sscanf(line, "v %lf %lf", &x, &y) == 2);
        circle.push_back({double(real(x)), double(real(y))});  // as the mesh holds it
    }
    std::string face = "f";
    // Appended, not added: GCC 12 warns, wrongly, about some inlined string additions.
    for (int k = 1; k <= 255; ++k) face.append(" ").append(std::to_string(k));
    // The 255-gon's area by the shoelace formula.
    double twice = 0;
    for (std::size_t k = 0; k < 255; ++k) {
        const auto& p = circle[k];
        const auto& q = circle[(k + 1) % 255];
        twice += p[0] * q[1] - q[0] * p[1];
    }
    const rt::obj_model m = load(text_of(plus(lines, {face})));
    CHECK(m.mesh.triangles.size() == 253);
    CHECK(m.mesh.positions.size() == 255);
    CHECK(total_area(m.mesh) == Approx(twice / 2).epsilon(1e-6));
    for (const auto& t : m.mesh.triangles) CHECK(normal_z(m.mesh, t) > 0);
    CHECK(m.warnings.empty());

    CHECK(refusal(text_of(plus(lines, {face + " 256"}))) ==
          "model.obj:257:1: a face of 256 corners (at most 255)");
}

TEST_CASE("parse_obj: a text with no triangle is refused as not a mesh", "[ch18]") {
    CHECK(refusal("") ==
          "model.obj: holds no triangle (0 vertices, 0 points, 0 lines): not a mesh");
    CHECK(refusal("# only a comment\n\n") ==
          "model.obj: holds no triangle (0 vertices, 0 points, 0 lines): not a mesh");
    CHECK(refusal(text_of(three_vertices)) ==
          "model.obj: holds no triangle (3 vertices, 0 points, 0 lines): not a mesh");
    CHECK(refusal(text_of(plus(three_vertices, {"p 1 2 3", "l 1 2"}))) ==
          "model.obj: holds no triangle (3 vertices, 3 points, 1 line): not a mesh");
}

TEST_CASE(
    "read_obj: a missing file, a folder and a file over max_obj_bytes are refused, naming "
    "the path",
    "[ch18]") {
    temp_folder dir("obj_model", "refused");
    const std::string missing = dir.file("missing.obj");
    CHECK_THAT(read_refusal(missing), Catch::StartsWith(missing + ": cannot read the model ("));
    CHECK(read_refusal(dir.path().string()) ==
          dir.path().string() + ": a folder, not a model file");

    // A sparse file one byte over the limit: refused from its size, before anything is read (a
    // read would take a gigabyte of memory and find only NUL bytes).
    const std::string big = dir.file("big.obj");
    write_bytes(big, "v 0 0 0\n");
    fs::resize_file(big, rt::max_obj_bytes + 1);
    REQUIRE(fs::file_size(big) == rt::max_obj_bytes + 1);
    CHECK(read_refusal(big) == big + ": " + std::to_string(rt::max_obj_bytes + 1) +
                                   " bytes: a model file may have at most " +
                                   std::to_string(rt::max_obj_bytes));
}

TEST_CASE("read_obj: a file reads as its text parses, and its messages name its path", "[ch18]") {
    temp_folder dir("obj_model", "read");
    const std::string text = text_of(plus(three_vertices, {"v 1 1 0", "f 1 2 4 3", "usemtl x"}));
    const std::string good = dir.file("good.obj");
    write_bytes(good, text);
    const rt::obj_model from_file = rt::read_obj(good);
    const rt::obj_model from_text = load(text);
    CHECK(same_positions(from_file.mesh.positions, from_text.mesh.positions));
    CHECK(from_file.mesh.triangles == from_text.mesh.triangles);
    CHECK(from_file.warnings == std::vector<std::string>{material_warning});  // without the name

    const std::string bad = dir.file("bad.obj");
    write_bytes(bad, text_of(plus(three_vertices, {"f 1 2 3 4"})));
    CHECK(read_refusal(bad) == bad + ":4:9: vertex index 4 is outside the 3 vertices declared");
}

TEST_CASE(
    "obj_mesh: the degenerate triangles the mesh drops are counted in one warning after "
    "the model's own, each naming the file",
    "[ch18]") {
    temp_folder dir("obj_model", "degenerate");
    const std::string path = dir.file("flat.obj");
    // One good triangle, one of zero area (its corners in a line), one with a corner repeated.
    write_bytes(path, text_of(plus(three_vertices,
                                   {"v 2 0 0", "usemtl x", "f 1 2 3", "f 1 2 4", "f 1 3 3"})));
    std::vector<std::string> warnings = {"an earlier warning"};
    const auto mesh                   = rt::obj_mesh(path, rt_test::any_material(), warnings);
    REQUIRE(mesh);
    CHECK(mesh->triangle_count() == 1);
    CHECK(mesh->dropped_triangles() == 2);
    CHECK(warnings ==
          std::vector<std::string>{"an earlier warning", path + ": " + material_warning,
                                   path + ": 2 degenerate triangles dropped (zero area, a vertex "
                                          "repeated, or a coordinate not finite)"});

    // Nothing dropped, nothing said.
    const std::string good = dir.file("good.obj");
    write_bytes(good, text_of(plus(three_vertices, {"f 1 2 3"})));
    std::vector<std::string> none;
    CHECK(rt::obj_mesh(good, rt_test::any_material(), none)->triangle_count() == 1);
    CHECK(none.empty());
}

TEST_CASE(
    "read_obj: the committed Stanford bunny has the vertices, triangles and bounding box "
    "its header states",
    "[ch18]") {
    const std::string path = rt::asset_path("models/bunny.obj");
    INFO(path);
    // The header's own numbers.
    const std::string text = rt_test::read_bytes(path);
    REQUIRE(text.find("# Vertices: 1839, triangles: 3674\n") != std::string::npos);
    const std::size_t box_at = text.find("# Bounding box: min ");
    REQUIRE(box_at != std::string::npos);
    double lo[3] = {}, hi[3] = {};
    REQUIRE(std::sscanf(text.c_str() + box_at, "# Bounding box: min %lf %lf %lf, max %lf %lf %lf",
                        &lo[0], &lo[1], &lo[2], &hi[0], &hi[1], &hi[2]) == 6);

    const rt::obj_model m = rt::read_obj(path);
    CHECK(m.mesh.positions.size() == 1839);
    CHECK(m.mesh.triangles.size() == 3674);
    CHECK(m.mesh.normals.empty());
    CHECK(m.mesh.uvs.empty());
    CHECK(m.warnings.empty());
    REQUIRE_FALSE(m.mesh.positions.empty());
    point3 low = m.mesh.positions[0], high = low;
    for (const point3& p : m.mesh.positions) {
        for (int i = 0; i < 3; ++i) {
            low[i]  = std::min(low[i], p[i]);
            high[i] = std::max(high[i], p[i]);
        }
    }
    // The header's numbers are the file's own, to their last digit: within a rounding to real.
    for (int i = 0; i < 3; ++i) {
        INFO("axis " << i);
        CHECK(std::fabs(double(low[i]) - lo[i]) <= 1e-6 * std::max(1.0, std::fabs(lo[i])));
        CHECK(std::fabs(double(high[i]) - hi[i]) <= 1e-6 * std::max(1.0, std::fabs(hi[i])));
    }

    std::vector<std::string> warnings;
    const auto mesh = rt::obj_mesh(path, rt_test::any_material(), warnings);
    CHECK(mesh->triangle_count() == 3674);
    CHECK(mesh->dropped_triangles() == 0);
    CHECK(warnings.empty());
}

TEST_CASE(
    "parse_obj: a model declaring more triangles than the limit given is refused before it "
    "is read, at the face that passes it",
    "[ch18]") {
    // Four triangles (triangles only: cutting polygons is an exercise of its own).
    const std::string text =
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\nf 1 2 4\nf 1 4 3\n";
    CHECK(rt::parse_obj(text, "m.obj", 4).mesh.triangles.size() == 4);
    std::string message;
    try {
        rt::parse_obj(text, "m.obj", 3);
    } catch (const rt::user_error& e) {
        message = e.what();
    }
    CHECK(message == "m.obj:8:1: more than 3 triangles");
}
