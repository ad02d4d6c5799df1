// gs_cost/constants.hpp — the GS timing figures the cost model is built on, each with its source and a
// confidence, and the model options for what no source states (docs/cost.md has the same table; the
// sources are public pages and one console measurement, read with the search tool; nothing copied).
//
// Sources (short names used below):
//   Sony spec   Sony's published GS figures as web pages transcribe them: clock 147.456 MHz, 16 pixel
//               engines, 2.4 Gpixel/s, eDRAM bus 2560 bits = 1024 read + 1024 write + 512 texture, 48 GB/s;
//               "75 million polygons per second" (e-scapegames.co.uk/playstation2.htm, oocities
//               egothesite playstationspecs.html, the-uncensored-wiki "Graphics Synthesizer").
//   psdevwiki   psdevwiki.com/ps2 "Graphics Synthesizer": "16 pixels per clock with untextured 2400
//               Mpixels; or 8 pixels per clock with 1200 megapixels with bilinear texturing".
//   jbit        jbit.net "PS2 Graphics Synthesizer Fill Performance" (a PS2Dev forum post): the GS
//               rasterises 8x2 pixels per clock, 4x2 when texturing, left to right then top to bottom,
//               one frame-buffer page (64x32 at 32 bpp) at a time, a "page break" when it changes page.
//   RenderWare  RenderWare 3.5 PS2 reference "PlayStation 2 fill-rate considerations" (aap.papnet.eu
//               rwref_35_sky2 group__sky2fillrate): frame pages are shared by frame and Z buffer; large
//               textures cause page breaks per span between texture pages.
//   clearbench  F0bes/clearbench (GitHub) ps2_results.txt, measured on a SCPH-39001 with main.cpp's
//               GS FINISH wait, in EE cycles (COP0 Count, 294.912 MHz = 2 GS cycles): 640x448 PSMCT32
//               sprite with a PSMZ32 Z write 79945 (BigSprite), the same as 140 page-aligned 64x32
//               sprites 40496 (Page Clear), as 3 sprites of FBW 1 40567 (VIS Clear), with FBP = ZBP
//               18399 / 18514 for half the pixels (Interleaved / VIS interleaved), 640x224 with Z in
//               the other half 39199 (Double Half Clear).
//   tecchannel  tecchannel.de "Die Technik der PlayStation2": the GIF -> GS bus is 64 bits wide at
//               150 MHz, 1.2 GB/s; the PS2 Linux kit handbook: "1.2GB/s of bandwidth to main RAM".
#pragma once

#include <cstdint>

namespace gs::cost {

// The GS clock (Sony spec; confidence high: every source gives 147.456 MHz, the PCRTC's 2 × 73.728).
inline constexpr double gs_clock_hz = 147'456'000.0;

// Pixels per cycle: 16 untextured, 8 textured, bilinear included (Sony spec 2.4 Gpixel/s = 16 × 147.456 MHz;
// psdevwiki; confidence high for the peak, a peak only).
inline constexpr std::uint32_t pixels_per_cycle_untextured = 16;
inline constexpr std::uint32_t pixels_per_cycle_textured = 8;
// The block the pipeline walks per cycle (jbit; confidence medium: one source, consistent with the above).
inline constexpr std::uint32_t block_width_untextured = 8, block_width_textured = 4, block_height = 2;
static_assert(block_width_untextured * block_height == pixels_per_cycle_untextured);
static_assert(block_width_textured * block_height == pixels_per_cycle_textured);

// Alpha blending (a destination read) and Z read / write at the full rate: 16 pixels × (32-bit colour +
// 32-bit Z) = 1024 bits, exactly the read bus and the write bus of the Sony spec; clearbench's
// Interleaved Clear writes colour and Z of 143 360 pixels in 9 200 GS cycles, 97 % of 16 per cycle
// (confidence medium: the bus argument for blending, a measurement for the Z write). PSMCT16 runs at the
// same rate; it differs in its page (64x64 pixels), which the page walk takes from gs_memory.
inline constexpr std::uint32_t blend_rate_divisor_sourced = 1;

// Primitive set-up: 75 million polygons per second (Sony spec) at 147.456 MHz = 1.97 cycles per
// triangle (confidence medium: a headline peak, no console measurement found).
inline constexpr std::uint32_t triangle_setup_cycles = 2;

// Host -> local bandwidth over the GIF: 64 bits per GS cycle (tecchannel: 64 bits at 150 MHz = 1.2 GB/s;
// the PS2 Linux handbook's 1.2 GB/s; confidence medium for the peak; no measured PATH3 rate found).
inline constexpr std::uint32_t gif_bytes_per_cycle = 8;

// The texture bus: 512 bits = 64 bytes per cycle (Sony spec: 9.6 GB/s texture buffer bandwidth at
// 150 MHz; confidence medium). Used for the CLUT load's transfer time.
inline constexpr std::uint32_t texture_bus_bytes_per_cycle = 64;

// NTSC and PAL field rates (the frame budgets; confidence high, broadcast standards).
inline constexpr double ntsc_hz = 59.94, pal_hz = 50.0;

// How pixel cycles are counted. blocks: one cycle per 8x2 (4x2 textured) block the primitive touches,
// blocks aligned to multiples of the block size (jbit's walk: the default); pixels: pixels / rate,
// rounded up per primitive (the headline rate, a lower bound).
enum class pixel_walk { blocks, pixels };

// What a texture miss is: the walk's texel leaving the 8 KiB page (page, RenderWare's "page breaks
// between texture pages": the default) or the 2 KiB quarter page the paper's texture buffer holds
// (quarter_page; gs_arith options.hpp texture_buffer).
enum class texture_unit { page, quarter_page };

// Every timing no source states, as a named option with its default (docs/cost.md: why each default).
struct cost_options {
  pixel_walk walk = pixel_walk::blocks;
  // Cycles per change of the (frame page, Z page) pair the walk works in. Fitted to clearbench's
  // BigSprite: (39 972 - 286 720 / 16) / 2 240 page changes = 9.8; the other clearbench cases then come
  // within 12 % (docs/cost.md). jbit: "dozens to hundreds of cycles" (not measured there).
  std::uint32_t page_break_cycles = 10;
  // Cycles per texture miss (texture_unit): no source measures it; the frame page break's cost.
  std::uint32_t texture_miss_cycles = 10;
  texture_unit texture_miss_unit = texture_unit::page;
  // Sprite set-up: no source; clearbench's Interleaved Clear leaves at most 1.7 cycles per 32x32
  // sprite beyond its pixels, page changes included.
  std::uint32_t sprite_setup_cycles = 1;
  // A CLUT load: one page break plus the palette over the texture bus (entries × 4 bytes / 64 per
  // cycle, rounded up); no source times it.
  std::uint32_t clut_load_extra_cycles = 10;
  // Divides the pixel rate of primitives whose blend reads the destination (ABE with Cd in A, B or D):
  // 1 (full rate) is the sourced figure above; 2 is the what-if of a read-modify-write at half rate.
  std::uint32_t blend_rate_divisor = blend_rate_divisor_sourced;
};

}  // namespace gs::cost
