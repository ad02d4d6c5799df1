// Whole frames of the default scene (512×448, 416 triangles, two lights) through the GS model, per
// method, and the float reference. Counters: frames/s and Mpixel-ops/s, where a pixel-op is one
// pixel through gs::pixel_pipeline (the renderer counts them: frame::pixel_ops).
//   build/<dir>/bench/bench_render --benchmark_min_time=2
#include <benchmark/benchmark.h>

#include "pipeline/default_scene.hpp"
#include "pipeline/reference.hpp"
#include "pipeline/render.hpp"

namespace {

using namespace gsdot3::pipeline;

const scene& default_frame_scene() {
  static const scene s = default_scene();
  return s;
}

void frame_bench(benchmark::State& state, method m, bool memory_path = false, bool simd = true) {
  const scene& s = default_frame_scene();
  const prepared_scene ps = prepare(s);
  render_options o;
  o.threads = static_cast<int>(state.range(0));
  o.memory_path = memory_path;
  o.simd = simd;
  double ops = 0;
  for (auto _ : state) {
    const frame f = render(s, ps, m, o);
    ops = static_cast<double>(f.pixel_ops);
    benchmark::DoNotOptimize(f.colour.data());
  }
  state.counters["frames/s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["Mpixel-ops/s"] =
      benchmark::Counter(ops * static_cast<double>(state.iterations()) / 1e6, benchmark::Counter::kIsRate);
  state.counters["pixel-ops/frame"] = ops;
}

void BM_TwoPass(benchmark::State& st) { frame_bench(st, method::two_pass); }
void BM_FourPass(benchmark::State& st) { frame_bench(st, method::four_pass); }
void BM_Baseline(benchmark::State& st) { frame_bench(st, method::baseline); }

// render_options::memory_path: the frame buffers in the modelled GS local memory.
void BM_TwoPassMemory(benchmark::State& st) { frame_bench(st, method::two_pass, true); }
void BM_FourPassMemory(benchmark::State& st) { frame_bench(st, method::four_pass, true); }
void BM_BaselineMemory(benchmark::State& st) { frame_bench(st, method::baseline, true); }

// render_options::simd = false (`--scalar`): every pixel through the scalar gs::pixel_pipeline.
void BM_TwoPassScalar(benchmark::State& st) { frame_bench(st, method::two_pass, false, false); }
void BM_FourPassScalar(benchmark::State& st) { frame_bench(st, method::four_pass, false, false); }
void BM_BaselineScalar(benchmark::State& st) { frame_bench(st, method::baseline, false, false); }
void BM_FourPassMemoryScalar(benchmark::State& st) { frame_bench(st, method::four_pass, true, false); }

void BM_FloatReference(benchmark::State& state) {
  const scene& s = default_frame_scene();
  const prepared_scene ps = prepare(s);
  const frame f = render(s, ps, method::four_pass, {});
  for (auto _ : state) {
    const reference_frame r = render_reference(s, ps, f.visible_triangle, false);
    benchmark::DoNotOptimize(r.colour.data());
  }
  state.counters["frames/s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

}  // namespace

BENCHMARK(BM_TwoPass)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FourPass)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Baseline)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TwoPassMemory)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FourPassMemory)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BaselineMemory)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TwoPassScalar)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FourPassScalar)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BaselineScalar)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FourPassMemoryScalar)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FloatReference)->UseRealTime()->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
