// Progress of a long render on stderr: percent done, samples per second, time left. The
// render loop tells it of each finished row (render.h's row_observer), from any thread; one of
// them prints, at most a few times a second.
#pragma once

#include <atomic>
#include <chrono>
#include <mutex>

#include "rt/render/render.h"

namespace rt {

class progress_meter : public row_observer {
  public:
    // total_rows rows of samples_per_row camera samples each; silent when quiet.
    progress_meter(int total_rows, double samples_per_row, bool quiet);

    void row_done() override;  // thread-safe
    void finish();             // clears the progress line

  private:
    using clock = std::chrono::steady_clock;
    double elapsed_seconds() const;

    int total_rows;
    double samples_per_row;
    bool quiet;
    bool interactive;  // stderr is a terminal: redraw one line instead of printing many
    clock::time_point start;
    std::atomic<int> rows_done{0};
    std::mutex print_mutex;
    clock::time_point last_print;
};

}  // namespace rt
