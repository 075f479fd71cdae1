#include "rt/program/command_line.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>

#include "rt/core/error.h"
#include "rt/files/image_outputs.h"
#include "rt/files/output_set.h"
#include "rt/program/flag_checks.h"
#include "rt/program/progress.h"
#include "rt/render/film.h"

namespace rt {

namespace {

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
                 double(r.camera_samples) / r.seconds * 1e-6);
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

// The name of the sampler the settings choose.
std::string sampler_name(const render_settings& s) {
    return s.make_sampler(s.seed)->name();
}

}  // namespace

command_line::command_line(std::string program_name)
    : program(std::move(program_name)), cli(std::make_unique<CLI::App>(program)) {
    // A flag given twice takes its last value, as most Unix tools do.
    cli->option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    cli->add_option("--width", flags.width, "Image width in pixels (default: the scene's)")
        ->check(integer_in(1, 16384));
    cli->add_option("--spp", flags.samples_per_pixel, "Samples per pixel (default: the scene's)")
        ->check(integer_in(1, 1 << 20));
    cli->add_option("--max-depth", flags.max_depth,
                    "Ray segments per path at most (default: the scene's)")
        ->check(integer_in(1, 10000));
    cli->add_option("--seed", flags.seed, "Seed of the random streams")
        ->check(integer_in(0, UINT64_MAX))
        ->capture_default_str();
    cli->add_option("--threads", flags.threads, "Worker threads; 0 = all cores")
        ->check(integer_in(0, 1024))
        ->capture_default_str();
    cli->add_option("--out", outputs.images, "Output image, .png, .pfm or .exr; may repeat")
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
        ->check(output_file({".png", ".pfm", ".exr"}));
    cli->add_flag("--exr-half", outputs.exr_half,
                  "Write the .exr images of --out in 16-bit half floats, not 32-bit (about 3 "
                  "digits; a value beyond half's largest, 65504, is written as 65504)");
    cli->add_option("--variance-out", outputs.variance,
                    "Also write the variance of each pixel's mean, as .pfm or 32-bit .exr")
        ->check(output_file({".pfm", ".exr"}));
    cli->add_option("--stats-out", outputs.stats,
                    "Also write the record of the run (time, samples, rays, settings) as .json")
        ->check(stats_file());
    cli->add_option("--crop", crop_text,
                    "Render only the pixels X0 <= x < X1, Y0 <= y < Y1 (from the top-left); the "
                    "image is the window's size")
        ->check(crop_syntax());
    cli->add_option("--samples", samples_text,
                    "Render only sample indices FROM <= k < TO of each pixel; --spp stays the "
                    "whole render's count (TO <= spp)")
        ->check(samples_syntax());
    cli->add_flag("--quiet", quiet, "No progress or summary on stderr");
    for (const CLI::Option* option : cli->get_options()) shared_options.push_back(option);
}

command_line::~command_line() = default;

void command_line::add_choice(const std::string& flag, std::string& value,
                              const std::vector<std::string>& allowed, const std::string& help,
                              bool show_default) {
    CLI::Option* option = cli->add_option(flag, value, help)->check(CLI::IsMember(allowed));
    if (show_default) option->capture_default_str();
}

void command_line::add_text(const std::string& flag, std::string& value, const std::string& help,
                            bool show_default) {
    CLI::Option* option = cli->add_option(flag, value, help);
    if (show_default) option->capture_default_str();
}

void command_line::add_number(const std::string& flag, std::optional<real>& value,
                              const std::string& help, double lo, bool lo_allowed) {
    cli->add_option(flag, value, help)->check(lo_allowed ? number_at_least(lo) : number_above(lo));
}

void command_line::add_choice_action(const std::string& flag,
                                     const std::vector<std::string>& allowed,
                                     const std::string& help,
                                     const std::function<void(const std::string&)>& act) {
    cli->add_option_function<std::string>(flag, act, help)->check(CLI::IsMember(allowed));
}

void command_line::add_uint32_action(const std::string& flag, const std::string& help,
                                     const std::function<void(std::uint32_t)>& act) {
    cli->add_option_function<std::uint32_t>(flag, act, help);
}

void command_line::add_flag(const std::string& flag, bool& value, const std::string& help) {
    cli->add_flag(flag, value, help);
}

