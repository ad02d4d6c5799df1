// Google Benchmark figures for include/fixed: the cost of each rounding mode (compile-time and
// run-time selected) and of the GS blend term on the width-carrying integers.
#include <benchmark/benchmark.h>

#include <cstdint>

#include "fixed/fixed.hpp"

namespace {

// Sums shift_right<R>(v, 7) over all 2^16 int16_t values (one iteration = 65536 shifts).
template <fixed::rounding R>
void shift_right_all_int16(benchmark::State& state) {
  for (auto _ : state) {
    std::int64_t sum = 0;
    for (std::int32_t v = -32768; v < 32768; ++v) { sum += fixed::shift_right<R>(static_cast<std::int16_t>(v), 7); }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * 65536);
}

void shift_right_runtime_mode(benchmark::State& state) {
  auto r = static_cast<fixed::rounding>(state.range(0));
  for (auto _ : state) {
    benchmark::DoNotOptimize(r);
    std::int64_t sum = 0;
    for (std::int32_t v = -32768; v < 32768; ++v) sum += fixed::shift_right(static_cast<std::int16_t>(v), 7, r);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * 65536);
}

// (A - B) * C >> 7 over all 2^16 (A, C) pairs with B = 0x40: u8 - u8 -> s9, * u8 -> s17, >> 7 -> s10.
void blend_term_integer(benchmark::State& state) {
  const auto b = fixed::u8::literal(0x40);
  for (auto _ : state) {
    std::int64_t sum = 0;
    for (std::int32_t a = 0; a < 256; ++a) {
      for (std::int32_t c = 0; c < 256; ++c) {
        sum +=
            fixed::shift_right<fixed::rounding::floor, 7>((fixed::u8::from_wrapped(a) - b) * fixed::u8::from_wrapped(c))
                .value();
      }
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * 65536);
}

BENCHMARK(shift_right_all_int16<fixed::rounding::floor>);
BENCHMARK(shift_right_all_int16<fixed::rounding::toward_zero>);
BENCHMARK(shift_right_all_int16<fixed::rounding::nearest_ties_up>);
BENCHMARK(shift_right_all_int16<fixed::rounding::nearest_ties_even>);
BENCHMARK(shift_right_runtime_mode)->DenseRange(0, 3);
BENCHMARK(blend_term_integer);

}  // namespace

BENCHMARK_MAIN();
