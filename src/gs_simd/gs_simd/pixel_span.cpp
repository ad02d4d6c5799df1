// gs_simd/pixel_span.cpp — see pixel_span.hpp: the per-target loops over pixel_units-inl.h and the
// dispatch tables (Highway foreach_target.h / HWY_EXPORT / HWY_DYNAMIC_DISPATCH).
#include "gs_simd/pixel_span.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "gs_simd/pixel_span.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "gs_simd/pixel_units-inl.h"
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace gsdot3::simd::HWY_NAMESPACE {

HWY_INLINE V load(const std::uint32_t* p) { return hn::Load(D(), reinterpret_cast<const std::int32_t*>(p)); }

void pixel_pipeline_batch(const gs::gs_registers& regs, const gs::model_options& o, pixel_batch& b) {
  const std::size_t lanes = hn::Lanes(D());
  for (std::size_t i = 0; i < b.n; i += lanes) {
    const rgba_v cf{load(b.cf[0] + i), load(b.cf[1] + i), load(b.cf[2] + i), load(b.cf[3] + i)};
    const V out = pixel_pipeline(regs, o, load(b.texel + i), cf, load(b.dst + i), load(b.x + i), load(b.y + i));
    hn::Store(out, D(), reinterpret_cast<std::int32_t*>(b.out + i));
  }
}

// One vector of lanes of unit call c at offset i.
HWY_INLINE void unit_lanes(const unit_call& c, std::size_t i) {
  const D d;
  auto in = [&](int k) { return hn::LoadU(d, c.in[k] + i); };
  auto out = [&](int k, V v) { hn::StoreU(v, d, c.out[k] + i); };
  const gs::gs_registers& r = c.regs;
  const gs::frame_psm psm = r.FRAME_1.PSM;
  switch (c.which) {
    case unit::modulate: out(0, modulate(in(0), in(1), c.options)); break;
    case unit::texture_function:
      out(0,
          pack32(texture_function(r.TEX0_1.TFX, r.TEX0_1.TCC, unpack(in(0)), {in(1), in(2), in(3), in(4)}, c.options)));
      break;
    case unit::texture_off: out(0, pack32(texture_off({in(1), in(2), in(3), in(4)}))); break;
    case unit::alpha_test: {
      const write_masks m = alpha_test(r.TEST_1, in(0), psm, c.options);
      const V one = set(1);
      out(0, hn::Or(hn::IfThenElseZero(m.rgb, one),
                    hn::Or(hn::IfThenElseZero(m.a, set(2)), hn::IfThenElseZero(m.z, set(4)))));
      break;
    }
    case unit::frame_read: out(0, pack32(frame_read(psm, in(0)))); break;
    case unit::blend_channel: out(0, blend_channel(in(0), in(1), in(2), in(3), c.options.shift)); break;
    case unit::alpha_blend: {
      const rgb_v v = alpha_blend(r.ALPHA_1, unpack(in(0)), unpack(in(1)), c.options);
      out(0, v.r), out(1, v.g), out(2, v.b);
      break;
    }
    case unit::dither_value: out(0, dither_value(in(0), c.options.dither)); break;
    case unit::dither: {
      if (!gs::dither_applies(r.DTHE.DTHE, psm, c.options)) {
        out(0, in(0)), out(1, in(1)), out(2, in(2));
        break;
      }
      const V offset = dither_offsets(r.DIMX, in(3), in(4), c.options.dither);
      out(0, dither_add(in(0), offset)), out(1, dither_add(in(1), offset)), out(2, dither_add(in(2), offset));
      break;
    }
    case unit::colclamp: out(0, colclamp_channel(in(0), r.COLCLAMP.CLAMP)); break;
    case unit::apply_fba: {
      rgba_v v = unpack(in(0));
      v.a = apply_fba(v.a, r.FBA_1.FBA, psm);
      out(0, pack32(v));
      break;
    }
    case unit::frame_pack: out(0, frame_pack(psm, unpack(in(0)))); break;
    case unit::frame_mask: out(0, frame_mask(psm, in(0))); break;
    case unit::masked_merge: out(0, masked_merge(in(0), in(1), in(2))); break;
  }
}

void run_unit_span(const unit_call& c) {
  for (std::size_t i = 0; i < c.n; i += hn::Lanes(D())) unit_lanes(c, i);
}

}  // namespace gsdot3::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace gsdot3::simd {

HWY_EXPORT(pixel_pipeline_batch);
HWY_EXPORT(run_unit_span);

void pixel_pipeline(const gs::gs_registers& regs, const gs::model_options& o, pixel_batch& batch) {
  HWY_DYNAMIC_DISPATCH(pixel_pipeline_batch)(regs, o, batch);
}

void run_unit(const unit_call& call) { HWY_DYNAMIC_DISPATCH(run_unit_span)(call); }

std::vector<target> available_targets() {
  std::vector<target> out;
  for (const std::int64_t t : hwy::SupportedAndGeneratedTargets()) out.push_back({t, hwy::TargetName(t)});
  return out;
}

std::string current_target() {
  // The dispatch table's choice: the best supported target among those compiled in.
  const std::vector<std::int64_t> ts = hwy::SupportedAndGeneratedTargets();
  return ts.empty() ? "none" : hwy::TargetName(ts.front());
}

void force_target(std::int64_t bits) { hwy::SetSupportedTargetsForTest(bits); }

}  // namespace gsdot3::simd
#endif  // HWY_ONCE
