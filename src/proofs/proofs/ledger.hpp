// proofs/ledger.hpp — the ledger of a run in three forms: a terminal table, one JSON document, and the
// Markdown of docs/claims.md (no timings, so the file is reproducible).
#pragma once

#include <string>
#include <vector>

#include "proofs/runner.hpp"

namespace gsdot3::proofs {

std::string ledger_text(const std::vector<claim_result>& results);
// {"claims": [{"id", "paper", "statement", "verdict", "domain_size", "counterexamples", "figures": {...},
//   "witnesses": [...], "options": {...}, "seconds", "domain", "method", "note", "variants": [...]}]}
std::string ledger_json(const std::vector<claim_result>& results);
std::string ledger_markdown(const std::vector<claim_result>& results);

}  // namespace gsdot3::proofs
