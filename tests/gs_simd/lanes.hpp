// tests/gs_simd/lanes.hpp — runs one gs_simd unit over a block of lanes and compares every lane with
// the scalar gs_arith unit (the reference), reporting the first differences' inputs in hex.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "gs_simd/pixel_span.hpp"

namespace gsdot3::simd::test {

// Lanes of one call: five input columns, three output columns.
struct block {
  explicit block(std::size_t lanes) : n(lanes) {
    for (auto& c : in) c.assign(n, 0);
    for (auto& c : out) c.assign(n, 0);
  }
  std::size_t n;
  std::array<std::vector<std::int32_t>, 5> in;
  std::array<std::vector<std::int32_t>, 3> out;

  void run(unit_call c) {
    c.n = n;
    for (std::size_t k = 0; k < 5; ++k) c.in[k] = in[k].data();
    for (std::size_t k = 0; k < 3; ++k) c.out[k] = out[k].data();
    run_unit(c);
  }
};

// The scalar reference of lane i: its expected outputs (unused ones left 0 on both sides).
using reference = std::function<std::array<std::int32_t, 3>(const block&, std::size_t)>;

// Counts lanes where the SIMD outputs differ from the reference (first three reported).
inline std::size_t compare(const block& b, std::size_t outputs, const reference& ref, const std::string& what) {
  std::size_t wrong = 0;
  for (std::size_t i = 0; i < b.n; ++i) {
    const std::array<std::int32_t, 3> e = ref(b, i);
    for (std::size_t k = 0; k < outputs; ++k)
      if (b.out[k][i] != e[k] && wrong++ < 3) {
        std::ostringstream in;
        for (const auto& c : b.in)
          in << " " << std::dec << c[i] << "/0x" << std::hex << static_cast<std::uint32_t>(c[i]);
        ADD_FAILURE() << what << " (target " << current_target() << "): inputs" << in.str() << ", output " << k
                      << " SIMD 0x" << std::hex << b.out[k][i] << ", scalar 0x" << e[k];
      }
  }
  return wrong;
}

// Runs body once per SIMD target this CPU supports, with dispatch forced to it.
inline void for_each_target(const std::function<void(const std::string&)>& body) {
  for (const target& t : available_targets()) {
    force_target(t.bits);
    body(t.name);
  }
  force_target(0);
}

}  // namespace gsdot3::simd::test
