// pipeline/scheme_methods.cpp — the one table of the other seeds' methods in the report. A scheme
// adds one row here; its render function lives with the scheme's pipeline glue.
#include <algorithm>

#include "pipeline/scheme_method.hpp"

namespace gsdot3::pipeline {

const std::vector<scheme_method>& scheme_methods() {
  static const std::vector<scheme_method> rows = {
  };
  return rows;
}

const scheme_method* find_scheme_method(std::string_view name) noexcept {
  const auto& rows = scheme_methods();
  const auto it = std::find_if(rows.begin(), rows.end(), [&](const scheme_method& m) { return m.name == name; });
  return it == rows.end() ? nullptr : &*it;
}

}  // namespace gsdot3::pipeline
