// A preload library for profiling under valgrind only (bench/callgrind_frame): libhwy 1.0's static
// initialiser calls hwy::platform::TimerResolution(), which executes rdtscp, an instruction
// valgrind 3.19's VEX cannot decode, so every binary linking libhwy (gsdot3, bench_render) dies at
// start-up under callgrind. Both functions are exported from libhwy.so (nm -D), so a preloaded
// definition takes their place; no gsdot3 code reads the timer.
#include <cstdint>

namespace hwy::platform {
std::uint64_t TimerResolution() { return 1; }
double InvariantTicksPerSecond() { return 1e9; }
}  // namespace hwy::platform
