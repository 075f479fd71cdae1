#include "options.h"

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

void print_summary(const std::string& name, const chapter_settings& s, int height, double seconds) {
    const auto& r  = s.render;
    double samples = double(s.width) * height * r.samples_per_pixel;
    int threads    = r.threads > 0 ? r.threads : omp_get_num_procs();
    std::fprintf(stderr,
                 "%s: %dx%d, %d spp, max depth %d, seed %llu, %d threads: %.3f s, %.3f M "
                 "samples/s\n",
                 name.c_str(), s.width, height, r.samples_per_pixel, r.max_depth,
                 static_cast<unsigned long long>(r.seed), threads, seconds,
                 samples / seconds * 1e-6);
}

}  // namespace

command_line::command_line(std::string program_name, chapter_settings defaults)
    : program(std::move(program_name)), current(std::move(defaults)), cli(program) {
    auto& r = current.render;
    cli.add_option("--width", current.width, "Image width in pixels")
        ->check(CLI::Range(1, 16384))
        ->capture_default_str();
    cli.add_option("--spp", r.samples_per_pixel, "Samples per pixel")
        ->check(CLI::Range(1, 1 << 20))
        ->capture_default_str();
    cli.add_option("--max-depth", r.max_depth, "Ray segments per path at most")
        ->check(CLI::Range(1, 10000))
        ->capture_default_str();
    cli.add_option("--seed", r.seed, "Seed of the random streams")->capture_default_str();
    cli.add_option("--threads", r.threads, "Worker threads; 0 = all cores")
        ->check(CLI::Range(0, 1024))
        ->capture_default_str();
    cli.add_option("--out", current.outputs, "Output image, .png or .pfm; may repeat")
        ->check(output_file({".png", ".pfm"}));
    cli.add_option("--variance-out", current.variance_output,
                   "Also write the variance of each pixel's mean, as .pfm")
        ->check(output_file({".pfm"}));
    cli.add_flag("--quiet", r.quiet, "No progress or summary on stderr");
}

int command_line::run(int argc, char** argv, const std::function<scene()>& build_scene) {
    try {
        cli.parse(argc, argv);
    } catch (const CLI::CallForHelp&) {
        std::printf("%s", cli.help().c_str());
        return 0;
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "%s: error: %s\n", program.c_str(), e.what());
        return 2;
    }
    if (current.outputs.empty()) current.outputs.push_back(program + ".png");

    try {
        scene sc           = build_scene();
        sc.cam.image_width = current.width;
        sc.cam.initialize();
        render_result result = render(sc, current.render);
        for (const auto& path : current.outputs) write_image(path, result.mean);
        if (!current.variance_output.empty())
            write_image(current.variance_output, result.mean_variance);
        if (!current.render.quiet)
            print_summary(program, current, sc.cam.image_height(), result.seconds);
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
