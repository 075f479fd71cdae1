#include "rt/scene_files/scene_writer.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <typeinfo>
#include <utility>
#include <vector>

#include "rt/accel/bvh.h"
#include "rt/camera/thin_lens_camera.h"
#include "rt/core/error.h"
#include "rt/core/exercise.h"
#include "rt/files/output_set.h"
#include "rt/geometry/box.h"
#include "rt/geometry/instance.h"
#include "rt/geometry/moving_sphere.h"
#include "rt/geometry/quad.h"
#include "rt/geometry/sphere.h"
#include "rt/geometry/triangle_mesh.h"
#include "rt/materials/dielectric.h"
#include "rt/materials/diffuse_light.h"
#include "rt/materials/lambertian.h"
#include "rt/materials/metal.h"
#include "rt/materials/textured_lambertian.h"
#include "rt/media/constant_medium.h"
#include "rt/media/isotropic.h"
#include "rt/samplers/independent_sampler.h"
#include "rt/samplers/sobol_sampler.h"
#include "rt/scene/hittable_list.h"
#include "rt/scene_files/scene_reader.h"
#include "rt/scene_files/scene_words.h"
#include "rt/scene_files/toml_text.h"
#include "rt/textures/image_texture.h"
#include "rt/textures/noise_texture.h"
#include "rt/textures/texture.h"

namespace rt {

std::string number_text(double x) {
    // [exercise number_text begin]
    if (x == 0 && std::signbit(x)) return "-0.0";  // an integer -0 would read back as +0
    char buffer[64];
    auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, x);
    std::string text(buffer, end);
    // Digits alone read back as a TOML integer: exact below 2^53, beyond which a float is
    // written (an integer that large may not fit TOML's 64 bits).
    if (text.find_first_of(".e") == std::string::npos && std::fabs(x) >= 9007199254740992.0) {
        auto [end2, error2] =
            std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::scientific);
        text.assign(buffer, end2);
    }
    return text;
    // [exercise number_text end]
}

namespace {

namespace fs = std::filesystem;

std::string vector_text(const vec3& v) {
    return "[" + number_text(double(v.x())) + ", " + number_text(double(v.y())) + ", " +
           number_text(double(v.z())) + "]";
}

// The keys of one table, in the order written.
using key_values = std::vector<std::pair<std::string, std::string>>;

std::string inline_table(const key_values& keys) {
    std::string text = "{ ";
    for (std::size_t i = 0; i < keys.size(); ++i)
        text += (i ? ", " : "") + keys[i].first + " = " + keys[i].second;
    return text + " }";
}

std::string block(const std::string& header, const key_values& keys) {
    std::string text = "[" + header + "]\n";
    for (const auto& [key, value] : keys) text.append(key).append(" = ").append(value).append("\n");
    return text;
}

[[noreturn]] void cannot_write(const std::string& what) {
    throw std::logic_error("scene file writer: no form for " + what);
}

class writer {
  public:
    explicit writer(std::string file_folder) : folder(std::move(file_folder)) {}

    std::string text(const described_scene& described, const std::string& title);

  private:
    void count_uses(const std::shared_ptr<hittable>& object);
    static std::vector<std::shared_ptr<hittable>> members(const hittable& object);
    static bool is_group(const hittable& object);

    // The object as it stands in a list: its inline table, or its name when it has one.
    std::string object_value(const std::shared_ptr<hittable>& object);
    key_values object_keys(const std::shared_ptr<hittable>& object);
    key_values shape_keys(const hittable& object);
    std::string objects_array(const std::vector<std::shared_ptr<hittable>>& list,
                              const std::string& indent);

    std::string material_value(const std::shared_ptr<material>& mat);
    // A texture where a colour may stand: [r, g, b] for a solid colour, else its name.
    std::string texture_value(const std::shared_ptr<texture>& tex, bool colour_allowed);
    std::string relative_path(const std::string& path) const;
    // A checker's keys: both kinds hold a scale and two textures.
    template <typename Checker>
    key_values checker_keys(const char* type, const Checker& checker) {
        return {{"type", type},
                {"scale", number_text(double(checker.scale()))},
                {"even", texture_value(checker.even_texture(), true)},
                {"odd", texture_value(checker.odd_texture(), true)}};
    }

