// proofs_triangle certify, certify-class — a certified upper bound on the continuous relaxation of
// two-pass.max-s.interpolated's error bound, class by class: the branch and bound of
// two_pass_triangle/triangle_certify.hpp (its header: the sign-constrained dual, why a fixed dual point certifies a
// whole rectangle of geometries from its four corners, and the exact integer check). Not a benchmark
// and not a test; reproducible (no randomness). A class that closes is proven safe at S and every
// s <= S by the bound's statements (the ball of radius s lies in that of S, the threshold does not
// depend on s).
//
//   proofs_triangle certify S [--truncate-to-8] [FIRST [COUNT]] [--min-cell-log2 N] [--max-cells N] [--box N]
//       the classes (|n| sorted, side threshold) bound_safe_s's reach leaves open at S, most open
//       first (certify::open_classes), classes FIRST ..
//       FIRST + COUNT − 1: one line each (closed or open, rectangles, seconds, the largest certified
//       bound among the closed rectangles, the best attained value in an open one), then the Appendix 2
//       normals of the classes left open (a wrap at S needs one of them)
//   proofs_triangle certify-class S W0 W1 W2 THRESHOLD128 [--min-cell-log2 N] [--max-cells N] [--box N]
//       one class given directly (THRESHOLD128 = 128·relaxation_threshold)
// --min-cell-log2 (default −4): rectangles narrower than 2^N pixels stay open; --max-cells (default
// 2 000 000) per class. Shard the survey by FIRST/COUNT; run it under `nice` on one core.
// --box (default survey_box = 2047; the reduction's own box is 2048, triangle_certify.hpp): the families' box
// side A in pixels. 2047 is enough: the claim's vertices lie in 0 .. 2047 (12.4 window coordinates 0 .. 2047·16), so
// after the reduction's translation (least vertex coordinate = r, moved by less than a pixel) every
// vertex coordinate lies in [0, max − min] ⊂ [0, 2047], and its scaling (λ, μ >= 1) reaches A = 2047;
// the bound's own statements use a, b <= W − 1 = 2047 likewise. A smaller box lowers the relaxation.
//
// Measured (one core, nice, this machine shared; `certify` with its defaults unless given), with the
// thresholds of two_pass_triangle.hpp (the floors give back 16383/16384 or 127/128 of a level, the truncation 127
// units):
//   `83`: all 2 183 classes closed, 38.1 s; `82 --truncate-to-8`: all 2 965 closed, 57.6 s
//   (with --box 2048 one stays open); `83 --truncate-to-8`: 4 967 of 5 270 closed, 303 stop where the
//   relaxation exceeds (the first, pack(67, 73) bottom, +0.018 levels·|n|), 131 s; they hold 1 042 normals.
//   `84` (another machine, 2 cores, the other busy): 3 696 of 3 851 closed, 155 stop where the
//   relaxation exceeds (the first, pack(−73, −67) top, +0.026), 140 s; they hold 557 normals. The value
//   printed is where the branch and bound first meets the excess, not the relaxation's supremum: class
//   (67, 73, 81) given directly with its threshold raised by 32 levels·|n| still exceeds (F1, Y and Z
//   within 1/16 pixel of one column, v -> 2047).
// Earlier, with the thresholds before it (a whole level per floor and per truncation) and --box 2048:
//   `83`: all 1 218 classes closed, 22.8 s: s_max >= 83 under keep_fraction.
//   `84`: 1 939 of 2 071 closed, 132 stop where the relaxation exceeds (e.g. pack(−73, −67) top).
//   `80 --truncate-to-8`: 446 of 446 closed, 9.8 s; `81 --truncate-to-8`: 1 358 of 1 358
//   closed, 24.2 s: s_max >= 81 under truncate_to_8.
//   `82 --truncate-to-8 --min-cell-log2=-2`: 3 008 of 3 010 closed, 58.6 s; the relaxation
//   exceeds for pack(60, 67) bottom (+0.0174 levels·|n|) and pack(61, 66) bottom (+0.0041), so no
//   argument from the bound's statements alone proves s = 82 there (box 2048: also pack(62, 65), +0.0021).
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "two_pass_triangle/relaxation_classes.hpp"
#include "two_pass_triangle/triangle_certify.hpp"
#include "triangle_args.hpp"

namespace tc = gsdot3::proofs::two_pass::triangle::certify;

