#include "rt/files/png_guard.h"

#include <stb/stb_image.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

namespace rt {

namespace {

std::uint32_t big_endian32(const unsigned char* b) {
    return std::uint32_t(b[0]) << 24 | std::uint32_t(b[1]) << 16 | std::uint32_t(b[2]) << 8 | b[3];
}

// What IHDR says: the size, the bits of one texel (bit depth x channels) and the interlacing.
struct png_header {
    std::int64_t width = 0, height = 0;
    int bits_per_texel = 0;  // 0: a color type or depth stb will refuse anyway
    bool interlaced    = false;
};

png_header read_header(const std::array<unsigned char, 13>& ihdr) {
    png_header h;
    h.width                   = big_endian32(&ihdr[0]);
    h.height                  = big_endian32(&ihdr[4]);
    const int depth           = ihdr[8];
    const int color_type      = ihdr[9];
    constexpr int channels[7] = {1, 0, 3, 1,
                                 2, 0, 4};  // gray, -, RGB, palette, gray+alpha, -, RGBA
    if (color_type <= 6 && (depth == 1 || depth == 2 || depth == 4 || depth == 8 || depth == 16))
        h.bits_per_texel = channels[color_type] * depth;
    h.interlaced = ihdr[12] == 1;
    return h;
}

// The bytes of raw image data the header asks for: each row is a filter byte and its texels.
std::int64_t needed_bytes(const png_header& h) {
    auto rows = [&](std::int64_t width, std::int64_t height) {
        return width > 0 && height > 0 ? height * (1 + (width * h.bits_per_texel + 7) / 8) : 0;
    };
    if (!h.interlaced) return rows(h.width, h.height);
    // Adam7: seven sub-images, each on its own grid (first texel, spacing) of the image.
    constexpr int x0[7] = {0, 4, 0, 2, 0, 1, 0}, y0[7] = {0, 0, 4, 0, 2, 0, 1};
    constexpr int dx[7] = {8, 8, 4, 4, 2, 2, 1}, dy[7] = {8, 8, 8, 4, 4, 2, 2};
    std::int64_t total = 0;
    for (int p = 0; p < 7; ++p)
        total +=
            rows((h.width - x0[p] + dx[p] - 1) / dx[p], (h.height - y0[p] + dy[p] - 1) / dy[p]);
    return total;
}

}  // namespace

std::string png_data_problem(std::FILE* file) {
    struct rewind_at_end {
        std::FILE* f;
        ~rewind_at_end() { std::rewind(f); }
    } rewound{file};
    if (std::fseek(file, 0, SEEK_END) != 0) return "";
    const long file_size = std::ftell(file);
    std::rewind(file);
    std::array<unsigned char, 8> signature{};
    if (std::fread(signature.data(), 1, 8, file) != 8 ||
        std::memcmp(signature.data(), "\x89PNG\r\n\x1a\n", 8) != 0)
        return "";

    // The chunks: length, type, data, CRC. Only IHDR and IDAT matter here.
    png_header header;
    bool apple = false;      // Apple's "CgBI" PNGs hold a bare deflate stream, without zlib's
    std::vector<char> data;  // header; stb reads them too. The IDAT chunks, concatenated.
    for (;;) {
        std::array<unsigned char, 8> head{};
        if (std::fread(head.data(), 1, 8, file) != 8) break;
        const std::uint32_t length = big_endian32(&head[0]);
        const long left            = file_size - std::ftell(file);
        if (left < 0 || std::int64_t(length) + 4 > left)
            return "damaged or truncated image (a PNG chunk runs past the end of the file)";
        const char* type = reinterpret_cast<const char*>(&head[4]);
        if (std::memcmp(type, "IHDR", 4) == 0 && length == 13) {
            std::array<unsigned char, 13> ihdr{};
            if (std::fread(ihdr.data(), 1, 13, file) != 13) return "";
            header = read_header(ihdr);
        } else if (std::memcmp(type, "IDAT", 4) == 0) {
            // Legal, but stb_image (2.27) copies an empty first IDAT to its still-null buffer
            // plus 0, which is undefined behaviour; no encoder writes one.
            if (length == 0 && data.empty())
                return "unsupported image (an empty PNG IDAT chunk before any image data)";
            const std::size_t at = data.size();
            data.resize(at + length);
            if (std::fread(data.data() + at, 1, length, file) != length) return "";
        } else if (std::memcmp(type, "IEND", 4) == 0) {
            break;
        } else {
            apple = apple || std::memcmp(type, "CgBI", 4) == 0;
            if (std::fseek(file, long(length), SEEK_CUR) != 0) return "";
        }
        if (std::fseek(file, 4, SEEK_CUR) != 0) return "";  // the CRC (stb checks none either)
    }
    // Sizes the caller's texel limit refuses anyway (and whose byte counts could overflow) are
    // left to it, as are files stb refuses without inflating anything.
    if (header.bits_per_texel == 0 || header.width > INT_MAX || header.height > INT_MAX ||
        header.width * header.height > (std::int64_t(1) << 40) || data.empty() ||
        data.size() > std::size_t(INT_MAX))
        return "";

    const std::int64_t needed = needed_bytes(header);
    const std::int64_t room   = std::min<std::int64_t>(2 * needed + (1 << 20), INT_MAX);
    // Not zeroed: only the pages the stream fills are ever touched.
    auto buffer = std::make_unique_for_overwrite<char[]>(std::size_t(room));
    const int got =
        apple ? stbi_zlib_decode_noheader_buffer(buffer.get(), int(room), data.data(),
                                                 int(data.size()))
              : stbi_zlib_decode_buffer(buffer.get(), int(room), data.data(), int(data.size()));
    if (got < 0)
        return "damaged or truncated image (its PNG data is corrupt, or inflates to more than " +
               std::to_string(room) + " bytes where its " + std::to_string(header.width) + " x " +
               std::to_string(header.height) + " texels need " + std::to_string(needed) + ")";
    return "";
}

}  // namespace rt
