// Book 1's final scene as the benchmarks see it (chapters/ch06_defocus, `--scene final`): its
// ~480 spheres, its camera, and the two batches of rays the benchmarks measure on it: camera
// rays and diffuse bounce rays from their hits.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "rt/accel/bounded.h"
#include "rt/camera/thin_lens_camera.h"
#include "rt/render/film.h"

namespace rt_bench {

// The spheres of book 1's final scene (random_spheres()), each with its box, for a BVH.
std::vector<rt::bounded_object> book1_objects();

// The scene's image: 400 x 225, as tools/benchmark renders it.
rt::film book1_film();

// Its camera (the settings of ch06_defocus's final_scene()), initialized for f.
std::shared_ptr<rt::thin_lens_camera> book1_camera(const rt::film& f);

// One camera ray per pixel sample, pixel by pixel, samples_per_pixel per pixel: the rays a
// render draws first, from the sampler streams of `seed`.
std::vector<rt::ray> camera_rays(const rt::camera& cam, const rt::film& f, int samples_per_pixel,
                                 std::uint64_t seed);

// From each ray's nearest hit in world (within (0, inf)), one ray in a cosine-weighted direction
// about the normal, as a diffuse surface scatters it; rays that miss give none. Origins are
// offset for float (single_precision.h), so the rays can go to Embree as they are.
std::vector<rt::ray> diffuse_bounce_rays(const rt::hittable& world, const std::vector<rt::ray>& in,
                                         std::uint64_t seed);

}  // namespace rt_bench
