// vectors/generate.hpp — `gsdot3 vectors gen`: test cases with the model's expected outputs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <ostream>

#include "gs_arith/options.hpp"
#include "vectors/units.hpp"

namespace gsdot3::vectors {

// 1: boundary patterns crossed with every mode; 2: level 1 plus weighted random cases;
// all: the unit's exhaustive domain (only where it is finite and practical).
enum class level { one, two, all };

struct generate_settings {
  level lvl = level::one;
  std::uint64_t seed = 1;
  std::size_t random_cases = 10000;  // added by level 2
  gs::model_options options;
};

// Writes the header line, the field-name comment and one line per case; returns the case count.
// Throws domain_error when `all` is asked of a unit whose domain is not practical to enumerate.
std::size_t generate(const unit& u, const generate_settings& s, std::ostream& out);

}  // namespace gsdot3::vectors
