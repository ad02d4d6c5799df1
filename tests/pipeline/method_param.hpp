// tests/pipeline/method_param.hpp — every GS method as a gtest parameter, named after the method.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "pipeline/method.hpp"

namespace gsdot3::pipeline {

// A GS method's name as a gtest parameter name: "two-pass" -> "two_pass".
inline std::string method_param_name(const ::testing::TestParamInfo<method>& info) {
  std::string n(name(info.param));
  std::replace(n.begin(), n.end(), '-', '_');
  return n;
}

}  // namespace gsdot3::pipeline
