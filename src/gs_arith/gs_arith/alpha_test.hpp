// gs_arith/alpha_test.hpp — TEST.ATE / ATST / AREF / AFAIL: which of RGB, A and Z a pixel writes.
//
// Evidence (../shared/spec/gs-alu-facts.md, "Alpha test"; matrix row rgb_only_targets of docs/evidence.md):
// the post-TFX alpha is compared with the 8-bit AREF by ATST (PCSX2 GSDrawScanline.cpp TestAlpha,
// DobieStation gsthread.cpp draw_pixel, Play! GSH_VulkanDrawUtils.cpp CDrawUtils::AlphaTest agree); on
// failure AFAIL picks what is still written:
//   KEEP     nothing          FB_ONLY  RGB and A, not Z     ZB_ONLY  only Z
//   RGB_ONLY RGB only (not A, not Z). Model option rgb_only_targets: thirty_two_bit_only (default) —
//            other frame formats act as FB_ONLY (PCSX2 GSRegs.h GIFRegTEST::GetAFAIL(FRAME.PSM); PR 9652,
//            tested against a PS2 per ../shared/spec/gs-alu-facts.md, "Alpha test") | all_formats — the
//            alpha (16-bit: the A bit) is kept on every format (Play! CDrawUtils::AlphaTest, DobieStation
//            at 3a23544b). Deciding it by TEX0.PSM (DobieStation at 68dd073e, issue 17) is not modelled:
//            the texture's format has no part in the frame write (GetAFAIL takes FRAME.PSM). Confidence
//            medium: no recording here.
// ATE = 0 or a pass writes everything (Z subject to the depth test, which is not modelled here).
#pragma once

#include <cstdint>

#include "fixed/integer.hpp"
#include "gs_arith/colour.hpp"
#include "gs_arith/frame_write.hpp"
#include "gs_arith/options.hpp"

namespace gs {

enum class atst : std::uint8_t {
  NEVER = 0,
  ALWAYS = 1,
  LESS = 2,
  LEQUAL = 3,
  EQUAL = 4,
  GEQUAL = 5,
  GREATER = 6,
  NOTEQUAL = 7
};
enum class afail : std::uint8_t { KEEP = 0, FB_ONLY = 1, ZB_ONLY = 2, RGB_ONLY = 3 };
enum class ztst : std::uint8_t { NEVER = 0, ALWAYS = 1, GEQUAL = 2, GREATER = 3 };

// TEST_1 / TEST_2. The alpha test uses ATE..AFAIL; the destination-alpha and depth fields are
// decoded for completeness and not modelled.
struct test_reg {
  bool ATE = false;
  atst ATST = atst::NEVER;
  u8 AREF{};
  afail AFAIL = afail::KEEP;
  bool DATE = false;
  bool DATM = false;
  bool ZTE = false;
  ztst ZTST = ztst::NEVER;
  friend constexpr bool operator==(const test_reg&, const test_reg&) = default;
};

struct write_enables {
  bool rgb, a, z;
  friend constexpr bool operator==(const write_enables&, const write_enables&) = default;
};

// "A ATST AREF", e.g. LESS: A < AREF.
constexpr bool alpha_test_passes(atst method, u8 a, u8 aref) noexcept {
  switch (method) {
    case atst::NEVER: return false;
    case atst::ALWAYS: return true;
    case atst::LESS: return a < aref;
    case atst::LEQUAL: return a <= aref;
    case atst::EQUAL: return a == aref;
    case atst::GEQUAL: return a >= aref;
    case atst::GREATER: return a > aref;
    case atst::NOTEQUAL: return a != aref;
  }
  return false;
}

// `o` defaults to the model defaults, so callers without options keep their meaning.
constexpr write_enables alpha_test(const test_reg& t, u8 a, frame_psm psm, const model_options& o = {}) noexcept {
  if (!t.ATE || alpha_test_passes(t.ATST, a, t.AREF)) return {true, true, true};
  switch (t.AFAIL) {
    case afail::KEEP: return {false, false, false};
    case afail::FB_ONLY: return {true, true, false};
    case afail::ZB_ONLY: return {false, false, true};
    case afail::RGB_ONLY:
      if (bits_of(psm) == pixel_bits::b32 || o.rgb_only == rgb_only_targets::all_formats) return {true, false, false};
      return {true, true, false};
  }
  return {true, true, true};
}

}  // namespace gs
