#include "rt/files/pnm_guard.h"

#include <algorithm>
#include <climits>
#include <cstdint>

namespace rt {

namespace {

bool is_space(int c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

// Reads the header as stb does: `c` is the character in hand; blanks and # comments (to the end
// of the line) are skipped, then the digits read, leaving the first character after them in
// hand. The value saturates just above INT_MAX instead of overflowing.
std::int64_t next_number(std::FILE* file, int& c) {
    for (;;) {
        while (is_space(c)) c = std::fgetc(file);
        if (c != '#') break;
        while (c != EOF && c != '\n' && c != '\r') c = std::fgetc(file);
    }
    std::int64_t value = 0;
    while (c >= '0' && c <= '9') {
        value = std::min<std::int64_t>(value * 10 + (c - '0'), std::int64_t(INT_MAX) + 1);
        c     = std::fgetc(file);
    }
    return value;
}

}  // namespace

std::string pnm_problem(std::FILE* file, bool check_data) {
    struct rewind_at_end {
        std::FILE* f;
        ~rewind_at_end() { std::rewind(f); }
    } rewound{file};
    std::rewind(file);
    const int p = std::fgetc(file), kind = std::fgetc(file);
    if (p != 'P' || (kind != '5' && kind != '6')) return "";
    int c                    = std::fgetc(file);
    const std::int64_t width = next_number(file, c), height = next_number(file, c);
    const std::int64_t max_value = next_number(file, c);
    for (std::int64_t n : {width, height, max_value})
        if (n > INT_MAX)
            return "damaged or truncated image (a number in its PPM/PGM header is above " +
                   std::to_string(INT_MAX) + ")";
    if (kind == '5' && max_value > 255)
        return "16-bit PGM images are not read (stb_image 2.27 reads past its buffer converting "
               "them to RGB)";
    // Sizes beyond 2^40 texels are the caller's limit to refuse (and would overflow below).
    if (!check_data || width < 1 || height < 1 || width * height > (std::int64_t(1) << 40))
        return "";
    // The texels start after the one character that ends the maximum value, now in hand.
    const long start = std::ftell(file);
    if (std::fseek(file, 0, SEEK_END) != 0 || start < 0) return "";
    const std::int64_t held   = std::int64_t(std::ftell(file)) - start;
    const std::int64_t needed = width * height * (kind == '6' ? 3 : 1) * (max_value > 255 ? 2 : 1);
    if (held < needed)
        return "damaged or truncated image (its PPM/PGM data holds " + std::to_string(held) +
               " bytes where its " + std::to_string(width) + " x " + std::to_string(height) +
               " texels need " + std::to_string(needed) + ")";
    return "";
}

}  // namespace rt
