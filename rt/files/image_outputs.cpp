#include "rt/files/image_outputs.h"

#include <filesystem>

#include "rt/core/error.h"
#include "rt/image/image_io.h"

namespace rt {

namespace fs = std::filesystem;

namespace {

bool is_exr(const std::string& path) {
    return fs::path(path).extension() == ".exr";
}

}  // namespace

std::string output_path_problem(const std::string& path) {
    if (!format_of(path) && !is_exr(path))
        return "output '" + path + "' has an unknown extension '" +
               fs::path(path).extension().string() + "' (use .png, .pfm or .exr)";
    fs::path folder = fs::path(path).parent_path();
    if (folder.empty()) folder = ".";
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        return "output '" + path + "': folder '" + folder.string() + "' does not exist";
    if (fs::is_directory(path, ec)) return "output '" + path + "' is a folder";
    return "";
}

void write_image(output_set& outputs, const std::string& path, const image& img, exr_pixels exr) {
    if (auto problem = output_path_problem(path); !problem.empty()) throw user_error(problem);
    // Through temporary_file, which remembers a failed write (stbi_write_png ignores fwrite's
    // and fclose's errors: a full disk would give a truncated PNG and "success").
    outputs.add(path, [&](temporary_file& file) {
        const byte_sink sink = [&file](const void* data, std::size_t size) {
            file.append(data, size);
        };
        if (is_exr(path)) {
            try {
                encode_exr(img, exr, sink);
            } catch (const user_error& e) {
                throw user_error("cannot write '" + path + "': " + e.what());
            }
            return;
        }
        const bool encoded = encode_image(img, *format_of(path), sink);
        if (!encoded)
            throw user_error("cannot write '" + path + "': the PNG encoder failed (out of memory)");
    });
}

void write_image(const std::string& path, const image& img, exr_pixels exr) {
    output_set one;
    write_image(one, path, img, exr);
    one.commit();
}

image read_exact_image(const std::string& path) {
    if (!is_exr(path)) return read_pfm(path);
    exr_image read = read_exr(path);
    if (read.stored != exr_pixels::float32)
        throw user_error("'" + path +
                         "' holds half floats, not the exact 32-bit floats of the "
                         "render (write it without --exr-half)");
    return std::move(read.pixels);
}

}  // namespace rt
