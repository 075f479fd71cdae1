// Micro benchmarks of the renderer's hot functions, with Google Benchmark: the
// ray-sphere and ray-quad tests, the slab test, building and traversing the BVH over book 1's
// final scene, and the random numbers. Each reports items per second: rays, objects or numbers.
// Run by tools/bench-micro; single thread.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "book1_rays.h"
#include "rt/accel/aabb.h"
#include "rt/accel/bvh.h"
#include "rt/accel/wide_bvh.h"
#include "rt/core/rng.h"
#include "rt/geometry/quad.h"
#include "rt/geometry/sphere.h"
#include "rt/materials/lambertian.h"
#include "rt/samplers/independent_sampler.h"

namespace {

constexpr std::size_t batch_size = 1024;  // rays per shape benchmark: fits in L1 with the shape
constexpr std::uint64_t seed     = 2024;

// Rays from the origin through target(rng): the shapes below sit around -z.
template <typename Target>
std::vector<rt::ray> rays_towards(Target target) {
    rt::pcg32 rng(/*sequence=*/5, seed);
    std::vector<rt::ray> rays;
    for (std::size_t i = 0; i < batch_size; ++i)
        rays.emplace_back(rt::point3(0, 0, 0), target(rng));
    return rays;
}

// A point of the plane z = -4 at a distance from the z axis uniform in [r0, r1).
rt::point3 ring_point(rt::pcg32& rng, double r0, double r1) {
    double r = r0 + (r1 - r0) * double(rng.uniform()), phi = 2 * rt::pi * double(rng.uniform());
    return rt::point3(r * std::cos(phi), r * std::sin(phi), -4);
}

// Traces every ray of the batch through `object` per iteration.
void trace_batch(benchmark::State& state, const rt::hittable& object,
                 const std::vector<rt::ray>& rays) {
    std::int64_t hits = 0;
    for (auto _ : state) {
        for (const rt::ray& r : rays) {
            rt::hit_record rec;
            bool hit = object.hit(r, rt::interval(0, rt::infinity), rec);
            benchmark::DoNotOptimize(hit);
            benchmark::DoNotOptimize(rec.t);
            hits += hit;
        }
    }
    auto traced = std::int64_t(state.iterations()) * std::int64_t(rays.size());
    state.SetItemsProcessed(traced);
    state.counters["hit_fraction"] = double(hits) / double(traced);
}

const rt::sphere& unit_sphere() {
    static const rt::sphere s(rt::point3(0, 0, -4), 1);
    return s;
}

void ray_sphere_hit(benchmark::State& state) {
    // Aimed within 0.9 of the radius: every ray hits (the sphere looks slightly smaller than 1
    // from the origin, so not closer to the silhouette).
    static const auto rays = rays_towards([](rt::pcg32& rng) { return ring_point(rng, 0, 0.9); });
    trace_batch(state, unit_sphere(), rays);
}

void ray_sphere_miss(benchmark::State& state) {
    static const auto rays = rays_towards([](rt::pcg32& rng) { return ring_point(rng, 1.1, 3); });
    trace_batch(state, unit_sphere(), rays);
}

const rt::quad& square() {
    static const rt::quad q(rt::point3(-1, -1, -4), rt::vec3(2, 0, 0), rt::vec3(0, 2, 0),
                            std::make_shared<rt::lambertian>(rt::color(0.5, 0.5, 0.5)));
    return q;
}

void ray_quad_hit(benchmark::State& state) {
    static const auto rays = rays_towards([](rt::pcg32& rng) { return ring_point(rng, 0, 0.99); });
    trace_batch(state, square(), rays);
}

void ray_quad_miss(benchmark::State& state) {
    // Through the plane outside the square: the miss is found after the plane hit, by (a, b).
    static const auto rays = rays_towards([](rt::pcg32& rng) { return ring_point(rng, 1.5, 3); });
    trace_batch(state, square(), rays);
}

void aabb_slab_test(benchmark::State& state) {
    // Rays from 5 units away towards points of a box twice the size of the test box: about
    // half hit.
    struct slab_ray {
        rt::point3 origin;
        rt::vec3 inv_dir;
    };
    static const auto rays = [] {
        rt::pcg32 rng(/*sequence=*/6, seed);
        auto coordinate = [&](rt::real size) { return size * (2 * rng.uniform() - 1); };
        std::vector<slab_ray> out;
        for (std::size_t i = 0; i < batch_size; ++i) {
            rt::point3 from(coordinate(5), coordinate(5), 5);
            rt::point3 to(coordinate(2), coordinate(2), coordinate(2));
            rt::vec3 d = to - from;
            out.push_back({from, rt::vec3(1 / d.x(), 1 / d.y(), 1 / d.z())});
        }
        return out;
    }();
    const rt::aabb box(rt::point3(-1, -1, -1), rt::point3(1, 1, 1));
    std::int64_t hits = 0;
    for (auto _ : state) {
        for (const slab_ray& r : rays) {
            bool hit = box.hit(r.origin, r.inv_dir, rt::interval(0, rt::infinity));
            benchmark::DoNotOptimize(hit);
            hits += hit;
        }
    }
    auto tested = std::int64_t(state.iterations()) * std::int64_t(rays.size());
    state.SetItemsProcessed(tested);
    state.counters["hit_fraction"] = double(hits) / double(tested);
}

const std::vector<rt::bounded_object>& book1() {
    static const auto objects = rt_bench::book1_objects();
    return objects;
}

void bvh_build(benchmark::State& state) {
    std::size_t nodes = 0;
    for (auto _ : state) {
        // Chapter 07's build, then chapter 17's packing of its tree: what a scene's BVH costs.
        const rt::bvh binary(book1());
        const rt::wide_bvh tree(binary);
        nodes = binary.node_count() + tree.wide_node_count();
        benchmark::DoNotOptimize(nodes);
    }
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(book1().size()));
    state.counters["objects"] = double(book1().size());
    state.counters["nodes"]   = double(nodes);  // binary nodes and wide nodes
}

