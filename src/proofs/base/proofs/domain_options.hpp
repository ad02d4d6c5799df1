// proofs/domain_options.hpp — input-set choices the paper's code does not pin down, as named
// options of the claims whose domain they change (what the paper's text supports: docs/claims.md,
// "Domain choices"). The runner re-evaluates each such claim under every other value, like the
// model options; they travel in the sweep configuration because they are the proofs' own, not the GS's.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gsdot3::proofs {

struct domain_options {
  // two-pass tolight vectors (char)(s·T): T a unit vector (eq. (2)), or attenuated, |T| <= 1 (§3.5).
  enum class tolight { unit, attenuated } light = tolight::unit;
  // four-pass normal-map vectors round(127·n): tangent-space n with n_z >= 0, or any unit n.
  enum class normal_map { upper_hemisphere, full_sphere } normals = normal_map::upper_hemisphere;
  // fade_att = clamp(6·(n·l), 0, 1) per vertex (§3.6): from the pixel's own texel direction's z, or
  // from a vertex whose direction is not the pixel's (any fade in [0, 1] for any texel).
  enum class fade_source { texel_z, any_vertex } fade = fade_source::texel_z;
};

struct domain_option_info {
  std::string_view name;
  std::vector<std::string_view> values;  // default first
  std::vector<std::string_view> claims;  // ids of the claims whose domain it changes
};
const std::vector<domain_option_info>& domain_option_catalogue();
std::optional<std::string> set_domain_option(domain_options& d, std::string_view name, std::string_view value);
std::string_view domain_option_value(const domain_options& d, std::string_view name);

}  // namespace gsdot3::proofs
