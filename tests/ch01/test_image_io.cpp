// Tests for image_io.h and display_encoding.h (chapter 01): PFM round trips bit for bit and is
// laid out as the format says (bottom row first), PNG decodes to the sRGB bytes, and an
// independent reader (oiiotool) agrees with ours.
#include <stb/stb_image.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "rt/image/display_encoding.h"
#include "rt/image/image_io.h"
#include "test_helpers.h"

namespace {

namespace fs = std::filesystem;
using rt::color, rt::real;

using rt_test::read_bytes, rt_test::same_bits, rt_test::temp_folder;

}  // namespace

TEST_CASE("image_io: a PFM written and read back is the same image bit for bit", "[ch01]") {
    temp_folder dir("image_io", "roundtrip");
    for (auto [w, h] : {std::pair{5, 3}, std::pair{1, 1}, std::pair{1, 7}, std::pair{64, 2}}) {
        INFO(w << " x " << h);
        rt::image img = rt_test::varied_image(w, h);
        rt_test::write_image_file(dir.file("a.pfm"), img);
        CHECK(same_bits(rt::read_pfm(dir.file("a.pfm")), img));
    }
}

TEST_CASE("image_io: a PFM starts with its header and stores the bottom image row first",
          "[ch01]") {
    temp_folder dir("image_io", "layout");
    const int w = 5, h = 3;
    rt::image img = rt_test::varied_image(w, h);
    rt_test::write_image_file(dir.file("a.pfm"), img);
    std::string bytes = read_bytes(dir.file("a.pfm"));

    const std::string header = "PF\n5 3\n-1.0\n";  // -1: little-endian, as the x86 floats are
    REQUIRE(bytes.size() == header.size() + std::size_t(w * h * 3) * sizeof(float));
    CHECK(bytes.substr(0, header.size()) == header);
    // Stored row r is image row h - 1 - r: the file's first row is the image's last.
    const std::size_t row_bytes = std::size_t(w * 3) * sizeof(float);
    for (int stored = 0; stored < h; ++stored) {
        INFO("stored row " << stored);
        const float* image_row = img.data().data() + std::size_t((h - 1 - stored) * w * 3);
        CHECK(std::memcmp(bytes.data() + header.size() + stored * row_bytes, image_row,
                          row_bytes) == 0);
    }
}

TEST_CASE(
    "image_io: a PFM that is not one, or holds fewer pixels than its header promises, is "
    "refused before its pixels are allocated",
    "[ch01]") {
    temp_folder dir("image_io", "refused");
    const std::string floats(2 * 2 * 12, '\0');
    rt_test::write_bytes(dir.file("exact.pfm"), "PF\n2 2\n-1.0\n" + floats);
    CHECK(rt::read_pfm(dir.file("exact.pfm")).width() == 2);
    rt_test::write_bytes(dir.file("short.pfm"), "PF\n2 2\n-1.0\n" + floats.substr(1));
    CHECK_THROWS_WITH(rt::read_pfm(dir.file("short.pfm")),
                      "'" + dir.file("short.pfm") + "' is truncated");
    // 10^10 pixels claimed (120 GB of floats), 12 bytes given: refused, not allocated.
    rt_test::write_bytes(dir.file("huge.pfm"), "PF\n100000 100000\n-1.0\n" + floats.substr(36));
    CHECK_THROWS_WITH(rt::read_pfm(dir.file("huge.pfm")),
                      "'" + dir.file("huge.pfm") + "' is truncated");
    rt_test::write_bytes(dir.file("text.pfm"), "P3\n1 1\n255\n0 0 0\n");
    CHECK_THROWS_WITH(rt::read_pfm(dir.file("text.pfm")),
                      "'" + dir.file("text.pfm") + "' is not an RGB PFM file");
}

TEST_CASE("image_io: a PNG decodes to the 8-bit sRGB codes of the image", "[ch01]") {
    temp_folder dir("image_io", "png");
    const int w = 7, h = 4;
    rt::image img(w, h);
    const real nan = std::numeric_limits<real>::quiet_NaN();
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            img.set(x, y, color(real(x) / 6, real(y) / 3, x == 0 ? nan : real(x - 3)));
    rt_test::write_image_file(dir.file("a.png"), img);

    std::string bytes = read_bytes(dir.file("a.png"));
    REQUIRE(bytes.size() > 8);
    CHECK(bytes.substr(0, 8) == std::string("\x89PNG\r\n\x1a\n", 8));

    int width = 0, height = 0, channels = 0;
    unsigned char* pixels = stbi_load(dir.file("a.png").c_str(), &width, &height, &channels, 0);
    REQUIRE(pixels != nullptr);
    CHECK(width == w);
    CHECK(height == h);
    CHECK(channels == 3);
    int wrong = 0;
    if (width == w && height == h && channels == 3) {
        for (std::size_t i = 0; i < img.data().size(); ++i)
            if (pixels[i] != rt::to_srgb8(double(img.data()[i]))) ++wrong;
    }
    stbi_image_free(pixels);
    CHECK(wrong == 0);
}

