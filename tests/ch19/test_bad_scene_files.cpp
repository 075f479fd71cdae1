// Bad scene files (chapter 19): each refused with one line "FILE:LINE:COLUMN: message" that
// names the key or value and what was expected, pointing at the value itself (or at the table
// that lacks a key). One row per kind of mistake a teacher or a student makes, and the hostile
// files a reader must survive: cycles, nesting without end, a file too large.
#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "rt/core/error.h"
#include "rt/program/asset_path.h"
#include "rt/scene_files/scene_limits.h"
#include "rt/scene_files/scene_reader.h"
#include "test_helpers.h"

namespace {

namespace fs = std::filesystem;

std::string refusal(const std::string& text, const std::string& folder = "") {
    try {
        rt::parse_scene_text(text, "bad.toml", folder);
        return "(read without an error)";
    } catch (const rt::user_error& e) {
        return e.what();
    }
}

struct bad_file {
    const char* mistake;
    std::string text;
    const char* place;    // where the message points: "bad.toml:LINE:COLUMN: "
    const char* message;  // what it says there (a part of it)
};

const std::string header = "format = 1\n";
const std::string matte =
    "[materials]\nmatte = { type = \"lambertian\", albedo = [0.5, 0.5, 0.5] }\n";

}  // namespace

TEST_CASE("every bad file is refused with its line, column and what was expected", "[ch19]") {
    const std::vector<bad_file> rows = {
        {"TOML syntax", header + "[render\nwidth = 4\n", "bad.toml:2:8: ", "expected ']'"},
        {"no format key", "[render]\nwidth = 4\n", "bad.toml:1:1: ", "scene file needs 'format'"},
        {"a later format", "format = 2\n",
         "bad.toml:1:10: ", "format 2 is newer than this program reads (format 1)"},
        {"a misspelt key",
         header + "[world]\nobjects = [{ type = \"sphere\", center = [0, 0, 0], "
                  "raduis = 1 }]\n",
         "bad.toml:3:51: ", "unknown key 'raduis' in sphere"},
        {"a misspelt section", header + "[camra]\nvfov = 20\n",
         "bad.toml:2:2: ", "unknown key 'camra' in scene file"},
        {"a missing key",
         header + "[world]\nobjects = [{ type = \"sphere\", center = [0, 0, 0] }]\n",
         "bad.toml:3:12: ", "sphere needs 'radius'"},
        {"an unknown type", header + "[world]\nobjects = [{ type = \"cone\" }]\n",
         "bad.toml:3:21: ", "type must be \"sphere\", \"moving-sphere\", \"quad\", \"box\""},
        {"a number where a point is expected",
         header + "[world]\nobjects = [{ type = \"sphere\", center = 3, radius = 1 }]\n",
         "bad.toml:3:40: ", "center must be three numbers [x, y, z], got 3"},
        {"a string where a number is expected", header + "[render]\nwidth = \"wide\"\n",
         "bad.toml:3:9: ", "width must be an integer in [1, 16384], got \"wide\""},
        {"a width out of range", header + "[render]\nwidth = 0\n",
         "bad.toml:3:9: ", "width must be an integer in [1, 16384], got 0"},
        {"an unknown integrator", header + "[render]\nintegrator = \"photon\"\n",
         "bad.toml:3:14: ", "integrator must be sky, normals, path, light or mis"},
        {"a negative radius",
         header + matte +
             "[world]\nobjects = [{ type = \"sphere\", center = [0, 0, 0], radius = -1, "
             "material = \"matte\" }]\n",
         "bad.toml:5:60: ", "radius must be a number in (0, 1000000], got -1"},
        {"an infinite coordinate",
         header + "[world]\nobjects = [{ type = \"sphere\", center = [0, inf, 0], radius = 1 }]\n",
         "bad.toml:3:44: ", "center[1] must be a number in [-1000000, 1000000], got inf"},
        {"not a number", header + "[camera]\nvfov = nan\n",
         "bad.toml:3:8: ", "vfov must be a number in (0, 180), got nan"},
        {"a coordinate beyond the limit", header + "[camera]\nlookfrom = [0, 0, 1e7]\n",
         "bad.toml:3:19: ", "lookfrom[2] must be a number in [-1000000, 1000000], got 1e+07"},
        {"a field of view of 180 degrees", header + "[camera]\nvfov = 180\n",
         "bad.toml:3:8: ", "vfov must be a number in (0, 180), got 180"},
        {"an albedo above 1 (made by the constructor, placed by the reader)",
         header + "[materials]\nbright = { type = \"lambertian\", albedo = [1.5, 0, 0] }\n",
         "bad.toml:3:42: ", "lambertian albedo must be in [0, 1] per channel"},
        {"a negative radiance", header + "[sky]\ncolor = [0, -1, 0]\n",
         "bad.toml:3:9: ", "color must be three numbers >= 0"},
        {"numbers below 1 in a refused array (shown as written, not by toml++'s array layout)",
         header + "[sky]\ncolor = [0.05, -0.5, 0]\n",
         "bad.toml:3:9: ", "color must be three numbers >= 0, got [0.05, -0.5, 0]"},
        {"a shutter closing before it opens", header + "[camera]\nshutter = [1, 0]\n",
         "bad.toml:3:11: ", "shutter must open before it closes"},
        {"an undefined material",
         header + matte +
             "[world]\nobjects = [{ type = \"sphere\", center = [0, 0, 0], radius = 1, "
             "material = \"glass\" }]\n",
         "bad.toml:5:74: ", "no material named 'glass' (defined: matte)"},
        {"an undefined texture",
         header + "[materials]\nm = { type = \"lambertian\", albedo = \"wood\" }\n",
         "bad.toml:3:37: ", "no texture named 'wood' (none is defined)"},
        {"an undefined named object", header + "[world]\nobjects = [{ use = \"table\" }]\n",
         "bad.toml:3:20: ", "no named object named 'table'"},
        {"named objects in a cycle",
         header + "[named_objects.a]\nuse = \"b\"\n[named_objects.b]\nuse = \"a\"\n"
                  "[world]\nobjects = [\"a\"]\n",
         "bad.toml:5:7: ", "named objects use each other in a cycle: a -> b -> a"},
        {"a named object that uses itself",
         header + "[named_objects.a]\ntype = \"group\"\nobjects = [\"a\"]\n",
         "bad.toml:4:12: ", "named objects use each other in a cycle: a -> a"},
        {"a texture made of itself",
         header +
             "[textures]\nt = { type = \"checker\", scale = 1, even = \"t\", odd = [0, 0, 0] }\n",
         "bad.toml:3:43: ", "texture 't' is made of itself"},
        {"both type and use",
         header + "[named_objects.a]\ntype = \"group\"\nobjects = []\n"
                  "[world]\nobjects = [{ type = \"group\", use = \"a\", objects = [] }]\n",
         "bad.toml:6:12: ", "has either 'type' (a new object) or 'use' (a named one)"},
        {"a list moved by a transform",
         header + "[world]\nobjects = [{ type = \"group\", objects = [], transform = "
                  "[{ translate = [1, 0, 0] }] }]\n",
         "bad.toml:3:57: ", "a group with bvh = false has none (give it bvh = true)"},
        {"a transform step of neither kind",
         header + "[world]\nobjects = [{ type = \"group\", bvh = true, objects = [], transform = "
                  "[{ scale = 2 }] }]\n",
         "bad.toml:3:71: ",
         "unknown key 'scale' in transform step (its keys: translate, rotate, "
         "degrees)"},
        {"an empty transform step",
         header + "[world]\nobjects = [{ type = \"group\", bvh = true, objects = [], transform = "
                  "[{}] }]\n",
         "bad.toml:3:69: ", "transform step needs 'translate' or 'rotate'"},
        {"a rotation about no axis",
         header + "[world]\nobjects = [{ type = \"group\", bvh = true, objects = [], transform = "
                  "[{ rotate = \"w\", degrees = 2 }] }]\n",
         "bad.toml:3:80: ", "rotate must be \"x\", \"y\" or \"z\", got \"w\""},
        {"quad edges that span no area",
         header + matte +
             "[world]\nobjects = [{ type = \"quad\", corner = [0, 0, 0], u = [1, 0, 0], "
             "v = [2, 0, 0], material = \"matte\" }]\n",
         "bad.toml:5:12: ", "quad edges must span an area"},
        {"a flat box",
         header + matte +
             "[world]\nobjects = [{ type = \"box\", corners = [[0, 0, 0], "
             "[1, 0, 1]], material = \"matte\" }]\n",
         "bad.toml:5:38: ", "box corners must differ in every coordinate"},
        {"a sky with a colour and a gradient",
         header + "[sky]\ncolor = [0, 0, 0]\ntop = [1, 1, 1]\n",
         "bad.toml:2:1: ", "sky has either 'color'"},
        {"an aspect ratio that is no ratio", header + "[camera]\naspect_ratio = \"wide\"\n",
         "bad.toml:3:16: ", "aspect_ratio must be a number > 0 or \"W:H\""},
        {"a missing texture file",
         header + "[textures]\nt = { type = \"image\", file = \"no_such_map.png\" }\n",
         "bad.toml:3:30: ", "texture file 'no_such_map.png' (resolved: scenes/no_such_map.png): "},
        {"a missing model file",
         header + matte +
             "[world]\nobjects = [{ type = \"mesh\", file = \"../teapot.obj\", "
             "material = \"matte\" }]\n",
         "bad.toml:5:36: ", "model file '../teapot.obj' (resolved: teapot.obj): "},
        {"a model file that is not a model",
         header + matte +
             "[world]\nobjects = [{ type = \"mesh\", file = \"/etc/hostname\", "
             "material = \"matte\" }]\n",
         "bad.toml:5:36: ", "model file '/etc/hostname' (resolved: /etc/hostname): "},
        {"a boolean cut short (toml++ quotes the line's end it saw: shown as \\n)",
         header + "[render]\nseed = t\n", "bad.toml:3:9: ", "expected 'true', saw 't\\n'"},
        {"a quoted key holding a newline", header + "\"a\\nb\" = 1\n",
         "bad.toml:2:1: ", "unknown key 'a\\nb' in scene file"},
        {"a character outside ASCII between tokens (toml++ 3.3.0 would misread it: refused first)",
         header + "[render]\nwidth = 4 \xcc\xaa\n",
         "bad.toml:3:11: ", "a character outside ASCII stands outside a string or a comment"},
        {"a bare key outside ASCII", header + "caf\xc3\xa9 = 1\n",
         "bad.toml:2:4: ", "a character outside ASCII stands outside a string or a comment"},
        {"a quote after a number opens no string: toml++ reads on to the value's end",
         header + "[render]\nwidth = 4'\xc3\xa9'\n",
         "bad.toml:3:11: ", "a character outside ASCII in a value that starts as a number"},
        {"a quote after a date and a blank opens no string either",
         header + "[render]\nseed = [1979-05-27 \"\xc3\xa9\"]\n",
         "bad.toml:3:21: ", "a character outside ASCII in a value that starts as a number"},
        {"a character outside ASCII after a line-ending backslash",
         header + "s = \"\"\"\\\n\xc2\xa7\"\"\"\n",
         "bad.toml:3:1: ", "a character outside ASCII right after a line-ending backslash"},
        {"a backslash before a character outside ASCII in a multi-line string",
         header + "s = \"\"\"\n\\\xc2\xa7\"\"\"\n",
         "bad.toml:3:1: ", "a backslash before a character outside ASCII in a string"},
        {"a duplicated key (TOML refuses it)", header + "[render]\nwidth = 4\nwidth = 5\n",
         "bad.toml:4:9: ", "cannot redefine existing integer 'width'"},
    };
    for (const bad_file& row : rows) {
        INFO(row.mistake << "\n--- file:\n" << row.text);
        const std::string message = refusal(row.text, "scenes");
        CHECK(message.rfind(row.place, 0) == 0);
        CHECK_THAT(message, Catch::Contains(row.message));
        CHECK(message.find('\n') == std::string::npos);  // one line
    }
}

