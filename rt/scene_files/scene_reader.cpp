#include "rt/scene_files/scene_reader.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <system_error>
#include <utility>
#include <vector>

#include "rt/accel/bvh.h"
#include "rt/camera/thin_lens_camera.h"
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
#include "rt/models/model_fit.h"
#include "rt/models/obj_model.h"
#include "rt/models/vertex_normals.h"
#include "rt/samplers/independent_sampler.h"
#include "rt/samplers/sobol_sampler.h"
#include "rt/scene/hittable_list.h"
#include "rt/scene_files/scene_limits.h"
#include "rt/scene_files/scene_words.h"
#include "rt/scene_files/toml_fields.h"
#include "rt/scene_files/toml_guard.h"
#include "rt/textures/image_texture.h"
#include "rt/textures/noise_texture.h"
#include "rt/textures/texture.h"

namespace rt {

namespace {

namespace fs         = std::filesystem;
constexpr double big = scene_limits::max_magnitude;

// An object as built: what it is, and its box where it has one (a group with bvh = false has
// none: it cannot go into a BVH, an instance or a medium).
struct built_object {
    std::shared_ptr<hittable> object;
    std::optional<bounded_object> bounded;
};

template <typename Shape>
built_object with_box(std::shared_ptr<Shape> shape) {
    bounded_object b(shape);
    return {b.object, b};
}

// A colour: three finite numbers in [0, limit].
color color_value(const toml::node& value, const std::string& what) {
    const color c = vector_value(value, what, big);
    for (int i = 0; i < 3; ++i)
        if (c[i] < 0)
            refuse_at(value.source(), what + " must be three numbers >= 0, got " + shown(value));
    return c;
}

// The keys each kind of table may have.
std::vector<std::string_view> object_keys(const std::string& type) {
    if (type == "sphere") return {"type", "center", "radius", "material", "transform"};
    if (type == "moving-sphere") return {"type", "centers", "radius", "material", "transform"};
    if (type == "quad") return {"type", "corner", "u", "v", "material", "transform"};
    if (type == "box") return {"type", "corners", "material", "transform"};
    if (type == "group") return {"type", "objects", "bvh", "transform"};
    if (type == "medium") return {"type", "boundary", "density", "albedo", "transform"};
    return {"type", "file", "material", "shading", "fit", "transform"};  // a mesh
}

std::vector<std::string_view> texture_keys(const std::string& type) {
    if (type == "color") return {"type", "color"};
    if (type == "checker" || type == "sine-checker") return {"type", "scale", "even", "odd"};
    if (type == "image") return {"type", "file", "decoding"};
    return {"type", "scale", "perlin_seed", "perlin_skip"};  // marble
}

std::vector<std::string_view> material_keys(const std::string& type) {
    if (type == "metal") return {"type", "albedo", "fuzz"};
    if (type == "dielectric") return {"type", "index", "fresnel"};
    if (type == "light") return {"type", "emit"};
    return {"type", "albedo"};  // lambertian, isotropic
}

class reader {
  public:
    reader(const toml::table& file_root, fs::path file_folder, std::size_t triangle_limit)
        : root(file_root), folder(std::move(file_folder)), triangles_left(triangle_limit) {}

    described_scene read();

  private:
    void read_format(fields& top);
    void read_render(const toml::node& node, described_scene& out);
    std::shared_ptr<camera> read_camera(const toml::node& node);
    background read_sky(const toml::node& node);
    std::shared_ptr<hittable> read_world(const toml::node& node);