TEST_CASE("display_encoding: linear_to_srgb follows the sRGB curve and clamps to 0..1", "[ch01]") {
    auto srgb = [](double L) {  // IEC 61966-2-1, written out independently
        return L <= 0.0031308 ? 12.92 * L : 1.055 * std::pow(L, 1 / 2.4) - 0.055;
    };
    for (double L : {0.0, 0.001, 0.0031308, 0.01, 0.18, 0.5, 0.9, 1.0}) {
        INFO("L = " << L);
        CHECK(rt::linear_to_srgb(L) == Approx(srgb(L)).epsilon(1e-14).margin(1e-15));
    }
    CHECK(rt::linear_to_srgb(0) == 0);
    CHECK(rt::linear_to_srgb(0.0031308) == Approx(0.040449936).epsilon(1e-12));
    CHECK(rt::linear_to_srgb(0.5) == Approx(0.7353569830524495).epsilon(1e-14));
    CHECK(rt::linear_to_srgb(1) == 1);
    // The two pieces meet at the threshold (to 3e-8, the precision of the standard's constants).
    CHECK(std::fabs(12.92 * 0.0031308 - (1.055 * std::pow(0.0031308, 1 / 2.4) - 0.055)) < 1e-7);

    // Out of range: no bad pixel can turn bright.
    for (double bad : {std::nan(""), -0.5, -std::numeric_limits<double>::infinity(), -0.0}) {
        INFO("L = " << bad);
        CHECK(rt::linear_to_srgb(bad) == 0);
    }
    for (double bright : {1.5, 1e30, std::numeric_limits<double>::infinity()}) {
        INFO("L = " << bright);
        CHECK(rt::linear_to_srgb(bright) == 1);
    }

    // Every 8-bit code survives decoding to linear and encoding back.
    int lost = 0;
    for (int code = 0; code < 256; ++code)
        if (rt::to_srgb8(rt::srgb_to_linear(code / 255.0)) != code) ++lost;
    CHECK(lost == 0);
    CHECK(rt::to_srgb8(0.5) == 188);  // 255 * 0.73536 = 187.52, rounded to nearest
}

TEST_CASE("image_io: oiiotool reads our PFM with the right size, average and orientation",
          "[ch01]") {
    if (std::system("command -v oiiotool > /dev/null 2>&1") != 0) {
        WARN("oiiotool is not on PATH: skipping the check of our PFM by an independent reader");
        return;
    }
    temp_folder dir("image_io", "oiiotool");
    // 6 x 4 with dyadic values, so the averages are exact: red x/8 (mean 5/16), green y/4 (mean
    // 3/8), blue 1 except the top-left pixel, 0 (mean 23/24).
    const int w = 6, h = 4;
    rt::image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            img.set(x, y, color(real(x) / 8, real(y) / 4, x == 0 && y == 0 ? 0 : 1));
    rt_test::write_image_file(dir.file("a.pfm"), img);

    const std::string out = dir.file("oiiotool.txt");
    const std::string command =
        "oiiotool --info --stats --dumpdata '" + dir.file("a.pfm") + "' > '" + out + "' 2>&1";
    REQUIRE(std::system(command.c_str()) == 0);
    std::string report = read_bytes(out);
    INFO("oiiotool said:\n" << report);

    std::smatch m;
    REQUIRE(std::regex_search(report, m, std::regex(R"((\d+)\s*x\s*(\d+), 3 channel)")));
    CHECK(std::stoi(m[1]) == w);
    CHECK(std::stoi(m[2]) == h);
    // oiiotool prints 6 decimals: 1e-6 is its rounding, not ours.
    REQUIRE(std::regex_search(report, m, std::regex(R"(Stats Avg: (\S+) (\S+) (\S+))")));
    CHECK(std::stod(m[1]) == Approx(5.0 / 16).margin(1e-6));
    CHECK(std::stod(m[2]) == Approx(3.0 / 8).margin(1e-6));
    CHECK(std::stod(m[3]) == Approx(23.0 / 24).margin(1e-6));
    // Its pixel (0, 0) is the top left: the one pixel with blue 0, stored in the file's last row.
    REQUIRE(std::regex_search(report, m, std::regex(R"(Pixel \(0, 0\): (\S+) (\S+) (\S+))")));
    CHECK(std::stod(m[3]) == 0);
    REQUIRE(std::regex_search(report, m, std::regex(R"(Pixel \(5, 3\): (\S+) (\S+) (\S+))")));
    CHECK(std::stod(m[1]) == Approx(5.0 / 8).margin(1e-6));
    CHECK(std::stod(m[2]) == Approx(3.0 / 4).margin(1e-6));
}