// The BVH of book 1's final scene and its rays: one camera ray per pixel of the 400 x 225 image.
struct book1_traversal {
    rt::wide_bvh tree{book1()};
    std::vector<rt::ray> camera;
    std::vector<rt::ray> bounce;

    book1_traversal() {
        rt::film f = rt_bench::book1_film();
        camera     = rt_bench::camera_rays(*rt_bench::book1_camera(f), f, 1, seed);
        bounce     = rt_bench::diffuse_bounce_rays(tree, camera, seed);
    }
    static const book1_traversal& get() {
        static const book1_traversal instance;
        return instance;
    }
};

void bvh_camera_rays(benchmark::State& state) {
    trace_batch(state, book1_traversal::get().tree, book1_traversal::get().camera);
}

void bvh_diffuse_bounce_rays(benchmark::State& state) {
    trace_batch(state, book1_traversal::get().tree, book1_traversal::get().bounce);
}

void pcg32_next_u32(benchmark::State& state) {
    rt::pcg32 rng(/*sequence=*/1, seed);
    for (auto _ : state) benchmark::DoNotOptimize(rng.next_u32());
    state.SetItemsProcessed(std::int64_t(state.iterations()));
}

void pcg32_uniform(benchmark::State& state) {
    rt::pcg32 rng(/*sequence=*/1, seed);
    for (auto _ : state) benchmark::DoNotOptimize(rng.uniform());
    state.SetItemsProcessed(std::int64_t(state.iterations()));
}

void sampler_next_2d(benchmark::State& state) {
    rt::independent_sampler s(seed);
    s.start_pixel_sample(17, 42, 3);
    for (auto _ : state) benchmark::DoNotOptimize(s.next_2d());
    state.SetItemsProcessed(std::int64_t(state.iterations()));
}

// Selecting a pixel sample's stream: a hash and a jump ahead of sample_index * 65536 steps,
// paid once per camera sample.
void sampler_start_pixel_sample(benchmark::State& state) {
    rt::independent_sampler s(seed);
    int i = 0;
    for (auto _ : state) {
        s.start_pixel_sample(i & 511, (i >> 9) & 511, i & 1023);
        benchmark::DoNotOptimize(s);
        ++i;
    }
    state.SetItemsProcessed(std::int64_t(state.iterations()));
}

}  // namespace

BENCHMARK(ray_sphere_hit);
BENCHMARK(ray_sphere_miss);
BENCHMARK(ray_quad_hit);
BENCHMARK(ray_quad_miss);
BENCHMARK(aabb_slab_test);
BENCHMARK(bvh_build)->Unit(benchmark::kMicrosecond);
BENCHMARK(bvh_camera_rays)->Unit(benchmark::kMillisecond);
BENCHMARK(bvh_diffuse_bounce_rays)->Unit(benchmark::kMillisecond);
BENCHMARK(pcg32_next_u32);
BENCHMARK(pcg32_uniform);
BENCHMARK(sampler_next_2d);
BENCHMARK(sampler_start_pixel_sample);

BENCHMARK_MAIN();
