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

#include "gs_arith/options.hpp"

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

// Counts and prints results, honouring the error cap and --errorstop.
class reporter {
 public:
  reporter(std::ostream& out, const verify_settings& s) : out_(out), s_(s) {}

  void pass() { ++r_.passed; }
  void mismatch(const std::string& inputs, const std::string& observed, const std::string& expected) {
    fail(inputs + " => " + observed + " expected: " + expected);
  }
  void malformed(std::size_t line, const std::string& why) {
    fail("line " + std::to_string(line) + ": malformed: " + why);
  }
  bool stopped() const { return s_.errorstop && r_.failed > 0; }
  verify_result finish() {
    out_ << r_.passed << " passed, " << r_.failed << " failed\n";
    return r_;
  }

 private:
  void fail(const std::string& text) {
    ++r_.failed;
    if (s_.max_errors == 0 || r_.failed <= s_.max_errors) {
      out_ << text << '\n';
    } else if (r_.failed == s_.max_errors + 1) {
      out_ << "... further failures not shown (--errors " << s_.max_errors << ")\n";
    }
  }
  std::ostream& out_;
  const verify_settings& s_;
  verify_result r_;
};

// The NAME=VALUE overrides of `s` applied to `o`; throws format_error for an unknown name or value.
void apply_overrides(gs::model_options& o, const verify_settings& s);

// A gsdot3 vector file. Throws format_error ("line N: ...") when the header is missing or invalid:
// without it no line can be checked.
verify_result verify_vectors(std::istream& in, std::ostream& report, const verify_settings& s);

// The ps2autotests gs/blend.expected format (see ../shared/hw/README.md): each sample is the
// recorded hardware result of drawing `dst` unblended, then `src` blended with ALPHA_1 = ABCD/FIX,
// COLCLAMP = 1, PSMCT32; the model runs the same two pixels through gs::pixel_pipeline. The
// recorded value is the observed one. Throws format_error when no line is an 'ABCD: ...' mode line (not
// such a recording); a malformed line in a recording is a failure.
verify_result verify_ps2autotests(std::istream& in, std::ostream& report, const verify_settings& s);

}  // namespace gsdot3::vectors
