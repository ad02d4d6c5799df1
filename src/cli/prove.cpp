// gsdot3 prove — runs the proof catalogue (src/proofs) and prints its ledger: as a table, as one JSON
// document (--json), or as the Markdown of docs/claims.md (--markdown). Progress goes to stderr for
// claims that take longer than a second. `--shard K/N` and `prove merge` split one claim's sweeps
// across processes (proofs/shard.hpp; docs/sharding.md). Exit 0 when the catalogue ran (refutations are results),
// 2 for bad arguments or an unknown claim id.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "commands.hpp"
#include "model_args.hpp"
#include "output_file.hpp"
#include "gs_arith/options.hpp"
#include "gs_arith/profiles.hpp"
#include "proofs/claim.hpp"
#include "proofs/ledger.hpp"
#include "pipeline/method.hpp"
#include "pipeline/performance_claims.hpp"
#include "pipeline/quality_claims.hpp"
#include "pipeline/scheme_method.hpp"
#include "proofs/runner.hpp"
#include "proofs/seed_coverage.hpp"
#include "proofs/shard.hpp"

namespace gsdot3::cli {

namespace {
struct prove_args {
  std::vector<std::string> claims;
  model_args model{"--option"};
  bool json = false, markdown = false, no_variants = false, list = false, brute_force = false, coverage = false;
  unsigned threads = 0;
  std::string shard, output;       // --shard K/N, --output FILE
  std::vector<std::string> parts;  // prove merge PARTS...
};

// The ledger text on stdout, or into FILE through a temporary name and a rename (no half-written file).
void emit(const std::string& text, const std::string& output) {
  if (output.empty()) {
    std::cout << text;
    return;
  }
  write_output(output, text, "--output");
}

std::string ledger_as(const std::vector<proofs::claim_result>& results, const prove_args& a) {
  if (a.json) return proofs::ledger_json(results);
  if (a.markdown) return proofs::ledger_markdown(results);
  return proofs::ledger_text(results);
}

// Progress on stderr once the run has taken more than a second: claims done and the ones running
// (run() runs several at once), with the sweep's fraction when one claim runs alone. Called from the
// worker threads.
class progress_printer {
 public:
  explicit progress_printer(std::size_t claims) : total_(claims) {}
  void started(std::string_view id) {
    const std::lock_guard lock(m_);
    running_.emplace_back(id);
    fraction_ = -1;
  }
  void finished(std::string_view id) {
    const std::lock_guard lock(m_);
    running_.erase(std::find(running_.begin(), running_.end(), id));
    ++done_;
    fraction_ = -1;
    show();
  }
  void update(double fraction) {
    const std::lock_guard lock(m_);
    fraction_ = fraction;
    show();
  }
  void finish() {
    const std::lock_guard lock(m_);
    if (printed_) print(std::to_string(done_) + " of " + std::to_string(total_) + " claims done\n");
  }

