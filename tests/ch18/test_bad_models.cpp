// Tests of read_obj and the mesh it makes (chapter 18) on the OBJ files of Debian's
// assimp-testmodels package: files written by other programs, with the faults models found in
// the wild have (UTF-16 text, a face of hundreds of corners, indices out of range, faces of no
// corners, materials that do not exist, points and lines, a concave polygon, Latin-1 bytes,
// texture coordinates on some corners only, vertex colours). Each file either loads, with the
// counts and warnings checked, or is refused with a message naming it (and the line and column
// for a bad index). The package is a test dependency (tools/install-deps): a missing file fails
// its test rather than skipping it.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "ch03/material_helpers.h"
#include "rt/core/error.h"
#include "rt/models/obj_model.h"
#include "test_helpers.h"

namespace {

namespace fs = std::filesystem;
using rt::point3, rt::real;

const std::string root = "/usr/share/assimp/models/";

// The package's file `name` (under root), which must be there.
std::string model(const std::string& name) {
    const std::string path = root + name;
    INFO(path << ": Debian's package assimp-testmodels must be installed (tools/install-deps)");
    REQUIRE(fs::is_regular_file(path));
    return path;
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

// The model's mesh, as a scene would make it.
std::shared_ptr<rt::triangle_mesh> mesh_of(const rt::obj_model& m) {
    return std::make_shared<rt::triangle_mesh>(m.mesh, rt_test::any_material());
}

const std::string material_warning =
    "materials (mtllib, usemtl) ignored: the scene gives the mesh its material";
const std::string uvs_warning = "texture coordinates (vt) on only some face corners: all ignored";

// The file's lines, split on \n (the package's files other than the UTF-16 one end lines so).
std::vector<std::string> lines_of(const std::string& path) {
    std::vector<std::string> lines;
    std::istringstream in(rt_test::read_bytes(path));
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// The distinct corner words ("12/7/3") of the file's faces: the vertices a mesh of it needs,
// for files whose faces use positive indices only.
std::size_t distinct_corners(const std::string& path) {
    std::set<std::string> corners;
    for (const std::string& line : lines_of(path)) {
        std::istringstream words(line);
        std::string kind, corner;
        if (!(words >> kind) || kind != "f") continue;
        while (words >> corner) corners.insert(corner);
    }
    return corners.size();
}

double triangle_area(const rt::mesh_data& d, const std::array<std::uint32_t, 3>& t) {
    const point3 &a = d.positions[t[0]], &b = d.positions[t[1]], &c = d.positions[t[2]];
    const double ux = double(b.x()) - a.x(), uy = double(b.y()) - a.y(), uz = double(b.z()) - a.z();
    const double vx = double(c.x()) - a.x(), vy = double(c.y()) - a.y(), vz = double(c.z()) - a.z();
    const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    return std::sqrt(nx * nx + ny * ny + nz * nz) / 2;
}

}  // namespace

TEST_CASE("bad models: invalid/empty.obj, an empty file, is refused as holding no triangle",
          "[ch18]") {
    const std::string path = model("invalid/empty.obj");
    INFO(path);
    REQUIRE(fs::file_size(path) == 0);
    CHECK(read_refusal(path) ==
          path + ": holds no triangle (0 vertices, 0 points, 0 lines): not a mesh");
}

TEST_CASE(
    "bad models: invalid/malformed.obj is refused at its first index out of range, line 23 "
    "column 5",
    "[ch18]") {
    const std::string path = model("invalid/malformed.obj");
    INFO(path);
    // The file's line 23 is "f 4 12 2 1", and it has 8 vertices (later faces hold -1 and 0,
    // which are valid and not, but the first bad index is the one named).
    const std::vector<std::string> lines = lines_of(path);
    REQUIRE(lines.size() >= 23);
    REQUIRE(lines[22] == "f 4 12 2 1");
    CHECK(read_refusal(path) == path + ":23:5: vertex index 12 is outside the 8 vertices declared");
}

TEST_CASE(
    "bad models: invalid/malformed2.obj, a face of no corners and a material that does not "
    "exist, loads its five quads with the material warning",
    "[ch18]") {
    const std::string path = model("invalid/malformed2.obj");
    INFO(path);
    const std::vector<std::string> lines = lines_of(path);
    REQUIRE(lines.size() >= 23);
    REQUIRE(lines[22] == "f");  // the face of no corners: nothing to cut, skipped
    const rt::obj_model m = rt::read_obj(path);
    CHECK(m.mesh.triangles.size() == 10);
    CHECK(m.mesh.positions.size() == 8);
    CHECK(m.warnings == std::vector<std::string>{material_warning});
    const auto mesh = mesh_of(m);
    CHECK(mesh->triangle_count() == 10);
    CHECK(mesh->dropped_triangles() == 0);  // five faces of the unit cube, none degenerate
    double area = 0;
    for (const auto& t : m.mesh.triangles) area += triangle_area(m.mesh, t);
    CHECK(area == Approx(5).epsilon(1e-12));
}

TEST_CASE("bad models: OBJ/box_UTF16BE.obj is refused as UTF-16", "[ch18]") {
    const std::string path = model("OBJ/box_UTF16BE.obj");
    INFO(path);
    REQUIRE(rt_test::read_bytes(path).substr(0, 2) == "\xFE\xFF");
    CHECK(read_refusal(path) ==
          path + ": UTF-16 text; an OBJ model is ASCII or UTF-8 (save it as UTF-8)");
}

TEST_CASE(
    "bad models: OBJ/box_longline.obj, a face of 936 corners, is refused naming its line "
    "and corner count",
    "[ch18]") {
    const std::string path = model("OBJ/box_longline.obj");
    INFO(path);
    CHECK(read_refusal(path) == path + ":24:1: a face of 936 corners (at most 255)");
}

TEST_CASE(
    "bad models: OBJ/concave_polygon.obj, one concave keyhole polygon of 66 corners, is "
    "covered exactly, never beyond its edges",
    "[ch18]") {
    const std::string path = model("OBJ/concave_polygon.obj");
    INFO(path);
    // The polygon from the file's own text: its vertices (rounded to real, as the mesh holds
    // them) and its one face's corners, in the plane x = -1.146.
    std::vector<point3> vertices;
    std::vector<point3> polygon;
    for (const std::string& line : lines_of(path)) {
        double x = 0, y = 0, z = 0;
        if (std::sscanf(line.c_str(), "v %lf %lf %lf", &x, &y, &z) == 3)
            vertices.emplace_back(real(x), real(y), real(z));
        if (line.rfind("f ", 0) != 0) continue;
        std::istringstream words(line.substr(2));
        for (std::string corner; words >> corner;) {
            const std::size_t index = std::stoul(corner.substr(0, corner.find('/')));
            REQUIRE(index >= 1);
            REQUIRE(index <= vertices.size());
            polygon.push_back(vertices[index - 1]);
        }
    }
    REQUIRE(vertices.size() == 64);
    REQUIRE(polygon.size() == 66);  // two corners repeated at the keyhole's bridge
    for (const point3& p : polygon) REQUIRE(p.x() == real(-1.146));
    // Newell's normal of the polygon: along x, twice its area. (tinyobjloader's own fan covered
    // 1.82, seven times the polygon.)
    double nx = 0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const point3& a = polygon[i];
        const point3& b = polygon[(i + 1) % polygon.size()];
        nx += (double(a.y()) - b.y()) * (double(a.z()) + b.z());
    }
    const double area = std::fabs(nx) / 2;
    REQUIRE(area == Approx(0.2455).margin(0.0005));

    const rt::obj_model m = rt::read_obj(path);
    CHECK(m.warnings == std::vector<std::string>{material_warning});
    REQUIRE(m.mesh.triangles.size() == 64);
    CHECK(m.mesh.positions.size() == 64);
    REQUIRE(m.mesh.normals.size() == 64);  // every corner names the normal (1, 0, 0)
    for (const auto& n : m.mesh.normals) CHECK(rt_test::exactly(n, rt::vec3(1, 0, 0)));

    // Each triangle faces the polygon's way, and points in it lie inside the polygon (the
    // even-odd rule in the (y, z) plane; the bridge, walked both ways, cancels out).
    auto inside = [&](double y, double z) {
        bool in = false;
        for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
            const double ay = polygon[i].y(), az = polygon[i].z();
            const double by = polygon[j].y(), bz = polygon[j].z();
            if ((az > z) != (bz > z) && y < (by - ay) * (z - az) / (bz - az) + ay) in = !in;
        }
        return in;
    };
    double sum  = 0;
    int against = 0, outside = 0;
    for (const auto& t : m.mesh.triangles) {
        const point3 &a = m.mesh.positions[t[0]], &b = m.mesh.positions[t[1]],
                     &c = m.mesh.positions[t[2]];
        const double tx = (double(b.y()) - a.y()) * (double(c.z()) - a.z()) -
                          (double(b.z()) - a.z()) * (double(c.y()) - a.y());
        against += !(tx * nx > 0);
        sum += triangle_area(m.mesh, t);
        const double weights[4][3] = {
            {1.0 / 3, 1.0 / 3, 1.0 / 3}, {0.8, 0.1, 0.1}, {0.1, 0.8, 0.1}, {0.1, 0.1, 0.8}};
        for (const auto& w : weights)
            outside += !inside(w[0] * a.y() + w[1] * b.y() + w[2] * c.y(),
                               w[0] * a.z() + w[1] * b.z() + w[2] * c.z());
    }
    CHECK(against == 0);
    CHECK(outside == 0);
    CHECK(sum == Approx(area).epsilon(1e-6));
    const auto mesh = mesh_of(m);
    CHECK(mesh->triangle_count() == 64);
    CHECK(mesh->dropped_triangles() == 0);
}

