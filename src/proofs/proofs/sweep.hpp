// proofs/sweep.hpp — the one enumeration engine: a domain of n indices, split into chunks that the
// worker threads take in turn; each chunk fills its own accumulator and the accumulators are merged
// in chunk order, so every result (counts, extremes, first witnesses) is identical for any number
// of threads.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <thread>
#include <vector>

namespace gsdot3::proofs {

struct sweep_config {
  unsigned threads = std::max(1U, std::thread::hardware_concurrency());
  // Called now and then with the fraction of the current sweep done (from worker threads, one at a
  // time); the CLI prints progress on stderr with it. May be empty.
  std::function<void(double)> progress;
};

// Runs body(acc, begin, end) over [0, n) in chunks; Acc needs a default constructor and
// merge(const Acc& later). Chunk boundaries depend only on n.
template <class Acc, class Body>
Acc sweep(std::uint64_t n, const sweep_config& cfg, Body&& body) {
  constexpr std::uint64_t max_chunks = 512;
  const std::uint64_t chunk = std::max<std::uint64_t>(1, (n + max_chunks - 1) / max_chunks);
  const std::uint64_t chunks = n == 0 ? 0 : (n + chunk - 1) / chunk;
  std::vector<Acc> parts(chunks);
  std::atomic<std::uint64_t> next{0};
  std::atomic<std::uint64_t> done{0};
  std::atomic_flag reporting = ATOMIC_FLAG_INIT;
  auto work = [&] {
    for (std::uint64_t c = next++; c < chunks; c = next++) {
      const std::uint64_t begin = c * chunk;
      body(parts[c], begin, std::min(n, begin + chunk));
      const auto d = ++done;
      if (cfg.progress && !reporting.test_and_set()) {
        cfg.progress(static_cast<double>(d) / static_cast<double>(chunks));
        reporting.clear();
      }
    }
  };
  const unsigned workers = static_cast<unsigned>(std::min<std::uint64_t>(std::max(1U, cfg.threads), chunks));
  std::vector<std::jthread> pool;
  for (unsigned t = 1; t < workers; ++t) pool.emplace_back(work);
  work();
  pool.clear();  // joins
  Acc all{};
  for (const auto& p : parts) all.merge(p);
  return all;
}

// Several accumulators swept together.
template <class A, class B>
struct pair_acc {
  A first{};
  B second{};
  void merge(const pair_acc& later) {
    first.merge(later.first);
    second.merge(later.second);
  }
};

}  // namespace gsdot3::proofs
