#include "rt/image/image_io.h"

#include <stb/stb_image_write.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "rt/core/error.h"
#include "rt/image/display_encoding.h"

namespace rt {

namespace fs = std::filesystem;

namespace {

// stb compresses the whole image, then hands it over in one piece.
bool encode_png(const image& img, const byte_sink& sink) {
    std::vector<std::uint8_t> bytes(img.data().size());
    for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = to_srgb8(img.data()[i]);
    auto to_sink = [](void* context, void* data, int size) {
        (*static_cast<const byte_sink*>(context))(data, std::size_t(size));
    };
    return stbi_write_png_to_func(to_sink, const_cast<byte_sink*>(&sink), img.width(), img.height(),
                                  3, bytes.data(), img.width() * 3) != 0;
}

void encode_pfm(const image& img, const byte_sink& sink) {
    static_assert(std::endian::native == std::endian::little, "PFM writer assumes little-endian");
    const std::string header =
        "PF\n" + std::to_string(img.width()) + ' ' + std::to_string(img.height()) + "\n-1.0\n";
    sink(header.data(), header.size());
    const std::size_t row_floats = std::size_t(img.width()) * 3;
    for (int y = img.height() - 1; y >= 0; --y)  // PFM stores the bottom row first
        sink(img.data().data() + std::size_t(y) * row_floats, row_floats * sizeof(float));
}

}  // namespace

std::optional<image_format> format_of(const std::string& path) {
    const std::string ext = fs::path(path).extension().string();
    if (ext == ".png") return image_format::png;
    if (ext == ".pfm") return image_format::pfm;
    return std::nullopt;
}

bool encode_image(const image& img, image_format format, const byte_sink& sink) {
    if (format == image_format::png) return encode_png(img, sink);
    encode_pfm(img, sink);
    return true;
}

image read_pfm(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw user_error("cannot open '" + path + "'");
    std::string magic;
    int width = 0, height = 0;
    double scale = 0;
    in >> magic >> width >> height >> scale;
    if (magic != "PF" || width <= 0 || height <= 0 || scale == 0 || !in)
        throw user_error("'" + path + "' is not an RGB PFM file");
    in.get();  // the single whitespace character that ends the header

    // The pixels the header promises must be in the file before they are allocated: a header
    // alone may claim any size.
    const std::streampos data_start = in.tellg();
    in.seekg(0, std::ios::end);
    const std::streamoff data_bytes = in.tellg() - data_start;
    in.seekg(data_start);
    if (!in || data_bytes < 0 ||
        std::uintmax_t(data_bytes) / 12 / std::uintmax_t(width) < std::uintmax_t(height))
        throw user_error("'" + path + "' is truncated");

    const bool file_little_endian = scale < 0;
    const std::size_t row_floats  = std::size_t(width) * 3;
    std::vector<float> row(row_floats);
    image img(width, height);
    for (int y = height - 1; y >= 0; --y) {
        in.read(reinterpret_cast<char*>(row.data()), std::streamsize(row_floats * sizeof(float)));
        if (!in) throw user_error("'" + path + "' is truncated");
        if (file_little_endian != (std::endian::native == std::endian::little)) {
            for (float& f : row) {
                std::uint32_t bits;
                std::memcpy(&bits, &f, 4);
                bits = __builtin_bswap32(bits);
                std::memcpy(&f, &bits, 4);
            }
        }
        for (int x = 0; x < width; ++x)
            img.set(x, y,
                    color(row[std::size_t(x) * 3], row[std::size_t(x) * 3 + 1],
                          row[std::size_t(x) * 3 + 2]));
    }
    return img;
}

}  // namespace rt
