// pipeline/framing.hpp — a camera and lights for any model: the model is moved and scaled so its
// bounding sphere is the unit sphere at the origin (prepare's fixed near/far planes 0.1..100 and its
// back view, a turn about the vertical axis through the origin, then suit every model), the camera
// looks at the origin from AZIMUTH, ELEVATION far enough for the sphere to fill the frame with a
// margin, and the default lights are the embedded scene's (whose head has radius ≈ 1) turned with the view.
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "pipeline/scene.hpp"

namespace gsdot3::pipeline {

struct bounding_sphere {
  glm::vec3 centre{};
  float radius = 0.0f;
};

// The centre of the bounding box and the largest distance of a vertex from it (encloses every vertex).
bounding_sphere bounds_of(const mesh& m);

// Moves and scales the mesh so `b` becomes the unit sphere at the origin.
void normalise(mesh& m, const bounding_sphere& b);

// The camera looking at the origin from azimuth (degrees about +y, 0 = from +z, 90 = from +x) and
// elevation (degrees above the horizon, clamped to ±89), at the distance where the unit sphere's
// outline keeps `margin` (a factor, 1.1 = 10 %) inside the nearer frame edge. `fov_degrees` is the
// field of view across the frame's narrower side (the camera's vertical field widens for a frame
// taller than wide, up to 160°).
camera frame_unit_sphere(float azimuth, float elevation, int width, int height, float fov_degrees = 40.0f,
                         float margin = 1.1f);

// The embedded scene's two lights (green front-left above, blue right), turned with the view.
std::vector<scene_light> default_lights(float azimuth, float elevation);

}  // namespace gsdot3::pipeline
