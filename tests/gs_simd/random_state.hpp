// Random register sets and model options for the gs_simd properties (rapidcheck generators; call inside a property).
#pragma once

#include <rapidcheck.h>

#include <cstddef>
#include <cstdint>

#include "gs_arith/options.hpp"
#include "gs_arith/registers.hpp"

namespace gsdot3::simd::test {

inline constexpr gs::frame_psm formats[] = {gs::frame_psm::PSMCT32,  gs::frame_psm::PSMCT24, gs::frame_psm::PSMCT16,
                                            gs::frame_psm::PSMCT16S, gs::frame_psm::PSMZ32,  gs::frame_psm::PSMZ24,
                                            gs::frame_psm::PSMZ16,   gs::frame_psm::PSMZ16S};

inline gs::model_options random_options() {
  gs::model_options o;
  o.tfx = *rc::gen::element(gs::tfx_rounding::floor, gs::tfx_rounding::truncate);
  o.gouraud = *rc::gen::element(gs::gouraud_fraction::keep_fraction, gs::gouraud_fraction::truncate_to_8);
  o.shift = *rc::gen::element(gs::blend_shift::floor, gs::blend_shift::truncate);
  o.dither = *rc::gen::element(gs::dither_decode::twos_complement, gs::dither_decode::sign_magnitude,
                               gs::dither_decode::inverted_magnitude);
  o.dither_on = *rc::gen::element(gs::dither_targets::sixteen_bit_only, gs::dither_targets::all_formats);
  o.rgb_only = *rc::gen::element(gs::rgb_only_targets::thirty_two_bit_only, gs::rgb_only_targets::all_formats);
  return o;
}

inline gs::gs_registers random_registers() {
  gs::gs_registers r;
  r.PRIM.TME = *rc::gen::arbitrary<bool>();
  r.PRIM.ABE = *rc::gen::arbitrary<bool>();
  r.TEX0_1.TFX = static_cast<gs::tfx>(*rc::gen::inRange(0, 4));
  r.TEX0_1.TCC = *rc::gen::element(gs::tcc::RGB, gs::tcc::RGBA);
  auto colour = [] { return static_cast<gs::blend_colour>(*rc::gen::inRange(0, 3)); };
  r.ALPHA_1 = {colour(), colour(), static_cast<gs::blend_alpha>(*rc::gen::inRange(0, 3)), colour(),
               gs::u8::from_wrapped(*rc::gen::inRange(0, 256))};
  r.TEST_1 = {*rc::gen::arbitrary<bool>(), static_cast<gs::atst>(*rc::gen::inRange(0, 8)),
              gs::u8::from_wrapped(*rc::gen::inRange(0, 256)), static_cast<gs::afail>(*rc::gen::inRange(0, 4))};
  r.FRAME_1.PSM = formats[*rc::gen::inRange(0, 8)];
  r.FRAME_1.FBMSK = *rc::gen::oneOf(rc::gen::just(0u), rc::gen::arbitrary<std::uint32_t>());
  r.COLCLAMP.CLAMP = *rc::gen::arbitrary<bool>();
  r.PABE.PABE = *rc::gen::arbitrary<bool>();
  r.FBA_1.FBA = *rc::gen::arbitrary<bool>();
  r.DTHE.DTHE = *rc::gen::arbitrary<bool>();
  for (auto& row : r.DIMX.DM)
    for (auto& dm : row) dm = gs::u3::from_wrapped(*rc::gen::inRange(0, 8));
  return r;
}

}  // namespace gsdot3::simd::test
