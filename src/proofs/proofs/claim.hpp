// proofs/claim.hpp — one row of the catalogue: a statement of the paper, its domain, its method and
// the predicate, evaluated through the GS model (src/gs_arith) under given model options.
#pragma once

#include <string_view>
#include <vector>

#include "gs_arith/options.hpp"
#include "proofs/sweep.hpp"
#include "proofs/verdict.hpp"

namespace gsdot3::proofs {

enum class method { exhaustive, reduction };
const char* name(method m) noexcept;

struct claim {
  std::string_view id;                       // e.g. "eq4.signed-multiply"
  std::string_view paper;                    // equation / section / appendix of Mikkelsen 2004
  std::string_view statement;                // what the paper asserts, in words
  std::string_view domain;                   // the inputs enumerated (the exact size is in the outcome)
  method how;                                // exhaustive, or a reduction whose argument is beside the code
  std::vector<std::string_view> depends_on;  // model options (gs::option_catalogue names)
  outcome (*evaluate)(const gs::model_options&, const sweep_config&);
  // Which seed the claim comes from: the ledger groups claims under it. The paper's own claims keep
  // the default; the other seeds' rows (src/schemes) name theirs, e.g. "Seed 001: Green 2007, ...".
  std::string_view section = mikkelsen_section;
  static constexpr std::string_view mikkelsen_section = "Seed 000: Mikkelsen 2004, DOT3 Normal Mapping on the PS2";
};

// The catalogue, in the paper's order. Ids are unique.
const std::vector<claim>& catalogue();
const claim* find_claim(std::string_view id) noexcept;

}  // namespace gsdot3::proofs
