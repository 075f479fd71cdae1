// Chapter 04: metal. A polished metal reflects a ray as a mirror, r = v - 2 (v.n) n; a brushed
// one moves the reflected direction by up to `fuzz` inside a ball, blurring the reflection.
// A fuzzed ray that ends up below the surface is absorbed.
#include "metal_scene.h"
#include "rt/integrators/path_tracer.h"
#include "rt/program/command_line.h"

int main(int argc, char** argv) {
    return rt::command_line("ch04_metal").run(argc, argv, [] {
        return rt::path_trace(metal_spheres());
    });
}
