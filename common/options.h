// The command line every chapter shares (CLI11):
//   chNN_name [--width N] [--spp N] [--max-depth N] [--seed N] [--threads N] [--out FILE]...
//             [--variance-out FILE] [--quiet] [--help]
// A chapter may add flags of its own through app() before it runs. Chapter 01.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "render.h"
#include "scene.h"

namespace rt {

// A chapter's settings; the defaults a chapter passes in are its report settings.
struct chapter_settings {
    int width = 400;                   // Image width in pixels; height from the aspect ratio
    render_settings render;            // spp, max depth, seed, threads, quiet
    std::vector<std::string> outputs;  // .png and/or .pfm files; default "<name>.png"
    std::string variance_output;       // optional .pfm of the per-pixel variance of the mean
};

class command_line {
  public:
    command_line(std::string program_name, chapter_settings defaults);

    CLI::App& app() { return cli; }
    const std::string& name() const { return program; }

    // For a scene function called by run(): whether the user gave `flag` (e.g. "--width"), and
    // the settings to change where they did not, so a scene can bring its own defaults.
    bool given(const std::string& flag) const { return cli.count(flag) > 0; }
    chapter_settings& settings() { return current; }

    // Parses the arguments, builds the scene, renders it and writes every output. Returns the
    // exit code: 0 on success (or --help), 2 for a user error with one line on stderr naming it.
    int run(int argc, char** argv, const std::function<scene()>& build_scene);

  private:
    std::string program;
    chapter_settings current;
    CLI::App cli;
};

}  // namespace rt
