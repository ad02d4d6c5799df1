// tests/gs_arith/model_calls.hpp — the model's typed API called from plain ints, shared by the
// gs_arith test suites (unit, property, exhaustive). These only adapt arguments; the expected values
// always come from reference.hpp.
#pragma once

#include <cstdint>
#include <string_view>

#include "gs_arith/alpha_test.hpp"
#include "gs_arith/registers.hpp"

namespace gs_test {

inline gs::u8 u8v(int v) { return gs::u8::from_wrapped(v); }

// TEST_1 fields as ints -> gs::alpha_test on alpha `a` for a frame of format `psm`.
inline gs::write_enables alpha_test_of(bool ate, int method, int aref, int afail, int a, gs::frame_psm psm,
                                       const gs::model_options& o = {}) {
  gs::test_reg t;
  t.ATE = ate;
  t.ATST = static_cast<gs::atst>(method);
  t.AREF = u8v(aref);
  t.AFAIL = static_cast<gs::afail>(afail);
  return gs::alpha_test(t, u8v(a), psm, o);
}

// Sets register `name` to `v` in `regs`; false when the model rejects the value as reserved.
inline bool decodes(gs::gs_registers& regs, std::string_view name, std::uint64_t v) {
  try {
    gs::set_register(regs, name, v);
  } catch (const gs::register_error&) { return false; }
  return true;
}

}  // namespace gs_test
