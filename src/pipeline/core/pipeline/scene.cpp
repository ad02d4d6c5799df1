// pipeline/scene.cpp — a normal map's layers apart and together (scene.hpp).
#include "pipeline/scene.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace gsdot3::pipeline {

normal_map layer_map(const normal_map& m, std::size_t k) {
  if (k >= layers(m))
    throw std::out_of_range("normal map layer " + std::to_string(k) + " of " + std::to_string(layers(m)));
  const std::size_t n = layer_texels(m);
  normal_map one;
  one.width = m.width, one.height = m.height, one.bits = m.bits;
  const auto first = static_cast<std::ptrdiff_t>(k * n);
  one.index.assign(m.index.begin() + first, m.index.begin() + first + static_cast<std::ptrdiff_t>(n));
  if (m.unquantised.size() == m.index.size())
    one.unquantised.assign(m.unquantised.begin() + first,
                           m.unquantised.begin() + first + static_cast<std::ptrdiff_t>(n));
  one.palette = layer_palette(m, k);
  return one;
}

normal_map stacked(const std::vector<normal_map>& all) {
  if (all.empty()) throw std::invalid_argument("a normal map of no layers");
  if (all.size() == 1) return all.front();
  normal_map m;
  m.width = all.front().width, m.height = all.front().height, m.bits = all.front().bits;
  const bool unquantised =
      std::all_of(all.begin(), all.end(), [](const normal_map& l) { return l.unquantised.size() == l.index.size(); });
  for (const normal_map& l : all) {
    if (l.width != m.width || l.height != m.height || l.bits != m.bits || layers(l) != 1)
      throw std::invalid_argument("normal map layers differ in size or bits");
    m.palette_start.push_back(static_cast<std::uint32_t>(m.palette.size()));
    m.palette.insert(m.palette.end(), l.palette.begin(), l.palette.end());
    m.index.insert(m.index.end(), l.index.begin(), l.index.end());
    if (unquantised) m.unquantised.insert(m.unquantised.end(), l.unquantised.begin(), l.unquantised.end());
  }
  return m;
}

}  // namespace gsdot3::pipeline
