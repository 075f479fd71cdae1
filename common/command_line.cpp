#include "command_line.h"

#include <omp.h>

#include <cstdio>
#include <exception>

#include "error.h"
#include "image_io.h"

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

void print_summary(const std::string& name, const film& f, const render_settings& s,
                   double seconds) {
    double samples = double(f.width) * f.height * s.samples_per_pixel;
    int threads    = s.threads > 0 ? s.threads : omp_get_num_procs();
    std::fprintf(stderr,
                 "%s: %dx%d, %d spp, max depth %d, seed %llu, %d threads: %.3f s, %.3f M "
                 "samples/s\n",
                 name.c_str(), f.width, f.height, s.samples_per_pixel, s.max_depth,
                 static_cast<unsigned long long>(s.seed), threads, seconds,
                 samples / seconds * 1e-6);
}

}  // namespace

command_line::command_line(std::string program_name)
    : program(std::move(program_name)), cli(program) {
    // A flag given twice takes its last value, as most Unix tools do.
    cli.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    cli.add_option("--width", flags.width, "Image width in pixels (default: the scene's)")
        ->check(CLI::Range(1, 16384));
    cli.add_option("--spp", flags.samples_per_pixel, "Samples per pixel (default: the scene's)")
        ->check(CLI::Range(1, 1 << 20));
    cli.add_option("--max-depth", flags.max_depth,
                   "Ray segments per path at most (default: the scene's)")
        ->check(CLI::Range(1, 10000));
    cli.add_option("--seed", flags.seed, "Seed of the random streams")->capture_default_str();
    cli.add_option("--threads", flags.threads, "Worker threads; 0 = all cores")
        ->check(CLI::Range(0, 1024))
        ->capture_default_str();
    cli.add_option("--out", outputs, "Output image, .png or .pfm; may repeat")
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
        ->check(output_file({".png", ".pfm"}));
    cli.add_option("--variance-out", variance_output,
                   "Also write the variance of each pixel's mean, as .pfm")
        ->check(output_file({".pfm"}));
    cli.add_flag("--quiet", flags.quiet, "No progress or summary on stderr");
}

render_settings command_line::with_flags(render_settings s) const {
    auto given = [this](const char* flag) { return cli.count(flag) > 0; };
    if (given("--width")) s.width = flags.width;
    if (given("--spp")) s.samples_per_pixel = flags.samples_per_pixel;
    if (given("--max-depth")) s.max_depth = flags.max_depth;
    if (given("--seed")) s.seed = flags.seed;
    if (given("--threads")) s.threads = flags.threads;
    if (given("--quiet")) s.quiet = flags.quiet;
    return s;
}

int command_line::run(int argc, char** argv, const std::function<render_job()>& build) {
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

    try {
        render_job job          = build();
        render_settings setting = with_flags(job.settings);
        film f                  = film::for_aspect(setting.width, job.cam->aspect_ratio);
        job.cam->initialize(f);
        render_result result = render(f, *job.cam, *job.estimator, setting);
        for (const auto& path : outputs) write_image(path, result.mean);
        if (!variance_output.empty()) write_image(variance_output, result.mean_variance);
        if (!setting.quiet) print_summary(program, f, setting, result.seconds);
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
