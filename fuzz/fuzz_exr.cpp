// Fuzz target: OpenEXR files through read_exr_bytes (rt/files/exr_file.h), which tools/merge
// uses to read the parts of a split render. Any input must end in an image or a user_error,
// never a crash, a leak or undefined behaviour in our checks; and a header claiming a huge image
// must be refused before anything is allocated for its pixels (libFuzzer's -rss_limit_mb and
// malloc limit catch an allocation that grows with the claimed size). The library itself is
// Debian's, not instrumented: its bugs show here as crashes, not as sanitizer reports.
#include <cstddef>
#include <cstdint>

#include "rt/core/error.h"
#include "rt/files/exr_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        // At most 2^20 pixels: 12 MiB of floats, well under the fuzzer's memory limit.
        const rt::exr_image read = rt::read_exr_bytes(data, size, "input", 1LL << 20);
        if (read.pixels.width() <= 0 || read.pixels.height() <= 0) __builtin_trap();
    } catch (const rt::user_error&) {
    }
    return 0;
}
