// Normals for a model that has none: at each vertex, the average of the normals of the
// triangles around it, each weighted by its area (the cross product of two of its edges is its
// normal times twice its area, so the sum weighs itself). Chapter 18.
// A scan such as the Stanford bunny samples a smooth surface; shading it with these normals
// (triangle_mesh.h) hides the facets the silhouette still shows.
#pragma once

#include "rt/geometry/triangle_mesh.h"

namespace rt {

// Sets mesh.normals, one per vertex (replacing any). A vertex no triangle with an area uses
// gets the zero vector: its triangles then shade with their geometric normal.
void add_smooth_normals(mesh_data& mesh);

}  // namespace rt
