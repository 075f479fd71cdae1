#include "rt/lights/mesh_light.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rt/core/exercise.h"
#include "rt/materials/material.h"

namespace rt {

namespace {

constexpr real one_minus_epsilon = 1 - std::numeric_limits<real>::epsilon() / 2;

// The unit normal of triangle i's plane (not its shading normal).
vec3 geometric_normal(const triangle_mesh& mesh, std::size_t i) {
    const auto& v = mesh.triangle(i);
    return unit_vector(cross(mesh.position(v[1]) - mesh.position(v[0]),
                             mesh.position(v[2]) - mesh.position(v[0])));
}

}  // namespace

mesh_light::mesh_light(const triangle_mesh& m) : mesh(&m) {
    cumulative.reserve(m.triangle_count());
    double sum = 0;
    for (std::size_t i = 0; i < m.triangle_count(); ++i) {
        const auto& v = m.triangle(i);
        const vec3 n =
            cross(m.position(v[1]) - m.position(v[0]), m.position(v[2]) - m.position(v[0]));
        sum += 0.5 * double(n.length());
        cumulative.push_back(sum);
    }
    total_area = real(sum);
    tree       = std::make_shared<mesh_bvh>(mesh_tree(m));
}

std::size_t mesh_light::choose(real& u) const {
    const double target = double(u) * cumulative.back();
    const std::size_t i = std::min<std::size_t>(
        std::size_t(std::upper_bound(cumulative.begin(), cumulative.end(), target) -
                    cumulative.begin()),
        cumulative.size() - 1);
    const double before = i == 0 ? 0 : cumulative[i - 1];
    const double share  = cumulative[i] - before;
    const double within = share > 0 ? (target - before) / share : 0;
    u                   = std::clamp(real(within), real(0), one_minus_epsilon);
    return i;
}

bool mesh_light::sample(const point3& ref, sample2 u, light_sample& out) const {
    if (!(total_area > 0)) return false;
    // [exercise mesh_light::sample begin]
    real pick           = u.u;
    const std::size_t i = choose(pick);
    // A uniform point of the triangle: sqrt(pick) spreads the points evenly from corner 0 to
    // the opposite edge, u.v along that edge.
    const real s  = std::sqrt(pick);
    const real b1 = s * (1 - u.v), b2 = s * u.v;
    const auto& v       = mesh->triangle(i);
    const point3 target = (1 - b1 - b2) * mesh->position(v[0]) + b1 * mesh->position(v[1]) +
                          b2 * mesh->position(v[2]);
    // As a quad light does: aim at the point and let the triangle say where the ray meets it.
    if (!mesh->faces()[i].hit(ray(ref, target - ref), interval(0, infinity), out.on_light))
        return false;
    // The direction of the ray that met it (the hit's p may have moved a few ulps along the
    // surface for its shading normal).
    const vec3 to_light = target - ref;
    const real distance = to_light.length();
    if (!(distance > 0)) return false;
    out.wi  = to_light / distance;
    out.pdf = pdf_at(ref, out.wi, out.on_light);
    if (!(out.pdf > 0 && std::isfinite(out.pdf))) return false;  // edge-on: no solid angle
    out.radiance    = out.on_light.mat->emitted(ray(ref, out.wi), out.on_light);
    out.at_infinity = false;
    return true;
    // [exercise mesh_light::sample end]
}

real mesh_light::pdf(const point3& ref, const vec3& wi) const {
    // A direction is drawn by aiming at any point of the mesh along it, not only the nearest:
    // its density sums every crossing (a closed mesh is crossed twice, in and out). The point
    // a ray hits has pdf_at's density alone, which is what an MIS weight of that hit needs.
    const ray r(ref, wi);
    interval beyond(0, infinity);
    hit_record hit;
    real density = 0;
    while (tree->hit(r, beyond, hit)) {
        density += pdf_at(ref, wi, hit);
        // The next crossing: farther than this one's rounding, so that a direction through an
        // edge, which both triangles there may answer a few ulps apart, counts it once.
        beyond.min = hit.t + 2 * hit.p_error;
    }
    return density;
}

real mesh_light::pdf_at(const point3& ref, const vec3& wi, const hit_record& hit) const {
    // d^2 / (|cos| A) with d the distance along wi to the triangle's plane, h / |cos| for ref at
    // height h above it: h^2 / (|cos|^3 A). From the plane, not from hit.p, which a shading
    // normal moves a few ulps along the surface (triangle_mesh.cpp), so sample() and pdf() give
    // a direction the same density whichever way they met the triangle.
    const auto& face     = *static_cast<const mesh_triangle*>(hit.object);
    const vec3 g         = geometric_normal(*mesh, face.index());
    const real height    = dot(mesh->position(mesh->triangle(face.index())[0]) - ref, g);
    const real cos_light = std::fabs(dot(g, wi));
    const real density   = height * height / (cos_light * cos_light * cos_light * total_area);
    return cos_light > 0 && std::isfinite(density) ? density : 0;
}

}  // namespace rt