    std::string folder;
    std::map<const hittable*, int> uses;
    std::map<const hittable*, std::string> object_names;
    std::map<const material*, std::string> material_names;
    std::map<const texture*, std::string> texture_names;
    std::map<std::string, int> kind_counts;  // for names: lambertian1, lambertian2...
    std::string texture_lines, material_lines, object_blocks;

    std::string next_name(const std::string& kind) {
        return kind + std::to_string(++kind_counts[kind]);
    }
};

// A BVH that is chapter 11's box: its six quads, as given, are box_faces() of two corners.
struct box_corners {
    point3 lo, hi;
    std::shared_ptr<material> mat;
};

std::optional<box_corners> as_box(const bvh& tree) {
    const auto given = tree.objects_as_given();
    if (given.size() != 6) return std::nullopt;
    std::vector<const quad*> faces;
    for (const auto& object : given) {
        const auto* face = dynamic_cast<const quad*>(object.get());
        if (!face) return std::nullopt;
        faces.push_back(face);
    }
    // box_faces() lists the bottom (from the low corner) last and the right face (from x, z of
    // the high corner) second, the top (y of the high corner) fifth.
    const point3 lo = faces[5]->corner();
    const point3 hi(faces[1]->corner().x(), faces[4]->corner().y(), faces[1]->corner().z());
    const std::shared_ptr<material>& mat = faces[0]->surface();
    if (!(lo.x() < hi.x() && lo.y() < hi.y() && lo.z() < hi.z())) return std::nullopt;
    const auto same = [](const vec3& a, const vec3& b) {
        return a.x() == b.x() && a.y() == b.y() && a.z() == b.z() &&
               std::signbit(a.x()) == std::signbit(b.x()) &&
               std::signbit(a.y()) == std::signbit(b.y()) &&
               std::signbit(a.z()) == std::signbit(b.z());
    };
    const auto expected = box_faces(lo, hi, mat);
    for (std::size_t i = 0; i < 6; ++i) {
        const auto* made = static_cast<const quad*>(expected[i].object.get());
        if (faces[i]->surface() != mat || !same(faces[i]->corner(), made->corner()) ||
            !same(faces[i]->edge_u(), made->edge_u()) || !same(faces[i]->edge_v(), made->edge_v()))
            return std::nullopt;
    }
    return box_corners{lo, hi, mat};
}

bool is_mesh(const bvh& tree) {
    return !tree.objects().empty() &&
           dynamic_cast<const mesh_triangle*>(tree.objects().front().get()) != nullptr;
}

std::vector<std::shared_ptr<hittable>> writer::members(const hittable& object) {
    if (const auto* list = dynamic_cast<const hittable_list*>(&object)) return list->objects;
    if (const auto* tree = dynamic_cast<const bvh*>(&object)) {
        if (as_box(*tree) || is_mesh(*tree)) return {};
        return tree->objects_as_given();
    }
    if (const auto* moved = dynamic_cast<const translate*>(&object)) return {moved->placed()};
    if (const auto* turned = dynamic_cast<const rotate*>(&object)) return {turned->placed()};
    if (const auto* fog = dynamic_cast<const constant_medium*>(&object))
        return {fog->boundary_object()};
    return {};
}

bool writer::is_group(const hittable& object) {
    if (dynamic_cast<const hittable_list*>(&object)) return true;
    const auto* tree = dynamic_cast<const bvh*>(&object);
    return tree && !as_box(*tree) && !is_mesh(*tree);
}

void writer::count_uses(const std::shared_ptr<hittable>& object) {
    if (++uses[object.get()] > 1) return;
    for (const auto& member : members(*object)) count_uses(member);
}

std::string writer::objects_array(const std::vector<std::shared_ptr<hittable>>& list,
                                  const std::string& indent) {
    std::string text = "[\n";
    for (const auto& object : list) text += indent + "  " + object_value(object) + ",\n";
    return text + indent + "]";
}

std::string writer::object_value(const std::shared_ptr<hittable>& object) {
    const hittable* key = object.get();
    if (auto found = object_names.find(key); found != object_names.end())
        return toml_string(found->second);
    if (uses[key] <= 1 && !is_group(*object)) return inline_table(object_keys(object));
    // A group, or an object used twice: a named object, defined once.
    const std::string name = next_name(is_group(*object) ? "group" : "object");
    object_names[key]      = name;
    key_values keys        = object_keys(object);
    std::string text       = "[named_objects." + name + "]\n";
    for (const auto& [k, v] : keys) text.append(k).append(" = ").append(v).append("\n");
    object_blocks += "\n" + text;
    return toml_string(name);
}

key_values writer::object_keys(const std::shared_ptr<hittable>& object) {
    // A chain of instances is its innermost object with a list of steps, innermost first; a
    // step stays an object of its own where the scene holds it twice.
    std::vector<std::string> steps;
    std::shared_ptr<hittable> inner = object;
    for (;;) {
        if (inner != object && uses[inner.get()] > 1) break;
        if (const auto* moved = dynamic_cast<const translate*>(inner.get())) {
            steps.push_back("{ translate = " + vector_text(moved->displacement()) + " }");
            inner = moved->placed();
        } else if (const auto* turned = dynamic_cast<const rotate*>(inner.get())) {
            const char* about = turned->turned_about() == axis::x   ? "x"
                                : turned->turned_about() == axis::y ? "y"
                                                                    : "z";
            steps.push_back("{ rotate = \"" + std::string(about) +
                            "\", degrees = " + number_text(double(turned->degrees())) + " }");
            inner = turned->placed();
        } else {
            break;
        }
    }
    key_values keys;
    if (inner != object && (uses[inner.get()] > 1 || is_group(*inner)))
        keys.emplace_back("use", object_value(inner));
    else
        keys = shape_keys(*inner);
    if (!steps.empty()) {
        std::string list = "[";
        for (std::size_t i = steps.size(); i-- > 0;) list += steps[i] + (i ? ", " : "");
        keys.emplace_back("transform", list + "]");
    }
    return keys;
}

key_values writer::shape_keys(const hittable& object) {
    if (const auto* ball = dynamic_cast<const sphere*>(&object)) {
        key_values keys{{"type", "\"sphere\""},
                        {"center", vector_text(ball->center())},
                        {"radius", number_text(double(ball->radius()))}};
        if (ball->surface()) keys.emplace_back("material", material_value(ball->surface()));
        return keys;
    }
    if (const auto* ball = dynamic_cast<const moving_sphere*>(&object))
        return {{"type", "\"moving-sphere\""},
                {"centers", "[" + vector_text(ball->path().center0) + ", " +
                                vector_text(ball->path().center1) + "]"},
                {"radius", number_text(double(ball->radius()))},
                {"material", material_value(ball->surface())}};
    if (const auto* face = dynamic_cast<const quad*>(&object))
        return {{"type", "\"quad\""},
                {"corner", vector_text(face->corner())},
                {"u", vector_text(face->edge_u())},
                {"v", vector_text(face->edge_v())},
                {"material", material_value(face->surface())}};
    if (const auto* list = dynamic_cast<const hittable_list*>(&object))
        return {{"type", "\"group\""}, {"objects", objects_array(list->objects, "")}};
    if (const auto* tree = dynamic_cast<const bvh*>(&object)) {
        if (auto corners = as_box(*tree))
            return {
                {"type", "\"box\""},
                {"corners", "[" + vector_text(corners->lo) + ", " + vector_text(corners->hi) + "]"},
                {"material", material_value(corners->mat)}};
        if (is_mesh(*tree))
            throw user_error(
                "a mesh made in code cannot be written as a scene file: it names no "
                "model file");
        return {{"type", "\"group\""},
                {"bvh", "true"},
                {"objects", objects_array(tree->objects_as_given(), "")}};
    }
    if (const auto* fog = dynamic_cast<const constant_medium*>(&object)) {
        const auto* phase = dynamic_cast<const isotropic*>(&fog->phase());
        if (!phase) cannot_write("a medium whose phase function is not isotropic");
        return {{"type", "\"medium\""},
                {"boundary", object_value(fog->boundary_object())},
                {"density", number_text(double(fog->density()))},
                {"albedo", texture_value(phase->albedo_texture(), true)}};
    }
    cannot_write(std::string("an object of type ") + typeid(object).name());
}

std::string writer::material_value(const std::shared_ptr<material>& mat) {
    const material* key = mat.get();
    if (auto found = material_names.find(key); found != material_names.end())
        return toml_string(found->second);
    std::string kind;
    key_values keys;
    if (const auto* plain = dynamic_cast<const lambertian*>(key)) {
        kind = "lambertian";
        keys = {{"type", "\"lambertian\""}, {"albedo", vector_text(plain->albedo())}};
    } else if (const auto* textured = dynamic_cast<const textured_lambertian*>(key)) {
        kind = "lambertian";
        keys = {{"type", "\"lambertian\""},
                {"albedo", texture_value(textured->albedo_texture(), false)}};
    } else if (const auto* shiny = dynamic_cast<const metal*>(key)) {
        kind = "metal";
        keys = {{"type", "\"metal\""},
                {"albedo", vector_text(shiny->albedo_color())},
                {"fuzz", number_text(double(shiny->fuzziness()))}};
    } else if (const auto* glass = dynamic_cast<const dielectric*>(key)) {
        kind = "dielectric";
        keys = {{"type", "\"dielectric\""},
                {"index", number_text(double(glass->refraction_index()))},
                {"fresnel", toml_string(std::string(fresnel_name(glass->fresnel())))}};
    } else if (const auto* lamp = dynamic_cast<const diffuse_light*>(key)) {
        kind = "light";
        keys = {{"type", "\"light\""}, {"emit", texture_value(lamp->emission(), true)}};
    } else if (const auto* fog = dynamic_cast<const isotropic*>(key)) {
        kind = "isotropic";
        keys = {{"type", "\"isotropic\""}, {"albedo", texture_value(fog->albedo_texture(), false)}};
    } else {
        const material& kind_of = *mat;
        cannot_write(std::string("a material of type ") + typeid(kind_of).name());
    }
    const std::string name = next_name(kind);
    material_names[key]    = name;
    material_lines += name + " = " + inline_table(keys) + "\n";
    return toml_string(name);
}

std::string writer::texture_value(const std::shared_ptr<texture>& tex, bool colour_allowed) {
    const texture* key = tex.get();
    const auto* solid  = dynamic_cast<const solid_color*>(key);
    if (solid && colour_allowed) return vector_text(solid->color_value());
    if (auto found = texture_names.find(key); found != texture_names.end())
        return toml_string(found->second);
    std::string kind;
    key_values keys;
    if (solid) {
        kind = "color";
        keys = {{"type", "\"color\""}, {"color", vector_text(solid->color_value())}};
    } else if (const auto* checker = dynamic_cast<const checker_texture*>(key)) {
        kind = "checker";
        keys = checker_keys("\"checker\"", *checker);
    } else if (const auto* sines = dynamic_cast<const sine_checker_texture*>(key)) {
        kind = "checker";
        keys = checker_keys("\"sine-checker\"", *sines);
    } else if (const auto* image = dynamic_cast<const image_texture*>(key)) {
        kind = "image";
        keys = {{"type", "\"image\""},
                {"file", toml_string(relative_path(image->path()))},
                {"decoding",
                 image->decoding_used() == texel_decoding::srgb ? "\"srgb\"" : "\"bytes\""}};
    } else if (const auto* marble = dynamic_cast<const noise_texture*>(key)) {
        kind = "marble";
        keys = {{"type", "\"marble\""},
                {"scale", number_text(double(marble->stripe_scale()))},
                {"perlin_seed", std::to_string(marble->tables().table_seed())},
                {"perlin_skip", std::to_string(marble->tables().table_skip())}};
    } else {
        const texture& kind_of = *tex;
        cannot_write(std::string("a texture of type ") + typeid(kind_of).name());
    }
    const std::string name = next_name(kind);
    texture_names[key]     = name;
    texture_lines += name + " = " + inline_table(keys) + "\n";
    return toml_string(name);
}

std::string writer::relative_path(const std::string& path) const {
    std::error_code error;
    const fs::path from = fs::absolute(folder.empty() ? fs::path(".") : fs::path(folder), error);
    const fs::path file = fs::absolute(path, error);
    const fs::path relative = fs::relative(file, from, error);
    return error || relative.empty() ? file.string() : relative.string();
}

std::string writer::text(const described_scene& described, const std::string& title) {
    const scene& s = described.scene;
    std::vector<std::shared_ptr<hittable>> top;
    bool top_bvh = false;
    if (s.world) {
        if (const auto* list = dynamic_cast<const hittable_list*>(s.world.get())) {
            top = list->objects;
        } else if (const auto* tree = dynamic_cast<const bvh*>(s.world.get());
                   tree && !as_box(*tree) && !is_mesh(*tree)) {
            top     = tree->objects_as_given();
            top_bvh = true;
        } else {
            top = {s.world};
        }
    }
    for (const auto& object : top) count_uses(object);
    const std::string objects = objects_array(top, "");

    std::ostringstream out;
    out << "# " << title << "\n"
        << "# A scene file (chapters/ch19_scene_files/README.md says what each key means).\n"
        << "format = " << scene_file_format << "\n";

    const render_settings& r = s.settings;
    std::string sampler;
    if (r.make_sampler == independent_sampler::make)
        sampler = "independent";
    else if (r.make_sampler == sobol_sampler::make)
        sampler = "sobol";
    else
        cannot_write("a sampler other than the independent and the Sobol' one");
    out << "\n"
        << block("render",
                 {{"width", std::to_string(r.width)},
                  {"samples_per_pixel", std::to_string(r.samples_per_pixel)},
                  {"max_depth", std::to_string(r.max_depth)},
                  {"seed", std::to_string(r.seed)},
                  {"integrator", toml_string(std::string(integrator_name(described.integrator)))},
                  {"sampler", toml_string(sampler)}});

    key_values cam;
    const auto* lens = dynamic_cast<const thin_lens_camera*>(s.cam.get());
    cam.emplace_back("type", lens ? "\"look-at\"" : "\"origin\"");
    const auto ratio = aspect_ratio_name(s.cam->aspect_ratio);
    cam.emplace_back("aspect_ratio",
                     ratio ? toml_string(*ratio) : number_text(s.cam->aspect_ratio));
    cam.emplace_back("vfov", number_text(double(s.cam->vfov)));
    if (lens) {
        cam.emplace_back("lookfrom", vector_text(lens->lookfrom));
        cam.emplace_back("lookat", vector_text(lens->lookat));
        cam.emplace_back("vup", vector_text(lens->vup));
        cam.emplace_back("aperture", number_text(double(lens->aperture)));
        cam.emplace_back("focus_distance", number_text(double(lens->focus_dist)));
        cam.emplace_back("shutter", "[" + number_text(double(lens->shutter_open)) + ", " +
                                        number_text(double(lens->shutter_close)) + "]");
    }
    out << "\n" << block("camera", cam);

    const background& sky = s.sky;
    const bool uniform    = sky.top.x() == sky.bottom.x() && sky.top.y() == sky.bottom.y() &&
                         sky.top.z() == sky.bottom.z();
    if (uniform)
        out << "\n" << block("sky", {{"color", vector_text(sky.top)}});
    else
        out << "\n"
            << block("sky", {{"top", vector_text(sky.top)}, {"bottom", vector_text(sky.bottom)}});

    if (!texture_lines.empty()) out << "\n[textures]\n" << texture_lines;
    if (!material_lines.empty()) out << "\n[materials]\n" << material_lines;
    if (!object_blocks.empty()) out << object_blocks;
    out << "\n# What the scene holds.\n[world]\n";
    if (top_bvh) out << "bvh = true  # its objects in one BVH (chapter 07)\n";
    if (!top.empty()) out << "objects = " << objects << "\n";
    return out.str();
}

}  // namespace

std::string scene_file_text(const described_scene& scene, const std::string& folder,
                            const std::string& title) {
    return writer(folder).text(scene, title);
}

void write_scene_file(const described_scene& scene, const std::string& path,
                      const std::string& title) {
    const std::string folder = fs::path(path).parent_path().string();
    const std::string text   = scene_file_text(scene, folder, title);
    output_set outputs;
    outputs.add(path, [&](temporary_file& file) { file.append(text.data(), text.size()); });
    outputs.commit();
}

}  // namespace rt
