// vectors/verify.hpp — `gsdot3 vectors ver`: check observed outputs against the model.
//
// Report lines (TestFloat style):
//   <inputs> => <observed> expected: <expected>      a mismatch, fields in hex
//   line <N>: malformed: <why>                       a line that could not be checked (counts as failed)
//   ... further failures not shown (--errors <cap>)  once, when the cap is reached
//   <P> passed, <F> failed                           always the last line
#pragma once

#include <cstddef>
#include <istream>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace gsdot3::vectors {

struct verify_settings {
  std::size_t max_errors = 20;  // failures reported in full; 0 = all
  bool errorstop = false;       // stop at the first failure
  // NAME=VALUE model options applied on top of the file's (or the defaults for ps2autotests).
  std::vector<std::pair<std::string, std::string>> option_overrides;
};

struct verify_result {
  std::size_t passed = 0, failed = 0;
};

// A gsdot3 vector file. Throws format_error ("line N: ...") when the header is missing or invalid:
// without it no line can be checked.
verify_result verify_vectors(std::istream& in, std::ostream& report, const verify_settings& s);

// The ps2autotests gs/blend.expected format (see ../shared/hw/README.md): each sample is the
// recorded hardware result of drawing `dst` unblended, then `src` blended with ALPHA_1 = ABCD/FIX,
// COLCLAMP = 1, PSMCT32; the model runs the same two pixels through gs::pixel_pipeline. The
// recorded value is the observed one.
verify_result verify_ps2autotests(std::istream& in, std::ostream& report, const verify_settings& s);

}  // namespace gsdot3::vectors
