// gs_packets/video_mode.hpp: the registers against values assembled by hand from the field values its
// sources give (PCSX2 GSRegs.h's recorded SMODE1 fields; the Linux PS2 driver's SYNCV and DISPLAY
// arithmetic), and PCSX2's GetVideoMode rule (CMOD 2 NTSC, 3 PAL, 0 with LC not 22 / 32 VESA).
#include <gtest/gtest.h>

#include "gs_packets/video_mode.hpp"

namespace {

namespace pk = gs::packets;

TEST(VideoMode, Smode1AsRecorded) {
  // RC 4 | LC 32 << 3 | T1248 1 << 10 | CMOD << 13 | PRST 1 << 16 | SPML 4 << 21 | CLKSEL 1 << 30 |
  // NVCK 1 << 32 | SLCK2 1 << 33 | VCKSEL 1 << 34.
  EXPECT_EQ(pk::encode(pk::smode1_for(pk::video_mode::ntsc)), 0x740814504u);
  EXPECT_EQ(pk::encode(pk::smode1_for(pk::video_mode::pal)), 0x740816504u);
  // RC 2 | LC 15 << 3 | T1248 1 << 10 | PRST 1 << 16 | SPML 2 << 21 | CLKSEL 1 << 30 | NVCK | SLCK2 | VHP 1 << 36.
  EXPECT_EQ(pk::encode(pk::smode1_for(pk::video_mode::vesa)), 0x134041047Au);
  for (const auto m : {pk::video_mode::ntsc, pk::video_mode::pal, pk::video_mode::vesa}) {
    const std::uint64_t s = pk::encode(pk::smode1_for(m));
    const unsigned cmod = (s >> 13) & 3, lc = (s >> 3) & 0x7F;
    EXPECT_EQ(cmod, m == pk::video_mode::ntsc ? 2u : m == pk::video_mode::pal ? 3u : 0u);
    if (m == pk::video_mode::vesa) { EXPECT_TRUE(lc != 22 && lc != 32); }
    // VCK = 13.5 MHz · LC / ((T1248 + 1) · SPML · RC): 27 MHz / 4 = 13.5 MHz per pixel for TV (640 × 4 VCK
    // per line), 25.3125 MHz for VESA.
    const double vck = 13.5e6 * lc / ((((s >> 10) & 3) + 1) * ((s >> 21) & 15) * (s & 7));
    EXPECT_DOUBLE_EQ(vck, m == pk::video_mode::vesa ? 25.3125e6 : 13.5e6);
  }
  EXPECT_EQ(pk::smode2_for(pk::video_mode::ntsc), 1u);  // INT
  EXPECT_EQ(pk::smode2_for(pk::video_mode::vesa), 0u);
}

TEST(VideoMode, SyncvAndDisplay) {
  // VFP | VFPE << 10 | VBP << 20 | VBPE << 32 | VDP << 42 | VS << 53.
  EXPECT_EQ(pk::encode(pk::syncv_for(pk::video_mode::ntsc)), 0xC7800601A01801u);  // 1, 6, 26, 6, 480, 6
  EXPECT_EQ(pk::encode(pk::syncv_for(pk::video_mode::pal)), 0xA9000502101401u);   // 1, 5, 33, 5, 576, 5
  // NTSC 512x448: MAGH 4 (2560 / 512 − 1), DW 2559, DH 447, DX = 254 + 222 + (2892 − 2560)/2 − 1 = 641,
  // DY = 6 + 26 + 6 + (480 − 448)/2 − 1 = 53.
  EXPECT_EQ(pk::display_for(pk::video_mode::ntsc, 512, 448), 0x1BF9FF02035281u);
  // PAL 512x448: DX = 254 + 262 + 166 − 1 = 681, DY = 5 + 33 + 5 + 64 − 1 = 106.
  const std::uint64_t pal = pk::display_for(pk::video_mode::pal, 512, 448);
  EXPECT_EQ(pal & 0xFFF, 681u);
  EXPECT_EQ((pal >> 12) & 0x7FF, 106u);
  // VESA 640x480: MAGH 1, DW 1279, DX = 144 · 2 − 2 = 286, DY = 34.
  const std::uint64_t vesa = pk::display_for(pk::video_mode::vesa, 640, 480);
  EXPECT_EQ((vesa >> 23) & 15, 1u);
  EXPECT_EQ((vesa >> 32) & 0xFFF, 1279u);
  EXPECT_EQ(vesa & 0xFFF, 286u);
  EXPECT_EQ((vesa >> 12) & 0x7FF, 34u);
  EXPECT_EQ(pk::video_mode_named("pal"), pk::video_mode::pal);
  EXPECT_FALSE(pk::video_mode_named("PAL60"));
}

}  // namespace
