// Tests for interrupt.h (chapter 01). Each case forks a child that creates a file, guards it and
// sends itself a signal; the parent checks how the child ended (killed by that very signal) and
// whether the file is gone. tests/cli/interrupt.sh does the same with whole renders.
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <csignal>
#include <filesystem>
#include <functional>
#include <string>

#include "common/interrupt.h"
#include "test_helpers.h"

namespace {

using rt_test::temp_folder, rt_test::write_bytes;

// How a child that ran `body` ended: "signal N", "exit N", or "fork failed".
std::string child_ends(const std::function<void()>& body) {
    const pid_t child = fork();
    if (child < 0) return "fork failed";
    if (child == 0) {
        body();
        _exit(0);  // not through the test framework's exit handlers
    }
    int status = 0;
    if (waitpid(child, &status, 0) != child) return "waitpid failed";
    if (WIFSIGNALED(status)) return "signal " + std::to_string(WTERMSIG(status));
    return "exit " + std::to_string(WEXITSTATUS(status));
}

std::string signal_name(int s) {
    return "signal " + std::to_string(s);
}

}  // namespace

TEST_CASE("interrupt: SIGINT, SIGTERM and SIGHUP remove the guarded file, then kill by the signal",
          "[ch01]") {
    for (int s : {SIGINT, SIGTERM, SIGHUP}) {
        INFO("signal " << s);
        temp_folder dir("interrupt", "removes_" + std::to_string(s));
        const std::string tmp = dir.file("out.png.tmp.1");
        write_bytes(dir.file("out.png"), "old");
        const std::string ends = child_ends([&] {
            write_bytes(tmp, "half an image");
            rt::removed_on_interrupt guard(tmp);
            std::raise(s);
            _exit(3);  // only if the signal did not end the child
        });
        // Died of the signal itself, so a shell reports 128 + s (130 for SIGINT, 143 for SIGTERM).
        CHECK(ends == signal_name(s));
        CHECK_FALSE(std::filesystem::exists(tmp));
        CHECK(rt_test::read_bytes(dir.file("out.png")) == "old");
    }
}

TEST_CASE("interrupt: after the guard ends, or with no guard, an interrupt removes nothing",
          "[ch01]") {
    temp_folder dir("interrupt", "after");
    const std::string first = dir.file("first.tmp"), second = dir.file("second.tmp");
    const std::string ends = child_ends([&] {
        write_bytes(first, "renamed already");
        { rt::removed_on_interrupt guard(first); }
        write_bytes(second, "guarded");
        rt::removed_on_interrupt guard(second);
        std::raise(SIGTERM);
        _exit(3);
    });
    CHECK(ends == signal_name(SIGTERM));
    CHECK(std::filesystem::exists(first));  // its guard had ended
    CHECK_FALSE(std::filesystem::exists(second));
}

TEST_CASE("interrupt: a signal ignored before the guard stays ignored (nohup, background jobs)",
          "[ch01]") {
    temp_folder dir("interrupt", "ignored");
    const std::string tmp  = dir.file("out.pfm.tmp.1");
    const std::string ends = child_ends([&] {
        std::signal(SIGINT, SIG_IGN);
        write_bytes(tmp, "half an image");
        rt::removed_on_interrupt guard(tmp);
        std::raise(SIGINT);
        _exit(7);  // the child goes on after the ignored signal
    });
    CHECK(ends == "exit 7");
    CHECK(std::filesystem::exists(tmp));  // not interrupted, so nothing to clean up
}
