#include "rt/scene_files/toml_guard.h"

#include <cctype>

namespace rt {

namespace {

// toml++ asks whether the character after a backslash is whitespace (a line-ending backslash);
// no escape starts with a character outside ASCII anyway.
constexpr const char* escaped_non_ascii =
    "a backslash before a character outside ASCII in a string (no escape starts so)";

}  // namespace

std::optional<toml_guard_finding> toml_guard(std::string_view text) {
    enum class state { between, comment, basic, literal, multi_basic, multi_literal };
    state at = state::between;
    int line = 1, column = 0;
    bool after_line_end_backslash = false;  // in a multi-line basic string, trimming blanks
    // toml++ reads a value that starts with a digit or a sign (a number or a date) up to a
    // comma, a bracket, a brace, '#' or the line's end (past a blank after a date), whatever
    // stands there: a quote in such a run opens no string. To know where a value starts, the
    // scan follows the brackets: '[' an array, '{' an inline table, 'h' a table header.
    std::string open;
    bool value_position = false;  // after '=', or after '[' or ',' in an array
    bool in_number = false, quote_in_number = false;
    bool line_blank = true;  // nothing but blanks yet on this line, outside strings
    auto starts     = [&](std::size_t i, std::string_view what) {
        return text.substr(i, what.size()) == what;
    };
    std::size_t i = 0;
    // A multi-line string may end in up to two more quotes than its three ("""a""""" is "a""):
    // they belong to it.
    auto close_quotes = [&](char quote) {
        for (int extra = 0; extra < 2 && i + 1 < text.size() && text[i + 1] == quote; ++extra)
            ++i, ++column;
    };
    for (; i < text.size(); ++i) {
        const auto byte = static_cast<unsigned char>(text[i]);
        if ((byte & 0xC0) != 0x80) ++column;  // a UTF-8 continuation byte is no new character
        const bool ascii = byte < 0x80;
        if (text[i] == '\n') {
            ++line;
            column = 0;
            if (at == state::comment || at == state::basic || at == state::literal)
                at = state::between;  // a one-line string cut by its line: toml++ refuses it
            if (at == state::between) in_number = quote_in_number = false, line_blank = true;
            continue;
        }
        switch (at) {
            case state::between: {
                if (!ascii)
                    return toml_guard_finding{
                        line, column,
                        quote_in_number
                            ? "a character outside ASCII in a value that starts as a number "
                              "or a date (a quote there opens no string)"
                            : "a character outside ASCII stands outside a string or a "
                              "comment (TOML allows it only inside quotes)"};
                const char c = text[i];
                if (c == ' ' || c == '\t' || c == '\r') break;
                const bool was_blank = line_blank;
                line_blank           = false;
                if (in_number) {
                    if (c != ',' && c != ']' && c != '}' && c != '#') {
                        quote_in_number = quote_in_number || c == '"' || c == '\'';
                        break;
                    }
                    in_number = quote_in_number = false;
                }
                const bool starts_value = value_position;
                value_position          = false;
                if (c == '=') {
                    value_position = true;
                } else if (c == '[') {
                    const bool header =
                        (open.empty() && was_blank) || (!open.empty() && open.back() == 'h');
                    open.push_back(header ? 'h' : '[');
                    value_position = !header;
                } else if (c == '{') {
                    open.push_back('{');
                } else if (c == ']' || c == '}') {
                    if (!open.empty()) open.pop_back();
                } else if (c == ',') {
                    value_position = !open.empty() && open.back() == '[';
                } else if (starts_value &&
                           (std::isdigit(static_cast<unsigned char>(c)) || c == '+' || c == '-')) {
                    in_number = true;
                }
                if (text[i] == '#')
                    at = state::comment;
                else if (starts(i, "\"\"\""))
                    at = state::multi_basic, i += 2, column += 2;
                else if (starts(i, "'''"))
                    at = state::multi_literal, i += 2, column += 2;
                else if (text[i] == '"')
                    at = state::basic;
                else if (text[i] == '\'')
                    at = state::literal;
                break;
            }
            case state::comment:
                break;
            case state::basic:
                if (text[i] == '\\' && i + 1 < text.size() &&
                    static_cast<unsigned char>(text[i + 1]) >= 0x80)
                    return toml_guard_finding{line, column, escaped_non_ascii};
                if (text[i] == '\\' && i + 1 < text.size() && text[i + 1] != '\n')
                    ++i, ++column;
                else if (text[i] == '"')
                    at = state::between;
                break;
            case state::literal:
                if (text[i] == '\'') at = state::between;
                break;
            case state::multi_basic:
                if (after_line_end_backslash) {
                    if (text[i] == ' ' || text[i] == '\t' || text[i] == '\r') break;
                    after_line_end_backslash = false;
                    if (!ascii)
                        return toml_guard_finding{
                            line, column,
                            "a character outside ASCII right after a line-ending backslash in a "
                            "multi-line string (end the line without the backslash)"};
                }
                if (text[i] == '\\') {
                    std::size_t j = i + 1;
                    while (j < text.size() &&
                           (text[j] == ' ' || text[j] == '\t' || text[j] == '\r'))
                        ++j;
                    if (j < text.size() && static_cast<unsigned char>(text[j]) >= 0x80)
                        return toml_guard_finding{line, column, escaped_non_ascii};
                    if (j < text.size() && text[j] == '\n')
                        after_line_end_backslash = true;
                    else if (j < text.size())
                        ++i, ++column;  // an escape: the next character is its
                } else if (starts(i, "\"\"\"")) {
                    at = state::between;
                    i += 2, column += 2;
                    close_quotes('"');
                }
                break;
            case state::multi_literal:
                if (starts(i, "'''")) {
                    at = state::between;
                    i += 2, column += 2;
                    close_quotes('\'');
                }
                break;
        }
    }
    return std::nullopt;
}

}  // namespace rt
