// gs_arith/frame_write.hpp — FRAME.PSM, FBA, the 16-bit pack and the FRAME.FBMSK merge.
//
// A frame-buffer word is the raw memory value of one pixel: 32 bits A8B8G8R8 for PSMCT32 and
// PSMCT24 (whose top byte is never written), 16 bits A1B5G5R5 in the low half for PSMCT16/16S
// (bits 16..31 are zero). Evidence (../shared/spec/gs-alu-facts.md, "After the blend"):
// - FBA = 1 sets alpha bit 7 (SW, SH; not 24-bit targets). Confidence: medium, no HW test.
// - 16-bit pack truncates, >> 3 per channel, alpha = bit 7 (SW). Confidence: medium, no HW test.
// - FBMSK: a 1 bit keeps the old frame-buffer bit (GS manual, SW, SH, DB). For 16-bit targets PCSX2
//   SW merges in the 32-bit expanded space before packing, so only FBMSK bits 3..7 of each colour
//   byte and bit 31 matter (GSRendererSW `fm & 0x80f8f8f8`); frame_mask() packs FBMSK the same way.
//   ps2tek (FRAME_1/2) agrees: the mask "is applied before format conversions", bit 63 of FRAME
//   reaching the A bit; DobieStation draw_pixel merges before convert_color_down (matrix row A2).
// - 24-bit target: the blender reads Ad as 0x80 and the alpha byte is never written (SW, comment
//   "tested on a PS2"). 16-bit target: the blender reads the word expanded by << 3 with Ad = 0x80
//   when bit 15 is set, else 0 (SW). Confidence: medium.
#pragma once

#include <cstdint>

#include "fixed/integer.hpp"
#include "gs_arith/colour.hpp"

namespace gs {

// FRAME.PSM values a frame buffer can have (GS manual codes). The Z formats are drawable as colour
// buffers and store pixels like their CT counterparts (only the memory swizzle differs).
enum class frame_psm : std::uint8_t {
  PSMCT32 = 0x00,
  PSMCT24 = 0x01,
  PSMCT16 = 0x02,
  PSMCT16S = 0x0A,
  PSMZ32 = 0x30,
  PSMZ24 = 0x31,
  PSMZ16 = 0x32,
  PSMZ16S = 0x3A,
};

enum class pixel_bits : std::uint8_t { b32, b24, b16 };

constexpr pixel_bits bits_of(frame_psm psm) noexcept {
  switch (psm) {
    case frame_psm::PSMCT32:
    case frame_psm::PSMZ32: return pixel_bits::b32;
    case frame_psm::PSMCT24:
    case frame_psm::PSMZ24: return pixel_bits::b24;
    case frame_psm::PSMCT16:
    case frame_psm::PSMCT16S:
    case frame_psm::PSMZ16:
    case frame_psm::PSMZ16S: return pixel_bits::b16;
  }
  return pixel_bits::b32;
}

// A1B5G5R5 from an 8-bit colour by truncation: each channel >> 3, alpha bit 7 -> bit 15.
constexpr std::uint32_t pack16(rgba8 c) noexcept {
  return static_cast<std::uint32_t>(c.r.value() >> 3) | static_cast<std::uint32_t>(c.g.value() >> 3) << 5 |
         static_cast<std::uint32_t>(c.b.value() >> 3) << 10 | static_cast<std::uint32_t>(c.a.value() >> 7) << 15;
}

// The destination (Cd, Ad) as the blender reads a frame-buffer word.
constexpr rgba8 frame_read(frame_psm psm, std::uint32_t word) noexcept {
  switch (bits_of(psm)) {
    case pixel_bits::b32: return rgba8::from_u32(word);
    case pixel_bits::b24: {
      rgba8 c = rgba8::from_u32(word);
      c.a = u8::literal(0x80);
      return c;
    }
    case pixel_bits::b16: {
      auto five = [&](int shift) { return u8::from_wrapped(((word >> shift) & 0x1Fu) << 3); };
      return {five(0), five(5), five(10), u8::from_wrapped((word >> 15 & 1u) << 7)};
    }
  }
  return rgba8::from_u32(word);
}

// FBA_1.FBA: alpha bit 7 forced to 1 (not for 24-bit targets, which store no alpha).
constexpr rgba8 apply_fba(rgba8 c, bool FBA, frame_psm psm) noexcept {
  if (FBA && bits_of(psm) != pixel_bits::b24) c.a = u8::from_wrapped(c.a.value() | 0x80);
  return c;
}

// The colour as the bits the pixel's memory word would hold (24-bit: top byte 0, 16-bit: pack16).
constexpr std::uint32_t frame_pack(frame_psm psm, rgba8 c) noexcept {
  switch (bits_of(psm)) {
    case pixel_bits::b32: return c.to_u32();
    case pixel_bits::b24: return c.to_u32() & 0x00FFFFFFu;
    case pixel_bits::b16: return pack16(c);
  }
  return c.to_u32();
}

// The keep mask in memory-word bits: FBMSK itself for 32 bits; plus the never-written top byte for
// 24 bits; for 16 bits FBMSK packed like a colour (bits 3..7 of each byte, bit 31), plus bits 16..31.
constexpr std::uint32_t frame_mask(frame_psm psm, std::uint32_t FBMSK) noexcept {
  switch (bits_of(psm)) {
    case pixel_bits::b32: return FBMSK;
    case pixel_bits::b24: return FBMSK | 0xFF000000u;
    case pixel_bits::b16: return pack16(rgba8::from_u32(FBMSK)) | 0xFFFF0000u;
  }
  return FBMSK;
}

// Per bit, a 1 in `keep` keeps the old bit: (new & ~keep) | (old & keep).
constexpr std::uint32_t masked_merge(std::uint32_t fresh, std::uint32_t old, std::uint32_t keep) noexcept {
  return (fresh & ~keep) | (old & keep);
}

// The new frame-buffer word after writing colour `c` (already through COLCLAMP and FBA) over `old`.
constexpr std::uint32_t frame_write(frame_psm psm, rgba8 c, std::uint32_t old, std::uint32_t FBMSK) noexcept {
  return masked_merge(frame_pack(psm, c), old, frame_mask(psm, FBMSK));
}

}  // namespace gs
