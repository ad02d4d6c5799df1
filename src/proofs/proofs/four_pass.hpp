// proofs/four_pass.hpp — section 3.6's per-channel signed multiplication as a table built through the
// model (methods::four_pass_channel), for the claims that sum it over large vector sets.
#pragma once

#include <cstdint>
#include <vector>

#include "gs_arith/options.hpp"
#include "proofs/domains.hpp"

namespace gsdot3::proofs::four_pass {

// product(a, b): the DPB channel after the pass minus 128, for the sphere-map component a ∈ [−127, 128]
// (DPB byte a2 = 128 − a) and the normal-map component b ∈ [−128, 127] (palette alpha b2 = b + 128).
class table {
 public:
  explicit table(const gs::model_options& o);
  int product(int a, int b) const noexcept { return product_[static_cast<std::size_t>((a + 127) * 256 + (b + 128))]; }
  const std::int16_t* row(int a) const noexcept { return &product_[static_cast<std::size_t>((a + 127) * 256 + 128)]; }
  // Whether product(a, ·) is monotone in b (checked when the table is built).
  bool monotone(int a) const noexcept { return monotone_[static_cast<std::size_t>(a + 127)]; }
  int dot(const ivec3& a, const ivec3& b) const noexcept {
    return product(a[0], b[0]) + product(a[1], b[1]) + product(a[2], b[2]);
  }

 private:
  std::vector<std::int16_t> product_;
  std::vector<bool> monotone_;
};

}  // namespace gsdot3::proofs::four_pass
