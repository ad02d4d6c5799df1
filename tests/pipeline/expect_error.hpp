// tests/pipeline/expect_error.hpp — the input readers' error contract: f() throws a
// std::runtime_error whose one-line message contains `part`.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

namespace gsdot3::pipeline::test {

inline void expect_error(const std::function<void()>& f, const std::string& part) {
  try {
    f();
    FAIL() << "no error; expected one containing '" << part << "'";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(part), std::string::npos) << "message: " << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << "message spans lines: " << what;
  }
}

}  // namespace gsdot3::pipeline::test