    // A texture: a colour [r, g, b], a named texture's name, or a texture's table.
    std::shared_ptr<texture> texture_from(const toml::node& value, const std::string& what);
    std::shared_ptr<texture> texture_table(const toml::table& table);
    std::shared_ptr<texture> named_texture(const std::string& name,
                                           const toml::source_region& where);
    std::shared_ptr<material> named_material(const std::string& name,
                                             const toml::source_region& where);
    // A material: a named material's name, or a material's table.
    std::shared_ptr<material> material_from(const toml::node& value, const std::string& what);
    std::shared_ptr<material> material_table(const toml::table& table);
    // An object: a named object's name, or an object's table.
    built_object object_from(const toml::node& value, const std::string& what);
    built_object object_table(const toml::table& table);
    built_object shape(fields& f, const std::string& type);
    built_object group(fields& f);
    built_object mesh(fields& f);
    built_object named_object(const std::string& name, const toml::source_region& where);
    built_object transformed(built_object object, const toml::node& steps);
    // The object's box, or a refusal at `where` saying why it needs one.
    static bounded_object boxed(const built_object& object, const toml::source_region& where,
                                const std::string& use);
    // A file named in the scene: relative to the scene file's folder.
    std::string resolved(const std::string& path) const;

    // The table of definitions under `key` ("materials"), or null.
    const toml::table* definitions(fields& top, std::string_view key);
    // The definition `name` of a kind, or a refusal naming what is defined.
    static const toml::table& definition(const toml::table* defs, const std::string& name,
                                         const toml::source_region& where, const std::string& kind);

    const toml::table& root;
    fs::path folder;
    const toml::table *texture_defs = nullptr, *material_defs = nullptr, *object_defs = nullptr;
    std::map<std::string, std::shared_ptr<texture>, std::less<>> textures;
    std::map<std::string, std::shared_ptr<material>, std::less<>> materials;
    std::map<std::string, built_object, std::less<>> objects;
    std::vector<std::string> being_built;  // names whose definitions are being read
    int depth = 0;                         // tables inside tables being read
    std::size_t triangles_left;            // of the scene's budget, for the meshes still to read
};

// Counts one level of nesting while it lives; refuses beyond the limit.
class nesting {
  public:
    nesting(int& depth, const toml::source_region& where) : level(depth) {
        if (++level > scene_limits::max_nesting)
            refuse_at(where, "objects, textures or names nested more than " +
                                 std::to_string(scene_limits::max_nesting) + " deep");
    }
    ~nesting() { --level; }
    nesting(const nesting&)            = delete;
    nesting& operator=(const nesting&) = delete;

