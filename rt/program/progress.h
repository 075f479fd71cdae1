// Chapter 01. Progress of a long render on stderr: percent done, samples per second, time left.
// Any thread may report a finished row; one of them prints, at most a few times a second.
#pragma once

#include <atomic>
#include <chrono>
#include <mutex>

namespace rt {

class progress_meter {
  public:
    // total_rows rows of samples_per_row camera samples each; silent when quiet.
    progress_meter(int total_rows, double samples_per_row, bool quiet);

    void row_done();  // thread-safe
    void finish();    // clears the progress line
    double elapsed_seconds() const;

  private:
    using clock = std::chrono::steady_clock;

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
