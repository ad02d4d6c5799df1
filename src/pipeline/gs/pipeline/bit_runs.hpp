// pipeline/bit_runs.hpp — the runs of set bits in a row's pass bits (simd::depth_row's: bit k % 64 of
// word k / 64 for pixel k), so that step 1 and the runs of the later passes go by runs, not by pixel.
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>

namespace gsdot3::pipeline::detail {

// The first k' >= k below n whose bit equals `value` (n when none).
inline std::size_t next_bit(const std::uint64_t* words, std::size_t k, std::size_t n, bool value) noexcept {
  while (k < n) {
    const std::uint64_t w = (value ? words[k / 64] : ~words[k / 64]) >> (k % 64);
    if (w != 0) return std::min(n, k + static_cast<std::size_t>(std::countr_zero(w)));
    k = (k / 64 + 1) * 64;
  }
  return n;
}

// fn(a, b) for each maximal range [a, b) of set bits among bits 0 .. n − 1, left to right.
template <class Fn>
void for_each_bit_run(const std::uint64_t* words, std::size_t n, Fn&& fn) {
  for (std::size_t a = next_bit(words, 0, n, true); a < n; a = next_bit(words, a, n, true)) {
    const std::size_t b = next_bit(words, a, n, false);
    fn(a, b);
    a = b;
  }
}

}  // namespace gsdot3::pipeline::detail
