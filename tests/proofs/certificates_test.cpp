// certificates.csv as compiled in (src/proofs/two_pass_triangle/certificates.hpp): its row count, rows
// checked against values copied from the table it replaced, malformed input rejected, and every row a
// wrap under the options its row names.
#include <gtest/gtest.h>

#include <array>
#include <sstream>
#include <stdexcept>
#include <string>

#include "gs_arith/options.hpp"
#include "proofs/paper_code.hpp"
#include "proofs/two_pass.hpp"
#include "two_pass_triangle/certificates.hpp"

namespace tt = gsdot3::proofs::two_pass::triangle;

namespace {
void expect_case(const tt::triangle_case& c, const tt::triangle_case& want) {
  EXPECT_EQ(c.s, want.s);
  EXPECT_EQ(c.iX, want.iX);
  EXPECT_EQ(c.iY, want.iY);
  EXPECT_EQ(c.light, want.light);
  EXPECT_EQ(c.xy16, want.xy16);
  EXPECT_EQ(c.px, want.px);
  EXPECT_EQ(c.py, want.py);
}
}  // namespace

TEST(TriangleCertificates, RowsAsStored) {
  const auto rows = tt::certificate_rows();
  ASSERT_EQ(rows.size(), 25u);
  ASSERT_EQ(tt::certificates().size(), rows.size());
  // the first, the flat and the last row of the table certificates.csv replaced (commit 3d179f4)
  expect_case(rows[0].at, {84,
                           61,
                           66,
                           {{{-54, -61, -19}, {-49, -56, 38}, {-29, -36, -70}}},
                           {0, 13295, 23592, 0, 31868, 32752},
                           1989,
                           2045});
  EXPECT_EQ(rows[0].options, "gouraud_setup=plane_steps gouraud_fraction=truncate_to_8");
  expect_case(rows[20].at,
              {126, -127, -15, {{{-125, -15, 0}, {-125, -15, 0}, {-125, -15, 0}}}, {0, 0, 160, 0, 0, 160}, 2, 2});
  EXPECT_EQ(rows[20].options, "-");
  expect_case(rows[24].at, {122,
                            -20,
                            -117,
                            {{{-113, -43, 16}, {-8, -110, 52}, {-113, -43, 16}}},
                            {16048, 16000, 16065, 16000, 16048, 16032},
                            1004,
                            1000});
  EXPECT_EQ(rows[24].options, "gouraud_setup=pcsx2_rows_4");
  for (const auto& r : rows) EXPECT_FALSE(r.provenance.empty());
  EXPECT_EQ(rows[13].provenance, "tools/proofs_triangle search 100");
}

TEST(TriangleCertificates, MalformedRowsAreErrors) {
  const std::string header =
      "s,iX,iY,l0_x,l0_y,l0_z,l1_x,l1_y,l1_z,l2_x,l2_y,l2_z,x0,y0,x1,y1,x2,y2,px,py,options,provenance\n";
  const std::string good = "1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,19,20,-,reasoning, with a comma\n";
  const auto rows = tt::parse_certificates(header + good);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].at.py, 20);
  EXPECT_EQ(rows[0].provenance, "reasoning, with a comma");
  EXPECT_THROW(tt::parse_certificates(""), std::invalid_argument);
  EXPECT_THROW(tt::parse_certificates("s,iX\n" + good), std::invalid_argument);
  EXPECT_THROW(tt::parse_certificates(header + "1,2,3\n"), std::invalid_argument);
  EXPECT_THROW(tt::parse_certificates(header + "1,2,x3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,19,20,-,p\n"),
               std::invalid_argument);
  EXPECT_THROW(tt::parse_certificates(header + "1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,19,20,-,\n"),
               std::invalid_argument);
  EXPECT_THROW(tt::parse_certificates(header + good + "\n"), std::invalid_argument);
}

// Each row wraps under every combination of gouraud_setup and gouraud_fraction its options allow (the
// other options at their defaults).
TEST(TriangleCertificates, EachRowWrapsUnderItsOptions) {
  for (const auto& row : tt::certificate_rows()) {
    const std::string where = "s = " + std::to_string(row.at.s) + " (" + row.options + ")";
    gs::model_options named;
    bool setup_named = false, fraction_named = false;
    std::istringstream words(row.options == "-" ? "" : row.options);
    for (std::string w; words >> w;) {
      const auto eq = w.find('=');
      ASSERT_NE(eq, std::string::npos) << where;
      EXPECT_FALSE(gs::set_option(named, w.substr(0, eq), w.substr(eq + 1))) << where;
      setup_named = setup_named || w.substr(0, eq) == "gouraud_setup";
      fraction_named = fraction_named || w.substr(0, eq) == "gouraud_fraction";
    }
    for (const char* setup : {"per_pixel", "pcsx2_rows_4", "pcsx2_rows_8", "per_pixel_level", "plane_steps"})
      for (const char* fraction : {"keep_fraction", "truncate_to_8"}) {
        gs::model_options o = named;
        if (!setup_named) (void)gs::set_option(o, "gouraud_setup", setup);
        if (!fraction_named) (void)gs::set_option(o, "gouraud_fraction", fraction);
        const auto p = gsdot3::proofs::paper::pack_normal_from(row.at.iX, row.at.iY);
        const auto r = gsdot3::proofs::two_pass::pixel(p, tt::pixel_light(row.at, o.setup), o);
        EXPECT_NE(r.dot, r.value) << where << " under " << gs::option_value(o, "gouraud_setup") << ", "
                                  << gs::option_value(o, "gouraud_fraction");
      }
  }
}
