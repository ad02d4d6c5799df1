// fuzz/alu_diff.cpp — libFuzzer harness: random register values, colours and model options through
// the GS model; every path that computes the same thing must agree bit for bit.
//   1. gs::pixel_pipeline (the reference per-unit path) against the same pixel computed with plain
//      int arithmetic written from the formulas of ../shared/spec/gs-alu-facts.md (pixel_reference
//      below), stage by stage;
//   2. register decode/encode: a decoded 64-bit value re-encodes to itself, a rejected one throws
//      gs::register_error and nothing else;
//   1b. gs_simd::pixel_pipeline (the SIMD units, issue 30) on every SIMD target against
//      gs::pixel_pipeline, the pixel in a random lane of a batch of copies;
//   3. the proof layer where it overlaps: methods::offset_multiply / add_wrapped / minus_128 against
//      their closed forms, four_pass::table against methods::four_pass_channel, and two_pass::table
//      (the vertex-light fast path) against two_pass::pixel.
// A difference aborts with the inputs in hex.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iomanip>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <tuple>

#include <fuzzer/FuzzedDataProvider.h>

#include "fuzz_check.hpp"
#include "gs_arith/pixel_pipeline.hpp"
#include "gs_arith/registers.hpp"
#include "gs_simd/pixel_span.hpp"
#include "proofs/domains.hpp"
#include "proofs/four_pass.hpp"
#include "proofs/methods.hpp"
#include "proofs/two_pass.hpp"

