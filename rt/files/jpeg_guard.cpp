#include "rt/files/jpeg_guard.h"

#include <array>
#include <string>
#include <tuple>

namespace rt {

namespace {

// Which Huffman tables the file has defined so far: [class: 0 DC, 1 AC][id 0..3].
using defined_tables = std::array<std::array<bool, 4>, 2>;

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
std::string huffman_problem(std::FILE* file, int length, bool& stop, defined_tables& defined) {
    auto byte = [file] {
        const int c = std::fgetc(file);
        return c == EOF ? 0 : c;
    };
    int left = length - 2;
    while (left > 0) {
        const int class_and_id = byte();
        const int table_class = class_and_id >> 4, id = class_and_id & 15;
        if (table_class > 1 || id > 3) {  // stb refuses it ("bad DHT header")
            stop = true;
            return "";
        }
        defined[table_class][id] = true;
        int codes                = 0;
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

// A scan (SOS segment) that decodes with a Huffman table no DHT segment before it defined: stb
// 2.27 then decodes with the uninitialized table in its heap block, and its own assertion or
// garbage follows (stb checks neither). Which tables a scan decodes with, as stb reads it: a
// baseline scan both of each component's; a progressive scan its DC tables in a first DC scan
// (start 0, high bit 0; refining DC bits reads no table) and its AC tables in an AC scan
// (start > 0). Returns the problem, or empty.
std::string scan_problem(std::FILE* file, int length, bool progressive,
                         const defined_tables& defined) {
    std::array<unsigned char, 4 + 2 * 4> header{};
    const auto size = std::size_t(length - 2);
    if (length < 2 || size > header.size() || std::fread(header.data(), 1, size, file) != size)
        return "";  // stb refuses a scan header of another length ("bad SOS len")
    const int components = header[0];
    if (components < 1 || components > 4 || size != 4 + 2 * std::size_t(components)) return "";
    const int start = header[1 + 2 * components], high_bit = header[3 + 2 * components] >> 4;
    const bool needs_dc = !progressive || (start == 0 && high_bit == 0);
    const bool needs_ac = !progressive || start > 0;
    for (int i = 0; i < components; ++i) {
        const int dc = header[2 + 2 * i] >> 4, ac = header[2 + 2 * i] & 15;
        for (const auto& [needed, table_class, id, name] :
             {std::tuple{needs_dc, 0, dc, "DC"}, std::tuple{needs_ac, 1, ac, "AC"}}) {
            if (needed && id <= 3 && !defined[std::size_t(table_class)][std::size_t(id)])
                return std::string("damaged or truncated image (a JPEG scan decodes with ") + name +
                       " Huffman table " + std::to_string(id) +
                       ", which no table before it defines)";
        }
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
    defined_tables defined{};
    bool progressive = false;
    for (;;) {
        const int marker = next_marker(file);
        if (marker == EOF || marker == 0xD9) return "";  // the end, or end of image
        if (marker == 0xD8 || marker == 0x01) continue;  // markers without a length
        std::array<unsigned char, 2> bytes{};
        if (std::fread(bytes.data(), 1, 2, file) != 2) return "";
        const int length = bytes[0] << 8 | bytes[1];
        if (marker == 0xC2) progressive = true;  // the frame header of a progressive JPEG
        if (marker == 0xC4) {
            bool stop = false;
            if (std::string problem = huffman_problem(file, length, stop, defined);
                !problem.empty())
                return problem;
            if (stop) return "";
        } else if (marker == 0xDA) {
            if (std::string problem = scan_problem(file, length, progressive, defined);
                !problem.empty())
                return problem;
        } else if (length < 2 || std::fseek(file, length - 2, SEEK_CUR) != 0) {
            return "";
        }
    }
}

}  // namespace rt
