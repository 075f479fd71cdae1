// How many rays the estimators trace into the world: one per call of the world's hit(), so one
// per path segment (a shadow ray counts too). Chapter 01. render() reports the total, so that
// --stats-out can give rays per second beside camera samples per second.
// A counter per thread, not an atomic shared by all: incrementing it costs one add to memory
// the thread owns, with no contention; render() adds up what each thread counted.
#pragma once

#include <cstdint>

namespace rt {

// Rays traced by this thread since it started. Only ever grows; read differences of it.
inline constinit thread_local std::uint64_t rays_traced_by_this_thread = 0;

// Call once per ray traced into the world.
inline void count_ray() {
    ++rays_traced_by_this_thread;
}

}  // namespace rt
