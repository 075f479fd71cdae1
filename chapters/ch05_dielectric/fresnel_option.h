// --fresnel, on chapter 05's program and every later one: which reflectance the scene's glass
// uses. schlick (the default) takes Schlick's cosine on the less dense side, as chapter 05
// explains; book takes the incident cosine on both sides, as the book's code does, so that a
// render can be compared with one of the book's (tools/check-render); exact is Fresnel's.
#pragma once

#include <string>

#include "rt/materials/dielectric.h"
#include "rt/program/command_line.h"

inline void add_fresnel_option(rt::command_line& cli) {
    cli.add_choice_action(
        "--fresnel", {"schlick", "book", "exact"},
        "Glass reflectance: schlick (ours, the cosine on the less dense side; default), book "
        "(the book's incident cosine), or exact (Fresnel)",
        [](const std::string& form) {
            rt::set_default_fresnel_model(form == "book"    ? rt::fresnel_model::book_schlick
                                          : form == "exact" ? rt::fresnel_model::exact
                                                            : rt::fresnel_model::schlick);
        });
}
