#include "interrupt.h"

#include <unistd.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>

namespace rt {

namespace {

constexpr std::array<int, 3> interrupting_signals = {SIGINT, SIGTERM, SIGHUP};

// The file to remove on an interrupt. The handler may run on any thread at any moment, so it
// reads only these: the path is copied in while `armed` is false, then `armed` is set (a lock-free
// atomic, safe to read in a handler), so the handler never sees a path half written. A path that
// does not fit is one no system call would accept (PATH_MAX), so no such file can exist.
std::array<char, 4096> pending_path{};
std::atomic<bool> armed{false};
static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" void on_interrupt(int signal_number) {
    if (armed.load()) ::unlink(pending_path.data());
    // Die of the signal itself: back to the default action (terminate), then raise it again. It
    // stays blocked while this handler runs and is delivered as soon as the handler returns.
    struct sigaction default_action {};
    default_action.sa_handler = SIG_DFL;
    sigemptyset(&default_action.sa_mask);
    ::sigaction(signal_number, &default_action, nullptr);
    ::raise(signal_number);
}

// Installs on_interrupt for each signal not ignored. Again at every write, not once: another
// part of the process (a test framework) may have put its own handlers back in the meantime.
void install_handlers() {
    struct sigaction handler {};
    handler.sa_handler = on_interrupt;
    // While one interrupt is handled the others wait, so the file is removed before any of them
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
    armed.store(false);
    if (path.size() >= pending_path.size()) return;
    std::memcpy(pending_path.data(), path.c_str(), path.size() + 1);
    armed.store(true);
}

removed_on_interrupt::~removed_on_interrupt() {
    armed.store(false);
}

}  // namespace rt