TEST_CASE(
    "bad models: OBJ/box_without_lineending.obj, its last line unended, gives the box's 12 "
    "triangles",
    "[ch18]") {
    const std::string path = model("OBJ/box_without_lineending.obj");
    INFO(path);
    const std::string bytes = rt_test::read_bytes(path);
    REQUIRE(bytes.substr(bytes.size() - 9) == "f 6 7 8 5");  // no newline after it
    const rt::obj_model m = rt::read_obj(path);
    CHECK(m.mesh.triangles.size() == 12);
    CHECK(m.mesh.positions.size() == 8);
    CHECK(m.warnings == std::vector<std::string>{material_warning});
    // The last face is there: the box is closed, 6 square faces of area 1.
    double area = 0;
    for (const auto& t : m.mesh.triangles) area += triangle_area(m.mesh, t);
    CHECK(area == Approx(6).epsilon(1e-12));
    CHECK(mesh_of(m)->dropped_triangles() == 0);
}

TEST_CASE(
    "bad models: OBJ/cube_usemtl.obj, OBJ/box_mat_with_spaces.obj and "
    "OBJ/space_in_material_name.obj load with one material warning",
    "[ch18]") {
    struct row {
        const char* name;
        std::size_t triangles, vertices;
        bool normals;
    };
    for (const row& r : {row{"OBJ/cube_usemtl.obj", 12, 24, true},  // 6 faces' 4 corners each
                         row{"OBJ/box_mat_with_spaces.obj", 12, 8, false},
                         row{"OBJ/space_in_material_name.obj", 64, 64, true}}) {
        const std::string path = model(r.name);
        INFO(path);
        const rt::obj_model m = rt::read_obj(path);
        CHECK(m.mesh.triangles.size() == r.triangles);
        CHECK(m.mesh.positions.size() == r.vertices);
        CHECK(m.mesh.normals.size() == (r.normals ? r.vertices : 0));
        CHECK(m.mesh.uvs.empty());
        CHECK(m.warnings == std::vector<std::string>{material_warning});
        const auto mesh = mesh_of(m);
        CHECK(mesh->triangle_count() == r.triangles);
        CHECK(mesh->dropped_triangles() == 0);
    }
}

