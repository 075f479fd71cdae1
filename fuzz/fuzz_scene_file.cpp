// Fuzz target: scene files (chapter 19). Each input is read by rt::parse_scene_text (our reader,
// and toml++ compiled into this target: toml.cpp); texture and model files are looked for beside
// the book's committed scenes (assets/scenes/book). The contract checked:
//   - a file is refused with a user_error of one line that starts with its name and the place
//     ("fuzz.toml:LINE:COLUMN: "), or
//   - it is read, and then written (rt::scene_file_text) and read again, the second writing is
//     the first, character for character (what a file says survives the round trip); and rays
//     into the world give finite hits;
//   - nothing else: no crash, no sanitizer finding, no other exception, no leak, no hang or
//     runaway memory (tools/fuzz sets libFuzzer's -timeout and -rss_limit_mb).
// A path that climbs out of assets/ or starts at the root is left alone (the input is skipped):
// reading the machine's other files is not the reader's contract, and fuzz_texture and fuzz_obj
// fuzz the file formats themselves.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "rt/core/error.h"
#include "rt/scene_files/scene_reader.h"
#include "rt/scene_files/scene_writer.h"

#ifndef RT_SCENE_FOLDER
#error "RT_SCENE_FOLDER: the folder of the committed scenes (fuzz/CMakeLists.txt defines it)"
#endif

namespace {

const std::string name = "fuzz.toml";

[[noreturn]] void broken(const char* what, const std::string& detail) {
    std::fprintf(stderr, "fuzz_scene_file: %s: %s\n", what, detail.c_str());
    std::abort();
}

bool finite(const rt::vec3& v) {
    return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    for (const char* outside : {"\"/", "'/", "../../..", "\\u", "\\U"})
        if (text.find(outside) != std::string::npos) return 0;
    std::string first;
    try {
        const rt::described_scene read = rt::parse_scene_text(text, name, RT_SCENE_FOLDER);
        first                          = rt::scene_file_text(read, RT_SCENE_FOLDER, "fuzz");
        for (const rt::vec3& d : {rt::vec3(0, 0, -1), rt::vec3(1, -1, 0.5), rt::vec3(0, -1, 0)}) {
            rt::hit_record rec;
            const rt::ray r(rt::point3(0.25, 1, 3), d);
            if (!read.scene.world->hit(r, rt::interval(0, rt::infinity), rec)) continue;
            if (!finite(rec.p) || !std::isfinite(rec.t) || !finite(rec.normal))
                broken("a hit that is not finite", std::to_string(rec.t));
        }
    } catch (const rt::user_error& e) {
        const std::string message = e.what();
        if (message.rfind(name + ":", 0) != 0)
            broken("the refusal does not name the file", message);
        if (message.find('\n') != std::string::npos) broken("the refusal is not one line", message);
        return 0;
    }
    // What was read, written and read again, is written the same.
    try {
        const rt::described_scene again =
            rt::parse_scene_text(first, "written.toml", RT_SCENE_FOLDER);
        const std::string second = rt::scene_file_text(again, RT_SCENE_FOLDER, "fuzz");
        if (second != first) broken("the written file, read and written again, differs", first);
    } catch (const rt::user_error& e) {
        broken("the written file is refused", std::string(e.what()) + "\n" + first);
    }
    return 0;
}
