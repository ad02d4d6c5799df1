// vectors/generate.cpp — case generation through the unit table.
#include "vectors/generate.hpp"

#include <string>

#include "vectors/format.hpp"

namespace gsdot3::vectors {

std::size_t generate(const unit& u, const generate_settings& s, std::ostream& out) {
  if (s.lvl == level::all && !u.exhaustive)
    throw domain_error("unit " + std::string(u.name) + " has no --level all: " + std::string(u.exhaustive_domain));
  out << header_line(u, s.options) << '\n' << fields_comment(u) << '\n';
  std::size_t count = 0;
  const case_sink emit = [&](const values& in) {
    out << case_line(u, in, u.evaluate(in, s.options)) << '\n';
    ++count;
  };
  if (s.lvl == level::all) {
    u.exhaustive(emit);
    return count;
  }
  u.level1(emit);
  if (s.lvl == level::two) {
    random rng(s.seed);
    for (std::size_t i = 0; i < s.random_cases; ++i) u.random_case(rng, emit);
  }
  return count;
}

}  // namespace gsdot3::vectors
