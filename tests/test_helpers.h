// Small helpers that several test files share: random draws, exact comparisons and temporary
// files. Every random helper makes each draw in a statement of its own (the order in which
// function arguments are evaluated is unspecified), so that every compiler draws the same numbers
// in the same order; a test's seed then fixes all of its cases.
// Chapter 01, like every file directly in tests/: it includes chapter-01 headers only, so that
// every chapter's tests can use it. Helpers that need materials are in ch03/material_helpers.h.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <ostream>
#include <string>
#include <system_error>
#include <vector>

#include "rt/core/rng.h"
#include "rt/core/scalar.h"
#include "rt/core/vec3.h"
#include "rt/image/image.h"
#include "rt/image/image_io.h"
#include "rt/samplers/independent_sampler.h"

namespace rt_test {

// A property checked over many cases: how many were tried, how many failed, and the first
// failure's description, for one CHECK at the end that says how many failed and how.
struct tally {
    long long cases    = 0;
    long long failures = 0;
    std::string first;

    void fail(const std::string& what) {
        if (failures++ == 0) first = what;
    }
};

inline std::ostream& operator<<(std::ostream& out, const tally& t) {
    out << t.failures << " of " << t.cases;
    if (t.failures > 0) out << " (first: " << t.first << ")";
    return out;
}

// A real uniform in [lo, hi): one draw, the building block of the random cases.
inline rt::real uniform(rt::pcg32& rng, rt::real lo, rt::real hi) {
    return lo + (hi - lo) * rng.uniform();
}

// 10 to a power uniform in [lo_exponent, hi_exponent): scales spread evenly over the decades.
inline rt::real log_uniform(rt::pcg32& rng, rt::real lo_exponent, rt::real hi_exponent) {
    return std::pow(rt::real(10), uniform(rng, lo_exponent, hi_exponent));
}

// A unit vector uniform on the sphere: two draws, the first one for u. Archimedes' map, z = 1 - 2u
// and the azimuth 2 pi v: the same operations as chapter 03's sample_uniform_sphere (so the same
// vectors), written out here so that chapter 02's tests can use it.
inline rt::vec3 random_unit(rt::pcg32& rng) {
    rt::real u   = rng.uniform();
    rt::real v   = rng.uniform();
    rt::real z   = 1 - 2 * u;
    rt::real r   = std::sqrt(std::max(rt::real(0), 1 - z * z));
    rt::real phi = 2 * rt::pi * v;
    return rt::vec3(r * std::cos(phi), r * std::sin(phi), z);
}

// A point uniform in the cube [-half_side, half_side]^3: three draws, x, then y, then z.
inline rt::vec3 random_in_cube(rt::pcg32& rng, rt::real half_side) {
    rt::real x = uniform(rng, -half_side, half_side);
    rt::real y = uniform(rng, -half_side, half_side);
    return rt::vec3(x, y, uniform(rng, -half_side, half_side));
}

// A unit direction with dot(d, n) > min_cos, uniform over that cap: new rays leaving a surface.
inline rt::vec3 random_in_hemisphere(rt::pcg32& rng, const rt::vec3& n, rt::real min_cos = 0) {
    for (;;) {
        rt::vec3 d = random_unit(rng);
        if (dot(d, n) < 0) d = -d;
        if (dot(d, n) > min_cos) return d;
    }
}

// A unit direction in the tangent plane of the unit normal n (perpendicular to n), at random.
inline rt::vec3 random_tangent(rt::pcg32& rng, const rt::vec3& n) {
    for (;;) {
        rt::vec3 c = cross(n, random_unit(rng));
        if (c.length() > rt::real(0.1)) return rt::unit_vector(c);
    }
}

// Component-wise ==, for results that must come out bit for bit the same.
inline bool exactly(const rt::vec3& a, const rt::vec3& b) {
    return a.x() == b.x() && a.y() == b.y() && a.z() == b.z();
}

// The number a sampler started at pixel sample (px, py, k) returns after `draws` numbers: what a
// part that draws exactly `draws` dimensions leaves for the next part (sampler.h's layout).
inline rt::real next_after_draws(std::uint64_t seed, int px, int py, int k, int draws) {
    rt::independent_sampler s(seed);
    s.start_pixel_sample(px, py, k);
    for (int i = 0; i < draws; ++i) s.next_1d();
    return s.next_1d();
}

// Whether two images have the same size and the same float bits, -0 and NaN payloads included.
inline bool same_bits(const rt::image& a, const rt::image& b) {
    return a.width() == b.width() && a.height() == b.height() &&
           std::memcmp(a.data().data(), b.data().data(), a.data().size() * sizeof(float)) == 0;
}

// An image whose floats exercise every kind of value a PFM must carry: signs, -0, float
// subnormals, the largest float, and ordinary radiance values; no two pixels alike.
inline rt::image varied_image(int width, int height) {
    const float specials[] = {0.0f,  -0.0f, 1e-40f, std::numeric_limits<float>::max(),
                              -1.5f, 1e-3f, 0.1f,   65504.0f};
    rt::image img(width, height);
    int n = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x, ++n) {
            float r = specials[n % 8];
            float g = float(x) / 7.0f + float(y);
            float b = -float(n) * 0.37f;
            img.set(x, y, rt::color(rt::real(r), rt::real(g), rt::real(b)));
        }
    }
    return img;
}

// The whole content of a file, byte for byte ("" if it cannot be read).
inline std::string read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Writes `bytes` as the whole content of a file, to set up a file that a test then reads.
inline void write_bytes(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

// Writes img as the file `path`, in the format its extension names (.png or .pfm): a test's
// own plain write, so that tests of chapters need no part of the program's all-or-none outputs.
inline void write_image_file(const std::string& path, const rt::image& img) {
    std::ofstream out(path, std::ios::binary);
    const auto format = rt::format_of(path);
    REQUIRE(format);
    REQUIRE(rt::encode_image(img, *format, [&out](const void* data, std::size_t size) {
        out.write(static_cast<const char*>(data), std::streamsize(size));
    }));
    REQUIRE(out.good());
}

// A fresh, empty folder under the system's temporary folder, removed with everything in it.
class temp_folder {
  public:
    temp_folder(const std::string& suite, const std::string& name)
        : root(std::filesystem::temp_directory_path() /
               ("rt_test_" + suite + "_" + name + "_" + std::to_string(::getpid()))) {
        std::filesystem::remove_all(root);
        std::filesystem::create_directories(root);
    }
    ~temp_folder() {
        std::error_code ec;
        std::filesystem::remove_all(root, ec);
    }
    temp_folder(const temp_folder&)            = delete;
    temp_folder& operator=(const temp_folder&) = delete;

    std::string file(const std::string& name) const { return (root / name).string(); }
    const std::filesystem::path& path() const { return root; }

    // The names in the folder, sorted.
    std::vector<std::string> entries() const {
        std::vector<std::string> names;
        for (const auto& e : std::filesystem::directory_iterator(root))
            names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }

  private:
    std::filesystem::path root;
};

}  // namespace rt_test
