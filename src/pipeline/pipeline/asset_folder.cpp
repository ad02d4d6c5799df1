// pipeline/asset_folder.cpp — see asset_folder.hpp.
#include "pipeline/asset_folder.hpp"

#include <algorithm>
#include <cctype>

namespace gsdot3::pipeline {

namespace {

// RFC 3986 section 3.1: scheme = ALPHA *( ALPHA / DIGIT / "+" / "-" / "." ) ":". A one-letter
// scheme is taken for a scheme too: a Windows drive ("C:") is just as absolute.
bool has_scheme(const std::string& s) {
  const std::size_t colon = s.find(':');
  if (colon == std::string::npos || colon == 0 || std::isalpha(static_cast<unsigned char>(s[0])) == 0) return false;
  for (std::size_t i = 1; i < colon; ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (std::isalnum(c) == 0 && c != '+' && c != '-' && c != '.') return false;
  }
  return true;
}

}  // namespace

std::string outside_folder(const std::filesystem::path& folder, const std::string& reference) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path root = fs::weakly_canonical(fs::absolute(folder.empty() ? fs::path(".") : folder, ec), ec);
  std::string rest = reference;  // assimp composes "folder/uri": judge the uri part
  const std::string prefix = folder.empty() ? std::string() : folder.string() + "/";
  if (!prefix.empty() && rest.compare(0, prefix.size(), prefix) == 0) rest.erase(0, prefix.size());
  if (has_scheme(rest)) return "a URI scheme (" + rest.substr(0, rest.find(':') + 1) + ") other than a relative path";
  const fs::path p = fs::path(rest).is_absolute() ? fs::path(rest) : root / fs::path(rest);  // "folder//etc/x": /etc/x
  const fs::path resolved = fs::weakly_canonical(p, ec);
  if (ec) return "a path that cannot be resolved";
  const auto [r, q] = std::mismatch(root.begin(), root.end(), resolved.begin(), resolved.end());
  if (r != root.end()) return "a path outside the file's folder (" + resolved.string() + ")";
  return "";
}

bool confined_io::Exists(const char* file) const {
  const std::string why = outside_folder(folder_, file);
  if (why.empty()) return DefaultIOSystem::Exists(file);
  if (refused_.empty()) refused_ = std::string(file) + ": " + why;
  return false;
}

Assimp::IOStream* confined_io::Open(const char* file, const char* mode) {
  const std::string why = outside_folder(folder_, file);
  if (why.empty()) return DefaultIOSystem::Open(file, mode);
  if (refused_.empty()) refused_ = std::string(file) + ": " + why;
  return nullptr;
}

}  // namespace gsdot3::pipeline
