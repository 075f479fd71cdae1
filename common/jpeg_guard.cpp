#include "jpeg_guard.h"

#include <array>

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

// stb_image's reading of a DHT segment: tables one after another, each a class/id byte, 16
// counts of codes by length and as many symbols as the counts add up to, while the segment's
// length says there is more. Like stb, it reads the counts from the file whatever the length
// says (0 past the end), so a table that claims more than its segment holds is seen as stb sees
// it. Returns the problem, or empty with `stop` set when stb would stop reading the file here.
std::string huffman_problem(std::FILE* file, int length, bool& stop) {
    auto byte = [file] {
        const int c = std::fgetc(file);
        return c == EOF ? 0 : c;
    };
    int left = length - 2;
    while (left > 0) {
        byte();  // class and id
        int codes = 0;
        for (int i = 0; i < 16; ++i) codes += byte();
        if (codes > 256)
            return "damaged or truncated image (a JPEG Huffman table of " + std::to_string(codes) +
                   " codes, more than 256)";
        for (int i = 0; i < codes; ++i) byte();
        left -= 17 + codes;
    }
    stop = left != 0;  // stb refuses a segment whose tables do not fill it exactly
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
        std::array<unsigned char, 2> bytes{};
        if (std::fread(bytes.data(), 1, 2, file) != 2) return "";
        const int length = bytes[0] << 8 | bytes[1];
        if (marker == 0xC4) {
            bool stop = false;
            if (std::string problem = huffman_problem(file, length, stop); !problem.empty())
                return problem;
            if (stop) return "";
        } else if (length < 2 || std::fseek(file, length - 2, SEEK_CUR) != 0) {
            return "";
        }
    }
}

}  // namespace rt
