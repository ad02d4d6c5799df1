// pipeline/frame_program.hpp — a method's whole frame as one list of GS operations, labelled with the
// paper's steps: the only place where a method's step sequence, the spot light's placement, the
// one-buffer variant, the z-trick clears and step 5 are written (frame_program.cpp). Its consumers:
// - frame_packets.cpp encodes every operation as GIF packets (the register writes and primitives);
// - render.cpp executes the drawing operations on the value and the memory path, per frame band,
//   and keeps the trace and the dot layers where the program marks them;
// - the cost model prices the encoded stream (gs_cost), so it prices this list too.
// Register-state operations (scissor, depth, target, texture, TEXFLUSH, environment, uploads) are the
// packet stream's; the renderer's drawing operations carry what they draw with (register set, buffer,
// texture, area), and the replay tests hold the two readings together (replayed frame = rendered frame).
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "gs_arith/registers.hpp"
#include "pipeline/gs_inputs.hpp"
#include "pipeline/method.hpp"
#include "pipeline/pass_table.hpp"
#include "pipeline/prepare.hpp"
#include "pipeline/scene.hpp"
#include "pipeline/texture_stream.hpp"

namespace gsdot3::pipeline {

// The frame buffers by role; gs_inputs.hpp's buffer_layout gives their FBP: the DPB and the diffuse
// layer (step 3 reuses the DPB's memory) at FBP 0, the LAB, the output, the Z buffer's words read and
// written as PSMCT32 (the one-buffer variant's second free alpha). The value path keeps the diffuse
// layer in a vector of its own and the Z words' stand-in in the LAB's vector (unused with one buffer).
enum class buffer_role : std::uint8_t { dpb, lab, diffuse, output, z_words };
// Whether buffer b is drawn in PSMZ32 (FRAME_1.PSM, and read back in the Z layout: gs::mem::zsigma)
// under DPB clear mode c (method.hpp): the DPB with z_trick, the LAB with z_trick_psmz32.
constexpr bool in_z_layout(buffer_role b, dpb_clear_mode c) noexcept {
  return (b == buffer_role::dpb && c == dpb_clear_mode::z_trick) ||
         (b == buffer_role::lab && c == dpb_clear_mode::z_trick_psmz32);
}
// SCISSOR_1, and the extent of a fill: the frame, the sprite area (the drawn triangles' bounding
// rectangle, band_renderer::drawn_area), the sprite area out to whole pages (gs_inputs.hpp's
// whole_pages: the z-trick's ILP pass clears whole pages), or a streamed texture's piece.
enum class area_role : std::uint8_t { frame, sprite_area, sprite_pages, piece };
// What TEX0_1 / TEX1_1 / CLAMP_1 bind: a normal-map texture, the sphere map, the spot map, the diffuse
// texture, a piece of a streamed one, or a frame buffer read back (PSMT8H: the DPB's alpha; PSMCT32).
// none: an untextured pass (TME = 0).
enum class texture_role : std::uint8_t {
  none,
  normal_map,
  sphere_map,
  spot_map,
  diffuse,
  piece,
  buffer_t8h,
  buffer_ct32
};

struct frame_op {
  enum class kind : std::uint8_t {
    environment,    // PRMODECONT, XYOFFSET_1, SCISSOR_1 = frame, DTHE, PABE, FBA_1
    uploads,        // the textures and palettes (gs_inputs.hpp's add_uploads), TEXFLUSH
    scissor,        // SCISSOR_1 = area (piece: pieces[piece])
    depth,          // TEST_1 = *test, ZBUF_1 = *zbuf at buffer (the Z buffer; the DPB for the z-trick clear)
    target,         // FRAME_1 = buffer, ALPHA_1, COLCLAMP of *regs
    texflush,       // TEXFLUSH before a texture drawn earlier in the frame is read
    texture,        // TEX0_1, TEX1_1, CLAMP_1: texture (+ palette clut unless no_clut; CLD = load)
    piece_uploads,  // the page transfers of pieces[piece] of streamed[stream]
    fill,           // a flat sprite of colour over area into buffer (Z = 0 written when writes_z)
    ambient,        // step 1: every triangle, flat colour, ZTST = GEQUAL, Z written
    triangles,      // a triangle pass into buffer: texture, vertex colour of light (−1: white), piece
    projective,     // section 3.6's spot light of light: ST/Q triangles into buffer
    buffer_sprite,  // one 1:1 sprite over the sprite area reading source as texture into buffer
    channel,        // channel-fetch sprites: byte `channel` of source through clut into buffer
    copy_lab,       // step 4's local -> local copy of the LAB into the output over the sprite area
    plain,          // step 5: the non-normal-mapped geometry, Gouraud × diffuse, Z written
    dot_ready,      // (renderer) light's dot layer is the red byte of buffer
    checkpoint,     // (renderer's trace) after the pass `label` of light into buffer, named `name`
    display,        // the output buffer displayed (DISPFB1)
  };
  kind what = kind::environment;
  const pass_regs* regs = nullptr;
  buffer_role buffer = buffer_role::dpb, source = buffer_role::dpb;
  area_role area = area_role::frame;
  texture_role texture = texture_role::normal_map;
  clut_slot clut = clut_slot::pos;
  bool no_clut = false, load = true, writes_z = false;
  bool z_clear = false;  // the ILP pass also clears the DPB: its sprites' Z is clear_dpb (dpb_clear_mode z_trick*)
  passes::vertex_colour colour_of = passes::vertex_colour::white;
  gs::rgba8 colour{};
  int light = -1, piece = -1, stream = -1;
  unsigned channel = 0;
  std::size_t normal_map = 0;  // texture_role::normal_map: which of normal_map_count(in)
  // texture (normal map) and triangles: the normal map's layer (scene.hpp), its texture and palettes,
  // and its triangles (prepared_scene::layer); −1: a triangle pass over every triangle.
  int layer = -1;
  const gs::test_reg* test = nullptr;
  const gs::zbuf_reg* zbuf = nullptr;
  std::string_view label, name;
};

struct frame_program {
  std::vector<frame_op> ops;
  std::vector<stream_texture> streamed;  // the streamed textures piece_uploads name
  std::vector<stream_piece> pieces;      // the streamed passes' pieces, in drawing order
};

// The frame's operations for scene s prepared as ps, drawn with method m and options o from inputs
// `in` (placed and, with the textures streamed, started: the pieces are taken from in.stream here,
// so a consumer draws them without asking the streamer again). frame_limits.hpp's check comes first.
frame_program build_frame_program(const scene& s, const prepared_scene& ps, method m, const render_options& o,
                                  const gs_inputs& in);

// The register sets each kind of drawing operation takes (a renderer instantiates its pixel loops
// per set): the light passes' and the diffuse layers' for triangles, and so on. A set may be listed
// twice (baseline_add is two passes): it is one instantiation all the same. No address comparison
// here: g++ with -fsanitize=address does not fold one between two objects in a constant expression.
struct regs_list {
  std::array<const pass_regs*, 24> at{};
  std::size_t n = 0;
  constexpr regs_list& add(const pass_regs* r) {
    at[n++] = r;
    return *this;
  }
};
// The light passes' sets of every method, those drawing a sprite (pass_source::dpb_alpha) or not.
constexpr regs_list light_pass_regs(bool sprites) {
  regs_list l;
  for (method m : gs_methods)
    passes::with_method(
        m, [&]<const auto & D>() {
          for (const passes::light_pass& p : D.light)
            if ((p.source == passes::pass_source::dpb_alpha) == sprites) l.add(p.regs);
        });
  return l;
}
namespace program_regs {
using namespace passes;
inline constexpr regs_list fill = regs_list{}.add(&step1_ambient).add(&flat_rgb);
inline constexpr regs_list triangles = light_pass_regs(false).add(&diffuse_layer).add(&diffuse_layer_rgb);
inline constexpr regs_list projective = regs_list{}.add(&spot_attenuation).add(&spot_attenuation_red);
inline constexpr regs_list t8h_sprite = light_pass_regs(true);  // buffer_sprite reading buffer_t8h
inline constexpr regs_list buffer_sprite = regs_list{}.add(&multiply_red).add(&multiply_green).add(&multiply_blue);
inline constexpr regs_list channel = regs_list{}
                                         .add(&post_add_into_red)
                                         .add(&ilp_into_lab)
                                         .add(&move_into_alpha)
                                         .add(&multiply_red_by_as)
                                         .add(&multiply_green_by_as)
                                         .add(&multiply_blue_by_as);
inline constexpr regs_list plain = regs_list{}.add(&plain_gouraud);
}  // namespace program_regs

}  // namespace gsdot3::pipeline
