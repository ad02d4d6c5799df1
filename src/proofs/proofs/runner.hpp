// proofs/runner.hpp — evaluates claims under the chosen model options and under every other value
// of each option the claim depends on, timing each, and notes where the verdict changes.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "gs_arith/options.hpp"
#include "proofs/claim.hpp"

namespace gsdot3::proofs {

// The claim re-evaluated with one option set to another value.
struct option_variant {
  std::string option, value;
  outcome result;
  bool changed = false;  // verdict, counterexample count or a figure differs from the base run
};

struct claim_result {
  const claim* row = nullptr;
  gs::model_options options;  // the base options
  outcome result;
  std::vector<option_variant> variants;
  double seconds = 0;  // base run plus variants, wall clock (shared with the claims running beside it)
};

struct run_config {
  sweep_config sweep;
  // Also evaluate under the other values of each option the claim depends on (not when the base
  // outcome is option_free: every variant would repeat it).
  bool variants = true;
  // Called before and after each claim (may be empty; from the worker threads, as claims run
  // concurrently: run()): the CLI reports progress with them.
  std::function<void(const claim&)> starting, finished;
};

claim_result run_claim(const claim& c, const gs::model_options& base, const run_config& cfg);
std::vector<claim_result> run(const std::vector<const claim*>& claims, const gs::model_options& base,
                              const run_config& cfg);

}  // namespace gsdot3::proofs
