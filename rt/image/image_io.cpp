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

std::string extension_of(const std::string& path) {
    return fs::path(path).extension().string();
}

// Through our own sink: stbi_write_png ignores fwrite/fclose errors (a full disk would give a
// truncated PNG and "success"); temporary_file remembers them. stb compresses the whole image,
// then hands it over in one piece.
void write_png(temporary_file& file, const std::string& path, const image& img) {
    std::vector<std::uint8_t> bytes(img.data().size());
    for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = to_srgb8(img.data()[i]);
    auto append = [](void* context, void* data, int size) {
        static_cast<temporary_file*>(context)->append(data, std::size_t(size));
    };
    if (!stbi_write_png_to_func(append, &file, img.width(), img.height(), 3, bytes.data(),
                                img.width() * 3))
        throw user_error("cannot write '" + path + "': the PNG encoder failed (out of memory)");
}

void write_pfm(temporary_file& file, const image& img) {
    static_assert(std::endian::native == std::endian::little, "PFM writer assumes little-endian");
    const std::string header =
        "PF\n" + std::to_string(img.width()) + ' ' + std::to_string(img.height()) + "\n-1.0\n";
    file.append(header.data(), header.size());
    const std::size_t row_floats = std::size_t(img.width()) * 3;
    for (int y = img.height() - 1; y >= 0; --y)  // PFM stores the bottom row first
        file.append(img.data().data() + std::size_t(y) * row_floats, row_floats * sizeof(float));
}

}  // namespace

std::string output_path_problem(const std::string& path) {
    std::string ext = extension_of(path);
    if (ext != ".png" && ext != ".pfm")
        return "output '" + path + "' has an unknown extension '" + ext + "' (use .png or .pfm)";
    fs::path folder = fs::path(path).parent_path();
    if (folder.empty()) folder = ".";
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        return "output '" + path + "': folder '" + folder.string() + "' does not exist";
    if (fs::is_directory(path, ec)) return "output '" + path + "' is a folder";
    return "";
}

void write_image(output_set& outputs, const std::string& path, const image& img) {
    if (auto problem = output_path_problem(path); !problem.empty()) throw user_error(problem);
    if (extension_of(path) == ".png")
        outputs.add(path, [&](temporary_file& file) { write_png(file, path, img); });
    else
        outputs.add(path, [&](temporary_file& file) { write_pfm(file, img); });
}

void write_image(const std::string& path, const image& img) {
    output_set one;
    write_image(one, path, img);
    one.commit();
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
