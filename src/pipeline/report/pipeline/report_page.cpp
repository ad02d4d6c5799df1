// pipeline/report_page.cpp — report.html and report-pixels.js (see report_page.hpp). The page is
// pipeline/report_page.html (HTML, CSS) and its script, report_page.js then report_page_panels.js,
// embedded at build time with docs/claims.md (whose summary table gives the claims' verdicts without
// running the catalogue: the report stays fast, and tests/proofs keeps that file current).
#include "pipeline/report_page.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <zlib.h>

#include "gs_arith/bilinear.hpp"
#include "pipeline/files.hpp"
#include "pipeline/lod.hpp"
#include "pipeline/pixel_walk.hpp"
#include "pipeline/render.hpp"
#include "proofs/claim.hpp"

// Generated from report_page.html, report_page.js, report_page_panels.js and docs/claims.md
// (src/pipeline/CMakeLists.txt).
extern const char gsdot3_report_page_html[];
extern const char gsdot3_report_page_js[];
extern const char gsdot3_report_page_panels_js[];
extern const char gsdot3_claims_md[];

namespace gsdot3::pipeline {

namespace {

// The catalogue's claims that settle a step a GS method performs (ids of src/proofs catalogue.cpp).
struct method_claims {
  std::string_view method;
  std::vector<std::string_view> ids;
};
const std::vector<method_claims>& gs_method_claims() {
  static const std::vector<method_claims> rows = {
      {"two-pass",
       {"eq5-eq7.split-multiply", "eq10.split-offset-multiply", "appendix2.packing", "two-pass.na-rounding",
        "two-pass.error-bound", "two-pass.max-s.vertex", "two-pass.max-s.interpolated", "eq9.rgb-sum",
        "ilp.palette-permutation", "ilp.dpb-clear-zero", "clamp-wrap.intermediates", "lod.two-vs-four"}},
      {"four-pass",
       {"eq1-eq2.ranges", "eq3.identity", "eq4.signed-multiply", "eq8.offset-multiply", "appendix1.sphere-map",
        "four-pass.channel-exact", "four-pass.sum-wrap", "highlight.attenuation", "eq9.rgb-sum",
        "ilp.palette-permutation", "ilp.dpb-clear-zero", "clamp-wrap.intermediates",
        "specular.attenuation-compensation", "lod.two-vs-four"}},
      // Breugelmans 2002 (section 2): products of the positive parts added and subtracted by the
      // blender, then the same R+G+B post filter and ILP.
      {"baseline", {"eq9.rgb-sum", "ilp.palette-permutation", "ilp.dpb-clear-zero"}},
      // Section 3.5's alternative: two-pass's passes 1 and 2, then the n_a terms in an additive pass.
      {"three-pass",
       {"eq5-eq7.split-multiply", "eq10.split-offset-multiply", "appendix2.packing", "three-pass.error-bound",
        "eq9.rgb-sum", "ilp.palette-permutation", "ilp.dpb-clear-zero", "clamp-wrap.intermediates"}},
      // Section 4's traditional Gouraud shading: per-vertex dot products, the same post filter and ILP.
      {"gouraud", {"eq9.rgb-sum", "ilp.palette-permutation", "ilp.dpb-clear-zero"}},
  };
  return rows;
}

struct ledger_row {
  std::string anchor, verdict, option_changes;
};

// The summary table of docs/claims.md: | [`id`](#anchor) | paper | verdict | domain size | option changes |
std::vector<std::pair<std::string, ledger_row>> ledger_rows() {
  std::vector<std::pair<std::string, ledger_row>> rows;
  std::istringstream in(gsdot3_claims_md);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("| [`", 0) != 0) continue;
    std::vector<std::string> cells;
    std::size_t at = 1;
    for (std::size_t bar; (bar = line.find(" |", at)) != std::string::npos; at = bar + 2) {
      std::string c = line.substr(at, bar - at);
      c.erase(0, c.find_first_not_of(' '));
      cells.push_back(c);
    }
    if (cells.size() < 5) continue;
    const std::size_t id_end = cells[0].find("`](#");
    if (id_end == std::string::npos) continue;
    const std::string id = cells[0].substr(2, id_end - 2);
    const std::string anchor = cells[0].substr(id_end + 4, cells[0].size() - id_end - 5);
    rows.push_back({id, {anchor, cells[2], cells[4]}});
  }
  return rows;
}

