// gs_arith_evidence — docs/evidence.md against the model: every option of gs::option_catalogue() has
// one row of the summary table naming all its values, each profile column equals gs::profiles(), every
// row names each profile's behaviour and a probe of the hardware probe list; and the profiles set
// every option to a valid value.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "gs_arith/options.hpp"
#include "gs_arith/profiles.hpp"

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(' '), e = s.find_last_not_of(' ');
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

// "| a | b |" -> {"a", "b"}.
std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line.substr(1));
  for (std::string c; std::getline(in, c, '|');) out.push_back(trim(c));
  return out;
}

// The table rows (header first, separator dropped) of the section starting with `heading`.
std::vector<std::vector<std::string>> table(const std::vector<std::string>& lines, const std::string& heading) {
  std::vector<std::vector<std::string>> rows;
  bool in_section = false;
  for (const auto& l : lines) {
    if (l.rfind("## ", 0) == 0) in_section = l == heading;
    if (in_section && l.rfind("| ", 0) == 0) rows.push_back(cells(l));
  }
  return rows;
}

// The first `...` token of a cell, or "".
std::string first_code(const std::string& cell) {
  const auto b = cell.find('`');
  if (b == std::string::npos) return {};
  const auto e = cell.find('`', b + 1);
  return e == std::string::npos ? std::string() : cell.substr(b + 1, e - b - 1);
}

struct evidence : ::testing::Test {
  std::vector<std::string> lines;
  void SetUp() override {
    std::ifstream in(GSDOT3_EVIDENCE_MD);
    ASSERT_TRUE(in) << "cannot read " << GSDOT3_EVIDENCE_MD;
    for (std::string l; std::getline(in, l);) lines.push_back(l);
  }
  std::vector<std::vector<std::string>> summary() const { return table(lines, "## Summary"); }
};

TEST_F(evidence, HeaderNamesTheProfilesInOrder) {
  const auto rows = summary();
  ASSERT_FALSE(rows.empty());
  const auto& h = rows.front();
  const std::size_t profiles = gs::profiles().size();
  ASSERT_EQ(h.size(), 5 + profiles);
  EXPECT_EQ(h[0], "row");
  EXPECT_EQ(h[1], "option");
  EXPECT_EQ(h[2], "values");
  for (std::size_t i = 0; i < profiles; ++i) EXPECT_EQ(h[3 + i], gs::profiles()[i].name);
  EXPECT_EQ(h[4 + profiles], "probe");
}

TEST_F(evidence, EveryOptionHasOneRowWithEveryValue) {
  const auto rows = summary();
  for (const auto& opt : gs::option_catalogue()) {
    std::string name = "`";
    name.append(opt.name).append("`");
    const auto n = std::count_if(rows.begin(), rows.end(), [&](const auto& r) { return r.size() > 1 && r[1] == name; });
    ASSERT_EQ(n, 1) << opt.name;
    const auto& r =
        *std::find_if(rows.begin(), rows.end(), [&](const auto& r) { return r.size() > 1 && r[1] == name; });
    std::string values;
    for (auto v : opt.values) values.append(values.empty() ? "`" : ", `").append(v).append("`");
    EXPECT_EQ(r[2], values) << opt.name;
    // The row's detail section exists.
    std::string heading = "### ";
    heading.append(r[0]).append(" ").append(name);
    EXPECT_TRUE(std::any_of(lines.begin(), lines.end(), [&](const std::string& l) { return l.rfind(heading, 0) == 0; }))
        << heading;
  }
}

TEST_F(evidence, ProfileColumnsEqualTheProfileTable) {
  for (const auto& r : summary()) {
    if (r.size() != 5 + gs::profiles().size() || r[0] == "row" || r[0] == "---") continue;
    const std::string option = first_code(r[1]);
    for (std::size_t i = 0; i < gs::profiles().size(); ++i) {
      const auto& p = gs::profiles()[i];
      const std::string& cell = r[3 + i];
      EXPECT_FALSE(cell.empty()) << r[0] << " " << p.name << ": every row names each profile's behaviour";
      if (option.empty()) continue;  // a defect or agreement row: text only
      const auto it =
          std::find_if(p.values.begin(), p.values.end(), [&](const auto& kv) { return kv.first == option; });
      ASSERT_NE(it, p.values.end()) << p.name << " does not set " << option;
      EXPECT_EQ(first_code(cell), it->second) << r[0] << " " << p.name;
    }
  }
}

