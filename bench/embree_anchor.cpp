// The Embree anchor: the same batches of rays traced through our fastest BVH (chapter 17's) and
// through Embree 3, one ray at a time on one thread, closest hit, and the rays per second of each.
//   embree_anchor --out FILE.json [--rays N] [--repeat N] [--note TEXT]
// Batches (generated once, from fixed seeds, and rounded to float so both see the same rays):
//   book1-camera   book 1's final scene (ch06 --scene final): its camera, 400 x 225, one ray
//                  per pixel sample, ceil(N / 90,000) samples per pixel;
//   book1-bounce   from each camera ray's hit, a cosine-weighted direction about the normal;
//   ch07-recorded  the rays a path trace of book 2's bouncing spheres (ch07) at time 0 traces
//                  (400 x 225, depth 50): the moving spheres stand at their start;
//   ch13-recorded  the rays a path trace of book 2's final scene (ch13) at time 0 traces
//                  (400 x 400, depth 40), against its spheres and quads (anchor_geometry.h
//                  says what is left out);
//   ch11-recorded  the rays a path trace of book 2's Cornell box (ch11) traces (200 x 200,
//                  depth 50), against its walls, light and the boxes' faces in the world.
// Each batch is timed `repeat` times, ours and Embree in turn; the median counts. Hit counts
// of the two must agree up to rays that graze an edge or a silhouette (float against double).
#include <time.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <unordered_map>
#include <vector>

#include "anchor_geometry.h"
#include "book1_rays.h"
#include "ch06_defocus/random_spheres.h"
#include "ch11_instances/cornell_box.h"
#include "ch13_final/final_scene.h"
#include "embree_scene.h"
#include "recorded_rays.h"
#include "rt/accel/fast_traversal.h"
#include "rt/accel/wide_bvh.h"
#include "rt/integrators/path_tracer.h"
#include "single_precision.h"

namespace {

using rt_bench::anchor_geometry;

constexpr std::uint64_t seed = 2024;

// One scene's shapes in both tracers.
struct both_tracers {
    const anchor_geometry& geometry;
    std::vector<rt::bounded_object> objects = geometry.objects();
    rt::wide_bvh ours{objects};
    rt_bench::embree_scene embree{geometry};
    std::unordered_map<const rt::hittable*, std::int32_t> shape_of;

    explicit both_tracers(const anchor_geometry& g) : geometry(g) {
        for (std::size_t k = 0; k < objects.size(); ++k)
            shape_of[objects[k].object.get()] = std::int32_t(k);
    }
};

struct batch {
    std::string name;
    const both_tracers* tracers;
    std::vector<rt::ray> rays;
    std::vector<rt_bench::recorded_rays::surface_hit> surface_hits;  // to check (recorded only)
};

struct result {
    std::vector<double> ours_seconds, embree_seconds;
    std::size_t hits_ours = 0, hits_embree = 0, same_shape = 0, only_ours = 0, only_embree = 0;
    std::size_t checked = 0, check_agrees = 0;  // the geometry check of recorded batches

    double ours_rate(std::size_t rays) const { return double(rays) / median(ours_seconds); }
    double embree_rate(std::size_t rays) const { return double(rays) / median(embree_seconds); }
    static double median(std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
    }
};

// The CPU time of this thread, in seconds: what one core spends, without the time other work
// on a shared machine takes the core away (Google Benchmark's rates count the same).
double thread_seconds() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
}

// Our closest hits: the object hit (null for a miss) and the distance.
double trace_ours(const rt::hittable& world, const std::vector<rt::ray>& rays,
                  std::vector<const rt::hittable*>& object, std::vector<rt::real>& t) {
    object.assign(rays.size(), nullptr);
    t.assign(rays.size(), 0);
    double start = thread_seconds();
    for (std::size_t i = 0; i < rays.size(); ++i) {
        rt::hit_record rec;
        if (world.hit(rays[i], rt::interval(0, rt::infinity), rec)) {
            object[i] = rec.object;
            t[i]      = rec.t;
        }
    }
    return thread_seconds() - start;
}

