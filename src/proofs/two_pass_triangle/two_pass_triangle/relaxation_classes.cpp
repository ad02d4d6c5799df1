#include "two_pass_triangle/relaxation_classes.hpp"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <map>
#include <set>
#include <tuple>

#include "proofs/domains.hpp"
#include "proofs/sweep.hpp"
#include "two_pass_triangle/triangle_certify.hpp"
#include "two_pass_triangle/triangle_relaxation.hpp"
#include "proofs/two_pass.hpp"
#include "two_pass_triangle/two_pass_triangle.hpp"

namespace gsdot3::proofs::two_pass::triangle::certify {

namespace {
using class_key = std::tuple<int, int, int, std::int64_t>;  // |n| sorted, threshold128
// Every (normal, wrap side) whose bound reach_units leaves open at s: f(normal, side, its class, over),
// over = reach + truncation − wrap threshold >= 0 (8.7·n units).
template <class F>
void for_each_open_side(int s, const gs::model_options& o, F&& f) {
  const two_pass::table t(o);
  for (const auto& nm : appendix2_normals()) {
    std::array<int, 3> a{std::abs(nm.iX), std::abs(nm.iY), std::abs(nm.iZ)};
    std::sort(a.begin(), a.end());
    const std::int64_t reach = reach_units({a[0], a[1], a[2]}, s, window_pixels);
    const int e = t.alpha_error(nm);
    for (int side : {1, -1}) {
      const std::int64_t over = reach + truncation_units(nm, side, o) - wrap_threshold_units(nm, e, side, o);
      if (over >= 0) f(nm, side, class_key{a[0], a[1], a[2], relaxation_threshold_units(nm, e, side, o)}, over);
    }
  }
}
}  // namespace

std::vector<open_class> open_classes(int s, const gs::model_options& o) {
  std::map<class_key, std::array<std::int64_t, 4>> open;  // gap, iX, iY, side
  for_each_open_side(s, o, [&](const paper::packed_normal& nm, int side, const class_key& k, std::int64_t over) {
    auto [it, fresh] = open.try_emplace(k, std::array<std::int64_t, 4>{over, nm.iX, nm.iY, side});
    if (!fresh && over > it->second[0]) it->second = {over, nm.iX, nm.iY, side};
  });
  std::vector<open_class> out;
  for (const auto& [k, g] : open)
    out.push_back(
        {g[0], {std::get<0>(k), std::get<1>(k), std::get<2>(k)}, std::get<3>(k), int(g[1]), int(g[2]), int(g[3])});
  std::stable_sort(out.begin(), out.end(), [](const open_class& x, const open_class& y) { return x.gap > y.gap; });
  return out;
}

namespace {
// certify_class with the survey's settings closes the class at s
bool closes(const open_class& c, int s) {
  constexpr std::int64_t min_cell = coord_one >> -survey_min_cell_log2;
  return certify_class({c.w, s, c.threshold128}, survey_box, min_cell, survey_max_cells, 1).open_count == 0;
}
// The indices of the classes that do not close at s, ascending, the classes certified on every core
// (sweep.hpp: chunks merged in order); with `first_only` the classes after the first that does not
// close may be skipped (relaxation_certified needs only whether there is one).
struct still_open {
  std::vector<std::size_t> index;
  void merge(const still_open& later) { index.insert(index.end(), later.index.begin(), later.index.end()); }
};
std::vector<std::size_t> not_closing(const std::vector<open_class>& classes, int s, bool first_only) {
  std::atomic<bool> found{false};
  return sweep<still_open>(
             classes.size(), sweep_config{},
             [&](still_open& acc, std::uint64_t lo, std::uint64_t hi) {
               for (auto i = lo; i < hi && !(first_only && found); ++i)
                 if (!closes(classes[i], s)) acc.index.push_back(i), found = true;
             },
             classes.size())
      .index;
}
}  // namespace

bool relaxation_certified(int s, const gs::model_options& o) {
  return not_closing(open_classes(s, o), s, true).empty();
}

std::vector<open_class> uncertified_classes(int s, const gs::model_options& o) {
  const auto classes = open_classes(s, o);
  std::vector<open_class> out;
  for (const std::size_t i : not_closing(classes, s, false)) out.push_back(classes[i]);
  return out;
}

std::vector<paper::packed_normal> normals_in(const std::vector<open_class>& classes, int s,
                                             const gs::model_options& o) {
  std::set<class_key> keys;
  for (const auto& c : classes) keys.insert({c.w[0], c.w[1], c.w[2], c.threshold128});
  std::vector<paper::packed_normal> out;
  for_each_open_side(s, o, [&](const paper::packed_normal& nm, int, const class_key& k, std::int64_t) {
    // both sides of one normal can be open: list it once
    if (keys.count(k) != 0 && (out.empty() || out.back().iX != nm.iX || out.back().iY != nm.iY)) out.push_back(nm);
  });
  return out;
}

int certified_relaxation_s(const gs::model_options& o) noexcept {
  if (o.setup != gs::gouraud_setup::plane_steps) return 0;
  return o.gouraud == gs::gouraud_fraction::keep_fraction ? 83 : 82;
}

next_s_survey uncertified_next_s(const gs::model_options& o) noexcept {
  if (o.setup != gs::gouraud_setup::plane_steps) return {};
  return o.gouraud == gs::gouraud_fraction::keep_fraction ? next_s_survey{84, 3851, 155, 557}
                                                          : next_s_survey{83, 5270, 303, 1042};
}

}  // namespace gsdot3::proofs::two_pass::triangle::certify
