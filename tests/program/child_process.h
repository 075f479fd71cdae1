// Running a piece of a test in a child process, to see how it ends: the interrupt tests
// (test_interrupt.cpp, test_output_set.cpp) let a child be killed by a signal, which the test
// process itself must survive. Chapter 01.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <functional>
#include <string>

namespace rt_test {

// How a child that ran `body` ended: "signal N", "exit N", or "fork failed". The child leaves by
// _exit(0) after body (not through the test framework's exit handlers), unless body ends it.
inline std::string child_ends(const std::function<void()>& body) {
    const pid_t child = fork();
    if (child < 0) return "fork failed";
    if (child == 0) {
        body();
        _exit(0);
    }
    int status = 0;
    if (waitpid(child, &status, 0) != child) return "waitpid failed";
    if (WIFSIGNALED(status)) return "signal " + std::to_string(WTERMSIG(status));
    return "exit " + std::to_string(WEXITSTATUS(status));
}

inline std::string killed_by(int signal_number) {
    return "signal " + std::to_string(signal_number);
}

}  // namespace rt_test
