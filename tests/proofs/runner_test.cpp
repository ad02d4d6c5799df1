// Unit tests of the proof framework: accumulators, the sweep engine, the runner and the ledger.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "proofs/claim.hpp"
#include "proofs/ledger.hpp"
#include "proofs/runner.hpp"
#include "proofs/sweep.hpp"
#include "proofs/verdict.hpp"

namespace p = gsdot3::proofs;

TEST(Tally, CountsEverythingAndKeepsTheFirstWitnessesInOrder) {
  p::tally left, right;
  for (std::uint64_t i : {3u, 5u, 8u}) left.add(i);
  for (std::uint64_t i : {10u, 11u, 12u, 13u}) right.add(i);
  left.merge(right);
  EXPECT_EQ(left.count, 7u);
  ASSERT_EQ(left.first.size(), p::witness_cap);
  EXPECT_TRUE(left.first == (std::vector<std::uint64_t>{3, 5, 8, 10}));
}

TEST(Extremes, KeepTheEarliestIndexOnTies) {
  p::extremes a, b;
  a.add(4, 1), a.add(-2, 2), a.add(4, 3);
  b.add(-2, 7), b.add(9, 8);
  a.merge(b);
  EXPECT_EQ(a.min, -2);
  EXPECT_EQ(a.arg_min, 2u);
  EXPECT_EQ(a.max, 9);
  EXPECT_EQ(a.arg_max, 8u);
  EXPECT_TRUE(p::extremes{}.empty());
}

namespace {
// A synthetic domain: index i has value (i·2654435761) mod 1000 − 500; "counterexamples" are the
// multiples of 97. The expected results come from a plain loop.
std::int64_t synthetic(std::uint64_t i) { return static_cast<std::int64_t>((i * 2654435761u) % 1000) - 500; }
struct both {
  p::tally t;
  p::extremes e;
  void merge(const both& l) {
    t.merge(l.t);
    e.merge(l.e);
  }
};
both run_synthetic(std::uint64_t n, unsigned threads) {
  p::sweep_config cfg;
  cfg.threads = threads;
  return p::sweep<both>(n, cfg, [](both& acc, std::uint64_t lo, std::uint64_t hi) {
    for (auto i = lo; i < hi; ++i) {
      acc.e.add(synthetic(i), i);
      if (i % 97 == 0) acc.t.add(i);
    }
  });
}
}  // namespace

TEST(Sweep, SameResultForAnyThreadCountAndEqualToAPlainLoop) {
  for (std::uint64_t n : {0u, 1u, 5u, 1000u, 123457u}) {
    std::uint64_t count = 0;
    std::vector<std::uint64_t> first;
    std::int64_t mn = INT64_MAX, mx = INT64_MIN;
    std::uint64_t amn = 0, amx = 0;
    for (std::uint64_t i = 0; i < n; ++i) {
      if (i % 97 == 0) {
        ++count;
        if (first.size() < p::witness_cap) first.push_back(i);
      }
      if (synthetic(i) < mn) mn = synthetic(i), amn = i;
      if (synthetic(i) > mx) mx = synthetic(i), amx = i;
    }
    for (unsigned threads : {1u, 2u, 3u}) {
      const auto r = run_synthetic(n, threads);
      EXPECT_EQ(r.t.count, count) << "n " << n << " threads " << threads;
      EXPECT_TRUE(r.t.first == first);
      if (n > 0) {
        EXPECT_EQ(r.e.min, mn);
        EXPECT_EQ(r.e.arg_min, amn);
        EXPECT_EQ(r.e.max, mx);
        EXPECT_EQ(r.e.arg_max, amx);
      }
    }
  }
}

