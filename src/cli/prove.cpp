// gsdot3 prove — runs the proof catalogue (src/proofs) and prints its ledger: as a table, as one JSON
// document (--json), or as the Markdown of docs/claims.md (--markdown). Progress goes to stderr for
// claims that take longer than a second. Exit 0 when the catalogue ran (refutations are results),
// 2 for bad arguments or an unknown claim id.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "gs_arith/options.hpp"
#include "gs_arith/profiles.hpp"
#include "proofs/claim.hpp"
#include "proofs/ledger.hpp"
#include "proofs/runner.hpp"

namespace gsdot3::cli {

namespace {
struct prove_args {
  std::vector<std::string> claims, options;
  std::string profile;
  bool json = false, markdown = false, no_variants = false, list = false;
  unsigned threads = 0;
};

// Progress on stderr, only once a claim has run for more than a second.
struct progress_printer {
  std::string label;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last{};
  bool printed = false;
  void update(double fraction) {
    const auto now = std::chrono::steady_clock::now();
    if (now - start < std::chrono::seconds(1) || now - last < std::chrono::milliseconds(500)) return;
    last = now;
    printed = true;
    std::fprintf(stderr, "\rgsdot3 prove: %s %3.0f%%", label.c_str(), fraction * 100.0);
    std::fflush(stderr);
  }
  void finish() {
    if (printed) std::fprintf(stderr, "\rgsdot3 prove: %s done      \n", label.c_str());
  }
};

void run_prove(const prove_args& a, context& ctx) {
  if (a.json && a.markdown) throw usage_error("--json and --markdown are exclusive");
  gs::model_options opts;
  if (!a.profile.empty())
    if (auto err = gs::apply_profile(opts, a.profile)) throw usage_error("--profile: " + *err);
  for (const auto& o : a.options) {
    const auto eq = o.find('=');
    if (eq == std::string::npos || eq == 0) throw usage_error("--option: expected NAME=VALUE, got '" + o + "'");
    if (auto err = gs::set_option(opts, o.substr(0, eq), o.substr(eq + 1))) throw usage_error("--option: " + *err);
  }
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
  auto printer = std::make_shared<progress_printer>();
  proofs::run_config cfg;
  if (a.threads > 0) cfg.sweep.threads = a.threads;
  cfg.variants = !a.no_variants;
  cfg.sweep.progress = [printer](double f) { printer->update(f); };
  cfg.starting = [printer](const proofs::claim& c) {
    printer->finish();
    *printer = progress_printer{std::string(c.id)};
  };
  const auto results = proofs::run(selected, opts, cfg);
  printer->finish();
  if (a.json) std::cout << proofs::ledger_json(results);
  else if (a.markdown) std::cout << proofs::ledger_markdown(results);
  else std::cout << proofs::ledger_text(results);
  ctx.exit_code = 0;
}
}  // namespace

void add_prove_command(CLI::App& app, context& ctx) {
  auto args = std::make_shared<prove_args>();
  auto* cmd = app.add_subcommand("prove", "Settle the paper's claims on the modeled GS: proven, refuted (with witnesses) or bound");
  cmd->add_option("--claim", args->claims, "Claim id to run (repeatable; default: the whole catalogue)");
  cmd->add_option("--option", args->options, "Model option NAME=VALUE for the base run (repeatable)");
  cmd->add_option("--profile", args->profile,
                  "Emulator option set for the base run (" + gs::profile_names() + "); --option overrides it");
  cmd->add_flag("--json", args->json, "Print the ledger as one JSON document");
  cmd->add_flag("--markdown", args->markdown, "Print the ledger as Markdown (docs/claims.md; no timings)");
  cmd->add_flag("--no-variants", args->no_variants, "Skip the re-runs under the other option values");
  cmd->add_option("--threads", args->threads, "Worker threads (default: all cores)")->check(CLI::Range(1U, 256U));
  cmd->add_flag("--list", args->list, "List the claim ids and exit");
  cmd->callback([args, &ctx] {
    if (args->list) {
      for (const auto& c : proofs::catalogue()) std::cout << c.id << "\t" << c.paper << "\n";
      ctx.exit_code = 0;
      return;
    }
    run_prove(*args, ctx);
  });
}

}  // namespace gsdot3::cli
