// probe/decode.cpp — option verdicts from a screenshot (see decode.hpp).
#include "probe/decode.hpp"

#include <algorithm>
#include <cstdio>
#include <map>

#include "gs_arith/options.hpp"
#include "probe/design.hpp"
#include "probe/frame.hpp"

namespace gsdot3::probe {
namespace {

std::string hex6(std::uint32_t v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%06x", static_cast<unsigned>(v & 0xFFFFFF));
  return buf;
}

rgb_frame as_rgb(const std::vector<std::uint32_t>& words) {
  rgb_frame f(words.size());
  for (std::size_t i = 0; i < words.size(); ++i) f[i] = rgb_of(words[i]);
  return f;
}

std::uint32_t at(const rgb_frame& f, int x, int y) { return f[static_cast<std::size_t>(y) * frame_width + x]; }

bool agrees(const rgb_frame& shot, const rgb_frame& expected, const patch& p) {
  for (const auto& [x, y] : sample_pixels(p))
    if (at(shot, x, y) != at(expected, x, y)) return false;
  return true;
}

struct candidate {
  std::string value;
  rgb_frame frame;
};

verdict judge(std::string name, bool is_check, const std::vector<const patch*>& patches,
              const std::vector<candidate>& candidates, const rgb_frame& shot) {
  verdict v{std::move(name), is_check, {}, {}, {}};
  for (const candidate& c : candidates) {
    bool all = true;
    for (const patch* p : patches) all = all && agrees(shot, c.frame, *p);
    if (all) v.matches.push_back(c.value);
  }
  if (!v.matches.empty()) return v;
  // One line per patch: the candidates it agrees with (when the patches disagree among themselves), or
  // its first pixel that no candidate shows (else the first that differs from some candidate).
  for (const patch* p : patches) {
    std::string agreeing;
    for (const candidate& c : candidates)
      if (agrees(shot, c.frame, *p)) agreeing += (agreeing.empty() ? "" : ", ") + c.value;
    const std::string where = "patch " + p->name + " at (" + std::to_string(p->x) + ", " + std::to_string(p->y) + ")";
    if (!agreeing.empty()) {
      v.details.push_back(where + " agrees with " + agreeing + " only");
      continue;
    }
    const auto pixels = sample_pixels(*p);
    auto shown_by_none = [&](std::pair<int, int> px) {
      for (const candidate& c : candidates)
        if (at(shot, px.first, px.second) == at(c.frame, px.first, px.second)) return false;
      return true;
    };
    auto pick = std::find_if(pixels.begin(), pixels.end(), shown_by_none);
    if (pick == pixels.end())
      pick = std::find_if(pixels.begin(), pixels.end(), [&](std::pair<int, int> px) {
        return at(shot, px.first, px.second) != at(candidates[0].frame, px.first, px.second);
      });
    const auto [x, y] = *pick;
    std::string line =
        where + ", pixel (" + std::to_string(x) + ", " + std::to_string(y) + "): shows " + hex6(at(shot, x, y)) + ";";
    for (const candidate& c : candidates) line += " " + c.value + " " + hex6(at(c.frame, x, y));
    v.details.push_back(line);
  }
  return v;
}

}  // namespace

rgb_frame model_rgb_frame(const gs::model_options& o) { return as_rgb(model_frame(o)); }

std::vector<verdict> decode(const rgb_frame& shot) {
  const design& des = probe_design();
  std::vector<verdict> out;
  for (const auto& row : gs::option_catalogue()) {
    const std::string name(row.name);
    std::vector<const patch*> patches;
    for (const patch& p : des.patches)
      if (p.option == name) patches.push_back(&p);
    if (patches.empty()) {
      verdict v{name, false, "no patch", {}, {}};
      for (const unprobed& u : des.not_probed)
        if (u.option == name) v.not_probed = u.reason;
      out.push_back(v);
      continue;
    }
    std::vector<candidate> candidates;
    for (const std::string_view value : row.values) {
      gs::model_options o;
      gs::set_option(o, name, value);
      candidates.push_back({std::string(value), as_rgb(model_frame(o))});
    }
    out.push_back(judge(name, false, patches, candidates, shot));
  }
  std::map<std::string, std::vector<const patch*>> checks;
  for (const patch& p : des.patches)
    if (!p.check.empty()) checks[p.check].push_back(&p);
  const std::vector<candidate> model{{"model", model_rgb_frame()}};
  for (const auto& [name, patches] : checks) out.push_back(judge(name, true, patches, model, shot));
  return out;
}

std::string format_verdicts(const std::vector<verdict>& verdicts) {
  std::string s;
  for (const verdict& v : verdicts) {
    const std::string label = (v.is_check ? "check " : "") + v.name + ": ";
    if (!v.not_probed.empty()) {
      s += label + "not probed (" + v.not_probed + ")\n";
    } else if (v.matches.empty()) {
      s += label + "none matches\n";
      for (const std::string& d : v.details) s += "  " + d + "\n";
    } else {
      std::string values;
      for (const std::string& m : v.matches) values += (values.empty() ? "" : " or ") + m;
      s += label + (v.is_check ? "agrees with the model" : values) + "\n";
    }
  }
  return s;
}

}  // namespace gsdot3::probe
