// vectors/random.cpp — the splitmix64 generator behind level 2's cases (units.hpp), the same on every
// platform so that `--seed N` gives the same file everywhere.
#include <iterator>

#include "vectors/units.hpp"

namespace gsdot3::vectors {

std::uint64_t random::next() {
  std::uint64_t z = (state_ += 0x9E3779B97F4A7C15u);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
  return z ^ (z >> 31);
}
std::uint64_t random::below(std::uint64_t n) {
  // Rejection sampling: uniform, and the same sequence on every platform.
  const std::uint64_t limit = ~std::uint64_t{0} - (~std::uint64_t{0} % n);
  std::uint64_t v = next();
  while (v >= limit) v = next();
  return v % n;
}
std::uint8_t random::colour_byte() {
  if (coin()) return boundary_bytes[below(std::size(boundary_bytes))];
  return static_cast<std::uint8_t>(next());
}
std::uint32_t random::colour_word() {
  std::uint32_t w = 0;
  for (int i = 0; i < 4; ++i) w |= std::uint32_t{colour_byte()} << (8 * i);
  return w;
}

}  // namespace gsdot3::vectors
