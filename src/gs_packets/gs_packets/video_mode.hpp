// gs_packets/video_mode.hpp — the privileged registers that set a video mode (SMODE1, SMODE2, SYNCV)
// and the DISPLAY rectangle for a frame, for the modes a dump can ask for: NTSC, PAL (interlaced
// 480i / 576i) and VESA (640x480 at 60 Hz).
//
// Layouts: gs_regs/privileged.hpp's SMODE1, SYNCV and DISPLAY tables (PCSX2 `pcsx2/GS/GSRegs.h`,
// `REG64_(GSReg, SMODE1)` and the others, lays them out the same way). Register offsets in the 8 KiB
// block: the GS manual's map (SMODE1 0x10, SMODE2 0x20, SYNCV 0x60, DISPLAY1 0x80).
//
// Values, two sources read with the search tool:
// - NTSC / PAL SMODE1: the field values GSRegs.h records for PAL and NTSC (CLKSEL 1, CMOD 3 / 2, LC 32,
//   NVCK 1, PRST 1, RC 4, SINT 0, SLCK2 1, SPML 4, T1248 1, VCKSEL 1, the rest 0); Fredrik Noring's Linux
//   PS2 GS driver (`gs_crtc.c`, `vm_to_sp_sdtv`) sets the same fields (it writes PRST / SINT in a reset
//   sequence, ending with both 0: the one difference, which only matters while the PLL locks).
// - SYNCV and DISPLAY's DX / DY for NTSC / PAL: `vm_to_sp_sdtv` (NTSC VS 6, VBP 26, VBPE = VFPE = 6;
//   PAL VS 5, VBP 33, VBPE = VFPE = 5; VFP 1 interlaced; VDP 480 / 576; HS 254, HBP 222 / 262, the line
//   2892 VCK; DX = HS + HBP + (2892 − DW)/2 − 1, DY = VS + VBP + VBPE + (VDP − DH)/2 − 1, interlaced).
// - PCSX2 `GSState::GetVideoMode` reads the mode back: CMOD 2 NTSC, 3 PAL; CMOD 0 is VESA unless LC is
//   22 or 32 (HDTV / 480p). `GSState::isReallyInterlaced` needs SYNCV.VFP bit 0 and CMOD ≠ 0.
// - VESA 640x480 at 60 Hz: `vm_to_sp_vesa`'s structure (CMOD 0, VHP 1, VCKSEL 0, SPML 2, MAGH = SPML − 1,
//   SYNCV from the VESA timing: VS 2, VBP 33, VFP 10, VDP 480; DX = (HSYNC 96 + back porch 48)·SPML − 1 −
//   SPML/2, DY = VS + VBP − 1) with the clock chosen here by its formula VCK = 13.5 MHz·LC / ((T1248 + 1)
//   ·SPML·RC): LC 15, RC 2, T1248 1 gives 25.3125 MHz for VESA's 25.175 (0.55 % high). Confidence: low
//   (computed, not a recorded value); PCSX2 reports it as VESA (LC 15 is neither 22 nor 32).
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string_view>

#include "gs_regs/privileged.hpp"

