#include "proofs/four_pass.hpp"

#include "proofs/methods.hpp"

namespace gsdot3::proofs::four_pass {

table::table(const gs::model_options& o) : product_(256 * 256), monotone_(256) {
  for (int a = -127; a <= 128; ++a)
    for (int b = -128; b <= 127; ++b) {
      const std::uint32_t dpb =
          gs::rgba8{methods::byte(128 - a), methods::byte(0), methods::byte(0), methods::byte(0)}.to_u32();
      const std::uint32_t out = methods::four_pass_channel(dpb, 0, methods::byte(b + 128), o);
      product_[static_cast<std::size_t>((a + 127) * 256 + (b + 128))] =
          static_cast<std::int16_t>(static_cast<int>(out & 0xFF) - 128);
    }
  for (int a = -127; a <= 128; ++a) {
    bool up = true, down = true;
    for (int b = -127; b <= 127; ++b) {
      up = up && product(a, b) >= product(a, b - 1);
      down = down && product(a, b) <= product(a, b - 1);
    }
    monotone_[static_cast<std::size_t>(a + 127)] = up || down;
  }
}

}  // namespace gsdot3::proofs::four_pass
