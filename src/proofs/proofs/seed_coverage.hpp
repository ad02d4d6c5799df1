// proofs/seed_coverage.hpp — seed 000 item by item (every numbered step, equation, figure, listing and
// arithmetic statement, in the paper's order) with what covers it: a claim of this catalogue, of
// docs/quality-claims.md or docs/performance-claims.md, a renderer method, or a render option; an
// uncovered row says why. The rows are data, seed_coverage.json beside this file, compiled in;
// `gsdot3 prove --markdown` appends them to docs/claims.md (`gsdot3 prove --coverage` prints them
// alone, after checking every method and option they name against the CLI).
#pragma once

#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace gsdot3::proofs {

struct coverage_row {
  std::string section, item, what;
  std::vector<std::string> covered_by;  // claim ids, "method:NAME", "option:--NAME"
  std::string kind;                     // "claim", "method", "option" (the strongest cover) or "none"
  std::string note;                     // uncovered: why; covered: what is partial or what the verdict says
};

// The embedded seed_coverage.json, parsed on first use (malformed, it throws std::logic_error naming the
// row: a bug of the build, not bad input). parse_seed_coverage throws std::invalid_argument.
const std::vector<coverage_row>& seed_coverage();
std::vector<coverage_row> parse_seed_coverage(std::string_view json);

// What a reference in covered_by is: a claim of the catalogue (no prefix), of the quality or the
// performance ledger (ids "quality.*", "perf.*"), a method or an option.
enum class reference_kind { catalogue_claim, quality_claim, performance_claim, method, option };
reference_kind kind_of(std::string_view reference);

// The rows' problems, one line each ("row 12 (3.1 step 2.1): ..."), empty when there are none: a kind
// that is not one of the four; kind "none" with a cover or a cover without a kind; an uncovered row
// without a note; kind "claim" without a claim id among its references, "method" without a method
// (and no claim), "option" with neither; a reference `resolves` rejects (catalogue ids through
// find_claim; methods, options, quality and performance ids: the layers above know them).
std::vector<std::string> coverage_problems(std::span<const coverage_row> rows,
                                           const std::function<bool(std::string_view)>& resolves);

// The rows as the Markdown section "Coverage of seed 000" of docs/claims.md, with their counts.
std::string coverage_markdown(std::span<const coverage_row> rows);

}  // namespace gsdot3::proofs
