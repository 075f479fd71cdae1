#include "rt/textures/image_texture.h"

#include <stb/stb_image.h>
#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <system_error>

#include "rt/core/error.h"
#include "rt/core/exercise.h"
#include "rt/files/jpeg_guard.h"
#include "rt/files/png_guard.h"
#include "rt/files/pnm_guard.h"
#include "rt/image/display_encoding.h"

namespace rt {

namespace {

// The book's reading: each byte over 255, taken as linear light.
const std::array<real, 256>& bytes_over_255() {
    static const std::array<real, 256> table = [] {
        std::array<real, 256> t{};
        for (int i = 0; i < 256; ++i) t[std::size_t(i)] = real(i / 255.0);
        return t;
    }();
    return table;
}

// 8-bit sRGB code -> linear light: 256 values, computed once for every texture.
const std::array<real, 256>& srgb8_to_linear() {
    static const std::array<real, 256> table = [] {
        std::array<real, 256> t{};
        for (int i = 0; i < 256; ++i) t[std::size_t(i)] = real(srgb_to_linear(i / 255.0));
        return t;
    }();
    return table;
}

[[noreturn]] void refuse(const std::string& path, const std::string& reason) {
    throw user_error("cannot read texture '" + path + "': " + reason);
}

// stb's reason for its last failure, in parentheses, or nothing: it gives none for some broken
// files (a PNG cut just before its end chunk). Some reasons quote the file's own bytes (an
// unknown PNG chunk "XXXX PNG chunk not known" names its four type bytes), which a hostile file
// can make a newline or an escape sequence: every byte outside printable ASCII is shown as \xNN,
// so the error stays one line of plain text.
std::string stb_reason() {
    const char* reason = stbi_failure_reason();
    if (!reason || !*reason) return "";
    std::string text = " (";
    for (const char* c = reason; *c; ++c) {
        const auto byte = static_cast<unsigned char>(*c);
        if (byte >= 0x20 && byte < 0x7f) {
            text += *c;
        } else {
            static const char hex[] = "0123456789abcdef";
            text += {'\\', 'x', hex[byte >> 4u], hex[byte & 15u]};
        }
    }
    return text + ")";
}

struct declared_size {
    std::int64_t width = 0, height = 0;
};

std::uint32_t big_endian(const unsigned char* b, int bytes) {
    std::uint32_t x = 0;
    for (int i = 0; i < bytes; ++i) x = x << 8 | b[i];
    return x;
}

// The size a PNG or JPEG header declares, read by hand from the file's start, or nothing. Used
// only to explain a file stbi_info refused: stb refuses a PNG or JPEG of more than 2^24 texels a
// side or 2^30 (PNG) or 2^31 (JPEG) bytes with the same "unknown image type" as a text file.
std::optional<declared_size> png_or_jpeg_size(std::FILE* file) {
    std::array<unsigned char, 24> head{};
    std::rewind(file);
    const std::size_t got = std::fread(head.data(), 1, head.size(), file);
    // PNG: the 8-byte signature, then the IHDR chunk (length, "IHDR", width, height, ...).
    if (got == 24 && std::memcmp(head.data(), "\x89PNG\r\n\x1a\n", 8) == 0 &&
        std::memcmp(head.data() + 12, "IHDR", 4) == 0)
        return declared_size{big_endian(&head[16], 4), big_endian(&head[20], 4)};
    if (got < 2 || head[0] != 0xFF || head[1] != 0xD8) return std::nullopt;
    // JPEG: segments "FF marker length(2) ...", until a start of frame: precision(1), height(2),
    // width(2). Every step moves forward, so the walk ends at the end of the file.
    std::rewind(file);
    std::fseek(file, 2, SEEK_SET);
    for (;;) {
        std::array<unsigned char, 4> segment{};
        if (std::fread(segment.data(), 1, 4, file) != 4 || segment[0] != 0xFF) return std::nullopt;
        const int marker  = segment[1];
        const long length = long(big_endian(&segment[2], 2));
        const bool frame =
            marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
        if (frame) {
            std::array<unsigned char, 5> sof{};
            if (std::fread(sof.data(), 1, 5, file) != 5) return std::nullopt;
            return declared_size{big_endian(&sof[3], 2), big_endian(&sof[1], 2)};
        }
        if (length < 2 || std::fseek(file, length - 2, SEEK_CUR) != 0) return std::nullopt;
    }
}

// Whether the file starts as a PNG, a JPEG or a binary PPM (P6) or PGM (P5) does. stb_image
// reads more formats (BMP, TGA, GIF, PSD, PIC, HDR), but we take only these three. Leaves the
// file rewound.
bool readable_format(std::FILE* file) {
    std::array<unsigned char, 8> head{};
    std::rewind(file);
    const std::size_t got = std::fread(head.data(), 1, head.size(), file);
    std::rewind(file);
    const bool png  = got == 8 && std::memcmp(head.data(), "\x89PNG\r\n\x1a\n", 8) == 0;
    const bool jpeg = got >= 3 && head[0] == 0xFF && head[1] == 0xD8 && head[2] == 0xFF;
    const bool pnm  = got >= 2 && head[0] == 'P' && (head[1] == '5' || head[1] == '6');
    return png || jpeg || pnm;
}

}  // namespace

void image_texture::stb_free::operator()(unsigned char* pixels) const {
    stbi_image_free(pixels);
}

namespace {
texel_decoding scene_default = texel_decoding::srgb;
}  // namespace

texel_decoding default_texel_decoding() {
    return scene_default;
}

void set_default_texel_decoding(texel_decoding d) {
    scene_default = d;
}

image_texture::image_texture(const std::string& path, std::int64_t texel_limit, texel_decoding d)
    : decoding(d) {
    given_path = path;  // [ch19]
    // One open file for the header and the pixels, so both are read from the same file.
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                         std::fclose);
    if (!file) refuse(path, std::error_code(errno, std::generic_category()).message());
    // A folder opens but cannot be read; a pipe or device cannot seek back after the header.
    struct stat about {};
    if (fstat(fileno(file.get()), &about) != 0 || !S_ISREG(about.st_mode))
        refuse(path, S_ISDIR(about.st_mode) ? "it is a folder" : "it is not a regular file");
    if (about.st_size == 0) refuse(path, "the file is empty");

