// The mesh anchor: triangle meshes of 10^3 to 10^6 and more triangles (the Stanford bunny, and
// the bunny subdivided 1 to 5 times), the same rays through our BVH (chapter 18's mesh object,
// chapter 07's tree over the triangles, packed by mesh_bvh as the fast traversal packs it) and
// through Embree 3's own triangle geometry (rtcIntersect1, one ray at a time, one thread, closest
// hit). Per mesh: the build's seconds (of this thread), the bytes per triangle the built
// structure holds, and the rays per second of each; and the mesh as one light (mesh_light):
// nanoseconds per sample and per density, from the rays' origins.
//   mesh_anchor --out FILE.json [--rays N] [--repeat N] [--levels N] [--note TEXT]
// Rays: a 512 x 512 camera looking at the model from the front and above, and from each of
// their hits a cosine-weighted bounce about the geometric normal; rounded to float, so both
// tracers see the same numbers. The vertices are rounded to float too.
// Memory: ours is what the heap grew by while the mesh, its tree and the packed tree were built
// (glibc's mallinfo2, after the build's temporaries are freed); Embree's is what its memory
// monitor reports it holds once the scene is committed.
#include <embree3/rtcore.h>
#include <malloc.h>
#include <time.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "rt/accel/mesh_bvh.h"
#include "rt/core/onb.h"
#include "rt/core/rng.h"
#include "rt/geometry/triangle_mesh.h"
#include "rt/lights/mesh_light.h"
#include "rt/materials/diffuse_light.h"
#include "rt/materials/lambertian.h"
#include "rt/models/obj_model.h"
#include "rt/samplers/sampling.h"
#include "single_precision.h"

namespace {

double thread_seconds() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
}

std::size_t heap_bytes() {
    const struct mallinfo2 m = mallinfo2();
    return m.uordblks + m.hblkhd;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

// Each triangle split into four at its edges' midpoints, a midpoint shared by the two
// triangles of its edge: the same surface, four times the triangles.
rt::mesh_data subdivided(const rt::mesh_data& in) {
    rt::mesh_data out;
    out.positions = in.positions;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoint;
    auto middle = [&](std::uint32_t a, std::uint32_t b) {
        auto key         = std::minmax(a, b);
        auto [at, added] = midpoint.try_emplace(key, std::uint32_t(out.positions.size()));
        if (added) out.positions.push_back((in.positions[a] + in.positions[b]) / 2);
        return at->second;
    };
    out.triangles.reserve(4 * in.triangles.size());
    for (const auto& t : in.triangles) {
        const std::uint32_t ab = middle(t[0], t[1]), bc = middle(t[1], t[2]),
                            ca = middle(t[2], t[0]);
        out.triangles.push_back({t[0], ab, ca});
        out.triangles.push_back({ab, t[1], bc});
        out.triangles.push_back({ca, bc, t[2]});
        out.triangles.push_back({ab, bc, ca});
    }
    return out;
}

struct mesh_result {
    std::size_t triangles = 0, vertices = 0;
    double ours_build = 0, embree_build = 0;  // seconds
    double ours_bytes = 0, embree_bytes = 0;  // per triangle
    std::vector<double> ours_seconds, embree_seconds;
    std::size_t rays = 0, hits_ours = 0, hits_embree = 0, same_triangle = 0;
    // The mesh as a light (chapter 18's mesh_light): nanoseconds per sample drawn from a point,
    // per density of a direction (pdf: the directions' crossings of the mesh), and per density
    // of a hit on it (pdf_at: from the hit's triangle alone).
    double light_sample_ns = 0, light_pdf_ns = 0, light_pdf_at_ns = 0;
};

std::atomic<std::int64_t> embree_held{0};

bool monitor(void*, ssize_t bytes, bool) {
    embree_held += bytes;
    return true;
}

struct embree_mesh {
    RTCDevice device = nullptr;
    RTCScene scene   = nullptr;

    explicit embree_mesh(const rt::mesh_data& m) {
        device = rtcNewDevice("threads=1");
        rtcSetDeviceMemoryMonitorFunction(device, monitor, nullptr);
        scene = rtcNewScene(device);
        rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v       = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                                                                    RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                                    m.positions.size()));
        for (const rt::point3& p : m.positions) {
            *v++ = float(p.x());
            *v++ = float(p.y());
            *v++ = float(p.z());
        }
        auto* index = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                    3 * sizeof(unsigned), m.triangles.size()));
        for (const auto& t : m.triangles) {
            *index++ = t[0];
            *index++ = t[1];
            *index++ = t[2];
        }
        rtcCommitGeometry(g);
        rtcAttachGeometry(scene, g);
        rtcReleaseGeometry(g);
        rtcCommitScene(scene);
    }
    ~embree_mesh() {
        rtcReleaseScene(scene);
        rtcReleaseDevice(device);
    }
    embree_mesh(const embree_mesh&)            = delete;
    embree_mesh& operator=(const embree_mesh&) = delete;
};

