#include "scene/procedural/isosurface.h"

#include "core/error.h"
#include "core/log.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_set>
#include <vector>

namespace glint::procedural {

namespace {

constexpr int kBlock = 4;    // cells per block edge
constexpr int kPadding = 2;  // cells of margin around the bounds
// The narrow-band test assumes the field changes at most this much faster than a true distance
// (the ellipsoid bound, the blend and armour ridges stay below it).
constexpr float kLipschitz = 1.5f;

struct Grid {
  vec3 origin{0.0f};
  float h = 1.0f;
  int n[3] = {0, 0, 0};        // points per axis
  int blocks[3] = {0, 0, 0};   // blocks per axis
  std::vector<float> value;    // n[0] * n[1] * n[2], x fastest

  std::size_t point(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * static_cast<std::size_t>(n[1]) + static_cast<std::size_t>(j)) *
               static_cast<std::size_t>(n[0]) + static_cast<std::size_t>(i);
  }
  // Cells are indexed like their lowest corner point.
  std::size_t cell(int i, int j, int k) const { return point(i, j, k); }
  vec3 position(int i, int j, int k) const {
    return origin + h * vec3(static_cast<float>(i), static_cast<float>(j), static_cast<float>(k));
  }
  int block_count() const { return blocks[0] * blocks[1] * blocks[2]; }
  void block_coords(int b, int& bx, int& by, int& bz) const {
    bx = b % blocks[0];
    by = (b / blocks[0]) % blocks[1];
    bz = b / (blocks[0] * blocks[1]);
  }
  vec3 block_centre(int b) const {
    int bx, by, bz;
    block_coords(b, bx, by, bz);
    return origin + h * static_cast<float>(kBlock) *
                        (vec3(static_cast<float>(bx), static_cast<float>(by), static_cast<float>(bz)) + 0.5f);
  }
  // Radius of a ball around block_centre() holding every point a block owns or its cells touch.
  float block_radius() const { return 0.5f * std::sqrt(3.0f) * static_cast<float>(kBlock + 1) * h; }
};

Grid make_grid(const Aabb& bounds, float cell_size) {
  if (!(cell_size > 0.0f) || bounds.empty()) fail("isosurface: invalid cell size {} or empty bounds", cell_size);
  Grid grid;
  grid.h = cell_size;
  grid.origin = bounds.min - vec3(static_cast<float>(kPadding) * cell_size);
  const vec3 extent = bounds.extent();
  for (int a = 0; a < 3; ++a) {
    const int cells = static_cast<int>(std::ceil(extent[a] / cell_size)) + 2 * kPadding;
    grid.n[a] = cells + 1;
    grid.blocks[a] = (cells + kBlock - 1) / kBlock;
  }
  const double points = static_cast<double>(grid.n[0]) * grid.n[1] * grid.n[2];
  if (points > 4.0e8) fail("isosurface: a grid of {} points is too large (cell size {})", points, cell_size);
  grid.value.resize(static_cast<std::size_t>(points));
  return grid;
}

// The points a block owns: [b * kBlock, b * kBlock + kBlock) per axis, plus the grid's last point
// for the last block. Each point has exactly one owner, so parallel blocks never share writes.
template <typename PerPoint>
void for_owned_points(const Grid& grid, int block, const PerPoint& per_point) {
  int bx, by, bz;
  grid.block_coords(block, bx, by, bz);
  const int i_end = std::min(grid.n[0], (bx + 1) * kBlock + (bx + 1 == grid.blocks[0] ? 1 : 0));
  const int j_end = std::min(grid.n[1], (by + 1) * kBlock + (by + 1 == grid.blocks[1] ? 1 : 0));
  const int k_end = std::min(grid.n[2], (bz + 1) * kBlock + (bz + 1 == grid.blocks[2] ? 1 : 0));
  for (int k = bz * kBlock; k < k_end; ++k)
    for (int j = by * kBlock; j < j_end; ++j)
      for (int i = bx * kBlock; i < i_end; ++i) per_point(i, j, k);
}

// Fills grid.value. With `narrow_band`, blocks far from the surface get their centre value
// everywhere; a block is evaluated when it or a lower neighbour (whose cells reach into this
// block's points) is near the surface. Returns which blocks were evaluated.
std::vector<std::uint8_t> evaluate(Grid& grid, const ImplicitField& field, bool narrow_band) {
  const int count = grid.block_count();
  std::vector<float> centre(static_cast<std::size_t>(count), 0.0f);
  std::vector<std::uint8_t> near(static_cast<std::size_t>(count), 1);
  const float reach = kLipschitz * grid.block_radius() + grid.h;
  if (narrow_band) {
    tbb::parallel_for(0, count, [&](int b) {
      const float v = field.value(grid.block_centre(b));
      centre[static_cast<std::size_t>(b)] = v;
      near[static_cast<std::size_t>(b)] = std::abs(v) < reach ? 1 : 0;
    });
  }
  std::vector<std::uint8_t> evaluated(static_cast<std::size_t>(count), 0);
  for (int b = 0; b < count; ++b) {
    int bx, by, bz;
    grid.block_coords(b, bx, by, bz);
    bool needed = false;
    for (int d = 0; d < 8 && !needed; ++d) {
      const int x = bx - (d & 1), y = by - ((d >> 1) & 1), z = bz - ((d >> 2) & 1);
      if (x < 0 || y < 0 || z < 0) continue;
      needed = near[static_cast<std::size_t>((z * grid.blocks[1] + y) * grid.blocks[0] + x)] != 0;
    }
    evaluated[static_cast<std::size_t>(b)] = needed ? 1 : 0;
  }
  tbb::parallel_for(0, count, [&](int b) {
    if (evaluated[static_cast<std::size_t>(b)]) {
      constexpr std::size_t kMax = (kBlock + 1) * (kBlock + 1) * (kBlock + 1);
      std::array<vec3, kMax> points;
      std::array<float, kMax> values;
      std::array<std::size_t, kMax> slots;
      std::size_t n = 0;
      for_owned_points(grid, b, [&](int i, int j, int k) {
        points[n] = grid.position(i, j, k);
        slots[n++] = grid.point(i, j, k);
      });
      field.values_near(grid.block_centre(b), grid.block_radius(), points.data(), values.data(), n);
      for (std::size_t q = 0; q < n; ++q) grid.value[slots[q]] = values[q];
    } else {
      const float fill = centre[static_cast<std::size_t>(b)];
      for_owned_points(grid, b, [&](int i, int j, int k) { grid.value[grid.point(i, j, k)] = fill; });
    }
  });
  return evaluated;
}

bool inside(float value) { return value < 0.0f; }

// The 8 corner offsets of a cell (bit 0 = x, bit 1 = y, bit 2 = z) and its 12 edges as corner pairs.
constexpr std::array<std::array<int, 2>, 12> kCellEdges{{{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                                          {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}};

struct SurfaceCell {
  std::size_t cell;
  int i, j, k;
  int block;
  vec3 position;
};

// Surface cells (mixed corner signs) of the evaluated blocks, in block order then cell order, so
// the vertex order does not depend on the thread schedule.
std::vector<SurfaceCell> find_surface_cells(const Grid& grid, const std::vector<std::uint8_t>& evaluated) {
  std::vector<int> blocks;
  for (int b = 0; b < grid.block_count(); ++b)
    if (evaluated[static_cast<std::size_t>(b)]) blocks.push_back(b);
  std::vector<std::vector<SurfaceCell>> per_block(blocks.size());
  tbb::parallel_for(std::size_t{0}, blocks.size(), [&](std::size_t slot) {
    const int b = blocks[slot];
    int bx, by, bz;
    grid.block_coords(b, bx, by, bz);
    std::vector<SurfaceCell>& out = per_block[slot];
    for (int k = bz * kBlock; k < std::min((bz + 1) * kBlock, grid.n[2] - 1); ++k)
      for (int j = by * kBlock; j < std::min((by + 1) * kBlock, grid.n[1] - 1); ++j)
        for (int i = bx * kBlock; i < std::min((bx + 1) * kBlock, grid.n[0] - 1); ++i) {
          std::array<float, 8> corner;
          int inside_count = 0;
          for (int c = 0; c < 8; ++c) {
            corner[static_cast<std::size_t>(c)] = grid.value[grid.point(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1))];
            inside_count += inside(corner[static_cast<std::size_t>(c)]) ? 1 : 0;
          }
          if (inside_count == 0 || inside_count == 8) continue;
          vec3 sum(0.0f);
          int crossings = 0;
          for (const auto& edge : kCellEdges) {
            const float a = corner[static_cast<std::size_t>(edge[0])], bv = corner[static_cast<std::size_t>(edge[1])];
            if (inside(a) == inside(bv)) continue;
            const float t = std::clamp(a / (a - bv), 0.0f, 1.0f);
            const vec3 pa(static_cast<float>(edge[0] & 1), static_cast<float>((edge[0] >> 1) & 1), static_cast<float>((edge[0] >> 2) & 1));
            const vec3 pb(static_cast<float>(edge[1] & 1), static_cast<float>((edge[1] >> 1) & 1), static_cast<float>((edge[1] >> 2) & 1));
            sum += pa + t * (pb - pa);
            ++crossings;
          }
          out.push_back({grid.cell(i, j, k), i, j, k, b, grid.position(i, j, k) + grid.h * (sum / static_cast<float>(crossings))});
        }
  });
  std::vector<SurfaceCell> cells;
  for (auto& block : per_block) cells.insert(cells.end(), block.begin(), block.end());
  return cells;
}

// Resolves ambiguous faces (signs alternating around the face): the field at the face centre says
// which diagonal pair is connected; the other pair's corner nearest the surface joins the centre's
// side. Serial, in surface-cell order, so the result is deterministic. Returns the number changed.
// A corner is changed at most once (`changed_points`), so fixes cannot undo each other.
std::size_t resolve_ambiguous_faces(Grid& grid, const ImplicitField& field, const std::vector<SurfaceCell>& cells,
                                    std::unordered_set<std::size_t>& changed_points) {
  std::size_t changed = 0;
  for (const SurfaceCell& c : cells) {
    // The cell's three faces through its lowest corner: in the planes (x, y), (y, z), (z, x).
    for (int a = 0; a < 3; ++a) {
      const int b = (a + 1) % 3;
      int corner[4][3];
      for (int q = 0; q < 4; ++q) {
        corner[q][0] = c.i, corner[q][1] = c.j, corner[q][2] = c.k;
        corner[q][a] += (q == 1 || q == 2) ? 1 : 0;
        corner[q][b] += (q >= 2) ? 1 : 0;
      }
      std::size_t slot[4];
      bool in[4];
      for (int q = 0; q < 4; ++q) {
        slot[q] = grid.point(corner[q][0], corner[q][1], corner[q][2]);
        in[q] = inside(grid.value[slot[q]]);
      }
      // Going round the face (0, 1, 2, 3): ambiguous when every step changes sign.
      if (!(in[0] != in[1] && in[1] != in[2] && in[2] != in[3])) continue;
      vec3 mid(0.0f);
      for (int q = 0; q < 4; ++q) mid += grid.position(corner[q][0], corner[q][1], corner[q][2]);
      const bool centre_inside = inside(field.value(0.25f * mid));
      // Prefer a corner of the pair the centre separates; when both were changed already, join the
      // other pair instead (either choice makes the face unambiguous).
      int pick = -1;
      for (int pass = 0; pass < 2 && pick < 0; ++pass)
        for (int q = 0; q < 4; ++q) {
          const bool wanted = pass == 0 ? in[q] != centre_inside : in[q] == centre_inside;
          if (!wanted || changed_points.count(slot[q])) continue;
          if (pick < 0 || std::abs(grid.value[slot[q]]) < std::abs(grid.value[slot[pick]])) pick = q;
        }
      if (pick < 0) continue;
      // A tiny value of the other sign: the crossing stays next to that corner.
      grid.value[slot[pick]] = (inside(grid.value[slot[pick]]) ? 1e-6f : -1e-6f) * grid.h;
      changed_points.insert(slot[pick]);
      ++changed;
    }
  }
  return changed;
}

// Builds the faces; returns false when a quad needed a cell that has no vertex (the narrow band
// missed part of the surface).
bool build_faces(const Grid& grid, const std::vector<SurfaceCell>& cells, std::vector<std::uint32_t>& indices,
                 const std::vector<vec3>& positions) {
  std::vector<std::int32_t> vertex_of(grid.value.size(), -1);
  for (std::size_t v = 0; v < cells.size(); ++v) vertex_of[cells[v].cell] = static_cast<std::int32_t>(v);
  indices.clear();
  indices.reserve(cells.size() * 6);
  for (const SurfaceCell& c : cells) {
    const float here = grid.value[grid.point(c.i, c.j, c.k)];
    for (int a = 0; a < 3; ++a) {
      // The edge from this cell's lowest corner along axis a; (a, b, d) is a cyclic axis order.
      const int b = (a + 1) % 3, d = (a + 2) % 3;
      int step[3] = {0, 0, 0};
      step[a] = 1;
      const float there = grid.value[grid.point(c.i + step[0], c.j + step[1], c.k + step[2])];
      if (inside(here) == inside(there)) continue;
      // The four cells around the edge, counter-clockwise about +a: offsets (b, d) of
      // (-1,-1), (0,-1), (0,0), (-1,0).
      const int offsets[4][2] = {{-1, -1}, {0, -1}, {0, 0}, {-1, 0}};
      std::array<std::uint32_t, 4> quad{};
      for (int q = 0; q < 4; ++q) {
        int at[3] = {c.i, c.j, c.k};
        at[b] += offsets[q][0];
        at[d] += offsets[q][1];
        if (at[0] < 0 || at[1] < 0 || at[2] < 0) return false;
        const std::int32_t v = vertex_of[grid.cell(at[0], at[1], at[2])];
        if (v < 0) return false;
        quad[static_cast<std::size_t>(q)] = static_cast<std::uint32_t>(v);
      }
      // Inside -> outside along +a means the outward normal is +a: keep the order; else reverse.
      if (!inside(here)) std::swap(quad[1], quad[3]);
      // Split along the shorter diagonal (better-shaped triangles).
      const float d02 = glm::distance(positions[quad[0]], positions[quad[2]]);
      const float d13 = glm::distance(positions[quad[1]], positions[quad[3]]);
      if (d02 <= d13) indices.insert(indices.end(), {quad[0], quad[1], quad[2], quad[0], quad[2], quad[3]});
      else indices.insert(indices.end(), {quad[0], quad[1], quad[3], quad[1], quad[2], quad[3]});
    }
  }
  return true;
}

// Normals from the field gradient (central differences a quarter cell wide), evaluated block by
// block so the field can reuse its per-region preparation.
void compute_normals(const Grid& grid, const ImplicitField& field, const std::vector<SurfaceCell>& cells,
                     std::vector<vec3>& normals) {
  normals.resize(cells.size());
  std::vector<std::size_t> starts;
  for (std::size_t v = 0; v < cells.size(); ++v)
    if (v == 0 || cells[v].block != cells[v - 1].block) starts.push_back(v);
  starts.push_back(cells.size());
  const float step = 0.25f * grid.h;
  tbb::parallel_for(std::size_t{0}, starts.size() - 1, [&](std::size_t r) {
    const std::size_t first = starts[r], last = starts[r + 1];
    std::vector<vec3> points;
    points.reserve((last - first) * 6);
    for (std::size_t v = first; v < last; ++v)
      for (int a = 0; a < 3; ++a) {
        vec3 offset(0.0f);
        offset[a] = step;
        points.push_back(cells[v].position + offset);
        points.push_back(cells[v].position - offset);
      }
    std::vector<float> values(points.size());
    field.values_near(grid.block_centre(cells[first].block), grid.block_radius() + 2.0f * grid.h, points.data(),
                      values.data(), points.size());
    for (std::size_t v = first; v < last; ++v) {
      const float* g = values.data() + (v - first) * 6;
      const vec3 gradient(g[0] - g[1], g[2] - g[3], g[4] - g[5]);
      const float length = glm::length(gradient);
      normals[v] = length > 0.0f ? gradient / length : vec3(0.0f, 1.0f, 0.0f);
    }
  });
}

}  // namespace

namespace {
// Evaluates the grid and finds its surface cells after resolving ambiguous faces.
std::vector<SurfaceCell> surface_cells(Grid& grid, const ImplicitField& field, bool narrow_band,
                                       std::vector<std::uint8_t>& evaluated) {
  evaluated = evaluate(grid, field, narrow_band);
  std::vector<SurfaceCell> cells = find_surface_cells(grid, evaluated);
  // Each fix can create a new ambiguous face next to it; a few rounds settle them all.
  std::unordered_set<std::size_t> changed_points;
  for (int round = 0; round < 16; ++round) {
    if (resolve_ambiguous_faces(grid, field, cells, changed_points) == 0) break;
    cells = find_surface_cells(grid, evaluated);
  }
  return cells;
}
}  // namespace

std::size_t count_surface_vertices(const ImplicitField& field, const Aabb& bounds, float cell_size) {
  Grid grid = make_grid(bounds, cell_size);
  std::vector<std::uint8_t> evaluated;
  return surface_cells(grid, field, true, evaluated).size();
}

std::size_t count_surface_vertices(const ScalarField& field, const Aabb& bounds, float cell_size) {
  return count_surface_vertices(FunctionField(field), bounds, cell_size);
}

Mesh polygonize(const ImplicitField& field, const Aabb& bounds, float cell_size) {
  Grid grid = make_grid(bounds, cell_size);
  Mesh mesh;
  std::vector<SurfaceCell> cells;
  for (int attempt = 0; attempt < 2; ++attempt) {
    const bool narrow_band = attempt == 0;
    std::vector<std::uint8_t> evaluated;
    cells = surface_cells(grid, field, narrow_band, evaluated);
    mesh.positions.resize(cells.size());
    for (std::size_t v = 0; v < cells.size(); ++v) mesh.positions[v] = cells[v].position;
    if (build_faces(grid, cells, mesh.indices, mesh.positions)) break;
    if (!narrow_band) fail("isosurface: the field is not positive on the grid border (surface leaves the bounds)");
    log_debug("isosurface: narrow band missed part of the surface, evaluating the whole grid");
  }
  compute_normals(grid, field, cells, mesh.normals);
  return mesh;
}

Mesh polygonize(const ScalarField& field, const Aabb& bounds, float cell_size) {
  return polygonize(FunctionField(field), bounds, cell_size);
}

TargetedMesh polygonize_to_vertex_count(const ImplicitField& field, const Aabb& bounds, std::size_t target_vertices,
                                        float tolerance, int max_steps, float initial_cell) {
  if (target_vertices < 8) fail("isosurface: a target of {} vertices is too small", target_vertices);
  const auto target = static_cast<double>(target_vertices);
  // The count follows count ~ C / cell^p with p close to 2 (area / cell^2; finer grids resolve a
  // little more detail, so p is fitted from the last two counts when there are two).
  double exponent = 2.0;
  auto predict = [&](float cell, std::size_t count) {
    return cell * static_cast<float>(std::pow(static_cast<double>(count) / target, 1.0 / exponent));
  };
  auto fit = [&](float cell_a, std::size_t count_a, float cell_b, std::size_t count_b) {
    if (count_a == 0 || count_b == 0 || cell_a == cell_b) return;
    const double p = std::log(static_cast<double>(count_b) / static_cast<double>(count_a)) /
                     std::log(static_cast<double>(cell_a) / static_cast<double>(cell_b));
    exponent = std::clamp(p, 1.5, 2.5);
  };
  float cell = initial_cell;
  if (!(cell > 0.0f)) {
    // Coarse first count (about 48 cells along the longest side), then a count at twice the
    // predicted cell size: a quarter of the cost of the real mesh, and it fixes the exponent.
    const vec3 extent = bounds.extent();
    const float coarse = std::max(extent.x, std::max(extent.y, extent.z)) / 48.0f;
    const std::size_t coarse_count = count_surface_vertices(field, bounds, coarse);
    if (coarse_count == 0) fail("isosurface: the field has no surface inside the bounds");
    const float half = 2.0f * predict(coarse, coarse_count);
    const std::size_t half_count = count_surface_vertices(field, bounds, half);
    fit(coarse, coarse_count, half, half_count);
    cell = predict(half, half_count);
  }
  TargetedMesh best;
  double best_error = std::numeric_limits<double>::infinity();
  for (int step = 0; step < max_steps; ++step) {
    Mesh mesh = polygonize(field, bounds, cell);
    const std::size_t count = mesh.vertex_count();
    const double error = std::abs(static_cast<double>(count) - target) / target;
    if (error < best_error) {
      best_error = error;
      best.mesh = std::move(mesh);
      best.cell_size = cell;
    }
    best.meshes_built = step + 1;
    if (error <= tolerance || count == 0) break;
    cell = predict(cell, count);
  }
  return best;
}

TargetedMesh polygonize_to_vertex_count(const ScalarField& field, const Aabb& bounds, std::size_t target_vertices,
                                        float tolerance, int max_steps, float initial_cell) {
  return polygonize_to_vertex_count(FunctionField(field), bounds, target_vertices, tolerance, max_steps, initial_cell);
}

}  // namespace glint::procedural
