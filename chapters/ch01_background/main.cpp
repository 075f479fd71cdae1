// Chapter 01: the background. With nothing in the scene every ray sees the sky, a blend from
// white (looking down) to light blue (looking up) by the y of the ray's unit direction:
//   color = (1 - a) * white + a * blue,   a = (y + 1) / 2.
#include "empty_sky.h"
#include "rt/program/command_line.h"

int main(int argc, char** argv) {
    return rt::command_line("ch01_background").run(argc, argv, empty_sky);
}
