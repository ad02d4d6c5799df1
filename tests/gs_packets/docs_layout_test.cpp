// docs/dumps.md against the code: the state blob table (offset, size, field, in order) is the code's
// state_fields_v8, and every header field the header table names sits at the documented offset of a
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

struct row {
  std::uint32_t offset, size;
  std::string field;
};

// The rows "| offset | size | field | ..." of the first table after `heading`.
std::vector<row> table_after(const std::string& heading) {
  std::ifstream in(GSDOT3_DUMPS_MD);
  EXPECT_TRUE(in) << GSDOT3_DUMPS_MD;
  std::string line;
  while (std::getline(in, line) && line != heading) {}
  std::vector<row> rows;
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
    if (cells.size() < 3 || cells[0].empty() || !std::isdigit(static_cast<unsigned char>(cells[0][0]))) continue;
    rows.push_back(
        {static_cast<std::uint32_t>(std::stoul(cells[0])), static_cast<std::uint32_t>(std::stoul(cells[1])), cells[2]});
  }
  return rows;
}

TEST(DocsLayout, StateTableIsTheCodesVersion8Fields) {
  const auto rows = table_after("## The state blob");
  ASSERT_EQ(rows.size(), gs::dump::state_fields_v8.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].field, gs::dump::state_fields_v8[i].name) << i;
    EXPECT_EQ(rows[i].offset, gs::dump::state_fields_v8[i].offset) << rows[i].field;
    EXPECT_EQ(rows[i].size, gs::dump::state_fields_v8[i].size) << rows[i].field;
  }
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
                                                  {"state_size", 4194760},
                                                  {"serial_offset (from byte 8; 36)", 36},
                                                  {"serial_size", 4},
                                                  {"crc (the game's CRC)", 0x12345678},
                                                  {"screenshot_width", 2},
                                                  {"screenshot_height", 3},
                                                  {"screenshot_offset (from byte 8; 36 + serial size)", 40},
                                                  {"screenshot_size (width × height × 4, RGBA)", 24}};
  const auto rows = table_after("## The file");
  ASSERT_EQ(rows.size(), want.size());
  for (const row& r : rows) {
    ASSERT_TRUE(want.count(r.field)) << "undocumented in the test: " << r.field;
    EXPECT_EQ(r.size, 4u) << r.field;
    EXPECT_EQ(le32(r.offset), want.at(r.field)) << r.field;
  }
}

}  // namespace
