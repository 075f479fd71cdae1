#include "rt/program/progress.h"

#include <unistd.h>

#include <cstdio>

namespace rt {

progress_meter::progress_meter(int rows, double per_row, bool be_quiet)
    : total_rows(rows),
      samples_per_row(per_row),
      quiet(be_quiet),
      interactive(::isatty(STDERR_FILENO) != 0),
      start(clock::now()),
      last_print(start) {}

double progress_meter::elapsed_seconds() const {
    return std::chrono::duration<double>(clock::now() - start).count();
}

void progress_meter::row_done() {
    int done = ++rows_done;
    if (quiet) return;
    // A log file gets a line every 5 s; a terminal a redrawn line 4 times a second.
    const auto interval = interactive ? std::chrono::milliseconds(250) : std::chrono::seconds(5);
    std::unique_lock lock(print_mutex, std::try_to_lock);
    if (!lock.owns_lock()) return;  // another thread is printing; never wait in the render loop
    auto now = clock::now();
    if (now - last_print < interval) return;
    last_print = now;

    double seconds = elapsed_seconds();
    double rate    = done * samples_per_row / seconds;
    double left    = seconds * (total_rows - done) / done;
    std::fprintf(stderr, "%s%5.1f%% | %8.3f M samples/s | %6.1f s left%s", interactive ? "\r" : "",
                 100.0 * done / total_rows, rate * 1e-6, left, interactive ? "" : "\n");
    std::fflush(stderr);
}

void progress_meter::finish() {
    if (!quiet && interactive) std::fprintf(stderr, "\r%60s\r", "");
}

}  // namespace rt
