// The floor of a textured pixel-op's texel fetch on this CPU (issue 30's bound): nearest PSMT8 texels
// through a 32-bit CLUT (the four-pass x, y, z passes' fetch), 64 pixels along a row at a constant
// u step (12.4), REPEAT on a 256×256 map — with Highway gathers (the target dispatch picks: an index
// word gathered at the texel's byte offset, then the CLUT entry gathered by the index) and with scalar
// loads. Nothing else of a pass (attribute walk, units, frame buffer) is in the loop, so the figure is
// what the fetch alone costs per pixel; set against the 4.6 core cycles a pixel-op may take at the GS's
// 1.18 G pixel-ops/s on 2 cores (docs/benchmarks.md).
#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "fetch_bench.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

#ifndef FETCH_BENCH_SHARED  // this file is included once per SIMD target (foreach_target.h)
#define FETCH_BENCH_SHARED
namespace fetch {
constexpr std::size_t batch = 64, size_log2 = 8, size = 1u << size_log2;
struct inputs {
  std::vector<std::uint8_t> index;  // size × size texels, then 3 bytes of padding (a word gathered at the last)
  std::vector<std::uint32_t> clut;  // 256 entries
};
}  // namespace fetch
#endif

HWY_BEFORE_NAMESPACE();
namespace fetch::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// out[i] = clut[index[v·size + ((u0 + i·du) >> 4) mod size]] for i < batch.
void gathered(const inputs& in, std::int32_t u0, std::int32_t du, std::int32_t v, std::uint32_t* out) {
  const hn::ScalableTag<std::int32_t> d;
  const std::size_t lanes = hn::Lanes(d);
  const auto row = hn::Set(d, (v & static_cast<std::int32_t>(size - 1)) << size_log2);
  const auto mask = hn::Set(d, static_cast<std::int32_t>(size - 1));
  auto u = hn::Add(hn::Set(d, u0), hn::Mul(hn::Iota(d, 0), hn::Set(d, du)));
  const auto step = hn::Set(d, du * static_cast<std::int32_t>(lanes));
  const auto* words = reinterpret_cast<const std::int32_t*>(in.clut.data());
  for (std::size_t i = 0; i < batch; i += lanes) {
    const auto offset = hn::Add(row, hn::And(hn::ShiftRight<4>(u), mask));
    const auto index =
        hn::And(hn::GatherOffset(d, reinterpret_cast<const std::int32_t*>(in.index.data()), offset), hn::Set(d, 0xFF));
    hn::StoreU(hn::GatherIndex(d, words, index), d, reinterpret_cast<std::int32_t*>(out + i));
    u = hn::Add(u, step);
  }
}

}  // namespace fetch::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fetch {
HWY_EXPORT(gathered);

void scalar(const inputs& in, std::int32_t u0, std::int32_t du, std::int32_t v, std::uint32_t* out) {
  const std::size_t row = static_cast<std::size_t>(v & static_cast<std::int32_t>(size - 1)) << size_log2;
  for (std::size_t i = 0; i < batch; ++i) {
    const auto u = static_cast<std::size_t>((u0 + static_cast<std::int32_t>(i) * du) >> 4) & (size - 1);
    out[i] = in.clut[in.index[row + u]];
  }
}

inputs make_inputs() {
  inputs in{std::vector<std::uint8_t>(size * size + 3), std::vector<std::uint32_t>(256)};
  std::uint32_t seed = 0x9E3779B9u;
  for (auto& t : in.index) t = static_cast<std::uint8_t>((seed = seed * 1664525u + 1013904223u) >> 24);
  for (auto& c : in.clut) c = seed = seed * 1664525u + 1013904223u;
  return in;
}

// Arg 0: gathers, 1: scalar loads. Rows and starting u vary per batch (the map's rows are L1/L2-resident
// as a pass's are: 64 KiB).
void BM_NearestClutFetch(benchmark::State& state) {
  const inputs in = make_inputs();
  alignas(64) std::uint32_t out[batch];
  const bool simd = state.range(0) == 0;
  std::int32_t v = 0, u0 = 5;
  for (auto _ : state) {
    if (simd)
      HWY_DYNAMIC_DISPATCH(gathered)(in, u0, 13, v, out);
    else
      scalar(in, u0, 13, v, out);
    benchmark::DoNotOptimize(out);
    v = (v + 1) & static_cast<std::int32_t>(size - 1);
    u0 = static_cast<std::int32_t>(out[0] & 0xFFF);  // the next batch depends on this one
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(batch));
  const std::vector<std::int64_t> targets = hwy::SupportedAndGeneratedTargets();  // dispatch picks the first
  state.SetLabel(!simd ? "scalar" : targets.empty() ? "none" : hwy::TargetName(targets.front()));
}
BENCHMARK(BM_NearestClutFetch)->Arg(0)->Arg(1)->ArgName("scalar");

}  // namespace fetch

BENCHMARK_MAIN();
#endif  // HWY_ONCE
