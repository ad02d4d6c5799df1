// pipeline/frame_program.cpp — the frame's steps (section 3.1), written once; frame_program.hpp says
// who reads them.
#include "pipeline/frame_program.hpp"

#include <optional>
#include <stdexcept>

#include "pipeline/lod.hpp"

namespace gsdot3::pipeline {

namespace {

using namespace passes;
using kind = frame_op::kind;

// Where a spot light's texture is drawn over the DPB (section 3.6): four-pass "after the first pass"
// (render_options::spot_after_first_pass) or "after all four passes are complete" (the default), the
// blend on every channel; every other method after the post filter (step 2.4) on its sum, the red byte
// (spot_attenuation_red: the paper gives four-pass's placements only, so this is the model's choice
// for the others — the same blend on the one byte that holds the dot product).
enum class spot_step : std::uint8_t { after_first_pass, after_light_passes, after_post_filter };
spot_step spot_placement(method m, const render_options& o) {
  if (m != method::four_pass) return spot_step::after_post_filter;
  return o.spot_after_first_pass ? spot_step::after_first_pass : spot_step::after_light_passes;
}

class writer {
 public:
  explicit writer(frame_program& p) : p_(p) {}
  frame_op& add(kind k) {
    frame_op& o = p_.ops.emplace_back();
    o.what = k;
    return o;
  }
  void clip(area_role a, int piece = -1) {
    frame_op& o = add(kind::scissor);
    o.area = a, o.piece = piece;
  }
  void depth(const gs::test_reg& t, const gs::zbuf_reg& z, buffer_role at = buffer_role::z_words) {
    frame_op& o = add(kind::depth);
    o.test = &t, o.zbuf = &z, o.buffer = at;
  }
  void target(buffer_role b, const pass_regs& r) {
    frame_op& o = add(kind::target);
    o.buffer = b, o.regs = &r;
  }
  void texflush() { add(kind::texflush); }
  frame_op& texture(const pass_regs& r, texture_role t, std::optional<clut_slot> clut = std::nullopt) {
    frame_op& o = add(kind::texture);
    o.regs = &r, o.texture = t, o.no_clut = !clut, o.clut = clut.value_or(clut_slot::pos);
    return o;
  }
  void fill(const pass_regs& r, buffer_role b, std::uint32_t colour, area_role a, bool writes_z = false) {
    frame_op& o = add(kind::fill);
    o.regs = &r, o.buffer = b, o.colour = gs::rgba8::from_u32(colour), o.area = a, o.writes_z = writes_z;
  }
  frame_op& draw(kind k, const pass_regs& r, buffer_role b) {
    frame_op& o = add(k);
    o.regs = &r, o.buffer = b;
    return o;
  }
  void channel(const pass_regs& r, gs::rgba8 colour, clut_slot clut, unsigned channel, buffer_role from,
               buffer_role into, bool z_clear = false) {
    frame_op& o = draw(kind::channel, r, into);
    o.colour = colour, o.clut = clut, o.channel = channel, o.source = from, o.z_clear = z_clear;
  }
  void checkpoint(std::string_view label, int light, std::string_view name, buffer_role b) {
    frame_op& o = add(kind::checkpoint);
    o.label = label, o.light = light, o.name = name, o.buffer = b;
  }