    // Only the formats the fuzz target covers reach stb_image (each of its other decoders is one
    // more that a hostile file could reach), and JPEG tables stb 2.27 overflows never do.
    if (!readable_format(file.get())) refuse(path, "not a PNG, JPEG or binary PPM/PGM image");
    if (std::string problem = jpeg_table_problem(file.get()); !problem.empty())
        refuse(path, problem);
    if (std::string problem = pnm_problem(file.get(), false); !problem.empty())
        refuse(path, problem);

    // The header next: the size is checked before stb allocates anything.
    auto refuse_size = [&](std::int64_t width, std::int64_t height) {
        throw user_error("texture '" + path + "' must have at most " + std::to_string(texel_limit) +
                         " texels" + (texel_limit == max_texels ? " (2^26)" : "") + ", got " +
                         std::to_string(width) + " x " + std::to_string(height));
    };
    int header_w = 0, header_h = 0, channels = 0;
    if (!stbi_info_from_file(file.get(), &header_w, &header_h, &channels)) {
        auto size = png_or_jpeg_size(file.get());
        // Each side below 2^32: the product fits 64 unsigned bits (found by the fuzz target).
        if (size &&
            std::uint64_t(size->width) * std::uint64_t(size->height) > std::uint64_t(texel_limit))
            refuse_size(size->width, size->height);
        refuse(path, "damaged or truncated image (its header cannot be read)");
    }
    if (header_w < 1 || header_h < 1 || std::int64_t(header_w) * header_h > texel_limit)
        refuse_size(header_w, header_h);

    // A PNG's data is inflated once within a bound first: stb would inflate a bomb whole. A
    // PPM/PGM must hold all its texels: stb would leave the missing ones unwritten.
    if (std::string problem = png_data_problem(file.get()); !problem.empty()) refuse(path, problem);
    if (std::string problem = pnm_problem(file.get(), true); !problem.empty())
        refuse(path, problem);

    unsigned char* pixels = stbi_load_from_file(file.get(), &w, &h, &channels, 3);
    texels.reset(pixels);
    if (!pixels) refuse(path, "damaged or truncated image" + stb_reason());
    // stb reads the same header twice; should a decoder ever disagree with its own header, the
    // buffer would not be the size the limit was checked on.
    if (w != header_w || h != header_h)
        refuse(path, "its header says " + std::to_string(header_w) + " x " +
                         std::to_string(header_h) + " but its image is " + std::to_string(w) +
                         " x " + std::to_string(h));
}

color image_texture::value(real u, real v, const point3&) const {
    // Clamp to [0, 1]; the negated comparisons also send NaN to 0.
    // [exercise image_texture::value begin]
    u                      = !(u > 0) ? 0 : std::min(u, real(1));
    v                      = !(v > 0) ? 0 : std::min(v, real(1));
    int col                = std::min(int(u * real(w)), w - 1);
    int row                = std::min(int((1 - v) * real(h)), h - 1);
    const unsigned char* t = texels.get() + 3 * (std::size_t(row) * std::size_t(w) + col);
    const auto& linear = decoding == texel_decoding::srgb ? srgb8_to_linear() : bytes_over_255();
    return color(linear[t[0]], linear[t[1]], linear[t[2]]);
    // [exercise image_texture::value end]
}

}  // namespace rt