 private:
  void show() {
    const auto now = std::chrono::steady_clock::now();
    if (now - start_ < std::chrono::seconds(1) || now - last_ < std::chrono::milliseconds(500)) return;
    last_ = now, printed_ = true;
    std::string running;
    for (const auto& id : running_) running += (running.empty() ? "" : ", ") + id;
    std::string line = std::to_string(done_) + " of " + std::to_string(total_) + " claims done";
    if (!running.empty()) line += "; running " + running;
    if (running_.size() == 1 && fraction_ >= 0) line += " " + std::to_string(static_cast<int>(fraction_ * 100)) + "%";
    print(line);
  }
  // Over the last line (\r, then spaces where the last line was longer): no terminal escapes in logs.
  void print(const std::string& line) {
    std::fprintf(stderr, "\rgsdot3 prove: %s%*s", line.c_str(),
                 static_cast<int>(last_length_ > line.size() ? last_length_ - line.size() : 0), "");
    std::fflush(stderr);
    last_length_ = line.size();
  }
  std::mutex m_;
  std::size_t total_, done_ = 0;
  std::vector<std::string> running_;
  double fraction_ = -1;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now(), last_{};
  bool printed_ = false;
  std::size_t last_length_ = 0;
};

// Whether a reference of the coverage table names something this program has: a quality or
// performance claim id, a `gsdot3 render --method` or a `gsdot3 render` option.
bool resolves(std::string_view ref, const CLI::App& app) {
  using proofs::reference_kind;
  const std::string r(ref);
  switch (proofs::kind_of(ref)) {
    case reference_kind::catalogue_claim: return proofs::find_claim(ref) != nullptr;
    case reference_kind::quality_claim: {
      const auto ids = pipeline::quality_claim_ids();
      return std::find(ids.begin(), ids.end(), r) != ids.end();
    }
    case reference_kind::performance_claim:
      return std::find(std::begin(pipeline::performance_ids::all), std::end(pipeline::performance_ids::all), ref) !=
             std::end(pipeline::performance_ids::all);
    case reference_kind::method: {
      const std::string_view m = ref.substr(7);
      for (auto gs : pipeline::gs_methods)
        if (pipeline::name(gs) == m) return true;
      return pipeline::find_scheme_method(m) != nullptr;
    }
    case reference_kind::option: {
      const auto render = app.get_subcommands([](const CLI::App* sub) { return sub->get_name() == "render"; });
      return render.size() == 1 && render[0]->get_option_no_throw(r.substr(7)) != nullptr;
    }
  }
  return false;
}

// Seed 000's coverage table as Markdown, after checking every row (a problem is an internal error:
// the table ships with the program, ctest runs this).
std::string coverage_section(const CLI::App& app) {
  const auto& rows = proofs::seed_coverage();
  const auto problems = proofs::coverage_problems(rows, [&](std::string_view r) { return resolves(r, app); });
  if (!problems.empty()) {
    std::string all;
    for (const auto& p : problems) all += "\n  " + p;
    throw std::logic_error("seed_coverage.json:" + all);
  }
  return proofs::coverage_markdown(rows);
}

void run_prove(const prove_args& a, const CLI::App& app, context& ctx) {
  if (a.json && a.markdown) throw usage_error("--json and --markdown are exclusive");
  const gs::model_options opts = a.model.resolve();
  std::vector<const proofs::claim*> selected;
  if (a.claims.empty()) {
    for (const auto& c : proofs::catalogue()) selected.push_back(&c);
  } else {
    for (const auto& id : a.claims) {
      const auto* c = proofs::find_claim(id);
      if (c == nullptr) throw usage_error("--claim: unknown claim id '" + id + "' (gsdot3 prove --list shows them)");
      selected.push_back(c);
    }
  }
  auto printer = std::make_shared<progress_printer>(selected.size());
  proofs::run_config cfg;
  if (a.threads > 0) cfg.sweep.threads = a.threads;
  cfg.variants = !a.no_variants;
  cfg.sweep.brute_force = a.brute_force;
  cfg.sweep.progress = [printer](double f) { printer->update(f); };
  cfg.starting = [printer](const proofs::claim& c) { printer->started(c.id); };
  cfg.finished = [printer](const proofs::claim& c) { printer->finished(c.id); };
  if (!a.shard.empty()) {
    const auto shard = proofs::parse_shard(a.shard);
    if (!shard) throw usage_error("--shard: expected K/N with 0 <= K < N, got '" + a.shard + "'");
    if (selected.size() != 1 || a.claims.empty()) throw usage_error("--shard needs exactly one --claim ID");
    if (!a.json) throw usage_error("--shard writes a partial ledger: add --json");
    cfg.starting(*selected[0]);
    const auto text = proofs::run_shard(*selected[0], opts, cfg, *shard);
    cfg.finished(*selected[0]);
    printer->finish();
    emit(text, a.output);
    ctx.exit_code = 0;
    return;
  }
  const auto results = proofs::run(selected, opts, cfg);
  printer->finish();
  // The whole catalogue's Markdown is docs/claims.md, which ends with seed 000's coverage table.
  emit(ledger_as(results, a) + (a.markdown && a.claims.empty() ? coverage_section(app) : ""), a.output);
  ctx.exit_code = 0;
}

void run_merge(const prove_args& a, context& ctx) {
  if (a.json && a.markdown) throw usage_error("--json and --markdown are exclusive");
  std::vector<std::string> texts;
  for (const auto& path : a.parts) {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw usage_error("merge: cannot read '" + path + "'");
    std::ostringstream ss;
    ss << f.rdbuf();
    texts.push_back(ss.str());
  }
  proofs::run_config cfg;
  if (a.threads > 0) cfg.sweep.threads = a.threads;
  try {
    const auto m = proofs::merge_shards(texts, cfg);
    if (m.recomputed_chunks > 0)
      std::fprintf(stderr, "gsdot3 prove merge: %llu chunks were in no part and were computed here\n",
                   static_cast<unsigned long long>(m.recomputed_chunks));
    emit(ledger_as({m.result}, a), a.output);
  } catch (const std::invalid_argument& e) { throw usage_error(std::string("merge: ") + e.what()); }
  ctx.exit_code = 0;
}
}  // namespace

void add_prove_command(CLI::App& app, context& ctx) {
  auto args = std::make_shared<prove_args>();
  auto* cmd = app.add_subcommand(
      "prove", "Settle the paper's claims on the modeled GS: proven, refuted (with witnesses) or bound");
  cmd->add_option("--claim", args->claims, "Claim id to run (repeatable; default: the whole catalogue)");
  args->model.add_to(cmd, "for the base run");
  cmd->add_flag("--json", args->json, "Print the ledger as one JSON document");
  cmd->add_flag("--markdown", args->markdown, "Print the ledger as Markdown (docs/claims.md; no timings)");
  cmd->add_flag("--no-variants", args->no_variants, "Skip the re-runs under the other option values");
  cmd->add_option("--threads", args->threads, "Worker threads (default: all cores)")->check(CLI::Range(1U, 256U));
  cmd->add_flag("--list", args->list, "List the claim ids and exit");
  cmd->add_flag("--coverage", args->coverage,
                "Print seed 000's coverage table (the last section of docs/claims.md: every step, equation, figure "
                "and statement of the paper with the claim, method or option covering it) and exit");
  cmd->add_option(
      "--shard", args->shard,
      "K/N: evaluate only the K-th of N deterministic slices of the claim's sweeps (0 <= K < N) and write a "
      "partial ledger (needs one --claim and --json; combine the N parts with `prove merge`)");
  cmd->add_option("-o,--output", args->output, "Write the ledger to FILE (atomically) instead of stdout");
  cmd->add_flag(
      "--brute-force", args->brute_force,
      "Claims with a direct enumeration beside their reduction run it instead. two-pass.max-s.interpolated: "
      "the bound's per-channel statements (two_pass_triangle/triangle_brute_force.hpp), for every channel c and both "
      "wrap "
      "sides sigma, exact against the rational plane P_c; a channel is aligned on an axis where sigma times its "
      "exact gradient is < 0, p = r + (a, b) from the reference pixel r: (A) sigma*L_c(p) < sigma*P_c(p) + W where the "
      "channel is aligned on at most one axis, (B) < "
      "sigma*P_c(p) + 1 + a + b and (C) < sigma*P_c(w) + W where it is aligned on both, and the bound's point w "
      "in the closed triangle; at every pixel centre of 2^24 cases (8x8-lattice triangles of the full 2048^2 "
      "window x ordered triples of 4 lights of L_122) in 65536 chunks: a cluster run, split it with --shard "
      "(its cases depend on no model or domain option, so they are checked once, without variants)");
  auto* merge = cmd->add_subcommand("merge",
                                    "Combine the partial ledgers of `prove --claim ID --shard K/N --json` (K = 0..N-1) "
                                    "into the ledger of the unsplit run");
  merge->add_option("parts", args->parts, "Partial ledger files, one per shard, any order")->check(CLI::ExistingFile);
  merge->allow_extras();  // the second and later PARTS (every option takes one value, main.cpp)
  merge->add_flag("--json", args->json, "Print the ledger as one JSON document");
  merge->add_flag("--markdown", args->markdown, "Print the ledger as Markdown");
  merge->add_option("--threads", args->threads, "Worker threads for chunks no part holds (default: all cores)")
      ->check(CLI::Range(1U, 256U));
  merge->add_option("-o,--output", args->output, "Write the ledger to FILE (atomically) instead of stdout");
  merge->callback([args, merge, &ctx] {
    for (const auto& extra : merge->remaining()) {
      if (extra.starts_with("-")) throw usage_error("merge: unknown option '" + extra + "'");
      args->parts.push_back(extra);
    }
    if (args->parts.empty()) throw usage_error("merge: no partial ledger files given");
    run_merge(*args, ctx);
  });
  cmd->callback([args, merge, &app, &ctx] {
    if (merge->parsed()) return;
    if (args->coverage) {
      if (args->json || args->markdown || args->list || !args->claims.empty() || !args->shard.empty())
        throw usage_error("--coverage prints the coverage table alone (Markdown): it takes only --output");
      emit(coverage_section(app), args->output);
      ctx.exit_code = 0;
      return;
    }
    if (args->list) {
      for (const auto& c : proofs::catalogue()) std::cout << c.id << "\t" << c.paper << "\n";
      ctx.exit_code = 0;
      return;
    }
    run_prove(*args, app, ctx);
  });
}

}  // namespace gsdot3::cli