TEST_CASE("objects nested beyond the limit are refused, not followed", "[ch19]") {
    // 100 groups inside each other: a hostile file must not exhaust the stack.
    std::string nested = "{ type = \"group\", objects = [] }";
    for (int i = 0; i < 100; ++i) nested = "{ type = \"group\", objects = [" + nested + "] }";
    const std::string message = refusal(header + "[world]\nobjects = [" + nested + "]\n");
    CHECK_THAT(message, Catch::Contains("nested more than " +
                                        std::to_string(rt::scene_limits::max_nesting) + " deep"));
    CHECK(message.rfind("bad.toml:3:", 0) == 0);
}

TEST_CASE("a file too large is refused before it is read", "[ch19]") {
    const rt_test::temp_folder folder("ch19", "too_large");
    const fs::path path = folder.file("scene.toml");
    {
        std::ofstream out(path);
        out << "format = 1\n";
    }
    // A sparse file: its size says too large, though it holds almost nothing.
    fs::resize_file(path, rt::scene_limits::max_file_bytes + 1);
    std::string message;
    try {
        rt::read_scene_file(path.string());
    } catch (const rt::user_error& e) {
        message = e.what();
    }
    CHECK_THAT(message, Catch::Contains(
                            "must be at most " + std::to_string(rt::scene_limits::max_file_bytes) +
                            " bytes, got " + std::to_string(rt::scene_limits::max_file_bytes + 1)));
}

