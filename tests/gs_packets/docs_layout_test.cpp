// docs/dumps.md against the code: the state blob table (version-8 offset, version-9 offset, size,
// field, in order) is the code's state_fields_v8 (the rows with a version-8 offset) and state_fields_v9
// (every row), and every header field the header table names sits at the documented offset of a
// dump written by write_dump (values chosen distinct, so a misplaced field cannot match).
#include <gtest/gtest.h>

#include <cctype>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "gs_packets/dump.hpp"
#include "gs_packets/state.hpp"

namespace {

// The data rows (first cell a number or "–") of the first table after `heading`, as cells.
std::vector<std::vector<std::string>> table_after(const std::string& heading) {
  std::ifstream in(GSDOT3_DUMPS_MD);
  EXPECT_TRUE(in) << GSDOT3_DUMPS_MD;
  std::string line;
  while (std::getline(in, line) && line != heading) {}
  std::vector<std::vector<std::string>> rows;
  bool in_table = false;
  while (std::getline(in, line)) {
    if (line.rfind('|', 0) != 0) {
      if (in_table) break;
      continue;
    }
    in_table = true;
    std::vector<std::string> cells;
    std::stringstream cs(line.substr(1));
    for (std::string c; std::getline(cs, c, '|');) cells.push_back(c.substr(1, c.size() - 2));
    if (cells.size() >= 3 && (std::isdigit(static_cast<unsigned char>(cells[0][0])) || cells[0] == "–"))
      rows.push_back(cells);
  }
  return rows;
}
std::uint32_t number(const std::string& cell) { return static_cast<std::uint32_t>(std::stoul(cell)); }

TEST(DocsLayout, StateTableIsTheCodesVersion8And9Fields) {
  const auto rows = table_after("## The state blob");
  ASSERT_EQ(rows.size(), gs::dump::state_fields_v9.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& r = rows[i];
    ASSERT_GE(r.size(), 4u);
    EXPECT_EQ(r[3], gs::dump::state_fields_v9[i].name) << i;
    EXPECT_EQ(number(r[1]), gs::dump::state_fields_v9[i].offset) << r[3];
    EXPECT_EQ(number(r[2]), gs::dump::state_fields_v9[i].size) << r[3];
    if (r[0] == "–") continue;
    ASSERT_LT(k, gs::dump::state_fields_v8.size());
    EXPECT_EQ(r[3], gs::dump::state_fields_v8[k].name) << i;
    EXPECT_EQ(number(r[0]), gs::dump::state_fields_v8[k].offset) << r[3];
    EXPECT_EQ(number(r[2]), gs::dump::state_fields_v8[k].size) << r[3];
    ++k;
  }
  EXPECT_EQ(k, gs::dump::state_fields_v8.size());
}

TEST(DocsLayout, HeaderFieldsSitWhereTheTableSays) {
  gs::dump::gs_dump d;
  d.state_version = 8;
  d.state = gs::dump::make_state_v8();
  d.serial = "SLUS";
  d.crc = 0x12345678;
  d.screenshot_width = 2;
  d.screenshot_height = 3;
  d.screenshot.assign(2 * 3 * 4, 0);
  const auto b = gs::dump::write_dump(d);
  auto le32 = [&](std::uint32_t at) {
    return std::uint32_t{b[at]} | std::uint32_t{b[at + 1]} << 8 | std::uint32_t{b[at + 2]} << 16 |
           std::uint32_t{b[at + 3]} << 24;
  };
  // What each documented field holds for this dump (header_size = 36 + 4 + 24).
  const std::map<std::string, std::uint32_t> want{{"0xFFFFFFFF (marks the new layout)", 0xFFFFFFFFu},
                                                  {"header_size: 36 + serial size + screenshot size", 64},
                                                  {"state_version", 8},
                                                  {"state_size", 4194752},
                                                  {"serial_offset (from byte 8; 36)", 36},
                                                  {"serial_size", 4},
                                                  {"crc (the game's CRC)", 0x12345678},
                                                  {"screenshot_width", 2},
                                                  {"screenshot_height", 3},
                                                  {"screenshot_offset (from byte 8; 36 + serial size)", 40},
                                                  {"screenshot_size (width × height × 4, RGBA)", 24}};
  const auto rows = table_after("## The file");
  ASSERT_EQ(rows.size(), want.size());
  for (const auto& r : rows) {
    ASSERT_TRUE(want.count(r[2])) << "undocumented in the test: " << r[2];
    EXPECT_EQ(number(r[1]), 4u) << r[2];
    EXPECT_EQ(le32(number(r[0])), want.at(r[2])) << r[2];
  }
}

}  // namespace
