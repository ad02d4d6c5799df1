#include "proofs/domain_options.hpp"

namespace gsdot3::proofs {

const std::vector<domain_option_info>& domain_option_catalogue() {
  static const std::vector<domain_option_info> rows = {
      {"tolight",
       {"unit_T", "attenuated_T"},
       {"two-pass.error-bound", "two-pass.max-s.vertex", "two-pass.max-s.interpolated"}},
      {"normal_map", {"n_z_nonnegative", "full_sphere"}, {"four-pass.sum-wrap"}},
      {"fade_att", {"texel_z", "any_vertex"}, {"four-pass.sum-wrap"}},
  };
  return rows;
}

std::optional<std::string> set_domain_option(domain_options& d, std::string_view name, std::string_view value) {
  using D = domain_options;
  if (name == "tolight" && (value == "unit_T" || value == "attenuated_T")) {
    d.light = value == "unit_T" ? D::tolight::unit : D::tolight::attenuated;
    return std::nullopt;
  }
  if (name == "normal_map" && (value == "n_z_nonnegative" || value == "full_sphere")) {
    d.normals = value == "full_sphere" ? D::normal_map::full_sphere : D::normal_map::upper_hemisphere;
    return std::nullopt;
  }
  if (name == "fade_att" && (value == "texel_z" || value == "any_vertex")) {
    d.fade = value == "any_vertex" ? D::fade_source::any_vertex : D::fade_source::texel_z;
    return std::nullopt;
  }
  return "unknown domain option or value '" + std::string(name) + "=" + std::string(value) + "'";
}

std::string_view domain_option_value(const domain_options& d, std::string_view name) {
  using D = domain_options;
  if (name == "tolight") return d.light == D::tolight::unit ? "unit_T" : "attenuated_T";
  if (name == "normal_map") return d.normals == D::normal_map::upper_hemisphere ? "n_z_nonnegative" : "full_sphere";
  if (name == "fade_att") return d.fade == D::fade_source::texel_z ? "texel_z" : "any_vertex";
  return {};
}

}  // namespace gsdot3::proofs
