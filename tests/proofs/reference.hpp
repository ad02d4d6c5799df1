// Independent references for the proofs tests: plain int arithmetic written without the model
// (gs_arith) and without the claim code, from the closed forms of the paper's equations.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <thread>
#include <vector>

namespace ref {

// floor(x / 128) by integer division (C++ division truncates, so correct negatives by hand).
constexpr int floor128(int x) { return x >= 0 ? x / 128 : -((-x + 127) / 128); }
// floor(sqrt(v)) by counting.
constexpr int isqrt(int v) {
  int r = 0;
  while ((r + 1) * (r + 1) <= v) ++r;
  return r;
}

// The two-pass per-channel value for a normal component n and light colour L = 128 + l, integer
// light: pass 1 floor(max(n,0)·L/128), pass 2 subtracts floor(max(−n,0)·L/128).
constexpr int two_pass_channel(int n, int L) { return n >= 0 ? floor128(n * L) : -floor128(-n * L); }
// Appendix 2's iZ and alpha from (iX, iY).
struct normal {
  int x, y, z, alpha;
};
constexpr normal appendix2(int x, int y) {
  const int z = isqrt(16384 - x * x - y * y);
  return {x, y, z, (3 * 128 - (x + y + z) + 1) / 3};
}
// value = Σ channel + 3·alpha − 384 for a vertex light l.
constexpr int two_pass_value(const normal& n, int lx, int ly, int lz) {
  return two_pass_channel(n.x, 128 + lx) + two_pass_channel(n.y, 128 + ly) + two_pass_channel(n.z, 128 + lz) +
         3 * n.alpha - 384;
}

// The three-pass value: the same channels, then each channel's term 128 + Max(−n, 0) − Max(n, 0) = 128 − n
// added instead of 3·alpha.
constexpr int three_pass_value(const normal& n, int lx, int ly, int lz) {
  return two_pass_channel(n.x, 128 + lx) + two_pass_channel(n.y, 128 + ly) + two_pass_channel(n.z, 128 + lz) +
         (128 - n.x) + (128 - n.y) + (128 - n.z) - 384;
}

// All reachable (iX, iY), in (iX, iY) order.
inline std::vector<normal> appendix2_normals() {
  std::vector<normal> out;
  for (int x = -127; x <= 127; ++x)
    for (int y = -127; y <= 127; ++y)
      if (x * x + y * y <= 16358) out.push_back(appendix2(x, y));
  return out;
}

// Runs body(begin, end) on [0, n) split in two halves on two threads (the brute forces are long).
template <class Body>
void two_halves(std::size_t n, Body body) {
  std::thread second([&] { body(n / 2, n); });
  body(0, n / 2);
  second.join();
}

}  // namespace ref
