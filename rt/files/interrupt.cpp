#include "rt/files/interrupt.h"

#include <unistd.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>
#include <stdexcept>

namespace rt {

namespace {

constexpr std::array<int, 3> interrupting_signals = {SIGINT, SIGTERM, SIGHUP};

// The files to remove on an interrupt, one row each. The handler may run on any thread at any
// moment, so it reads only this table: a row's path is copied in while its state is `filling`,
// then the state becomes `armed` (a lock-free atomic, safe to read in a handler), so the handler
// never reads a path half written. A path that does not fit is one no system call would accept
// (PATH_MAX), so no such file can exist and it needs no row.
enum row_state : int { row_free, row_filling, row_armed };
struct guarded_file {
    std::array<char, 4096> path{};
    std::atomic<int> state{row_free};
};
std::array<guarded_file, max_removed_on_interrupt> guarded{};
static_assert(std::atomic<int>::is_always_lock_free);

// 0: signals act at once; -1: held, none arrived yet; > 0: held, this signal arrived. One
// variable, changed by compare-and-swap, so a signal arriving while the hold ends is never lost:
// either the handler stores it before end() takes it, or it finds 0 and acts itself.
std::atomic<int> hold_state{0};
constexpr int held_none = -1;

void remove_guarded_files() {
    for (const guarded_file& g : guarded)
        if (g.state.load() == row_armed) ::unlink(g.path.data());
}

// Die of the signal itself: back to the default action (terminate), then raise it again. In the
// handler it stays blocked until the handler returns, and is delivered then.
void die_of(int signal_number) {
    struct sigaction default_action {};
    default_action.sa_handler = SIG_DFL;
    sigemptyset(&default_action.sa_mask);
    ::sigaction(signal_number, &default_action, nullptr);
    ::raise(signal_number);
}

extern "C" void on_interrupt(int signal_number) {
    int expected = held_none;
    if (hold_state.compare_exchange_strong(expected, signal_number)) return;  // waits for end()
    if (expected > 0) return;  // held, and an earlier signal is already waiting
    remove_guarded_files();
    die_of(signal_number);
}

// Installs on_interrupt for each signal not ignored. Again at every guard, not once: another
// part of the process (a test framework) may have put its own handlers back in the meantime.
void install_handlers() {
    struct sigaction handler {};
    handler.sa_handler = on_interrupt;
    // While one interrupt is handled the others wait, so the files are removed before any of them
    // ends the process.
    sigemptyset(&handler.sa_mask);
    for (int s : interrupting_signals) sigaddset(&handler.sa_mask, s);
    for (int s : interrupting_signals) {
        struct sigaction before {};
        if (::sigaction(s, nullptr, &before) != 0 || before.sa_handler == SIG_IGN) continue;
        ::sigaction(s, &handler, nullptr);
    }
}

}  // namespace

removed_on_interrupt::removed_on_interrupt(const std::string& path) {
    install_handlers();
    if (path.size() >= guarded.front().path.size()) return;
    for (int i = 0; i < max_removed_on_interrupt; ++i) {
        int expected = row_free;
        if (!guarded[i].state.compare_exchange_strong(expected, row_filling)) continue;
        std::memcpy(guarded[i].path.data(), path.c_str(), path.size() + 1);
        guarded[i].state.store(row_armed);
        slot = i;
        return;
    }
    throw std::length_error("more than " + std::to_string(max_removed_on_interrupt) +
                            " files to remove on an interrupt at once");
}

removed_on_interrupt::removed_on_interrupt(removed_on_interrupt&& other) noexcept
    : slot(other.slot) {
    other.slot = -1;
}

removed_on_interrupt::~removed_on_interrupt() {
    if (slot >= 0) guarded[slot].state.store(row_free);
}

interrupts_held::interrupts_held() {
    install_handlers();
    hold_state.store(held_none);
}

bool interrupts_held::arrived() const {
    return hold_state.load() > 0;
}

void interrupts_held::end() {
    if (!holding) return;
    holding                 = false;
    const int signal_number = hold_state.exchange(0);
    if (signal_number <= 0) return;
    remove_guarded_files();
    die_of(signal_number);
    ::_exit(128 + signal_number);  // only if this thread blocks the signal: end as a shell says
}

}  // namespace rt
