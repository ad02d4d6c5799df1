// pipeline/word_hash.hpp — FNV-1a over an array of 32-bit words: the hash of the bit-pattern keys the
// mesh code welds and compares by (corners, vertices, triangles).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace gsdot3::pipeline {

struct word_hash {
  template <std::size_t N>
  std::size_t operator()(const std::array<std::uint32_t, N>& k) const noexcept {
    std::uint64_t h = 1469598103934665603ull;
    for (std::uint32_t w : k) h = (h ^ w) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

}  // namespace gsdot3::pipeline
