#include "rt/integrators/in_scattering.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "rt/geometry/instance.h"
#include "rt/materials/material.h"
#include "rt/media/equiangular.h"
#include "rt/render/ray_count.h"

namespace rt {

namespace {

// A medium's stretch along a segment.
struct crossing {
    const constant_medium* medium = nullptr;
    real t_in = 0, t_out = 0;
};
// Stretches kept per segment: beyond this many media crossed, the segment asks the world.
constexpr int max_kept = 8;
// The largest real below 1 is 1 minus this.
constexpr real epsilon_below_1 = std::numeric_limits<real>::epsilon() / 2;

// Walks lists and BVHs down to their media, as light_set's search walks them to its lights,
// and looks inside instances for media it cannot place there.
class media_finder : public part_visitor {
  public:
    std::vector<const constant_medium*> found;
    bool hidden = false;  // a medium inside an instance

    void visit(const hittable& part) override {
        if (const auto* m = dynamic_cast<const constant_medium*>(&part)) {
            if (inside_instance)
                hidden = true;
            else if (std::find(found.begin(), found.end(), m) == found.end())
                found.push_back(m);
        } else if (const auto* moved = dynamic_cast<const translate*>(&part)) {
            look_inside(*moved->placed());
        } else if (const auto* turned = dynamic_cast<const rotate*>(&part)) {
            look_inside(*turned->placed());
        } else {
            part.visit_parts(*this);
        }
    }

  private:
    bool inside_instance = false;
    void look_inside(const hittable& placed) {
        const bool was  = inside_instance;
        inside_instance = true;
        visit(placed);
        inside_instance = was;
    }
};

}  // namespace

in_scattering::in_scattering(const hittable& w, const light_set& l) : world(w), lights(l) {
    media_finder finder;
    finder.visit(world);
    found          = std::move(finder.found);
    all_media_seen = !finder.hidden;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        point3 at;
        has_center.push_back(lights[i].center(at));
        centers.push_back(at);
    }
}

bool in_scattering::covers(const ray& r, const hit_record& rec) const {
    const auto* m = dynamic_cast<const constant_medium*>(rec.object);
    if (!m || std::find(found.begin(), found.end(), m) == found.end()) return false;
    if (all_media_seen) return true;  // no instance places a copy of it
    // The medium where it stands itself, not a copy an instance placed elsewhere (the same
    // object, seen in another frame): its own stretch along r holds the point.
    real t_in = 0, t_out = 0;
    return m->stretch(r, interval(0, infinity), t_in, t_out) && t_in <= rec.t && rec.t <= t_out;
}

real in_scattering::distance_pdf(const point3& origin, const vec3& unit_direction, real s_min,
                                 real s_max, real at) const {
    if (!(at >= s_min && at <= s_max) || lights.empty()) return 0;
    const real uniform = 1 / (s_max - s_min);
    real sum           = 0;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        if (has_center[i]) {
            const equiangular about(origin, unit_direction, centers[i], s_min, s_max);
            if (about.usable()) {
                sum += about.pdf(at);
                continue;
            }
        }
        sum += uniform;
    }
    return sum / real(lights.size());
}

real in_scattering::sample_distance(const point3& origin, const vec3& unit_direction, real s_min,
                                    real s_max, real u_light, real u_at) const {
    const std::size_t count = lights.size();
    const std::size_t i     = std::min(count - 1, static_cast<std::size_t>(u_light * real(count)));
    if (has_center[i]) {
        const equiangular about(origin, unit_direction, centers[i], s_min, s_max);
        if (about.usable()) return about.sample(u_at);
    }
    return std::min(s_min + u_at * (s_max - s_min), s_max);
}

