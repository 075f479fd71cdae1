// Tests of exr_file.h: a run's image written as OpenEXR and read back holds the very floats (32
// bits) or their nearest halves (16 bits, the brightest clamped to 65504, never infinite); and a
// file that is not a readable scan-line RGB image, or is larger than allowed, is refused with
// the file's name and the reason.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "rt/core/error.h"
#include "rt/files/exr_file.h"
#include "rt/files/image_outputs.h"
#include "test_helpers.h"

namespace {
using rt_test::read_bytes, rt_test::same_bits, rt_test::temp_folder, rt_test::varied_image,
    rt_test::write_bytes;

std::string encoded(const rt::image& img, rt::exr_pixels pixels) {
    std::string bytes;
    rt::encode_exr(img, pixels, [&bytes](const void* data, std::size_t size) {
        bytes.append(static_cast<const char*>(data), size);
    });
    return bytes;
}

rt::exr_image decoded(const std::string& bytes, long long max_pixels = rt::max_exr_pixels) {
    return rt::read_exr_bytes(bytes.data(), bytes.size(), "test.exr", max_pixels);
}

// The nearest half float to f, by rounding its bits (round to nearest, ties to even), for
// normal halves (|f| in [2^-14, 65504]).
float nearest_half(float f) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &f, 4);
    const std::uint32_t dropped = bits & 0x1fffu, half_way = 0x1000u;
    bits &= ~0x1fffu;
    if (dropped > half_way || (dropped == half_way && (bits & 0x2000u))) bits += 0x2000u;
    float out = 0;
    std::memcpy(&out, &bits, 4);
    return out;
}
}  // namespace

TEST_CASE("exr: 32-bit floats come back bit for bit: signs, -0, subnormals, the largest float",
          "[program]") {
    for (const auto& [w, h] : {std::pair{1, 1}, std::pair{7, 5}, std::pair{40, 33}}) {
        INFO(w << " x " << h);
        const rt::image img     = varied_image(w, h);
        const rt::exr_image got = decoded(encoded(img, rt::exr_pixels::float32));
        CHECK(got.stored == rt::exr_pixels::float32);
        CHECK(same_bits(got.pixels, img));
    }
    // The same image encodes to the same bytes (no time stamp, no thread order).
    CHECK(encoded(varied_image(9, 4), rt::exr_pixels::float32) ==
          encoded(varied_image(9, 4), rt::exr_pixels::float32));
}

TEST_CASE("exr: half floats are the nearest halves, and beyond 65504 they are 65504, not infinite",
          "[program]") {
    rt::image img(4, 2);
    const float values[8][3] = {{1.0f, 0.5f, 0.25f},         {0.1f, 0.3f, 3.14159f},
                                {100.7f, 1000.3f, -2.71f},   {65504.0f, 65519.0f, 70000.0f},
                                {1e30f, -1e30f, 1e9f},       {0.0f, -0.0f, 0.001f},
                                {12345.6f, -65504.0f, 7.0f}, {0.75f, 1.5f, 2048.9f}};
    for (int k = 0; k < 8; ++k)
        img.set(k % 4, k / 4, rt::color(values[k][0], values[k][1], values[k][2]));
    const rt::exr_image got = decoded(encoded(img, rt::exr_pixels::half16));
    CHECK(got.stored == rt::exr_pixels::half16);
    REQUIRE(got.pixels.width() == 4);
    REQUIRE(got.pixels.height() == 2);
    for (int k = 0; k < 8; ++k)
        for (int c = 0; c < 3; ++c) {
            const float v    = values[k][c];
            const float read = float(got.pixels.get(k % 4, k / 4)[c]);
            INFO("value " << v);
            CHECK(std::isfinite(read));
            if (std::fabs(v) >= rt::largest_half)
                CHECK(read == std::copysign(rt::largest_half, v));
            else if (std::fabs(v) >= 0x1p-14f)
                CHECK(read == nearest_half(v));
            else
                CHECK(std::fabs(read - v) <= 0x1p-24f);  // a subnormal half's step
        }
}

