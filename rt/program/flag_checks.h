// The checks of the command line's values, as CLI11 validators: a bad value is refused while
// parsing, with a message that says the rule and the value ("--width: must be an integer from 1
// to 16384, got 2.5"), before anything is built or rendered.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rt/render/render.h"

namespace rt {

// An integer in [lo, hi], in decimal digits only, so that the number used is the one typed
// (CLI11 alone reads "0x10" as 16, calls 2.5 "not in range 1 to 16384", and turns a --seed of
// -1 into 2^64 - 1).
CLI::Validator integer_in(std::uint64_t lo, std::uint64_t hi);

// A finite real number >= lo ("--aperture: must be a finite number >= 0, got -1"), or > lo.
CLI::Validator number_at_least(double lo);
CLI::Validator number_above(double lo);

// An output file the run can write, ending in one of `extensions` (the first is named in the
// message).
CLI::Validator output_file(const std::vector<std::string>& extensions);
// A .json record of the run (run_stats.h) in an existing folder.
CLI::Validator stats_file();

// --crop X0,Y0,X1,Y1 and --samples FROM:TO: the syntax is checked while parsing; whether the
// values fit the image and the sample count is known only once the scene is built (render.h:
// window_of, samples_of).
CLI::Validator crop_syntax();
CLI::Validator samples_syntax();
std::optional<pixel_window> parse_crop(const std::string& text);
std::optional<sample_range> parse_samples(const std::string& text);

}  // namespace rt
