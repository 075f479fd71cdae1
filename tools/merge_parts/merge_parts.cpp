// The pixel work of tools/merge: puts the parts of a split render back together.
//   merge_parts --size W H --spp N --part X0 Y0 X1 Y1 FROM TO MEAN.pfm VARIANCE.pfm ...
//               --out FILE... [--variance-out FILE.pfm]
// (MEAN, VARIANCE and the variance output may be 32-bit .exr files instead of .pfm.)
// Each part rendered the window [X0, X1) x [Y0, Y1) of a W x H image with the sample indices
// [FROM, TO) of each pixel (render.h); VARIANCE.pfm is its --variance-out, or "-" for none.
// tools/merge reads the parts' --stats-out records and calls this; it is not meant for people.
//
// Crops: a pixel's value is copied, never recomputed, so the whole image holds the very floats
// a single run would have written, and they are encoded the same way: byte-identical .pfm, .exr
// and .png. Sample ranges of one window: means are combined weighted by their sample counts,
// variances by Chan, Golub and LeVeque's parallel formula (the one Welford's update in render.cpp
// is a special case of), in double. That is the single run's result up to the float rounding
// of the parts' files.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "rt/core/error.h"
#include "rt/files/image_outputs.h"
#include "rt/files/output_set.h"
#include "rt/image/image.h"
#include "rt/image/image_io.h"
#include "rt/render/render.h"