namespace gs::packets {

enum class video_mode { ntsc, pal, vesa };

constexpr std::string_view name(video_mode m) {
  return m == video_mode::ntsc ? "ntsc" : m == video_mode::pal ? "pal" : "vesa";
}
constexpr std::optional<video_mode> video_mode_named(std::string_view s) {
  for (const video_mode m : {video_mode::ntsc, video_mode::pal, video_mode::vesa})
    if (name(m) == s) return m;
  return std::nullopt;
}

inline constexpr std::uint32_t SMODE1_offset = 0x0010, SMODE2_offset = 0x0020, SYNCV_offset = 0x0060;

struct smode1_reg {
  unsigned RC = 0, LC = 0, T1248 = 0, SLCK = 0, CMOD = 0, EX = 0, PRST = 0, SINT = 0, XPCK = 0, PCK2 = 0, SPML = 0,
           GCONT = 0, PHS = 0, PVS = 0, PEHS = 0, PEVS = 0, CLKSEL = 0, NVCK = 0, SLCK2 = 0, VCKSEL = 0, VHP = 0;
};
constexpr std::uint64_t encode(const smode1_reg& r) {
  namespace S = gs::regs::SMODE1;
  using gs::regs::encode;
  return encode(S::RC, r.RC) | encode(S::LC, r.LC) | encode(S::T1248, r.T1248) | encode(S::SLCK, r.SLCK) |
         encode(S::CMOD, r.CMOD) | encode(S::EX, r.EX) | encode(S::PRST, r.PRST) | encode(S::SINT, r.SINT) |
         encode(S::XPCK, r.XPCK) | encode(S::PCK2, r.PCK2) | encode(S::SPML, r.SPML) | encode(S::GCONT, r.GCONT) |
         encode(S::PHS, r.PHS) | encode(S::PVS, r.PVS) | encode(S::PEHS, r.PEHS) | encode(S::PEVS, r.PEVS) |
         encode(S::CLKSEL, r.CLKSEL) | encode(S::NVCK, r.NVCK) | encode(S::SLCK2, r.SLCK2) |
         encode(S::VCKSEL, r.VCKSEL) | encode(S::VHP, r.VHP);
}

struct syncv_reg {
  unsigned VFP = 0, VFPE = 0, VBP = 0, VBPE = 0, VDP = 0, VS = 0;
};
constexpr std::uint64_t encode(const syncv_reg& r) {
  namespace S = gs::regs::SYNCV;
  using gs::regs::encode;
  return encode(S::VFP, r.VFP) | encode(S::VFPE, r.VFPE) | encode(S::VBP, r.VBP) | encode(S::VBPE, r.VBPE) |
         encode(S::VDP, r.VDP) | encode(S::VS, r.VS);
}

constexpr smode1_reg smode1_for(video_mode m) {
  if (m == video_mode::vesa)
    return {
        .RC = 2, .LC = 15, .T1248 = 1, .PRST = 1, .SPML = 2, .CLKSEL = 1, .NVCK = 1, .SLCK2 = 1, .VCKSEL = 0, .VHP = 1};
  return {.RC = 4,
          .LC = 32,
          .T1248 = 1,
          .CMOD = m == video_mode::pal ? 3u : 2u,
          .PRST = 1,
          .SPML = 4,
          .CLKSEL = 1,
          .NVCK = 1,
          .SLCK2 = 1,
          .VCKSEL = 1};
}
// SMODE2: INT = 1 for the interlaced TV modes (FFMD = 0, field mode), 0 for VESA.
constexpr std::uint64_t smode2_for(video_mode m) { return m == video_mode::vesa ? 0u : 1u; }
constexpr syncv_reg syncv_for(video_mode m) {
  switch (m) {
    case video_mode::ntsc: return {.VFP = 1, .VFPE = 6, .VBP = 26, .VBPE = 6, .VDP = 480, .VS = 6};
    case video_mode::pal: return {.VFP = 1, .VFPE = 5, .VBP = 33, .VBPE = 5, .VDP = 576, .VS = 5};
    case video_mode::vesa: break;
  }
  return {.VFP = 10, .VFPE = 0, .VBP = 33, .VBPE = 0, .VDP = 480, .VS = 2};
}

// DISPLAY1 for a width × height frame: MAGH the largest (≤ 15) that keeps DW + 1 within the mode's
// active width in VCK (TV: 640 × 4 = 2560, VESA: 640 × SPML 2 = 1280), DH + 1 = height, DX / DY
// centring the rectangle as the Linux driver does (DX, DY clamped at 0 for frames larger than the mode).
constexpr std::uint64_t display_for(video_mode m, int width, int height) {
  const int active = m == video_mode::vesa ? 1280 : 2560;
  const int magh = std::clamp(active / width - 1, 0, 15);
  const int dw = width * (magh + 1);
  int dx = 0, dy = 0;
  if (m == video_mode::vesa) {
    dx = (96 + 48) * 2 - 1 - 1;
    dy = 2 + 33 - 1;
  } else {
    const bool pal = m == video_mode::pal;
    const syncv_reg v = syncv_for(m);
    dx = 254 + (pal ? 262 : 222) + std::max(0, 2892 - dw) / 2 - 1;
    dy = static_cast<int>(v.VS + v.VBP + v.VBPE) + std::max(0, static_cast<int>(v.VDP) - height) / 2 - 1;
  }
  namespace D = gs::regs::DISPLAY;
  auto put = [](gs::regs::field f, int v) { return gs::regs::encode(f, static_cast<std::uint64_t>(v)); };
  return put(D::DX, dx) | put(D::DY, dy) | put(D::MAGH, magh) | put(D::DW, dw - 1) | put(D::DH, height - 1);
}

}  // namespace gs::packets
