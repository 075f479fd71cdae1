// Fuzz target: texture files. Each input is written to a file and loaded through
// rt::image_texture, the code a chapter runs for --texture (header and size checks, the PNG
// guard, stb_image's decoders, compiled into this target). The contract checked:
//   - a file either loads, as a texture whose size is within the limit and whose every lookup
//     is a color in [0, 1], or
//   - is refused with a user_error of one line that names the file (the chapter's exit code 2);
//   - nothing else: no crash, no sanitizer finding, no other exception, no leak, and no hang
//     or runaway memory (tools/fuzz sets libFuzzer's -timeout and -rss_limit_mb).
// The texel limit here is 2^16 (256 x 256), not the real 2^26: the same comparison, and each
// input decodes in milliseconds, so the fuzzer spends its time on many inputs, not on a few
// large ones. The real limit is tested in tests/ch08/test_image_texture.cpp.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "rt/core/error.h"
#include "rt/textures/image_texture.h"

namespace {

constexpr std::int64_t fuzz_texel_limit = std::int64_t(1) << 16;

// One file per fuzzing process, rewritten for each input, removed at exit.
std::string input_path;

void remove_input() {
    std::remove(input_path.c_str());
}

[[noreturn]] void broken(const char* what, const std::string& detail) {
    std::fprintf(stderr, "fuzz_texture: %s: %s\n", what, detail.c_str());
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    input_path = (std::filesystem::temp_directory_path() /
                  ("rt_fuzz_texture_" + std::to_string(::getpid()) + ".img"))
                     .string();
    std::atexit(remove_input);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::FILE* file = std::fopen(input_path.c_str(), "wb");
    if (!file || std::fwrite(data, 1, size, file) != size || std::fclose(file) != 0)
        broken("cannot write the input file", input_path);
    try {
        const rt::image_texture texture(input_path, fuzz_texel_limit);
        const std::int64_t w = texture.width(), h = texture.height();
        if (w < 1 || h < 1 || w * h > fuzz_texel_limit)
            broken("loaded a texture of a refused size",
                   std::to_string(w) + " x " + std::to_string(h));
        // Every texel's row and column is reached: the corners, the center and a 5 x 5 grid.
        for (int i = 0; i <= 4; ++i) {
            for (int j = 0; j <= 4; ++j) {
                const rt::color c =
                    texture.value(rt::real(i) / 4, rt::real(j) / 4, rt::point3(0, 0, 0));
                for (int k = 0; k < 3; ++k)
                    if (!(c[k] >= 0 && c[k] <= 1))
                        broken("a texel outside [0, 1]", std::to_string(c[k]));
            }
        }
    } catch (const rt::user_error& e) {
        const std::string message = e.what();
        if (message.find("'" + input_path + "'") == std::string::npos)
            broken("the refusal does not name the file", message);
        if (message.find('\n') != std::string::npos) broken("the refusal is not one line", message);
    }
    return 0;
}
