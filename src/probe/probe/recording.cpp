// probe/recording.cpp — the probe recording format (see recording.hpp).
#include "probe/recording.hpp"

#include <cstdio>
#include <map>
#include <optional>
#include <sstream>

#include "probe/design.hpp"
#include "probe/frame.hpp"
#include "vectors/format.hpp"

namespace gsdot3::probe {
namespace {

using vectors::format_error;

std::string frame_size() { return std::to_string(frame_width) + "x" + std::to_string(frame_height); }

std::string hex6(std::uint32_t v) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "%06x", static_cast<unsigned>(v & 0xFFFFFF));
  return buf;
}

std::vector<std::string> words(std::string_view line) {
  std::vector<std::string> w;
  std::istringstream in{std::string(line)};
  for (std::string s; in >> s;) w.push_back(s);
  return w;
}

gs::model_options parse_header(std::string_view line) {
  const std::vector<std::string> w = words(line);
  if (w.size() < 2 || w[0] != recording_magic)
    throw format_error("not a probe recording header '" + std::string(recording_magic) + " " +
                       std::to_string(recording_version) + " frame=" + frame_size() + " ...'");
  if (w[1] != std::to_string(recording_version)) throw format_error("probe recording version " + w[1] + " is not 1");
  gs::model_options o;
  bool frame = false;
  for (std::size_t i = 2; i < w.size(); ++i) {
    const auto eq = w[i].find('=');
    if (eq == std::string::npos) throw format_error("header field '" + w[i] + "' is not NAME=VALUE");
    const std::string name = w[i].substr(0, eq), value = w[i].substr(eq + 1);
    if (name == "frame") {
      if (value != frame_size()) throw format_error("frame=" + value + ": the probe frame is " + frame_size());
      frame = true;
    } else if (auto err = gs::set_option(o, name, value)) {
      throw format_error(*err);
    }
  }
  if (!frame) throw format_error("the header has no frame=" + frame_size());
  return o;
}

std::uint32_t parse_hex6(const std::string& s) {
  if (s.empty() || s.size() > 6) throw format_error("pixel '" + s + "' is not 1..6 hex digits");
  std::uint32_t v = 0;
  for (const char c : s) {
    const int d = c >= '0' && c <= '9'   ? c - '0'
                  : c >= 'a' && c <= 'f' ? c - 'a' + 10
                  : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                         : -1;
    if (d < 0) throw format_error("pixel '" + s + "' is not hex");
    v = v << 4 | static_cast<std::uint32_t>(d);
  }
  return v;
}

int parse_coordinate(const std::string& s) {
  if (s.empty() || s.size() > 4 || s.find_first_not_of("0123456789") != std::string::npos)
    throw format_error("cell coordinate '" + s + "' is not a decimal number");
  return std::stoi(s);
}

}  // namespace

std::string write_recording(const rgb_frame& shot, const std::vector<verdict>& decoded) {
  gs::model_options o;
  std::string comments;
  for (const verdict& v : decoded) {
    if (!v.is_check && v.matches.size() == 1) gs::set_option(o, v.name, v.matches[0]);
    comments += "# " + std::string(v.is_check ? "check " : "") + v.name + ": " +
                (!v.not_probed.empty() ? "not probed"
                 : v.matches.empty()   ? "none matches"
                                       : v.matches[0]) +
                "\n";
  }
  std::string s = std::string(recording_magic) + " " + std::to_string(recording_version) + " frame=" + frame_size();
  for (const auto& row : gs::option_catalogue())
    s.append(" ").append(row.name).append("=").append(gs::option_value(o, row.name));
  s += "\n# gsdot3 probe decode: the options the screenshot showed (the default where none matched)\n" + comments;
  s += "# PATCH X Y => the cell's inner 6x6 pixels, row by row, as RRGGBB\n";
  for (const patch& p : probe_design().patches) {
    s += p.name + " " + std::to_string(p.x) + " " + std::to_string(p.y) + " =>";
    for (const auto& [x, y] : sample_pixels(p))
      s.append(" ").append(hex6(shot[static_cast<std::size_t>(y) * frame_width + x]));
    s += "\n";
  }
  return s;
}

bool is_recording(std::string_view text) {
  std::istringstream in{std::string(text.substr(0, 4096))};
  for (std::string line; std::getline(in, line);) {
    if (vectors::is_ignorable(line)) continue;
    return line.rfind(recording_magic, 0) == 0;
  }
  return false;
}

vectors::verify_result verify_recording(std::istream& in, std::ostream& report, const vectors::verify_settings& s) {
  vectors::reporter rep(report, s);
  std::optional<rgb_frame> expected;
  std::map<std::string, const patch*> by_name;
  for (const patch& p : probe_design().patches) by_name[p.name] = &p;
  std::string line;
  std::size_t number = 0;
  while (!rep.stopped() && std::getline(in, line)) {
    ++number;
    if (vectors::is_ignorable(line)) continue;
    if (!expected) {
      try {
        gs::model_options o = parse_header(line);
        vectors::apply_overrides(o, s);
        std::vector<std::uint32_t> words32 = model_frame(o);
        expected.emplace(words32.size());
        for (std::size_t i = 0; i < words32.size(); ++i) (*expected)[i] = rgb_of(words32[i]);
      } catch (const format_error& e) { throw format_error("line " + std::to_string(number) + ": " + e.what()); }
      continue;
    }
    try {
      const std::vector<std::string> w = words(line);
      if (w.size() < 4 || w[3] != "=>") throw format_error("expected 'PATCH X Y => PIXELS'");
      const auto it = by_name.find(w[0]);
      if (it == by_name.end()) throw format_error("unknown patch '" + w[0] + "'");
      const patch& p = *it->second;
      if (parse_coordinate(w[1]) != p.x || parse_coordinate(w[2]) != p.y)
        throw format_error("patch " + p.name + " is at " + std::to_string(p.x) + " " + std::to_string(p.y));
      const auto pixels = sample_pixels(p);
      if (w.size() != 4 + pixels.size())
        throw format_error(std::to_string(w.size() - 4) + " pixels, the patch has " + std::to_string(pixels.size()));
      std::string observed, wanted;
      bool same = true;
      for (std::size_t k = 0; k < pixels.size(); ++k) {
        const std::uint32_t got = parse_hex6(w[4 + k]);
        const std::uint32_t want =
            (*expected)[static_cast<std::size_t>(pixels[k].second) * frame_width + pixels[k].first];
        same = same && got == want;
        if (k != 0) {
          observed += ' ';
          wanted += ' ';
        }
        observed += hex6(got);
        wanted += hex6(want);
      }
      if (same) {
        rep.pass();
      } else {
        rep.mismatch(p.name + " " + w[1] + " " + w[2], observed, wanted);
      }
    } catch (const format_error& e) { rep.malformed(number, e.what()); }
  }
  if (!expected)
    throw format_error("line " + std::to_string(number + 1) + ": no header line '" + std::string(recording_magic) +
                       " " + std::to_string(recording_version) + " frame=" + frame_size() + " ...' (empty input)");
  return rep.finish();
}

}  // namespace gsdot3::probe