namespace {

using rt::image, rt::pixel_window, rt::sample_range, rt::user_error;

struct part {
    pixel_window crop;
    sample_range range;
    std::string mean_path, variance_path;  // variance_path empty: none
    image mean, variance;
};

std::string text(const pixel_window& w) {
    return std::to_string(w.x0) + "," + std::to_string(w.y0) + "," + std::to_string(w.x1) + "," +
           std::to_string(w.y1);
}

std::string text(const sample_range& r) {
    return std::to_string(r.from) + ":" + std::to_string(r.to);
}

int to_int(const std::string& s, const char* what) {
    try {
        std::size_t used = 0;
        int value        = std::stoi(s, &used);
        if (used == s.size()) return value;
    } catch (const std::exception&) {
    }
    throw user_error(std::string(what) + " must be an integer, got " + s);
}

image read_part_image(const std::string& path, const pixel_window& crop) {
    image img = rt::read_exact_image(path);
    if (img.width() != crop.width() || img.height() != crop.height())
        throw user_error("'" + path + "' must be " + std::to_string(crop.width()) + " x " +
                         std::to_string(crop.height()) + " (its crop " + text(crop) + "), got " +
                         std::to_string(img.width()) + " x " + std::to_string(img.height()));
    return img;
}

// The sample ranges of one window must tile [0, spp): sorted, each starts where the last ended.
void check_ranges(std::vector<part*>& parts, int spp) {
    std::sort(parts.begin(), parts.end(),
              [](const part* a, const part* b) { return a->range.from < b->range.from; });
    int covered = 0;
    for (const part* p : parts) {
        if (p->range.from < covered)
            throw user_error("sample ranges of crop " + text(p->crop) + " must not overlap, got " +
                             text(p->range) + " and one ending at " + std::to_string(covered));
        if (p->range.from > covered)
            throw user_error("sample ranges of crop " + text(p->crop) +
                             " must cover 0:" + std::to_string(spp) + ", missing " +
                             std::to_string(covered) + ":" + std::to_string(p->range.from));
        covered = p->range.to;
    }
    if (covered != spp)
        throw user_error("sample ranges of crop " + text(parts.front()->crop) +
                         " must cover 0:" + std::to_string(spp) + ", missing " +
                         std::to_string(covered) + ":" + std::to_string(spp));
}

// The windows must tile the image: no two overlap, and their areas add up to the whole.
void check_crops(const std::vector<pixel_window>& crops, int width, int height) {
    long long area = 0;
    for (std::size_t a = 0; a < crops.size(); ++a) {
        const pixel_window& p = crops[a];
        area += (long long)p.width() * p.height();
        for (std::size_t b = a + 1; b < crops.size(); ++b) {
            const pixel_window& q = crops[b];
            if (p.x0 < q.x1 && q.x0 < p.x1 && p.y0 < q.y1 && q.y0 < p.y1)
                throw user_error("crops must not overlap, got " + text(p) + " and " + text(q));
        }
    }
    if (area == (long long)width * height) return;
    std::vector<char> covered(std::size_t(width) * height, 0);
    for (const auto& c : crops)
        for (int y = c.y0; y < c.y1; ++y)
            for (int x = c.x0; x < c.x1; ++x) covered[std::size_t(y) * width + x] = 1;
    const auto first = std::find(covered.begin(), covered.end(), 0) - covered.begin();
    throw user_error("crops must cover the whole " + std::to_string(width) + " x " +
                     std::to_string(height) + " image, got none for pixel (" +
                     std::to_string(first % width) + ", " + std::to_string(first / width) + ")");
}

// Combines the sample ranges of one window into `mean` and `variance` of the whole image.
// Chan et al.: two sets of n_a and n_b samples with means m_a, m_b and sums of squared
// deviations M_a, M_b have, together, n = n_a + n_b samples, with d = m_b - m_a,
//   mean m = m_a + d n_b / n,   M = M_a + M_b + d^2 n_a n_b / n.
// A part's file holds the variance of its mean, V = M / ((n - 1) n) (render.cpp), so
// M = V (n - 1) n. With a single part, its floats are copied as they are.
void combine(const std::vector<part*>& parts, bool with_variance, image& mean, image& variance) {
    const pixel_window& c = parts.front()->crop;
    for (int y = 0; y < c.height(); ++y) {
        for (int x = 0; x < c.width(); ++x) {
            rt::color m, v;
            for (int channel = 0; channel < 3; ++channel) {
                double n = 0, mean_sum = 0, m2 = 0;
                for (const part* p : parts) {
                    const double nb = p->range.count();
                    const double mb = double(p->mean.get(x, y)[channel]);
                    const double m2b =
                        with_variance ? double(p->variance.get(x, y)[channel]) * nb * (nb - 1) : 0;
                    if (n == 0) {
                        mean_sum = mb;
                        m2       = m2b;
                    } else {
                        const double d = mb - mean_sum;
                        mean_sum += d * nb / (n + nb);
                        m2 += m2b + d * d * n * nb / (n + nb);
                    }
                    n += nb;
                }
                m[channel] = rt::real(mean_sum);
                v[channel] = rt::real(n > 1 ? m2 / (n - 1) / n : 0.0);
            }
            mean.set(c.x0 + x, c.y0 + y, m);
            if (with_variance) variance.set(c.x0 + x, c.y0 + y, v);
        }
    }
}

int merge(int width, int height, int spp, const std::vector<std::vector<std::string>>& specs,
          const std::vector<std::string>& outputs, const std::string& variance_output) {
    for (const auto& path : outputs)
        if (auto problem = rt::output_path_problem(path); !problem.empty())
            throw user_error(problem);
    if (!variance_output.empty() && !variance_output.ends_with(".pfm") &&
        !variance_output.ends_with(".exr"))
        throw user_error("variance output must end in .pfm or .exr, got " + variance_output);

    std::vector<part> parts;
    for (const auto& spec : specs) {
        part p;
        p.crop          = {to_int(spec[0], "X0"), to_int(spec[1], "Y0"), to_int(spec[2], "X1"),
                           to_int(spec[3], "Y1")};
        p.range         = {to_int(spec[4], "FROM"), to_int(spec[5], "TO")};
        p.mean_path     = spec[6];
        p.variance_path = spec[7] == "-" ? "" : spec[7];
        const pixel_window& c = p.crop;
        if (!(0 <= c.x0 && c.x0 < c.x1 && c.x1 <= width && 0 <= c.y0 && c.y0 < c.y1 &&
              c.y1 <= height))
            throw user_error("a part's crop must be a non-empty window inside the " +
                             std::to_string(width) + " x " + std::to_string(height) +
                             " image, got " + text(c));
        if (!(0 <= p.range.from && p.range.from < p.range.to && p.range.to <= spp))
            throw user_error("a part's sample range must lie in 0:" + std::to_string(spp) +
                             ", got " + text(p.range));
        parts.push_back(std::move(p));
    }
    if (parts.empty()) throw user_error("parts to merge must be given, got none");

    // Group by window; check the tiling before reading any pixel.
    std::map<std::tuple<int, int, int, int>, std::vector<part*>> windows;
    for (auto& p : parts) windows[{p.crop.x0, p.crop.y0, p.crop.x1, p.crop.y1}].push_back(&p);
    std::vector<pixel_window> crops;
    for (auto& [key, group] : windows) {
        check_ranges(group, spp);
        crops.push_back(group.front()->crop);
    }
    check_crops(crops, width, height);

    const bool with_variance = !variance_output.empty();
    for (auto& p : parts) {
        p.mean = read_part_image(p.mean_path, p.crop);
        if (with_variance) {
            if (p.variance_path.empty())
                throw user_error(
                    "each part must have a variance image (--variance-out) to "
                    "merge variances, got none for '" +
                    p.mean_path + "'");
            p.variance = read_part_image(p.variance_path, p.crop);
        }
    }
    image mean(width, height), variance(width, height);
    for (auto& [key, group] : windows) combine(group, with_variance, mean, variance);
    rt::output_set files;  // all or none, as a chapter's run (rt/files/output_set.h)
    for (const auto& path : outputs) rt::write_image(files, path, mean);
    if (with_variance) rt::write_image(files, variance_output, variance);
    files.commit();
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app("merge_parts: the pixel work of tools/merge");
    std::vector<int> size;
    int spp = 0;
    std::vector<std::vector<std::string>> specs;
    std::vector<std::string> outputs;
    std::string variance_output;
    app.add_option("--size", size, "Width and height of the whole image")->expected(2)->required();
    app.add_option("--spp", spp, "Samples per pixel of the whole render")->required();
    app.add_option("--part", specs, "X0 Y0 X1 Y1 FROM TO MEAN.pfm VARIANCE.pfm|-")
        ->expected(8)
        ->required();
    app.add_option("--out", outputs, "Merged image, .png, .pfm or .exr; may repeat")->required();
    app.add_option("--variance-out", variance_output, "Merged variance of the mean, .pfm or .exr");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);
        std::fprintf(stderr, "merge: error: %s\n", e.what());
        return 2;
    }
    try {
        return merge(size[0], size[1], spp, specs, outputs, variance_output);
    } catch (const user_error& e) {
        std::fprintf(stderr, "merge: error: %s\n", e.what());
        return 2;
    }
}
