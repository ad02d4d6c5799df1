// Sections 3.2 - 3.4: the signed multiplication, its offset form, the R+G+B sum and the ILP.
#include <algorithm>
#include <array>
#include <string>

#include "proofs/claim_util.hpp"
#include "proofs/claims.hpp"
#include "proofs/methods.hpp"

namespace gsdot3::proofs::claims {

namespace m = methods;
using fixed::u8;

outcome eq1_eq2_ranges(const gs::model_options&, const sweep_config& cfg) {
  // a2 = 128 − a and b2 = b + 128 must be u8; the product a·b must stay in [−128, 127].
  struct acc {
    tally bad;
    extremes a2, b2, product;
    void merge(const acc& l) {
      bad.merge(l.bad);
      a2.merge(l.a2);
      b2.merge(l.b2);
      product.merge(l.product);
    }
  };
  auto r = sweep<acc>(operands::count, cfg, [](acc& s, std::uint64_t lo, std::uint64_t hi) {
    for (auto i = lo; i < hi; ++i) {
      const auto x = operands::at(i);
      const int a2 = 128 - x.a, b2 = x.b + 128, p = char_multiply(x.a, x.b);
      s.a2.add(a2, i), s.b2.add(b2, i), s.product.add(p, i);
      if (!u8::from_checked(a2) || !u8::from_checked(b2) || p < -128 || p > 127) s.bad.add(i);
    }
  });
  auto out = verdict_of(r.bad, operands::count, [](auto i) { return operands::at(i).describe(); });
  out.figures = {fig("a2_min", r.a2.min), fig("a2_max", r.a2.max),           fig("b2_min", r.b2.min),
                 fig("b2_max", r.b2.max), fig("product_min", r.product.min), fig("product_max", r.product.max)};
  out.note = "a2, b2 are 8-bit unsigned and a·b (>> 7) stays a signed byte over the stated ranges";
  return out;
}

outcome eq3_identity(const gs::model_options&, const sweep_config& cfg) {
  auto bad = sweep<tally>(operands::count, cfg, [](tally& t, std::uint64_t lo, std::uint64_t hi) {
    for (auto i = lo; i < hi; ++i) {
      const auto x = operands::at(i);
      // Exact products in width-carrying integers: no shift anywhere.
      const auto a2 = fixed::sint<10>::from_wrapped(x.a2), b2 = fixed::sint<10>::from_wrapped(x.b2);
      const auto k128 = fixed::sint<10>::literal(128);
      const auto lhs = (k128 - a2) * (b2 - k128);
      const auto rhs = k128 * b2 - a2 * b2 + k128 * a2 - k128 * k128;
      if (lhs.value() != rhs.value() || lhs.value() != x.a * x.b) t.add(i);
    }
  });
  auto out = verdict_of(bad, operands::count, [](auto i) { return operands::at(i).describe(); });
  out.note = "(128 − a2)(b2 − 128) = 128·b2 − a2·b2 + 128·a2 − 128² = a·b exactly";
  return out;
}

namespace {
// Eq. (4) / (8) through the blend: GS value minus the paper's value, over the whole (a, b) domain.
struct offset_acc {
  tally bad;
  extremes out, err;
  std::uint64_t outside_byte = 0;
  void merge(const offset_acc& l) {
    bad.merge(l.bad);
    out.merge(l.out);
    err.merge(l.err);
    outside_byte += l.outside_byte;
  }
};
offset_acc sweep_offset_multiply(const gs::model_options& o, const sweep_config& cfg) {
  return sweep<offset_acc>(operands::count, cfg, [&](offset_acc& s, std::uint64_t lo, std::uint64_t hi) {
    for (auto i = lo; i < hi; ++i) {
      const auto x = operands::at(i);
      const int v = m::offset_multiply(m::byte(x.a2), m::byte(x.b2), o).value();
      const int err = v - (char_multiply(x.a, x.b) + 128);
      s.out.add(v, i);
      s.err.add(err, i);
      if (v < 0 || v > 255) ++s.outside_byte;
      if (err != 0) s.bad.add(i);
    }
  });
}
std::string describe_offset(std::uint64_t i, const gs::model_options& o) {
  const auto x = operands::at(i);
  const int v = m::offset_multiply(m::byte(x.a2), m::byte(x.b2), o).value();
  return x.describe() + " => blend " + hexdec(v, 12) + ", a·b + 128 = " + hexdec(char_multiply(x.a, x.b) + 128, 12);
}
}  // namespace

outcome eq4_signed_multiply(const gs::model_options& o, const sweep_config& cfg) {
  const auto r = sweep_offset_multiply(o, cfg);
  auto out = verdict_of(r.bad, operands::count, [&](auto i) { return describe_offset(i, o); });
  out.figures = {fig("err_min", r.err.min), fig("err_max", r.err.max)};
  out.note = "((128 − a2)·b2 >> 7) + a2 − 128 by the blend A=Cs(0x80) B=Cd(a2) C=As(b2) D=Cd equals (a·b) >> 7";
  return out;
}

outcome eq8_offset_multiply(const gs::model_options& o, const sweep_config& cfg) {
  const auto r = sweep_offset_multiply(o, cfg);
  auto out = verdict_of(r.bad, operands::count, [&](auto i) { return describe_offset(i, o); });
  out.figures = {fig("out_min", r.out.min), fig("out_max", r.out.max),
                 fig("needs_clamp_or_wrap", static_cast<std::int64_t>(r.outside_byte))};
  out.note = "the blend output is a·b + 128 exactly and stays in 0..255: neither clamp nor wrap is needed";
  return out;
}

namespace {
// Eq. (5)-(7) and (10) as the two-pass GS evaluates one channel: pass 1 MODULATE with the positive
// palette value Max(a, 0) and the light colour b2; pass 2 MODULATE with Max(−a, 0), blended Cd − Cs.
struct split_result {
  int value;  // eq. (7): pass-2 blend output (before COLCLAMP) + c2 − 128
  int byte;   // eq. (10): pass 2 wrapped, then + c2 by an additive blend, wrapped
};
split_result split_multiply(const operands& x, const gs::model_options& o) {
  const int pos = std::max(x.a, 0), neg = std::max(-x.a, 0), c2 = 128 + neg - pos;
  const auto light = gs::fragment_colour::flat(m::grey(x.b2, 0x80));
  const auto dpb = m::two_pass_pass1(m::grey(pos, 0), light, o);
  const auto p2 = m::two_pass_pass2_wide(m::grey(neg, 0), light, dpb, o);
  const u8 wrapped = gs::colclamp_channel(p2.wide.r, false);
  return {p2.wide.r.value() + c2 - 128, m::add_wrapped(wrapped, m::byte(c2), o).value()};
}
struct split_acc {
  tally bad;
  extremes err;
  void merge(const split_acc& l) {
    bad.merge(l.bad);
    err.merge(l.err);
  }
};
template <class Error>
split_acc sweep_split(const gs::model_options& o, const sweep_config& cfg, Error error) {
  return sweep<split_acc>(operands::count, cfg, [&](split_acc& s, std::uint64_t lo, std::uint64_t hi) {
    for (auto i = lo; i < hi; ++i) {
      const int e = error(operands::at(i), split_multiply(operands::at(i), o));
      s.err.add(e, i);
      if (e != 0) s.bad.add(i);
    }
  });
}
}  // namespace

outcome eq5_eq7_split_multiply(const gs::model_options& o, const sweep_config& cfg) {
  auto err = [](const operands& x, const split_result& r) { return r.value - char_multiply(x.a, x.b); };
  const auto r = sweep_split(o, cfg, err);
  auto out = verdict_of(r.bad, operands::count, [&](auto i) {
    const auto x = operands::at(i);
    return x.describe() + " => GS " + hexdec(split_multiply(x, o).value) +
           ", (a·b) >> 7 = " + hexdec(char_multiply(x.a, x.b));
  });
  out.figures = {fig("err_min", r.err.min), fig("err_max", r.err.max)};
  out.note =
      "for a < 0 the GS floors Max(−a,0)·b2 before negating, so the product rounds up: "
      "off by +1 whenever a < 0 and a·b is not a multiple of 128";
  return out;
}

outcome eq10_split_offset_multiply(const gs::model_options& o, const sweep_config& cfg) {
  auto err = [](const operands& x, const split_result& r) { return r.byte - (char_multiply(x.a, x.b) + 128); };
  const auto r = sweep_split(o, cfg, err);
  auto out = verdict_of(r.bad, operands::count, [&](auto i) {
    const auto x = operands::at(i);
    return x.describe() + " => DPB byte " + hexdec(split_multiply(x, o).byte) +
           ", a·b + 128 = " + hexdec(char_multiply(x.a, x.b) + 128);
  });
  out.figures = {fig("err_min", r.err.min), fig("err_max", r.err.max)};
  out.note = "the same +1 as eq. (7), now in the wrapped byte; the modulo-256 steps themselves are exact";
  return out;
}

outcome eq9_rgb_sum(const gs::model_options& o, const sweep_config& cfg) {
  // Every DPB pixel (r, g, b): each channel holds a product + 128 and every byte is reachable
  // (eq. (8) with a = 128 gives b + 128 for every b). P = r + g + b − 384 is the true sum.
  // Claim: the post filter's (r + g + b − 128) mod 256 read as a signed byte equals P exactly
  // when −128 <= P <= 127 — and is always P mod 256.
  constexpr std::uint64_t n = std::uint64_t{1} << 24;
  struct acc {
    tally bad;  // breaks "≡ P (mod 256)" or the exact condition
    std::uint64_t wraps = 0;
    extremes sum;
    void merge(const acc& l) {
      bad.merge(l.bad);
      wraps += l.wraps;
      sum.merge(l.sum);
    }
  };
  auto r = sweep<acc>(n, cfg, [&](acc& s, std::uint64_t lo, std::uint64_t hi) {
    for (auto i = lo; i < hi; ++i) {
      const gs::rgba8 px{m::byte(static_cast<int>(i & 0xFF)), m::byte(static_cast<int>((i >> 8) & 0xFF)),
                         m::byte(static_cast<int>(i >> 16)), u8{}};
      const int P = px.r.value() + px.g.value() + px.b.value() - 384;
      const u8 dot = m::minus_128(m::sum_rgb(px, o), o);
      const bool in_range = P >= -128 && P <= 127;
      const bool exact = m::as_signed(dot) == P;
      s.sum.add(P, i);
      if (!in_range) ++s.wraps;
      if (((dot.value() - P) & 0xFF) != 0 || exact != in_range) s.bad.add(i);
    }
  });
  auto out = verdict_of(r.bad, n, [](auto i) { return "DPB pixel " + hexdec(static_cast<std::int64_t>(i), 24); });
  out.figures = {fig("sum_min", r.sum.min), fig("sum_max", r.sum.max),
                 fig("wrapping_pixels", static_cast<std::int64_t>(r.wraps))};
  out.note =
      "(r+g+b−128) mod 256 ≡ Σ a·b always; read as a signed byte it is the dot product exactly "
      "iff −128 <= Σ a·b <= 127";
  return out;
}

outcome ilp_palette_permutation(const gs::model_options& o, const sweep_config&) {
  // The offset-keeping post filter leaves j = (Σ a·b + 128) mod 256. The rotated palette
  // ILP'[j] = ILP[(j + 128) mod 256] must (1) be a permutation of ILP and (2) give, for all 256 j,
  // the entry the plain method reads after its GS "− 128" pass.
  tally bad;
  std::array<int, 256> plain{}, rotated{};
  for (int j = 0; j < 256; ++j) {
    plain[static_cast<std::size_t>(j)] = m::ilp_entry(j);
    rotated[static_cast<std::size_t>(j)] = m::ilp_offset_entry(j);
    if (rotated[static_cast<std::size_t>(j)] != m::ilp_entry(m::minus_128(m::byte(j), o).value()))
      bad.add(static_cast<std::uint64_t>(j));
  }
  std::sort(plain.begin(), plain.end());
  std::sort(rotated.begin(), rotated.end());
  const bool permutation = plain == rotated;
  if (!permutation) bad.add(256);
  auto out = verdict_of(bad, 256, [](auto j) {
    return j == 256 ? std::string("rotated palette is not a permutation")
                    : "sum byte " + hexdec(static_cast<std::int64_t>(j));
  });
  out.figures = {fig("rotation", 128), fig("permutation", permutation ? 1 : 0)};
  out.note = "ILP' is ILP rotated by 128 entries; all 256 look-ups agree with the '− 128' post filter";
  return out;
}

outcome ilp_dpb_clear_zero(const gs::model_options& o, const sweep_config&) {
  // A never-rendered pixel keeps the clear value 0x00808080 through step 2.3; the post filter and the
  // ILP then give its intensity. Four-pass: r + g + b (offset-keeping ILP'). Two-pass: r+g+b+3a (ILP').
  const auto clear = gs::rgba8::from_u32(0x00808080u);
  const int four = m::ilp_offset_entry(m::sum_rgb(clear, o).value());
  const int four_plain = m::ilp_entry(m::minus_128(m::sum_rgb(clear, o), o).value());
  const int two = m::ilp_offset_entry(m::sum_rgb_plus_3a(clear, o).value());
  tally bad;
  if (four != 0) bad.add(0);
  if (four_plain != 0) bad.add(1);
  if (two != 0) bad.add(2);
  const auto alt = gs::rgba8::from_u32(0x0080807Fu);
  auto out = verdict_of(bad, 3, [&](auto k) {
    const char* what[] = {"four-pass, r+g+b with ILP'", "four-pass, r+g+b−128 with ILP",
                          "two-pass, r+g+b+3a with ILP'"};
    const int v[] = {four, four_plain, two};
    return std::string("DPB 0x00808080, ") + what[k] + " => intensity " + std::to_string(v[k]) +
           " (1/128 of the light), not 0";
  });
  out.figures = {fig("intensity_four_pass", four), fig("intensity_four_pass_minus_128", four_plain),
                 fig("intensity_two_pass", two),
                 fig("intensity_clear_0x0080807F", m::ilp_offset_entry(m::sum_rgb(alt, o).value()))};
  out.note =
      "an unrendered pixel reads as dot product 0, and the paper's ILP maps 0 to 1, not 0 (a faint 1/128); "
      "clearing to 0x0080807F (dot −1) or an ILP of 0..127 would give 0";
  return out;
}

}  // namespace gsdot3::proofs::claims
