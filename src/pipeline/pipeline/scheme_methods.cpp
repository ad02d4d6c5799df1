// pipeline/scheme_methods.cpp — the one table of the other seeds' methods in the report. A scheme
// adds one row here; its render function lives with the scheme's pipeline glue.
#include <algorithm>

#include "pipeline/scheme_method.hpp"
#include "pipeline/scheme_valve.hpp"

namespace gsdot3::pipeline {

const std::vector<scheme_method>& scheme_methods() {
  static const std::vector<scheme_method> rows = {
      {"rnm", "001 (Green 2007)", "RGB8 normal N = 2t − 1, D = saturate(N·B)²/Σ, Σ D_i·saturate(B_i·T) (Listing 1, fp32)", true,
       render_valve_rnm},
      {"ssbump", "001 (Green 2007)", "RGB8 D from normal2ssbump of the same map, Σ t_i·saturate(B_i·T) (Listing 2, fp32)", true,
       render_valve_ssbump},
  };
  return rows;
}

const scheme_method* find_scheme_method(std::string_view name) noexcept {
  const auto& rows = scheme_methods();
  const auto it = std::find_if(rows.begin(), rows.end(), [&](const scheme_method& m) { return m.name == name; });
  return it == rows.end() ? nullptr : &*it;
}

}  // namespace gsdot3::pipeline
