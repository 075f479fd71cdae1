// Tests for image_texture.h (chapter 08). Small PNGs are written with stb_image_write into a
// fresh temporary folder: the lookup picks the nearest texel with u = 0 the left column and
// v = 1 the top row, clamps u and v (NaN too) to the edge texels, decodes 8-bit sRGB to linear
// light, and refuses missing, empty, truncated, non-image and too large files with a user_error
// that names the file; the size is read from the header, so a file that claims to be enormous
// is refused before anything is decoded.
#include <stb/stb_image_write.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "rt/core/error.h"
#include "rt/image/display_encoding.h"
#include "rt/textures/image_texture.h"
#include "test_helpers.h"

namespace {

namespace fs = std::filesystem;
using rt::color, rt::point3, rt::real;

using rt_test::read_bytes, rt_test::temp_folder, rt_test::write_bytes;

// Writes rows top first, `channels` bytes per texel (1 gray, 3 RGB, 4 RGBA).
void write_png(const std::string& path, int width, int height, int channels,
               const std::vector<std::uint8_t>& bytes) {
    REQUIRE(bytes.size() == std::size_t(width * height * channels));
    REQUIRE(stbi_write_png(path.c_str(), width, height, channels, bytes.data(), width * channels) !=
            0);
}

// The sRGB decoding curve, written out here from IEC 61966-2-1 rather than taken from
// display_encoding.h, so that the test checks the texture against the standard.
double srgb_decode(int byte) {
    const double c = byte / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

color decoded(int r, int g, int b) {
    return color(real(srgb_decode(r)), real(srgb_decode(g)), real(srgb_decode(b)));
}

// The decoded texel against the standard: one rounding to real of a double (the texture keeps
// a table of srgb_to_linear(i / 255.0) in real), so a few ulps of real.
bool close(const color& a, const color& b) {
    const real tolerance = 4 * std::numeric_limits<real>::epsilon();
    for (int i = 0; i < 3; ++i)
        if (!(std::fabs(a[i] - b[i]) <= tolerance)) return false;
    return true;
}

// A 2 x 2 image, rows top first: red, green / blue, gray 128.
const std::vector<std::uint8_t> two_by_two = {255, 0, 0,   0,   255, 0,  //
                                              0,   0, 255, 128, 128, 128};
const color top_left = decoded(255, 0, 0), top_right = decoded(0, 255, 0),
            bottom_left = decoded(0, 0, 255), bottom_right = decoded(128, 128, 128);

color at(const rt::image_texture& t, real u, real v) {
    return t.value(u, v, point3(0, 0, 0));
}

// 'path', as a message quotes a file. Appended, not added: GCC 12 warns, wrongly, about some
// inlined string additions (-Wstringop-overflow).
std::string quoted(const std::string& path) {
    std::string q = "'";
    q.append(path).append("'");
    return q;
}

// The message of the user_error that loading `path` throws, or a note that it loaded.
std::string refusal(const std::string& path, std::int64_t limit = rt::image_texture::max_texels) {
    try {
        rt::image_texture t(path, limit);
        return "(loaded " + std::to_string(t.width()) + " x " + std::to_string(t.height()) +
               " without an error)";
    } catch (const rt::user_error& e) {
        return e.what();
    }
}

// The CRC-32 of PNG chunks (ISO 3309, reflected polynomial 0xEDB88320), bit by bit.
std::uint32_t crc32(const std::string& bytes) {
    std::uint32_t crc = 0xFFFFFFFFu;
    for (unsigned char byte : bytes) {
        crc ^= byte;
        for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

std::string big_endian(std::uint32_t x) {
    return {char(x >> 24), char(x >> 16), char(x >> 8), char(x)};
}

// One PNG chunk: length, type, data, CRC of type and data.
std::string png_chunk(const std::string& type, const std::string& data) {
    return big_endian(std::uint32_t(data.size())) + type + data + big_endian(crc32(type + data));
}

// A PNG of 8-bit RGB whose header (IHDR) claims width x height, with no image data: all a
// reader of the header sees is a valid file of that size.
std::string png_claiming(std::uint32_t width, std::uint32_t height) {
    const std::string signature = "\x89PNG\r\n\x1a\n";
    const std::string ihdr      = big_endian(width) + big_endian(height) +
                             std::string("\x08\x02\x00\x00\x00", 5);  // 8 bit, RGB
    return signature + png_chunk("IHDR", ihdr) + png_chunk("IEND", "");
}

}  // namespace

TEST_CASE("image_texture: u = 0 is the left column, v = 1 the top row, nearest texel", "[ch08]") {
    temp_folder dir("image_texture", "lookup");
    write_png(dir.file("quad.png"), 2, 2, 3, two_by_two);
    const rt::image_texture t(dir.file("quad.png"));
    CHECK(t.width() == 2);
    CHECK(t.height() == 2);
    CHECK(t.uses_uv());  // so a hit computes its (u, v) for it
    // The texel centers, and points just inside each quarter.
    CHECK(close(at(t, 0.25, 0.75), top_left));
    CHECK(close(at(t, 0.75, 0.75), top_right));
    CHECK(close(at(t, 0.25, 0.25), bottom_left));
    CHECK(close(at(t, 0.75, 0.25), bottom_right));
    CHECK(close(at(t, 0, 1), top_left));  // the corners of the image
    CHECK(close(at(t, 1, 1), top_right));
    CHECK(close(at(t, 0, 0), bottom_left));
    CHECK(close(at(t, 1, 0), bottom_right));
    CHECK(close(at(t, real(0.499), real(0.501)), top_left));
    CHECK(close(at(t, real(0.501), real(0.499)), bottom_right));
    // Exactly on the texel boundaries: u = 1/2 goes to the right column, v = 1/2 to the lower
    // row (rows are counted from the top: row = floor((1 - v) H)).
    CHECK(close(at(t, 0.5, 0.75), top_right));
    CHECK(close(at(t, 0.25, 0.5), bottom_left));
    // p plays no part.
    CHECK(close(t.value(0.25, 0.75, point3(100, -3, 7)), top_left));
}

TEST_CASE("image_texture: every texel of a larger image is found at its center", "[ch08]") {
    // 7 x 5 texels (odd sizes, so no boundary falls on a power of two), each with its own color.
    temp_folder dir("image_texture", "centers");
    const int w = 7, h = 5;
    std::vector<std::uint8_t> bytes;
    for (int row = 0; row < h; ++row) {
        for (int col = 0; col < w; ++col) {
            bytes.push_back(std::uint8_t(30 * col));
            bytes.push_back(std::uint8_t(50 * row));
            bytes.push_back(std::uint8_t(200 + col + row));
        }
    }
    write_png(dir.file("grid.png"), w, h, 3, bytes);
    const rt::image_texture t(dir.file("grid.png"));
    int wrong = 0;
    for (int row = 0; row < h; ++row) {
        for (int col = 0; col < w; ++col) {
            const color want = decoded(30 * col, 50 * row, 200 + col + row);
            const real u = (real(col) + real(0.5)) / w, v = 1 - (real(row) + real(0.5)) / h;
            // The center, and 0.4 texel towards each side: the same texel.
            for (real du : {real(-0.4), real(0), real(0.4)}) {
                for (real dv : {real(-0.4), real(0), real(0.4)}) {
                    if (!close(at(t, u + du / w, v + dv / h), want)) ++wrong;
                }
            }
        }
    }
    CHECK(wrong == 0);
}

TEST_CASE("image_texture: u and v outside 0..1, infinite or NaN clamp to the edge texels",
          "[ch08]") {
    temp_folder dir("image_texture", "clamp");
    write_png(dir.file("quad.png"), 2, 2, 3, two_by_two);
    const rt::image_texture t(dir.file("quad.png"));
    const real inf = rt::infinity, nan = std::numeric_limits<real>::quiet_NaN();
    CHECK(close(at(t, -0.5, 0.75), top_left));
    CHECK(close(at(t, 1.5, 0.75), top_right));
    CHECK(close(at(t, 0.25, 2), top_left));
    CHECK(close(at(t, 0.25, -1), bottom_left));
    CHECK(close(at(t, -inf, inf), top_left));
    CHECK(close(at(t, inf, -inf), bottom_right));
    const real huge = std::numeric_limits<real>::max();
    CHECK(close(at(t, -huge, huge), top_left));
    // NaN clamps to 0: the left column, the bottom row (documented in image_texture.cpp).
    CHECK(close(at(t, nan, 0.75), top_left));
    CHECK(close(at(t, 0.75, nan), bottom_right));
    CHECK(close(at(t, nan, nan), bottom_left));
}

TEST_CASE("image_texture: 8-bit sRGB decodes to linear light", "[ch08]") {
    // A 256 x 1 gray ramp: texel i holds byte i in all three channels.
    temp_folder dir("image_texture", "srgb");
    std::vector<std::uint8_t> bytes;
    for (int i = 0; i < 256; ++i) bytes.insert(bytes.end(), 3, std::uint8_t(i));
    write_png(dir.file("ramp.png"), 256, 1, 3, bytes);
    const rt::image_texture t(dir.file("ramp.png"));
    auto texel = [&](int i) { return at(t, (real(i) + real(0.5)) / 256, 0.5); };

    CHECK(texel(0).x() == 0);
    CHECK(texel(255).x() == 1);  // (1 + 0.055) / 1.055 = 1 exactly, and 1^2.4 = 1
    CHECK(texel(128).x() == Approx(0.2158605).epsilon(1e-6));  // not 128/255 = 0.502
    int wrong = 0, not_increasing = 0, not_inverse = 0;
    for (int i = 0; i < 256; ++i) {
        const color c = texel(i);
        if (!close(c, decoded(i, i, i))) ++wrong;
        if (i > 0 && !(c.x() > texel(i - 1).x())) ++not_increasing;
        // The encoding used for output takes it back to the same byte.
        if (rt::to_srgb8(double(c.x())) != i) ++not_inverse;
    }
    CHECK(wrong == 0);
    CHECK(not_increasing == 0);
    CHECK(not_inverse == 0);
}

TEST_CASE("image_texture: gray and RGBA files load as RGB (gray replicated, alpha ignored)",
          "[ch08]") {
    temp_folder dir("image_texture", "channels");
    write_png(dir.file("gray.png"), 2, 1, 1, {64, 200});
    const rt::image_texture gray(dir.file("gray.png"));
    CHECK(close(at(gray, 0.25, 0.5), decoded(64, 64, 64)));
    CHECK(close(at(gray, 0.75, 0.5), decoded(200, 200, 200)));
    write_png(dir.file("rgba.png"), 1, 2, 4, {10, 20, 30, 0, 250, 128, 5, 255});
    const rt::image_texture rgba(dir.file("rgba.png"));
    CHECK(close(at(rgba, 0.5, 0.75), decoded(10, 20, 30)));
    CHECK(close(at(rgba, 0.5, 0.25), decoded(250, 128, 5)));
}

TEST_CASE(
    "image_texture: a missing, empty, truncated or non-image file throws a user_error "
    "naming it",
    "[ch08]") {
    temp_folder dir("image_texture", "errors");
    // A valid PNG large enough that its first half ends inside the image data: 64 x 64 texels
    // of varied bytes (little for the compressor to remove).
    std::vector<std::uint8_t> bytes;
    std::uint32_t state = 12345;
    for (int i = 0; i < 64 * 64 * 3; ++i) {
        state = state * 1664525u + 1013904223u;
        bytes.push_back(std::uint8_t(state >> 24));
    }
    write_png(dir.file("full.png"), 64, 64, 3, bytes);
    CHECK_NOTHROW(rt::image_texture(dir.file("full.png")));
    const std::string full = read_bytes(dir.file("full.png"));
    REQUIRE(full.size() > 10000);
    write_bytes(dir.file("half.png"), full.substr(0, full.size() / 2));
    // Only its 12-byte end chunk (IEND) cut off: stb refuses it, but gives no reason of its own.
    write_bytes(dir.file("no_end.png"), full.substr(0, full.size() - 12));
    // Cut the small 2 x 2 file in half too: there the cut falls in the header chunks.
    write_png(dir.file("small.png"), 2, 2, 3, two_by_two);
    const std::string small = read_bytes(dir.file("small.png"));
    write_bytes(dir.file("small_half.png"), small.substr(0, small.size() / 2));
    write_bytes(dir.file("empty.png"), "");
    write_bytes(dir.file("notes.png"), "These are not the pixels you are looking for.\n");

    for (const std::string name :
         {"missing.png", "empty.png", "half.png", "no_end.png", "small_half.png", "notes.png"}) {
        const std::string path = dir.file(name);
        INFO(path);
        std::string message;
        try {
            rt::image_texture t(path);
            message = "(loaded " + std::to_string(t.width()) + " x " + std::to_string(t.height()) +
                      " without an error)";
        } catch (const rt::user_error& e) {
            message = e.what();
        }
        CHECK_THAT(message, Catch::Contains(path));
        // And a reason after the name.
        CHECK_THAT(message, !Catch::EndsWith(": ") && !Catch::EndsWith("'"));
    }
}

TEST_CASE("image_texture: a folder or a device is refused, naming it", "[ch08]") {
    temp_folder dir("image_texture", "not_files");
    const std::string folder = dir.file("textures.png");
    fs::create_directory(folder);
    CHECK_THAT(refusal(folder),
               Catch::Contains(quoted(folder)) && Catch::Contains("it is a folder"));
    CHECK_THAT(refusal("/dev/null"),
               Catch::Contains("'/dev/null'") && Catch::Contains("not a regular file"));
}

TEST_CASE("image_texture: a refusal quoting the file's own bytes stays one line of text",
          "[ch08]") {
    // stb names an unknown critical PNG chunk by its four type bytes: here "P5", a newline and
    // an escape, as in fuzz/regressions/texture/png_chunk_type_with_newline.png (the fuzzer's
    // find). The error must still be one line, with those bytes shown as \xNN.
    temp_folder dir("image_texture", "chunk_name");
    const std::string file = png_claiming(2, 2);
    const std::string odd =
        file.substr(0, 33) + png_chunk(std::string("P5\n\x1b", 4), "12") + file.substr(33);
    write_bytes(dir.file("odd.png"), odd);
    const std::string message = refusal(dir.file("odd.png"));
    CHECK_THAT(message, Catch::Contains(quoted(dir.file("odd.png"))) &&
                            Catch::Contains("P5\\x0a\\x1b PNG chunk not known"));
    CHECK(message.find_first_of("\n\r\x1b") == std::string::npos);
}

TEST_CASE("image_texture: a PNG whose first IDAT chunk is empty is refused before stb reads it",
          "[ch08]") {
    // stb_image 2.27 copies an empty first IDAT to its null buffer plus 0 (undefined behaviour,
    // fuzz/regressions/texture/png_empty_first_idat.png is the fuzzer's find): refused first.
    temp_folder dir("image_texture", "empty_idat");
    const std::string file = png_claiming(2, 2);
    write_bytes(dir.file("empty_idat.png"),
                file.substr(0, 33) + png_chunk("IDAT", "") + file.substr(33));
    const std::string message = refusal(dir.file("empty_idat.png"));
    CHECK_THAT(message, Catch::Contains(quoted(dir.file("empty_idat.png"))) &&
                            Catch::Contains("an empty PNG IDAT chunk before any image data"));
}

TEST_CASE("image_texture: the CRC of the hand-made PNG chunks is the standard one", "[ch08]") {
    // The check value of CRC-32 (ISO 3309), and the IEND chunk every PNG ends with.
    CHECK(crc32("123456789") == 0xCBF43926u);
    CHECK(png_chunk("IEND", "") == std::string("\0\0\0\0IEND\xAE\x42\x60\x82", 12));
}

TEST_CASE(
    "image_texture: a file whose header claims more than 2^26 texels is refused from the "
    "header, naming the file and the size",
    "[ch08]") {
    temp_folder dir("image_texture", "enormous");
    // 100000 x 100000 texels would be 30 GB of 8-bit RGB: the file itself is 57 bytes.
    write_bytes(dir.file("huge.png"), png_claiming(100000, 100000));
    const std::string message = refusal(dir.file("huge.png"));
    CHECK_THAT(message, Catch::Contains(quoted(dir.file("huge.png"))));
    CHECK_THAT(message, Catch::Contains("must have at most 67108864 texels (2^26)"));
    CHECK_THAT(message, Catch::EndsWith("got 100000 x 100000"));
    CHECK(message.find('\n') == std::string::npos);

    // The same from a PPM header, and one side alone may be long: 2^26 + 1 texels in one row.
    write_bytes(dir.file("huge.ppm"), "P6\n100000 100000\n255\n" + std::string(30, '\0'));
    CHECK_THAT(refusal(dir.file("huge.ppm")), Catch::EndsWith("got 100000 x 100000"));
    // The most a PNG header can claim, 2^32 - 1 a side: no overflow on the way to the refusal.
    write_bytes(dir.file("most.png"), png_claiming(0xFFFFFFFFu, 0xFFFFFFFFu));
    CHECK_THAT(refusal(dir.file("most.png")), Catch::EndsWith("got 4294967295 x 4294967295"));
    write_bytes(dir.file("long.png"), png_claiming((1u << 26) + 1, 1));
    CHECK_THAT(refusal(dir.file("long.png")), Catch::EndsWith("got 67108865 x 1"));

    // A JPEG's start of frame (SOF0) claiming 65535 x 65535, the most it can, and 10000 x 10000
    // (stb itself refuses the first from its header, as "unknown image type"; the second only
    // our limit stops).
    auto jpeg_claiming = [](std::uint32_t width, std::uint32_t height) {
        return std::string("\xFF\xD8\xFF\xC0\x00\x11\x08", 7) + big_endian(height).substr(2) +
               big_endian(width).substr(2) +
               std::string("\x03\x01\x22\x00\x02\x11\x01\x03\x11\x01\xFF\xD9", 12);
    };
    write_bytes(dir.file("huge.jpg"), jpeg_claiming(65535, 65535));
    CHECK_THAT(refusal(dir.file("huge.jpg")), Catch::Contains(quoted(dir.file("huge.jpg"))) &&
                                                  Catch::EndsWith("got 65535 x 65535"));
    write_bytes(dir.file("big.jpg"), jpeg_claiming(10000, 10000));
    CHECK_THAT(refusal(dir.file("big.jpg")), Catch::EndsWith("got 10000 x 10000"));

    // 8192 x 8192 is exactly 2^26: within the limit, so this file gets as far as the decoder,
    // which refuses it for having no image data, not for its size.
    write_bytes(dir.file("limit.png"), png_claiming(8192, 8192));
    CHECK_THAT(refusal(dir.file("limit.png")), Catch::Contains(quoted(dir.file("limit.png"))) &&
                                                   Catch::Contains("damaged or truncated") &&
                                                   !Catch::Contains("texels"));
    write_bytes(dir.file("over.png"), png_claiming(8193, 8192));
    CHECK_THAT(refusal(dir.file("over.png")), Catch::EndsWith("got 8193 x 8192"));
}

TEST_CASE("image_texture: the texel limit is inclusive, and a smaller one refuses small files",
          "[ch08]") {
    temp_folder dir("image_texture", "limit");
    write_png(dir.file("quad.png"), 2, 2, 3, two_by_two);
    CHECK_NOTHROW(rt::image_texture(dir.file("quad.png"), 4));
    CHECK_THAT(refusal(dir.file("quad.png"), 3),
               Catch::Contains("'" + dir.file("quad.png") +
                               "' must have at most 3 texels, got "
                               "2 x 2"));
}

TEST_CASE("image_texture: PPM and JPEG files load too (the fuzz corpus's formats)", "[ch08]") {
    temp_folder dir("image_texture", "formats");
    // A binary PPM (P6) of 2 x 1 texels: red, then gray 128.
    write_bytes(dir.file("pair.ppm"), std::string("P6\n2 1\n255\n\xFF\x00\x00\x80\x80\x80", 17));
    const rt::image_texture ppm(dir.file("pair.ppm"));
    CHECK(close(at(ppm, 0.25, 0.5), decoded(255, 0, 0)));
    CHECK(close(at(ppm, 0.75, 0.5), decoded(128, 128, 128)));
    // A JPEG of one flat color: lossy, but a flat 8 x 8 block survives within a few codes.
    std::vector<std::uint8_t> flat;
    for (int i = 0; i < 8 * 8; ++i) flat.insert(flat.end(), {200, 100, 50});
    REQUIRE(stbi_write_jpg(dir.file("flat.jpg").c_str(), 8, 8, 3, flat.data(), 100) != 0);
    const rt::image_texture jpg(dir.file("flat.jpg"));
    CHECK(jpg.width() == 8);
    CHECK(jpg.height() == 8);
    const color c = at(jpg, 0.5, 0.5);
    CHECK(std::abs(rt::to_srgb8(double(c.x())) - 200) <= 3);
    CHECK(std::abs(rt::to_srgb8(double(c.y())) - 100) <= 3);
    CHECK(std::abs(rt::to_srgb8(double(c.z())) - 50) <= 3);
}

TEST_CASE(
    "image_texture: a PNG whose data inflates to far more than its size needs (a "
    "decompression bomb) is refused before it is decoded",
    "[ch08]") {
    temp_folder dir("image_texture", "bomb");
    // 1024 x 4096 gray texels of 0: 4 MiB of raw data that deflate packs into a few KiB.
    const int w = 1024, h = 4096;
    write_png(dir.file("tall.png"), w, h, 1, std::vector<std::uint8_t>(std::size_t(w) * h, 0));
    const std::string tall = read_bytes(dir.file("tall.png"));
    REQUIRE(tall.size() < 100000);
    REQUIRE(tall.substr(12, 4) == "IHDR");
    // The same file with its header claiming another size (its IHDR chunk rewritten).
    auto claiming = [&](std::uint32_t width, std::uint32_t height) {
        const std::string ihdr = big_endian(width) + big_endian(height) + tall.substr(24, 5);
        return tall.substr(0, 8) + png_chunk("IHDR", ihdr) + tall.substr(33);
    };
    CHECK_NOTHROW(rt::image_texture(dir.file("tall.png")));

    // 16 x 16 texels need 16 rows of 1 + 16 bytes: the 4 MiB stream is refused, with the sizes.
    write_bytes(dir.file("bomb.png"), claiming(16, 16));
    const std::string message = refusal(dir.file("bomb.png"));
    CHECK_THAT(message, Catch::Contains(quoted(dir.file("bomb.png"))));
    CHECK_THAT(message, Catch::Contains("inflates to more than 1049120 bytes where its 16 x 16 "
                                        "texels need 272"));

    // Half the rows: 2 MiB needed, 4 MiB given, within the allowance of twice plus 1 MiB (stb
    // accepts data after the image, and some encoders leave some), so it loads.
    write_bytes(dir.file("half_rows.png"), claiming(1024, 2048));
    const rt::image_texture half(dir.file("half_rows.png"));
    CHECK(half.height() == 2048);
    // A quarter of the rows: 1 MiB needed, 4 MiB given, more than 2 x 1 MiB + 1 MiB: refused.
    write_bytes(dir.file("quarter_rows.png"), claiming(1024, 1024));
    CHECK_THAT(refusal(dir.file("quarter_rows.png")), Catch::Contains("inflates to more than"));
}

TEST_CASE(
    "image_texture: formats other than PNG, JPEG and binary PPM/PGM are refused, though stb "
    "reads them",
    "[ch08]") {
    temp_folder dir("image_texture", "formats_refused");
    const std::vector<std::uint8_t> gray = {10, 20, 30, 40};
    REQUIRE(stbi_write_bmp(dir.file("quad.bmp").c_str(), 2, 2, 1, gray.data()) != 0);
    REQUIRE(stbi_write_tga(dir.file("quad.tga").c_str(), 2, 2, 1, gray.data()) != 0);
    write_bytes(dir.file("ascii.ppm"), "P3\n1 1\n255\n1 2 3\n");  // stb reads only P5 and P6
    for (const std::string name : {"quad.bmp", "quad.tga", "ascii.ppm"}) {
        INFO(name);
        CHECK_THAT(refusal(dir.file(name)),
                   Catch::Contains(quoted(dir.file(name))) &&
                       Catch::EndsWith("not a PNG, JPEG or binary PPM/PGM image"));
    }
    // The same texels as a binary PGM load.
    write_bytes(dir.file("quad.pgm"), std::string("P5\n2 2\n255\n\x0A\x14\x1E\x28", 15));
    CHECK(close(at(rt::image_texture(dir.file("quad.pgm")), 0.25, 0.75), decoded(10, 10, 10)));
}

TEST_CASE(
    "image_texture: a JPEG Huffman table of more than 256 codes is refused before stb "
    "reads it (stb 2.27 would write past its arrays)",
    "[ch08]") {
    temp_folder dir("image_texture", "dht");
    // SOI, then a DHT segment: class/id 0, sixteen counts of 20 (320 codes), 320 symbols.
    auto dht = [](int count) {
        const int length = 2 + 17 + 16 * count;
        return std::string("\xFF\xD8\xFF\xC4", 4) + char(length >> 8) + char(length & 0xFF) +
               std::string(1, '\0') + std::string(16, char(count)) +
               std::string(std::size_t(16 * count), '\0');
    };
    write_bytes(dir.file("overflow.jpg"), dht(20));
    CHECK_THAT(refusal(dir.file("overflow.jpg")),
               Catch::Contains(quoted(dir.file("overflow.jpg"))) &&
                   Catch::EndsWith("(a JPEG Huffman table of 320 codes, more than 256)"));
    // 16 x 16 = 256 codes is within the rule: stb then refuses the file for what it lacks.
    write_bytes(dir.file("full_table.jpg"), dht(16));
    CHECK_THAT(refusal(dir.file("full_table.jpg")), !Catch::Contains("Huffman"));
    // A table cut short by the end of the file is checked as far as it goes.
    write_bytes(dir.file("cut.jpg"), dht(20).substr(0, 4 + 2 + 1 + 15));
    CHECK_THAT(refusal(dir.file("cut.jpg")), Catch::EndsWith("of 300 codes, more than 256)"));
    // A segment whose length (17) ends before its table's last two counts: stb reads them from
    // the bytes after it all the same (found by the fuzz target), so the guard does too.
    std::string short_segment("\xFF\xD8\xFF\xC4\x00\x11", 6);
    short_segment.append(15, '\0');
    short_segment.append(2, '\xFF');
    write_bytes(dir.file("short_segment.jpg"), short_segment);
    CHECK_THAT(refusal(dir.file("short_segment.jpg")),
               Catch::EndsWith("of 510 codes, more than 256)"));
}

TEST_CASE(
    "image_texture: a JPEG scan that decodes with a Huffman table defined nowhere before it is "
    "refused (stb 2.27 would decode with an uninitialized table)",
    "[ch08]") {
    // A valid baseline JPEG from stb's writer (tables 0 and 1 of each class, then the scan),
    // then the same file with its scan's first component pointed at tables 2, which no DHT
    // segment defines (as the fuzzer's jpeg_scan_uses_undefined_table.jpg does).
    temp_folder dir("image_texture", "undefined_table");
    std::vector<std::uint8_t> flat;
    for (int i = 0; i < 8 * 8; ++i) flat.insert(flat.end(), {200, 100, 50});
    REQUIRE(stbi_write_jpg(dir.file("good.jpg").c_str(), 8, 8, 3, flat.data(), 90) != 0);
    CHECK_NOTHROW(rt::image_texture(dir.file("good.jpg")));
    std::string bytes      = read_bytes(dir.file("good.jpg"));
    const std::size_t scan = bytes.find("\xFF\xDA");
    REQUIRE(scan != std::string::npos);
    // FF DA, length (2 bytes), component count, then (id, DC << 4 | AC) per component.
    bytes[scan + 6] = '\x22';
    write_bytes(dir.file("undefined.jpg"), bytes);
    CHECK_THAT(refusal(dir.file("undefined.jpg")),
               Catch::Contains(quoted(dir.file("undefined.jpg"))) &&
                   Catch::EndsWith("(a JPEG scan decodes with DC Huffman table 2, which no "
                                   "table before it defines)"));
    // Only its AC table undefined: named too.
    bytes[scan + 6] = '\x03';
    write_bytes(dir.file("undefined_ac.jpg"), bytes);
    CHECK_THAT(refusal(dir.file("undefined_ac.jpg")),
               Catch::EndsWith("(a JPEG scan decodes with AC Huffman table 3, which no table "
                               "before it defines)"));
}

TEST_CASE(
    "image_texture: a PPM/PGM whose header numbers overflow an int, or whose texels are cut "
    "short, is refused before stb reads it",
    "[ch08]") {
    temp_folder dir("image_texture", "pnm");
    // A header, then n bytes of texel data (appended: GCC 12 warns, wrongly, on string + string).
    auto with_bytes = [](const char* header, std::size_t n) {
        std::string bytes = header;
        bytes.append(n, 'x');
        return bytes;
    };
    // stb 2.27 adds the digits up in an int: 99999999999 would overflow it.
    write_bytes(dir.file("digits.ppm"), with_bytes("P6\n99999999999 1\n255\n", 3));
    CHECK_THAT(refusal(dir.file("digits.ppm")),
               Catch::Contains(quoted(dir.file("digits.ppm"))) &&
                   Catch::EndsWith("(a number in its PPM/PGM header is above 2147483647)"));
    write_bytes(dir.file("maximum.pgm"), with_bytes("P5\n# a comment\n1 1\n4294967296\n", 2));
    CHECK_THAT(refusal(dir.file("maximum.pgm")), Catch::Contains("above 2147483647"));
    // 2 x 2 RGB texels need 12 bytes; stb would hand back a buffer with 6 of them never written.
    write_bytes(dir.file("short.ppm"), with_bytes("P6\n2 2\n255\n", 6));
    CHECK_THAT(refusal(dir.file("short.ppm")),
               Catch::EndsWith("(its PPM/PGM data holds 6 bytes where its 2 x 2 texels need 12)"));
    // 16 bits a sample: 24 bytes.
    write_bytes(dir.file("short16.ppm"), with_bytes("P6 2 2 65535\n", 23));
    CHECK_THAT(refusal(dir.file("short16.ppm")), Catch::EndsWith("holds 23 bytes where its 2 x 2 "
                                                                 "texels need 24)"));
    write_bytes(dir.file("full16.ppm"), with_bytes("P6 2 2 65535\n", 24));
    CHECK_NOTHROW(rt::image_texture(dir.file("full16.ppm")));
    // A 16-bit PGM: stb 2.27 would read past its buffer converting it (found by the fuzz target).
    write_bytes(dir.file("gray16.pgm"), with_bytes("P5 1 3 725\n", 6));
    CHECK_THAT(refusal(dir.file("gray16.pgm")),
               Catch::Contains(quoted(dir.file("gray16.pgm"))) &&
                   Catch::Contains("16-bit PGM images are not read"));
}
