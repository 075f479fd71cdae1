#include "rt/program/command_line.h"

#include <omp.h>

#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <sstream>

#include "rt/core/error.h"
#include "rt/files/output_set.h"
#include "rt/image/image_io.h"
#include "rt/program/run_stats.h"

namespace rt {

namespace {

// CLI11 validator for output files: the error names the value and what is wrong with it.
CLI::Validator output_file(const std::vector<std::string>& extensions) {
    return CLI::Validator(
        [extensions](std::string& path) -> std::string {
            std::string problem = output_path_problem(path);
            if (!problem.empty()) return problem;
            for (const auto& ext : extensions)
                if (path.size() >= ext.size() && path.ends_with(ext)) return "";
            return "output '" + path + "' must end in " + extensions.front();
        },
        "FILE");
}

// Exactly `count` decimal integers separated by `separator`, and nothing else: "0,0,20,10" for
// four and ','; not "0,0,20", "0,0,20,10," or " 0,0,20,10".
bool parse_integers(const std::string& text, char separator, int count, int* out) {
    const char* p   = text.data();
    const char* end = text.data() + text.size();
    for (int i = 0; i < count; ++i) {
        if (i > 0) {
            if (p == end || *p != separator) return false;
            ++p;
        }
        auto [next, ec] = std::from_chars(p, end, out[i]);
        if (ec != std::errc() || next == p) return false;
        p = next;
    }
    return p == end;
}

std::optional<pixel_window> parse_crop(const std::string& text) {
    int v[4];
    if (!parse_integers(text, ',', 4, v)) return std::nullopt;
    return pixel_window{v[0], v[1], v[2], v[3]};
}

std::optional<sample_range> parse_samples(const std::string& text) {
    int v[2];
    if (!parse_integers(text, ':', 2, v)) return std::nullopt;
    return sample_range{v[0], v[1]};
}

// The syntax is checked while parsing; whether the values fit the image and the sample count
// is known only once the scene is built (render.h: window_of, samples_of).
CLI::Validator crop_syntax() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            return parse_crop(text) ? "" : "crop must be X0,Y0,X1,Y1 (integers), got " + text;
        },
        "X0,Y0,X1,Y1");
}

CLI::Validator samples_syntax() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            return parse_samples(text) ? ""
                                       : "sample range must be FROM:TO (integers), got " + text;
        },
        "FROM:TO");
}

CLI::Validator stats_file() {
    return CLI::Validator([](std::string& path) { return stats_path_problem(path); }, "FILE");
}

void print_summary(const std::string& name, const film& f, const render_settings& s,
                   const render_result& r) {
    std::string part;
    if (s.crop)
        part += ", crop " + std::to_string(r.window.x0) + "," + std::to_string(r.window.y0) + "," +
                std::to_string(r.window.x1) + "," + std::to_string(r.window.y1);
    if (s.samples)
        part += ", samples " + std::to_string(r.samples.from) + ":" + std::to_string(r.samples.to);
    std::fprintf(stderr,
                 "%s: %dx%d, %d spp, max depth %d, seed %llu%s, %d threads: %.3f s, %.3f M "
                 "samples/s\n",
                 name.c_str(), f.width, f.height, s.samples_per_pixel, s.max_depth,
                 static_cast<unsigned long long>(s.seed), part.c_str(), r.threads, r.seconds,
                 double(r.camera_samples()) / r.seconds * 1e-6);
}

// Whether two paths name the same file, as far as the paths tell ("x.pfm", "./x.pfm").
bool same_file(const std::string& a, const std::string& b) {
    namespace fs  = std::filesystem;
    auto resolved = [](const std::string& path) {
        std::error_code ec;
        fs::path full = fs::absolute(path, ec);
        if (!ec) full = fs::weakly_canonical(full, ec);
        return ec ? fs::path(path) : full;
    };
    return resolved(a) == resolved(b);
}

