// Chapter 18: triangle meshes from model files. A model is a list of vertices and of triangles
// that index them, read from a Wavefront OBJ file: each vertex stored once, each triangle three
// indices. A ray meets a triangle where its three edge functions agree in sign, computed in a
// space where the ray runs along z (Woop, Benthin and Wald): the two triangles of a shared
// edge compute it from the same two numbers, so no ray slips between them. The mesh is one
// object of the scene with a BVH of its own over its triangles, and chapter 17's traversal
// packs it with the rest.
// Vertex normals, the file's or averaged from the triangles around each vertex, shade the facets
// smooth; the silhouette stays a polygon.
// --model renders another OBJ file in the same place; --look glass or light changes its surface;
// --shading flat shows the facets.
#include <string>

#include "ch05_dielectric/fresnel_option.h"
#include "mesh_scenes.h"
#include "rt/accel/fast_traversal.h"
#include "rt/accel/mesh_bvh.h"
#include "rt/integrators/mis_tracer.h"
#include "rt/integrators/path_tracer.h"
#include "rt/program/asset_path.h"
#include "rt/program/command_line.h"
#include "rt/samplers/sobol_sampler.h"

int main(int argc, char** argv) {
    rt::command_line cli("ch18_meshes");
    add_fresnel_option(cli);
    std::string model = rt::asset_path("models/bunny.obj"), look = "white", shading = "smooth";
    std::string integrator = "mis";
    cli.add_text("--model", model, "OBJ model to place in book 3's Cornell box");
    cli.add_choice("--look", look, {"white", "glass", "light"},
                   "the model's surface: white (diffuse), glass, or light (it emits)");
    cli.add_choice("--shading", shading, {"smooth", "flat"},
                   "smooth (vertex normals: the file's, or averaged from its triangles), or "
                   "flat (each triangle's own normal)");
    cli.add_choice("--integrator", integrator, {"mis", "path"},
                   "mis (chapter 15), or path (chapter 03)");
    return cli.run(argc, argv, [&] {
        const model_look as = look == "glass"   ? model_look::glass
                              : look == "light" ? model_look::light
                                                : model_look::white;
        const model_shading normals =
            shading == "flat" ? model_shading::flat : model_shading::smooth;
        rt::scene scene = rt::with_fast_traversal(model_in_cornell_box(model, as, normals), {},
                                                  {rt::mesh_bvh::packer()});
        scene.settings.make_sampler = rt::sobol_sampler::make;
        return integrator == "mis" ? rt::mis_trace(scene) : rt::path_trace(scene);
    });
}