result measure(const batch& b, int repeat) {
    std::vector<RTCRay> embree_rays;
    embree_rays.reserve(b.rays.size());
    for (const rt::ray& r : b.rays) embree_rays.push_back(rt_bench::embree_ray(r));

    result out;
    std::vector<const rt::hittable*> ours_object;
    std::vector<rt::real> ours_t;
    std::vector<std::int32_t> embree_shape;
    std::vector<float> embree_t;
    for (int k = 0; k < repeat; ++k) {
        out.ours_seconds.push_back(trace_ours(b.tracers->ours, b.rays, ours_object, ours_t));
        double start = thread_seconds();
        b.tracers->embree.trace(embree_rays, embree_shape, embree_t);
        out.embree_seconds.push_back(thread_seconds() - start);
    }

    for (std::size_t i = 0; i < b.rays.size(); ++i) {
        std::int32_t ours   = ours_object[i] ? b.tracers->shape_of.at(ours_object[i]) : -1;
        std::int32_t theirs = embree_shape[i];
        out.hits_ours += ours >= 0;
        out.hits_embree += theirs >= 0;
        out.same_shape += ours >= 0 && ours == theirs;
        out.only_ours += ours >= 0 && theirs < 0;
        out.only_embree += ours < 0 && theirs >= 0;
        if (!b.surface_hits.empty() && std::isfinite(b.surface_hits[i].p.x())) {
            // The real scene hits a surface along this ray: our copy of its shapes must hit the
            // same point, within the error bound of that hit in the float build (the copy is
            // rounded to float). The real p may be off by as much (a float ground sphere of
            // radius 1000 rounds its hit points by ~1e-4).
            ++out.checked;
            const auto& expected = b.surface_hits[i];
            rt::real tolerance =
                expected.error + rt::real(1e-6) * rt::max_abs_component(expected.p);
            out.check_agrees += ours >= 0 && rt::max_abs_component(b.rays[i].at(ours_t[i]) -
                                                                   expected.p) <= tolerance;
        }
    }
    return out;
}

// s as a JSON string: quotes and backslashes escaped, control characters dropped.
std::string json_string(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) >= 0x20) out += c;
    }
    return out + "\"";
}

void write_json(const std::string& path, const std::vector<batch>& batches,
                const std::vector<result>& results, int repeat, const std::string& note) {
    const std::string temporary = path + ".tmp";
    {
        std::ofstream json(temporary);
        json << std::setprecision(6);
        json << "{\n  \"program\": \"embree_anchor\",\n  \"embree\": \"" << RTC_VERSION_STRING
             << "\",\n  \"real\": \"" << (sizeof(rt::real) == 8 ? "double" : "float")
             << "\",\n  \"threads\": 1,\n  \"repeat\": " << repeat
             << ",\n  \"note\": " << json_string(note) << ",\n  \"batches\": [\n";
        for (std::size_t k = 0; k < batches.size(); ++k) {
            const batch& b  = batches[k];
            const result& r = results[k];
            auto seconds    = [&](const std::vector<double>& v) {
                std::string s;
                for (double x : v) s += (s.empty() ? "" : ", ") + std::to_string(x);
                return "[" + s + "]";
            };
            json << "    {\"batch\": \"" << b.name << "\", \"rays\": " << b.rays.size()
                 << ", \"ours_rays_per_second\": " << r.ours_rate(b.rays.size())
                 << ", \"embree_rays_per_second\": " << r.embree_rate(b.rays.size())
                 << ", \"ratio\": " << r.ours_rate(b.rays.size()) / r.embree_rate(b.rays.size())
                 << ", \"hits_ours\": " << r.hits_ours << ", \"hits_embree\": " << r.hits_embree
                 << ", \"same_shape\": " << r.same_shape << ", \"only_ours\": " << r.only_ours
                 << ", \"only_embree\": " << r.only_embree
                 << ", \"spheres\": " << b.tracers->geometry.spheres.size()
                 << ", \"quads\": " << b.tracers->geometry.quads.size()
                 << ", \"ours_seconds\": " << seconds(r.ours_seconds)
                 << ", \"embree_seconds\": " << seconds(r.embree_seconds);
            if (!b.surface_hits.empty())
                json << ", \"geometry_check\": {\"surface_hits\": " << r.checked
                     << ", \"agree\": " << r.check_agrees << "}";
            if (!b.tracers->geometry.left_out.empty())
                json << ", \"left_out\": " << json_string(b.tracers->geometry.left_out);
            json << "}" << (k + 1 < batches.size() ? "," : "") << "\n";
        }
        json << "  ]\n}\n";
        if (!json) throw std::runtime_error("could not write " + temporary);
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0)
        throw std::runtime_error("could not rename " + temporary + " to " + path);
}

