// normal_encoding/seed_psnr.hpp — seed 002's quality measure, as its notes define it: "n1 is actual
// normal, and n2 is normal encoded into a texture, read back & decoded. MSE and PSNR is computed on
// the difference (abs(n1-n2)) image". The difference image holds |n1 − n2| per channel in normal
// units, clamped to [0, 1] as a render target clamps; MSE is the mean of its squares over pixels and
// the 3 channels; PSNR = −10·log10(MSE) (peak 1). The published pairs fit that peak: MSE 0.0000054
// with 52.661 dB and 0.0312331 with 15.054 dB (−10·log10 of each). A decode that is not finite counts
// as a full-scale error (1 in every channel) and is counted apart.
// `image_bits` > 0 stores each difference as a unorm of that many bits first (round to nearest), as
// an 8-bit difference image would; 0 keeps it exact (the seed's xyz figure fits exact, see README).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "normal_encoding/vec.hpp"

namespace gsdot3::normal_encoding {

struct seed_error {
  std::size_t samples = 0, nonfinite = 0;
  double mse = 0, psnr = 0;  // psnr = +inf when mse = 0
};

class seed_error_sum {
 public:
  explicit seed_error_sum(int image_bits = 0) noexcept
      : levels_(image_bits > 0 ? std::ldexp(1.0, image_bits) - 1 : 0) {}
  void add(vec3 actual, vec3 decoded) noexcept {
    ++samples_;
    if (!finite(decoded)) {
      ++nonfinite_;
      sum_ += 3;
      return;
    }
    sum_ += square(channel(actual.x - decoded.x)) + square(channel(actual.y - decoded.y)) +
            square(channel(actual.z - decoded.z));
  }
  [[nodiscard]] seed_error done() const noexcept {
    seed_error e{samples_, nonfinite_, 0, 0};
    if (samples_ == 0) return e;
    e.mse = sum_ / (3.0 * static_cast<double>(samples_));
    e.psnr = e.mse > 0 ? -10 * std::log10(e.mse) : std::numeric_limits<double>::infinity();
    return e;
  }

 private:
  static double square(double v) noexcept { return v * v; }
  [[nodiscard]] double channel(double d) const noexcept {
    const double e = std::min(std::fabs(d), 1.0);
    return levels_ > 0 ? std::floor(e * levels_ + 0.5) / levels_ : e;
  }
  double levels_;
  double sum_ = 0;
  std::size_t samples_ = 0, nonfinite_ = 0;
};

}  // namespace gsdot3::normal_encoding
