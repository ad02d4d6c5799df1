// pipeline/generated_normals.hpp — normals for a mesh whose file has none, as modelling tools make
// them (Blender's auto smooth, 3ds Max's and Maya's smoothing angle): smooth across an edge whose two
// faces differ by at most the crease angle, split across a sharper one.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace gsdot3::pipeline {

// One unit normal per triangle corner (index 3·t + k; zero for a triangle with keep[t] == 0, and where
// the group's sum cancels, e.g. the two sides of a sheet: the caller takes the face normal there).
// Positions are matched by their bits (a UV seam, where importers duplicate the vertex, is no edge).
// The rule, per edge (two positions) shared by two kept triangles: when the angle between their face
// normals is at most `crease_degrees`, their corners at both ends of the edge share one normal.
// An edge of more than two triangles joins each with the one before it in triangle order. A group's
// normal is the sum of its faces' unit normals, each weighted by its corner angle (Thürmer and
// Wüthrich 1998). 0° splits every edge that is not flat, 180° joins across every edge (one normal
// per position wherever the triangles around it are joined by edges).
std::vector<glm::vec3> crease_normals(const std::vector<glm::vec3>& positions,
                                      const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                      const std::vector<char>& keep, float crease_degrees);

}  // namespace gsdot3::pipeline
