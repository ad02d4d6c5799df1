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

// gsdot3::simd::pixel_pipeline on full batches (64 pixels) of every register set a four-pass frame
// draws (arg: the index into frame_passes), texels, colours and old words varied per batch: the SIMD
// units with nothing around them, the part of a pixel-op no fetch, walk or frame buffer adds to.
namespace gm = gsdot3::gs_methods;
constexpr const gm::pass_regs* frame_passes[] = {&gm::four_pass_x,      &gm::two_pass_positive, &gm::step1_ambient,
                                                 &gm::four_pass_sphere, &gm::post_add_into_red, &gm::ilp_into_lab,
                                                 &gm::diffuse_layer,    &gm::multiply_red};
constexpr const char* frame_pass_names[] = {"four-pass x, y, z (DECAL, signed multiply, FBMSK)",
                                            "two-pass pass 1 (MODULATE, no blend)",
                                            "step 1 (flat, untextured)",
                                            "four-pass sphere (HIGHLIGHT)",
                                            "2.4 post filter (DECAL, Cs + Cd, red only)",
                                            "2.6 ILP (MODULATE, Cs + Cd, COLCLAMP)",
                                            "3 diffuse layer (DECAL)",
                                            "4 multiply (DECAL, Cs·Ad, one channel)"};
void BM_SimdBatch(benchmark::State& state) {
  const gs::gs_registers regs = frame_passes[state.range(0)]->registers();
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
  state.SetLabel(frame_pass_names[state.range(0)]);
}
BENCHMARK(BM_SimdBatch)->DenseRange(0, 7)->ArgName("pass")->Threads(1)->Threads(2)->UseRealTime();

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
