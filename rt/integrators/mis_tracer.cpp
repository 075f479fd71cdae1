#include "rt/integrators/mis_tracer.h"

#include <cmath>

#include "rt/core/exercise.h"
#include "rt/core/validate.h"
#include "rt/geometry/spawn_ray.h"
#include "rt/materials/material.h"
#include "rt/render/ray_count.h"

namespace rt {

namespace {
std::shared_ptr<const hittable> given(std::shared_ptr<const hittable> world) {
    require_given(world, "scene world");
    return world;
}

// Russian roulette starts after this many segments: the first bounces carry most of the light.
constexpr int roulette_after = 3;

// [ch17 begin]
// A material whose spread is evaluable (material::spread_is_evaluable: fuzzy metal) seen as an
// evaluable lobe: the same directions and weights, with eval and pdf its spread's, and each
// sample saying so with its density. Only for the vertex that holds it.
class spread_lobe final : public material {
  public:
    explicit spread_lobe(const material& m) : inner(m) {}

    color emitted(const ray& r_in, const hit_record& rec) const override {
        return inner.emitted(r_in, rec);
    }
    std::optional<scatter_sample> scatter(const ray& r_in, const hit_record& rec,
                                          sampler& s) const override {
        std::optional<scatter_sample> sample = inner.scatter(r_in, rec, s);
        if (sample) {
            sample->from = lobe::evaluable;
            sample->pdf  = inner.spread_pdf(r_in, rec, unit_vector(sample->scattered.direction()));
        }
        return sample;
    }
    lobe lobe_kind() const override { return lobe::evaluable; }
    color eval(const ray& r_in, const hit_record& rec, const vec3& wi) const override {
        return inner.spread_eval(r_in, rec, wi);
    }
    real pdf(const ray& r_in, const hit_record& rec, const vec3& wi) const override {
        return inner.spread_pdf(r_in, rec, wi);
    }

