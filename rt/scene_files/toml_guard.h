// What the reader refuses before toml++ sees the text. Chapter 19.
// Debian's toml++ 3.3.0 asks whether a character is whitespace wherever whitespace may stand
// between tokens, and for some code points outside ASCII (U+00A1..U+0499, U+2CEE..U+30E7 but
// U+3000) that question reaches a branch the library marks unreachable: undefined behaviour in
// the shipped library (toml++ issues 190 and 295, fixed upstream after 3.3.0). TOML allows
// characters outside ASCII only inside strings (quoted keys included) and comments, so a file
// holding one anywhere else is not TOML anyway; it is refused here, at its line and column,
// before the library reads it. Inside a basic string, toml++ asks the same question of what
// follows a backslash (blanks, then a line's end, make a line-ending backslash): a character
// outside ASCII there, right after the backslash or after its blanks or line end, is refused
// too (no escape starts with one).
// toml++ also reads a value that starts with a digit or a sign (a number, a date) up to its
// terminator, quotes included, so a quote there opens no string for the scan either.
// The scan knows just enough of TOML to tell strings and comments from the rest.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace rt {

struct toml_guard_finding {
    int line = 1, column = 1;  // column counted in characters, as toml++ counts it
    std::string message;
};

// The first thing in `text` that toml++ 3.3.0 cannot be trusted with, or nothing.
std::optional<toml_guard_finding> toml_guard(std::string_view text);

}  // namespace rt
