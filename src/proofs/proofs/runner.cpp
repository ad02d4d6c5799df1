#include "proofs/runner.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <thread>

namespace gsdot3::proofs {

namespace {
bool same(const outcome& a, const outcome& b) {
  return a.result == b.result && a.counterexamples == b.counterexamples && a.figures == b.figures;
}
}  // namespace

claim_result run_claim(const claim& c, const gs::model_options& base, const run_config& cfg) {
  const auto t0 = std::chrono::steady_clock::now();
  // A shard run or merge numbers the evaluations so that each sweep is matched with its own.
  auto evaluate = [&](const gs::model_options& o) {
    if (cfg.sweep.shard) cfg.sweep.shard->begin_evaluation();
    return c.evaluate(o, cfg.sweep);
  };
  claim_result r{&c, base, evaluate(base), {}, 0};
  if (cfg.variants && !r.result.option_free) {
    for (auto name : c.depends_on) {
      const auto current = gs::option_value(base, name);
      for (const auto& info : gs::option_catalogue()) {
        if (info.name != name) continue;
        for (auto value : info.values) {
          if (value == current) continue;
          gs::model_options o = base;
          gs::set_option(o, name, value);
          option_variant v{std::string(name), std::string(value), evaluate(o), false};
          v.changed = !same(v.result, r.result);
          r.variants.push_back(std::move(v));
        }
      }
    }
    for (const auto& info : domain_option_catalogue()) {
      if (std::find(info.claims.begin(), info.claims.end(), c.id) == info.claims.end()) continue;
      const auto current = domain_option_value(cfg.sweep.domain, info.name);
      for (auto value : info.values) {
        if (value == current) continue;
        run_config d = cfg;
        (void)set_domain_option(d.sweep.domain, info.name, value);
        if (d.sweep.shard) d.sweep.shard->begin_evaluation();
        option_variant v{std::string(info.name), std::string(value), c.evaluate(base, d.sweep), false};
        v.changed = !same(v.result, r.result);
        r.variants.push_back(std::move(v));
      }
    }
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

std::vector<claim_result> run(const std::vector<const claim*>& claims, const gs::model_options& base,
                              const run_config& cfg) {
  // Claims are independent, so up to sweep.threads of them run at once, each sweeping with the same
  // number of threads: the serial parts of one claim (tables built through the model, merges, the
  // ledger's text) overlap another's sweeps. Results come back in the catalogue's order and are the
  // same for any number of threads (sweep.hpp). A shard log counts evaluations in order, so a run
  // with one is sequential.
  // A claim that throws stops the others from starting, and its exception is rethrown here, as in a
  // sequential run (not std::terminate from a worker thread).
  std::vector<claim_result> out(claims.size());
  std::atomic<std::size_t> next{0};
  std::vector<std::exception_ptr> failed(claims.size());
  auto work = [&] {
    for (std::size_t i = next++; i < claims.size(); i = next++) {
      try {
        if (cfg.starting) cfg.starting(*claims[i]);
        out[i] = run_claim(*claims[i], base, cfg);
        if (cfg.finished) cfg.finished(*claims[i]);
      } catch (...) {
        failed[i] = std::current_exception();
        next = claims.size();
      }
    }
  };
  const std::size_t workers =
      cfg.sweep.shard ? 1 : std::min<std::size_t>(std::max(1U, cfg.sweep.threads), claims.size());
  {
    std::vector<std::jthread> pool;
    for (std::size_t t = 1; t < workers; ++t) pool.emplace_back(work);
    work();
  }
  for (const auto& e : failed)
    if (e) std::rethrow_exception(e);
  return out;
}

}  // namespace gsdot3::proofs