render_settings command_line::with_flags(render_settings s) const {
    auto given = [this](const char* flag) { return cli->count(flag) > 0; };
    if (given("--width")) s.width = flags.width;
    if (given("--spp")) s.samples_per_pixel = flags.samples_per_pixel;
    if (given("--max-depth")) s.max_depth = flags.max_depth;
    if (given("--seed")) s.seed = flags.seed;
    if (given("--threads")) s.threads = flags.threads;
    if (given("--crop")) s.crop = parse_crop(crop_text);
    if (given("--samples")) s.samples = parse_samples(samples_text);
    return s;
}

std::vector<std::pair<std::string, std::string>> command_line::chapter_options() const {
    std::vector<std::pair<std::string, std::string>> options;
    for (const CLI::Option* option : cli->get_options()) {
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
        cli->parse(argc, argv);
    } catch (const CLI::CallForHelp&) {
        std::printf("%s", cli->help().c_str());
        return 0;
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "%s: error: %s\n", program.c_str(), e.what());
        return 2;
    }
    command.assign(argv, argv + argc);
    if (outputs.images.empty()) outputs.images.push_back(program + ".png");
    // Refused now, not after the render: one run's files are written as one output_set.
    const std::size_t files = outputs.images.size() + (outputs.variance.empty() ? 0 : 1) +
                              (outputs.stats.empty() ? 0 : 1);
    if (files > std::size_t(output_set::max_files)) {
        std::fprintf(stderr,
                     "%s: error: --out, --variance-out and --stats-out must name at most %d files "
                     "together, got %zu\n",
                     program.c_str(), output_set::max_files, files);
        return 2;
    }
    // Written after the images, the variance would replace one of them without a word.
    for (const auto& path : outputs.images)
        if (!outputs.variance.empty() && same_file(path, outputs.variance)) {
            std::fprintf(stderr, "%s: error: --variance-out must differ from every --out, got %s\n",
                         program.c_str(), outputs.variance.c_str());
            return 2;
        }
    return std::nullopt;
}

render_result command_line::render_with_progress(const film& f, const render_job& job,
                                                 const render_settings& settings) const {
    const pixel_window window = window_of(f, settings);
    progress_meter progress(window.height(), double(window.width()) * samples_of(settings).count(),
                            quiet);
    render_result result = render(f, *job.cam, *job.estimator, settings, &progress);
    progress.finish();
    return result;
}

run_stats command_line::record_of(const render_job& job, const film& f,
                                  const render_settings& settings, const render_result& result,
                                  clock::time_point start) const {
    run_stats record{
        .program         = program,
        .integrator      = std::string(job.estimator->name()),
        .sampler         = sampler_name(settings),
        .options         = chapter_options(),
        .command         = command,
        .full            = f,
        .settings        = settings,
        .window          = result.window,
        .samples         = result.samples,
        .camera_samples  = result.camera_samples,
        .rays            = result.rays,
        .seconds         = result.seconds,
        .process_seconds = std::chrono::duration<double>(clock::now() - start).count(),
        .outputs         = outputs.images,
        .variance_output = outputs.variance,
    };
    record.settings.threads = result.threads;
    return record;
}

void command_line::write_outputs(const render_result& result,
                                 const std::function<run_stats()>& make_record) const {
    // All or none: each file is written in full beside its target, and only when every one is
    // does commit() rename them onto their targets. A failure or an interrupt before that leaves
    // every old file as it was (output_set.h).
    output_set files;
    const exr_pixels exr = outputs.exr_half ? exr_pixels::half16 : exr_pixels::float32;
    for (const auto& path : outputs.images) write_image(files, path, result.mean, exr);
    if (!outputs.variance.empty()) write_image(files, outputs.variance, result.mean_variance);
    // Added last, so renamed last: a stats file means every image of the run is complete.
    if (!outputs.stats.empty()) write_stats(files, outputs.stats, make_record());
    files.commit();
}

int command_line::run(int argc, char** argv, const std::function<render_job()>& build) {
    return run(argc, argv, build, [] { return false; });
}

int command_line::run(int argc, char** argv, const std::function<render_job()>& build,
                      const std::function<bool()>& instead) {
    const auto start = clock::now();
    if (auto stop = parse(argc, argv)) return *stop;
    try {
        if (instead()) return 0;
        render_job job                 = build();
        const render_settings settings = with_flags(job.settings);
        const film f                   = film::for_aspect(settings.width, job.cam->aspect_ratio);
        job.cam->initialize(f);
        const render_result result = render_with_progress(f, job, settings);
        write_outputs(result, [&] { return record_of(job, f, settings, result, start); });
        if (!quiet) print_summary(program, f, settings, result);
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
