// pipeline/lod.hpp — section 3.8's level of detail: "two lights of the same type can be put in the
// same position: one is rendered using Gouraud shading and the other using the fancy per pixel
// lighting. If one is rendering at say 70% then the other renders at 30% and so on. Once 0% intensity
// on the expensive version of the light is reached, it is removed from the rendering process", so
// that an object fades "at distance continuously to the Gouraud shaded lighting".
#pragma once

#include <vector>

#include "pipeline/method.hpp"
#include "pipeline/scene.hpp"

namespace gsdot3::pipeline {

// Every light split into a co-located pair: the per-pixel (DOT3) light at colour nearest(share · c)
// per channel and the Gouraud light (scene_light::gouraud) at the rest, c − nearest(share · c), so the
// pair's colours add up to c exactly (the paper gives percentages, not a rounding; the exact sum is this
// model's choice, so that share 1 and share 0 are the unsplit frame and the all-Gouraud frame). A
// light of colour 0 is left out ("removed from the rendering process"). share in [0, 1], else
// std::invalid_argument.
std::vector<scene_light> split_for_lod(const std::vector<scene_light>& lights, double share);

// The share at a distance, an engine's mapping the paper leaves to the engine ("fade at distance
// continuously"; this linear ramp is the model's choice): 1 at distance ≤ near, 0 at ≥ far, linear
// between. Throws std::invalid_argument unless 0 ≤ near < far (finite).
double lod_share_at(double distance, double near, double far);
// The camera's distance to the centre of the model's bounding box (world units; the model as drawn,
// yaw 0). Throws std::invalid_argument for a model without vertices.
double camera_distance(const scene& s);

// The GS method that draws light l of a frame drawn with method m: gouraud for a Gouraud light.
constexpr method light_method(method m, const scene_light& l) noexcept { return l.gouraud ? method::gouraud : m; }

}  // namespace gsdot3::pipeline
