// bench_gs_arith — Google Benchmark figures for the GS model: pixels per second through
// gs::pixel_pipeline for a few register sets, and the blend unit alone. Figures, never pass/fail.
#include <benchmark/benchmark.h>

#include <cstdint>

#include "gs_arith/pixel_pipeline.hpp"
#include "gs_arith/registers.hpp"

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