void print_table(const std::vector<batch>& batches, const std::vector<result>& results) {
    std::cout << std::left << std::setw(15) << "batch" << std::right << std::setw(9) << "rays"
              << std::setw(12) << "ours M/s" << std::setw(12) << "Embree M/s" << std::setw(13)
              << "ours/Embree" << std::setw(11) << "hits ours" << std::setw(13) << "hits Embree"
              << std::setw(12) << "same shape" << '\n';
    for (std::size_t k = 0; k < batches.size(); ++k) {
        const batch& b  = batches[k];
        const result& r = results[k];
        double ours = r.ours_rate(b.rays.size()), embree = r.embree_rate(b.rays.size());
        std::cout << std::left << std::setw(15) << b.name << std::right << std::setw(9)
                  << b.rays.size() << std::fixed << std::setprecision(2) << std::setw(12)
                  << ours / 1e6 << std::setw(12) << embree / 1e6 << std::setprecision(3)
                  << std::setw(13) << ours / embree << std::setw(11) << r.hits_ours << std::setw(13)
                  << r.hits_embree << std::setw(12) << r.same_shape << '\n';
    }
    for (std::size_t k = 0; k < batches.size(); ++k) {
        const result& r = results[k];
        if (r.only_ours + r.only_embree > 0)
            std::cout << batches[k].name << ": hit by ours only " << r.only_ours
                      << ", by Embree only " << r.only_embree << " (grazing rays)\n";
        if (r.checked > 0)
            std::cout << batches[k].name << ": geometry check, " << r.check_agrees << " of "
                      << r.checked << " surface hits of the real scene found by the copy\n";
    }
}

// Book 2's bouncing spheres (ch07) at time 0: its spheres (the moving ones at their start),
// its camera with the shutter closed.
rt::scene bouncing_spheres_at_time_0() {
    auto cam        = std::make_shared<rt::thin_lens_camera>();
    cam->vfov       = 20;
    cam->lookfrom   = rt::point3(13, 2, 3);
    cam->lookat     = rt::point3(0, 0, 0);
    cam->focus_dist = 10;
    cam->aperture   = 2 * cam->focus_dist * std::tan(rt::degrees_to_radians(0.01));
    rt::scene sc;
    std::vector<rt::bounded_object> spheres;
    for (auto& s : random_sphere_layout(/*bouncing=*/true)) spheres.emplace_back(s.sphere);
    sc.world    = std::make_shared<rt::wide_bvh>(spheres);
    sc.sky      = rt::background::uniform(rt::color(0.70, 0.80, 1.00));
    sc.cam      = cam;
    sc.settings = {.width = 400, .samples_per_pixel = 1, .max_depth = 50};
    return sc;
}

// Book 2's final scene (ch13) at time 0, at the depth tools/benchmark renders it with.
rt::scene book2_final_at_time_0() {
    rt::scene sc = rt::with_fast_traversal(book2_final_scene(RT_ASSET_DIR "/globe.png"));
    std::dynamic_pointer_cast<rt::thin_lens_camera>(sc.cam)->shutter_close = 0;
    sc.settings.max_depth                                                  = 40;
    return sc;
}

// Book 2's Cornell box (ch11) at the settings tools/benchmark renders it with.
rt::scene cornell_box_at_benchmark_settings() {
    rt::scene sc          = rt::with_fast_traversal(cornell_box());
    sc.settings.width     = 200;
    sc.settings.max_depth = 50;
    return sc;
}

