// pipeline/mesh_repair.cpp — normals, UVs, tangents and merging (see mesh_repair.hpp).
#include "pipeline/mesh_repair.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "pipeline/generated_normals.hpp"
#include "pipeline/mesh_duplicates.hpp"
#include "pipeline/mikktspace.hpp"
#include "pipeline/uv_generation.hpp"
#include "pipeline/word_hash.hpp"

namespace gsdot3::pipeline {

namespace {

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Zero area relative to the triangle's size (also true for NaN): the test compute_tangents uses.
bool degenerate(glm::vec3 a, glm::vec3 b, glm::vec3 c) {
  const glm::vec3 e1 = b - a, e2 = c - a;
  const float scale = std::max({glm::length(e1), glm::length(e2), 1e-30f});
  return !(glm::length(glm::cross(e1, e2)) > 1e-7f * scale * scale);
}

// v / |v| computed on v scaled by its largest component first: glm::normalize squares the components,
// and a node transform that scales by 1e-20 makes those squares denormal (found by
// fuzz/mesh_from_scene: a normal of length 0.92 came out; regression-tangent-not-orthogonal).
// A zero or non-finite v gives a non-finite result, which the callers drop.
glm::vec3 unit_scaled(glm::vec3 v) {
  const float m = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  return glm::normalize(v / m);
}

glm::vec3 face_normal(glm::vec3 a, glm::vec3 b, glm::vec3 c) { return glm::normalize(glm::cross(b - a, c - a)); }

struct key3_hash {
  std::size_t operator()(const std::array<std::uint32_t, 3>& k) const {
    return (static_cast<std::size_t>(k[0]) * 73856093u) ^ (static_cast<std::size_t>(k[1]) * 19349663u) ^
           (static_cast<std::size_t>(k[2]) * 83492791u);
  }
};
std::array<std::uint32_t, 3> bits(glm::vec3 v) {
  return {std::bit_cast<std::uint32_t>(v.x), std::bit_cast<std::uint32_t>(v.y), std::bit_cast<std::uint32_t>(v.z)};
}

struct corner {
  glm::vec3 position, normal, tangent;
  glm::vec2 uv;
  float sign;
};

// Corners with identical attributes become one vertex; triangle t samples layer layer[t] (none but 0: no layers).
mesh weld(const std::vector<corner>& corners, std::vector<std::uint16_t> layer) {
  mesh m;
  if (std::any_of(layer.begin(), layer.end(), [](std::uint16_t k) { return k != 0; })) m.layer = std::move(layer);
  std::unordered_map<std::array<std::uint32_t, 12>, std::uint32_t, word_hash> ids;
  std::array<std::uint32_t, 3> tri{};
  for (std::size_t c = 0; c < corners.size(); ++c) {
    const corner& k = corners[c];
    const std::array<float, 12> f = {k.position.x, k.position.y, k.position.z, k.normal.x, k.normal.y, k.normal.z,
                                     k.tangent.x,  k.tangent.y,  k.tangent.z,  k.uv.x,     k.uv.y,     k.sign};
    std::array<std::uint32_t, 12> key{};
    for (std::size_t i = 0; i < 12; ++i) key[i] = std::bit_cast<std::uint32_t>(f[i]);
    const auto [it, fresh] = ids.try_emplace(key, static_cast<std::uint32_t>(m.vertices.size()));
    if (fresh) m.vertices.push_back({k.position, k.normal, k.tangent, glm::cross(k.normal, k.tangent) * k.sign, k.uv});
    tri[c % 3] = it->second;
    if (c % 3 == 2) m.triangles.push_back(tri);
  }
  return m;
}

}  // namespace

mesh build_mesh(const std::vector<source_mesh>& meshes, const std::vector<source_instance>& instances,
                const import_options& options, import_report& report) {
  // Model-space bounds and triangles (for generated UVs).
  uv_bounds b;
  std::vector<std::array<glm::vec3, 3>> model_triangles;
  const bool uvs_missing = std::any_of(instances.begin(), instances.end(),
                                       [&](const source_instance& in) { return meshes[in.mesh].uvs.empty(); });
  for (const source_instance& in : instances) {
    const source_mesh& sm = meshes[in.mesh];
    auto to_model = [&](std::uint32_t i) { return glm::vec3(in.transform * glm::vec4(sm.positions[i], 1.0f)); };
    for (std::uint32_t i = 0; i < sm.positions.size(); ++i) {
      const glm::vec3 q = to_model(i);
      b.lo = glm::min(b.lo, q);
      b.hi = glm::max(b.hi, q);
    }
    if (uvs_missing && options.uvs == uv_projection::automatic)
      for (const auto& t : sm.triangles) model_triangles.push_back({to_model(t[0]), to_model(t[1]), to_model(t[2])});
  }
  projection_choice projection{options.uvs, "--uv-projection"};
  if (!model_triangles.empty()) projection = choose_projection(model_triangles, b);

  std::vector<char> counted(meshes.size(), 0);
  std::size_t meshes_file_tangents = 0, meshes_mikk = 0, meshes_generated_normals = 0;
  std::vector<corner> all;
  std::vector<std::uint16_t> layer;  // per triangle of `all`
  for (const source_instance& in : instances) {
    const source_mesh& sm = meshes[in.mesh];
    const bool first = !counted[in.mesh];
    counted[in.mesh] = 1;
    std::vector<char> keep(sm.triangles.size()), used(sm.positions.size(), 0);
    for (std::size_t t = 0; t < sm.triangles.size(); ++t) {
      const auto& tri = sm.triangles[t];
      keep[t] = !degenerate(sm.positions[tri[0]], sm.positions[tri[1]], sm.positions[tri[2]]);
      if (first && !keep[t]) ++report.dropped_degenerate;
      if (keep[t]) used[tri[0]] = used[tri[1]] = used[tri[2]] = 1;
    }

    // Normals per vertex: the file's, repaired, or generated. Repairs are counted per distinct
    // position (importers such as assimp's OBJ reader give every face corner its own vertex).
    const std::vector<glm::vec3> generated_normal =
        crease_normals(sm.positions, sm.triangles, keep, options.crease_degrees);  // per corner
    std::vector<glm::vec3> normal(sm.positions.size(), glm::vec3(0.0f));           // zero: take the generated normal
    std::unordered_map<std::array<std::uint32_t, 3>, int, key3_hash> generated, replaced, renormalised;
    for (std::size_t i = 0; i < sm.positions.size(); ++i) {
      if (!used[i]) continue;
      const auto at = bits(sm.positions[i]);
      if (sm.normals.empty()) {
        generated[at] = 1;
        continue;
      }
      const glm::vec3 n = sm.normals[i];
      const float len = glm::length(n);
      if (!finite(n) || !(len > 1e-6f)) {
        replaced[at] = 1;
      } else {
        normal[i] = n / len;
        if (std::fabs(len - 1.0f) > 1e-3f) renormalised[at] = 1;
      }
    }
    if (first) {
      meshes_generated_normals += sm.normals.empty();
      report.normals_generated += generated.size();
      report.normals_replaced += replaced.size();
      report.normals_renormalised += renormalised.size();
    }

    // Corners in mesh space, with UVs.
    std::vector<tangent_corner> tc;
    std::vector<std::uint32_t> source;  // vertex of each corner
    for (std::size_t t = 0; t < sm.triangles.size(); ++t) {
      if (!keep[t]) continue;
      const auto& tri = sm.triangles[t];
      std::array<glm::vec3, 3> p{}, world{};
      for (int k = 0; k < 3; ++k) {
        p[k] = sm.positions[tri[k]];
        world[k] = glm::vec3(in.transform * glm::vec4(p[k], 1.0f));
      }
      const glm::vec3 fn = face_normal(p[0], p[1], p[2]);
      std::array<glm::vec2, 3> uv{};
      if (!sm.uvs.empty()) {
        for (int k = 0; k < 3; ++k) {
          uv[k] = sm.uvs[tri[k]];
          if (!std::isfinite(uv[k].x) || !std::isfinite(uv[k].y))
            throw std::runtime_error("vertex " + std::to_string(tri[k]) + " has a non-finite UV (NaN or infinity)");
        }
      } else {
        uv = project(projection.how, world, b);
      }
      const bool flat = sm.normals.empty() && options.normals == normals_mode::flat;
      for (int k = 0; k < 3; ++k) {
        glm::vec3 n = flat ? fn : normal[tri[k]];
        if (glm::length(n) == 0.0f) n = generated_normal[3 * t + k];
        tc.push_back({p[k], glm::length(n) == 0.0f ? fn : n, uv[k]});
        source.push_back(tri[k]);
      }
    }

    // Tangents: the file's (all usable), else MikkTSpace. The file's bitangent points up the image;
    // the renderer's bitangent points down it (v runs down), hence the sign's minus.
    std::vector<corner_tangent> tan(tc.size());
    bool from_file = !sm.tangents.empty() && options.tangents == tangent_mode::automatic;
    for (std::size_t c = 0; from_file && c < tc.size(); ++c) {
      const glm::vec3 n = tc[c].normal, t = sm.tangents[source[c]], bt = sm.bitangents[source[c]];
      const glm::vec3 tp = t - n * glm::dot(n, t);
      const float handed = glm::dot(glm::cross(n, tp), bt);
      if (!finite(t) || !finite(bt) || !(glm::length(tp) > 1e-6f) || !(std::fabs(handed) > 0.0f)) {
        if (first)
          report.notices.push_back(
              "tangents: the file's tangent at vertex " + std::to_string(source[c]) +
              " is unusable (zero, NaN or along the normal); MikkTSpace tangents computed for that mesh instead");
        from_file = false;
        break;
      }
      tan[c] = {glm::normalize(tp), handed < 0.0f ? 1.0f : -1.0f};
    }
    if (!from_file) {
      const mikktspace_result mr = mikktspace_tangents(tc);
      tan = mr.corners;
      if (first) {
        report.zero_uv_area_triangles += mr.zero_uv_area_triangles;
        report.fallback_tangent_corners += mr.fallback_corners;
      }
    }
    if (first) ++(from_file ? meshes_file_tangents : meshes_mikk);

    // Into model space: normals by the inverse transpose, tangent and bitangent as surface
    // directions; a mirroring transform also reverses the winding (front faces stay counter-clockwise).
    const glm::mat3 m3(in.transform), nm = glm::transpose(glm::inverse(m3));
    const bool mirrored = glm::determinant(m3) < 0.0f;
    for (std::size_t t = 0; t + 2 < tc.size(); t += 3) {
      std::array<corner, 3> k{};
      bool ill_conditioned = false;
      for (std::size_t i = 0; i < 3; ++i) {
        const tangent_corner& c = tc[t + i];
        const glm::vec3 n = unit_scaled(nm * c.normal);
        const glm::vec3 tm = m3 * tan[t + i].tangent;
        const glm::vec3 bt = m3 * (glm::cross(c.normal, tan[t + i].tangent) * tan[t + i].sign);
        // Exactly, m3·t is orthogonal to the transformed normal; what is left after the projection
        // is only rounding when the transform is ill-conditioned (found by fuzz/mesh_from_scene:
        // a tangent normalised from a residual along n came out as −n).
        const glm::vec3 tm1 = unit_scaled(tm), tt = tm1 - n * glm::dot(n, tm1);
        ill_conditioned = ill_conditioned || !(glm::length(tt) > 1e-3f);
        k[i] = {glm::vec3(in.transform * glm::vec4(c.position, 1.0f)), n, unit_scaled(tt), c.uv,
                glm::dot(glm::cross(n, tt), bt) < 0.0f ? -1.0f : 1.0f};
      }
      if (mirrored) std::swap(k[1], k[2]);
      if (degenerate(k[0].position, k[1].position, k[2].position) || !finite(k[0].normal) || !finite(k[1].normal) ||
          !finite(k[2].normal) || !finite(k[0].tangent) || !finite(k[1].tangent) || !finite(k[2].tangent) ||
          ill_conditioned) {
        ++report.dropped_degenerate;  // collapsed by its node's transform
        continue;
      }
      all.insert(all.end(), k.begin(), k.end());
      layer.push_back(sm.layer);
    }
  }
  if (all.empty()) {
    const std::string why = "no triangles (0 faces after dropping points, lines, zero-area triangles and " +
                            std::to_string(report.dropped_non_finite) + " triangle(s) with a non-finite position)";
    if (!options.describe_empty) throw std::runtime_error(why);
    report.notices.push_back(why + ": nothing to draw");
  }

  char crease[24];
  std::snprintf(crease, sizeof crease, "%g", static_cast<double>(options.crease_degrees));
  const std::string gen =
      options.normals == normals_mode::smooth
          ? std::string("generated smooth (angle-weighted), split across edges sharper than ") + crease + " degrees"
          : "generated flat";
  report.normals =
      meshes_generated_normals == 0 ? "file" : (meshes_generated_normals == report.meshes ? gen : "file + " + gen);
  report.uvs = uvs_missing ? std::string(projection_name(projection.how)) +
                                 (options.uvs == uv_projection::automatic ? " (chosen for the shape: " : " (") +
                                 projection.why + ")"
                           : "file";
  report.tangents = meshes_mikk == 0 ? "file (TANGENT)"
                    : meshes_file_tangents == 0
                        ? "MikkTSpace (computed)"
                        : "file (TANGENT) for " + std::to_string(meshes_file_tangents) +
                              " meshes, MikkTSpace (computed) for " + std::to_string(meshes_mikk);
  mesh out = weld(all, std::move(layer));
  report.duplicates_dropped = options.duplicates == duplicates_mode::drop;
  report.duplicate_triangles = find_duplicate_triangles(out, report.duplicates_dropped);
  report.triangles = out.triangles.size();
  if (!all.empty()) validate(out);
  return out;
}

}  // namespace gsdot3::pipeline
