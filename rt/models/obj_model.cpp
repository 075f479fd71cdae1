#include "rt/models/obj_model.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string_view>
#include <unordered_map>

#include "rt/core/error.h"
#include "rt/models/polygon_triangulation.h"

namespace rt {

namespace {

// "1 polygon", "2 polygons".
std::string counted(std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

[[noreturn]] void refuse(const std::string& name, const std::string& why) {
    throw user_error(name + ": " + why);
}

[[noreturn]] void refuse_at(const std::string& name, std::size_t line, std::size_t column,
                            const std::string& why) {
    refuse(name + ":" + std::to_string(line) + ":" + std::to_string(column), why);
}

// What the raw text declares, counted before tinyobjloader reads it.
struct declared {
    std::size_t positions = 0, normals = 0, uvs = 0;
    std::size_t triangles = 0;  // after triangulation: a face of n corners makes n - 2
    std::size_t points = 0, lines = 0;
    std::size_t short_faces = 0;  // of one or two corners: no triangle
    bool materials          = false;
};

// The text's lines, each with its number (from 1), split on \n, \r\n or a lone \r.
template <typename Visit>
void for_each_line(std::string_view text, Visit visit) {
    std::size_t number = 1, start = 0;
    while (start < text.size()) {
        std::size_t end = text.find_first_of("\r\n", start);
        if (end == std::string_view::npos) end = text.size();
        visit(number++, text.substr(start, end - start), start);
        start = end + (text.compare(end, 2, "\r\n") == 0 ? 2 : 1);
    }
}

bool blank(char c) {
    return c == ' ' || c == '\t';
}

// The line's words (split on spaces and tabs), each with its column (from 1). A keyword counts
// only when a blank follows it, as tinyobjloader reads it: a line "v" alone declares nothing.
std::vector<std::pair<std::string_view, std::size_t>> words(std::string_view line) {
    std::vector<std::pair<std::string_view, std::size_t>> result;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && blank(line[i])) ++i;
        const std::size_t begin = i;
        while (i < line.size() && !blank(line[i])) ++i;
        if (i > begin) result.emplace_back(line.substr(begin, i - begin), begin + 1);
    }
    if (result.size() == 1) result.clear();  // a keyword with nothing after it
    return result;
}

// Counts what the text declares, and refuses more than a mesh may hold before anything is
// allocated for it: the first pass over the text.
declared count_elements(std::string_view text, const std::string& name,
                        std::size_t triangle_limit) {
    declared d;
    for_each_line(text, [&](std::size_t number, std::string_view line, std::size_t) {
        const auto w = words(line);
        if (w.empty()) return;
        const std::string_view kind = w[0].first;
        if (kind == "v") {
            ++d.positions;
        } else if (kind == "vn") {
            ++d.normals;
        } else if (kind == "vt") {
            ++d.uvs;
        } else if (kind == "f") {
            const std::size_t corners = w.size() - 1;
            if (corners > 255)
                refuse_at(name, number, 1,
                          "a face of " + std::to_string(corners) + " corners (at most 255)");
            if (corners >= 3) d.triangles += corners - 2;
            if (corners < 3) ++d.short_faces;
        } else if (kind == "p") {
            ++d.points;
        } else if (kind == "l") {
            ++d.lines;
        } else if (kind == "mtllib" || kind == "usemtl") {
            d.materials = true;
        }
        if (d.positions > triangle_mesh::max_vertices)
            refuse_at(name, number, 1,
                      "more than " + std::to_string(triangle_mesh::max_vertices) + " vertices");
        if (d.triangles > triangle_limit)
            refuse_at(name, number, 1,
                      "more than " + std::to_string(triangle_limit) + " triangles");
    });
    return d;
}

// One index of a face corner ("7", "-2"), checked against the elements of its kind: a positive
// index counts from the file's first (of `total`), a negative one back from the last declared
// before its line (`so_far`).
struct element_kind {
    const char* one;
    const char* many;
};
constexpr element_kind positions_kind{"vertex", "vertices"};
constexpr element_kind uvs_kind{"texture coordinate", "texture coordinates"};
constexpr element_kind normals_kind{"normal", "normals"};

void check_index(std::string_view word, std::size_t so_far, std::size_t total,
                 const element_kind& kind, const std::string& name, std::size_t line,
                 std::size_t column) {
    long long index = 0;
    // A '+' before the digits is read as tinyobjloader reads it; from_chars takes none.
    const std::string_view digits = word.substr(word.size() > 1 && word[0] == '+' ? 1 : 0);
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), index);
    if (error != std::errc() || end != digits.data() + digits.size())
        refuse_at(name, line, column,
                  "'" + std::string(word) + "' is no " + kind.one + " index (an integer" +
                      (word[0] == '#' ? "; a comment takes a line of its own)" : ")"));
    if (index == 0)
        refuse_at(name, line, column,
                  std::string(kind.one) +
                      " index 0 (an OBJ file counts from 1, or back from "
                      "-1)");
    const bool ok = index > 0 ? std::size_t(index) <= total : std::size_t(-index) <= so_far;
    if (!ok)
        refuse_at(name, line, column,
                  std::string(kind.one) + " index " + std::to_string(index) + " is outside the " +
                      std::to_string(index > 0 ? total : so_far) + " " + kind.many + " declared" +
                      (index > 0 ? "" : " before it"));
}