// [ch16 begin]
// The name of the sampler the settings choose (chapter 01's independent one unless a later
// chapter's program chose another).
std::string sampler_name(const render_settings& s) {
    return s.make_sampler ? s.make_sampler(s.seed)->name() : sampler(s.seed).name();
}
// [ch16 end]

// [ch06 begin]
// "must be a finite number <relation> <lo>" unless the whole text is a finite number that
// satisfies it.
CLI::Validator finite_number(double lo, bool lo_allowed) {
    std::ostringstream rule;
    rule << "must be a finite number " << (lo_allowed ? ">= " : "> ") << lo;
    return CLI::Validator(
        [lo, lo_allowed, rule = rule.str()](std::string& text) -> std::string {
            double value   = 0;
            auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
            const bool ok  = ec == std::errc() && end == text.data() + text.size() &&
                            std::isfinite(value) && (value > lo || (lo_allowed && value == lo));
            return ok ? "" : rule + ", got " + text;
        },
        rule.str().substr(8));  // the help shows "FLOAT:a finite number >= 0"
}
// [ch06 end]

}  // namespace

CLI::Validator integer_in(std::uint64_t lo, std::uint64_t hi) {
    return CLI::Validator(
        [lo, hi](std::string& text) -> std::string {
            std::uint64_t value = 0;
            auto [end, ec]      = std::from_chars(text.data(), text.data() + text.size(), value);
            if (ec == std::errc() && end == text.data() + text.size() && value >= lo && value <= hi)
                return "";
            return "must be an integer from " + std::to_string(lo) + " to " + std::to_string(hi) +
                   ", got " + text;
        },
        // The help shows "INT:INT in [1, 16384]"; a bound of 2^64 - 1 (--seed) says nothing.
        hi == UINT64_MAX ? "" : "INT in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

// [ch06 begin]
CLI::Validator number_at_least(double lo) {
    return finite_number(lo, true);
}
CLI::Validator number_above(double lo) {
    return finite_number(lo, false);
}
// [ch06 end]

command_line::command_line(std::string program_name)
    : program(std::move(program_name)), cli(program) {
    // A flag given twice takes its last value, as most Unix tools do.
    cli.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    cli.add_option("--width", flags.width, "Image width in pixels (default: the scene's)")
        ->check(integer_in(1, 16384));
    cli.add_option("--spp", flags.samples_per_pixel, "Samples per pixel (default: the scene's)")
        ->check(integer_in(1, 1 << 20));
    cli.add_option("--max-depth", flags.max_depth,
                   "Ray segments per path at most (default: the scene's)")
        ->check(integer_in(1, 10000));
    cli.add_option("--seed", flags.seed, "Seed of the random streams")
        ->check(integer_in(0, UINT64_MAX))
        ->capture_default_str();
    cli.add_option("--threads", flags.threads, "Worker threads; 0 = all cores")
        ->check(integer_in(0, 1024))
        ->capture_default_str();
    cli.add_option("--out", outputs, "Output image, .png or .pfm; may repeat")
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
        ->check(output_file({".png", ".pfm"}));
    cli.add_option("--variance-out", variance_output,
                   "Also write the variance of each pixel's mean, as .pfm")
        ->check(output_file({".pfm"}));
    cli.add_option("--stats-out", stats_output,
                   "Also write the record of the run (time, samples, rays, settings) as .json")
        ->check(stats_file());
    cli.add_option("--crop", crop_text,
                   "Render only the pixels X0 <= x < X1, Y0 <= y < Y1 (from the top-left); the "
                   "image is the window's size")
        ->check(crop_syntax());
    cli.add_option("--samples", samples_text,
                   "Render only sample indices FROM <= k < TO of each pixel; --spp stays the "
                   "whole render's count (TO <= spp)")
        ->check(samples_syntax());
    cli.add_flag("--quiet", flags.quiet, "No progress or summary on stderr");
    for (const CLI::Option* option : cli.get_options()) shared_options.push_back(option);
}

render_settings command_line::with_flags(render_settings s) const {
    auto given = [this](const char* flag) { return cli.count(flag) > 0; };
    if (given("--width")) s.width = flags.width;
    if (given("--spp")) s.samples_per_pixel = flags.samples_per_pixel;
    if (given("--max-depth")) s.max_depth = flags.max_depth;
    if (given("--seed")) s.seed = flags.seed;
    if (given("--threads")) s.threads = flags.threads;
    if (given("--quiet")) s.quiet = flags.quiet;
    if (given("--crop")) s.crop = parse_crop(crop_text);
    if (given("--samples")) s.samples = parse_samples(samples_text);
    return s;
}

std::vector<std::pair<std::string, std::string>> command_line::chapter_options() const {
    std::vector<std::pair<std::string, std::string>> options;
    for (const CLI::Option* option : cli.get_options()) {
        if (std::find(shared_options.begin(), shared_options.end(), option) != shared_options.end())
            continue;
        std::string value;
        if (option->count() > 0) {
            for (const auto& result : option->results())
                value += (value.empty() ? "" : " ") + result;
        } else {
            value = option->get_default_str();
        }
        options.emplace_back(option->get_name(), value);
    }
    return options;
}

std::optional<int> command_line::parse(int argc, char** argv) {
    try {
        cli.parse(argc, argv);
    } catch (const CLI::CallForHelp&) {
        std::printf("%s", cli.help().c_str());
        return 0;
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "%s: error: %s\n", program.c_str(), e.what());
        return 2;
    }
    if (outputs.empty()) outputs.push_back(program + ".png");
    // Refused now, not after the render: one run's files are written as one output_set.
    const std::size_t files =
        outputs.size() + (variance_output.empty() ? 0 : 1) + (stats_output.empty() ? 0 : 1);
    if (files > std::size_t(output_set::max_files)) {
        std::fprintf(stderr,
                     "%s: error: --out, --variance-out and --stats-out must name at most %d files "
                     "together, got %zu\n",
                     program.c_str(), output_set::max_files, files);
        return 2;
    }
    // Written after the images, the variance would replace one of them without a word.
    for (const auto& path : outputs)
        if (!variance_output.empty() && same_file(path, variance_output)) {
            std::fprintf(stderr, "%s: error: --variance-out must differ from every --out, got %s\n",
                         program.c_str(), variance_output.c_str());
            return 2;
        }
    return std::nullopt;
}

int command_line::run(int argc, char** argv, const std::function<render_job()>& build) {
    const auto start = std::chrono::steady_clock::now();
    if (auto stop = parse(argc, argv)) return *stop;

    try {
        render_job job          = build();
        render_settings setting = with_flags(job.settings);
        film f                  = film::for_aspect(setting.width, job.cam->aspect_ratio);
        job.cam->initialize(f);
        render_result result = render(f, *job.cam, *job.estimator, setting);
        // All or none: each file is written in full beside its target, and only when every one
        // is does commit() rename them onto their targets. A failure or an interrupt before that
        // leaves every old file as it was (output_set.h).
        output_set files;
        for (const auto& path : outputs) write_image(files, path, result.mean);
        if (!variance_output.empty()) write_image(files, variance_output, result.mean_variance);
        if (!stats_output.empty()) {
            // Added last, so renamed last: a stats file means every image of the run is complete.
            run_stats stats{program,
                            std::string(job.estimator->name()),
                            sampler_name(setting),
                            chapter_options(),
                            std::vector<std::string>(argv, argv + argc),
                            f,
                            setting,
                            result.window,
                            result.samples,
                            result.rays,
                            result.seconds,
                            0,
                            outputs,
                            variance_output};
            stats.settings.threads = result.threads;
            stats.process_seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            write_stats(files, stats_output, stats);
        }
        files.commit();
        if (!setting.quiet) print_summary(program, f, setting, result);
        return 0;
    } catch (const user_error& e) {
        std::fprintf(stderr, "%s: error: %s\n", program.c_str(), e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: internal error: %s\n", program.c_str(), e.what());
        return 1;
    }
}

}  // namespace rt
