// pipeline/default_scene.hpp — the embedded scene of the paper's section 4 setup, made procedurally:
// a smooth low-poly head-like mesh (416 triangles), a 256×256 8-bit normal map, a diffuse texture,
// two point lights (green and blue) and a 512×448 frame.
#pragma once

#include "pipeline/scene.hpp"

namespace gsdot3::pipeline {

// A head-like surface of revolution, deformed (brow, nose, chin, cheeks), `rings`×`segments` grid
// with pole fans: 2·segments·(rings − 1) triangles. Normals from the analytic surface, tangents
// from the UVs (u around, v down).
mesh head_mesh(int rings = 14, int segments = 16);

// A tileable height field of rivets, grooves and dents, `size`×`size`, its normals quantised to a
// 256-entry palette.
normal_map procedural_normal_map(int size = 256);

// A warm diffuse texture with faint panel lines (A8B8G8R8, alpha 0x80).
texture32 procedural_diffuse(int width = 256, int height = 256);

// The whole default scene; `normal_map_size` is reduced in tests to keep them fast.
scene default_scene(int normal_map_size = 256);

}  // namespace gsdot3::pipeline
