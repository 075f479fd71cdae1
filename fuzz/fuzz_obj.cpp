// Fuzz target: OBJ model files. Each input is read by rt::parse_obj (our counts and index
// checks, then tinyobjloader, compiled into this target: tiny_obj_loader.cpp), made a mesh and
// a BVH, and hit by a few rays. The contract checked:
//   - a model either loads, as a mesh whose every triangle indexes its vertices, whose hits are
//     finite with a unit normal, or
//   - is refused with a user_error of one line that names the model;
//   - nothing else: no crash, no sanitizer finding, no other exception, no leak, and no hang
//     or runaway memory (tools/fuzz sets libFuzzer's -timeout and -rss_limit_mb).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "rt/core/error.h"
#include "rt/geometry/triangle_mesh.h"
#include "rt/materials/lambertian.h"
#include "rt/models/obj_model.h"

namespace {

const std::string name = "fuzz.obj";

[[noreturn]] void broken(const char* what, const std::string& detail) {
    std::fprintf(stderr, "fuzz_obj: %s: %s\n", what, detail.c_str());
    std::abort();
}

bool finite(const rt::vec3& v) {
    return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        rt::obj_model model        = rt::parse_obj(text, name);
        const std::size_t vertices = model.mesh.positions.size();
        for (const auto& t : model.mesh.triangles)
            for (std::uint32_t v : t)
                if (v >= vertices) broken("a triangle indexes no vertex", std::to_string(v));
        auto mesh = std::make_shared<rt::triangle_mesh>(
            std::move(model.mesh), std::make_shared<rt::lambertian>(rt::color(0.5, 0.5, 0.5)));
        auto object        = rt::mesh_object(mesh);
        const rt::aabb box = object->bounding_box();
        if (box.empty()) return 0;  // every triangle was degenerate
        // Rays from outside the box at its centre, along each axis and a diagonal.
        const rt::point3 centre = box.centroid();
        for (const rt::vec3& d : {rt::vec3(1, 0, 0), rt::vec3(0, 1, 0), rt::vec3(0, 0, 1),
                                  rt::vec3(-1, -1, -1), rt::vec3(0.3, -0.7, 0.2)}) {
            const rt::ray r(centre - 2 * (box.magnitude() + 1) * d, d);
            rt::hit_record rec;
            if (!object->hit(r, rt::interval(0, rt::infinity), rec)) continue;
            if (!finite(rec.p) || !std::isfinite(rec.t) || !std::isfinite(rec.p_error))
                broken("a hit that is not finite", std::to_string(rec.t));
            if (!(std::fabs(rec.normal.length() - 1) < 1e-6))
                broken("a normal that is not unit", std::to_string(rec.normal.length()));
        }
    } catch (const rt::user_error& e) {
        const std::string message = e.what();
        if (message.rfind(name, 0) != 0) broken("the refusal does not name the model", message);
        if (message.find('\n') != std::string::npos) broken("the refusal is not one line", message);
    }
    return 0;
}
