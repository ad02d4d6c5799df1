// Compile-time proofs over whole domains (CNL style): eq4.signed-multiply, eq8.offset-multiply and
// ilp.palette-permutation, with the model's blend under the hardware's floor shift (the default
// options). One static_assert per a2 row keeps each constant evaluation within the compilers'
// step limits (g++ -fconstexpr-ops-limit, clang -fconstexpr-steps). The run-time claims evaluate the
// same predicates under every option; this TU pins the default verdicts into the build.
#include <utility>

#include "proofs/claim_util.hpp"
#include "proofs/methods.hpp"

namespace gsdot3::proofs::static_checks {

namespace m = methods;

// Eq. (8) for every b2 of one a2 row: the blend gives a·b + 128, inside 0..255. Eq. (4) is the
// same value minus 128, so it holds on exactly the same rows.
constexpr bool offset_multiply_row(int a2) {
  const gs::model_options o{};
  for (int b2 = 0; b2 < 256; ++b2) {
    const int v = m::offset_multiply(m::byte(a2), m::byte(b2), o).value();
    const int a = 128 - a2, b = b2 - 128;
    if (v != char_multiply(a, b) + 128 || v < 0 || v > 255) return false;  // eq. (8) and its range
    if (v - 128 != char_multiply(a, b)) return false;                      // eq. (4)
  }
  return true;
}

template <int A2>
struct offset_multiply_proof {
  static_assert(offset_multiply_row(A2), "eq. (4)/(8) fails on this a2 row");
  static constexpr bool value = true;
};

template <int... A2>
constexpr bool all_rows(std::integer_sequence<int, A2...>) {
  return (offset_multiply_proof<A2>::value && ...);
}
static_assert(all_rows(std::make_integer_sequence<int, 256>{}));

// ILP' (rotation by 128) is a permutation of ILP and agrees with the GS "− 128" post filter.
constexpr bool ilp_rotation_agrees() {
  const gs::model_options o{};
  int count_plain[130] = {}, count_rotated[130] = {};
  for (int j = 0; j < 256; ++j) {
    if (m::ilp_offset_entry(j) != m::ilp_entry(m::minus_128(m::byte(j), o).value())) return false;
    ++count_plain[m::ilp_entry(j)];
    ++count_rotated[m::ilp_offset_entry(j)];
  }
  for (int v = 0; v < 130; ++v)
    if (count_plain[v] != count_rotated[v]) return false;
  return true;
}
static_assert(ilp_rotation_agrees());

}  // namespace gsdot3::proofs::static_checks
