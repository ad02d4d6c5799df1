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
  // The scheme is judged on what the file named: assimp composes "folder/" + the URI.
  std::string named = reference;
  const std::string prefix = folder.empty() ? std::string() : folder.string() + "/";
  bool absolute = false;  // "folder/" + an absolute URI
  if (!prefix.empty() && named.compare(0, prefix.size(), prefix) == 0) {
    named.erase(0, prefix.size());
    absolute = named.starts_with('/');
  }
  named.erase(0, named.find_first_not_of('/'));
  if (has_scheme(named))
    return "a URI scheme (" + named.substr(0, named.find(':') + 1) + ") other than a relative path";
  // As the operating system opens a path: "a//b" is "a/b", ".." and links resolved.
  auto outside = [&](const fs::path& p) {
    const fs::path resolved = fs::weakly_canonical(fs::absolute(p, ec), ec);
    return std::mismatch(root.begin(), root.end(), resolved.begin(), resolved.end()).first != root.end();
  };
  // An absolute URI that names a file outside the folder. (assimp's OBJ reader also composes "folder/" +
  // the material library's absolute path, or "folder//" + its name: files below the folder or none.)
  if (absolute && fs::exists("/" + named, ec) && outside("/" + named))
    return "a path outside the file's folder (/" + named + ")";
  const fs::path resolved = fs::weakly_canonical(fs::absolute(fs::path(reference), ec), ec);
  if (ec) return "a path that cannot be resolved";
  if (outside(resolved)) return "a path outside the file's folder (" + resolved.string() + ")";
  return "";
}

namespace {

// The path to open for `file`, or "" (with `why`) when it may not be opened. Some importers (LWS's
// object files, Ogre's materials) name a file relative to the working directory, not composed under
// the folder as glTF's "folder/" + URI is; such a name that leads out of the folder is taken
// relative to the folder instead, when that lies inside it.
std::string confined(const std::filesystem::path& folder, const char* file, std::string& why) {
  why = outside_folder(folder, file);
  if (why.empty()) return file;
  const std::string name = file, prefix = folder.string() + "/";
  if (folder.empty() || !std::filesystem::path(name).is_relative() || name.starts_with(prefix)) return "";
  const std::string beside = (folder / file).string();
  return outside_folder(folder, beside).empty() ? beside : "";
}

}  // namespace

bool confined_io::Exists(const char* file) const {
  std::string why;
  if (const std::string path = confined(folder_, file, why); !path.empty())
    return DefaultIOSystem::Exists(path.c_str());
  if (probed_.empty()) probed_ = std::string(file) + ": " + why;
  return false;
}

Assimp::IOStream* confined_io::Open(const char* file, const char* mode) {
  std::string why;
  if (const std::string path = confined(folder_, file, why); !path.empty())
    return DefaultIOSystem::Open(path.c_str(), mode);
  if (refused_.empty()) refused_ = std::string(file) + ": " + why;
  return nullptr;
}

}  // namespace gsdot3::pipeline