  private:
    const material& inner;
};
// [ch17 end]
}  // namespace

real power_heuristic(real pdf_taken, real pdf_other) {
    // [exercise power_heuristic begin]
    if (!(pdf_taken > 0)) return 0;
    if (std::isinf(pdf_taken)) return std::isinf(pdf_other) ? real(0.5) : 1;
    // 1 / (1 + (other / taken)^2): no overflow when both densities are huge.
    real ratio = pdf_other / pdf_taken;
    return 1 / (1 + ratio * ratio);
    // [exercise power_heuristic end]
}

mis_tracer::mis_tracer(std::shared_ptr<const hittable> w, const background& b)
    : world(given(std::move(w))), sky(b), lights(*world, b) {}

// [ch17 begin]
mis_tracer::mis_tracer(std::shared_ptr<const hittable> w, const background& b, const mis_choices& c)
    : world(given(std::move(w))), sky(b), lights(*world, b, c.make_quad), choices(c) {
    if (choices.aim_along_rays) along_rays = choices.aim_along_rays(*world, lights);
}

color mis_tracer::expected_light(const ray& r, const hittable*& shape, hit_record& on_light) const {
    shape = lights.first_light_on(r, interval(0, infinity), on_light);
    if (!shape) return color(0, 0, 0);
    const color emitted = on_light.mat->emitted(r, on_light);
    if (is_black(emitted)) return emitted;
    count_ray();
    // Up to the light, not including it: the interval is open, so the light's own hit at
    // on_light.t does not block.
    const real passed = world->transmittance(r, interval(0, on_light.t));
    return passed * emitted;
}
// [ch17 end]

real mis_tracer::visibility(const ray& r_in, const hit_record& rec,
                            const light_sample& towards) const {
    ray shadow = spawn_ray(rec, r_in, towards.wi);
    if (towards.at_infinity) return world->transmittance(shadow, interval(0, infinity));
    // End just short of the light: its point moved off its surface, towards us, by its own
    // error bound, so the light itself never blocks the ray that reaches it.
    const hit_record& on = towards.on_light;
    point3 target        = on.p + on.p_error * on.normal;
    return world->transmittance(shadow.continued(shadow.origin(), target - shadow.origin()),
                                interval(0, 1));
}

color mis_tracer::radiance(const ray& camera_ray, sampler& s, int max_depth) const {
    ray r = camera_ray;
    color radiance(0, 0, 0);
    color throughput(1, 1, 1);
    // Whether light the next segment finds was also aimed at from the last vertex, and with
    // what density the material chose that segment's direction.
    bool weigh_emission = false;
    real material_pdf   = 0;
    point3 last_vertex;
    // [ch17 begin]
    // Whether the last vertex was a medium's point whose light along_rays aimed at along the
    // segment that reached it: the light set's lights this segment finds are counted already.
    bool aimed_before = false;
    // Whether the eye sees this segment directly or through mirrors and glass only (every
    // vertex so far followed, none evaluable): where the light a medium scatters shows most.
    bool seen_sharply = true;
    // [ch17 end]
    for (int segment = 0; segment < max_depth; ++segment) {
        // [ch17 begin]
        // The light met along this segment, in expectation over the media it crosses.
        const hittable* light_shape = nullptr;
        hit_record on_light;
        if (choices.through_media == light_through_media::expected) {
            const color expected = expected_light(r, light_shape, on_light);
            if (!is_black(expected)) {
                real w = 1;
                if (weigh_emission)
                    w = power_heuristic(
                        material_pdf,
                        lights.pdf_of_hit(last_vertex, unit_vector(r.direction()), on_light));
                // Counted along the segment before, if the light set could have aimed at it.
                if (aimed_before &&
                    lights.pdf_of_hit(last_vertex, unit_vector(r.direction()), on_light) > 0)
                    w = 0;
                radiance += throughput * w * expected;
            }
        }
        // [ch17 end]
        hit_record rec;
        count_ray();
        const bool found = world->hit(r, interval(0, infinity), rec);
        // [ch17 begin]
        if (along_rays && seen_sharply && segment + 1 < max_depth) {
            s.start_side_draws(segment);
            radiance += throughput * along_rays->along(r, found, rec, s);
        }
        // [ch17 end]
        if (!found) {
            real w = 1;
            if (weigh_emission)
                w = power_heuristic(material_pdf,
                                    lights.pdf_of_sky(last_vertex, unit_vector(r.direction())));
            // [ch17 begin]
            if (aimed_before && lights.pdf_of_sky(last_vertex, unit_vector(r.direction())) > 0)
                w = 0;
            // [ch17 end]
            radiance += throughput * w * sky.radiance(r.direction());
            break;
        }
        // [ch17 begin]
        // Fuzzy metal weighed: for the rest of this vertex its material is seen through
        // spread_lobe, whose lobe is evaluable, so that the light is aimed at from it too.
        const spread_lobe weighed_spread(*rec.mat);
        if (choices.weigh_fuzzy_metal && rec.mat->spread_is_evaluable()) rec.mat = &weighed_spread;
        // [ch17 end]
        const material& surface = *rec.mat;
        color emitted           = surface.emitted(r, rec);
        // [ch17 begin]
        // Already counted, in expectation, if this is the light expected_light found.
        if (light_shape && rec.object == light_shape && light_set::same_point(r, rec, on_light))
            emitted = color(0, 0, 0);
        // Counted along the segment before, if the light set could have aimed at it.
        if (aimed_before && !is_black(emitted) &&
            lights.pdf_of_hit(last_vertex, unit_vector(r.direction()), rec) > 0)
            emitted = color(0, 0, 0);
        // [ch17 end]
        if (!is_black(emitted)) {
            // [exercise mis_tracer::hit_weight begin]
            real w = 1;
            if (weigh_emission)
                w = power_heuristic(
                    material_pdf, lights.pdf_of_hit(last_vertex, unit_vector(r.direction()), rec));
            radiance += throughput * w * emitted;
            // [exercise mis_tracer::hit_weight end]
        }

        s.start_segment(segment);  // [ch16]
        const bool evaluable = surface.lobe_kind() == lobe::evaluable && !lights.empty();
        // Next-event estimation: only where the light it finds is still within max_depth.
        bool next_event = evaluable && segment + 1 < max_depth;
        // [ch17 begin]
        // A medium's point whose light was aimed at along the segment that reached it.
        const bool aimed_here = along_rays && seen_sharply && along_rays->covers(r, rec);
        if (aimed_here) next_event = false;
        // [ch17 end]
        if (next_event) {
            // [exercise mis_tracer::next_event begin]
            real pick = s.next_1d();
            light_sample towards;
            if (lights.sample(rec.p, pick, s.next_2d(), towards)) {
                color f = surface.eval(r, rec, towards.wi);
                if (!is_black(f) && !is_black(towards.radiance)) {
                    count_ray();
                    real passed = visibility(r, rec, towards);
                    if (passed > 0) {
                        real w = power_heuristic(towards.pdf, surface.pdf(r, rec, towards.wi));
                        radiance += throughput * f * towards.radiance * (passed * w / towards.pdf);
                    }
                }
            }
            // [exercise mis_tracer::next_event end]
        }

        const std::optional<scatter_sample> next = surface.scatter(r, rec, s);
        if (!next) break;
        // The light the next segment finds was also aimed at from here only where the lobe
        // could be weighed; the sample brings the density it was drawn with.
        weigh_emission = evaluable && next->from == lobe::evaluable;
        // [ch17 begin]
        aimed_before = aimed_here;
        seen_sharply = seen_sharply && !evaluable && next->from != lobe::evaluable;
        // [ch17 end]
        material_pdf = next->pdf;
        // Where the scattered ray really starts (off the surface): light_set::pdf_of_hit asks
        // the light's shape again along this same ray, and must find the same point.
        last_vertex = next->scattered.origin();
        throughput  = throughput * next->weight;
        r           = next->scattered;

        if (segment + 1 >= roulette_after) {
            // [exercise mis_tracer::roulette begin]
            real carried = max_abs_component(throughput);
            if (carried < 1) {
                real q = 1 - carried;
                if (s.next_1d() < q) break;
                throughput = throughput / (1 - q);
            }
            // [exercise mis_tracer::roulette end]
        }
    }
    return radiance;
}

render_job mis_trace(const scene& sc) {
    return {sc.cam, std::make_shared<mis_tracer>(sc.world, sc.sky), sc.settings};
}

// [ch17 begin]
render_job mis_trace(const scene& sc, const mis_choices& choices) {
    return {sc.cam, std::make_shared<mis_tracer>(sc.world, sc.sky, choices), sc.settings};
}
// [ch17 end]

}  // namespace rt
