#include "rt/lights/light_set.h"

#include <algorithm>

#include "rt/lights/quad_light.h"
#include "rt/lights/sky_light.h"
#include "rt/lights/sphere_light.h"
#include "rt/materials/diffuse_light.h"

namespace rt {

namespace {

bool is_light(const std::shared_ptr<material>& m) {
    return dynamic_cast<const diffuse_light*>(m.get()) != nullptr;
}

// Walks lists and BVHs down to their shapes and makes a light of every emitting one.
class light_finder : public part_visitor {
  public:
    std::vector<std::unique_ptr<light>> found;
    std::vector<const hittable*> shapes;
    std::vector<const hittable*> single_shapes;  // [ch17] of the lights of one sphere or quad

    void visit(const hittable& part) override {
        // Exactly these types: a moving_sphere derives from neither, and its light moves.
        if (const auto* q = dynamic_cast<const quad*>(&part); q && is_light(q->surface()))
            add(part, light_of_quad(*q));
        else if (const auto* s = dynamic_cast<const sphere*>(&part); s && is_light(s->surface()))
            add(part, std::make_unique<sphere_light>(*s));
        else if (const auto* p = dynamic_cast<const light_part*>(&part); p && p->emits())  // [ch18]
            add_part(part, *p);                                                            // [ch18]
        else
            part.visit_parts(*this);
    }

    // [ch18 begin]
    // The parts of group lights, each with its light's index in `found`.
    std::vector<std::pair<const hittable*, std::size_t>> parts;
    // [ch18 end]

    light_set::quad_light_maker make_quad = nullptr;  // [ch17]

  private:
    std::unique_ptr<light> light_of_quad(const quad& q) const {
        if (make_quad) return make_quad(q);  // [ch17]
        return std::make_unique<quad_light>(q);
    }

    // [ch18 begin]
    std::unordered_map<const void*, std::size_t> group_light;
    void add_part(const hittable& shape, const light_part& part) {
        auto [at, added] = group_light.try_emplace(part.light_group(), found.size());
        if (added) {
            shapes.push_back(&shape);  // `shapes` stays one per light: the first part found
            found.push_back(part.make_group_light());
        }
        parts.emplace_back(&shape, at->second);
    }
    // [ch18 end]

    void add(const hittable& shape, std::unique_ptr<light> l) {
        // A shape placed twice in the same list is still one light.
        if (std::find(shapes.begin(), shapes.end(), &shape) != shapes.end()) return;
        shapes.push_back(&shape);
        single_shapes.push_back(&shape);  // [ch17]
        found.push_back(std::move(l));
    }
};

}  // namespace

light_set::light_set(const hittable& world, const background& background_sky) {
    find(world, background_sky);
}

// [ch17 begin]
light_set::light_set(const hittable& world, const background& background_sky,
                     quad_light_maker maker)
    : make_quad(maker) {
    find(world, background_sky);
}
// [ch17 end]

void light_set::find(const hittable& world, const background& background_sky) {
    light_finder finder;
    finder.make_quad = make_quad;  // [ch17]
    finder.visit(world);
    for (std::size_t i = 0; i < finder.found.size(); ++i)
        light_of_shape[finder.shapes[i]] = finder.found[i].get();
    // [ch18 begin]
    for (const auto& [shape, i] : finder.parts) light_of_shape[shape] = finder.found[i].get();
    // [ch18 end]
    lights = std::move(finder.found);
    if (sky_light::emits(background_sky)) {
        lights.push_back(std::make_unique<sky_light>(background_sky));
        sky = lights.back().get();
    }
    single_shapes = std::move(finder.single_shapes);  // [ch17]
}

bool light_set::sample(const point3& ref, real pick, sample2 u, light_sample& out) const {
    if (lights.empty()) return false;
    auto count = lights.size();
    auto index = std::min(count - 1, static_cast<std::size_t>(pick * real(count)));
    if (!lights[index]->sample(ref, u, out)) return false;
    out.pdf /= real(count);
    return true;
}

real light_set::pdf(const point3& ref, const vec3& wi) const {
    real sum = 0;
    for (const auto& l : lights) sum += l->pdf(ref, wi);
    return lights.empty() ? 0 : sum / real(lights.size());
}

real light_set::pdf_of_hit(const point3& ref, const vec3& wi, const hit_record& hit) const {
    auto found = light_of_shape.find(hit.object);
    if (found == light_of_shape.end()) return 0;
    // rec.object names the shape, not where it stands: a light's shape also placed by an
    // instance is hit as the same object. Only the light where it stands itself is aimed at, so
    // the hit counts as that light only if the shape, asked directly, is hit at the same point.
    hit_record direct;
    const ray r(ref, wi);
    if (!hit.object->hit(r, interval(0, infinity), direct)) return 0;
    if (!same_point(r, hit, direct)) return 0;
    return found->second->pdf_at(ref, wi, direct) / real(lights.size());
}

bool light_set::same_point(const ray& r, const hit_record& hit, const hit_record& direct) {
    real apart = (direct.p - hit.p).length();
    return apart <=
           4 * (direct.p_error + hit.p_error) + spawn_offset_scale * (hit.p - r.origin()).length();
}

// [ch17 begin]
const hittable* light_set::first_light_on(const ray& r, interval ray_t, hit_record& hit) const {
    const hittable* first = nullptr;
    hit_record candidate;
    for (const hittable* shape : single_shapes) {
        if (shape->hit(r, ray_t, candidate)) {
            first     = shape;
            hit       = candidate;
            ray_t.max = candidate.t;
        }
    }
    return first;
}
// [ch17 end]

real light_set::pdf_of_sky(const point3& ref, const vec3& wi) const {
    return sky ? sky->pdf(ref, wi) / real(lights.size()) : 0;
}

}  // namespace rt
