#include "pipeline/method.hpp"

namespace gsdot3::pipeline {

std::string_view name(method m) {
  switch (m) {
    case method::two_pass: return "two-pass";
    case method::four_pass: return "four-pass";
    case method::baseline: return "baseline";
    case method::three_pass: return "three-pass";
    case method::gouraud: return "gouraud";
  }
  return "?";
}

std::optional<method> find_method(std::string_view n) {
  for (method m : gs_methods)
    if (name(m) == n) return m;
  return std::nullopt;
}

std::string method_names() {
  std::string s;
  for (method m : gs_methods) s += (s.empty() ? "" : ", ") + std::string(name(m));
  return s;
}

std::string_view name(dpb_clear_mode m) {
  switch (m) {
    case dpb_clear_mode::explicit_clear: return "explicit";
    case dpb_clear_mode::z_trick: return "z-trick";
    case dpb_clear_mode::z_trick_psmz32: return "z-trick-psmz32";
  }
  return "?";
}

}  // namespace gsdot3::pipeline
