// pipeline/method.hpp — the words every layer of the pipeline shares: the GS methods, the render
// options, a rendered frame and a traced pass. Low on purpose: the pass table, the GS inputs, the
// band renderer, the packet stream and the report include this, not render.hpp (which only adds
// render()). What each method's passes are is pass_table.hpp's.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gs_arith/options.hpp"

namespace gsdot3::pipeline {

// two_pass, four_pass: sections 3.5, 3.6; three_pass: section 3.5's alternative (its n_a terms in a third,
// additive pass instead of the DPB alpha); baseline: section 2 (Breugelmans 2002); gouraud: traditional
// per-vertex lighting without the normal map (section 4, figure 6b).
enum class method { two_pass, four_pass, baseline, three_pass, gouraud };
std::string_view name(method m);
// Every GS method, in the order the report lists them.
inline constexpr method gs_methods[] = {method::two_pass, method::four_pass, method::baseline, method::three_pass,
                                        method::gouraud};
// The GS method of that name, or nothing; and every name, comma-separated ("two-pass, four-pass, ...").
std::optional<method> find_method(std::string_view name);
std::string method_names();

// reference: every pass rasterises every triangle again with ZTST = GEQUAL, as the GS does.
// cached: the fragments passing GEQUAL after step 1 are recorded once (in draw order) and every
// later pass replays them; identical by construction since no later pass writes Z (tests check it).
enum class raster_path { reference, cached };

// One pass of a traced render (render_options::trace), frame-sized: `word` is the target buffer after
// the pass; for the pixels the pass shaded, the texel and the fragment colour (r, g, b, a in 8.7)
// that went into gs::pixel_pipeline (`shaded` = 1). The inspector of the report page shows them.
struct pass_record {
  std::string label;   // the paper's step and what it does, e.g. "2.3 Max(n,0)·l (MODULATE)"
  int light = -1;      // the light of a step-2 pass, −1 for steps 1, 3, 4
  std::string target;  // "DPB", "LAB", "diffuse", "frame"
  std::vector<std::uint32_t> word, texel;
  std::vector<std::uint16_t> colour;  // 4 per pixel
  std::vector<std::uint8_t> shaded;
};
// Step 2.1's DPB clear (section 3.4; memory path only, which the z-trick modes imply): an explicit
// fill per light, or the Z-buffer clear during each light's ILP pass (ZBUF = the DPB in PSMZ24,
// Z = 0x00808080, ZTST always) — z_trick: the DPB rendered in PSMZ32 and the post-filter / ILP sprites
// drawn in the Z layout, so the LAB stays PSMCT32; z_trick_psmz32: the sprites at their own XYZ and
// the LAB in PSMZ32 throughout (read back as PSMZ32 at step 4). The z-trick modes render on one
// thread (the texture page buffer model, gs::texture_buffer, follows the draw order).
enum class dpb_clear_mode { explicit_clear, z_trick, z_trick_psmz32 };
std::string_view name(dpb_clear_mode m);
// Section 3.1's draw buffers. two: the DPB and the LAB beside the output (steps 1-4). one: the
// variant "if there is not enough VRAM for two draw buffers": at most 3 lights, the output buffer is
// each light's DPB, then the LAB, then the diffuse layer; each light's dot layer waits in a free alpha
// (render.cpp's alpha planes: the other display buffer's, the Z buffer's unused top byte, the output's
// own), then the LAB's R, G and B wait there while the diffuse layer is drawn, and step 4 multiplies
// by them. The frame equals the two-buffer frame bit for bit (tests/pipeline; alpha-layer.round-trip
// settles the moves).
enum class draw_buffers { two, one };
inline constexpr std::size_t max_free_alpha_lights = 3;

struct render_options {
  int s = 122;                  // two-pass tolight scale (section 3.5), 1..127
  bool bilinear = false;        // TEX1.MMAG for the normal map and the diffuse texture
  bool specular = false;        // half vectors instead of tolight vectors (section 3.7)
  double specular_power = 1.0;  // ILP exponent (section 3.7); 1 = diffuse
  gs::model_options model{};
  raster_path path = raster_path::cached;
  int threads = 2;                            // horizontal bands rendered in parallel
  std::vector<pass_record>* trace = nullptr;  // non-null: every pass appended here (one band, slower)
  bool memory_path = false;                   // frame buffers in the modelled GS local memory (render.cpp)
  dpb_clear_mode dpb_clear = dpb_clear_mode::explicit_clear;
  bool simd = true;  // the SIMD pixel pipeline (gs_simd); false: gs::pixel_pipeline per pixel
  // With simd, the value path's triangle passes through the span engine (gs_simd/span_draw.hpp) where
  // it applies; false: every pixel through the attribute walker and span_batch (tests compare both).
  bool span_engine = true;
  draw_buffers buffers = draw_buffers::two;
  // Section 3.6's spot light in four-pass: its texture over the DPB after the first (sphere-map) pass
  // instead of after all four (pass_table.hpp's spot_step).
  bool spot_after_first_pass = false;
};

struct frame {
  int width = 0, height = 0;
  std::vector<std::uint32_t> colour;           // the lit frame after step 4 (A8B8G8R8)
  std::vector<std::vector<std::uint8_t>> dot;  // per light: the DPB byte after the post filter
                                               // (dot product + 128, mod 256)
  std::vector<std::int32_t> visible_triangle;  // per pixel: index into prepared_scene::triangles, −1 = none
                                               // (or step 5's geometry drawn over it)
  std::vector<std::int32_t> plain_triangle;    // per pixel: index into prepared_scene::plain (step 5), −1 = none
  std::size_t pixel_ops = 0;                   // pixels sent through gs::pixel_pipeline
};

// The signed dot product (1/128 units) a DPB byte stands for: (v − 128) as a signed byte.
constexpr int dot_value(std::uint8_t v) noexcept {
  return static_cast<std::int8_t>(static_cast<std::uint8_t>(v - 128));
}

}  // namespace gsdot3::pipeline
