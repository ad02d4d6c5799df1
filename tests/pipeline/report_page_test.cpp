// tests/pipeline/report_page_test.cpp — the report page's files (the browser test, tests/browser,
// checks the page itself): both written, the templates filled, one data row per covered pixel, and
// the method → claim table naming only claims of the catalogue.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "pipeline/default_scene.hpp"
#include "pipeline/report.hpp"
#include "pipeline/report_page.hpp"
#include "proofs/claim.hpp"
#include "common/temp_dir.hpp"

namespace gsdot3::pipeline {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ReportPage, GsMethodClaimsAreInTheCatalogue) {
  for (const char* m : {"two-pass", "four-pass", "baseline"}) {
    const auto ids = claims_for_method(m, "");
    EXPECT_FALSE(ids.empty()) << m;
    for (const std::string& id : ids) EXPECT_NE(proofs::find_claim(id), nullptr) << m << ": " << id;
  }
  // A scheme method gets its seed's section; the paper's own section is "Seed 000".
  const auto paper = claims_for_method("some-scheme", "000 (Mikkelsen 2004)");
  EXPECT_EQ(
      paper.size(), proofs::catalogue().size() - [] {
        std::size_t others = 0;
        for (const auto& c : proofs::catalogue()) others += c.section != proofs::claim::mikkelsen_section;
        return others;
      }());
}

TEST(ReportPage, PageAndPixelFileAreWritten) {
  const fs::path d = gsdot3::test::fresh_temp_dir("gsdot3-report-page-test");
  scene s = default_scene(16);
  s.width = 64;
  s.height = 56;
  report_request r;
  r.out_dir = d;
  r.methods = {method::two_pass};
  const report_summary sum = write_report(s, r);
  const std::string html = read(sum.html), pixels = read(d / "report-pixels.js");
  EXPECT_EQ(html.find("/*GSDOT3_"), std::string::npos);
  EXPECT_EQ(html.find("http://"), std::string::npos);
  EXPECT_EQ(html.find("https://"), std::string::npos);
  EXPECT_NE(html.find("\"two-pass\""), std::string::npos);
  ASSERT_EQ(pixels.rfind("gsdot3_pixels = {", 0), 0u);
  const auto head = nlohmann::json::parse(pixels.substr(16, pixels.rfind('}') - 15));
  EXPECT_EQ(head["format"], 1);
  EXPECT_EQ(head["count"].get<std::size_t>(), sum.methods[0].vs_renormalised.samples / s.lights.size());
  for (const auto& e : fs::directory_iterator(d)) EXPECT_NE(e.path().extension(), ".tmp") << e.path();
  fs::remove_all(d);
}

// The page pins each method's worst pixel on opening: its |error| is the method's max |e| in the
// report's figures, over the lights they count (a --lod-fade Gouraud light is gouraud's, not two-pass's).
TEST(ReportPage, WorstPixelIsTheFiguresLargestError) {
  for (const bool fade_light0 : {false, true}) {
    const fs::path d = gsdot3::test::fresh_temp_dir("gsdot3-report-page-worst");
    scene s = default_scene(16);
    s.width = 64;
    s.height = 56;
    ASSERT_EQ(s.lights.size(), 2u);
    s.lights[0].gouraud = fade_light0;
    report_request r;
    r.out_dir = d;
    r.methods = {method::two_pass, method::gouraud};
    const report_summary sum = write_report(s, r);
    const std::string html = read(sum.html), open = "id=\"gsdot3-page\">";
    const std::size_t at = html.find(open) + open.size();
    const auto page = nlohmann::json::parse(html.substr(at, html.find("</script>", at) - at));
    for (const method_result& m : sum.methods) {
      const auto& worst = page["methods"][std::string(name(m.m))]["worst"];
      ASSERT_TRUE(worst.is_object()) << name(m.m);
      EXPECT_EQ(std::fabs(worst["error"].get<double>()), m.vs_renormalised.max_abs) << name(m.m) << " " << worst;
      EXPECT_LT(worst["x"].get<int>(), s.width);
      EXPECT_LT(worst["y"].get<int>(), s.height);
      if (fade_light0 && m.m == method::two_pass) { EXPECT_EQ(worst["light"], 1) << worst; }
    }
    fs::remove_all(d);
  }
}

}  // namespace
}  // namespace gsdot3::pipeline
