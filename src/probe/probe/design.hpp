// probe/design.hpp — the option probe: a grid of 8×8 patches in one displayed 640×448 PSMCT32 frame,
// each drawn by a few register writes and one or more primitives so that the values of one model
// option (gs_arith/options.hpp) give different pixel values (docs/dumps.md "The option probe", docs/evidence.md
// P1..P11).
//
// The design is a list of draws (register state + primitive) in GS order and a list of patches (the
// cells the decoder reads). Both consumers read this one list: probe/frame.hpp computes the frame the
// model predicts under any options, probe/packets.hpp encodes the same draws as GIF packets.
// Design rules that keep the prediction independent of rasteriser details the model does not settle:
//   - every textured primitive has one UV for all its vertices, so every pixel samples the same
//     texel footprint (no dependence on how the GS interpolates UV or where it samples in a pixel),
//     except the one that probes UV interpolation (uv_convert.below_texel): it assumes the sample point
//     at the pixel's integer coordinates (docs/evidence.md R13's sources) and exact U within 1/128 of a
//     sixteenth, and a GS that samples elsewhere shows "none matches" there;
//   - patches are uniform over their sampled pixels (the inner 6×6 of the cell) except the Gouraud
//     ramp, whose per-pixel values give the same verdict for any sample position within ±1/2 pixel,
//     and uv_convert.below_texel, uniform along each column;
//   - 16-bit patches are drawn into a PSMCT16 buffer laid over one page of the displayed frame: a
//     PSMCT16 block (16×8 pixels) occupies the same 256 bytes as a PSMCT32 block (8×8; gs_memory's
//     layout), so a uniform 16-bit value v shows as the 32-bit pixel v | v << 16, i.e. R = B = v & 0xFF,
//     G = v >> 8: the whole 16-bit word, A bit included, is visible in RGB.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gs_arith/registers.hpp"

namespace gsdot3::probe {

inline constexpr int frame_width = 640, frame_height = 448;
inline constexpr unsigned frame_fbw = 10;  // FRAME / DISPFB FBW: 640 / 64; FBP 0, PSMCT32
inline constexpr int cell = 8;             // patch side in pixels
inline constexpr int sample_inset = 1;     // the decoder reads the cell's inner (8 − 2)² pixels

// The 16×16 PSMCT32 texture every textured patch but the §3.4 ones reads, uploaded first (IMAGE).
inline constexpr unsigned texture_page = 140;  // just after the frame's 140 pages (640×448×4 bytes)
inline constexpr int texture_side = 16;

struct vertex {
  int x = 0, y = 0;        // window pixel (XYZ2 = x << 4, y << 4; XYOFFSET_1 = 0)
  std::uint32_t rgba = 0;  // RGBAQ, A8B8G8R8
  int u16 = 0, v16 = 0;    // UV in 12.4 texel units (FST = 1)
};

struct rect {
  int x0 = 0, y0 = 0, x1 = frame_width - 1, y1 = frame_height - 1;  // SCISSOR_1, inclusive
  friend bool operator==(const rect&, const rect&) = default;
};

// One primitive with the register state it is drawn under.
struct draw {
  gs::gs_registers regs;  // PRIM (type, IIP, TME, ABE, FST), TEX0_1, ALPHA_1, TEST_1, FRAME_1, COLCLAMP, ..., DIMX
  bool linear = false;    // TEX1_1 MMAG = MMIN = LINEAR (else NEAREST)
  rect scissor;
  bool texflush = false;  // TEXFLUSH before this draw: the texture buffer starts empty
  std::vector<vertex> v;  // SPRITE: 2, TRIANGLE: 3
};

// A cell the decoder reads. `option` is the gs::option_catalogue() name it settles, or empty for a
// check of a behaviour the model fixes (no option): then only the model's own value is expected.
struct patch {
  std::string name;  // "dither_decode.e4"
  std::string option;
  std::string check;  // for a check: the behaviour's name ("colclamp_wrap"); else empty
  int x = 0, y = 0;   // the cell's top-left pixel in the displayed frame
  std::string what;   // how it is drawn, one line (the legend)
};

// An option no patch can tell apart, with the reason.
struct unprobed {
  std::string option;
  std::string reason;
};

struct design {
  std::vector<std::uint32_t> texture;  // texture_side² texels, row-major (A8B8G8R8)
  std::vector<draw> draws;
  std::vector<patch> patches;
  std::vector<unprobed> not_probed;
};

const design& probe_design();

// The sampled pixels of a patch, row by row: (x, y) in the displayed frame.
std::vector<std::pair<int, int>> sample_pixels(const patch& p);

}  // namespace gsdot3::probe
