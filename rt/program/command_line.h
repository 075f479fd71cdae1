// The command line every chapter shares (CLI11). Chapter 01.
//   chNN_name [--width N] [--spp N] [--max-depth N] [--seed N] [--threads N] [--out FILE]...
//             [--variance-out FILE] [--stats-out FILE] [--crop X0,Y0,X1,Y1]
//             [--samples FROM:TO] [--quiet] [--help]
// It only parses: the scene brings its own default settings (render_job::settings) and a flag
// the user gives overrides that one setting. A chapter may add flags of its own through app().
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "rt/render/render.h"

namespace rt {

// Checks for a numeric flag, as CLI11 validators; the message says the rule and the value:
// "--width: must be an integer from 1 to 16384, got 2.5". Decimal digits only, so the number
// used is the one typed (CLI11 alone reads "0x10" as 16, calls 2.5 "not in range 1 to 16384",
// and turns a --seed of -1 into 2^64 - 1).
CLI::Validator integer_in(std::uint64_t lo, std::uint64_t hi);
// [ch06 begin]
// A finite real number >= lo ("--aperture: must be a finite number >= 0, got -1"), or > lo.
CLI::Validator number_at_least(double lo);
CLI::Validator number_above(double lo);
// [ch06 end]

class command_line {
  public:
    explicit command_line(std::string program_name);

    CLI::App& app() { return cli; }
    const std::string& name() const { return program; }

    // Parses the arguments, then builds the job (so chapter flags can choose the scene), puts
    // the flags given over the job's settings, renders and writes every output. Returns the exit
    // code: 0 on success (or --help), 2 for a user error with one line on stderr naming it.
    int run(int argc, char** argv, const std::function<render_job()>& build);

    // run()'s first step alone: parses and checks the arguments, builds and renders nothing.
    // Returns the exit code to stop with (0 after --help, 2 after one line on stderr naming the
    // error), or nothing when run() would go on. The fuzz target of the command line calls it.
    std::optional<int> parse(int argc, char** argv);

  private:
    // The job's settings with every flag the user gave put over them.
    render_settings with_flags(render_settings scene_defaults) const;

    // The chapter's own flags (those it added through app()) and their values in force.
    std::vector<std::pair<std::string, std::string>> chapter_options() const;

    std::string program;
    render_settings flags;             // the values parsed; only those given are used
    std::vector<std::string> outputs;  // .png and/or .pfm files; default "<name>.png"
    std::string variance_output;       // optional .pfm of the per-pixel variance of the mean
    std::string stats_output;          // optional .json record of the run (run_stats.h)
    std::string crop_text;             // --crop as given, checked by the parser
    std::string samples_text;          // --samples as given, checked by the parser
    CLI::App cli;
    std::vector<const CLI::Option*> shared_options;  // the flags every chapter has
};

}  // namespace rt
