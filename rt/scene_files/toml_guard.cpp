#include "rt/scene_files/toml_guard.h"

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
    auto starts                   = [&](std::size_t i, std::string_view what) {
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
            continue;
        }
        switch (at) {
            case state::between:
                if (!ascii)
                    return toml_guard_finding{line, column,
                                              "a character outside ASCII stands outside a string "
                                              "or a comment (TOML allows it only inside quotes)"};
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
