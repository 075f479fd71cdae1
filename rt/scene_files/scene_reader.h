// Reading a scene file: a TOML file a person writes by hand, with comments, that says everything
// a chapter's C++ scene says (chapters/ch19_scene_files/README.md gives the format, scenes/ holds
// the book's scenes as files). Chapter 19.
// Every refusal is one line, "FILE:LINE:COLUMN: message", naming the key or value and what was
// expected: a TOML syntax error, an unknown key (a misspelt key is never silently ignored), a
// missing one, a value of the wrong kind or out of range, a name of no material, texture or
// named object, named objects that use each other in a cycle, objects nested too deep, a file
// too large, and a texture or model file that cannot be read (named as written and as resolved:
// relative to the scene file's folder). Nothing is rendered or written after a refusal.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "rt/scene_files/described_scene.h"
#include "rt/scene_files/scene_limits.h"

namespace rt {

// The format this reader reads: a file says `format = 1`. A later reader that changes the
// format reads or refuses a file by this number.
inline constexpr int scene_file_format = 1;

// The scene in the file at `path`; its size is checked before it is read.
described_scene read_scene_file(const std::string& path);

// The scene in `text`, named `file_name` in messages, its texture and model files found
// relative to `folder` (the fuzz target and the tests read text this way). Its meshes may hold
// `triangle_limit` triangles together (tests pass a smaller budget).
described_scene parse_scene_text(std::string_view text, const std::string& file_name,
                                 const std::string& folder,
                                 std::size_t triangle_limit = scene_limits::max_triangles);

}  // namespace rt