// The second pass: every face corner's indices name elements the file declares.
void check_faces(std::string_view text, const declared& d, const std::string& name) {
    std::size_t positions = 0, normals = 0, uvs = 0;
    for_each_line(text, [&](std::size_t number, std::string_view line, std::size_t) {
        const auto w = words(line);
        if (w.empty()) return;
        const std::string_view kind = w[0].first;
        if (kind == "v") ++positions;
        if (kind == "vn") ++normals;
        if (kind == "vt") ++uvs;
        if (kind != "f") return;
        for (std::size_t i = 1; i < w.size(); ++i) {
            // position[/uv[/normal]], with uv possibly empty: "3//5".
            const std::string_view corner = w[i].first;
            std::size_t start             = 0;
            for (int part = 0; part < 3 && start <= corner.size(); ++part) {
                std::size_t slash = corner.find('/', start);
                if (slash == std::string_view::npos) slash = corner.size();
                const std::string_view index = corner.substr(start, slash - start);
                const std::size_t column     = w[i].second + start;
                if (part == 0 || !index.empty()) {
                    if (part == 0)
                        check_index(index, positions, d.positions, positions_kind, name, number,
                                    column);
                    if (part == 1) check_index(index, uvs, d.uvs, uvs_kind, name, number, column);
                    if (part == 2)
                        check_index(index, normals, d.normals, normals_kind, name, number, column);
                }
                start = slash + 1;
            }
        }
    });
}

// The distinct (position, uv, normal) triples of the faces, each one vertex of the mesh.
struct corner_key {
    int position, uv, normal;
    bool operator==(const corner_key&) const = default;
};

struct corner_hash {
    std::size_t operator()(const corner_key& k) const {
        std::size_t h = std::hash<int>()(k.position);
        h             = h * 1000003u ^ std::hash<int>()(k.uv);
        return h * 1000003u ^ std::hash<int>()(k.normal);
    }
};

std::string first_line(const std::string& text) {
    const std::string line = text.substr(0, text.find('\n'));
    return line.empty() ? "tinyobjloader could not read it" : line;
}

}  // namespace

