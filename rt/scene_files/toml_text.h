// Text as a TOML file writes it, for the writer (scene_writer.cpp), which so needs no toml++
// header of its own (toml++ is heavy to compile and to lint). Chapter 19.
#pragma once

#include <string>

namespace rt {

// A TOML basic string, quoted and escaped by toml++'s own formatter: "glass", "a\"b".
std::string toml_string(const std::string& text);

}  // namespace rt
