#include "rt/scene_files/toml_fields.h"

#include <charconv>
#include <cmath>
#include <sstream>

#include "rt/core/error.h"
#include "rt/core/exercise.h"
#include "rt/scene_files/toml_text.h"

namespace rt {

std::string toml_string(const std::string& text) {
    std::ostringstream out;
    out << toml::toml_formatter(toml::value<std::string>(text),
                                toml::format_flags::allow_unicode_strings);
    return out.str();
}

std::string place_of(const toml::source_region& where) {
    std::ostringstream place;
    place << (where.path ? *where.path : std::string("<scene>")) << ":" << where.begin.line << ":"
          << where.begin.column;
    return place.str();
}

namespace {

// The message as one line of text: a control character (a newline toml++ quotes as the
// character it saw, one inside a quoted key) shown as \n, \r, \t or \xNN.
std::string one_line(const std::string& message) {
    std::string line;
    for (const char c : message) {
        const auto byte = static_cast<unsigned char>(c);
        if (c == '\n')
            line += "\\n";
        else if (c == '\r')
            line += "\\r";
        else if (c == '\t')
            line += "\\t";
        else if (byte < 0x20 || byte == 0x7f) {
            constexpr char hex[] = "0123456789abcdef";
            line += "\\x";
            line += hex[byte >> 4];
            line += hex[byte & 15];
        } else {
            line += c;
        }
    }
    return line;
}

}  // namespace

void refuse_at(const toml::source_region& where, const std::string& message) {
    throw located_error(one_line(place_of(where) + ": " + message));
}

void refuse_at(const std::string& file, int line, int column, const std::string& message) {
    throw located_error(one_line(file + ":" + std::to_string(line) + ":" + std::to_string(column) +
                                 ": " + message));
}

namespace {

// A value as TOML writes it, an array element by element. toml++'s formatter writes each
// single value; an array it does not get: to lay one out, toml++ 3.3.0 estimates each float's
// width as log10 of the float converted to an unsigned integer, undefined behaviour for a float
// below 1 (found by the fuzz target: fuzz/README.md).
void write_value(std::ostringstream& text, const toml::node& value) {
    if (value.is_table()) {
        text << "a table";
    } else if (const toml::array* list = value.as_array()) {
        text << "[";
        for (std::size_t i = 0; i < list->size() && text.tellp() < 80; ++i) {
            if (i > 0) text << ", ";
            write_value(text, *list->get(i));
        }
        text << "]";
    } else if (const auto* number = value.as_floating_point()) {
        char digits[64];  // the shortest form that reads back: 0.05, not 0.050000000000000003
        const auto [end, error] = std::to_chars(digits, digits + sizeof digits, number->get());
        text << std::string_view(digits, std::size_t(end - digits));
    } else {
        value.visit([&](const auto& v) {
            if constexpr (toml::is_value<decltype(v)>)
                text << toml::toml_formatter(v, toml::format_flags::allow_unicode_strings);
        });
    }
}

}  // namespace

std::string shown(const toml::node& value) {
    std::ostringstream text;
    write_value(text, value);
    std::string s = text.str();
    // A message is one line, and never a whole file.
    for (char& c : s)
        if (c == '\n' || c == '\r') c = ' ';
    if (s.size() > 60) {
        s.resize(57);
        s += "...";
    }
    return s;
}

fields::fields(const toml::table& table, std::string what) : tab(table), name(std::move(what)) {}

const toml::node* fields::find(std::string_view key) {
    return tab.get(key);
}

const toml::node& fields::need(std::string_view key, std::string_view meaning) {
    const toml::node* value = find(key);
    if (!value) refuse("needs '" + std::string(key) + "' (" + std::string(meaning) + ")");
    return *value;
}

void fields::refuse(const std::string& message) const {
    refuse_at(tab.source(), name + " " + message);
}

namespace {

std::string range_text(double lo, double hi, bool lo_open, bool hi_open = false) {
    std::ostringstream text;
    text.precision(17);
    if (std::isinf(hi) && lo == -hi) return "a finite number";
    if (std::isinf(hi)) {
        text << "a finite number " << (lo_open ? "> " : ">= ") << lo;
        return text.str();
    }
    text << "a number in " << (lo_open ? "(" : "[") << lo << ", " << hi << (hi_open ? ")" : "]");
    return text.str();
}

}  // namespace

real number_value(const toml::node& value, const std::string& what, double lo, double hi,
                  bool lo_open, bool hi_open) {
    std::optional<double> x;
    if (value.is_integer()) x = double(*value.value<std::int64_t>());
    if (value.is_floating_point()) x = *value.value<double>();
    const std::string expected = range_text(lo, hi, lo_open, hi_open);
    if (!x) refuse_at(value.source(), what + " must be " + expected + ", got " + shown(value));
    const bool inside =
        std::isfinite(*x) && (lo_open ? *x > lo : *x >= lo) && (hi_open ? *x < hi : *x <= hi);
    // Also finite as the renderer's scalar: a double beyond float's range is no float.
    if (!inside || !std::isfinite(real(*x)))
        refuse_at(value.source(), what + " must be " + expected + ", got " + shown(value));
    return real(*x);
}

vec3 vector_value(const toml::node& value, const std::string& what, double limit) {
    const toml::array* list = value.as_array();
    if (!list || list->size() != 3)
        refuse_at(value.source(), what + " must be three numbers [x, y, z], got " + shown(value));
    vec3 v;
    for (std::size_t i = 0; i < 3; ++i)
        v[int(i)] =
            number_value(*list->get(i), what + "[" + std::to_string(i) + "]", -limit, limit);
    return v;
}

real fields::number(std::string_view key, double lo, double hi, bool lo_open) {
    return number_value(need(key, range_text(lo, hi, lo_open)), std::string(key), lo, hi, lo_open);
}

std::optional<real> fields::number_if(std::string_view key, double lo, double hi, bool lo_open,
                                      bool hi_open) {
    const toml::node* value = find(key);
    if (!value) return std::nullopt;
    return number_value(*value, std::string(key), lo, hi, lo_open, hi_open);
}

std::optional<std::int64_t> fields::integer_if(std::string_view key, std::int64_t lo,
                                               std::int64_t hi) {
    const toml::node* value = find(key);
    if (!value) return std::nullopt;
    const std::optional<std::int64_t> n =
        value->is_integer() ? value->value<std::int64_t>() : std::nullopt;
    if (!n || *n < lo || *n > hi)
        refuse_at(value->source(), std::string(key) + " must be an integer in [" +
                                       std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
                                       shown(*value));
    return *n;
}

std::optional<vec3> fields::vector_if(std::string_view key, double limit) {
    const toml::node* value = find(key);
    if (!value) return std::nullopt;
    return vector_value(*value, std::string(key), limit);
}

vec3 fields::vector(std::string_view key, double limit) {
    return vector_value(need(key, "three numbers [x, y, z]"), std::string(key), limit);
}

std::optional<bool> fields::flag_if(std::string_view key) {
    const toml::node* value = find(key);
    if (!value) return std::nullopt;
    if (!value->is_boolean())
        refuse_at(value->source(),
                  std::string(key) + " must be true or false, got " + shown(*value));
    return *value->value<bool>();
}

namespace {

std::string choices(const std::vector<std::string_view>& allowed) {
    std::string text;
    std::size_t i = 0;
    for (std::string_view word : allowed) {
        if (i > 0) text += i + 1 == allowed.size() ? " or " : ", ";
        text += '"';
        text += word;
        text += '"';
        ++i;
    }
    return text;
}

}  // namespace

std::optional<std::string> fields::word_if(std::string_view key,
                                           const std::vector<std::string_view>& allowed) {
    const toml::node* value = find(key);
    if (!value) return std::nullopt;
    std::optional<std::string> word = value->value<std::string>();
    if (value->is_string())
        for (std::string_view w : allowed)
            if (*word == w) return word;
    refuse_at(value->source(),
              std::string(key) + " must be " + choices(allowed) + ", got " + shown(*value));
}

std::string fields::word(std::string_view key, const std::vector<std::string_view>& allowed) {
    need(key, "one of " + choices(allowed));
    return *word_if(key, allowed);
}

void fields::allow(std::string what, const std::vector<std::string_view>& keys) {
    // [exercise fields::allow begin]
    name = std::move(what);
    for (const auto& [key, value] : tab) {
        bool known = false;
        for (std::string_view k : keys) known = known || k == key.str();
        if (known) continue;
        std::string list;
        for (std::string_view k : keys) {
            list += list.empty() ? "" : ", ";
            list += k;
        }
        refuse_at(key.source(), "unknown key '" + std::string(key.str()) + "' in " + name +
                                    " (its keys: " + list + ")");
    }
    // [exercise fields::allow end]
}

}  // namespace rt
