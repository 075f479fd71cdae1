// Tests for interrupt.h (chapter 01). Each case forks a child that creates files, guards them and
// sends itself a signal; the parent checks how the child ended (killed by that very signal) and
// whether the files are gone. tests/cli/interrupt.sh does the same with whole renders.
#include <catch2/catch.hpp>
#include <csignal>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "child_process.h"
#include "rt/files/interrupt.h"
#include "test_helpers.h"

namespace {

using rt_test::child_ends, rt_test::temp_folder, rt_test::write_bytes;

std::string signal_name(int s) {
    return rt_test::killed_by(s);
}

}  // namespace

TEST_CASE("interrupt: SIGINT, SIGTERM and SIGHUP remove the guarded file, then kill by the signal",
          "[program]") {
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
          "[program]") {
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
          "[program]") {
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

TEST_CASE("interrupt: one signal removes every guarded file", "[program]") {
    temp_folder dir("interrupt", "several");
    std::vector<std::string> files;
    for (int i = 0; i < 5; ++i) files.push_back(dir.file("out" + std::to_string(i) + ".tmp"));
    files.push_back(dir.file("not_guarded.tmp"));
    const std::string ends = child_ends([&] {
        for (const auto& f : files) write_bytes(f, "half an image");
        std::vector<rt::removed_on_interrupt> guards;
        for (std::size_t i = 0; i + 1 < files.size(); ++i) guards.emplace_back(files[i]);
        std::raise(SIGINT);
        _exit(3);
    });
    CHECK(ends == signal_name(SIGINT));
    CHECK(dir.entries() == std::vector<std::string>{"not_guarded.tmp"});
}

TEST_CASE("interrupt: the table holds max_removed_on_interrupt guards, one more throws",
          "[program]") {
    temp_folder dir("interrupt", "table");
    {
        std::vector<rt::removed_on_interrupt> guards;
        guards.reserve(rt::max_removed_on_interrupt);
        for (int i = 0; i < rt::max_removed_on_interrupt; ++i)
            guards.emplace_back(dir.file(std::to_string(i)));
        CHECK_THROWS_AS(rt::removed_on_interrupt(dir.file("one more")), std::length_error);
    }
    // The rows are free again once the guards are gone.
    std::vector<rt::removed_on_interrupt> again;
    again.reserve(rt::max_removed_on_interrupt);
    for (int i = 0; i < rt::max_removed_on_interrupt; ++i)
        CHECK_NOTHROW(again.emplace_back(dir.file(std::to_string(i))));
}

TEST_CASE("interrupt: while interrupts are held a signal waits, end() then removes and dies",
          "[program]") {
    for (int s : {SIGINT, SIGTERM, SIGHUP}) {
        INFO("signal " << s);
        temp_folder dir("interrupt", "held_" + std::to_string(s));
        const std::string tmp = dir.file("out.png.tmp.1"), went_on = dir.file("went_on");
        const std::string ends = child_ends([&] {
            write_bytes(tmp, "half an image");
            rt::removed_on_interrupt guard(tmp);
            rt::interrupts_held hold;
            std::raise(s);
            if (!hold.arrived() || !std::filesystem::exists(tmp)) _exit(4);
            write_bytes(went_on, "the signal waited");
            hold.end();
            _exit(3);  // only if end() did not act on the signal
        });
        CHECK(ends == signal_name(s));
        CHECK(dir.entries() == std::vector<std::string>{"went_on"});
    }
}

TEST_CASE("interrupt: a hold that saw no signal ends quietly, signals act at once again",
          "[program]") {
    temp_folder dir("interrupt", "held_quiet");
    const std::string tmp  = dir.file("out.pfm.tmp.1");
    const std::string ends = child_ends([&] {
        write_bytes(tmp, "half an image");
        rt::removed_on_interrupt guard(tmp);
        {
            rt::interrupts_held hold;
            if (hold.arrived()) _exit(4);
        }
        if (!std::filesystem::exists(tmp)) _exit(5);
        std::raise(SIGTERM);
        _exit(3);
    });
    CHECK(ends == signal_name(SIGTERM));
    CHECK(dir.entries().empty());
}