// The camera's rays at the model's box and the bounces from their hits (found by `ours`).
std::vector<rt::ray> rays_at(const rt::hittable& ours, const rt::aabb& box, std::size_t count) {
    const rt::point3 centre = box.centroid();
    const rt::real size     = std::max({box.x.size(), box.y.size(), box.z.size()});
    const rt::point3 eye    = centre + rt::vec3(0.3, 0.5, 2.2) * size;
    const rt::vec3 forward  = rt::unit_vector(centre - eye);
    const rt::vec3 right    = rt::unit_vector(rt::cross(forward, rt::vec3(0, 1, 0)));
    const rt::vec3 up       = rt::cross(right, forward);
    const int side          = int(std::ceil(std::sqrt(double(count) / 2)));
    std::vector<rt::ray> rays;
    rt::pcg32 rng(2024, 1);
    for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i) {
            const rt::real x = (rt::real(i) + rng.uniform()) / rt::real(side) - rt::real(0.5);
            const rt::real y = (rt::real(j) + rng.uniform()) / rt::real(side) - rt::real(0.5);
            rays.push_back(
                rt_bench::to_float(rt::ray(eye, forward + rt::real(0.55) * (x * right + y * up))));
        }
    const std::size_t camera = rays.size();
    for (std::size_t k = 0; k < camera && rays.size() < count; ++k) {
        rt::hit_record rec;
        if (!ours.hit(rays[k], rt::interval(0, rt::infinity), rec)) continue;
        const rt::vec3 local  = rt::sample_cosine_hemisphere({rng.uniform(), rng.uniform()});
        const rt::point3 from = rec.p + 4 * rec.p_error * rec.normal;
        rays.push_back(rt_bench::to_float(rt::ray(from, rt::onb(rec.normal).to_world(local))));
    }
    return rays;
}

// The mesh as one light, seen from the rays' origins: what chapter 14's light set asks of it per
// sample and per density, which must not grow with the triangles (no loop over them).
void measure_light(const rt::mesh_data& data, const std::vector<rt::ray>& rays, int repeat,
                   mesh_result& out) {
    auto glow = std::make_shared<rt::diffuse_light>(rt::color(1, 1, 1));
    const rt::triangle_mesh mesh(data, glow);
    const rt::mesh_light light(mesh);
    const std::size_t n = std::min<std::size_t>(rays.size(), 100000);
    rt::pcg32 rng(2025, 7);
    std::vector<rt::light_sample> samples(n);
    std::vector<bool> drawn(n);
    std::vector<double> sample_s, pdf_s, pdf_at_s;
    double sink = 0;
    for (int k = 0; k < repeat; ++k) {
        double start = thread_seconds();
        for (std::size_t i = 0; i < n; ++i)
            drawn[i] = light.sample(rays[i].origin(), {rng.uniform(), rng.uniform()}, samples[i]);
        sample_s.push_back(thread_seconds() - start);
        start = thread_seconds();
        for (std::size_t i = 0; i < n; ++i)
            if (drawn[i]) sink += light.pdf(rays[i].origin(), samples[i].wi);
        pdf_s.push_back(thread_seconds() - start);
        start = thread_seconds();
        for (std::size_t i = 0; i < n; ++i)
            if (drawn[i])
                sink += light.pdf_at(rays[i].origin(), samples[i].wi, samples[i].on_light);
        pdf_at_s.push_back(thread_seconds() - start);
    }
    const auto drawn_count =
        double(std::max<std::ptrdiff_t>(1, std::count(drawn.begin(), drawn.end(), true)));
    out.light_sample_ns = 1e9 * median(sample_s) / double(n);
    out.light_pdf_ns    = 1e9 * median(pdf_s) / drawn_count;
    out.light_pdf_at_ns = 1e9 * median(pdf_at_s) / drawn_count;
    if (!(sink > 0)) throw std::runtime_error("the mesh light gave no density");
}

