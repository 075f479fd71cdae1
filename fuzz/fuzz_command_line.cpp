// Fuzz target: the command line. Each input is split into words at spaces, tabs, newlines and
// NUL bytes (argv can hold no NUL) and parsed by rt::command_line::parse(), the first step of
// every chapter's run(), with the flags chapter 08 adds (--texture, --scene). Nothing is built,
// rendered or written. The contract checked:
//   - the arguments are accepted, and parse() prints nothing on stderr, or
//   - it stops with exit code 0 (--help, on stdout) and nothing on stderr, or
//   - with exit code 2 and exactly one line on stderr, "<program>: error: <message>";
//   - nothing else: no crash, no sanitizer finding, no exception, no leak, no hang.
// stderr (the stdio stream, not file descriptor 2, which the sanitizers' reports use) is caught
// in memory while parse() runs, so that its line can be checked.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "rt/program/command_line.h"

namespace {

[[noreturn]] void broken(const char* what, const std::string& detail) {
    std::fprintf(stderr, "fuzz_command_line: %s: [%s]\n", what, detail.c_str());
    std::abort();
}

std::vector<std::string> words_of(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> words;
    std::string word;
    for (std::size_t i = 0; i <= size; ++i) {
        const char c = i < size ? char(data[i]) : ' ';
        if (c == ' ' || c == '\t' || c == '\n' || c == '\0') {
            if (!word.empty()) words.push_back(word);
            word.clear();
        } else {
            word += c;
        }
    }
    return words;
}

// Runs parse() with the stdio stream stderr caught in memory; returns its result and the text.
std::optional<int> parse_caught(rt::command_line& cli, std::vector<char*>& argv, std::string& err) {
    char* text        = nullptr;
    std::size_t size  = 0;
    std::FILE* caught = open_memstream(&text, &size);
    if (!caught) broken("open_memstream failed", "");
    std::FILE* real = stderr;
    stderr          = caught;  // glibc's stderr is a variable, which may be set (its manual)
    struct restore {
        std::FILE* real;
        ~restore() { stderr = real; }
    } restored{real};
    const std::optional<int> stop = cli.parse(int(argv.size()) - 1, argv.data());
    std::fclose(caught);
    err.assign(text, size);
    std::free(text);
    return stop;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> words = words_of(data, size);
    std::string program            = "fuzz_command_line";
    std::vector<char*> argv{program.data()};
    for (auto& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);  // argv[argc], as main() gets it

    rt::command_line cli(program);
    std::string texture = "globe.png", scene = "globe";
    cli.add_text("--texture", texture, "Equirectangular image for the globe", false);
    cli.add_choice("--scene", scene, {"globe", "checker"}, "globe or checker", false);

    std::string err;
    const std::optional<int> stop = parse_caught(cli, argv, err);
    if (!stop || *stop == 0) {
        if (!err.empty()) broken("printed on stderr without an error", err);
    } else if (*stop == 2) {
        const std::string prefix = program + ": error: ";
        if (err.rfind(prefix, 0) != 0 || err.size() <= prefix.size() + 1)
            broken("the error line does not start with the program's name", err);
        if (err.find('\n') != err.size() - 1) broken("the error is not exactly one line", err);
    } else {
        broken("an exit code other than 0 or 2", std::to_string(*stop));
    }
    return 0;
}