TEST_CASE("exr: write_image writes .exr, and read_exact_image reads its floats but refuses halves",
          "[program]") {
    temp_folder dir("exr_file", "exact");
    const rt::image img = varied_image(6, 3);
    rt::write_image(dir.file("a.exr"), img);
    rt::write_image(dir.file("h.exr"), img, rt::exr_pixels::half16);
    rt::write_image(dir.file("a.pfm"), img);
    CHECK(same_bits(rt::read_exact_image(dir.file("a.exr")), img));
    CHECK(same_bits(rt::read_exact_image(dir.file("a.pfm")), img));
    CHECK(rt::read_exr(dir.file("h.exr")).stored == rt::exr_pixels::half16);
    CHECK_THROWS_WITH(rt::read_exact_image(dir.file("h.exr")),
                      Catch::Contains("h.exr' holds half floats"));
}

TEST_CASE("exr: what is not a readable scan-line RGB image is refused, naming it and why",
          "[program]") {
    const std::string good = encoded(varied_image(16, 40), rt::exr_pixels::float32);
    auto refusal           = [](const std::string& bytes, long long max_pixels) {
        try {
            decoded(bytes, max_pixels);
        } catch (const rt::user_error& e) {
            return std::string(e.what());
        }
        return std::string("(read)");
    };
    // Not an EXR at all, empty, or cut short: in the header or among the pixels.
    CHECK_THAT(refusal("P3\n1 1\n255\n0 0 0\n", 1000),
               Catch::StartsWith("'test.exr' is not a readable OpenEXR file"));
    CHECK_THAT(refusal("", 1000), Catch::StartsWith("'test.exr' is not a readable OpenEXR file"));
    CHECK_THAT(refusal(good.substr(0, 40), 1000), Catch::Contains("not a readable OpenEXR file"));
    CHECK_THAT(refusal(good.substr(0, good.size() - 64), 1000),
               Catch::Contains("not a readable OpenEXR file"));
    // Larger than allowed: refused from the header, however few bytes follow it.
    CHECK(refusal(good, 640) == "(read)");
    CHECK(refusal(good, 639) == "'test.exr' is 16 x 40: more than 639 pixels");
    // A header that claims 60000 x 60000 pixels (the data window's corners patched), in a file
    // of a few hundred bytes: refused before anything is allocated for 43 GB of floats.
    std::string huge      = good;
    const std::size_t box = huge.find(std::string("dataWindow\0box2i\0", 17));
    REQUIRE(box != std::string::npos);
    const std::int32_t corner[2] = {59999, 59999};
    std::memcpy(&huge[box + 17 + 4 + 8], corner, 8);  // after the size field and min.x, min.y
    CHECK(refusal(huge, rt::max_exr_pixels) ==
          "'test.exr' is 60000 x 60000: more than 268435456 pixels");
    // Without an R channel (its name changed to Y: still sorted B, G, Y).
    std::string no_red     = good;
    const std::size_t list = no_red.find(std::string("chlist\0", 7));
    REQUIRE(list != std::string::npos);
    const std::size_t red = no_red.find(std::string("\0R\0", 3), list);
    REQUIRE(red != std::string::npos);
    no_red[red + 1] = 'Y';
    CHECK(refusal(no_red, 1000) == "'test.exr' has no channel R");
}

TEST_CASE("exr: a file that cannot be opened is refused with its name", "[program]") {
    temp_folder dir("exr_file", "missing");
    CHECK_THROWS_WITH(rt::read_exr(dir.file("none.exr")),
                      Catch::StartsWith("'" + dir.file("none.exr") + "' is not a readable"));
    write_bytes(dir.file("text.exr"), "not an image");
    CHECK_THROWS_AS(rt::read_exr(dir.file("text.exr")), rt::user_error);
    CHECK(read_bytes(dir.file("text.exr")) == "not an image");
}