mesh_result measure(const rt::mesh_data& data, std::size_t ray_count, int repeat) {
    mesh_result out;
    out.triangles = data.triangles.size();
    out.vertices  = data.positions.size();

    const std::size_t heap_before = heap_bytes();
    double start                  = thread_seconds();
    auto material                 = std::make_shared<rt::lambertian>(rt::color(0.5, 0.5, 0.5));
    auto mesh                     = std::make_shared<rt::triangle_mesh>(data, material);
    std::shared_ptr<rt::hittable> ours;
    {
        auto tree = rt::mesh_object(mesh);
        ours      = std::make_shared<rt::mesh_bvh>(tree);
    }
    out.ours_build = thread_seconds() - start;
    out.ours_bytes = double(heap_bytes() - heap_before) / double(out.triangles);

    embree_held = 0;
    start       = thread_seconds();
    const embree_mesh theirs(data);
    out.embree_build = thread_seconds() - start;
    out.embree_bytes = double(embree_held.load()) / double(out.triangles);

    rt::aabb box;
    for (const rt::point3& p : data.positions) box = rt::aabb(box, rt::aabb(p, p));
    const std::vector<rt::ray> rays = rays_at(*ours, box, ray_count);
    out.rays                        = rays.size();
    std::vector<RTCRay> embree_rays;
    for (const rt::ray& r : rays) {
        RTCRay e{};
        e.org_x = float(r.origin().x());
        e.org_y = float(r.origin().y());
        e.org_z = float(r.origin().z());
        e.dir_x = float(r.direction().x());
        e.dir_y = float(r.direction().y());
        e.dir_z = float(r.direction().z());
        e.tnear = 0;
        e.tfar  = std::numeric_limits<float>::infinity();
        e.mask  = ~0u;
        embree_rays.push_back(e);
    }
    std::vector<std::int64_t> ours_triangle(rays.size()), embree_triangle(rays.size());
    for (int k = 0; k < repeat; ++k) {
        start = thread_seconds();
        for (std::size_t i = 0; i < rays.size(); ++i) {
            rt::hit_record rec;
            ours_triangle[i] =
                ours->hit(rays[i], rt::interval(0, rt::infinity), rec)
                    ? std::int64_t(static_cast<const rt::mesh_triangle*>(rec.object)->index())
                    : -1;
        }
        out.ours_seconds.push_back(thread_seconds() - start);
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        start = thread_seconds();
        for (std::size_t i = 0; i < rays.size(); ++i) {
            RTCRayHit query;
            query.ray           = embree_rays[i];
            query.hit.geomID    = RTC_INVALID_GEOMETRY_ID;
            query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(theirs.scene, &context, &query);
            embree_triangle[i] =
                query.hit.geomID == RTC_INVALID_GEOMETRY_ID ? -1 : std::int64_t(query.hit.primID);
        }
        out.embree_seconds.push_back(thread_seconds() - start);
    }
    for (std::size_t i = 0; i < rays.size(); ++i) {
        out.hits_ours += ours_triangle[i] >= 0;
        out.hits_embree += embree_triangle[i] >= 0;
        out.same_triangle += ours_triangle[i] >= 0 && ours_triangle[i] == embree_triangle[i];
    }
    measure_light(data, rays, repeat, out);
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Meshes of 10^3 to 10^6+ triangles through our BVH and through Embree 3"};
    std::string out, note;
    std::size_t rays = 500000;
    int repeat = 3, levels = 5;
    app.add_option("--out", out, "JSON file of the results")->required();
    app.add_option("--rays", rays, "Rays per mesh, about")
        ->check(CLI::Range(std::size_t(1000), std::size_t(1) << 24))
        ->capture_default_str();
    app.add_option("--repeat", repeat, "Timings per mesh and tracer; the median counts")
        ->check(CLI::Range(1, 99))
        ->capture_default_str();
    app.add_option("--levels", levels, "Subdivisions of the bunny beyond the model itself")
        ->check(CLI::Range(0, 6))
        ->capture_default_str();
    app.add_option("--note", note, "Free text kept in the JSON (the commit, the load)");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;
    }
    try {
        rt::mesh_data mesh = rt::read_obj(RT_ASSET_DIR "/models/bunny.obj").mesh;
        for (rt::point3& p : mesh.positions) p = rt_bench::to_float(p);
        std::vector<mesh_result> results;
        std::cout << std::setw(10) << "triangles" << std::setw(12) << "build ours" << std::setw(14)
                  << "build Embree" << std::setw(12) << "B/tri ours" << std::setw(14)
                  << "B/tri Embree" << std::setw(11) << "ours M/s" << std::setw(13) << "Embree M/s"
                  << std::setw(13) << "ours/Embree" << std::setw(14) << "same triangle"
                  << std::setw(16) << "light sample ns" << std::setw(13) << "light pdf ns"
                  << std::setw(16) << "light pdf_at ns" << '\n';
        for (int level = 0; level <= levels; ++level) {
            if (level > 0) mesh = subdivided(mesh);
            const mesh_result r = measure(mesh, rays, repeat);
            const double ours   = double(r.rays) / median(r.ours_seconds);
            const double embree = double(r.rays) / median(r.embree_seconds);
            std::cout << std::setw(10) << r.triangles << std::fixed << std::setprecision(3)
                      << std::setw(12) << r.ours_build << std::setw(14) << r.embree_build
                      << std::setprecision(0) << std::setw(12) << r.ours_bytes << std::setw(14)
                      << r.embree_bytes << std::setprecision(2) << std::setw(11) << ours / 1e6
                      << std::setw(13) << embree / 1e6 << std::setprecision(3) << std::setw(13)
                      << ours / embree << std::setw(14)
                      << double(r.same_triangle) / double(std::max<std::size_t>(1, r.hits_embree))
                      << std::setprecision(0) << std::setw(16) << r.light_sample_ns << std::setw(13)
                      << r.light_pdf_ns << std::setw(16) << r.light_pdf_at_ns << std::endl;
            results.push_back(r);
        }
        std::ofstream json(out);
        json << std::setprecision(6) << "{\n  \"program\": \"mesh_anchor\",\n  \"embree\": \""
             << RTC_VERSION_STRING << "\",\n  \"real\": \""
             << (sizeof(rt::real) == 8 ? "double" : "float") << "\",\n  \"threads\": 1,\n"
             << "  \"repeat\": " << repeat << ",\n  \"note\": \"" << note
             << "\",\n  \"meshes\": [\n";
        for (std::size_t k = 0; k < results.size(); ++k) {
            const mesh_result& r = results[k];
            json << "    {\"triangles\": " << r.triangles << ", \"vertices\": " << r.vertices
                 << ", \"rays\": " << r.rays << ", \"ours_build_seconds\": " << r.ours_build
                 << ", \"embree_build_seconds\": " << r.embree_build
                 << ", \"ours_bytes_per_triangle\": " << r.ours_bytes
                 << ", \"embree_bytes_per_triangle\": " << r.embree_bytes
                 << ", \"ours_rays_per_second\": " << double(r.rays) / median(r.ours_seconds)
                 << ", \"embree_rays_per_second\": " << double(r.rays) / median(r.embree_seconds)
                 << ", \"hits_ours\": " << r.hits_ours << ", \"hits_embree\": " << r.hits_embree
                 << ", \"same_triangle\": " << r.same_triangle
                 << ", \"light_sample_ns\": " << r.light_sample_ns
                 << ", \"light_pdf_ns\": " << r.light_pdf_ns
                 << ", \"light_pdf_at_ns\": " << r.light_pdf_at_ns << "}"
                 << (k + 1 < results.size() ? "," : "") << "\n";
        }
        json << "  ]\n}\n";
        if (!json) throw std::runtime_error("could not write " + out);
    } catch (const std::exception& e) {
        std::cerr << "mesh_anchor: " << e.what() << '\n';
        return 1;
    }
    return 0;
}