  private:
    int& level;
};

described_scene reader::read() {
    fields top(root, "scene file");
    top.allow("scene file", {"format", "render", "camera", "sky", "textures", "materials",
                             "named_objects", "world"});
    read_format(top);
    texture_defs  = definitions(top, "textures");
    material_defs = definitions(top, "materials");
    object_defs   = definitions(top, "named_objects");

    described_scene out;
    if (const toml::node* render = top.find("render")) read_render(*render, out);
    if (const toml::node* cam = top.find("camera")) out.scene.cam = read_camera(*cam);
    if (const toml::node* sky = top.find("sky")) out.scene.sky = read_sky(*sky);

    out.scene.world = std::make_shared<hittable_list>();
    if (const toml::node* world = top.find("world")) out.scene.world = read_world(*world);

    // Definitions nobody used are read too: a mistake in one is found before the teacher uses it.
    for (const toml::table* defs : {texture_defs, material_defs, object_defs}) {
        if (!defs) continue;
        for (const auto& [key, value] : *defs) {
            const std::string name(key.str());
            if (defs == texture_defs) named_texture(name, key.source());
            if (defs == material_defs) named_material(name, key.source());
            if (defs == object_defs) named_object(name, key.source());
        }
    }
    return out;
}

void reader::read_format(fields& top) {
    const toml::node& format            = top.need("format", "this format's number: format = 1");
    const std::optional<std::int64_t> n = format.value<std::int64_t>();
    if (!format.is_integer() || *n < 1)
        refuse_at(format.source(), "format must be 1, got " + shown(format));
    if (*n > scene_file_format)
        refuse_at(format.source(), "format " + std::to_string(*n) +
                                       " is newer than this program reads (format " +
                                       std::to_string(scene_file_format) + ")");
}

const toml::table* reader::definitions(fields& top, std::string_view key) {
    const toml::node* node = top.find(key);
    if (!node) return nullptr;
    if (!node->is_table())
        refuse_at(node->source(),
                  std::string(key) + " must be a table of names, got " + shown(*node));
    return node->as_table();
}

const toml::table& reader::definition(const toml::table* defs, const std::string& name,
                                      const toml::source_region& where, const std::string& kind) {
    const toml::node* def = defs ? defs->get(name) : nullptr;
    if (!def) {
        std::string known;
        if (defs)
            for (const auto& [key, value] : *defs)
                known += (known.empty() ? "" : ", ") + std::string(key.str());
        refuse_at(where, "no " + kind + " named '" + name + "' (" +
                             (known.empty() ? "none is defined" : "defined: " + known) + ")");
    }
    if (!def->is_table())
        refuse_at(def->source(), kind + " '" + name + "' must be a table, got " + shown(*def));
    return *def->as_table();
}

void reader::read_render(const toml::node& node, described_scene& out) {
    if (!node.is_table()) refuse_at(node.source(), "render must be a table, got " + shown(node));
    fields f(*node.as_table(), "render");
    f.allow("render", {"width", "samples_per_pixel", "max_depth", "seed", "integrator", "sampler"});
    render_settings& s = out.scene.settings;
    if (auto n = f.integer_if("width", 1, 16384)) s.width = int(*n);
    if (auto n = f.integer_if("samples_per_pixel", 1, 1 << 20)) s.samples_per_pixel = int(*n);
    if (auto n = f.integer_if("max_depth", 1, 10000)) s.max_depth = int(*n);
    if (auto n = f.integer_if("seed", 0, std::numeric_limits<std::int64_t>::max()))
        s.seed = std::uint64_t(*n);
    if (const toml::node* name = f.find("integrator")) {
        const auto kind =
            name->is_string() ? integrator_named(*name->value<std::string>()) : std::nullopt;
        if (!kind)
            refuse_at(name->source(),
                      "integrator must be " + integrator_names() + ", got " + shown(*name));
        out.integrator = *kind;
    }
    if (auto sampler = f.word_if("sampler", {"independent", "sobol"}))
        s.make_sampler = *sampler == "sobol" ? sobol_sampler::make : independent_sampler::make;
}

std::shared_ptr<camera> reader::read_camera(const toml::node& node) {
    if (!node.is_table()) refuse_at(node.source(), "camera must be a table, got " + shown(node));
    fields f(*node.as_table(), "camera");
    f.allow("camera", {"type", "aspect_ratio", "vfov", "lookfrom", "lookat", "vup", "aperture",
                       "focus_distance", "shutter"});
    const std::string type = f.word_if("type", {"look-at", "origin"}).value_or("look-at");
    std::shared_ptr<camera> cam;
    if (type == "origin") {
        cam = std::make_shared<camera>();
    } else {
        auto lens = std::make_shared<thin_lens_camera>();
        if (auto v = f.vector_if("lookfrom", big)) lens->lookfrom = *v;
        if (auto v = f.vector_if("lookat", big)) lens->lookat = *v;
        if (auto v = f.vector_if("vup", big)) lens->vup = *v;
        if (auto x = f.number_if("aperture", 0, big)) lens->aperture = *x;
        if (auto x = f.number_if("focus_distance", 0, big)) lens->focus_dist = *x;
        if (const toml::node* shutter = f.find("shutter")) {
            const toml::array* times = shutter->as_array();
            if (!times || times->size() != 2)
                refuse_at(shutter->source(),
                          "shutter must be two numbers [open, close] in [0, 1], "
                          "got " +
                              shown(*shutter));
            lens->shutter_open  = number_value(*times->get(0), "shutter open", 0, 1);
            lens->shutter_close = number_value(*times->get(1), "shutter close", 0, 1);
            if (lens->shutter_open > lens->shutter_close)
                refuse_at(shutter->source(),
                          "shutter must open before it closes, got " + shown(*shutter));
        }
        cam = lens;
    }
    if (const toml::node* aspect = f.find("aspect_ratio")) {
        if (auto ratio = aspect_ratio_named(aspect->value_or(std::string())))
            cam->aspect_ratio = *ratio;
        else if (aspect->is_string())
            refuse_at(aspect->source(),
                      "aspect_ratio must be a number > 0 or \"W:H\" with whole "
                      "numbers from 1 to 100000, got " +
                          shown(*aspect));
        else
            cam->aspect_ratio = double(number_value(*aspect, "aspect_ratio", 0, big, true));
    }
    if (auto x = f.number_if("vfov", 0, 180, true, true)) cam->vfov = *x;
    return cam;
}

background reader::read_sky(const toml::node& node) {
    if (!node.is_table()) refuse_at(node.source(), "sky must be a table, got " + shown(node));
    fields f(*node.as_table(), "sky");
    f.allow("sky", {"color", "top", "bottom"});
    background sky;
    if (const toml::node* c = f.find("color")) {
        sky = background::uniform(color_value(*c, "color"));
        if (f.find("top") || f.find("bottom"))
            f.refuse("has either 'color' (one colour everywhere) or 'top' and 'bottom', not both");
    } else {
        if (const toml::node* top = f.find("top")) sky.top = color_value(*top, "top");
        if (const toml::node* bottom = f.find("bottom"))
            sky.bottom = color_value(*bottom, "bottom");
    }
    return sky;
}

std::shared_ptr<hittable> reader::read_world(const toml::node& node) {
    if (!node.is_table()) refuse_at(node.source(), "world must be a table, got " + shown(node));
    fields f(*node.as_table(), "world");
    f.allow("world", {"bvh", "objects"});
    const bool use_bvh = f.flag_if("bvh").value_or(false);
    std::vector<std::pair<built_object, toml::source_region>> placed;
    if (const toml::node* list = f.find("objects")) {
        const toml::array* array = list->as_array();
        if (!array)
            refuse_at(list->source(), "objects must be an array of objects, got " + shown(*list));
        for (const toml::node& element : *array)
            placed.emplace_back(object_from(element, "object"), element.source());
    }
    if (use_bvh) {
        std::vector<bounded_object> boxed_objects;
        boxed_objects.reserve(placed.size());
        for (const auto& [object, where] : placed)
            boxed_objects.push_back(boxed(object, where, "bvh = true puts every object in a BVH"));
        return std::make_shared<bvh>(boxed_objects);
    }
    auto list = std::make_shared<hittable_list>();
    for (auto& [object, where] : placed) list->add(object.object);
    return list;
}

std::shared_ptr<texture> reader::texture_from(const toml::node& value, const std::string& what) {
    if (value.is_array()) return std::make_shared<solid_color>(color_value(value, what));
    if (value.is_string()) return named_texture(*value.value<std::string>(), value.source());
    if (value.is_table()) return texture_table(*value.as_table());
    refuse_at(value.source(), what +
                                  " must be a colour [r, g, b], a texture's name or a texture "
                                  "table, got " +
                                  shown(value));
}

std::shared_ptr<texture> reader::named_texture(const std::string& name,
                                               const toml::source_region& where) {
    if (auto found = textures.find(name); found != textures.end()) return found->second;
    const toml::table& def = definition(texture_defs, name, where, "texture");
    for (const std::string& open : being_built)
        if (open == "texture " + name) refuse_at(where, "texture '" + name + "' is made of itself");
    being_built.push_back("texture " + name);
    std::shared_ptr<texture> made = texture_table(def);
    being_built.pop_back();
    return textures[name] = made;
}

std::shared_ptr<texture> reader::texture_table(const toml::table& table) {
    nesting guard(depth, table.source());
    fields t(table, "texture");
    const std::string type =
        t.word("type", {"color", "checker", "sine-checker", "image", "marble"});
    t.allow(type + " texture", texture_keys(type));
    std::shared_ptr<texture> made;
    if (type == "color") {
        made = std::make_shared<solid_color>(
            color_value(t.need("color", "a colour [r, g, b]"), "color"));
    } else if (type == "checker" || type == "sine-checker") {
        const real scale = t.number("scale", 0, big, true);
        auto even        = texture_from(t.need("even", "a colour or a texture"), "even");
        auto odd         = texture_from(t.need("odd", "a colour or a texture"), "odd");
        made             = located(table.source(), [&]() -> std::shared_ptr<texture> {
            if (type == "checker") return std::make_shared<checker_texture>(scale, even, odd);
            return std::make_shared<sine_checker_texture>(scale, even, odd);
        });
    } else if (type == "image") {
        const toml::node& file = t.need("file", "the image's path, relative to the scene file");
        if (!file.is_string()) refuse_at(file.source(), "file must be a path, got " + shown(file));
        const std::string written = *file.value<std::string>();
        texel_decoding decoding   = default_texel_decoding();
        if (auto d = t.word_if("decoding", {"srgb", "bytes"}))
            decoding = *d == "srgb" ? texel_decoding::srgb : texel_decoding::bytes_over_255;
        const std::string path = resolved(written);
        try {
            made = std::make_shared<image_texture>(path, image_texture::max_texels, decoding);
        } catch (const user_error& e) {
            refuse_at(file.source(),
                      "texture file '" + written + "' (resolved: " + path + "): " + e.what());
        }
    } else {
        const real scale = t.number("scale", 0, big, true);
        const auto seed =
            std::uint32_t(t.integer_if("perlin_seed", 0, std::numeric_limits<std::uint32_t>::max())
                              .value_or(book_layout_seed()));
        // At most 2^20 draws (a few milliseconds): the book's scenes skip hundreds, and a file
        // cannot make the reader spin through billions.
        const auto skip = t.integer_if("perlin_skip", 0, std::int64_t(1) << 20).value_or(0);
        book_random draws(seed);
        draws.skip(std::size_t(skip));
        made = std::make_shared<noise_texture>(scale, draws);
    }
    return made;
}

std::shared_ptr<material> reader::material_from(const toml::node& value, const std::string& what) {
    if (value.is_table()) return material_table(*value.as_table());
    if (!value.is_string())
        refuse_at(value.source(),
                  what + " must be a material's name or a material table, got " + shown(value));
    return named_material(*value.value<std::string>(), value.source());
}

std::shared_ptr<material> reader::named_material(const std::string& name,
                                                 const toml::source_region& where) {
    if (auto found = materials.find(name); found != materials.end()) return found->second;
    const toml::table& def = definition(material_defs, name, where, "material");
    return materials[name] = material_table(def);
}

std::shared_ptr<material> reader::material_table(const toml::table& table) {
    nesting guard(depth, table.source());
    fields m(table, "material");
    const std::string type =
        m.word("type", {"lambertian", "metal", "dielectric", "light", "isotropic"});
    m.allow(type + " material", material_keys(type));
    std::shared_ptr<material> made;
    if (type == "lambertian" || type == "isotropic") {
        const toml::node& albedo = m.need("albedo", "a colour [r, g, b] or a texture");
        if (albedo.is_array()) {
            const color c = color_value(albedo, "albedo");
            made          = located(albedo.source(), [&]() -> std::shared_ptr<material> {
                if (type == "lambertian") return std::make_shared<lambertian>(c);
                return std::make_shared<isotropic>(c);
            });
        } else {
            auto tex = texture_from(albedo, "albedo");
            if (type == "lambertian")
                made = std::make_shared<textured_lambertian>(tex);
            else
                made = std::make_shared<isotropic>(tex);
        }
    } else if (type == "metal") {
        const toml::node& albedo = m.need("albedo", "a colour [r, g, b]");
        const color c            = color_value(albedo, "albedo");
        const real fuzz          = m.number_if("fuzz", 0, 1).value_or(0);
        made = located(albedo.source(), [&] { return std::make_shared<metal>(c, fuzz); });
    } else if (type == "dielectric") {
        const real index    = m.number("index", 0, big, true);
        fresnel_model model = default_fresnel_model();
        if (auto name = m.word_if("fresnel", fresnel_names())) model = *fresnel_named(*name);
        made = std::make_shared<dielectric>(index, model);
    } else {
        const toml::node& emit = m.need("emit", "a radiance [r, g, b] or a texture");
        if (emit.is_array())
            made = std::make_shared<diffuse_light>(color_value(emit, "emit"));
        else
            made = std::make_shared<diffuse_light>(texture_from(emit, "emit"));
    }
    return made;
}

built_object reader::object_from(const toml::node& value, const std::string& what) {
    if (value.is_table()) return object_table(*value.as_table());
    if (value.is_string()) return named_object(*value.value<std::string>(), value.source());
    refuse_at(value.source(),
              what + " must be an object table or a named object's name, got " + shown(value));
}

built_object reader::named_object(const std::string& name, const toml::source_region& where) {
    if (auto found = objects.find(name); found != objects.end()) return found->second;
    const toml::table& def = definition(object_defs, name, where, "named object");
    std::string cycle;
    for (const std::string& open : being_built) cycle += open + " -> ";
    for (const std::string& open : being_built)
        if (open == name)
            refuse_at(where, "named objects use each other in a cycle: " + cycle.append(name));
    being_built.push_back(name);
    built_object made = object_table(def);
    being_built.pop_back();
    return objects[name] = made;
}

built_object reader::object_table(const toml::table& table) {
    nesting guard(depth, table.source());
    fields f(table, "object");
    built_object made;
    if (const toml::node* use = f.find("use")) {
        if (!use->is_string())
            refuse_at(use->source(), "use must be a named object's name, got " + shown(*use));
        if (f.find("type")) f.refuse("has either 'type' (a new object) or 'use' (a named one)");
        f.allow("object", {"use", "transform"});
        made = named_object(*use->value<std::string>(), use->source());
    } else {
        const std::string type =
            f.word("type", {"sphere", "moving-sphere", "quad", "box", "group", "medium", "mesh"});
        f.allow(type, object_keys(type));
        if (type == "group")
            made = group(f);
        else if (type == "mesh")
            made = mesh(f);
        else
            made = shape(f, type);
    }
    if (const toml::node* steps = f.find("transform")) made = transformed(made, *steps);
    return made;
}

built_object reader::shape(fields& f, const std::string& type) {
    const toml::source_region& where = f.table().source();
    auto surface                     = [&] {
        return material_from(f.need("material", "a material's name or table"), "material");
    };
    if (type == "sphere") {
        const vec3 center = f.vector("center", big);
        const real radius = f.number("radius", 0, big, true);
        // Chapter 02's spheres have no material: they show their normals.
        const toml::node* mat = f.find("material");
        if (!mat) return with_box(std::make_shared<sphere>(center, radius));
        auto m = material_from(*mat, "material");
        return with_box(std::make_shared<sphere>(center, radius, m));
    }
    if (type == "moving-sphere") {
        const toml::node& centers = f.need("centers", "the centre at time 0 and at time 1");
        const toml::array* ends   = centers.as_array();
        if (!ends || ends->size() != 2)
            refuse_at(centers.source(),
                      "centers must be two points [[x, y, z], [x, y, z]], got " + shown(centers));
        const vec3 c0     = vector_value(*ends->get(0), "centers[0]", big);
        const vec3 c1     = vector_value(*ends->get(1), "centers[1]", big);
        const real radius = f.number("radius", 0, big, true);
        return with_box(std::make_shared<moving_sphere>(c0, c1, radius, surface()));
    }
    if (type == "quad") {
        const vec3 corner = f.vector("corner", big), u = f.vector("u", big), v = f.vector("v", big);
        auto m = surface();
        return located(where, [&] { return with_box(std::make_shared<quad>(corner, u, v, m)); });
    }
    if (type == "box") {
        const toml::node& corners =
            f.need("corners", "two opposite corners [[x, y, z], [x, y, z]]");
        const toml::array* pair = corners.as_array();
        if (!pair || pair->size() != 2)
            refuse_at(corners.source(),
                      "corners must be two points [[x, y, z], [x, y, z]], got " + shown(corners));
        const vec3 a = vector_value(*pair->get(0), "corners[0]", big);
        const vec3 b = vector_value(*pair->get(1), "corners[1]", big);
        auto m       = surface();
        return located(corners.source(), [&] { return with_box(box(a, b, m)); });
    }
    // A medium: a boundary filled with fog of a density, scattering isotropically.
    const built_object boundary =
        object_from(f.need("boundary", "the object the medium fills"), "boundary");
    const bounded_object inside =
        boxed(boundary, f.find("boundary")->source(), "a medium needs its boundary's box");
    const real density       = f.number("density", 0, big, true);
    const toml::node& albedo = f.need("albedo", "a colour [r, g, b] or a texture");
    if (albedo.is_array()) {
        const color c = color_value(albedo, "albedo");
        return located(albedo.source(), [&] {
            return with_box(std::make_shared<constant_medium>(inside, density, c));
        });
    }
    auto tex = texture_from(albedo, "albedo");
    return with_box(std::make_shared<constant_medium>(inside, density, tex));
}

built_object reader::group(fields& f) {
    const toml::node& list     = f.need("objects", "an array of objects");
    const toml::array* members = list.as_array();
    if (!members)
        refuse_at(list.source(), "objects must be an array of objects, got " + shown(list));
    const bool use_bvh = f.flag_if("bvh").value_or(false);
    if (use_bvh) {
        std::vector<bounded_object> boxed_members;
        boxed_members.reserve(members->size());
        for (const toml::node& member : *members)
            boxed_members.push_back(boxed(object_from(member, "object"), member.source(),
                                          "bvh = true puts every object in a BVH"));
        return with_box(std::make_shared<bvh>(boxed_members));
    }
    auto listed = std::make_shared<hittable_list>();
    for (const toml::node& member : *members) listed->add(object_from(member, "object").object);
    return {listed, std::nullopt};
}

built_object reader::mesh(fields& f) {
    const toml::node& file = f.need("file", "the OBJ model's path, relative to the scene file");
    if (!file.is_string()) refuse_at(file.source(), "file must be a path, got " + shown(file));
    const std::string written = *file.value<std::string>();
    const std::string shading = f.word_if("shading", {"smooth", "flat"}).value_or("smooth");
    std::optional<std::pair<vec3, real>> fit;
    if (const toml::node* fit_node = f.find("fit")) {
        if (!fit_node->is_table())
            refuse_at(fit_node->source(),
                      "fit must be a table { base = [x, y, z], height = h }, "
                      "got " +
                          shown(*fit_node));
        fields place(*fit_node->as_table(), "fit");
        place.allow("fit", {"base", "height"});
        fit.emplace(place.vector("base", big), place.number("height", 0, big, true));
    }
    auto surface = material_from(f.need("material", "a material's name or table"), "material");
    const std::string path = resolved(written);
    std::vector<std::string> warnings;
    std::shared_ptr<triangle_mesh> made;
    try {
        obj_model model = read_obj(path, triangles_left);
        triangles_left -= model.mesh.triangles.size();
        if (shading == "flat") model.mesh.normals.clear();
        if (shading == "smooth" && model.mesh.normals.empty()) add_smooth_normals(model.mesh);
        if (fit) model.mesh = fitted(std::move(model.mesh), fit->first, fit->second);
        made = mesh_of_model(std::move(model), surface, path, warnings);
    } catch (const user_error& e) {
        refuse_at(file.source(),
                  "model file '" + written + "' (resolved: " + path + "): " + e.what());
    }
    for (const std::string& w : warnings)
        std::cerr << place_of(file.source()) << ": warning: " << w << "\n";
    return with_box(mesh_object(made));
}

built_object reader::transformed(built_object object, const toml::node& steps) {
    const toml::array* list = steps.as_array();
    if (!list)
        refuse_at(steps.source(), "transform must be an array of steps, got " + shown(steps));
    if (list->size() > std::size_t(scene_limits::max_transform_steps))
        refuse_at(steps.source(), "transform must have at most " +
                                      std::to_string(scene_limits::max_transform_steps) +
                                      " steps, got " + std::to_string(list->size()));
    for (const toml::node& step : *list) {
        if (!step.is_table())
            refuse_at(step.source(),
                      "a transform step must be { translate = [x, y, z] } or "
                      "{ rotate = \"y\", degrees = d }, got " +
                          shown(step));
        fields s(*step.as_table(), "transform step");
        s.allow("transform step", {"translate", "rotate", "degrees"});
        const bounded_object inner = boxed(object, step.source(), "a transform moves its box");
        if (auto offset = s.vector_if("translate", big)) {
            object = with_box(std::make_shared<translate>(inner, *offset));
        } else if (auto about = s.word_if("rotate", {"x", "y", "z"})) {
            const real degrees = s.number("degrees", -big, big);
            const axis a       = *about == "x" ? axis::x : *about == "y" ? axis::y : axis::z;
            object             = with_box(std::make_shared<rotate>(inner, a, degrees));
        } else {
            s.refuse("needs 'translate' or 'rotate'");
        }
    }
    return object;
}

bounded_object reader::boxed(const built_object& object, const toml::source_region& where,
                             const std::string& use) {
    if (!object.bounded)
        refuse_at(where, use + ", and a group with bvh = false has none (give it bvh = true)");
    return *object.bounded;
}

std::string reader::resolved(const std::string& path) const {
    const fs::path written(path);
    if (written.is_absolute() || folder.empty()) return written.string();
    return (folder / written).lexically_normal().string();
}

}  // namespace

described_scene parse_scene_text(std::string_view text, const std::string& file_name,
                                 const std::string& folder, std::size_t triangle_limit) {
    if (text.size() > scene_limits::max_file_bytes)
        throw user_error("scene file '" + file_name + "' must be at most " +
                         std::to_string(scene_limits::max_file_bytes) + " bytes, got " +
                         std::to_string(text.size()));
    if (const auto finding = toml_guard(text))
        refuse_at(file_name, finding->line, finding->column, finding->message);
    toml::table root;
    try {
        root = toml::parse(text, std::string_view(file_name));
    } catch (const toml::parse_error& e) {
        refuse_at(e.source(), std::string(e.description()));
    }
    return reader(root, folder, triangle_limit).read();
}

described_scene read_scene_file(const std::string& path) {
    std::error_code error;
    const auto status = fs::status(path, error);
    if (error || !fs::exists(status))
        throw user_error("cannot read scene file '" + path +
                         "': " + (error ? error.message() : "no such file"));
    if (!fs::is_regular_file(status))
        throw user_error("scene file '" + path + "' is not a regular file");
    const std::uintmax_t size = fs::file_size(path, error);
    if (error) throw user_error("cannot read scene file '" + path + "': " + error.message());
    if (size > scene_limits::max_file_bytes)
        throw user_error("scene file '" + path + "' must be at most " +
                         std::to_string(scene_limits::max_file_bytes) + " bytes, got " +
                         std::to_string(size));
    std::ifstream in(path, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in && !in.eof()) throw user_error("cannot read scene file '" + path + "'");
    return parse_scene_text(text, path, fs::path(path).parent_path().string());
}

}  // namespace rt
