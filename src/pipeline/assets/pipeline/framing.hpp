// pipeline/framing.hpp — a camera and lights for any model: the model is moved and scaled so its
// bounding sphere is the unit sphere at the origin (prepare's fixed near/far planes 0.1..100 and its
// back view, a turn about the vertical axis through the origin, then suit every model), the camera
// looks at the origin from AZIMUTH, ELEVATION far enough for the sphere to fill the frame with a
// margin, and the default lights are the embedded scene's (whose head has radius ≈ 1) turned with the view.
#pragma once

#include <cstddef>
#include <optional>
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

// How many of the mesh's triangles face the eye (front faces are counter-clockwise: the eye lies on
// the side of the plane that (b − a) × (c − a) points to, by more than 0.01°), as back-face culling
// sees them.
std::size_t facing(const mesh& m, glm::vec3 eye);

struct front_view {
  float azimuth = 0.0f, elevation = 0.0f;
  std::size_t facing = 0;  // triangles that face the camera from there
};

// For a mesh normalised to the unit sphere, the first view, framed as frame_unit_sphere frames it,
// that some triangle faces: (0, 0); (180, 0), the default turned about the vertical axis; then
// looking against the area-weighted mean of the face normals, from where it points. nullopt when
// no triangle faces any of them.
std::optional<front_view> view_of_fronts(const mesh& m, int width, int height, float fov_degrees);

// The embedded scene's two lights (green front-left above, blue right), turned with the view.
std::vector<scene_light> default_lights(float azimuth, float elevation);

}  // namespace gsdot3::pipeline