TEST_CASE(
    "bad models: OBJ/testpoints.obj and OBJ/testline.obj, points or lines only, are refused "
    "counting them",
    "[ch18]") {
    // Six statements of four indices each: 24 points, or 6 lines.
    const std::string points = model("OBJ/testpoints.obj");
    INFO(points);
    CHECK(read_refusal(points) ==
          points + ": holds no triangle (8 vertices, 24 points, 0 lines): not a mesh");
    const std::string lines = model("OBJ/testline.obj");
    INFO(lines);
    CHECK(read_refusal(lines) ==
          lines + ": holds no triangle (8 vertices, 0 points, 6 lines): not a mesh");
}

TEST_CASE(
    "bad models: OBJ/testmixed.obj gives its 12 triangles and one warning for its points "
    "and lines",
    "[ch18]") {
    const std::string path = model("OBJ/testmixed.obj");
    INFO(path);
    const rt::obj_model m = rt::read_obj(path);
    CHECK(m.mesh.triangles.size() == 12);
    CHECK(m.mesh.positions.size() == 8);
    CHECK(m.warnings ==
          std::vector<std::string>{"24 points and 6 lines ignored (no surface for a ray to hit)",
                                   material_warning});
    CHECK(mesh_of(m)->dropped_triangles() == 0);
}

TEST_CASE("bad models: OBJ/point_cloud.obj, vertices and normals without faces, is refused",
          "[ch18]") {
    const std::string path = model("OBJ/point_cloud.obj");
    INFO(path);
    CHECK(read_refusal(path) ==
          path + ": holds no triangle (3 vertices, 0 points, 0 lines): not a mesh");
}

