// vectors/units.cpp — the unit table: per GS unit its fields, its model evaluation and its case
// generators (the field codecs and register values they use are in fields.hpp).
#include "vectors/units.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <string>

#include "gs_arith/perspective.hpp"
#include "vectors/fields.hpp"

namespace gsdot3::vectors {

namespace {

using gs::u8;
using namespace fields;

// ---- blend ---------------------------------------------------------------------------------------
values blend_eval(const values& in, const gs::model_options& o) {
  const auto reg = decode(gs::decode_alpha, in[0]);
  return wide_values(gs::alpha_blend(reg, colour_field(in[1], "Cs"), colour_field(in[2], "Cd"), o));
}
void blend_level1(const case_sink& emit) {
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      for (int c = 0; c < 3; ++c)
        for (int d = 0; d < 3; ++d)
          for (int s : boundary_bytes)
            for (int t : boundary_bytes)
              for (int k : boundary_bytes)
                // R crosses (Cs, Cd) = (s, t); As = k, Ad = t, FIX = s, so every C picks a different one.
                emit({alpha_value(a, b, c, d, s), word(s, t, k, k), word(t, s, s, t)});
}
void blend_random(random& rng, const case_sink& emit) {
  emit({alpha_random(rng), rng.colour_word(), rng.colour_word()});
}

// ---- tfx -------------------------------------------------------------------------------------------
values tfx_eval(const values& in, const gs::model_options& o) {
  check_max(in[0], 3, "TFX");
  check_max(in[1], 1, "TCC");
  const auto out = gs::texture_function(static_cast<gs::tfx>(in[0]), static_cast<gs::tcc>(in[1]),
                                        colour_field(in[2], "Ct"), fragment_fields(in, 3), o);
  return {out.to_u32()};
}
void tfx_level1(const case_sink& emit) {
  static constexpr int fractions[] = {0x00, 0x01, 0x40, 0x7F};
  for (std::uint64_t fn = 0; fn < 4; ++fn)
    for (std::uint64_t cc = 0; cc < 2; ++cc)
      for (int t : boundary_bytes)
        for (int f : boundary_bytes)
          for (int fr : fractions) {
            const std::uint64_t cf = std::uint64_t(f) << 7 | fr, ct_as_cf = std::uint64_t(t) << 7 | fr;
            emit({fn, cc, word(t, f, t ^ 0xFF, t), cf, ct_as_cf, cf, cf});
          }
}
void tfx_random(random& rng, const case_sink& emit) {
  emit({rng.below(4), rng.below(2), rng.colour_word(), cf_random(rng), cf_random(rng), cf_random(rng), cf_random(rng)});
}
void tfx_all(const case_sink& emit) {
  for (std::uint64_t fn = 0; fn < 4; ++fn)
    for (std::uint64_t cc = 0; cc < 2; ++cc)
      for (int t = 0; t < 256; ++t)
        for (std::uint64_t f = 0; f < 256; ++f) emit({fn, cc, word(t, t, t, t), f << 7, f << 7, f << 7, f << 7});
}

// ---- atest -----------------------------------------------------------------------------------------
values atest_eval(const values& in, const gs::model_options& o) {
  const auto reg = decode(gs::decode_test, in[0]);
  check_max(in[2], 0xFF, "A");
  const auto we = gs::alpha_test(reg, u8::from_wrapped(in[2]), psm_field(in[1]), o);
  return {we.rgb ? 1u : 0u, we.a ? 1u : 0u, we.z ? 1u : 0u};
}
void atest_level1(const case_sink& emit) {
  for (bool ate : {false, true})
    for (int atst = 0; atst < 8; ++atst)
      for (int afail = 0; afail < 4; ++afail)
        for (int aref : boundary_bytes)
          for (int a : boundary_bytes)
            for (auto psm : level1_formats) emit({test_value(ate, atst, aref, afail), psm, std::uint64_t(a)});
}
void atest_random(random& rng, const case_sink& emit) {
  emit({test_random(rng), frame_formats[rng.below(std::size(frame_formats))], rng.colour_byte()});
}
void atest_all(const case_sink& emit) {
  // Pass/fail: every ATST × AREF × A (AFAIL = KEEP, so a failure writes nothing); then what a
  // failure writes: every AFAIL × frame format.
  for (int atst = 0; atst < 8; ++atst)
    for (int aref = 0; aref < 256; ++aref)
      for (std::uint64_t a = 0; a < 256; ++a) emit({test_value(true, atst, aref, 0), 0x00, a});
  for (int afail = 0; afail < 4; ++afail)
    for (auto psm : frame_formats) emit({test_value(true, 0, 0, afail), psm, 0});
}

// ---- dither ----------------------------------------------------------------------------------------
values dither_eval(const values& in, const gs::model_options& o) {
  const bool dthe = decode(gs::decode_dthe, in[0]).DTHE;
  const auto psm = psm_field(in[1]);
  const auto dimx = decode(gs::decode_dimx, in[2]);
  check_max(in[3], 0x7FF, "X");
  check_max(in[4], 0x7FF, "Y");
  return wide_values(
      gs::dither(wide_fields(in, 5), dimx, static_cast<unsigned>(in[3]), static_cast<unsigned>(in[4]), dthe, psm, o));
}
void dither_level1(const case_sink& emit) {
  static constexpr std::uint64_t formats[] = {0x00, 0x01, 0x02, 0x0a};
  static constexpr std::uint64_t xy[][2] = {{0, 0}, {1, 2}, {3, 3}, {6, 5}};
  const std::uint64_t matrices[] = {dimx_filled(0), dimx_filled(4), dimx_filled(3), dimx_mixed};
  for (std::uint64_t dthe = 0; dthe < 2; ++dthe)
    for (auto psm : formats)
      for (auto m : matrices)
        for (const auto& p : xy)
          for (std::size_t i = 0; i < std::size(wide_boundary); ++i)
            emit({dthe, psm, m, p[0], p[1], wide_bits(wide_boundary[i]),
                  wide_bits(wide_boundary[(i + 5) % std::size(wide_boundary)]),
                  wide_bits(wide_boundary[(i + 11) % std::size(wide_boundary)])});
}
void dither_random(random& rng, const case_sink& emit) {
  emit({rng.below(2), frame_formats[rng.below(std::size(frame_formats))], dimx_random(rng), rng.below(0x800),
        rng.below(0x800), wide_random(rng), wide_random(rng), wide_random(rng)});
}
void dither_all(const case_sink& emit) {
  for (std::uint64_t dthe = 0; dthe < 2; ++dthe)
    for (auto psm : frame_formats)
      for (int dm = 0; dm < 8; ++dm)
        for (std::uint64_t v = 0; v < 0x800; ++v)
          emit({dthe, psm, dimx_filled(dm), 0, 0, v, (v + 683) & 0x7FF, (v + 1366) & 0x7FF});
}

// ---- colclamp --------------------------------------------------------------------------------------
values colclamp_eval(const values& in, const gs::model_options&) {
  const bool clamp = decode(gs::decode_colclamp, in[0]).CLAMP;
  const auto c = gs::colclamp(wide_fields(in, 1), u8{}, clamp);
  return {std::uint64_t(c.r.value()), std::uint64_t(c.g.value()), std::uint64_t(c.b.value())};
}
void colclamp_level1(const case_sink& emit) {
  constexpr std::size_t n = std::size(wide_boundary);
  for (std::uint64_t clamp = 0; clamp < 2; ++clamp)
    for (std::size_t i = 0; i < n; ++i)
      emit({clamp, wide_bits(wide_boundary[i]), wide_bits(wide_boundary[(i + 5) % n]),
            wide_bits(wide_boundary[(i + 11) % n])});
}
void colclamp_random(random& rng, const case_sink& emit) {
  emit({rng.below(2), wide_random(rng), wide_random(rng), wide_random(rng)});
}
void colclamp_all(const case_sink& emit) {
  for (std::uint64_t clamp = 0; clamp < 2; ++clamp)
    for (std::uint64_t v = 0; v < 0x800; ++v) emit({clamp, v, (v + 683) & 0x7FF, (v + 1366) & 0x7FF});
}

// ---- stq -------------------------------------------------------------------------------------------
// S and Q as float32 bit patterns, TW the texture's log2 width; out: the 12.4 texel coordinate
// (gs::stq_texel: S/Q in float32, stq_range, stq_convert) as a 32-bit two's-complement word.
float f32_field(std::uint64_t v, std::string_view name) {
  check_max(v, 0xFFFFFFFF, name);
  return std::bit_cast<float>(static_cast<std::uint32_t>(v));
}
values stq_eval(const values& in, const gs::model_options& o) {
  const float s = f32_field(in[0], "S"), q = f32_field(in[1], "Q");
  check_max(in[2], 10, "TW");
  if (!std::isfinite(static_cast<double>(s) / static_cast<double>(q)))
    throw domain_error("S/Q is not a finite number (Q = 0, or a NaN / infinite S or Q): not modelled");
  return {static_cast<std::uint32_t>(gs::stq_texel(s, q, static_cast<unsigned>(in[2]), o))};
}
std::uint64_t f32_bits(float f) { return std::bit_cast<std::uint32_t>(f); }
void stq_level1(const case_sink& emit) {
  // S/Q a few ulps either side of every sixteenth of a texel in -4..4 texels, Q = 1, 1/2, 3, -1; and S/Q
  // about the ±2047 limit.
  for (std::uint64_t tw : {0u, 4u, 10u})
    for (int sixteenth = -64; sixteenth <= 64; sixteenth += 7)
      for (const float q : {1.0f, 0.5f, 3.0f, -1.0f}) {
        float x = std::ldexp(static_cast<float>(sixteenth), -4 - static_cast<int>(tw));
        x = std::nextafter(std::nextafter(x, -1e9f), -1e9f);
        for (int k = 0; k < 5; ++k, x = std::nextafter(x, 1e9f)) emit({f32_bits(x * q), f32_bits(q), tw});
      }
  for (const float x : {2046.9f, 2047.0f, 2047.5f, 40000.0f, -2047.5f, -1.0e9f})
    for (std::uint64_t tw : {0u, 10u}) emit({f32_bits(x), f32_bits(1.0f), tw});
}
void stq_random(random& rng, const case_sink& emit) {
  // S of any sign and magnitude 2^-20..2^20, Q of either sign 2^-8..2^8.
  auto magnitude = [&](int lo, int hi) {
    const float m = 1.0f + static_cast<float>(rng.below(1u << 23)) / 8388608.0f;
    return std::ldexp(rng.coin() ? m : -m, lo + static_cast<int>(rng.below(static_cast<std::uint64_t>(hi - lo + 1))));
  };
  emit({f32_bits(magnitude(-20, 20)), f32_bits(magnitude(-8, 8)), rng.below(11)});
}

// ---- frame -----------------------------------------------------------------------------------------
values frame_eval(const values& in, const gs::model_options&) {
  const auto psm = psm_field(in[0]);
  const bool fba = decode(gs::decode_fba, in[1]).FBA;
  check_max(in[2], 0xFFFFFFFF, "FBMSK");
  const auto c = gs::apply_fba(colour_field(in[3], "C"), fba, psm);
  return {gs::frame_write(psm, c, frame_word(in[4], psm, "old"), static_cast<std::uint32_t>(in[2]))};
}
void frame_level1(const case_sink& emit) {
  static constexpr std::uint64_t masks[] = {0, 0xFFFFFFFF, 0xFFFFFF00, 0x00FFFFFF, 0x80000000, 0x07070707, 0xF8F8F8F8};
  static constexpr std::uint32_t colours[] = {0x00000000, 0xFFFFFFFF, 0x80808080, 0x7F7F7F7F, 0x01FE81FF};
  static constexpr std::uint32_t olds[] = {0x00000000, 0xFFFFFFFF, 0x12345678};
  for (auto psm : frame_formats)
    for (std::uint64_t fba = 0; fba < 2; ++fba)
      for (auto m : masks)
        for (auto c : colours)
          for (auto old : olds) emit({psm, fba, m, c, fit_frame_word(old, psm)});
}
void frame_random(random& rng, const case_sink& emit) {
  const auto psm = frame_formats[rng.below(std::size(frame_formats))];
  emit({psm, rng.below(2), rng.coin() ? 0 : rng.colour_word(), rng.colour_word(),
        fit_frame_word(rng.colour_word(), psm)});
}

// ---- pixel -----------------------------------------------------------------------------------------
// Inputs 0..9 are registers (named as in gs::register_names), set through gs::set_register.
constexpr std::string_view pixel_registers[] = {"PRIM",     "TEX0_1", "ALPHA_1", "TEST_1", "FRAME_1",
                                                "COLCLAMP", "PABE",   "FBA_1",   "DTHE",   "DIMX"};
constexpr std::size_t pixel_register_count = std::size(pixel_registers);

values pixel_eval(const values& in, const gs::model_options& o) {
  gs::gs_registers regs;
  for (std::size_t i = 0; i < pixel_register_count; ++i) {
    decode(
        [&](std::uint64_t v) {
          gs::set_register(regs, pixel_registers[i], v);
          return 0;
        },
        in[i]);
  }
  std::size_t k = pixel_register_count;
  const auto cf = fragment_fields(in, k);
  const auto texel = colour_field(in[k + 4], "texel");
  const auto dst = frame_word(in[k + 5], regs.FRAME_1.PSM, "dst");
  check_max(in[k + 6], 0x7FF, "X");
  check_max(in[k + 7], 0x7FF, "Y");
  const gs::pixel_input p{cf, texel, dst, static_cast<unsigned>(in[k + 6]), static_cast<unsigned>(in[k + 7])};
  return {gs::pixel_pipeline(regs, p, o).out};
}
void pixel_level1(const case_sink& emit) {
  // Every switch of the pipeline crossed with boundary vertex and destination colours; the
  // remaining registers fixed: MODULATE/RGBA, (Cs − Cd)·As + Cd, A >= 0x40 else RGB_ONLY, mixed DIMX.
  const std::uint64_t tex0 = tex0_value(0, 1), alpha = alpha_value(0, 1, 0, 1, 0x80),
                      test = test_value(true, 5, 0x40, 3);
  for (int prim = 0; prim < 4; ++prim)
    for (auto psm : level1_formats)
      for (int bitset = 0; bitset < 16; ++bitset)
        for (int f : boundary_bytes)
          for (int d : boundary_bytes) {
            const std::uint64_t cf = std::uint64_t(f) << 7;
            emit({prim_value(prim & 1, prim & 2), tex0, alpha, test, frame_value(psm, 0), std::uint64_t(bitset & 1),
                  std::uint64_t(bitset >> 1 & 1), std::uint64_t(bitset >> 2 & 1), std::uint64_t(bitset >> 3 & 1),
                  dimx_mixed, cf, std::uint64_t(d) << 7, cf, cf, 0x80FF4080, fit_frame_word(word(d, f, d, d), psm), 1,
                  2});
          }
}
void pixel_random(random& rng, const case_sink& emit) {
  gs::prim_reg prim;
  prim.PRIM = static_cast<gs::prim_type>(rng.below(7));
  prim.IIP = rng.coin();
  prim.TME = rng.coin();
  prim.ABE = rng.coin();
  const auto psm = frame_formats[rng.below(std::size(frame_formats))];
  emit({gs::encode(prim), tex0_value(static_cast<int>(rng.below(4)), static_cast<int>(rng.below(2))), alpha_random(rng),
        test_random(rng), frame_value(psm, rng.coin() ? 0 : rng.colour_word()), rng.below(2), rng.below(2),
        rng.below(2), rng.below(2), dimx_random(rng), cf_random(rng), cf_random(rng), cf_random(rng), cf_random(rng),
        rng.colour_word(), fit_frame_word(rng.colour_word(), psm), rng.below(0x800), rng.below(0x800)});
}

std::vector<field> pixel_inputs() {
  std::vector<field> f;
  for (auto name : pixel_registers) {
    const bool one_bit = name == "COLCLAMP" || name == "PABE" || name == "FBA_1" || name == "DTHE";
    f.push_back({name, one_bit ? 1 : 16});
  }
  for (field extra : {field{"CfR", 4}, field{"CfG", 4}, field{"CfB", 4}, field{"CfA", 4}, field{"texel", 8},
                      field{"dst", 8}, field{"X", 3}, field{"Y", 3}})
    f.push_back(extra);
  return f;
}

}  // namespace

const std::vector<unit>& units() {
  static const std::vector<unit> table = {
      {"blend",
       "ALPHA_1 blend ((A - B) * C >> 7) + D per RGB channel, before COLCLAMP (11-bit two's complement)",
       {{"ALPHA_1", 16}, {"Cs", 8}, {"Cd", 8}},
       {{"R", 3}, {"G", 3}, {"B", 3}},
       blend_eval,
       blend_level1,
       blend_random,
       nullptr,
       "81 modes x FIX x Cs x Cd (2^72 cases) is not practical; level 2 samples it"},
      {"tfx",
       "texture function TFX/TCC: texel Ct and fragment colour Cf (8.7 per channel) -> Cs",
       {{"TFX", 1}, {"TCC", 1}, {"Ct", 8}, {"CfR", 4}, {"CfG", 4}, {"CfB", 4}, {"CfA", 4}},
       {{"Cs", 8}},
       tfx_eval,
       tfx_level1,
       tfx_random,
       tfx_all,
       "every TFX x TCC x Ct channel value x flat Cf channel value (fraction 0), all channels equal: 524288 cases; "
       "the 7 fraction bits of a Gouraud Cf are sampled by levels 1 and 2"},
      {"atest",
       "alpha test TEST_1 (ATE ATST AREF AFAIL) on alpha A for frame format PSM -> writes of RGB, A, Z",
       {{"TEST_1", 16}, {"PSM", 2}, {"A", 2}},
       {{"RGB", 1}, {"A", 1}, {"Z", 1}},
       atest_eval,
       atest_level1,
       atest_random,
       atest_all,
       "every ATST x AREF x A with AFAIL = KEEP (524288 cases), then every AFAIL x frame format on a failing test (32 "
       "cases)"},
      {"dither",
       "DTHE/DIMX offset added to the blend output at pixel (X, Y) for frame format PSM (11-bit two's complement)",
       {{"DTHE", 1}, {"PSM", 2}, {"DIMX", 16}, {"X", 3}, {"Y", 3}, {"R", 3}, {"G", 3}, {"B", 3}},
       {{"R", 3}, {"G", 3}, {"B", 3}},
       dither_eval,
       dither_level1,
       dither_random,
       dither_all,
       "every DTHE x frame format x 3-bit DIMX entry (filling the matrix) x 11-bit value: 262144 cases"},
      {"colclamp",
       "COLCLAMP: an 11-bit two's-complement blend output per channel -> 8 bits (clamp or wrap)",
       {{"CLAMP", 1}, {"R", 3}, {"G", 3}, {"B", 3}},
       {{"R", 2}, {"G", 2}, {"B", 2}},
       colclamp_eval,
       colclamp_level1,
       colclamp_random,
       colclamp_all,
       "every CLAMP x 11-bit value (each channel sees every value): 4096 cases"},
      {"frame",
       "frame write: FBA, pack to FRAME.PSM, FBMSK merge of colour C over the old word",
       {{"PSM", 2}, {"FBA", 1}, {"FBMSK", 8}, {"C", 8}, {"old", 8}},
       {{"new", 8}},
       frame_eval,
       frame_level1,
       frame_random,
       nullptr,
       "8 formats x FBA x FBMSK x C x old (2^100 cases) is not practical; level 2 samples it"},
      {"stq",
       "perspective texturing: S, Q (float32 bits) and TW -> the 12.4 texel coordinate of S/Q (stq_range, stq_convert)",
       {{"S", 8}, {"Q", 8}, {"TW", 1}},
       {{"U", 8}},
       stq_eval,
       stq_level1,
       stq_random,
       nullptr,
       "S x Q x TW (2^64 x 11 cases) is not practical; level 2 samples it"},
      {"pixel",
       "one pixel through the whole pipeline (gs::pixel_pipeline): registers, Cf (8.7), texel, dst, X, Y -> new word",
       pixel_inputs(),
       {{"out", 8}},
       pixel_eval,
       pixel_level1,
       pixel_random,
       nullptr,
       "the register state space is not practical to enumerate; level 2 samples it"},
  };
  return table;
}

const unit* find_unit(std::string_view name) {
  const auto& t = units();
  const auto it = std::find_if(t.begin(), t.end(), [&](const unit& u) { return u.name == name; });
  return it == t.end() ? nullptr : &*it;
}

std::string_view unit_names() {
  static const std::string names = [] {
    std::string s;
    for (const auto& u : units()) s.append(s.empty() ? "" : "|").append(u.name);
    return s;
  }();
  return names;
}

}  // namespace gsdot3::vectors
