// pipeline/mesh_duplicates.hpp — triangles drawn twice: the same three positions, in the same
// winding, as an earlier triangle (exporters leave them: XGL, LWO samples, a mesh pasted onto itself).
// The GS passes draw a duplicate again at the same depth (ZTST GEQUAL passes it), so every pass that
// blends into the frame with COLCLAMP off (Cs + Cd, Cd − Cs, (Cs − Cd)·As + Cd; pass_table.hpp)
// applies twice and wraps modulo 256. A copy with the opposite winding is not a duplicate: one of
// the two faces the camera and the other is culled.
#pragma once

#include <cstddef>

#include "pipeline/scene.hpp"

namespace gsdot3::pipeline {

// Counts the duplicates (positions compared as floats: −0 equals +0) and, when `drop`, removes them,
// keeping each triangle's first occurrence and the order of the rest.
std::size_t find_duplicate_triangles(mesh& m, bool drop);

}  // namespace gsdot3::pipeline