nlohmann::json claims_json() {
  nlohmann::json out = nlohmann::json::object();
  const auto ledger = ledger_rows();
  for (const proofs::claim& c : proofs::catalogue()) {
    nlohmann::json row = {{"paper", std::string(c.paper)},
                          {"statement", std::string(c.statement)},
                          {"domain", std::string(c.domain)},
                          {"section", std::string(c.section)}};
    const auto it = std::find_if(ledger.begin(), ledger.end(), [&](const auto& r) { return r.first == c.id; });
    if (it != ledger.end()) {
      row["verdict"] = it->second.verdict;
      row["option_changes"] = it->second.option_changes;
      row["anchor"] = it->second.anchor;
    } else {
      row["verdict"] = "not in docs/claims.md (regenerate it)";
    }
    out[std::string(c.id)] = row;
  }
  return out;
}

// The page's images of a method, named as report.cpp writes them.
nlohmann::json images_of(const std::string& name, std::size_t lights, bool with_error) {
  nlohmann::json im = {
      {"lit", name + "-lit.png"}, {"dot", nlohmann::json::array()}, {"error", nlohmann::json::array()}};
  for (std::size_t l = 0; l < lights; ++l) {
    im["dot"].push_back(name + "-dot-light" + std::to_string(l) + ".png");
    if (with_error) im["error"].push_back(name + "-error-light" + std::to_string(l) + ".png");
  }
  return im;
}

// A method's worst pixel: where |error(light, pixel, reference)| is largest over the covered pixels
// (the reference is NaN elsewhere) and the lights, the first of equals in light then raster order;
// error gives NaN for a light the method's figures do not count. Null when nothing is covered.
template <class Error>
nlohmann::json worst_pixel(const page_inputs& in, Error error) {
  const std::vector<std::vector<float>>& ref = in.reference->renormalised;
  nlohmann::json worst = nullptr;
  double largest = -1.0;
  for (std::size_t l = 0; l < ref.size(); ++l)
    for (std::size_t i = 0; i < ref[l].size(); ++i) {
      if (std::isnan(ref[l][i])) continue;
      const double e = error(l, i, static_cast<double>(ref[l][i]));
      if (!(std::fabs(e) > largest)) continue;
      largest = std::fabs(e);
      const auto w = static_cast<std::size_t>(in.s->width);
      worst = {{"x", i % w}, {"y", i / w}, {"light", l}, {"error", e}};
    }
  return worst;
}

// Column store of the pixel file.
class columns {
 public:
  template <class T>
  void add(const std::string& name, const char* type, std::size_t width, const std::vector<T>& v) {
    bool same = !v.empty();  // every row equal to the first: a constant (a number, or one per component)
    for (std::size_t i = width; same && i < v.size(); ++i) same = v[i] == v[i % width];
    if (same) {
      nlohmann::json value =
          width == 1 ? nlohmann::json(v.front())
                     : nlohmann::json(std::vector<T>(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(width)));
      meta_.push_back({{"name", name}, {"const", value}});
      return;
    }
    const std::size_t bytes = v.size() * sizeof(T);
    const auto* p = reinterpret_cast<const unsigned char*>(v.data());
    for (const auto& [other, where] : stored_)
      if (where.second == bytes && std::memcmp(data_.data() + where.first, p, bytes) == 0) {
        meta_.push_back({{"name", name}, {"same_as", other}});
        return;
      }
    stored_.push_back({name, {data_.size(), bytes}});
    meta_.push_back({{"name", name}, {"type", type}, {"width", width}, {"offset", data_.size()}});
    data_.insert(data_.end(), p, p + bytes);
  }
  std::size_t count = 0;  // rows
  std::string script() const {
    uLongf packed_size = compressBound(static_cast<uLong>(data_.size()));
    std::vector<unsigned char> packed(packed_size);
    if (compress2(packed.data(), &packed_size, data_.data(), static_cast<uLong>(data_.size()), 6) != Z_OK)
      throw std::runtime_error("report-pixels.js: deflate failed");
    packed.resize(packed_size);
    const nlohmann::json head = {{"format", 1}, {"count", count}, {"bytes", data_.size()}, {"columns", meta_}};
    std::string s = "gsdot3_pixels = " + head.dump();
    s.pop_back();  // the closing brace: the payload follows
    s += ",\"deflate_base64\":\"" + base64(packed) + "\"};\n";
    return s;
  }

