// What a scene file may hold, checked before anything is allocated for it. Chapter 19.
#pragma once

#include <cstddef>
#include <cstdint>

namespace rt::scene_limits {

// The file's size, checked before it is read: the largest scene of the book (book 1's final
// scene, 488 spheres) takes about 70 KB as a file; a million spheres about 100 MB.
inline constexpr std::uintmax_t max_file_bytes = std::uintmax_t(1) << 27;
// Objects inside objects (groups, media, transforms, named objects using others): deeper is
// refused, so that reading a hostile file cannot exhaust the stack.
inline constexpr int max_nesting = 64;
// Steps of one object's transform list.
inline constexpr int max_transform_steps = 64;
// The triangles of all of a scene's meshes together: as many as one mesh may hold (chapter 18),
// each model refused before it is read when it declares more than what is left.
inline constexpr std::size_t max_triangles = std::size_t(1) << 27;
// Every coordinate, length, radius and radiance: the book's largest is the ground sphere's 1000;
// a million times its unit keeps the products of a sphere test (lengths to the fourth power)
// far inside float's range, as chapter 18's float build needs.
inline constexpr double max_magnitude = 1e6;

}  // namespace rt::scene_limits
