// Reading a Wavefront OBJ model into a mesh's vertices and triangles. Chapter 18.
// The parsing is Debian's tinyobjloader (its double-precision build). It has no limits of its
// own, so the file's size and its counts of vertices and face corners are checked first, on the
// raw text, before it reads anything: a model too big is refused before memory is taken.
// What a model may hold, and what becomes of it:
// - polygons (up to 255 corners, tinyobjloader's limit; more is refused): cut into triangles by
//   ear clipping (polygon_triangulation.h), concave ones too;
// - points (p), lines (l) and faces of fewer than 3 corners: no surface to hit, ignored, with
//   one warning;
// - lines of other kinds (skin weights vw, tags t, free-form curves...): comments before
//   tinyobjloader reads them, with one warning (it has faults on some of them);
// - normals (vn) and texture coordinates (vt): kept per vertex when every face corner names one,
//   else dropped with one warning (a mesh has them on every vertex or none);
// - materials (mtllib, usemtl): ignored, with one warning; the scene gives the material;
// - a vertex is stored once per distinct (position, uv, normal) triple the faces use;
// - no triangle at all, an index outside the file's vertices, UTF-16 text, a NUL byte, or
//   anything tinyobjloader cannot read: refused, with the file's name and, where known, line.
// Degenerate triangles are the mesh's to drop (triangle_mesh.h): mesh_of_model() adds their
// count to the warnings, and refuses a model with none left.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "rt/geometry/triangle_mesh.h"

namespace rt {

struct obj_model {
    mesh_data mesh;
    std::vector<std::string> warnings;  // one line each, without the file's name
};

// The most bytes a model file may have: a million-triangle scan is about 60 MB of text.
inline constexpr std::uintmax_t max_obj_bytes = std::uintmax_t(1) << 30;

// The model in `text`, named `name` in messages. Throws user_error ("NAME: ...") for what is
// refused.
// A model declaring more than `triangle_limit` triangles (after triangulation) is refused before
// tinyobjloader reads it; the limit is at most triangle_mesh::max_triangles (a scene with
// several models passes what is left of its own budget).
obj_model parse_obj(const std::string& text, const std::string& name,
                    std::size_t triangle_limit = triangle_mesh::max_triangles);

// The model in the file at `path` (read whole, after its size is checked).
obj_model read_obj(const std::string& path,
                   std::size_t triangle_limit = triangle_mesh::max_triangles);

// The model as a mesh of `mat`; its warnings, and the count of degenerate triangles the mesh
// dropped, added to `warnings`, each starting with `name`. Refused when no triangle is left.
std::shared_ptr<triangle_mesh> mesh_of_model(obj_model model, std::shared_ptr<material> mat,
                                             const std::string& name,
                                             std::vector<std::string>& warnings);

// The file's model as a mesh of `mat`: read_obj, then mesh_of_model.
std::shared_ptr<triangle_mesh> obj_mesh(const std::string& path, std::shared_ptr<material> mat,
                                        std::vector<std::string>& warnings);

}  // namespace rt