 private:
  static std::string base64(const std::vector<unsigned char>& b) {
    static constexpr char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((b.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < b.size(); i += 3) {
      const unsigned v = static_cast<unsigned>(b[i]) << 16 |
                         (i + 1 < b.size() ? static_cast<unsigned>(b[i + 1]) << 8 : 0u) |
                         (i + 2 < b.size() ? static_cast<unsigned>(b[i + 2]) : 0u);
      out += digits[(v >> 18) & 63];
      out += digits[(v >> 12) & 63];
      out += i + 1 < b.size() ? digits[(v >> 6) & 63] : '=';
      out += i + 2 < b.size() ? digits[v & 63] : '=';
    }
    return out;
  }
  std::vector<unsigned char> data_;
  std::vector<std::pair<std::string, std::pair<std::size_t, std::size_t>>> stored_;
  nlohmann::json meta_ = nlohmann::json::array();
};

// JSON text safe inside <script>: "</" cannot end the element.
std::string script_json(const std::string& json) {
  std::string out;
  out.reserve(json.size());
  for (std::size_t i = 0; i < json.size(); ++i) {
    out += json[i];
    if (json[i] == '<' && i + 1 < json.size() && json[i + 1] == '/') out += '\\';
  }
  return out;
}

// The inspector's data: per covered pixel its inputs, every traced pass of every GS method, the
// reference's and the schemes' dot products; `passes` gets the page's description of the passes.
columns pixel_columns(const page_inputs& in, nlohmann::json& passes_of) {
  const scene& s = *in.s;
  const prepared_scene& ps = *in.front;
  const std::vector<std::int32_t>& visible = in.frames->front().visible_triangle;
  std::vector<std::uint32_t> pixel;
  std::vector<std::int32_t> triangle, u16, v16;
  std::vector<std::uint16_t> texel_index;  // the palette entry (layers: of the triangle's layer, scene.hpp)
  for_each_covered_pixel(ps, visible, [&](const pixel_sample& p) {
    pixel.push_back(static_cast<std::uint32_t>(p.index));
    triangle.push_back(static_cast<std::int32_t>(p.triangle));
    u16.push_back(p.u16);
    v16.push_back(p.v16);
    const gs::texel_footprint f = gs::footprint(p.u16, p.v16, gs::bilinear_mode::nearest);
    texel_index.push_back(static_cast<std::uint16_t>(palette_entry(
        s.normals, ps.triangles[p.triangle].layer, wrapped_texel(s.normals.width, s.normals.height, f.u0, f.v0))));
  });
  columns c;
  c.count = pixel.size();
  c.add("pixel", "u32", 1, pixel);
  c.add("triangle", "i32", 1, triangle);
  c.add("u16", "i32", 1, u16);
  c.add("v16", "i32", 1, v16);
  c.add("texel_index", "u16", 1, texel_index);
  auto at_pixels = [&](const auto& frame_sized, std::size_t width) {
    std::vector<std::remove_cvref_t<decltype(frame_sized[0])>> v;
    v.reserve(pixel.size() * width);
    for (std::uint32_t i : pixel)
      for (std::size_t k = 0; k < width; ++k) v.push_back(frame_sized[i * width + k]);
    return v;
  };
  for (std::size_t l = 0; l < s.lights.size(); ++l) {
    c.add("reference/dot" + std::to_string(l), "f32", 1, at_pixels(in.reference->renormalised[l], 1));
    c.add("reference/unnormalised" + std::to_string(l), "f32", 1, at_pixels(in.reference->unnormalised[l], 1));
  }
  passes_of = nlohmann::json::object();
  for (std::size_t k = 0; k < in.methods.size(); ++k) {
    const std::string nm(name(in.methods[k]));
    std::vector<pass_record> trace;
    render_options o = in.options;
    o.trace = &trace;
    const frame traced = render(*in.s, ps, in.methods[k], o);
    if (traced.dot != (*in.frames)[k].dot || traced.colour != (*in.frames)[k].colour)
      throw std::logic_error("report page: the traced " + nm + " render differs from the report's");
    nlohmann::json passes = nlohmann::json::array();
    for (std::size_t p = 0; p < trace.size(); ++p) {
      const pass_record& r = trace[p];
      const std::string key = nm + "/" + std::to_string(p) + "/";
      c.add(key + "word", "u32", 1, at_pixels(r.word, 1));
      c.add(key + "texel", "u32", 1, at_pixels(r.texel, 1));
      c.add(key + "colour", "u16", 4, at_pixels(r.colour, 4));
      c.add(key + "shaded", "u8", 1, at_pixels(r.shaded, 1));
      passes.push_back({{"label", r.label}, {"light", r.light}, {"target", r.target}});
    }
    for (std::size_t l = 0; l < s.lights.size(); ++l)
      c.add(nm + "/dot" + std::to_string(l), "u8", 1, at_pixels(traced.dot[l], 1));
    passes_of[nm] = passes;
  }
  for (const page_scheme& sm : in.schemes)
    for (std::size_t l = 0; l < sm.dot.size(); ++l)
      c.add(sm.name + "/dot" + std::to_string(l), "f32", 1, at_pixels(sm.dot[l], 1));
  return c;
}

}  // namespace

