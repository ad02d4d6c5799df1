// The methods' first light passes, as the catalogue claim zprefill.single-light lists them
// (src/proofs/proofs/claims_z_prefill.cpp first_passes): the claim's verdict holds for a method only
// while its first light pass is the register set the claim checked.
#include <gtest/gtest.h>

#include "gs_methods/pass_registers.hpp"
#include "pipeline/pass_table.hpp"

namespace gsdot3::pipeline {
namespace {

TEST(PassTable, FirstLightPassesAreTheOnesZPrefillChecks) {
  EXPECT_EQ(passes::describe(method::two_pass).light.front().regs, &::gsdot3::gs_methods::two_pass_positive);
  EXPECT_EQ(passes::describe(method::three_pass).light.front().regs, &::gsdot3::gs_methods::two_pass_positive);
  EXPECT_EQ(passes::describe(method::four_pass).light.front().regs, &::gsdot3::gs_methods::four_pass_sphere);
  EXPECT_EQ(passes::describe(method::gouraud).light.front().regs, &::gsdot3::gs_methods::gouraud_dot);
  EXPECT_EQ(passes::describe(method::baseline).light.front().regs, &::gsdot3::gs_methods::baseline_add);
  for (const ::gsdot3::gs_methods::pass_regs* p :
       {&::gsdot3::gs_methods::two_pass_positive, &::gsdot3::gs_methods::four_pass_sphere,
        &::gsdot3::gs_methods::gouraud_dot})
    EXPECT_FALSE(p->ABE);  // the claim's argument: the pass replaces the DPB word
}

}  // namespace
}  // namespace gsdot3::pipeline
