// pipeline/spot.hpp — section 3.6's spot light: "a projective texture ... containing the intensity
// attenuation", its texture coordinates per vertex (what the VU1 computes: the vertex in the light's
// projection, S = s/w, T = t/w, Q = 1/w) and the intensity it stands for. The GS side samples the
// 64×64 texture encoders.hpp's spot_map makes from spot_intensity; the float reference evaluates
// spot_intensity at the exact projective coordinates.
#pragma once

#include <vector>

#include <glm/mat4x4.hpp>

#include "pipeline/scene.hpp"

namespace gsdot3::pipeline {

inline constexpr int spot_map_size = 64;  // the intensity texture, spot_map_size² texels

// The intensity at projective coordinates (s, t) (0..1 across the light's frustum): 1 within radius
// 0.65 of the centre, falling linearly to 0 at radius 0.9 (the cone's edge) and 0 beyond, so every
// border texel of the 64×64 texture (centres at radius ≥ 0.98) is 0 and CLAMP keeps outside the
// frustum dark.
double spot_intensity(double s, double t);

// A vertex's texture coordinates in the spot light's projection, and whether it is in front of the
// light (w > 0.001); a triangle with a vertex behind is drawn with S = T = 0, Q = 1 (a border texel).
struct spot_vertex {
  float S = 0.0f, T = 0.0f, Q = 1.0f;
  bool front = false;
};
// Per mesh vertex, for light `l` (light_kind::spot), in the object space `to_object` maps world to.
std::vector<spot_vertex> spot_coordinates(const scene_light& l, const glm::mat4& to_object, const mesh& m);

}  // namespace gsdot3::pipeline