TEST_F(evidence, EveryRowNamesAProbeOfTheProbeList) {
  std::set<std::string> probes;
  for (const auto& r : table(lines, "## Hardware probe list"))
    if (!r.empty() && r[0].size() > 1 && r[0][0] == 'P') probes.insert(r[0]);
  int rows = 0;
  for (const auto& r : summary()) {
    if (r.size() != 5 + gs::profiles().size() || r[0] == "row" || r[0] == "---") continue;
    ++rows;
    const std::string& probe = r.back();
    EXPECT_TRUE(probes.count(probe) == 1) << r[0] << " names probe '" << probe << "'";
  }
  EXPECT_GE(rows, static_cast<int>(gs::option_catalogue().size()));
}

// "Profile sources": one row per option, each cell the profile's value first, then the file and
// function it was read from (a second `...` token) or "not read".
TEST_F(evidence, EveryProfileValueNamesItsSourceFunction) {
  const auto rows = table(lines, "## Profile sources");
  ASSERT_FALSE(rows.empty());
  ASSERT_EQ(rows.front().size(), 2 + gs::profiles().size());
  for (std::size_t i = 0; i < gs::profiles().size(); ++i) EXPECT_EQ(rows.front()[2 + i], gs::profiles()[i].name);
  for (const auto& opt : gs::option_catalogue()) {
    std::string name = "`";
    name.append(opt.name).append("`");
    const auto it = std::find_if(rows.begin(), rows.end(), [&](const auto& r) { return r.size() > 1 && r[1] == name; });
    ASSERT_NE(it, rows.end()) << opt.name << " has no row";
    for (std::size_t i = 0; i < gs::profiles().size(); ++i) {
      const auto& p = gs::profiles()[i];
      const std::string& cell = (*it)[2 + i];
      const auto v =
          std::find_if(p.values.begin(), p.values.end(), [&](const auto& kv) { return kv.first == opt.name; });
      ASSERT_NE(v, p.values.end());
      EXPECT_EQ(first_code(cell), v->second) << opt.name << " " << p.name;
      const auto after = cell.find('`', cell.find('`', cell.find('`') + 1) + 1);  // a second code token
      EXPECT_TRUE(after != std::string::npos || cell.find("not read") != std::string::npos)
          << opt.name << " " << p.name << ": names no function: " << cell;
    }
  }
}

TEST(Profiles, EachSetsEveryOptionOnceToAValidValue) {
  for (const auto& p : gs::profiles()) {
    std::set<std::string_view> named;
    gs::model_options one_by_one;
    for (const auto& [option, value] : p.values) {
      EXPECT_TRUE(named.insert(option).second) << p.name << " sets " << option << " twice";
      EXPECT_FALSE(gs::set_option(one_by_one, option, value).has_value()) << p.name << " " << option << "=" << value;
    }
    EXPECT_EQ(named.size(), gs::option_catalogue().size()) << p.name;
    for (const auto& opt : gs::option_catalogue()) EXPECT_EQ(named.count(opt.name), 1u) << p.name << " " << opt.name;
    gs::model_options applied;
    applied.tfx = gs::tfx_rounding::truncate;  // overwritten by every profile
    EXPECT_FALSE(gs::apply_profile(applied, p.name).has_value());
    EXPECT_EQ(applied, one_by_one) << p.name;
  }
}

TEST(Profiles, Pcsx2SwDiffersFromTheDefaultsWhereTheSourcesOutnumberItAndUnknownNamesAreErrors) {
  gs::model_options o;
  ASSERT_FALSE(gs::apply_profile(o, "pcsx2-sw").has_value());
  // The defaults are the best-evidenced values (docs/evidence.md): PCSX2 SW is outvoted on the bilinear
  // sum, the triangle set-up and the S/Q conversion, and section 3.4's buffer keeps the paper's reading.
  gs::model_options expected;
  expected.tex_buffer = gs::texture_buffer::draw_snapshot;
  expected.bilinear = gs::bilinear_mode::lerp16_4;
  expected.setup = gs::gouraud_setup::pcsx2_rows_8;
  expected.stq_range = gs::stq_range_mode::x86_int32;  // a tie kept for the value with a hardware report
  expected.stq_convert = gs::stq_convert_mode::trunc_16_16;
  expected.uv_plane = gs::uv_plane_mode::fixed_16;  // its 16.16 steps, outvoted by three float sources
  EXPECT_EQ(o, expected);
  const auto err = gs::apply_profile(o, "mame");
  ASSERT_TRUE(err.has_value());
  EXPECT_NE(err->find("pcsx2-sw, dobiestation, play, parallel-gs"), std::string::npos) << *err;
}

}  // namespace
