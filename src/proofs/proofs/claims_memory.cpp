// Section 3.4: clearing the DPB with the Z buffer during the ILP pass (proofs/dpb_clear.hpp models
// the pass over one DPB page through gs_memory). The ILP pass of one page is independent of every
// other page (its sprites, texture page and Z writes stay inside the page: TBP0, FRAME and ZBUF are
// set per page), so one page is the whole domain of pixel positions; the DPB contents are a pattern
// whose R bytes are never 0x80, so an overwritten texel is always seen.
#include <cstdio>
#include <string>

#include "proofs/claim_util.hpp"
#include "proofs/claims.hpp"
#include "proofs/dpb_clear.hpp"
#include "proofs/sweep.hpp"

namespace gsdot3::proofs::claims {
namespace {

namespace mem = gs::mem;

constexpr dpb_clear tricks[] = {dpb_clear::z_trick, dpb_clear::z_trick_psmz32};
constexpr mem::psm zbufs[] = {mem::psm::PSMZ24, mem::psm::PSMZ32};

std::string hex32(std::uint32_t v) {
  char b[16];
  std::snprintf(b, sizeof b, "0x%08x", v);
  return b;
}
std::string pixel(int p) {
  char b[24];
  std::snprintf(b, sizeof b, "(%d, %d)", p % 64, p / 64);
  return b;
}
const char* zname(mem::psm z) { return z == mem::psm::PSMZ24 ? "PSMZ24" : "PSMZ32"; }

// The DPB going into step 2.6: R never 0x80, G and B anything, alpha as given.
page_words dpb_pattern(std::uint32_t alpha) {
  page_words w{};
  for (int p = 0; p < page_pixels; ++p) {
    const auto u = static_cast<std::uint32_t>(p);
    w[static_cast<std::size_t>(p)] =
        alpha << 24 | ((u * 97 + 3) & 0xFFu) << 16 | ((u * 53 + 5) & 0xFFu) << 8 | ((u * 37 + 11) & 0x7Fu);
  }
  return w;
}

// Which DPB pixel, and which fetched byte, a LAB word records (dpb_clear.hpp).
int lab_source(std::uint32_t w) { return static_cast<int>(w >> 8) - 1; }

}  // namespace

// (a) After the pass every DPB pixel is 0x00808080.
outcome dpb_clear_value(const gs::model_options& o, const sweep_config& cfg) {
  constexpr std::uint64_t runs = 2 * 2 * 256;
  auto at = [](std::uint64_t i) {
    return std::tuple{tricks[i / 512], zbufs[(i / 256) % 2], static_cast<std::uint32_t>(i % 256)};
  };
  struct acc {
    tally t;
    std::uint64_t psmz32 = 0, psmz24_alpha0 = 0;  // counterexamples in these parts of the domain
    void merge(const acc& later) {
      t.merge(later.t);
      psmz32 += later.psmz32;
      psmz24_alpha0 += later.psmz24_alpha0;
    }
  };
  const acc a = sweep<acc>(runs, cfg, [&](acc& x, std::uint64_t b, std::uint64_t e) {
    for (std::uint64_t i = b; i < e; ++i) {
      const auto [v, z, alpha] = at(i);
      const ilp_pass r = run_ilp_pass(dpb_pattern(alpha), v, z, o.tex_buffer);
      for (int p = 0; p < page_pixels; ++p)
        if (r.dpb_after[static_cast<std::size_t>(p)] != 0x00808080u) {
          x.t.add(i * page_pixels + static_cast<std::uint64_t>(p));
          if (z == mem::psm::PSMZ32) ++x.psmz32;
          if (z == mem::psm::PSMZ24 && alpha == 0) ++x.psmz24_alpha0;
        }
    }
  });
  const tally& bad = a.t;
  outcome out = verdict_of(bad, runs * page_pixels, [&](std::uint64_t k) {
    const auto [v, z, alpha] = at(k / page_pixels);
    const int p = static_cast<int>(k % page_pixels);
    const ilp_pass r = run_ilp_pass(dpb_pattern(alpha), v, z, o.tex_buffer);
    return std::string(name(v)) + ", ZBUF " + zname(z) + ", DPB alpha 0x" + hex32(alpha).substr(8) +
           " before 2.6, pixel " + pixel(p) + " => " + hex32(r.dpb_after[static_cast<std::size_t>(p)]) +
           ", expected 0x00808080";
  });
  out.figures = {fig("counterexamples_psmz32", static_cast<std::int64_t>(a.psmz32)),
                 fig("counterexamples_psmz24_alpha_0", static_cast<std::int64_t>(a.psmz24_alpha0))};
  out.note =
      "PSMZ32 clears the whole word; PSMZ24 writes only bits 0-23, so the DPB ends 0x00808080 only where its "
      "alpha was already 0 (four-pass leaves alpha 0; two-pass's first pass writes alpha, and each light's "
      "first pass rewrites it on every pixel it covers)";
  return out;
}

// (b) Every texel the ILP pass reads has the value it had before the pass.
outcome dpb_clear_read_before_write(const gs::model_options& o, const sweep_config&) {
  tally bad;
  std::int64_t per_variant[2] = {0, 0};
  const page_words before = dpb_pattern(0);
  for (int vi = 0; vi < 2; ++vi)
    for (int zi = 0; zi < 2; ++zi) {
      const ilp_pass r = run_ilp_pass(before, tricks[vi], zbufs[zi], o.tex_buffer);
      for (int p = 0; p < page_pixels; ++p)
        if (r.fetched[static_cast<std::size_t>(p)] != (before[static_cast<std::size_t>(p)] & 0xFFu)) {
          bad.add(static_cast<std::uint64_t>((vi * 2 + zi) * page_pixels + p));
          ++per_variant[vi];
        }
    }
  outcome out = verdict_of(bad, 4 * page_pixels, [&](std::uint64_t k) {
    const int run = static_cast<int>(k / page_pixels), p = static_cast<int>(k % page_pixels);
    const ilp_pass r = run_ilp_pass(before, tricks[run / 2], zbufs[run % 2], o.tex_buffer);
    return std::string(name(tricks[run / 2])) + ", ZBUF " + zname(zbufs[run % 2]) + ", texture_buffer " +
           std::string(gs::option_value(o, "texture_buffer")) + ", DPB pixel " + pixel(p) +
           ": ILP read R = " + std::to_string(r.fetched[static_cast<std::size_t>(p)]) + ", expected " +
           std::to_string(before[static_cast<std::size_t>(p)] & 0xFFu) + " (overwritten by the Z clear first)";
  });
  out.figures = {fig("counterexamples_z_trick", per_variant[0]), fig("counterexamples_z_trick_psmz32", per_variant[1])};
  out.note =
      "z-trick draws each fragment where its Z write lands on the very pixel it has just read, so no buffering "
      "is needed; z-trick-psmz32's Z writes land on the diagonally opposite 32x16 quarter, which is read "
      "later, so it works only if the texture buffer holds that quarter already (page, draw_snapshot). The "
      "post filter (2.4) runs before 2.6 and is not affected";
  return out;
}

// (c) The two variants leave the same LAB.
outcome dpb_clear_variants_agree(const gs::model_options& o, const sweep_config&) {
  tally bad;
  const page_words before = dpb_pattern(0);
  for (int zi = 0; zi < 2; ++zi) {
    const ilp_pass a = run_ilp_pass(before, dpb_clear::z_trick, zbufs[zi], o.tex_buffer);
    const ilp_pass b = run_ilp_pass(before, dpb_clear::z_trick_psmz32, zbufs[zi], o.tex_buffer);
    for (int p = 0; p < page_pixels; ++p)
      if (a.lab[static_cast<std::size_t>(p)] != b.lab[static_cast<std::size_t>(p)])
        bad.add(static_cast<std::uint64_t>(zi * page_pixels + p));
  }
  outcome out = verdict_of(bad, 2 * page_pixels, [&](std::uint64_t k) {
    const int zi = static_cast<int>(k / page_pixels), p = static_cast<int>(k % page_pixels);
    const ilp_pass a = run_ilp_pass(before, dpb_clear::z_trick, zbufs[zi], o.tex_buffer);
    const ilp_pass b = run_ilp_pass(before, dpb_clear::z_trick_psmz32, zbufs[zi], o.tex_buffer);
    auto what = [](std::uint32_t w) {
      std::string t = "R ";
      t += std::to_string(w & 0xFFu);
      t += " of DPB pixel ";
      t += pixel(lab_source(w));
      return t;
    };
    return std::string("ZBUF ") + zname(zbufs[zi]) + ", LAB pixel " + pixel(p) + ": z-trick adds " +
           what(a.lab[static_cast<std::size_t>(p)]) + ", z-trick-psmz32 adds " +
           what(b.lab[static_cast<std::size_t>(p)]);
  });
  out.note =
      "both variants put DPB pixel P's contribution at the same LAB word (PSMCT32 pixel zsigma(P)); they differ "
      "where z-trick-psmz32 read an already cleared texel";
  return out;
}

// (d) The LAB comes out in PSMZ32 layout; rendering the signed multiplications in PSMZ32 (the DPB
// holding pixel P's value at PSMZ32 pixel P) brings it back to PSMCT32, as does reading the LAB as
// PSMZ32 (the unswizzle pass).
outcome dpb_clear_lab_layout(const gs::model_options& o, const sweep_config&) {
  tally bad;
  std::int64_t per_variant[2] = {0, 0};
  const page_words before = dpb_pattern(0);
  page_words in_z{};  // the DPB rendered in PSMZ32: pixel P's value in the word of PSMZ32 pixel P
  for (int p = 0; p < page_pixels; ++p) in_z[static_cast<std::size_t>(zsigma(p))] = before[static_cast<std::size_t>(p)];
  for (int vi = 0; vi < 2; ++vi) {
    const ilp_pass plain = run_ilp_pass(before, tricks[vi], mem::psm::PSMZ24, o.tex_buffer);
    const ilp_pass swz = run_ilp_pass(in_z, tricks[vi], mem::psm::PSMZ24, o.tex_buffer);
    for (int p = 0; p < page_pixels; ++p) {
      const auto sp = static_cast<std::size_t>(p);
      // PSMZ32 layout: DPB pixel P's contribution (its R byte) is at LAB PSMCT32 pixel zsigma(P).
      const std::uint32_t w = plain.lab[static_cast<std::size_t>(zsigma(p))];
      if (lab_source(w) != p || (w & 0xFFu) != (before[sp] & 0xFFu)) {
        bad.add(static_cast<std::uint64_t>((vi * 2) * page_pixels + p));
        ++per_variant[vi];
      }
      // Back to PSMCT32: logical pixel P (stored at zsigma(P)) lands at LAB PSMCT32 pixel P.
      const std::uint32_t back = swz.lab[sp];
      if ((back & 0xFFu) != (before[sp] & 0xFFu)) {
        bad.add(static_cast<std::uint64_t>((vi * 2 + 1) * page_pixels + p));
        ++per_variant[vi];
      }
    }
  }
  outcome out = verdict_of(bad, 4 * page_pixels, [&](std::uint64_t k) {
    const int run = static_cast<int>(k / page_pixels), p = static_cast<int>(k % page_pixels);
    return std::string(name(tricks[run / 2])) + (run % 2 ? ", DPB rendered in PSMZ32" : ", DPB in PSMCT32") +
           ", texture_buffer " + std::string(gs::option_value(o, "texture_buffer")) + ", pixel " + pixel(p) +
           " => its contribution is not where the claim puts it (overwritten texel or other layout)";
  });
  out.figures = {fig("counterexamples_z_trick", per_variant[0]), fig("counterexamples_z_trick_psmz32", per_variant[1])};
  out.note =
      "the trick's LAB is the PSMZ32 view of the intended LAB; a DPB rendered in PSMZ32 (or a final read of the "
      "LAB as PSMZ32) undoes it, wherever the texels were read intact (claim b)";
  return out;
}

}  // namespace gsdot3::proofs::claims
