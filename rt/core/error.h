// Chapter 01. The one error type for mistakes a user can fix (a bad flag value, a bad scene
// parameter, a missing file). main() catches it, prints its one-line message and exits with code 2.
#pragma once

#include <stdexcept>
#include <string>

namespace rt {

class user_error : public std::runtime_error {
  public:
    explicit user_error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace rt
