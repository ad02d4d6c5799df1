// pipeline/floor.hpp — non-normal-mapped geometry for section 3.1's step 5 (scene::plain): a floor
// under the model, so a frame shows ordinary Gouraud shading beside and behind the DOT3 object, in
// the same buffer and Z buffer.
#pragma once

#include "pipeline/scene.hpp"

namespace gsdot3::pipeline {

// A square at the lowest y of `model`'s vertices, centred under its bounding box, with sides of
// 4 × its larger horizontal half-extent (at least 1e-3): cells × cells quads, two triangles each,
// counter-clockwise seen from +y; normals +y; UVs `repeats` times across. Throws std::invalid_argument
// for an empty model or cells outside 1..256.
mesh floor_under(const mesh& model, int cells = 16, float repeats = 4.0f);

}  // namespace gsdot3::pipeline