namespace {

using gsdot3::fuzz::require;
namespace methods = gsdot3::proofs::methods;

std::string hex(std::uint64_t v, int digits) {
  std::ostringstream os;
  os << std::hex << std::setw(digits) << std::setfill('0') << v;
  return os.str();
}

// ---- random inputs ------------------------------------------------------------------------------
gs::model_options random_options(FuzzedDataProvider& in) {
  gs::model_options o;
  o.tfx = in.ConsumeBool() ? gs::tfx_rounding::truncate : gs::tfx_rounding::floor;
  o.gouraud = in.ConsumeBool() ? gs::gouraud_fraction::truncate_to_8 : gs::gouraud_fraction::keep_fraction;
  o.shift = in.ConsumeBool() ? gs::blend_shift::truncate : gs::blend_shift::floor;
  o.dither = static_cast<gs::dither_decode>(in.ConsumeIntegralInRange<int>(0, 2));  // the three decodes
  o.dither_on = in.ConsumeBool() ? gs::dither_targets::all_formats : gs::dither_targets::sixteen_bit_only;
  o.bilinear = in.ConsumeBool() ? gs::bilinear_mode::nearest : gs::bilinear_mode::lerp16_4;
  o.rgb_only = in.ConsumeBool() ? gs::rgb_only_targets::all_formats : gs::rgb_only_targets::thirty_two_bit_only;
  return o;
}

std::string options_text(const gs::model_options& o) {
  std::string s;
  for (const auto& row : gs::option_catalogue())
    s.append(" ").append(row.name).append("=").append(gs::option_value(o, row.name));
  return s;
}

// A byte, half the time one of the boundary values of an 8-bit colour channel.
std::uint8_t colour_byte(FuzzedDataProvider& in) {
  static constexpr std::uint8_t boundary[] = {0x00, 0x01, 0x3F, 0x40, 0x7F, 0x80, 0x81, 0xFE, 0xFF};
  if (in.ConsumeBool()) return in.PickValueInArray(boundary);
  return in.ConsumeIntegral<std::uint8_t>();
}
std::uint32_t colour_word(FuzzedDataProvider& in) {
  std::uint32_t w = 0;
  for (int i = 0; i < 4; ++i) w |= std::uint32_t{colour_byte(in)} << (8 * i);
  return w;
}

constexpr gs::frame_psm frame_formats[] = {gs::frame_psm::PSMCT32,  gs::frame_psm::PSMCT24, gs::frame_psm::PSMCT16,
                                           gs::frame_psm::PSMCT16S, gs::frame_psm::PSMZ32,  gs::frame_psm::PSMZ24,
                                           gs::frame_psm::PSMZ16,   gs::frame_psm::PSMZ16S};

// The registers the pixel pipeline reads, field by field (every field value the manual allows).
gs::gs_registers random_registers(FuzzedDataProvider& in) {
  gs::gs_registers r;
  r.PRIM.TME = in.ConsumeBool();
  r.PRIM.ABE = in.ConsumeBool();
  r.TEX0_1.TFX = static_cast<gs::tfx>(in.ConsumeIntegralInRange<int>(0, 3));
  r.TEX0_1.TCC = in.ConsumeBool() ? gs::tcc::RGBA : gs::tcc::RGB;
  auto colour_sel = [&] { return static_cast<gs::blend_colour>(in.ConsumeIntegralInRange<int>(0, 2)); };
  r.ALPHA_1.A = colour_sel();
  r.ALPHA_1.B = colour_sel();
  r.ALPHA_1.C = static_cast<gs::blend_alpha>(in.ConsumeIntegralInRange<int>(0, 2));
  r.ALPHA_1.D = colour_sel();
  r.ALPHA_1.FIX = gs::u8::from_wrapped(colour_byte(in));
  r.TEST_1.ATE = in.ConsumeBool();
  r.TEST_1.ATST = static_cast<gs::atst>(in.ConsumeIntegralInRange<int>(0, 7));
  r.TEST_1.AREF = gs::u8::from_wrapped(colour_byte(in));
  r.TEST_1.AFAIL = static_cast<gs::afail>(in.ConsumeIntegralInRange<int>(0, 3));
  r.FRAME_1.PSM = in.PickValueInArray(frame_formats);
  r.FRAME_1.FBMSK = in.ConsumeBool() ? 0u : colour_word(in);
  r.COLCLAMP.CLAMP = in.ConsumeBool();
  r.PABE.PABE = in.ConsumeBool();
  r.FBA_1.FBA = in.ConsumeBool();
  r.DTHE.DTHE = in.ConsumeBool();
  for (auto& row : r.DIMX.DM) {
    for (auto& dm : row) dm = gs::u3::from_wrapped(in.ConsumeIntegralInRange<int>(0, 7));
  }
  return r;
}

gs::pixel_input random_pixel(FuzzedDataProvider& in, gs::frame_psm psm) {
  gs::pixel_input p{};
  auto channel = [&] {  // 8.7: half the time flat (no fraction)
    const auto whole = colour_byte(in);
    const int fraction = in.ConsumeBool() ? 0 : in.ConsumeIntegralInRange<int>(0, 127);
    return gs::gouraud_channel::from_wrapped(whole << 7 | fraction);
  };
  p.vertex = {channel(), channel(), channel(), channel()};
  p.texel = gs::rgba8::from_u32(colour_word(in));
  p.dst = colour_word(in);
  if (gs::bits_of(psm) == gs::pixel_bits::b16) p.dst &= 0xFFFFu;  // 16-bit words: the low half
  p.x = in.ConsumeIntegralInRange<unsigned>(0, 2047);
  p.y = in.ConsumeIntegralInRange<unsigned>(0, 2047);
  return p;
}

std::string describe(const gs::gs_registers& r, const gs::pixel_input& p, const gs::model_options& o) {
  std::string s = "registers:";
  for (auto name : gs::register_names)
    s.append(" ").append(name).append("=").append(hex(gs::register_value(r, name), 16));
  s += " vertex(8.7)=" + hex(p.vertex.r.value(), 4) + "," + hex(p.vertex.g.value(), 4) + "," +
       hex(p.vertex.b.value(), 4) + "," + hex(p.vertex.a.value(), 4) + " texel=" + hex(p.texel.to_u32(), 8) +
       " dst=" + hex(p.dst, 8) + " x=" + std::to_string(p.x) + " y=" + std::to_string(p.y) +
       " options:" + options_text(o);
  return s;
}

// ---- the plain-int reference: the formulas of ../shared/spec/gs-alu-facts.md, one after the other --
struct reference_pixel {
  int cs[4];  // after TFX: r, g, b, a
  bool write_rgb, write_a;
  int cd[4];     // destination as the blender reads it
  int blend[3];  // before dither
  int dithered[3];
  int clamped[4];  // alpha is As
  std::uint32_t out;
};

int floor_shift7(int v) { return v >= 0 ? v / 128 : -((-v + 127) / 128); }
int trunc_shift7(int v) { return v / 128; }

reference_pixel pixel_reference(const gs::gs_registers& r, const gs::pixel_input& in, const gs::model_options& o) {
  reference_pixel ref{};
  const int cf[4] = {in.vertex.r.value(), in.vertex.g.value(), in.vertex.b.value(), in.vertex.a.value()};  // 8.7
  const std::uint32_t t = in.texel.to_u32();
  const int ct[4] = {int(t & 0xFF), int(t >> 8 & 0xFF), int(t >> 16 & 0xFF), int(t >> 24)};
  // Texture function (min(255, (Ct·Cf) >> 7) etc.; all products non-negative, so floor = truncation).
  auto modulate = [&](int texel, int frag87) {
    return o.gouraud == gs::gouraud_fraction::keep_fraction ? (texel * frag87) >> 14 : (texel * (frag87 >> 7)) >> 7;
  };
  const int af = cf[3] >> 7;
  if (!r.PRIM.TME) {
    for (int c = 0; c < 4; ++c) ref.cs[c] = cf[c] >> 7;
  } else {
    const auto fn = r.TEX0_1.TFX;
    for (int c = 0; c < 3; ++c) {
      if (fn == gs::tfx::DECAL)
        ref.cs[c] = ct[c];
      else if (fn == gs::tfx::MODULATE)
        ref.cs[c] = std::min(255, modulate(ct[c], cf[c]));
      else
        ref.cs[c] = std::min(255, modulate(ct[c], cf[c]) + af);
    }
    ref.cs[3] = af;
    if (r.TEX0_1.TCC == gs::tcc::RGBA) {
      if (fn == gs::tfx::MODULATE)
        ref.cs[3] = std::min(255, modulate(ct[3], cf[3]));
      else if (fn == gs::tfx::HIGHLIGHT)
        ref.cs[3] = std::min(255, ct[3] + af);
      else
        ref.cs[3] = ct[3];
    }
  }
  const int as = ref.cs[3];
  // Alpha test.
  const int aref = r.TEST_1.AREF.value();
  const bool pass = [&] {
    switch (static_cast<int>(r.TEST_1.ATST)) {
      case 0: return false;
      case 1: return true;
      case 2: return as < aref;
      case 3: return as <= aref;
      case 4: return as == aref;
      case 5: return as >= aref;
      case 6: return as > aref;
      default: return as != aref;
    }
  }();
  const int bits = r.FRAME_1.PSM == gs::frame_psm::PSMCT32 || r.FRAME_1.PSM == gs::frame_psm::PSMZ32   ? 32
                   : r.FRAME_1.PSM == gs::frame_psm::PSMCT24 || r.FRAME_1.PSM == gs::frame_psm::PSMZ24 ? 24
                                                                                                       : 16;
  ref.write_rgb = ref.write_a = true;
  if (r.TEST_1.ATE && !pass) {
    switch (static_cast<int>(r.TEST_1.AFAIL)) {
      case 0: ref.write_rgb = ref.write_a = false; break;                                                   // KEEP
      case 1: break;                                                                                        // FB_ONLY
      case 2: ref.write_rgb = ref.write_a = false; break;                                                   // ZB_ONLY
      default: ref.write_a = bits != 32 && o.rgb_only == gs::rgb_only_targets::thirty_two_bit_only; break;  // RGB_ONLY
    }
  }
  // The destination as read.
  const std::uint32_t d = in.dst;
  if (bits == 16) {
    for (int c = 0; c < 3; ++c) ref.cd[c] = int(d >> (5 * c) & 31) << 3;
    ref.cd[3] = (d >> 15 & 1) ? 0x80 : 0;
  } else {
    for (int c = 0; c < 4; ++c) ref.cd[c] = int(d >> (8 * c) & 0xFF);
    if (bits == 24) ref.cd[3] = 0x80;
  }
  // Blend.
  const bool blended = r.PRIM.ABE && !(r.PABE.PABE && as < 0x80);
  for (int c = 0; c < 3; ++c) {
    if (!blended) {
      ref.blend[c] = ref.cs[c];
      continue;
    }
    auto pick = [&](gs::blend_colour s) {
      return s == gs::blend_colour::Cs ? ref.cs[c] : s == gs::blend_colour::Cd ? ref.cd[c] : 0;
    };
    const int k = r.ALPHA_1.C == gs::blend_alpha::As   ? as
                  : r.ALPHA_1.C == gs::blend_alpha::Ad ? ref.cd[3]
                                                       : r.ALPHA_1.FIX.value();
    const int product = (pick(r.ALPHA_1.A) - pick(r.ALPHA_1.B)) * k;
    ref.blend[c] =
        (o.shift == gs::blend_shift::floor ? floor_shift7(product) : trunc_shift7(product)) + pick(r.ALPHA_1.D);
  }
  // Dither.
  const bool dither = r.DTHE.DTHE && (o.dither_on == gs::dither_targets::all_formats || bits == 16);
  const int dm = r.DIMX.DM[in.y % 4][in.x % 4].value();
  const int offset = dm < 4                                           ? dm
                     : o.dither == gs::dither_decode::twos_complement ? dm - 8
                     : o.dither == gs::dither_decode::sign_magnitude  ? 4 - dm
                                                                      : 3 - dm;  // inverted_magnitude
  for (int c = 0; c < 3; ++c) ref.dithered[c] = ref.blend[c] + (dither ? offset : 0);
  // COLCLAMP, FBA.
  for (int c = 0; c < 3; ++c)
    ref.clamped[c] = r.COLCLAMP.CLAMP ? std::clamp(ref.dithered[c], 0, 255) : ref.dithered[c] & 0xFF;
  ref.clamped[3] = as;
  const int a_out = (r.FBA_1.FBA && bits != 24) ? (as | 0x80) : as;
  // Pack and merge.
  auto pack16 = [](int rr, int gg, int bb, int aa) {
    return std::uint32_t(rr >> 3) | std::uint32_t(gg >> 3) << 5 | std::uint32_t(bb >> 3) << 10 |
           std::uint32_t(aa >> 7) << 15;
  };
  const std::uint32_t word = std::uint32_t(ref.clamped[0]) | std::uint32_t(ref.clamped[1]) << 8 |
                             std::uint32_t(ref.clamped[2]) << 16 | std::uint32_t(a_out) << 24;
  std::uint32_t keep = r.FRAME_1.FBMSK | (ref.write_rgb ? 0u : 0x00FFFFFFu) | (ref.write_a ? 0u : 0xFF000000u);
  std::uint32_t packed = word;
  if (bits == 24) {
    packed = word & 0x00FFFFFFu;
    keep |= 0xFF000000u;
  } else if (bits == 16) {
    packed = pack16(ref.clamped[0], ref.clamped[1], ref.clamped[2], a_out);
    keep = pack16(int(keep & 0xFF), int(keep >> 8 & 0xFF), int(keep >> 16 & 0xFF), int(keep >> 24)) | 0xFFFF0000u;
  }
  ref.out = (packed & ~keep) | (d & keep);
  return ref;
}

void check_simd_pixel(FuzzedDataProvider& in, const gs::gs_registers& regs, const gs::pixel_input& p,
                      const gs::model_options& o, std::uint32_t expected) {
  static gsdot3::simd::pixel_batch batch;
  const std::size_t lane = in.ConsumeIntegralInRange<std::size_t>(0, gsdot3::simd::pixel_batch::capacity - 1);
  batch.n = lane + 1;
  for (std::size_t i = 0; i < batch.n; ++i) {
    batch.texel[i] = p.texel.to_u32();
    const gs::gouraud_channel c[4] = {p.vertex.r, p.vertex.g, p.vertex.b, p.vertex.a};
    for (std::size_t k = 0; k < 4; ++k) batch.cf[k][i] = static_cast<std::uint32_t>(c[k].value());
    batch.dst[i] = p.dst, batch.x[i] = p.x, batch.y[i] = p.y;
  }
  for (const gsdot3::simd::target& target : gsdot3::simd::available_targets()) {
    gsdot3::simd::force_target(target.bits);
    gsdot3::simd::pixel_pipeline(regs, o, batch);
    require(batch.out[lane] == expected, [&] {
      return "gs_simd pixel_pipeline (" + target.name + ", lane " + std::to_string(lane) + ") out " +
             hex(batch.out[lane], 8) + ", gs::pixel_pipeline " + hex(expected, 8) + "; " + describe(regs, p, o);
    });
  }
  gsdot3::simd::force_target(0);
}

void check_pixel(FuzzedDataProvider& in) {
  const auto o = random_options(in);
  const auto regs = random_registers(in);
  const auto p = random_pixel(in, regs.FRAME_1.PSM);
  const gs::pixel_trace t = gs::pixel_pipeline(regs, p, o);
  const reference_pixel ref = pixel_reference(regs, p, o);
  auto stage = [&](const char* name, bool same) {
    require(same, [&] {
      return std::string("pixel_pipeline stage '") + name + "' differs from the plain-int reference; " +
             describe(regs, p, o) + "\n" + gs::format_trace(t);
    });
  };
  const gs::rgba8 cs = t.tfx_out;
  stage("tfx", cs.r.value() == ref.cs[0] && cs.g.value() == ref.cs[1] && cs.b.value() == ref.cs[2] &&
                   cs.a.value() == ref.cs[3]);
  stage("alpha test", t.test.rgb == ref.write_rgb && t.test.a == ref.write_a);
  stage("cd", t.cd.r.value() == ref.cd[0] && t.cd.g.value() == ref.cd[1] && t.cd.b.value() == ref.cd[2] &&
                  t.cd.a.value() == ref.cd[3]);
  stage("blend",
        t.blend.r.value() == ref.blend[0] && t.blend.g.value() == ref.blend[1] && t.blend.b.value() == ref.blend[2]);
  stage("dither", t.dithered.r.value() == ref.dithered[0] && t.dithered.g.value() == ref.dithered[1] &&
                      t.dithered.b.value() == ref.dithered[2]);
  stage("colclamp", t.clamped.r.value() == ref.clamped[0] && t.clamped.g.value() == ref.clamped[1] &&
                        t.clamped.b.value() == ref.clamped[2] && t.clamped.a.value() == ref.clamped[3]);
  require(t.out == ref.out, [&] {
    return "pixel_pipeline out " + hex(t.out, 8) + ", reference " + hex(ref.out, 8) + "; " + describe(regs, p, o) +
           "\n" + gs::format_trace(t);
  });
  check_simd_pixel(in, regs, p, o, t.out);
}

// ---- register decode / encode -------------------------------------------------------------------
void check_registers(FuzzedDataProvider& in) {
  const auto name = in.PickValueInArray(gs::register_names);
  const auto value = in.ConsumeIntegral<std::uint64_t>();
  gs::gs_registers regs;
  try {
    gs::set_register(regs, name, value);
  } catch (const gs::register_error&) {
    return;  // rejected: the documented outcome for a value the strict decoder refuses
  }
  const auto back = gs::register_value(regs, name);
  require(back == value,
          [&] { return std::string(name) + "=" + hex(value, 16) + " decodes and re-encodes to " + hex(back, 16); });
}

// ---- the proof layer ------------------------------------------------------------------------------
// Tables are built through the model once per option set (they depend on nothing else).
template <typename Table>
const Table& table_for(const gs::model_options& o) {
  static std::map<std::string, std::unique_ptr<Table>> cache;
  auto& slot = cache[options_text(o)];
  if (!slot) slot = std::make_unique<Table>(o);
  return *slot;
}

void check_proof_layer(FuzzedDataProvider& in) {
  const auto o = random_options(in);
  const bool floor = o.shift == gs::blend_shift::floor;
  const std::uint8_t a2 = colour_byte(in), b2 = colour_byte(in);
  // Eq. (8): (0x80 − a2)·b2 >> 7 + a2.
  const int product = (0x80 - a2) * b2;
  const int want = (floor ? floor_shift7(product) : trunc_shift7(product)) + a2;
  const int got = methods::offset_multiply(gs::u8::from_wrapped(a2), gs::u8::from_wrapped(b2), o).value();
  require(got == want, [&] {
    return "offset_multiply(" + hex(a2, 2) + ", " + hex(b2, 2) + ") = " + std::to_string(got) + ", expected " +
           std::to_string(want) + options_text(o);
  });
  // Post-filter additions and − 128 on the GS: modulo 256.
  const int sum = methods::add_wrapped(gs::u8::from_wrapped(a2), gs::u8::from_wrapped(b2), o).value();
  require(sum == ((a2 + b2) & 0xFF),
          [&] { return "add_wrapped(" + hex(a2, 2) + ", " + hex(b2, 2) + ") = " + hex(sum, 2) + options_text(o); });
  const int minus = methods::minus_128(gs::u8::from_wrapped(a2), o).value();
  require(minus == ((a2 - 128) & 0xFF),
          [&] { return "minus_128(" + hex(a2, 2) + ") = " + hex(minus, 2) + options_text(o); });
  // Four-pass: the table against one pass through the model.
  const int a = in.ConsumeIntegralInRange<int>(-127, 128), b = in.ConsumeIntegralInRange<int>(-128, 127);
  const int channel = in.ConsumeIntegralInRange<int>(0, 2);
  const std::uint32_t dpb_other = colour_word(in);
  const std::uint32_t dpb = (dpb_other & ~(0xFFu << (8 * channel))) | std::uint32_t(128 - a) << (8 * channel);
  const std::uint32_t after = methods::four_pass_channel(dpb, channel, gs::u8::from_wrapped(b + 128), o);
  const int table_product = table_for<gsdot3::proofs::four_pass::table>(o).product(a, b);
  require(int(after >> (8 * channel) & 0xFF) - 128 == table_product &&
              (after & ~(0xFFu << (8 * channel))) == (dpb & ~(0xFFu << (8 * channel))),
          [&] {
            return "four_pass table product(" + std::to_string(a) + ", " + std::to_string(b) +
                   ") = " + std::to_string(table_product) + ", four_pass_channel(" + hex(dpb, 8) + ", " +
                   std::to_string(channel) + ") = " + hex(after, 8) + options_text(o);
          });
  // Two-pass: the vertex-light table against the pixel through the model.
  const auto& normals = gsdot3::proofs::appendix2_normals();
  const auto& normal = normals[in.ConsumeIntegralInRange<std::size_t>(0, normals.size() - 1)];
  const gsdot3::proofs::ivec3 l{in.ConsumeIntegralInRange<int>(-128, 127), in.ConsumeIntegralInRange<int>(-128, 127),
                                in.ConsumeIntegralInRange<int>(-128, 127)};
  const int fast = table_for<gsdot3::proofs::two_pass::table>(o).value(normal, l);
  const int slow = gsdot3::proofs::two_pass::pixel(normal, gsdot3::proofs::two_pass::vertex_light(l), o).value;
  require(fast == slow, [&] {
    return "two_pass table value " + std::to_string(fast) + " != pixel value " + std::to_string(slow) +
           " for normal (" + std::to_string(normal.iX) + "," + std::to_string(normal.iY) + "," +
           std::to_string(normal.iZ) + ") light (" + std::to_string(l[0]) + "," + std::to_string(l[1]) + "," +
           std::to_string(l[2]) + ")" + options_text(o);
  });
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  for (int step = 0; step < 8 && in.remaining_bytes() > 0; ++step) {
    switch (in.ConsumeIntegralInRange<int>(0, 3)) {
      case 0:
      case 1: check_pixel(in); break;
      case 2: check_registers(in); break;
      default: check_proof_layer(in); break;
    }
  }
  return 0;
}