namespace {

double recheck_seconds = 0;  // the stored-certificate cost, summed over the classes run
std::int64_t recheck_cells = 0, searched_cells = 0;

// Runs one class and prints its line; true if every rectangle closed.
bool run(const tc::problem& pr, std::int64_t box, std::int64_t min_cell, std::int64_t max_cells, const char* label) {
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<tc::closed_cell> cert;
  const tc::outcome r = tc::certify_class(pr, box, min_cell, max_cells, 8, &cert);
  const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // What re-checking a stored certificate would cost: check_dual over the closing (rectangle, y).
  const auto t1 = std::chrono::steady_clock::now();
  std::size_t rechecked = 0;
  for (const auto& c : cert)
    rechecked += tc::check_dual(pr, tc::family_cell(c.family, c.p, c.u0, c.u1, c.v0, c.v1, box), c.pattern, c.y).below;
  recheck_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  recheck_cells += static_cast<std::int64_t>(cert.size());
  for (const auto& c : cert)  // the y_p = w closings need no stored y
    searched_cells += c.y[static_cast<std::size_t>((c.p + 1) % 3)] != tc::dual_grid::value_type{} ||
                      c.y[static_cast<std::size_t>((c.p + 2) % 3)] != tc::dual_grid::value_type{};
  if (rechecked != cert.size()) std::printf("RECHECK FAILED: %zu of %zu\n", cert.size() - rechecked, cert.size());
  const double th = static_cast<double>(pr.threshold128) / 128;
  std::printf(
      "%s|n| = (%d, %d, %d) threshold %.4f: %s, %lld rectangles (%lld closed), %.2f s, largest certified bound %.4f "
      "(margin %+.4f)",
      label, pr.w[0], pr.w[1], pr.w[2], th, r.open_count == 0 ? "CLOSED" : "OPEN", static_cast<long long>(r.cells),
      static_cast<long long>(r.closed), sec, static_cast<double>(r.worst_closed),
      static_cast<double>(r.worst_closed) - th);
  if (r.open_count)
    std::printf(", %lld open, best attained there %.4f (margin %+.4f)", static_cast<long long>(r.open_count),
                r.best_attained, r.best_attained - th);
  std::printf("\n");
  auto print = [](const char* what, const tc::open_cell& c) {
    std::printf("  %s: %s p = %d pattern %02o u [%.6f, %.6f] v [%.6f, %.6f] bound %.4f attained %.4f\n", what,
                tc::family_names[c.family], c.p, c.pattern, double(c.u0) / tc::coord_one, double(c.u1) / tc::coord_one,
                double(c.v0) / tc::coord_one, double(c.v1) / tc::coord_one, static_cast<double>(c.bound), c.attained);
  };
  if (r.exceeds) {
    const auto& c = r.witness;
    print("the relaxation exceeds the threshold at the centre of", c);
    const auto V = tc::family_member(c.family, (c.u0 + c.u1) / 2, (c.v0 + c.v1) / 2, box);
    std::printf("    vertices (%.9f, %.9f), (%.9f, %.9f), (%.9f, %.9f), p = vertex %d; lights (levels, folded):\n",
                double(V[0][0]) / tc::coord_one, double(V[0][1]) / tc::coord_one, double(V[1][0]) / tc::coord_one,
                double(V[1][1]) / tc::coord_one, double(V[2][0]) / tc::coord_one, double(V[2][1]) / tc::coord_one, c.p);
    for (const auto& yk : c.y) {
      const double nk = std::sqrt(yk[0] * yk[0] + yk[1] * yk[1] + yk[2] * yk[2]);
      std::printf("      (%.9f, %.9f, %.9f)\n", nk > 0 ? pr.s * yk[0] / nk : 0, nk > 0 ? pr.s * yk[1] / nk : 0,
                  nk > 0 ? pr.s * yk[2] / nk : 0);
    }
  }
  for (const auto& c : r.open) print("open", c);
  std::fflush(stdout);
  return r.open_count == 0;
}

std::int64_t min_cell_of(int log2) {
  return log2 >= -tc::coord_bits ? std::max<std::int64_t>(1, std::int64_t{1} << (tc::coord_bits + log2)) : 1;
}

// The branch and bound's settings (certify::survey_* by default).
struct bb_args {
  int min_cell_log2 = tc::survey_min_cell_log2;
  std::int64_t max_cells = tc::survey_max_cells, box = tc::survey_box;
};
void add_bb_args(CLI::App& cmd, bb_args& b) {
  cmd.add_option("--min-cell-log2", b.min_cell_log2, "Rectangles narrower than 2^N pixels stay open (default -4)")
      ->check(CLI::Range(-tc::coord_bits, 11));
  cmd.add_option("--max-cells", b.max_cells, "Rectangles per class (default 2000000)")->check(CLI::PositiveNumber);
  cmd.add_option("--box", b.box, "The families' box side, pixels (default 2047)")->check(CLI::Range(1, 4096));
}

struct survey_args {
  gsdot3::tools::search_args search;
  bb_args bb;
  int first = 0, count = 1 << 30;
};

int survey(const survey_args& sa) {
  const auto& args = sa.search;
  const gs::model_options o = args.options();
  const int first = sa.first, count = sa.count;
  const std::int64_t min_cell = min_cell_of(sa.bb.min_cell_log2), max_cells = sa.bb.max_cells, box = sa.bb.box;
  const auto classes = tc::open_classes(args.s, o);
  const int last = std::min<int>(static_cast<int>(classes.size()), first + count);
  std::printf("s = %d (%s), box %lld: %zu open classes; certifying %d .. %d\n", args.s, args.option_name(),
              static_cast<long long>(box), classes.size(), first, last - 1);
  int closed = 0;
  std::vector<tc::open_class> open;
  for (int i = first; i < last; ++i) {
    const auto& c = classes[static_cast<std::size_t>(i)];
    char label[96];
    std::snprintf(label, sizeof label, "#%d (n = pack(%d, %d) %s, over by %lld units) ", i, c.iX, c.iY,
                  c.side > 0 ? "top" : "bottom", static_cast<long long>(c.gap));
    if (run({c.w, args.s, c.threshold128}, box, min_cell, max_cells, label))
      ++closed;
    else
      open.push_back(c);
  }
  const auto normals = tc::normals_in(open, args.s, o);
  std::printf("the %zu normals of the classes left open (pack(iX, iY)):", normals.size());
  for (std::size_t k = 0; k < normals.size(); ++k)
    std::printf("%s(%d, %d)", k % 12 ? " " : "\n  ", normals[k].iX, normals[k].iY);
  std::printf("\n");
  std::printf(
      "s = %d (%s): classes %d .. %d: %d closed, %d open; re-checking the %lld closing (rectangle, y) pairs alone "
      "takes %.3f s "
      "(%lld of them with a searched y, the others y_p = w)\n",
      args.s, args.option_name(), first, last - 1, closed, std::max(0, last - first) - closed,
      static_cast<long long>(recheck_cells), recheck_seconds, static_cast<long long>(searched_cells));
  return 0;
}

struct class_args {
  int s = 0;
  std::array<int, 3> w{};
  std::int64_t threshold128 = 0;
  bb_args bb;
};
}  // namespace

