// fixed/fixed.hpp — the whole library: rounding, overflow, width-carrying integers, fixed point.
#pragma once

#include "fixed/fixed_point.hpp"
#include "fixed/integer.hpp"
#include "fixed/ios.hpp"
#include "fixed/overflow.hpp"
#include "fixed/rounding.hpp"
