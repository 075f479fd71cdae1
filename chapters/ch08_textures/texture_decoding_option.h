// --texture-decoding, on chapter 08's program and every later one: how an image texture's bytes
// become light. srgb (the default) decodes them as the sRGB they are; book divides them by 255,
// as the book's code does, so that a render can be compared with one of the book's
// (tools/check-render).
#pragma once

#include <string>

#include "rt/program/command_line.h"
#include "rt/textures/image_texture.h"

inline void add_texture_decoding_option(rt::command_line& cli) {
    cli.add_choice_action(
        "--texture-decoding", {"srgb", "book"},
        "Image texture bytes: srgb (decoded to linear light; default) or book (divided by "
        "255, as the book does)",
        [](const std::string& how) {
            rt::set_default_texel_decoding(how == "book" ? rt::texel_decoding::bytes_over_255
                                                         : rt::texel_decoding::srgb);
        });
}