obj_model parse_obj(const std::string& raw, const std::string& name, std::size_t triangle_limit) {
    std::string_view text = raw;
    if (text.size() >= 2 &&
        ((text[0] == '\xff' && text[1] == '\xfe') || (text[0] == '\xfe' && text[1] == '\xff')))
        refuse(name, "UTF-16 text; an OBJ model is ASCII or UTF-8 (save it as UTF-8)");
    if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos)
        refuse(name, "a NUL byte at byte " + std::to_string(nul + 1) +
                         ": not a text file (an OBJ model is ASCII or UTF-8; UTF-16 is not read)");
    if (text.substr(0, 3) == "\xef\xbb\xbf") text.remove_prefix(3);  // a UTF-8 byte order mark

    const declared d =
        count_elements(text, name, std::min(triangle_limit, triangle_mesh::max_triangles));
    check_faces(text, d, name);

    // tinyobjloader reads the kinds of line below; the others it knows (skin weights vw,
    // subdivision tags t, free-form curves) carry no triangles, and it has faults on some of
    // them (a vw joint beyond an int's range is undefined behaviour, fuzz/regressions/obj): they
    // become comments before it reads, with one warning.
    std::string kept(text);
    std::size_t ignored = 0;
    for_each_line(text, [&](std::size_t, std::string_view line, std::size_t start) {
        const std::size_t first = line.find_first_not_of(" \t");
        if (first == std::string_view::npos || line[first] == '#') return;
        const std::string_view keyword =
            line.substr(first, line.find_first_of(" \t", first) - first);
        for (const char* read : {"v", "vn", "vt", "f", "l", "p", "o", "g", "s", "mtllib", "usemtl"})
            if (keyword == read) return;
        kept[start + first] = '#';
        ++ignored;
    });

    tinyobj::ObjReaderConfig config;
    config.triangulate  = false;  // its fan covers a concave polygon's notches: ours clips ears
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    // The material library text is empty: materials come from the scene, never from a file
    // beside the model.
    if (!reader.ParseFromString(kept, "", config)) refuse(name, first_line(reader.Error()));

    obj_model model;
    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    // The checks above read the text as tinyobjloader does; should the two ever disagree, an
    // index outside what it read is still refused here, before anything is looked up.
    const auto read_positions = int(attrib.vertices.size() / 3);
    const auto read_normals   = int(attrib.normals.size() / 3);
    const auto read_uvs       = int(attrib.texcoords.size() / 2);
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        for (const tinyobj::index_t& corner : shape.mesh.indices) {
            if (corner.vertex_index < 0 || corner.vertex_index >= read_positions ||
                corner.normal_index < -1 || corner.normal_index >= read_normals ||
                corner.texcoord_index < -1 || corner.texcoord_index >= read_uvs)
                refuse(name, "a face corner names an element tinyobjloader did not read (vertex " +
                                 std::to_string(corner.vertex_index + 1) + " of " +
                                 std::to_string(read_positions) + ")");
        }
    }
    bool every_normal = true, every_uv = true, some_normal = false, some_uv = false;
    std::size_t points = 0, lines = 0;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        for (const tinyobj::index_t& corner : shape.mesh.indices) {
            every_normal &= corner.normal_index >= 0;
            every_uv &= corner.texcoord_index >= 0;
            some_normal |= corner.normal_index >= 0;
            some_uv |= corner.texcoord_index >= 0;
        }
        points += shape.points.indices.size();
        lines += shape.lines.num_line_vertices.size();
    }
    const bool normals = every_normal && !attrib.normals.empty();
    const bool uvs     = every_uv && !attrib.texcoords.empty();
    if (some_normal && !normals)
        model.warnings.push_back(
            "normals (vn) on only some face corners: all ignored, the "
            "triangles are flat");
    if (some_uv && !uvs)
        model.warnings.push_back(
            "texture coordinates (vt) on only some face corners: all "
            "ignored");
    if (points + lines > 0)
        model.warnings.push_back(counted(points, "point", "points") + " and " +
                                 counted(lines, "line", "lines") +
                                 " ignored (no surface for a ray to hit)");
    if (d.short_faces > 0)
        model.warnings.push_back(counted(d.short_faces, "face", "faces") +
                                 " of fewer than 3 corners ignored (no surface)");
    if (ignored > 0)
        model.warnings.push_back(counted(ignored, "line", "lines") +
                                 " of other kinds ignored (only v, vn, vt, f, l, p, o, g, s, "
                                 "mtllib and usemtl are read)");
    if (d.materials)
        model.warnings.push_back(
            "materials (mtllib, usemtl) ignored: the scene gives the "
            "mesh its material");

    mesh_data& mesh = model.mesh;
    std::unordered_map<corner_key, std::uint32_t, corner_hash> vertex_of;
    auto vertex = [&](const tinyobj::index_t& c) {
        const corner_key key{c.vertex_index, uvs ? c.texcoord_index : -1,
                             normals ? c.normal_index : -1};
        auto [where, added] = vertex_of.try_emplace(key, std::uint32_t(mesh.positions.size()));
        if (added) {
            const auto p = std::size_t(key.position) * 3;
            mesh.positions.emplace_back(real(attrib.vertices[p]), real(attrib.vertices[p + 1]),
                                        real(attrib.vertices[p + 2]));
            if (normals) {
                const auto n = std::size_t(key.normal) * 3;
                mesh.normals.emplace_back(real(attrib.normals[n]), real(attrib.normals[n + 1]),
                                          real(attrib.normals[n + 2]));
            }
            if (uvs) {
                const auto t = std::size_t(key.uv) * 2;
                mesh.uvs.push_back({real(attrib.texcoords[t]), real(attrib.texcoords[t + 1])});
            }
        }
        return where->second;
    };
    std::size_t not_simple = 0;
    std::vector<point3> polygon;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        const auto& c     = shape.mesh.indices;
        std::size_t first = 0;
        for (const unsigned char corners : shape.mesh.num_face_vertices) {
            if (corners == 3) {
                mesh.triangles.push_back(
                    {vertex(c[first]), vertex(c[first + 1]), vertex(c[first + 2])});
            } else if (corners > 3) {
                polygon.clear();
                for (std::size_t k = 0; k < corners; ++k) {
                    const auto at = std::size_t(c[first + k].vertex_index) * 3;
                    polygon.emplace_back(attrib.vertices[at], attrib.vertices[at + 1],
                                         attrib.vertices[at + 2]);
                }
                const polygon_triangles cut = triangulate_polygon(polygon);
                not_simple += cut.fanned;
                for (const auto& t : cut.triangles)
                    mesh.triangles.push_back({vertex(c[first + t[0]]), vertex(c[first + t[1]]),
                                              vertex(c[first + t[2]])});
            }
            first += corners;
        }
    }
    if (not_simple > 0)
        model.warnings.push_back(counted(not_simple, "polygon is", "polygons are") +
                                 " not simple (edges cross, or not flat): cut as fans, which "
                                 "may cover more than they do");
    if (mesh.triangles.empty())
        refuse(name, "holds no triangle (" + counted(d.positions, "vertex", "vertices") + ", " +
                         counted(points, "point", "points") + ", " +
                         counted(lines, "line", "lines") + "): not a mesh");
    return model;
}

