// proofs/sweep.hpp — the one enumeration engine: a domain of n indices, split into chunks that the
// worker threads take in turn; each chunk fills its own accumulator and the accumulators are merged
// in chunk order, so every result (counts, extremes, first witnesses) is identical for any number
// of threads.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <typeinfo>
#include <thread>
#include <vector>

#include "proofs/domain_options.hpp"

namespace gsdot3::proofs {

// Sharding splits a sweep across processes (machines) the way the thread pool splits it across
// threads: by chunk. Shard k of n evaluates the chunks c with floor(c·n / chunks) == k (a contiguous
// run) of every sweep a claim makes and records their accumulators, in call order, as bytes; a
// merge replays the claim with the union of the recorded chunks in place of computing them (and
// computes any chunk no part holds, e.g. when a claim's control flow took another path in a shard),
// merging in chunk order as always — so the merged outcome is the unsplit one.
struct chunk_record {
  std::uint64_t chunk = 0;
  std::string bytes;  // the chunk's accumulator, sizeof(Acc) bytes
};
// A sweep is identified by the evaluation it belongs to (the base run, then each option variant),
// its call number within it, its size and chunk count and the type of its body (one per call site;
// parts must come from the same build). A shard whose partial results made it call more sweeps
// than the whole run does (a search that would have stopped) records them in vain; one that called
// fewer, or others, leaves chunks the merge computes itself.
struct sweep_record {
  std::uint64_t eval = 0, call = 0, n = 0, chunks = 0, kind = 0;
  std::vector<chunk_record> parts;  // ascending chunk
  bool same_sweep(const sweep_record& o) const noexcept {
    return eval == o.eval && call == o.call && n == o.n && chunks == o.chunks && kind == o.kind;
  }
};
struct shard_log {
  enum class mode { record, replay };
  mode m = mode::record;
  unsigned k = 0, n = 1;             // record: this shard
  std::vector<sweep_record> sweeps;  // record: this shard's sweeps; replay: every part's
  std::uint64_t eval = 0, next = 0;  // the current evaluation and its next sweep call
  std::uint64_t recomputed = 0;      // replay: chunks no part held
  void begin_evaluation() noexcept { ++eval, next = 0; }
};

struct sweep_config {
  unsigned threads = std::max(1U, std::thread::hardware_concurrency());
  // Called now and then with the fraction of the current sweep done (from worker threads, one at a
  // time); the CLI prints progress on stderr with it. May be empty.
  std::function<void(double)> progress;
  // Set for a shard run or a merge (see shard_log); sweeps are then called one at a time.
  std::shared_ptr<shard_log> shard;
  // A claim with a direct enumeration besides its reduction evaluates that instead (--brute-force).
  bool brute_force = false;
  // The input-set choices of the claims (proofs/domain_options.hpp).
  domain_options domain;
};

// Runs body(acc, begin, end) over [0, n) in chunks; Acc needs a default constructor and
// merge(const Acc& later). Chunk boundaries depend only on n and max_chunks (a sweep whose indices
// are costly asks for more, so that shards can be small).
template <class Acc, class Body>
Acc sweep(std::uint64_t n, const sweep_config& cfg, Body&& body, std::uint64_t max_chunks = 512) {
  const std::uint64_t chunk = std::max<std::uint64_t>(1, (n + max_chunks - 1) / max_chunks);
  const std::uint64_t chunks = n == 0 ? 0 : (n + chunk - 1) / chunk;
  std::vector<Acc> parts(chunks);
  // Which chunks this process computes (all of them unless sharded).
  std::vector<std::uint64_t> to_run;
  shard_log* log = cfg.shard.get();
  sweep_record recorded;
  if (log != nullptr) {
    if constexpr (!std::is_trivially_copyable_v<Acc>) {
      throw std::logic_error("sweep: this claim's accumulator cannot be sharded");
    } else {
      const sweep_record key{log->eval, log->next++, n, chunks, typeid(Body).hash_code(), {}};
      std::vector<bool> have(chunks, false);
      if (log->m == shard_log::mode::replay)
        for (const auto& r : log->sweeps)
          if (r.same_sweep(key))
            for (const auto& p : r.parts)
              if (p.chunk < chunks && p.bytes.size() == sizeof(Acc) && !have[p.chunk]) {
                std::memcpy(static_cast<void*>(&parts[p.chunk]), p.bytes.data(), sizeof(Acc));
                have[p.chunk] = true;
              }
      recorded = key;
      for (std::uint64_t c = 0; c < chunks; ++c) {
        const bool mine = log->m == shard_log::mode::record ? c * log->n / chunks == log->k : !have[c];
        if (mine) to_run.push_back(c);
      }
      if (log->m == shard_log::mode::replay) log->recomputed += to_run.size();
    }
  } else {
    for (std::uint64_t c = 0; c < chunks; ++c) to_run.push_back(c);
  }
  std::atomic<std::uint64_t> next{0};
  std::atomic<std::uint64_t> done{0};
  std::atomic_flag reporting = ATOMIC_FLAG_INIT;
  auto work = [&] {
    for (std::uint64_t t = next++; t < to_run.size(); t = next++) {
      const std::uint64_t c = to_run[t];
      const std::uint64_t begin = c * chunk;
      body(parts[c], begin, std::min(n, begin + chunk));
      const auto d = ++done;
      // A chunk's report is skipped while another worker reports; 1.0 comes once, after the join.
      if (cfg.progress && d < to_run.size() && !reporting.test_and_set()) {
        cfg.progress(static_cast<double>(d) / static_cast<double>(to_run.size()));
        reporting.clear();
      }
    }
  };
  const unsigned workers = static_cast<unsigned>(std::min<std::uint64_t>(std::max(1U, cfg.threads), to_run.size()));
  std::vector<std::jthread> pool;
  for (unsigned t = 1; t < workers; ++t) pool.emplace_back(work);
  work();
  pool.clear();  // joins
  if (cfg.progress && !to_run.empty()) cfg.progress(1.0);
  if constexpr (std::is_trivially_copyable_v<Acc>) {
    if (log != nullptr && log->m == shard_log::mode::record) {
      for (auto c : to_run)
        recorded.parts.push_back({c, std::string(reinterpret_cast<const char*>(&parts[c]), sizeof(Acc))});
      log->sweeps.push_back(std::move(recorded));
    }
  }
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
