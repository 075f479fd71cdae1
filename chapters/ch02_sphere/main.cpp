// Chapter 02: a sphere. A ray A + t b hits the sphere |P - C| = r where the quadratic
//   (b.b) t^2 + 2 b.(A - C) t + (A - C).(A - C) - r^2 = 0
// has a root; the nearest positive root is the hit. Each hit shows its unit outward normal n
// as the color 0.5 (n + 1). Several samples per pixel smooth the sphere's edge (anti-aliasing).
#include "rt/integrators/show_normals.h"
#include "rt/program/command_line.h"
#include "sphere_scene.h"

int main(int argc, char** argv) {
    return rt::command_line("ch02_sphere").run(argc, argv, [] {
        return rt::show_normals(sphere_on_ground());
    });
}
