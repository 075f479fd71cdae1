// The command line every chapter's program shares (CLI11), and the run it starts:
//   chNN_name [--width N] [--spp N] [--max-depth N] [--seed N] [--threads N] [--out FILE]...
//             [--variance-out FILE] [--stats-out FILE] [--crop X0,Y0,X1,Y1]
//             [--samples FROM:TO] [--quiet] [--help]
// A chapter's main() names its program, adds its own flags (add_choice and the others below)
// and hands run() the function that builds its render job. The scene brings its own default
// settings (render_job::settings); a flag the user gives overrides that one setting.
// CLI11 parses; it stays inside command_line.cpp, so that a chapter's program, which includes
// this header, does not compile the 10,000 lines of its header again.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "rt/program/run_stats.h"
#include "rt/render/render.h"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace rt {

class command_line {
  public:
    explicit command_line(std::string program_name);
    ~command_line();
    command_line(const command_line&)            = delete;
    command_line& operator=(const command_line&) = delete;

    const std::string& name() const { return program; }

    // A chapter's own flags, shown by --help and kept with their values in the record of a run.
    // show_default: --help shows the value the variable starts with.
    // One of the words `allowed`, into value ("--scene: moon not in {floor,book}" otherwise).
    void add_choice(const std::string& flag, std::string& value,
                    const std::vector<std::string>& allowed, const std::string& help,
                    bool show_default = true);
    // Any text, such as a file name, into value.
    void add_text(const std::string& flag, std::string& value, const std::string& help,
                  bool show_default = true);
    // A finite number >= lo (lo_allowed) or > lo, into value; value stays empty when the flag
    // is not given (the scene's own number then).
    void add_number(const std::string& flag, std::optional<real>& value, const std::string& help,
                    double lo, bool lo_allowed);
    // One of the words `allowed`, handed to act when the flag is given.
    void add_choice_action(const std::string& flag, const std::vector<std::string>& allowed,
                           const std::string& help,
                           const std::function<void(const std::string&)>& act);
    // A flag without a value: value becomes true when it is given.
    void add_flag(const std::string& flag, bool& value, const std::string& help);
    // An unsigned 32-bit integer, handed to act when the flag is given.
    void add_uint32_action(const std::string& flag, const std::string& help,
                           const std::function<void(std::uint32_t)>& act);

    // The whole run: parse(), then build the job (so chapter flags can choose the scene), put
    // the flags given over its settings, render with a progress line, write every output all
    // or none, and print a summary. Returns the exit code: 0 on success (or --help), 2 for a
    // user error with one line on stderr naming it, 1 for an internal error.
    int run(int argc, char** argv, const std::function<render_job()>& build);
    // The same, except that once the arguments are parsed `instead` may do the run's whole work
    // itself and return true (chapter 19 writes a scene file rather than render it): then
    // nothing is built or rendered. Its user errors end the run as run()'s do.
    int run(int argc, char** argv, const std::function<render_job()>& build,
            const std::function<bool()>& instead);

    // run()'s first step alone: parses and checks the arguments, builds and renders nothing.
    // Returns the exit code to stop with (0 after --help, 2 after one line on stderr naming the
    // error), or nothing when run() would go on. The fuzz target of the command line calls it.
    std::optional<int> parse(int argc, char** argv);

    // The job's settings with every flag the user gave put over them.
    render_settings with_flags(render_settings scene_defaults) const;

  private:
    using clock = std::chrono::steady_clock;

    // The files a run writes: images (.png and/or .pfm; default "<name>.png"), the variance of
    // each pixel's mean (.pfm) and the record of the run (.json), the last two optional.
    struct output_files {
        std::vector<std::string> images;
        bool exr_half = false;  // the .exr images of `images` in half floats
        std::string variance;
        std::string stats;
    };

    // The chapter's own flags (those it added through app()) and their values in force.
    std::vector<std::pair<std::string, std::string>> chapter_options() const;

    // The render of a job whose camera is initialized for f, with a progress line unless quiet.
    render_result render_with_progress(const film& f, const render_job& job,
                                       const render_settings& settings) const;
    // What --stats-out records of a finished render.
    run_stats record_of(const render_job& job, const film& f, const render_settings& settings,
                        const render_result& result, clock::time_point start) const;
    // Writes every output, all or none; the record (made when the images are written) last.
    void write_outputs(const render_result& result,
                       const std::function<run_stats()>& make_record) const;

    std::string program;
    render_settings flags;  // the values parsed; only those given are used
    bool quiet = false;     // no progress line and no summary
    output_files outputs;
    std::string crop_text;             // --crop as given, checked by the parser
    std::string samples_text;          // --samples as given, checked by the parser
    std::vector<std::string> command;  // the arguments as given, for the record
    std::unique_ptr<CLI::App> cli;
    std::vector<const CLI::Option*> shared_options;  // the flags every chapter has
};

}  // namespace rt