// Progress ends with 1.0 exactly once, also when the last chunk finishes while another worker is
// reporting: the first report here is slow (a slow terminal), so the other worker finishes every
// chunk meanwhile (the interleaving that lost the 1.0 before it was reported after the join).
TEST(Sweep, ReportsProgressUpToCompletion) {
  p::sweep_config cfg;
  cfg.threads = 2;
  std::vector<double> seen;
  cfg.progress = [&](double f) {
    seen.push_back(f);
    if (seen.size() == 1) std::this_thread::sleep_for(std::chrono::milliseconds(30));
  };
  p::sweep<p::tally>(100000, cfg, [](p::tally&, std::uint64_t, std::uint64_t) {});
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.back(), 1.0);
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1.0), 1);
  for (double f : seen) EXPECT_GT(f, 0.0);
}

TEST(Catalogue, IdsAreUniqueAndOptionNamesExist) {
  std::set<std::string_view> ids;
  for (const auto& c : p::catalogue()) {
    EXPECT_TRUE(ids.insert(c.id).second) << c.id;
    EXPECT_EQ(p::find_claim(c.id), &c);
    for (auto o : c.depends_on) EXPECT_FALSE(gs::option_value(gs::model_options{}, o).empty()) << c.id << " " << o;
  }
  EXPECT_EQ(p::find_claim("no.such-claim"), nullptr);
}

TEST(Runner, SameOutcomeWithOneAndTwoThreads) {
  // error-bound has the early-exit search; the pruned wrap search is compared in reduction_test;
  // sum-wrap skips whole blocks of runs against running extremes; worst-case's threads split the
  // codes, and its ties (mirror-image cells of equal angle) must not follow the split.
  for (auto id : {"eq5-eq7.split-multiply", "eq9.rgb-sum", "two-pass.error-bound", "four-pass.sum-wrap",
                  "normal-encoding.worst-case"}) {
    const auto* c = p::find_claim(id);
    ASSERT_NE(c, nullptr);
    p::run_config one, two;
    one.sweep.threads = 1, two.sweep.threads = 2;
    one.variants = two.variants = false;
    const auto a = p::run_claim(*c, {}, one).result, b = p::run_claim(*c, {}, two).result;
    EXPECT_EQ(a.result, b.result) << id;
    EXPECT_EQ(a.counterexamples, b.counterexamples) << id;
    EXPECT_EQ(a.figures, b.figures) << id;
    EXPECT_EQ(a.witnesses, b.witnesses) << id;
  }
}

TEST(Runner, ClaimsSideBySideGiveTheSequentialLedgerInOrder) {
  // run() runs up to sweep.threads claims at once; each result must land in its claim's place and
  // equal the claim run alone, and starting / finished must pair up for every claim.
  std::vector<const p::claim*> claims;
  for (auto id : {"eq9.rgb-sum", "eq4.signed-multiply", "appendix2.packing", "highlight.attenuation"})
    claims.push_back(p::find_claim(id));
  p::run_config one, three;
  one.sweep.threads = 1, three.sweep.threads = 3;
  std::mutex m;
  std::multiset<std::string_view> started, finished;
  three.starting = [&](const p::claim& c) {
    const std::lock_guard l(m);
    started.insert(c.id);
  };
  three.finished = [&](const p::claim& c) {
    const std::lock_guard l(m);
    finished.insert(c.id);
  };
  const auto seq = p::run(claims, {}, one), par = p::run(claims, {}, three);
  ASSERT_EQ(par.size(), claims.size());
  for (std::size_t i = 0; i < claims.size(); ++i) {
    EXPECT_EQ(par[i].row, claims[i]);
    EXPECT_EQ(par[i].result.figures, seq[i].result.figures) << claims[i]->id;
    EXPECT_EQ(par[i].result.witnesses, seq[i].result.witnesses) << claims[i]->id;
    EXPECT_EQ(par[i].variants.size(), seq[i].variants.size()) << claims[i]->id;
    EXPECT_EQ(started.count(claims[i]->id), 1u);
    EXPECT_EQ(finished.count(claims[i]->id), 1u);
  }
}

p::outcome throwing_eval(const gs::model_options&, const p::sweep_config&) {
  throw std::logic_error("test.throws: out of range");
}

