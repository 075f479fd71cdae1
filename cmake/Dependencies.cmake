# Every dependency comes from a Debian package; a missing one stops the configure step with the
# package to install, so nobody has to guess from a compiler error.
function(rt_require_package found package what)
  if(NOT ${found})
    message(FATAL_ERROR "${what} not found: install the Debian package '${package}' "
                        "(sudo apt-get install ${package}) or run tools/install-deps")
  endif()
endfunction()

find_path(STB_INCLUDE_DIR stb/stb_image_write.h)
find_library(STB_LIBRARY stb)
rt_require_package(STB_INCLUDE_DIR libstb-dev "stb headers (stb/stb_image_write.h)")
rt_require_package(STB_LIBRARY libstb-dev "stb library (libstb.so)")
add_library(stb::stb UNKNOWN IMPORTED)
set_target_properties(stb::stb PROPERTIES IMPORTED_LOCATION "${STB_LIBRARY}"
                                          INTERFACE_INCLUDE_DIRECTORIES "${STB_INCLUDE_DIR}")

find_package(CLI11 CONFIG QUIET)
rt_require_package(CLI11_FOUND libcli11-dev "CLI11 (CLI/CLI.hpp)")

find_package(OpenMP QUIET COMPONENTS CXX)
rt_require_package(OpenMP_CXX_FOUND "libgomp1 (part of g++)" "OpenMP for C++")

if(BUILD_TESTING OR NOT DEFINED BUILD_TESTING)
  find_package(Catch2 2 CONFIG QUIET)
  rt_require_package(Catch2_FOUND catch2 "Catch2 v2 (catch2/catch.hpp)")
  find_program(IDIFF_EXECUTABLE idiff)
  rt_require_package(IDIFF_EXECUTABLE openimageio-tools "OpenImageIO's idiff")
  find_program(OIIOTOOL_EXECUTABLE oiiotool)
  rt_require_package(OIIOTOOL_EXECUTABLE openimageio-tools "OpenImageIO's oiiotool")
endif()

# Warnings on everywhere; the code base stays clean under them.
add_library(rt_warnings INTERFACE)
target_compile_options(rt_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                             -Wno-sign-conversion
                                             -Wno-missing-field-initializers)
# The test command (tools/run-tests) builds with warnings as errors, so CI fails on a warning;
# a student's own build only shows them.
option(RT_WERROR "Treat compiler warnings as errors" OFF)
if(RT_EXERCISE_WORKSPACE)
  target_compile_options(rt_warnings INTERFACE -Wno-unused-parameter -Wno-unused-variable
                                               -Wno-unused-but-set-variable)
endif()
if(RT_WERROR)
  target_compile_options(rt_warnings INTERFACE -Werror)
endif()
