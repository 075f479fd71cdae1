// Chapter 01. The hole a student fills. In an exercise workspace (tools/exercise), the code of
// each exercise region (its begin and end markers: tools/check-layers) is replaced by one call of
// not_implemented_yet, so that the workspace compiles and each target that reaches the missing
// code fails with one line saying what to write and where to read about it:
//   not implemented yet: metal::scatter, chapter 04 README step 3
// In this tree the regions hold the solution, and nothing calls it.
#pragma once

#include <stdexcept>

namespace rt {

class not_implemented : public std::logic_error {
  public:
    using std::logic_error::logic_error;
};

// Throws not_implemented with that line. Inside the render's threads an exception cannot
// leave its OpenMP region, so there the line is printed once, on stderr, and the program ends
// with exit code 3.
[[noreturn]] void not_implemented_yet(const char* what, const char* where);

}  // namespace rt
