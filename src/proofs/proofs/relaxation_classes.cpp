#include "proofs/relaxation_classes.hpp"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <set>
#include <tuple>

#include "proofs/domains.hpp"
#include "proofs/triangle_certify.hpp"
#include "proofs/triangle_relaxation.hpp"
#include "proofs/two_pass.hpp"
#include "proofs/two_pass_triangle.hpp"

namespace gsdot3::proofs::two_pass::triangle::certify {

std::vector<open_class> open_classes(int s, const gs::model_options& o) {
  const two_pass::table t(o);
  std::map<std::tuple<int, int, int, std::int64_t>, std::array<std::int64_t, 4>> open;  // gap, iX, iY, side
  for (const auto& nm : appendix2_normals()) {
    std::array<int, 3> a{std::abs(nm.iX), std::abs(nm.iY), std::abs(nm.iZ)};
    std::sort(a.begin(), a.end());
    const std::int64_t reach = reach_units({a[0], a[1], a[2]}, s, window_pixels);
    const int e = t.alpha_error(nm);
    for (int side : {1, -1}) {
      const std::int64_t over = reach + truncation_units(nm, side, o) - wrap_threshold_units(nm, e, side, o);
      if (over < 0) continue;
      const std::int64_t th128 = relaxation_threshold_units(nm, e, side, o);
      auto [it, fresh] = open.try_emplace({a[0], a[1], a[2], th128}, std::array<std::int64_t, 4>{over, nm.iX, nm.iY, side});
      if (!fresh && over > it->second[0]) it->second = {over, nm.iX, nm.iY, side};
    }
  }
  std::vector<open_class> out;
  for (const auto& [k, g] : open)
    out.push_back({g[0], {std::get<0>(k), std::get<1>(k), std::get<2>(k)}, std::get<3>(k), int(g[1]), int(g[2]), int(g[3])});
  std::stable_sort(out.begin(), out.end(), [](const open_class& x, const open_class& y) { return x.gap > y.gap; });
  return out;
}

bool relaxation_certified(int s, const gs::model_options& o) {
  constexpr std::int64_t min_cell = coord_one >> -survey_min_cell_log2;
  for (const auto& c : open_classes(s, o))
    if (certify_class({c.w, s, c.threshold128}, survey_box, min_cell, survey_max_cells, 1).open_count != 0) return false;
  return true;
}

std::vector<open_class> uncertified_classes(int s, const gs::model_options& o) {
  constexpr std::int64_t min_cell = coord_one >> -survey_min_cell_log2;
  std::vector<open_class> out;
  for (const auto& c : open_classes(s, o))
    if (certify_class({c.w, s, c.threshold128}, survey_box, min_cell, survey_max_cells, 1).open_count != 0) out.push_back(c);
  return out;
}

std::vector<paper::packed_normal> normals_in(const std::vector<open_class>& classes, int s, const gs::model_options& o) {
  std::set<std::tuple<int, int, int, std::int64_t>> keys;
  for (const auto& c : classes) keys.insert({c.w[0], c.w[1], c.w[2], c.threshold128});
  const two_pass::table t(o);
  std::vector<paper::packed_normal> out;
  for (const auto& nm : appendix2_normals()) {
    std::array<int, 3> a{std::abs(nm.iX), std::abs(nm.iY), std::abs(nm.iZ)};
    std::sort(a.begin(), a.end());
    const std::int64_t reach = reach_units({a[0], a[1], a[2]}, s, window_pixels);
    const int e = t.alpha_error(nm);
    bool in = false;
    for (int side : {1, -1})
      in = in || (reach + truncation_units(nm, side, o) - wrap_threshold_units(nm, e, side, o) >= 0 &&
                  keys.count({a[0], a[1], a[2], relaxation_threshold_units(nm, e, side, o)}) != 0);
    if (in) out.push_back(nm);
  }
  return out;
}

int certified_relaxation_s(const gs::model_options& o) noexcept {
  if (o.setup != gs::gouraud_setup::plane_steps) return 0;
  return o.gouraud == gs::gouraud_fraction::keep_fraction ? 83 : 82;
}

next_s_survey uncertified_next_s(const gs::model_options& o) noexcept {
  if (o.setup != gs::gouraud_setup::plane_steps) return {};
  return o.gouraud == gs::gouraud_fraction::keep_fraction ? next_s_survey{84, 3851, 155, 557} : next_s_survey{83, 5270, 303, 1042};
}

}  // namespace gsdot3::proofs::two_pass::triangle::certify
