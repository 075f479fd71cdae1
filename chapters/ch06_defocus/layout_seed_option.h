// --layout-seed, on chapter 06's program and every later one: the seed of the book's rand() that
// the scenes' random layouts (book 1's final scene, the bouncing spheres, book 2's final scene)
// and the Perlin tables are drawn from. 1, the default, is the book's own layout; any other
// gives another layout the book's code could have drawn, which tools/check-render uses to tell
// what does not depend on the layout (a student whose rand() is MSVC's has such a layout).
#pragma once

#include <cstdint>

#include "rt/core/book_random.h"
#include "rt/program/command_line.h"

inline void add_layout_seed_option(rt::command_line& cli) {
    cli.add_uint32_action(
        "--layout-seed",
        "srand() seed of the book's random layouts and Perlin tables (default 1, the book's)",
        [](std::uint32_t seed) { rt::set_book_layout_seed(seed); });
}
