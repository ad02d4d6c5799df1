// gsdot3 normal-encoding: seed 002 as the 2009 article measured it (normal_encoding_2009.hpp).
#include "normal_encoding_2009.hpp"

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>

#include "normal_encoding/methods.hpp"
#include "normal_encoding/seed_2009.hpp"

namespace gsdot3::cli {

namespace {
namespace ne = normal_encoding;

// The seed's three methods that are one mapping for unit input (claim normal-encoding.equivalence).
constexpr const char* three[] = {"spheremap", "cryengine3", "lambert"};

// The three best first, "spheremap 45.504 > lambert 44.871 > cryengine3 40.811", from db(row index).
template <class Db>
std::vector<std::pair<double, std::string>> ranked(const std::vector<pipeline::psnr_row>& rows, Db db) {
  std::vector<std::pair<double, std::string>> v;
  for (std::size_t r = 0; r < rows.size(); ++r)
    if (std::find(std::begin(three), std::end(three), rows[r].method) != std::end(three))
      v.push_back({db(r), rows[r].method});
  std::stable_sort(v.begin(), v.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  return v;
}
std::string order_text(const std::vector<std::pair<double, std::string>>& v,
                       const std::vector<std::pair<double, std::string>>& seed) {
  std::string s;
  bool same = v.size() == seed.size();
  for (std::size_t i = 0; i < v.size(); ++i) {
    char b[64];
    std::snprintf(b, sizeof b, "%s%s %.3f", i == 0 ? "" : " > ", v[i].second.c_str(), v[i].first);
    s += b;
    same = same && i < seed.size() && v[i].second == seed[i].second;
  }
  if (seed.empty()) return s;  // not at 8 bits: no published order to compare with
  return s + (same ? " (the seed's order)" : " (NOT the seed's order)");
}
}  // namespace

void print_as_measured_2009(const std::vector<pipeline::psnr_row>& rows, const std::vector<double>& seed_2009_db,
                            int bits) {
  if (rows.empty()) return;
  std::vector<std::vector<ne::vec3>> spheres;
  for (const auto& t : ne::sphere_tessellations)
    spheres.push_back(ne::faceted_sphere_normals(t.rings, t.segments, ne::sphere_pixels));
  std::printf(
      "AS THE SEED MEASURED IT (2009): per pixel the view-space vertex normals interpolated across the triangle, NOT\n"
      "normalised (g; mean |g| = %.6f on the scene), given to the 2009 encoder and decoded; n1 = g as given (the\n"
      "seed's xyz error 'only because of quantization' at 52.661 dB fits only that; vs_unit: n1 = normalize(g)).\n"
      "scene: its pixels; RxS: a UV sphere of R rings, S segments drawn orthographically at %dx%d (the seed's\n"
      "scene of spheres and walls is not available). diff = scene - seed_2009.\n",
      rows.front().as_2009.mean_length, ne::sphere_pixels, ne::sphere_pixels);
  std::printf("%-20s %9s %8s %7s %8s", "method", "seed_2009", "scene", "diff", "vs_unit");
  for (const auto& t : ne::sphere_tessellations)
    std::printf(" %8s", (std::to_string(t.rings) + "x" + std::to_string(t.segments)).c_str());
  std::printf("\n");
  std::vector<std::vector<double>> sphere_db(spheres.size(), std::vector<double>(rows.size()));
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const auto& row = rows[r];
    const double pub = seed_2009_db[r];
    char published[16] = "-", diff[16] = "-";
    if (pub > 0) {
      std::snprintf(published, sizeof published, "%.3f", pub);
      std::snprintf(diff, sizeof diff, "%+.2f", row.as_2009.vs_given.psnr - pub);
    }
    std::printf("%-20s %9s %8.3f %7s %8.3f", row.method.c_str(), published, row.as_2009.vs_given.psnr, diff,
                row.as_2009.vs_unit.psnr);
    for (std::size_t k = 0; k < spheres.size(); ++k) {
      sphere_db[k][r] = ne::measure_2009(ne::method_named(row.method), bits, spheres[k]).vs_given.psnr;
      std::printf(" %8.3f", sphere_db[k][r]);
    }
    std::printf("\n");
  }
  std::vector<std::pair<double, std::string>> seed;
  std::printf("sphere map, CryEngine 3, Lambert (one mapping for unit input), best first:\n");
  if (bits == 8) {
    seed = ranked(rows, [&](std::size_t r) { return seed_2009_db[r]; });
    std::printf("  the seed 2009: %s\n", order_text(seed, seed).c_str());
  }
  std::printf("  scene:         %s\n",
              order_text(ranked(rows, [&](std::size_t r) { return rows[r].as_2009.vs_given.psnr; }), seed).c_str());
  for (std::size_t k = 0; k < spheres.size(); ++k) {
    const auto& t = ne::sphere_tessellations[k];
    std::printf("  sphere %2dx%-3d  %s\n", t.rings, t.segments,
                order_text(ranked(rows, [&](std::size_t r) { return sphere_db[k][r]; }), seed).c_str());
  }
  std::printf("\n");
}

}  // namespace gsdot3::cli