obj_model read_obj(const std::string& path, std::size_t triangle_limit) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) refuse(path, "a folder, not a model file");
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error) refuse(path, "cannot read the model (" + error.message() + ")");
    if (size > max_obj_bytes)
        refuse(path, std::to_string(size) + " bytes: a model file may have at most " +
                         std::to_string(max_obj_bytes));
    std::ifstream in(path, std::ios::binary);
    std::string text(static_cast<std::size_t>(size), '\0');
    if (!in.read(text.data(), std::streamsize(size))) refuse(path, "cannot read the model");
    return parse_obj(text, path, triangle_limit);
}

std::shared_ptr<triangle_mesh> mesh_of_model(obj_model model, std::shared_ptr<material> mat,
                                             const std::string& name,
                                             std::vector<std::string>& warnings) {
    for (const std::string& warning : model.warnings) {
        std::string line = name;
        line.append(": ").append(warning);
        warnings.push_back(std::move(line));
    }
    auto mesh = std::make_shared<triangle_mesh>(std::move(model.mesh), std::move(mat));
    const std::size_t dropped = mesh->dropped_triangles();
    if (mesh->triangle_count() == 0)
        refuse(name, "every triangle is degenerate (" + std::to_string(dropped) +
                         " dropped): not a mesh");
    if (dropped > 0)
        warnings.push_back(name + ": " +
                           counted(dropped, "degenerate triangle", "degenerate triangles") +
                           " dropped (zero area, a vertex repeated, or a coordinate not finite)");
    return mesh;
}

std::shared_ptr<triangle_mesh> obj_mesh(const std::string& path, std::shared_ptr<material> mat,
                                        std::vector<std::string>& warnings) {
    return mesh_of_model(read_obj(path), std::move(mat), path, warnings);
}

}  // namespace rt
