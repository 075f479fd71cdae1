// An interrupted program leaves no half-written file behind.
// SIGINT (Ctrl-C), SIGTERM (kill) and SIGHUP (the terminal closed) end a render at once, as they
// would without us. What we add: while a run's outputs are being written to their temporary
// files (output_set.h writes each one beside its target, then renames them all onto their
// targets), the signal handler first removes every one of those files, so the folders keep the old
// outputs exactly as they were and nothing else. The process then dies of the same signal (the
// default action, raised again), so a shell reports 128 + its number, 130 for SIGINT and 143 for
// SIGTERM, and a script that ran the program in a loop stops as well (a shell ends its own loop
// only when the child died of the signal, not on exit code 130).
// While the temporary files are being renamed onto their targets (a few system calls), a signal
// waits instead (interrupts_held): output_set then undoes the renames made, and the process dies.
// A signal that was ignored when the handlers would be installed (nohup; a background job of a
// script) stays ignored.
#pragma once

#include <string>

namespace rt {

// How many files can be guarded at once. The handler may make only async-signal-safe calls, so
// it cannot walk a growing list: it reads the paths from a fixed table, filled in before a signal
// can need them.
inline constexpr int max_removed_on_interrupt = 32;

// While it lives, an interrupting signal removes `path` before the process ends. Creating one
// installs the handlers; the handler itself makes only async-signal-safe calls (unlink,
// sigaction, raise) and reads lock-free atomics. Guards are created and ended by one thread at
// a time (the one writing the outputs); the signal may arrive on any thread.
class removed_on_interrupt {
  public:
    // Throws std::length_error when max_removed_on_interrupt guards live already (output_set
    // refuses more files than that with a user_error first).
    explicit removed_on_interrupt(const std::string& path);
    ~removed_on_interrupt();
    removed_on_interrupt(removed_on_interrupt&& other) noexcept;
    removed_on_interrupt(const removed_on_interrupt&)            = delete;
    removed_on_interrupt& operator=(const removed_on_interrupt&) = delete;
    removed_on_interrupt& operator=(removed_on_interrupt&&)      = delete;

  private:
    int slot = -1;  // its row in the handler's table; -1: nothing to remove
};

// While it lives, an interrupting signal waits: the handler notes it and returns, so a sequence
// of steps that must all happen or none (output_set::commit's renames) is not cut in the middle.
// One at a time.
class interrupts_held {
  public:
    interrupts_held();
    ~interrupts_held() { end(); }
    interrupts_held(const interrupts_held&)            = delete;
    interrupts_held& operator=(const interrupts_held&) = delete;

    // Whether a signal has arrived since the hold began (and is waiting).
    bool arrived() const;

    // Ends the hold. A signal that arrived meanwhile now does what it would have done at once:
    // removes the guarded files and ends the process by that signal (so this does not return).
    void end();

  private:
    bool holding = true;
};

}  // namespace rt
