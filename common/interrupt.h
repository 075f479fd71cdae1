// An interrupted program leaves no half-written file behind. Chapter 01.
// SIGINT (Ctrl-C), SIGTERM (kill) and SIGHUP (the terminal closed) end a render at once, as they
// would without us. What we add: while an image is being written to its temporary file (image_io
// writes there, then renames it over the target), the signal handler first removes that file, so
// the folder keeps the old output exactly as it was and nothing else. The process then dies of
// the same signal (the default action, raised again), so a shell reports 128 + its number, 130
// for SIGINT and 143 for SIGTERM, and a script that ran the program in a loop stops as well
// (a shell ends its own loop only when the child died of the signal, not on exit code 130).
// A signal that was ignored when the handlers would be installed (nohup; a background job of a
// script) stays ignored.
#pragma once

#include <string>

namespace rt {

// While it lives, an interrupting signal removes `path` before the process ends. One at a time:
// image writes are sequential. Creating one installs the handlers; the handler itself makes only
// async-signal-safe calls (unlink, sigaction, raise).
class removed_on_interrupt {
  public:
    explicit removed_on_interrupt(const std::string& path);
    ~removed_on_interrupt();
    removed_on_interrupt(const removed_on_interrupt&)            = delete;
    removed_on_interrupt& operator=(const removed_on_interrupt&) = delete;
};

}  // namespace rt