// The recorded batch of sc, with about `rays` rays.
batch recorded_batch(const std::string& name, const both_tracers& tracers, const rt::scene& sc,
                     std::size_t rays) {
    // A first pass of one sample per pixel tells how many rays a sample brings.
    std::size_t per_sample = rt_bench::record_rays(sc, 1, rays).recorded;
    int samples            = int(std::max<std::size_t>(1, (rays + per_sample - 1) / per_sample));
    rt_bench::recorded_rays recorded = rt_bench::record_rays(sc, samples, rays);
    std::cerr << name << ": " << recorded.recorded << " rays traced at " << samples
              << " samples per pixel, " << recorded.respawned << " of them spawned from a hit; "
              << recorded.rays.size() << " kept\n";
    return {name, &tracers, std::move(recorded.rays), std::move(recorded.surface_hits)};
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Traces the same rays through our BVH and through Embree 3 (one thread)"};
    std::string out;
    std::size_t rays = 1000000;
    int repeat       = 3;
    app.add_option("--out", out, "JSON file of the results")->required();
    app.add_option("--rays", rays, "Rays per batch, about")
        ->check(CLI::Range(std::size_t(1000), std::size_t(1) << 26))
        ->capture_default_str();
    std::string note;
    app.add_option("--note", note, "Free text kept in the JSON (the commit, the load)");
    app.add_option("--repeat", repeat, "Timings per batch and tracer; the median counts")
        ->check(CLI::Range(1, 99))
        ->capture_default_str();
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;
    }

    try {
        const anchor_geometry book1    = rt_bench::book1_geometry();
        const anchor_geometry bouncing = rt_bench::bouncing_geometry();
        const anchor_geometry book2    = rt_bench::book2_final_geometry();
        const anchor_geometry cornell  = rt_bench::cornell_box_geometry();
        const both_tracers book1_tracers(book1), bouncing_tracers(bouncing), book2_tracers(book2),
            cornell_tracers(cornell);

        std::vector<batch> batches;
        rt::film f         = rt_bench::book1_film();
        std::size_t pixels = std::size_t(f.width) * std::size_t(f.height);
        int samples        = int((rays + pixels - 1) / pixels);
        std::vector<rt::ray> camera =
            rt_bench::camera_rays(*rt_bench::book1_camera(f), f, samples, seed);
        for (rt::ray& r : camera) r = rt_bench::to_float(r);
        std::vector<rt::ray> bounce =
            rt_bench::diffuse_bounce_rays(book1_tracers.ours, camera, seed);
        batches.push_back({"book1-camera", &book1_tracers, std::move(camera), {}});
        batches.push_back({"book1-bounce", &book1_tracers, std::move(bounce), {}});
        batches.push_back(
            recorded_batch("ch07-recorded", bouncing_tracers, bouncing_spheres_at_time_0(), rays));
        batches.push_back(
            recorded_batch("ch13-recorded", book2_tracers, book2_final_at_time_0(), rays));
        batches.push_back(recorded_batch("ch11-recorded", cornell_tracers,
                                         cornell_box_at_benchmark_settings(), rays));

        std::vector<result> results;
        for (const batch& b : batches) results.push_back(measure(b, repeat));
        print_table(batches, results);
        write_json(out, batches, results, repeat, note);
        // Rays per second mean nothing unless both traced the same shapes: the hit counts may
        // differ only by rays that graze, and a copy of a scene must find its surface hits.
        for (std::size_t k = 0; k < batches.size(); ++k) {
            const result& r = results[k];
            auto rays_seen  = double(batches[k].rays.size());
            if (double(r.only_ours + r.only_embree) > 1e-4 * rays_seen ||
                double(r.check_agrees) < 0.999 * double(r.checked)) {
                std::cerr << "embree_anchor: " << batches[k].name
                          << ": the two tracers do not see the same shapes (see above)\n";
                return 1;
            }
        }
    } catch (const std::exception& e) {
        std::cerr << "embree_anchor: " << e.what() << '\n';
        return 1;
    }
    return 0;
}