std::vector<std::string> claims_for_method(const std::string& name, const std::string& seed) {
  std::vector<std::string> ids;
  for (const method_claims& m : gs_method_claims())
    if (m.method == name)
      for (std::string_view id : m.ids) ids.emplace_back(id);
  if (!ids.empty() || seed.empty()) return ids;
  // A scheme method's seed reads e.g. "001 (Green 2007)"; its claims' section "Seed 001: Green 2007, ...".
  const std::string section_prefix = "Seed " + seed.substr(0, seed.find(' '));
  for (const proofs::claim& c : proofs::catalogue())
    if (c.section.rfind(section_prefix, 0) == 0) ids.emplace_back(c.id);
  return ids;
}

page_files write_report_page(const std::filesystem::path& dir, const page_inputs& in) {
  namespace fs = std::filesystem;
  page_files files{dir / "report.html", dir / "report-pixels.js", 0, 0};
  const std::size_t lights = in.s->lights.size();
  nlohmann::json page;
  page["heat_limit"] = in.heat_limit;
  page["claims"] = claims_json();
  page["palette"] = nlohmann::json::array();
  for (const glm::vec3& n : in.s->normals.palette) page["palette"].push_back({n.x, n.y, n.z});
  page["light_colours"] = nlohmann::json::array();
  for (const scene_light& l : in.s->lights) page["light_colours"].push_back({l.colour[0], l.colour[1], l.colour[2]});
  page["ambient"] = {in.s->ambient[0], in.s->ambient[1], in.s->ambient[2]};
  for (std::size_t k = 0; k < in.methods.size(); ++k) {
    const method m = in.methods[k];
    const std::string nm(name(m));
    page["methods"][nm] = {{"kind", "gs"},
                           {"images", images_of(nm, lights, true)},
                           {"claims", claims_for_method(nm, "")},
                           {"worst", worst_pixel(in, [&](std::size_t l, std::size_t i, double ref) {
                              // the lights its figures count: --lod-fade's Gouraud halves are gouraud's
                              return light_method(m, in.s->lights[l]) == m ? dot_value((*in.frames)[k].dot[l][i]) - ref
                                                                           : NAN;
                            })}};
  }
  for (const page_scheme& sm : in.schemes)
    page["methods"][sm.name] = {{"kind", "scheme"},
                                {"images", images_of(sm.name, lights, true)},
                                {"claims", claims_for_method(sm.name, sm.seed)},
                                {"worst", worst_pixel(in, [&](std::size_t l, std::size_t i, double ref) {
                                   return static_cast<double>(sm.dot[l][i]) -
                                          (sm.non_negative ? std::max(ref, 0.0) : ref);
                                 })}};
  page["reference_images"] = images_of("reference", lights, false);
  std::error_code ec;
  page["side_by_side"] =
      fs::exists(dir / "side-by-side.png", ec) ? nlohmann::json("side-by-side.png") : nlohmann::json(nullptr);
  fs::remove(files.pixels, ec);
  if (in.pixels) {
    nlohmann::json passes;
    const columns c = pixel_columns(in, passes);
    page["passes"] = passes;
    write_file_atomically(files.pixels, c.script());
    files.pixels_bytes = fs::file_size(files.pixels);
    page["pixels_file"] = files.pixels.filename().string();
  }
  std::string html = gsdot3_report_page_html;
  auto put = [&](const std::string& marker, const std::string& text) {
    const std::size_t at = html.find(marker);
    if (at == std::string::npos) throw std::logic_error("report_page.html: no " + marker);
    html.replace(at, marker.size(), text);
  };
  put("/*GSDOT3_PAGE_SCRIPT*/", std::string(gsdot3_report_page_js) + gsdot3_report_page_panels_js);
  put("/*GSDOT3_REPORT_JSON*/", script_json(in.report_json));
  put("/*GSDOT3_PAGE_JSON*/", script_json(page.dump()));
  write_file_atomically(files.html, html);
  files.html_bytes = fs::file_size(files.html);
  return files;
}

}  // namespace gsdot3::pipeline