TEST(Runner, AClaimThatThrowsSideBySideReachesTheCaller) {
  // Run beside another claim on two threads, its exception must come out of run() (a worker thread
  // that let it escape would end the program).
  const p::claim throws{"test.throws", "-", "-", "-", p::method::exhaustive, {}, throwing_eval};
  p::run_config two;
  two.sweep.threads = 2;
  EXPECT_THROW((void)p::run({p::find_claim("eq9.rgb-sum"), &throws}, {}, two), std::logic_error);
}

TEST(Runner, VariantsCoverEveryOtherValueAndFlagChanges) {
  const auto* c = p::find_claim("eq4.signed-multiply");
  ASSERT_NE(c, nullptr);
  const auto r = p::run_claim(*c, {}, p::run_config{});
  ASSERT_EQ(r.variants.size(), 1u);  // blend_shift: floor (base) and truncate
  EXPECT_EQ(r.variants[0].option, "blend_shift");
  EXPECT_EQ(r.variants[0].value, "truncate");
  EXPECT_EQ(r.result.result, p::verdict::proven);
  EXPECT_EQ(r.variants[0].result.result, p::verdict::refuted);
  EXPECT_TRUE(r.variants[0].changed);
}

namespace {
// Two synthetic claims on the same options, counting their evaluations: one outcome option-free.
int evaluations = 0;
p::outcome counted(bool option_free) {
  ++evaluations;
  p::outcome o;
  o.option_free = option_free;
  return o;
}
p::outcome option_free_eval(const gs::model_options&, const p::sweep_config&) { return counted(true); }
p::outcome option_reading_eval(const gs::model_options&, const p::sweep_config&) { return counted(false); }
}  // namespace

TEST(Runner, AnOptionFreeOutcomeIsEvaluatedOnceWithoutVariants) {
  const p::claim reading{
      "test.reads-options", "-", "-", "-", p::method::exhaustive, {"blend_shift", "gouraud_fraction"},
      option_reading_eval};
  const p::claim free{"test.option-free", "-", "-", "-", p::method::exhaustive, {"blend_shift", "gouraud_fraction"},
                      option_free_eval};
  evaluations = 0;
  const auto r = p::run_claim(reading, {}, p::run_config{});
  EXPECT_EQ(r.variants.size(), 2u);  // blend_shift=truncate, gouraud_fraction=truncate_to_8
  EXPECT_EQ(evaluations, 3);
  evaluations = 0;
  const auto f = p::run_claim(free, {}, p::run_config{});
  EXPECT_TRUE(f.variants.empty());
  EXPECT_EQ(evaluations, 1);
}

TEST(Ledger, JsonHasTheIssueSchemaAndMarkdownHasNoTimings) {
  const auto* c = p::find_claim("ilp.dpb-clear-zero");
  ASSERT_NE(c, nullptr);
  const auto results = p::run({c}, {}, p::run_config{});
  const auto doc = nlohmann::json::parse(p::ledger_json(results));
  ASSERT_EQ(doc["claims"].size(), 1u);
  const auto& row = doc["claims"][0];
  for (auto key : {"id", "paper", "statement", "verdict", "domain_size", "counterexamples", "figures", "witnesses",
                   "options", "seconds"})
    EXPECT_TRUE(row.contains(key)) << key;
  EXPECT_EQ(row["id"], "ilp.dpb-clear-zero");
  EXPECT_EQ(row["verdict"], "refuted");
  EXPECT_TRUE(row["figures"].is_object());
  EXPECT_TRUE(row["witnesses"].is_array());
  const auto md = p::ledger_markdown(results);
  EXPECT_EQ(md.find("seconds"), std::string::npos);
  EXPECT_NE(md.find("## ilp.dpb-clear-zero"), std::string::npos);
  const auto text = p::ledger_text(results);
  EXPECT_NE(text.find("seconds"), std::string::npos);
}

TEST(HexDec, ShowsTwosComplementAndDecimal) {
  EXPECT_EQ(p::hexdec(-3), "0xfd (-3)");
  EXPECT_EQ(p::hexdec(127), "0x7f (127)");
  EXPECT_EQ(p::hexdec(-128, 12), "0xf80 (-128)");
}
