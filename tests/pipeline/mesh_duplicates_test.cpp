// Duplicated triangles (pipeline/mesh_duplicates.hpp): found whichever corner a copy starts at and
// whatever its other attributes, not confused with the opposite winding, counted in the import
// report and dropped or kept as --duplicates says.
#include <gtest/gtest.h>

#include <filesystem>

#include "pipeline/mesh_duplicates.hpp"
#include "pipeline/mesh_import.hpp"

namespace gsdot3::pipeline {
namespace {

const std::filesystem::path data = std::filesystem::path(GSDOT3_TEST_DATA) / "meshes";

TEST(Duplicates, SameWindingAtAnyStartIsADuplicateOppositeWindingIsNot) {
  mesh m;
  for (glm::vec3 p : {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)})
    m.vertices.push_back({p, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {}});
  // Vertices 3..5: the same positions with other UVs (and −0 for +0): coincident corners.
  m.vertices.push_back({{-0.0f, 0, 0}, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {0.5f, 0.5f}});
  m.vertices.push_back({{1, -0.0f, 0}, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {0.7f, 0.5f}});
  m.vertices.push_back({{0, 1, 0}, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {0.5f, 0.7f}});
  m.triangles = {{0, 1, 2}, {1, 2, 0}, {0, 2, 1}, {3, 4, 5}, {5, 3, 4}};
  mesh kept = m;
  EXPECT_EQ(find_duplicate_triangles(kept, false), 3u);  // {1,2,0}, {3,4,5}, {5,3,4}; not the reversed {0,2,1}
  EXPECT_EQ(kept.triangles.size(), 5u);
  EXPECT_EQ(find_duplicate_triangles(m, true), 3u);
  ASSERT_EQ(m.triangles.size(), 2u);
  EXPECT_EQ(m.triangles[0], (std::array<std::uint32_t, 3>{0, 1, 2}));
  EXPECT_EQ(m.triangles[1], (std::array<std::uint32_t, 3>{0, 2, 1}));
}

// tests/data/meshes/two_quads_twice.obj: two quads (4 triangles), then the same 4 triangles again.
TEST(Duplicates, TwoQuadsDrawnTwiceAreCountedAndDroppedByDefault) {
  const imported_mesh dropped = import_mesh(data / "two_quads_twice.obj");
  EXPECT_EQ(dropped.report.duplicate_triangles, 4u);
  EXPECT_TRUE(dropped.report.duplicates_dropped);
  EXPECT_EQ(dropped.model.triangles.size(), 4u);
  EXPECT_EQ(dropped.report.triangles, 4u);
  bool noticed = false;
  for (const std::string& n : dropped.report.notices)
    noticed = noticed || n.find("4 duplicated triangle(s)") != std::string::npos;
  EXPECT_TRUE(noticed);

  import_options keep;
  keep.duplicates = duplicates_mode::keep;
  const imported_mesh kept = import_mesh(data / "two_quads_twice.obj", keep);
  EXPECT_EQ(kept.report.duplicate_triangles, 4u);
  EXPECT_FALSE(kept.report.duplicates_dropped);
  EXPECT_EQ(kept.model.triangles.size(), 8u);
}

}  // namespace
}  // namespace gsdot3::pipeline
