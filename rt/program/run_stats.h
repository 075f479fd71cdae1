// The record of one run, for machines: --stats-out FILE.json.
// The tools (tools/benchmark, tools/render-report, tools/merge, and any later convergence
// driver) read this file instead of the progress line on stderr, which is for people. One JSON
// object; README.md ("Every chapter's command line") lists its keys. Written like the images,
// into the run's output_set (output_set.h), and added after them: it is renamed onto FILE last,
// so its presence means every image of the run is complete.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "rt/files/output_set.h"
#include "rt/render/film.h"
#include "rt/render/render.h"

namespace rt {

struct run_stats {
    std::string program;     // the chapter's program, e.g. "ch07_motion_blur"
    std::string integrator;  // the estimator's name(): "sky", "normals", "path", ...
    std::string sampler;     // how pixel samples are drawn: "independent"
    // The chapter's own flags (--scene, --accel, ...) with the values in force, given or not:
    // two parts of one render must agree on them.
    std::vector<std::pair<std::string, std::string>> options;
    std::vector<std::string> command;  // the command line as given, for the record
    film full;                         // the whole image the render is (a part of)
    render_settings settings;          // threads resolved (never 0)
    pixel_window window;               // the pixels rendered
    sample_range samples;              // the sample indices rendered
    std::uint64_t camera_samples = 0;  // samples estimated (fewer where pixels stop early)
    std::uint64_t rays           = 0;  // rays traced into the world
    double seconds               = 0;  // the render loop, wall clock
    double process_seconds       = 0;  // the whole run: scene, render and writing the images
    std::vector<std::string> outputs;  // image files written
    std::string variance_output;       // or empty
};

// The record as a JSON object (paths relative to `relative_to`, a folder).
std::string to_json(const run_stats& stats, const std::string& relative_to);

// Empty when `path` can be written as a stats file (ends in .json, existing folder); else why.
std::string stats_path_problem(const std::string& path);

// Writes to_json(stats) into `outputs` (onto path at outputs.commit()); paths in it are relative
// to path's folder. Add it after the images. Throws user_error naming path and the reason.
void write_stats(output_set& outputs, const std::string& path, const run_stats& stats);

}  // namespace rt
