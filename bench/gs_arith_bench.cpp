// bench_gs_arith — Google Benchmark figures for the GS model: pixels per second through
// gs::pixel_pipeline for a few register sets, the blend unit alone, and the SIMD units (gs_simd) on
// full batches of the methods' passes at 1 and 2 threads: the rate the units alone allow a frame
// (issue 30's bound). Figures, never pass/fail.
#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>

#include "gs_arith/pixel_pipeline.hpp"
#include "gs_arith/registers.hpp"
#include "gs_methods/pass_registers.hpp"
#include "gs_simd/pixel_span.hpp"

namespace {

gs::gs_registers registers_for(int scenario) {
  gs::gs_registers regs;
  switch (scenario) {
    case 0: break;  // neutral: vertex colour written
    case 1:         // blended sprite, (Cs − Cd)·As + Cd
      gs::set_register(regs, "PRIM", 6 | 1 << 6);
      gs::set_register(regs, "ALPHA_1", 0x44);
      break;
    case 2:  // textured MODULATE RGBA, blended, 16-bit frame with dither and FBMSK
      gs::set_register(regs, "PRIM", 6 | 1 << 4 | 1 << 6);
      gs::set_register(regs, "TEX0_1", 1ull << 34);
      gs::set_register(regs, "ALPHA_1", 0x44);
      gs::set_register(regs, "FRAME_1", 0x000000FFull << 32 | 0x02ull << 24);
      gs::set_register(regs, "DTHE", 1);
      gs::set_register(regs, "DIMX", 0x0123456701234567ull);
      break;
    default: break;
  }
  return regs;
}

void BM_PixelPipeline(benchmark::State& state) {
  const gs::gs_registers regs = registers_for(static_cast<int>(state.range(0)));
  const gs::model_options o;
  std::uint32_t colour = 0x80402010u, dst = 0x12345678u;
  unsigned x = 0;
  for (auto _ : state) {
    const gs::pixel_input in{gs::fragment_colour::flat(gs::rgba8::from_u32(colour)), gs::rgba8::from_u32(~colour),
                             dst & 0xFFFFu, x, x >> 2};
    dst = gs::pixel_pipeline(regs, in, o).out;
    colour = colour * 1664525u + 1013904223u;
    ++x;
    benchmark::DoNotOptimize(dst);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_PixelPipeline)->Arg(0)->Arg(1)->Arg(2)->ArgName("scenario");

// gsdot3::simd::pixel_pipeline on full batches (64 pixels) of four-pass's x pass (DECAL, the signed
// multiply blend, FBMSK; arg 0) or two-pass's first pass (MODULATE, no blend; arg 1), texels, colours
// and old words varied per batch: the SIMD units with nothing around them.
void BM_SimdBatch(benchmark::State& state) {
  const gs::gs_registers regs = state.range(0) == 0 ? gsdot3::gs_methods::four_pass_x.registers()
                                                    : gsdot3::gs_methods::two_pass_positive.registers();
  const gs::model_options o;
  gsdot3::simd::pixel_batch b;
  std::uint32_t seed = 0x2545F491u + static_cast<std::uint32_t>(state.thread_index());
  auto next = [&seed] { return seed = seed * 1664525u + 1013904223u; };
  b.n = gsdot3::simd::pixel_batch::capacity;
  for (std::size_t i = 0; i < b.n; ++i) {
    b.texel[i] = next(), b.dst[i] = next();
    for (auto& c : b.cf) c[i] = next() & 0xFFFFu;
    b.x[i] = static_cast<std::uint32_t>(i), b.y[i] = 7;
  }
  for (auto _ : state) {
    gsdot3::simd::pixel_pipeline(regs, o, b);
    b.dst[b.n - 1] ^= b.out[0];  // the next batch depends on this one
    benchmark::DoNotOptimize(b.out);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(b.n));
}
BENCHMARK(BM_SimdBatch)->Arg(0)->Arg(1)->ArgName("pass")->Threads(1)->Threads(2)->UseRealTime();

void BM_BlendChannel(benchmark::State& state) {
  int a = 0;
  for (auto _ : state) {
    const auto v =
        gs::blend_channel(gs::u8::from_wrapped(a), gs::u8::from_wrapped(a >> 8), gs::u8::from_wrapped(a >> 16),
                          gs::u8::from_wrapped(a >> 24), gs::blend_shift::floor);
    benchmark::DoNotOptimize(v);
    a = a * 1103515245 + 12345;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_BlendChannel);

}  // namespace

BENCHMARK_MAIN();
