#include "jpeg_guard.h"

#include <array>
#include <vector>

namespace rt {

namespace {

// The next marker: skips everything up to a 0xFF that is followed by neither 0x00 (a stuffed
// byte inside entropy-coded data), 0xFF (fill) nor a restart marker (0xD0-0xD7). EOF at the end.
int next_marker(std::FILE* file) {
    int c = std::fgetc(file);
    for (;;) {
        while (c != EOF && c != 0xFF) c = std::fgetc(file);
        if (c == EOF) return EOF;
        while (c == 0xFF) c = std::fgetc(file);
        if (c == EOF) return EOF;
        if (c != 0x00 && !(c >= 0xD0 && c <= 0xD7)) return c;
        c = std::fgetc(file);
    }
}

// The problem of one DHT segment's payload: one or more tables, each a class/id byte, 16 counts
// of codes by length, and as many symbols as the counts add up to. A table cut short by the end
// of the file counts what is there (stb reads 0 past the end).
std::string huffman_problem(const std::vector<unsigned char>& payload) {
    std::size_t at = 0;
    while (at < payload.size()) {
        int codes = 0;
        for (std::size_t i = at + 1; i <= at + 16 && i < payload.size(); ++i) codes += payload[i];
        if (codes > 256)
            return "damaged or truncated image (a JPEG Huffman table of " + std::to_string(codes) +
                   " codes, more than 256)";
        at += 17 + std::size_t(codes);
    }
    return "";
}

}  // namespace

std::string jpeg_table_problem(std::FILE* file) {
    struct rewind_at_end {
        std::FILE* f;
        ~rewind_at_end() { std::rewind(f); }
    } rewound{file};
    std::rewind(file);
    if (std::fgetc(file) != 0xFF || std::fgetc(file) != 0xD8) return "";
    for (;;) {
        const int marker = next_marker(file);
        if (marker == EOF || marker == 0xD9) return "";  // the end, or end of image
        if (marker == 0xD8 || marker == 0x01) continue;  // markers without a length
        std::array<unsigned char, 2> length{};
        if (std::fread(length.data(), 1, 2, file) != 2) return "";
        const int size = (length[0] << 8 | length[1]) - 2;
        if (size < 0) return "";
        std::vector<unsigned char> payload(std::size_t(size), 0);
        const std::size_t got = std::fread(payload.data(), 1, payload.size(), file);
        payload.resize(got);  // a segment cut short is checked as far as it goes
        if (marker == 0xC4)
            if (std::string problem = huffman_problem(payload); !problem.empty()) return problem;
        if (got < std::size_t(size)) return "";
    }
}

}  // namespace rt
