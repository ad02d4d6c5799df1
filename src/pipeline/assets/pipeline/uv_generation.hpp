// pipeline/uv_generation.hpp — texture coordinates for a mesh whose file has none: a box, sphere or
// planar projection of the model-space positions, one repeat of the map across the model's largest
// extent, and the rule that picks one for the model's shape when none is asked for.
#pragma once

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "pipeline/mesh_import.hpp"

namespace gsdot3::pipeline {

struct uv_bounds {
  glm::vec3 lo{INFINITY}, hi{-INFINITY};
  float extent() const;  // the largest side (at least 1e-30)
};

// One triangle's UVs (v runs down the image). box: each triangle onto the side of the box its normal
// faces most; sphere: longitude and colatitude about the box's centre (a triangle across the back
// meridian kept on one side of it); planar: onto the plane of the box's two largest sides.
std::array<glm::vec2, 3> project(uv_projection how, const std::array<glm::vec3, 3>& p, const uv_bounds& b);

struct projection_choice {
  uv_projection how = uv_projection::box;
  std::string why;  // the rule's figures, for the notice
};

// The projection for the model's shape (the triangles in model space, `b` their bounds), weighting
// each triangle by its area:
//   planar when the mean |n·a| is at least 0.9, a the axis of the box's smallest side (the surface
//          faces one axis: a sheet, a terrain, a thin slab);
//   sphere when the mean |n·r| is at least 0.95, r the unit direction from the box's centre to the
//          triangle's centroid (the surface faces away from its centre everywhere: a ball);
//   box    otherwise (a cube: 1/3 and 0.905 with two triangles a side).
projection_choice choose_projection(const std::vector<std::array<glm::vec3, 3>>& triangles, const uv_bounds& b);

const char* projection_name(uv_projection how);  // "box projection", …

}  // namespace gsdot3::pipeline
