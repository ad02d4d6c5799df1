// fuzz/fuzz_check.hpp — how a harness reports a finding: the message (inputs and both results, in hex)
// on stderr, then abort(), which libFuzzer records as a crash and a replay test as a failure.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

namespace gsdot3::fuzz {

[[noreturn]] inline void fail(const std::string& message) {
  std::fprintf(stderr, "FINDING: %s\n", message.c_str());
  std::fflush(stderr);
  std::abort();
}

// Calls fail(describe()) when ok is false; describe is only evaluated on a finding.
template <typename Describe>
void require(bool ok, Describe&& describe) {
  if (!ok) fail(describe());
}

}  // namespace gsdot3::fuzz
