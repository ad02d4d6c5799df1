#include "pipeline/lod.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace gsdot3::pipeline {

std::vector<scene_light> split_for_lod(const std::vector<scene_light>& lights, double share) {
  if (!(share >= 0.0 && share <= 1.0))
    throw std::invalid_argument("level-of-detail share must be in [0, 1], got " + std::to_string(share));
  std::vector<scene_light> out;
  for (const scene_light& l : lights) {
    scene_light dot3 = l, gouraud = l;
    gouraud.gouraud = true;
    for (std::size_t c = 0; c < 3; ++c) {
      dot3.colour[c] = static_cast<std::uint8_t>(std::lround(share * l.colour[c]));
      gouraud.colour[c] = static_cast<std::uint8_t>(l.colour[c] - dot3.colour[c]);
    }
    for (const scene_light& half : {dot3, gouraud})
      if (half.colour != std::array<std::uint8_t, 3>{}) out.push_back(half);
  }
  return out;
}

}  // namespace gsdot3::pipeline
