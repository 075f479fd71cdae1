// Debian's toml++ (package libtomlplusplus-dev, 3.3.0), compiled into the fuzz targets with the
// sanitizers and libFuzzer's coverage, where the normal build links its prebuilt shared library.
// Its internal assertions are compiled out, as in Debian's library (built by g++ 12 with
// NDEBUG, where TOML_ASSERT_ASSUME is nothing at all): 3.3.0's parse_key() asserts that a table
// header's key starts with a key character, while its own code right after reports any other
// character as a parse error, which is what our reader gets ("[\x01]": fuzz/README.md). Not
// clang's NDEBUG form either: that turns the assertion into __builtin_assume, and the parse
// error into undefined behaviour (toml++ issue 294, fixed upstream after 3.3.0).
#define TOML_ASSERT(expr) static_cast<void>(0)
#define TOML_IMPLEMENTATION
#include <toml++/toml.h>