TEST_CASE(
    "bad models: OBJ/number_formats.obj loads its numbers, and its one face, whose corners "
    "lie in a line, is dropped by the mesh",
    "[ch18]") {
    const std::string path = model("OBJ/number_formats.obj");
    INFO(path);
    const rt::obj_model m = rt::read_obj(path);
    CHECK(m.warnings.empty());
    REQUIRE(m.mesh.triangles.size() == 1);
    // "f 1 2 4": "v 0 0 0", "v 1 2. 3.0" and "v -1 -2. -3.0".
    const auto& t = m.mesh.triangles[0];
    CHECK(rt_test::exactly(m.mesh.positions[t[0]], point3(0, 0, 0)));
    CHECK(rt_test::exactly(m.mesh.positions[t[1]], point3(1, 2, 3)));
    CHECK(rt_test::exactly(m.mesh.positions[t[2]], point3(-1, -2, -3)));
    const auto mesh = mesh_of(m);
    CHECK(mesh->dropped_triangles() == 1);
    CHECK(mesh->triangle_count() == 0);
}

TEST_CASE(
    "bad models: OBJ/regr01.obj, Latin-1 bytes in a material name, loads 2710 triangles "
    "and drops its texture coordinates, named by some corners only",
    "[ch18]") {
    const std::string path = model("OBJ/regr01.obj");
    INFO(path);
    REQUIRE(rt_test::read_bytes(path).find("usemtl Terraind\xE6k\n") != std::string::npos);
    const rt::obj_model m = rt::read_obj(path);
    CHECK(m.mesh.triangles.size() == 2710);
    CHECK(m.mesh.positions.size() == 2108);  // every vertex of the file, once
    CHECK(m.mesh.uvs.empty());
    CHECK(m.mesh.normals.empty());
    CHECK(m.warnings == std::vector<std::string>{uvs_warning, material_warning});
    // Four faces have their corners in a line along x (one coordinate varying): no area.
    const auto mesh = mesh_of(m);
    CHECK(mesh->dropped_triangles() == 4);
    CHECK(mesh->triangle_count() == 2706);
}

TEST_CASE(
    "bad models: OBJ/spider.obj and OBJ/WusonOBJ.obj load with their normals and texture "
    "coordinates, one vertex per distinct corner",
    "[ch18]") {
    struct row {
        const char* name;
        std::size_t triangles, vertices, dropped;
        std::vector<std::string> warnings;
    };
    // The spider has 56 faces with two corners at the same point (the same coordinates under
    // two vertex numbers): the mesh drops them.
    for (const row& r : {row{"OBJ/spider.obj", 1368, 974, 56, {material_warning}},
                         row{"OBJ/WusonOBJ.obj", 3732, 2117, 0, {}}}) {
        const std::string path = model(r.name);
        INFO(path);
        REQUIRE(distinct_corners(path) == r.vertices);
        const rt::obj_model m = rt::read_obj(path);
        CHECK(m.mesh.triangles.size() == r.triangles);
        CHECK(m.mesh.positions.size() == r.vertices);
        CHECK(m.mesh.normals.size() == r.vertices);
        CHECK(m.mesh.uvs.size() == r.vertices);
        CHECK(m.warnings == r.warnings);
        const auto mesh = mesh_of(m);
        CHECK(mesh->has_normals());
        CHECK(mesh->has_uvs());
        CHECK(mesh->dropped_triangles() == r.dropped);
        CHECK(mesh->triangle_count() == r.triangles - r.dropped);
    }
}

TEST_CASE(
    "bad models: OBJ/cube_with_vertexcolors.obj loads its 12 triangles, the colours "
    "ignored",
    "[ch18]") {
    const std::string path = model("OBJ/cube_with_vertexcolors.obj");
    INFO(path);
    const rt::obj_model m = rt::read_obj(path);
    CHECK(m.mesh.triangles.size() == 12);
    CHECK(m.mesh.positions.size() == 24);  // 8 corners, each with the normals of 3 faces
    CHECK(m.mesh.normals.size() == 24);
    CHECK(m.warnings.empty());
    // The positions are the cube's corners: the colours after them went nowhere.
    for (const point3& p : m.mesh.positions) {
        INFO(p);
        for (int i = 0; i < 3; ++i) CHECK((p[i] == 0 || p[i] == 1));
    }
    const auto mesh = mesh_of(m);
    CHECK(mesh->triangle_count() == 12);
    CHECK(mesh->dropped_triangles() == 0);
}
