// Section 3.1: "For a single light source, pre-filling the z-buffer (step 1) is not necessary." One
// pixel, the light's first pass over a sequence of fragments: step 1 (GEQUAL, Z written) then the
// pass (GEQUAL, Z read only), against the pass alone testing GEQUAL and writing Z. Every unit is the
// model's (gs::depth_test, gs::pixel_pipeline) with the methods' register sets (gs_methods).
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "gs_arith/pixel_pipeline.hpp"
#include "proofs/claim_util.hpp"
#include "proofs/claims.hpp"
#include "proofs/methods.hpp"

namespace gsdot3::proofs::claims {

namespace m = methods;

namespace {

// The first light pass of each method (pipeline/pass_table.hpp's method descriptions; a test there
// checks this list against them).
struct first_pass {
  const char* methods;
  const gs_methods::pass_regs* regs;
  bool paper;          // a method of seed 000 (the 2002 baseline is the one it improves on)
  const char* figure;  // the figure counting its differing sequences
};
constexpr std::array<first_pass, 4> first_passes{
    {{"two-pass, three-pass", &gs_methods::two_pass_positive, true, "differ_two_pass"},
     {"four-pass", &gs_methods::four_pass_sphere, true, "differ_four_pass"},
     {"gouraud", &gs_methods::gouraud_dot, true, "differ_gouraud"},
     {"baseline (2002)", &gs_methods::baseline_add, false, "differ_baseline"}}};

constexpr int max_fragments = 6;

// Fragment i: texel (and, untextured, vertex colour) 1 << i in R, G, B, so that the DPB tells which
// fragments were drawn (any set of them sums without a carry); the textured passes' colour is 1.0.
gs::pixel_input fragment(const gs_methods::pass_regs& p, int i, std::uint32_t dst) {
  const gs::rgba8 own = m::grey(1 << i, 0x80);
  return {gs::fragment_colour::flat(p.TME ? m::grey(0x80, 0x80) : own), own, dst, 0, 0};
}

struct pixel_state {
  std::uint32_t dpb = gs_methods::clear_dpb, z = 0;  // step 2.1's clear, and Z cleared to 0
};

// The pixel after step 1 and then pass p (prefill), or after p alone writing Z.
pixel_state draw(const gs_methods::pass_regs& p, const std::vector<std::uint32_t>& zs, bool prefill,
                 const gs::model_options& o) {
  const gs::gs_registers regs = p.registers();
  pixel_state s;
  if (prefill)
    for (const std::uint32_t z : zs)
      if (const auto d = gs::depth_test(gs_methods::depth_gequal, gs_methods::z_written, z, s.z); d.write_z) s.z = d.z;
  for (std::size_t i = 0; i < zs.size(); ++i) {
    const auto d =
        gs::depth_test(gs_methods::depth_gequal, prefill ? gs_methods::z_masked : gs_methods::z_written, zs[i], s.z);
    if (!d.pass) continue;
    s.dpb = gs::pixel_pipeline(regs, fragment(p, static_cast<int>(i), s.dpb), o).out;
    if (d.write_z) s.z = d.z;
  }
  return s;
}

}  // namespace

outcome z_prefill_single_light(const gs::model_options& o, const sweep_config&) {
  // Every sequence of k = 1..6 fragments with Z in 0..k − 1: the depth test only compares Z values
  // (GEQUAL, 24-bit values stored exactly), so any k fragments' Z order, ties included, is one of
  // these; against the cleared Z (0) every fragment passes either way.
  std::array<std::uint64_t, first_passes.size()> differ{};
  std::vector<std::string> witnesses;
  std::uint64_t size = 0;
  for (int k = 1; k <= max_fragments; ++k) {
    std::vector<std::uint32_t> zs(static_cast<std::size_t>(k), 0);
    for (bool more = true; more; ++size) {
      for (std::size_t f = 0; f < first_passes.size(); ++f) {
        const pixel_state a = draw(*first_passes[f].regs, zs, true, o), b = draw(*first_passes[f].regs, zs, false, o);
        if (a.dpb == b.dpb && a.z == b.z) continue;
        if (++differ[f] == 1) {
          std::string z;
          for (const auto v : zs) z += (z.empty() ? "" : ", ") + std::to_string(v);
          witnesses.push_back(std::string(first_passes[f].methods) + ": fragments' Z (" + z + ") => DPB " +
                              hexdec(a.dpb, 32) + " with step 1, " + hexdec(b.dpb, 32) + " without");
        }
      }
      more = false;  // the next Z sequence, as a base-k counter
      for (auto& v : zs)
        if (++v < static_cast<std::uint32_t>(k)) {
          more = true;
          break;
        } else {
          v = 0;
        }
    }
  }
  outcome out;
  out.domain_size = size * first_passes.size();
  for (std::size_t f = 0; f < first_passes.size(); ++f) {
    if (first_passes[f].paper) out.counterexamples += differ[f];
    out.figures.push_back(fig(first_passes[f].figure, static_cast<std::int64_t>(differ[f])));
  }
  out.result = out.counterexamples == 0 ? verdict::proven : verdict::refuted;
  out.witnesses = std::move(witnesses);
  out.note =
      "the paper's first light passes replace the DPB word (no blend), so the last of the nearest fragments "
      "wins with or without step 1 and the Z buffer ends the same; the 2002 baseline's first pass adds "
      "Cs + Cd, so without step 1 the hidden fragments drawn before the nearest one add into the DPB";
  return out;
}

}  // namespace gsdot3::proofs::claims
