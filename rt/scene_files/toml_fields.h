// Reading the values of a scene file's tables, each checked where it stands: every refusal is
// one line "FILE:LINE:COLUMN: message" naming the key and what was expected, at the value (or,
// for a missing key, at its table). Chapter 19.
// A table is read through `fields`, told first the keys its kind may have (allow): any other
// key is refused at once, so a misspelt key ("raduis") is an error, not a silent default.
// toml++ (Debian's libtomlplusplus-dev) parses; it knows the line and column of every node.
#pragma once

#include <toml++/toml.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rt/core/error.h"
#include "rt/core/vec3.h"

namespace rt {

// A refusal that names its place already: "FILE:LINE:COLUMN: message".
class located_error : public user_error {
  public:
    using user_error::user_error;
};

// Throws located_error "FILE:LINE:COLUMN: message" for the place `where` (a node's source).
[[noreturn]] void refuse_at(const toml::source_region& where, const std::string& message);

// The same for a place known by its line and column in `file`.
[[noreturn]] void refuse_at(const std::string& file, int line, int column,
                            const std::string& message);

// build(), its refusals without a place (a constructor's "sphere radius must be positive...")
// given the place `where`.
template <typename Build>
auto located(const toml::source_region& where, Build&& build) -> decltype(build()) {
    try {
        return build();
    } catch (const located_error&) {
        throw;
    } catch (const user_error& e) {
        refuse_at(where, e.what());
    }
}

// "FILE:LINE:COLUMN" of a place, as the messages start.
std::string place_of(const toml::source_region& where);

// A TOML value as a message shows it: 1.5, "glass", [1, 2, 3], a table.
std::string shown(const toml::node& value);

class fields {
  public:
    // `table`, described as `what` in messages ("camera", "sphere").
    fields(const toml::table& table, std::string what);

    const toml::table& table() const { return tab; }
    // The keys this table may have, once its kind is known: refuses the first other key at
    // once ("unknown key 'raduis' in sphere (its keys: ...)"), before a missing key is noticed
    // (the likely cause of a missing key is a misspelt one). From then on the table is called
    // `what` in messages ("sphere" rather than "object").
    void allow(std::string what, const std::vector<std::string_view>& keys);

    // The value of `key`, or null when absent.
    const toml::node* find(std::string_view key);
    // The value of `key`; refuses "<what> needs '<key>' (<meaning>)" when absent.
    const toml::node& need(std::string_view key, std::string_view meaning);

    // A finite number (integer or float) in [lo, hi] (lo excluded when lo_open, hi when hi_open).
    real number(std::string_view key, double lo, double hi, bool lo_open = false);
    std::optional<real> number_if(std::string_view key, double lo, double hi, bool lo_open = false,
                                  bool hi_open = false);
    // An integer in [lo, hi].
    std::optional<std::int64_t> integer_if(std::string_view key, std::int64_t lo, std::int64_t hi);
    // Three finite numbers, each within [-limit, limit].
    vec3 vector(std::string_view key, double limit);
    std::optional<vec3> vector_if(std::string_view key, double limit);
    // true or false.
    std::optional<bool> flag_if(std::string_view key);
    // One of `allowed`.
    std::string word(std::string_view key, const std::vector<std::string_view>& allowed);
    std::optional<std::string> word_if(std::string_view key,
                                       const std::vector<std::string_view>& allowed);

    // Refuses at this table: "<what>: message".
    [[noreturn]] void refuse(const std::string& message) const;

  private:
    const toml::table& tab;
    std::string name;
};

// The same checks for a value that is no table's key (an element of an array).
real number_value(const toml::node& value, const std::string& what, double lo, double hi,
                  bool lo_open = false, bool hi_open = false);
vec3 vector_value(const toml::node& value, const std::string& what, double limit);

}  // namespace rt