void gsdot3::tools::add_certify_command(CLI::App& app, int& rc) {
  auto sa = std::make_shared<survey_args>();
  CLI::App* cmd =
      app.add_subcommand("certify",
                         "The certified relaxation bound, class by class: certified_relaxation_s, the next-s survey, "
                         "the truncate_to_8 relaxation witness");
  cmd->footer(
      "One line per class (closed or open, rectangles, seconds, margins), then the normals of the classes left open. "
      "`83`: ~40 s, `82 --truncate-to-8`: ~1 min, `84`: ~2.5 min, one core.");
  add_search_args(*cmd, sa->search);
  cmd->add_option("FIRST", sa->first, "The first class (default 0)")->check(CLI::NonNegativeNumber);
  cmd->add_option("COUNT", sa->count, "How many classes (default all)")->check(CLI::PositiveNumber);
  add_bb_args(*cmd, sa->bb);
  cmd->callback([sa, &rc] { rc = survey(*sa); });

  auto ca = std::make_shared<class_args>();
  CLI::App* one = app.add_subcommand("certify-class", "The certified relaxation bound for one class given directly");
  one->footer("Exit status 0 if every rectangle closed, 1 if not.");
  one->add_option("S", ca->s, "The light scale s")->required()->check(CLI::Range(1, 127));
  one->add_option("W0", ca->w[0], "The folded weights |n| (any order)")->required()->check(CLI::Range(0, 127));
  one->add_option("W1", ca->w[1], "")->required()->check(CLI::Range(0, 127));
  one->add_option("W2", ca->w[2], "")->required()->check(CLI::Range(0, 127));
  one->add_option("THRESHOLD128", ca->threshold128, "128·relaxation_threshold (8.7·n units)")->required();
  add_bb_args(*one, ca->bb);
  one->callback([ca, &rc] {
    const tc::problem pr{ca->w, ca->s, ca->threshold128};
    rc = run(pr, ca->bb.box, min_cell_of(ca->bb.min_cell_log2), ca->bb.max_cells, "") ? 0 : 1;
  });
}