TEST_CASE("a missing or unreadable scene file is named", "[ch19]") {
    auto refused = [](const std::string& path) {
        try {
            rt::read_scene_file(path);
        } catch (const rt::user_error& e) {
            return std::string(e.what());
        }
        return std::string("(read)");
    };
    CHECK_THAT(refused("no/such/scene.toml"),
               Catch::Contains("cannot read scene file 'no/such/scene.toml'"));
    CHECK_THAT(refused(fs::temp_directory_path().string()),
               Catch::Contains("is not a regular file"));
}

TEST_CASE("meshes beyond the scene's triangle budget are refused before they are read", "[ch19]") {
    // Two bunnies of 3,674 triangles each, in a budget of 5,000: the second model declares more
    // than the 1,326 left, and is refused at its file's first face beyond them.
    const std::string assets = fs::path(rt::asset_path("globe.png")).parent_path().string();
    const std::string bunny =
        "{ type = \"mesh\", file = \"models/bunny.obj\", material = \"matte\" }";
    const std::string text = header + matte + "[world]\nobjects = [" + bunny + ", " + bunny + "]\n";
    std::string message;
    try {
        rt::parse_scene_text(text, "bad.toml", assets, 5000);
    } catch (const rt::user_error& e) {
        message = e.what();
    }
    CHECK(message.rfind("bad.toml:5:", 0) == 0);
    CHECK_THAT(message, Catch::Contains("more than 1326 triangles"));
    CHECK_NOTHROW(rt::parse_scene_text(text, "good.toml", assets, 2 * 3674));
}
