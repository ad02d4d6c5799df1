// pipeline/obj.cpp — a strict Wavefront OBJ reader: v, vt, vn, f (other statements ignored).
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>

#include "pipeline/files.hpp"

namespace gsdot3::pipeline {

namespace {

struct obj_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

float parse_float(const std::string& tok) {
  std::size_t used = 0;
  float v = 0.0f;
  try {
    v = std::stof(tok, &used);
  } catch (const std::exception&) {
    throw obj_error("'" + tok + "' is not a number");
  }
  if (used != tok.size()) throw obj_error("'" + tok + "' is not a number");
  if (!std::isfinite(v)) throw obj_error("non-finite value '" + tok + "' (NaN or infinity)");
  return v;
}

// A 1-based (or negative, relative) OBJ index into a list of `count` items, as a 0-based index.
std::size_t parse_index(const std::string& tok, std::size_t count, const char* what) {
  long v = 0;
  const auto [end, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
  if (ec != std::errc{} || end != tok.data() + tok.size() || v == 0)
    throw obj_error(std::string("bad ") + what + " index '" + tok + "'");
  const long idx = v > 0 ? v - 1 : static_cast<long>(count) + v;
  if (idx < 0 || static_cast<std::size_t>(idx) >= count)
    throw obj_error(std::string(what) + " index " + tok + " is out of range");
  return static_cast<std::size_t>(idx);
}

}  // namespace

mesh load_obj(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot open the mesh");
  std::vector<glm::vec3> pos, nrm;
  std::vector<glm::vec2> uv;
  std::map<std::tuple<std::size_t, std::size_t, std::size_t>, std::uint32_t> corner_ids;
  mesh m;
  std::string line;
  int line_no = 0;
  try {
    while (std::getline(in, line)) {
      ++line_no;
      std::istringstream ls(line);
      std::string kw;
      if (!(ls >> kw) || kw[0] == '#') continue;
      std::vector<std::string> tok;
      for (std::string t; ls >> t;) tok.push_back(t);
      auto floats = [&](std::size_t n) {
        if (tok.size() < n) throw obj_error("'" + kw + "' needs " + std::to_string(n) + " numbers");
        std::vector<float> f;
        for (std::size_t i = 0; i < n; ++i) f.push_back(parse_float(tok[i]));
        return f;
      };
      if (kw == "v") {
        const auto f = floats(3);
        pos.push_back({f[0], f[1], f[2]});
      } else if (kw == "vn") {
        const auto f = floats(3);
        nrm.push_back({f[0], f[1], f[2]});
      } else if (kw == "vt") {
        const auto f = floats(2);
        uv.push_back({f[0], f[1]});
      } else if (kw == "f") {
        if (tok.size() < 3) throw obj_error("a face needs at least 3 corners");
        std::vector<std::uint32_t> ids;
        for (const std::string& c : tok) {
          const auto s1 = c.find('/'), s2 = c.find('/', s1 == std::string::npos ? s1 : s1 + 1);
          if (s1 == std::string::npos || s2 == std::string::npos || s2 == s1 + 1)
            throw obj_error("face corner '" + c + "' needs v/vt/vn (a UV and a normal)");
          const auto key = std::make_tuple(parse_index(c.substr(0, s1), pos.size(), "position"),
                                           parse_index(c.substr(s1 + 1, s2 - s1 - 1), uv.size(), "UV"),
                                           parse_index(c.substr(s2 + 1), nrm.size(), "normal"));
          auto [it, fresh] = corner_ids.try_emplace(key, static_cast<std::uint32_t>(m.vertices.size()));
          if (fresh) {
            vertex v;
            v.position = pos[std::get<0>(key)];
            // OBJ's v runs up the texture; the normal map's rows run down.
            v.uv = {uv[std::get<1>(key)].x, 1.0f - uv[std::get<1>(key)].y};
            v.normal = nrm[std::get<2>(key)];
            m.vertices.push_back(v);
          }
          ids.push_back(it->second);
        }
        for (std::size_t i = 1; i + 1 < ids.size(); ++i) m.triangles.push_back({ids[0], ids[i], ids[i + 1]});
      }
    }
  } catch (const obj_error& e) {
    throw std::runtime_error(file.string() + ":" + std::to_string(line_no) + ": " + e.what());
  }
  if (m.triangles.empty()) throw std::runtime_error(file.string() + ": no faces (is this an OBJ mesh?)");
  try {
    compute_tangents(m);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(file.string() + ": " + e.what());
  }
  return m;
}

}  // namespace gsdot3::pipeline
