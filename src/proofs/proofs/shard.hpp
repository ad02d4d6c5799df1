// proofs/shard.hpp — a claim's sweeps split across processes: `gsdot3 prove --claim ID --shard K/N
// --json` runs shard K of N and writes a partial ledger; `gsdot3 prove merge PARTS...` replays the
// claim with every part's chunks and prints the same ledger as the unsplit run (the mechanism is
// the sweep engine's, proofs/sweep.hpp shard_log).
//
// Partial ledger (JSON): {"partial_ledger": 1, "claim": id, "shard": {"k", "n"}, "options": {every
// model option: value}, "variants": bool, "brute_force": bool, "sweeps": [{"eval", "call", "n", "chunks", "kind",
// "parts": [[chunk, "hex bytes"], ...]}, ...]}. The bytes are the chunks' accumulators as this build
// lays them out: merge parts made by the same gsdot3 binary.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "proofs/runner.hpp"

namespace gsdot3::proofs {

struct shard_id {
  unsigned k = 0, n = 1;
};
// "K/N" with 0 <= K < N, N >= 1; empty when malformed.
std::optional<shard_id> parse_shard(std::string_view text);

std::string run_shard(const claim& c, const gs::model_options& base, const run_config& cfg, shard_id shard);

struct merged {
  claim_result result;
  std::uint64_t recomputed_chunks = 0;  // chunks no part held (computed by the merge itself)
};
// Throws std::invalid_argument (with a one-line reason) unless the parts are one claim, one set of
// options and variants, and shards 0..N−1 of one N, each exactly once.
// A missing shard is named; several as ranges, "3,5-7" of the shards k with !seen[k] (Slurm's --array
// syntax, so that the scheduler can rerun exactly those).
merged merge_shards(const std::vector<std::string>& parts, const run_config& cfg);

// The k with !seen[k], ascending, runs of consecutive k as "A-B": "" when none is missing.
std::string missing_shards(const std::vector<bool>& seen);

}  // namespace gsdot3::proofs