color in_scattering::along(const ray& r, bool found_hit, const hit_record& nearest,
                           sampler& s) const {
    if (found.empty() || lights.empty()) return color(0, 0, 0);

    // Up to a surface the segment found; past a medium's random point, which the ray crosses
    // with some probability, the integrand is not 0.
    const bool to_surface = found_hit && !dynamic_cast<const constant_medium*>(nearest.object);
    const interval reach(0, to_surface ? nearest.t : infinity);

    // The media this segment crosses (their stretches kept for the transmittance below); one
    // of them, each as likely.
    std::array<crossing, max_kept> kept;
    int count = 0;
    for (const constant_medium* m : found) {
        crossing c{m, 0, 0};
        if (!m->stretch(r, reach, c.t_in, c.t_out)) continue;
        if (count < max_kept) kept[count] = c;
        ++count;
    }
    if (count == 0) return color(0, 0, 0);
    // Drawn only for a segment that crosses a medium: side draws keep their places whether or
    // not earlier segments drew. Which medium, then (the same number, stretched) which light's
    // density; where; and the light sample's own three.
    const sample2 u_choice = s.next_2d();
    const real u_pick      = s.next_1d();
    const sample2 u_on     = s.next_2d();
    const int k            = std::min(count - 1, static_cast<int>(u_choice.u * real(count)));
    const real u_light = std::min(u_choice.u * real(count) - real(k), real(1) - epsilon_below_1);
    crossing chosen;
    if (k < max_kept) {
        chosen = kept[k];
    } else {
        for (int seen = 0; const constant_medium* m : found) {
            crossing c{m, 0, 0};
            if (m->stretch(r, reach, c.t_in, c.t_out) && seen++ == k) chosen = c;
        }
    }
    if (!chosen.medium) return color(0, 0, 0);

    const real speed = r.direction().length();
    const vec3 unit  = r.direction() / speed;
    const real s_min = chosen.t_in * speed, s_max = chosen.t_out * speed;
    if (!(s_min < s_max) || !std::isfinite(s_max)) return color(0, 0, 0);
    real at = 0, density = 0;
    if (lights.size() == 1 && has_center[0]) {
        // One light (the common case): its equiangular density, made once.
        const equiangular about(r.origin(), unit, centers[0], s_min, s_max);
        if (about.usable()) {
            at      = about.sample(u_choice.v);
            density = about.pdf(at);
        }
    }
    if (!(density > 0)) {
        at      = sample_distance(r.origin(), unit, s_min, s_max, u_light, u_choice.v);
        density = distance_pdf(r.origin(), unit, s_min, s_max, at);
    }
    if (!(density > 0) || !std::isfinite(density)) return color(0, 0, 0);

    // What reaches that point unscattered: 0 behind a surface. Before the segment's nearest
    // hit no surface stands, and if every medium is in `found` (and all their stretches were
    // kept) that is the product of theirs alone.
    const real t     = at / speed;
    const bool clear = all_media_seen && count <= max_kept && (!found_hit || t <= nearest.t);
    real reached     = 1;
    if (clear) {
        real depth = 0;
        for (int i = 0; i < count; ++i)
            if (kept[i].t_in < t)
                depth += kept[i].medium->density() * (std::fmin(kept[i].t_out, t) - kept[i].t_in);
        reached = std::exp(-depth * speed);
    } else {
        count_ray();
        reached = world.transmittance(r, interval(0, t));
    }
    if (!(reached > 0)) return color(0, 0, 0);
    const constant_medium* medium = chosen.medium;

    hit_record here;
    here.t          = t;
    here.p          = r.at(t);
    here.normal     = vec3(1, 0, 0);
    here.front_face = true;
    here.p_error    = 0;
    here.mat        = &medium->phase();
    here.object     = medium;
    light_sample towards;
    if (!lights.sample(here.p, u_pick, u_on, towards)) return color(0, 0, 0);
    const color f = here.mat->eval(r, here, towards.wi);
    if (is_black(f) || is_black(towards.radiance)) return color(0, 0, 0);

    count_ray();
    real passed = 0;
    if (towards.at_infinity) {
        passed = world.transmittance(r.continued(here.p, towards.wi), interval(0, infinity));
    } else {
        // Just short of the light, as mis_tracer's shadow rays end.
        const hit_record& on = towards.on_light;
        const point3 target  = on.p + on.p_error * on.normal;
        passed = world.transmittance(r.continued(here.p, target - here.p), interval(0, 1));
    }
    if (!(passed > 0)) return color(0, 0, 0);
    const real weight =
        reached * medium->density() * passed * real(count) / (towards.pdf * density);
    const color L = f * towards.radiance * weight;
    return std::isfinite(L.x() + L.y() + L.z()) ? L : color(0, 0, 0);
}

}  // namespace rt