 private:
  frame_program& p_;
};

}  // namespace

frame_program build_frame_program(const scene& s, const prepared_scene& ps, method m, const render_options& o,
                                  const gs_inputs& in) {
  if (in.stream && !ps.plain.empty()) throw std::invalid_argument(plain_needs_resident_texture);
  frame_program prog;
  writer w(prog);
  // draw_buffers::one (section 3.1's variant, method.hpp): the output is every light's DPB, then the
  // LAB; the free alphas are those of the buffer at FBP 0, of the Z buffer's words and of the output.
  const bool one = o.buffers == draw_buffers::one;
  const buffer_role DPB = one ? buffer_role::output : buffer_role::dpb;
  const buffer_role LAB = one ? buffer_role::output : buffer_role::lab, OUT = buffer_role::output;
  const buffer_role plane[3] = {buffer_role::dpb, buffer_role::z_words, buffer_role::output};
  const gs::rgba8 ambient = rgb(s.ambient[0], s.ambient[1], s.ambient[2], 0x80);

  // The environment, the uploads; the buffers cleared over the frame (the DPB to 0x00808080, the LAB
  // to 0, the output and the Z buffer to 0 by one sprite).
  w.add(kind::environment);
  w.add(kind::uploads);
  w.depth(depth_always, z_masked);
  w.target(buffer_role::dpb, step1_ambient);
  w.fill(step1_ambient, buffer_role::dpb, clear_dpb, area_role::frame);
  w.target(buffer_role::lab, step1_ambient);
  w.fill(step1_ambient, buffer_role::lab, 0, area_role::frame);
  w.depth(depth_always, z_written);
  w.target(OUT, step1_ambient);
  w.fill(step1_ambient, OUT, 0, area_role::frame, true);

  // Step 1: Z and ambient.
  w.depth(depth_gequal, z_written);
  w.target(LAB, step1_ambient);
  w.draw(kind::ambient, step1_ambient, LAB).colour = ambient;
  w.checkpoint("1 Z and ambient", -1, "LAB", LAB);

  // A triangle pass drawing a texture into b: its TEX0_1 ... and triangles; a streamed texture (stream
  // k of prog.streamed) per piece: its uploads (and TEXFLUSH), SCISSOR_1 = the piece, TEX0_1 with the
  // piece's TBP0 / TBW (the CLUT loaded by the first) and the triangles that reach the piece.
  // Layer `layer` of the normal map (−1: the diffuse texture, every triangle).
  auto textured = [&](const pass_regs& r, buffer_role b, std::optional<clut_slot> clut, texture_role t, std::size_t nm,
                      int layer, const stream_texture& texels, int light, vertex_colour c) {
    auto triangles = [&](int piece, int stream) {
      frame_op& d = w.draw(kind::triangles, r, b);
      d.texture = t, d.normal_map = nm, d.clut = clut.value_or(clut_slot::pos), d.no_clut = !clut;
      d.light = light, d.colour_of = c, d.piece = piece, d.stream = stream, d.layer = layer;
    };
    if (!in.stream) {
      frame_op& tex = w.texture(r, t, clut);
      tex.normal_map = nm, tex.layer = layer;
      w.target(b, r);
      return triangles(-1, -1);
    }
    w.target(b, r);
    const int k = static_cast<int>(prog.streamed.size());
    prog.streamed.push_back(texels);
    bool first = true;
    for (stream_piece& piece : in.stream->next_pass(texels)) {
      const int i = static_cast<int>(prog.pieces.size());
      const bool uploads = !piece.uploads.empty();
      prog.pieces.push_back(std::move(piece));
      frame_op& u = w.add(kind::piece_uploads);
      u.piece = i, u.stream = k;
      if (uploads) w.texflush();
      w.clip(area_role::piece, i);
      frame_op& tex = w.texture(r, texture_role::piece, clut);
      tex.piece = i, tex.stream = k, tex.load = first, tex.layer = layer;
      first = false;
      triangles(i, k);
    }
    w.clip(area_role::frame);
  };
  const stream_texture diffuse_texels = diffuse_stream(in);
  // Step 3: buffer b cleared to zero over the sprite area (clear's FBMSK kept), the diffuse layer drawn.
  auto diffuse_step = [&](buffer_role b, const pass_regs& clear, const pass_regs& layer) {
    w.clip(area_role::sprite_area);
    w.depth(depth_always, z_masked);
    w.target(b, clear);
    w.fill(clear, b, 0, area_role::sprite_area);
    w.clip(area_role::frame);
    w.depth(depth_gequal, z_masked);
    textured(layer, b, std::nullopt, texture_role::diffuse, 0, -1, diffuse_texels, -1, vertex_colour::white);
  };

  for (std::size_t l = 0; l < s.lights.size(); ++l) {
    const int li = static_cast<int>(l);
    // 2.1: the DPB cleared over the sprite area; with the z-trick the previous light's ILP pass cleared it.
    if (l == 0 || o.dpb_clear == dpb_clear_mode::explicit_clear) {
      w.clip(area_role::sprite_area);
      w.depth(depth_always, z_masked);
      w.target(DPB, step1_ambient);
      w.fill(step1_ambient, DPB, clear_dpb, area_role::sprite_area);
    }
    w.clip(area_role::frame);
    w.depth(depth_gequal, z_masked);
    w.checkpoint("2.1 clear 0x00808080", li, "DPB", DPB);
    // 2.3 (and two-pass's 2.4a): the method's light passes (Gouraud's for a Gouraud light, lod.hpp),
    // pass_table.hpp's list in draw order; section 3.6's spot light where spot_placement says.
    const method lm = light_method(m, s.lights[l]);
    const spot_step spot_at = spot_placement(lm, o);
    auto spot_pass = [&](spot_step when) {  // whether it drew
      if (!ps.spot(l) || when != spot_at) return false;
      const bool red = when == spot_step::after_post_filter;
      const pass_regs& regs = red ? spot_attenuation_red : spot_attenuation;
      w.clip(area_role::frame);
      w.depth(depth_gequal, z_masked);
      w.texture(regs, texture_role::spot_map);
      w.target(DPB, regs);
      w.draw(kind::projective, regs, DPB).light = li;
      w.checkpoint(red ? "2.4 spot light: (R − 128)·As + 128 on the sum (projective texture, ST/Q)"
                       : "2.3 spot light: (Cd − 128)·As + 128 (projective texture, ST/Q)",
                   li, "DPB", DPB);
      return true;
    };
    std::size_t drawn = 0;
    for (const light_pass& p : describe(lm).light) {
      if (drawn++ == 1) spot_pass(spot_step::after_first_pass);  // after the first pass, before the second
      const pass_regs& regs = *p.regs;
      switch (p.source) {
        case pass_source::normal_map: {  // per layer (a material's map): its TEX0, CLUT and triangles
          const std::size_t k = normal_map_of(in, p.clut);
          for (std::size_t n = 0; n < ps.layer_count(); ++n)
            textured(regs, DPB, p.clut, texture_role::normal_map, k, static_cast<int>(n),
                     normal_map_stream(in, n, k, ps.layer(n)), li, p.colour);
          break;
        }
        case pass_source::sphere_map: {
          w.texture(regs, texture_role::sphere_map);
          w.target(DPB, regs);
          frame_op& d = w.draw(kind::triangles, regs, DPB);
          d.texture = texture_role::sphere_map, d.no_clut = true, d.light = li, d.colour_of = p.colour;
          break;
        }
        case pass_source::untextured: {  // TME = 0: no TEX0, the UV sent is not read
          w.target(DPB, regs);
          frame_op& d = w.draw(kind::triangles, regs, DPB);
          d.texture = texture_role::none, d.no_clut = true, d.light = li, d.colour_of = p.colour;
          break;
        }
        case pass_source::dpb_alpha: {  // the DPB read as PSMT8H through the palette, 1:1
          w.clip(area_role::sprite_area);
          w.depth(depth_always, z_masked);
          w.texflush();
          w.texture(regs, texture_role::buffer_t8h, p.clut).source = DPB;
          w.target(DPB, regs);
          frame_op& d = w.draw(kind::buffer_sprite, regs, DPB);
          d.texture = texture_role::buffer_t8h, d.source = DPB, d.clut = p.clut;
          break;
        }
      }
      w.checkpoint(p.label, li, "DPB", DPB);
    }
    spot_pass(spot_step::after_light_passes);
    // 2.4: R += G, R += B (mod 256): additive channel-fetch sprites writing red only.
    w.clip(area_role::sprite_area);
    w.depth(depth_always, z_masked);
    w.target(DPB, post_add_into_red);
    for (unsigned c : {1u, 2u}) {
      w.texflush();
      w.channel(post_add_into_red, white, clut_slot::grey, c, DPB, DPB);
      w.checkpoint(c == 1 ? "2.4 R += G" : "2.4 R += B (the post-filter sum)", li, "DPB", DPB);
    }
    if (spot_pass(spot_step::after_post_filter)) {  // the post filter's clip and depth again
      w.clip(area_role::sprite_area);
      w.depth(depth_always, z_masked);
    }
    frame_op& dot = w.add(kind::dot_ready);
    dot.light = li, dot.buffer = DPB;
    w.texflush();
    if (one) {  // the dot layer into free alpha l; 2.6 waits until the output is the LAB
      w.target(plane[l], move_into_alpha);
      w.channel(move_into_alpha, white, clut_slot::alpha_index, 0, DPB, plane[l]);
      w.checkpoint("2.6' dot layer into a free alpha", li, "alpha plane", plane[l]);
      continue;
    }
    // 2.5, 2.6: COLCLAMP = 1; ILP[sum] × light colour (MODULATE) added into the LAB. The z-trick
    // (section 3.4): the same sprites over whole pages with Z = 0x00808080, ZTST = ALWAYS written into
    // the DPB as a PSMZ24 Z buffer, clearing it for the next light.
    const bool z_clear = o.dpb_clear != dpb_clear_mode::explicit_clear;
    if (z_clear) {
      w.clip(area_role::sprite_pages);
      w.depth(depth_always, z_written, DPB);
    }
    const auto& lc = s.lights[l].colour;
    w.target(LAB, ilp_into_lab);
    w.channel(ilp_into_lab, rgb(lc[0], lc[1], lc[2], 0x80), clut_slot::ilp, 0, DPB, LAB, z_clear);
    w.checkpoint("2.6 LAB += ILP[sum] × light colour", li, "LAB", LAB);
  }

  if (one) {  // 2.6 from the free alphas, the LAB's channels into them, 3, and 4 as Cd·As
    w.clip(area_role::sprite_area);
    w.depth(depth_always, z_masked);
    w.target(OUT, flat_rgb);
    w.fill(flat_rgb, OUT, ambient.to_u32(), area_role::sprite_area);
    for (std::size_t l = 0; l < s.lights.size(); ++l) {
      const auto& lc = s.lights[l].colour;
      w.texflush();
      w.target(OUT, ilp_into_lab);
      w.channel(ilp_into_lab, rgb(lc[0], lc[1], lc[2], 0x80), clut_slot::ilp, 3, plane[l], OUT);
    }
    for (unsigned c = 0; c < 3; ++c) {
      w.texflush();
      w.target(plane[c], move_into_alpha);
      w.channel(move_into_alpha, white, clut_slot::alpha_index, c, OUT, plane[c]);
    }
    diffuse_step(OUT, flat_rgb, diffuse_layer_rgb);
    w.depth(depth_always, z_masked);
    w.clip(area_role::sprite_area);
    const pass_regs* multiply[3] = {&multiply_red_by_as, &multiply_green_by_as, &multiply_blue_by_as};
    for (unsigned c = 0; c < 3; ++c) {
      w.texflush();
      w.target(OUT, *multiply[c]);
      w.channel(*multiply[c], white, clut_slot::alpha_index, 3, plane[c], OUT);
    }
    w.checkpoint("2.6, 3, 4 in one buffer (LAB, its channels into the free alphas, diffuse, × the alphas)", -1, "frame",
                 OUT);
  } else {
    // Step 3: the DPB cleared to zero over the sprite area and the unlit diffuse layer drawn into it.
    diffuse_step(buffer_role::diffuse, step1_ambient, diffuse_layer);
    w.checkpoint("3 diffuse layer", -1, "diffuse", buffer_role::diffuse);
    // Step 4: the LAB copied into the output; per channel the LAB byte moved into the output's alpha,
    // then diffuse × alpha, (Cs − 0)·Ad >> 7, into that channel.
    w.depth(depth_always, z_masked);
    w.clip(area_role::sprite_area);
    w.add(kind::copy_lab);
    const pass_regs* multiply[3] = {&multiply_red, &multiply_green, &multiply_blue};
    for (unsigned c = 0; c < 3; ++c) {
      w.texflush();
      w.target(OUT, move_into_alpha);
      w.channel(move_into_alpha, white, clut_slot::alpha_index, c, buffer_role::lab, OUT);
      w.texflush();
      w.texture(*multiply[c], texture_role::buffer_ct32).source = buffer_role::diffuse;
      w.target(OUT, *multiply[c]);
      frame_op& d = w.draw(kind::buffer_sprite, *multiply[c], OUT);
      d.texture = texture_role::buffer_ct32, d.source = buffer_role::diffuse;
    }
    w.checkpoint("4 diffuse × LAB (R, G, B)", -1, "frame", OUT);
  }

  // Step 5 (section 3.1): the non-normal-mapped geometry into the output over the whole frame, Gouraud ×
  // the diffuse texture (resident: plain_needs_resident_texture), Z written.
  if (!ps.plain.empty()) {
    w.clip(area_role::frame);
    w.depth(depth_gequal, z_written);
    w.texture(plain_gouraud, texture_role::diffuse);
    w.target(OUT, plain_gouraud);
    w.draw(kind::plain, plain_gouraud, OUT);
    w.checkpoint("5 non-normal-mapped geometry: Gouraud × diffuse (MODULATE), Z written", -1, "frame", OUT);
  }
  w.add(kind::display).buffer = OUT;
  return prog;
}

}  // namespace gsdot3::pipeline
