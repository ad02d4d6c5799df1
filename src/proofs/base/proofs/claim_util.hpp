// proofs/claim_util.hpp — shared pieces of the claim evaluations (verdict from a sweep's tally,
// figures, the (a, b) operand domain of section 3.2).
#pragma once

#include <cstdint>
#include <string>
#include <utility>

#include "proofs/verdict.hpp"

namespace gsdot3::proofs {

// proven when the tally is empty, else refuted with its count and witnesses described by
// describe(index) -> std::string.
template <class Describe>
outcome verdict_of(const tally& t, std::uint64_t domain_size, Describe&& describe) {
  outcome o;
  o.result = t.count == 0 ? verdict::proven : verdict::refuted;
  o.domain_size = domain_size;
  o.counterexamples = t.count;
  for (auto i : t.first) o.witnesses.push_back(describe(i));
  return o;
}

inline figure fig(std::string name, std::int64_t v) { return {std::move(name), v}; }
inline figure fig_real(std::string name, double v) { return {std::move(name), v}; }

// The operands of section 3.2 by index: a2 = i >> 8, b2 = i & 0xFF over 65536 indices, so
// a = 128 − a2 in [−127, 128] and b = b2 − 128 in [−128, 127].
struct operands {
  int a2, b2, a, b;
  static constexpr std::uint64_t count = 65536;
  static constexpr operands at(std::uint64_t i) noexcept {
    const int a2 = static_cast<int>(i >> 8), b2 = static_cast<int>(i & 0xFF);
    return {a2, b2, 128 - a2, b2 - 128};
  }
  std::string describe() const;  // "a = 0x.. (..), b = 0x.. (..)"
};

// The paper's "a·b (implicit signed shift right by 7)": the exact product, arithmetic shift.
constexpr int char_multiply(int a, int b) noexcept { return (a * b) >> 7; }

}  // namespace gsdot3::proofs
