#include "scene/procedural/atrium_architecture.h"

#include "scene/procedural/atrium_layout.h"
#include "scene/procedural/mesh_builder.h"

#include <cmath>
#include <string>

namespace glint::procedural {
namespace {

using namespace atrium;
constexpr float kPi = 3.14159265358979f;
constexpr float kTextureMetres = 2.0f;  // every tiling texture covers 2 m x 2 m

// World-planar texture coordinates on a wall facing along z (u = x) or along x (u = z).
vec2 uv_xy(const vec3& p) { return vec2(p.x, p.y) / kTextureMetres; }

// One bay of an arcade wall: the face around a round arch (centre (xc, spring), `radius`) up to
// `top`, between xc - half_width and xc + half_width, on both faces of the wall (z_front faces the
// hall, z_back the aisle), and the arch's soffit between them.
void add_arch_bay(MeshBuilder& builder, float xc, float half_width, float spring, float radius, float top,
                  float z_front, float z_back, int arc_segments, int rings) {
  // The rectangle's boundary in three straight pieces (right side up, top leftwards, left side
  // down); each boundary point is joined to the arch point in the same direction from the centre,
  // so the rectangle's corners are grid lines and the face has no gaps.
  const vec2 corners[4] = {{xc + half_width, spring}, {xc + half_width, top}, {xc - half_width, top}, {xc - half_width, spring}};
  for (const float z : {z_front, z_back}) {
    const vec3 facing(0.0f, 0.0f, (z == z_front) == (z_front < z_back) ? -1.0f : 1.0f);
    for (int piece = 0; piece < 3; ++piece) {
      const vec2 a = corners[piece], b = corners[piece + 1];
      const float angle_a = std::atan2(a.y - spring, a.x - xc), angle_b = std::atan2(b.y - spring, b.x - xc);
      const int n = std::max(2, static_cast<int>(std::lround(static_cast<float>(arc_segments) * std::abs(angle_b - angle_a) / kPi)));
      builder.add_patch(
          n, rings,
          [=](float u, float v) {
            const vec2 edge = glm::mix(a, b, u);
            const float angle = std::atan2(edge.y - spring, edge.x - xc);
            const vec2 arch(xc + radius * std::cos(angle), spring + radius * std::sin(angle));
            const vec2 p = glm::mix(arch, edge, v);
            return vec3(p.x, p.y, z);
          },
          [](const vec3& p, float, float) { return uv_xy(p); }, facing);
    }
  }
  // Soffit: the half cylinder under the arch, facing down into the opening.
  const float depth = std::abs(z_back - z_front);
  builder.add_patch(
      arc_segments, std::max(1, static_cast<int>(std::ceil(depth / 0.3f))),
      [=](float u, float v) {
        const float angle = kPi * u;
        return vec3(xc + radius * std::cos(angle), spring + radius * std::sin(angle), glm::mix(z_front, z_back, v));
      },
      UvMap{vec2(0.0f), vec2(kPi * radius, depth) / kTextureMetres}, vec3(0.0f, -1.0f, 0.0f));
}

// A round column: square plinth, moulded base, shaft with a slight swelling (entasis), flared
// capital and a square abacus on which the arches spring.
struct ColumnShape {
  float bottom, radius, plinth_half, plinth_height, abacus_half, abacus_bottom, abacus_top;
};
void add_column(MeshBuilder& builder, vec2 centre, const ColumnShape& c, int segments, float box_segment) {
  const vec3 base(centre.x, 0.0f, centre.y);
  builder.add_box(vec3(centre.x - c.plinth_half, c.bottom, centre.y - c.plinth_half),
                  vec3(centre.x + c.plinth_half, c.bottom + c.plinth_height, centre.y + c.plinth_half), box_segment,
                  kTextureMetres, 0x3Bu);  // no bottom face
  const float r = c.radius, y0 = c.bottom + c.plinth_height, y1 = c.abacus_bottom;
  // Base moulding (a torus-like roll), then the shaft, then the capital's echinus: one smooth
  // profile each, so the creases between them stay sharp.
  builder.add_lathe(base, {{1.25f * r, y0}, {1.27f * r, y0 + 0.04f}, {1.2f * r, y0 + 0.08f}, {1.05f * r, y0 + 0.11f}},
                    segments, kTextureMetres);
  std::vector<vec2> shaft;
  const float shaft_bottom = y0 + 0.11f, shaft_top = y1 - 0.22f;
  constexpr int kRings = 10;
  for (int i = 0; i <= kRings; ++i) {
    const float t = static_cast<float>(i) / kRings;
    // Entasis: widest a third of the way up, 8 % slimmer at the top.
    const float swell = 1.0f + 0.03f * std::sin(kPi * std::min(1.0f, t * 1.5f)) - 0.08f * t * t;
    shaft.emplace_back(r * swell, glm::mix(shaft_bottom, shaft_top, t));
  }
  builder.add_lathe(base, shaft, segments, kTextureMetres);
  const float neck = shaft.back().x;
  builder.add_lathe(base, {{neck, shaft_top}, {neck * 1.08f, shaft_top + 0.06f}, {neck * 1.25f, shaft_top + 0.13f},
                           {c.abacus_half * 0.95f, y1 - 0.02f}, {c.abacus_half * 0.95f, y1}},
                    segments, kTextureMetres);
  builder.add_box(vec3(centre.x - c.abacus_half, c.abacus_bottom, centre.y - c.abacus_half),
                  vec3(centre.x + c.abacus_half, c.abacus_top, centre.y + c.abacus_half), box_segment, kTextureMetres,
                  0x3Bu);
}

std::uint32_t add_mesh(Scene& scene, Mesh&& mesh, std::uint32_t material) {
  mesh.material = material;
  const auto index = static_cast<std::uint32_t>(scene.meshes.size());
  scene.instances.push_back(Instance{mesh.name, index, mat4(1.0f)});
  scene.meshes.push_back(std::move(mesh));
  return index;
}

Mesh make_floor(const ArchitectureDetail& detail) {
  Mesh mesh;
  mesh.name = "floor";
  MeshBuilder builder(mesh);
  builder.add_rectangle(vec3(-kHalfLength, 0.0f, -kAisleWall), vec3(2.0f * kHalfLength, 0, 0), vec3(0, 0, 2.0f * kAisleWall),
                        detail.floor_segment, kTextureMetres, vec3(0, 1, 0));
  return mesh;
}

Mesh make_columns(const ArchitectureDetail& detail) {
  Mesh mesh;
  mesh.name = "columns";
  MeshBuilder builder(mesh);
  const ColumnShape lower{0.0f, kLowerColumnRadius, 0.42f, 0.18f, kLowerAbacusHalf, kLowerSpring - 0.2f, kLowerSpring};
  for (const vec2 c : lower_column_centres()) add_column(builder, c, lower, detail.column_segments, detail.trim_segment);
  const ColumnShape upper{kGalleryFloor, kUpperColumnRadius, 0.22f, 0.1f, kUpperAbacusHalf, kUpperSpring - 0.15f, kUpperSpring};
  for (const vec2 c : upper_column_centres())
    add_column(builder, c, upper, std::max(8, detail.column_segments * 2 / 3), detail.trim_segment);
  return mesh;
}

Mesh make_arcades(const ArchitectureDetail& detail) {
  Mesh mesh;
  mesh.name = "arcades";
  MeshBuilder builder(mesh);
  for (const float side : {-1.0f, 1.0f}) {
    const float lower_front = side * (kColumnLine - kArcadeHalfThickness), lower_back = side * (kColumnLine + kArcadeHalfThickness);
    const float upper_front = side * (kColumnLine - kUpperHalfThickness), upper_back = side * (kColumnLine + kUpperHalfThickness);
    for (int bay = 0; bay < kBays; ++bay)
      add_arch_bay(builder, bay_centre(bay), 0.5f * kBay, kLowerSpring, kLowerArchRadius, kGalleryFloor, lower_front,
                   lower_back, 18, 6);
    for (int bay = 0; bay < kUpperBays; ++bay)
      add_arch_bay(builder, -kHalfLength + kUpperBay * (static_cast<float>(bay) + 0.5f), 0.5f * kUpperBay, kUpperSpring,
                   kUpperArchRadius, kRoofLevel, upper_front, upper_back, 10, 4);
    // Half piers against the end walls, where the outermost arches spring.
    for (const float end : {-1.0f, 1.0f}) {
      const float inner = end * (kHalfLength - kLowerAbacusHalf), outer = end * kHalfLength;
      builder.add_box(vec3(std::min(inner, outer), 0.0f, std::min(lower_front, lower_back)),
                      vec3(std::max(inner, outer), kLowerSpring, std::max(lower_front, lower_back)), detail.flat_segment,
                      kTextureMetres, (end > 0 ? 0x01u : 0x02u) | 0x30u);
      const float upper_inner = end * (kHalfLength - kUpperAbacusHalf);
      builder.add_box(vec3(std::min(upper_inner, outer), kGalleryFloor, std::min(upper_front, upper_back)),
                      vec3(std::max(upper_inner, outer), kUpperSpring, std::max(upper_front, upper_back)),
                      detail.flat_segment, kTextureMetres, (end > 0 ? 0x01u : 0x02u) | 0x30u);
    }
    // Cornices along the hall: under the gallery's edge and at the roof line.
    const float z0 = side * (kColumnLine - kArcadeHalfThickness - 0.15f), z1 = side * (kColumnLine - kArcadeHalfThickness);
    builder.add_box(vec3(-kHalfLength, kGalleryFloor - 0.15f, std::min(z0, z1)), vec3(kHalfLength, kGalleryFloor + 0.1f, std::max(z0, z1)),
                    detail.trim_segment, kTextureMetres, side > 0 ? 0x1Cu : 0x2Cu);
    const float r0 = side * (kColumnLine - kUpperHalfThickness - 0.25f), r1 = side * (kColumnLine + kUpperHalfThickness);
    builder.add_box(vec3(-kHalfLength, kRoofLevel - 0.1f, std::min(r0, r1)), vec3(kHalfLength, kRoofLevel + 0.3f, std::max(r0, r1)),
                    detail.trim_segment, kTextureMetres, side > 0 ? 0x1Cu : 0x2Cu);
  }
  return mesh;
}

Mesh make_gallery_floor(const ArchitectureDetail& detail) {
  Mesh mesh;
  mesh.name = "gallery-floor";
  MeshBuilder builder(mesh);
  for (const float side : {-1.0f, 1.0f}) {
    const float z0 = side * (kColumnLine - kArcadeHalfThickness), z1 = side * kAisleWall;
    builder.add_rectangle(vec3(-kHalfLength, kGalleryFloor, std::min(z0, z1)), vec3(2.0f * kHalfLength, 0, 0),
                          vec3(0, 0, std::abs(z1 - z0)), detail.flat_segment, kTextureMetres, vec3(0, 1, 0));
  }
  return mesh;
}

Mesh make_ceilings(const ArchitectureDetail& detail) {
  Mesh mesh;
  mesh.name = "ceilings";
  MeshBuilder builder(mesh);
  for (const float side : {-1.0f, 1.0f}) {
    const float lower0 = side * (kColumnLine + kArcadeHalfThickness), upper0 = side * (kColumnLine + kUpperHalfThickness);
    const float wall = side * kAisleWall;
    builder.add_rectangle(vec3(-kHalfLength, kAisleCeiling, std::min(lower0, wall)), vec3(2.0f * kHalfLength, 0, 0),
                          vec3(0, 0, std::abs(wall - lower0)), detail.flat_segment, kTextureMetres, vec3(0, -1, 0));
    builder.add_rectangle(vec3(-kHalfLength, kRoofLevel, std::min(upper0, wall)), vec3(2.0f * kHalfLength, 0, 0),
                          vec3(0, 0, std::abs(wall - upper0)), detail.flat_segment, kTextureMetres, vec3(0, -1, 0));
    // The slab between the aisle ceiling and the gallery floor, seen from the aisle side of the arcade.
    builder.add_rectangle(vec3(-kHalfLength, kAisleCeiling, lower0), vec3(2.0f * kHalfLength, 0, 0),
                          vec3(0, kGalleryFloor - kAisleCeiling, 0), detail.flat_segment, kTextureMetres,
                          vec3(0, 0, side));
  }
  return mesh;
}

Mesh make_walls(const ArchitectureDetail& detail) {
  Mesh mesh;
  mesh.name = "walls";
  MeshBuilder builder(mesh);
  const float length = 2.0f * kHalfLength, width = 2.0f * kAisleWall;
  // Back walls of the aisles, windows in the gallery storey.
  for (const float side : {-1.0f, 1.0f}) {
    std::vector<MeshBuilder::Opening> windows;
    for (int bay = 0; bay < kBays; ++bay) {
      const float s = bay_centre(bay) + kHalfLength;
      windows.push_back({s - 0.6f, s + 0.6f, 7.2f, 9.4f});
    }
    builder.add_wall(vec3(-kHalfLength, 0.0f, side * kAisleWall), vec3(length, 0, 0), vec3(0, kRoofLevel, 0), windows,
                     detail.flat_segment, kTextureMetres, vec3(0, 0, -side));
    for (const auto& w : windows) {
      // Window reveals through the wall's thickness.
      const float x0 = w.s0 - kHalfLength, x1 = w.s1 - kHalfLength, z = side * kAisleWall, dz = side * kOuterWallThickness;
      builder.add_rectangle(vec3(x0, w.t0, z), vec3(0, 0, dz), vec3(0, w.t1 - w.t0, 0), detail.flat_segment, kTextureMetres, vec3(1, 0, 0));
      builder.add_rectangle(vec3(x1, w.t0, z), vec3(0, 0, dz), vec3(0, w.t1 - w.t0, 0), detail.flat_segment, kTextureMetres, vec3(-1, 0, 0));
      builder.add_rectangle(vec3(x0, w.t0, z), vec3(x1 - x0, 0, 0), vec3(0, 0, dz), detail.flat_segment, kTextureMetres, vec3(0, 1, 0));
      builder.add_rectangle(vec3(x0, w.t1, z), vec3(x1 - x0, 0, 0), vec3(0, 0, dz), detail.flat_segment, kTextureMetres, vec3(0, -1, 0));
    }
  }
  // End walls: a tall doorway into the hall, a smaller one into each aisle, windows above them.
  const std::vector<MeshBuilder::Opening> openings = {
      {kAisleWall - 1.6f, kAisleWall + 1.6f, 0.0f, 4.2f},
      {1.0f, 2.6f, 0.0f, 2.8f},
      {width - 2.6f, width - 1.0f, 0.0f, 2.8f},
      {1.2f, 2.4f, 7.2f, 9.0f},
      {width - 2.4f, width - 1.2f, 7.2f, 9.0f},
  };
  for (const float end : {-1.0f, 1.0f}) {
    const float x = end * kHalfLength, dx = end * kOuterWallThickness;
    builder.add_wall(vec3(x, 0.0f, -kAisleWall), vec3(0, 0, width), vec3(0, kRoofLevel, 0), openings, detail.flat_segment,
                     kTextureMetres, vec3(-end, 0, 0));
    for (const auto& o : openings) {
      const float z0 = o.s0 - kAisleWall, z1 = o.s1 - kAisleWall;
      builder.add_rectangle(vec3(x, o.t0, z0), vec3(dx, 0, 0), vec3(0, o.t1 - o.t0, 0), detail.flat_segment, kTextureMetres, vec3(0, 0, 1));
      builder.add_rectangle(vec3(x, o.t0, z1), vec3(dx, 0, 0), vec3(0, o.t1 - o.t0, 0), detail.flat_segment, kTextureMetres, vec3(0, 0, -1));
      builder.add_rectangle(vec3(x, o.t1, z0), vec3(dx, 0, 0), vec3(0, 0, z1 - z0), detail.flat_segment, kTextureMetres, vec3(0, -1, 0));
      if (o.t0 > 0.0f)
        builder.add_rectangle(vec3(x, o.t0, z0), vec3(dx, 0, 0), vec3(0, 0, z1 - z0), detail.flat_segment, kTextureMetres, vec3(0, 1, 0));
    }
  }
  builder.compact();  // the openings leave unused grid vertices
  return mesh;
}

Mesh make_balustrade(const ArchitectureDetail& detail) {
  Mesh mesh;
  mesh.name = "balustrade";
  MeshBuilder builder(mesh);
  // Turned balusters between the upper columns, on a plinth rail, under a hand rail.
  const std::vector<vec2> profile = {{0.055f, 0.0f}, {0.045f, 0.1f}, {0.06f, 0.28f}, {0.085f, 0.42f}, {0.07f, 0.52f},
                                     {0.04f, 0.62f}, {0.045f, 0.72f}, {0.06f, 0.78f}};
  constexpr float kRailBottom = kGalleryFloor + 0.1f, kRailTop = kBalustradeTop - 0.12f;
  for (const float side : {-1.0f, 1.0f}) {
    const float z = side * kColumnLine;
    for (int bay = 0; bay < kUpperBays; ++bay) {
      const float x0 = -kHalfLength + kUpperBay * static_cast<float>(bay);
      const float start = x0 + (bay == 0 ? 0.0f : kUpperColumnRadius), end = x0 + kUpperBay - (bay + 1 == kUpperBays ? 0.0f : kUpperColumnRadius);
      builder.add_box(vec3(start, kGalleryFloor, z - 0.12f), vec3(end, kRailBottom, z + 0.12f), detail.trim_segment, kTextureMetres, 0x3Cu);
      builder.add_box(vec3(start, kRailTop, z - 0.13f), vec3(end, kBalustradeTop, z + 0.13f), detail.trim_segment, kTextureMetres, 0x3Cu);
      constexpr int kBalusters = 6;
      for (int b = 0; b < kBalusters; ++b) {
        const float x = x0 + 0.375f + 0.25f * static_cast<float>(b);
        std::vector<vec2> scaled;
        for (const vec2 p : profile) scaled.emplace_back(p.x, kRailBottom + p.y * (kRailTop - kRailBottom) / 0.78f);
        builder.add_lathe(vec3(x, 0.0f, z), scaled, detail.baluster_segments, 0.5f);
      }
    }
  }
  return mesh;
}

Mesh make_beams(const ArchitectureDetail& detail) {
  Mesh mesh;
  mesh.name = "beams";
  MeshBuilder builder(mesh);
  for (const float side : {-1.0f, 1.0f}) {
    const float lower0 = side * (kColumnLine + kArcadeHalfThickness), upper0 = side * (kColumnLine + kUpperHalfThickness);
    const float wall = side * kAisleWall;
    for (const vec2 c : lower_column_centres())
      if (c.y * side > 0.0f)
        builder.add_box(vec3(c.x - 0.1f, kAisleCeiling - 0.25f, std::min(lower0, wall)), vec3(c.x + 0.1f, kAisleCeiling, std::max(lower0, wall)),
                        detail.trim_segment, kTextureMetres, 0x37u);
    for (const vec2 c : upper_column_centres())
      if (c.y * side > 0.0f)
        builder.add_box(vec3(c.x - 0.08f, kRoofLevel - 0.2f, std::min(upper0, wall)), vec3(c.x + 0.08f, kRoofLevel, std::max(upper0, wall)),
                        detail.trim_segment, kTextureMetres, 0x37u);
  }
  return mesh;
}

// A banner hanging in front of a ground bay: a cloth grid with soft vertical folds that deepen
// towards the hem, two-sided (a front sheet facing the hall and a back sheet facing the wall).
void add_drape(MeshBuilder& builder, float xc, float side, const ArchitectureDetail& detail, float phase) {
  constexpr float kWidth = 2.3f, kTop = kBalustradeTop + 0.3f, kBottom = 2.4f;
  const float z_hang = side * (kColumnLine - kArcadeHalfThickness - 0.35f);
  for (const float sheet : {0.0f, 1.0f}) {
    const float offset = side * 0.012f * sheet;  // the back sheet sits just behind the front one
    builder.add_patch(
        detail.drape_columns, detail.drape_rows,
        [=](float u, float v) {
          const float folds = std::sin(2.0f * kPi * 4.0f * u + phase) * (0.03f + 0.07f * v);
          const float billow = 0.12f * v * v;  // the hem swings out towards the hall
          const float gather = 1.0f - 0.06f * v;
          return vec3(xc + (u - 0.5f) * kWidth * gather, glm::mix(kTop, kBottom, v), z_hang + offset - side * (folds + billow));
        },
        sheet == 0.0f ? UvMap{vec2(0.0f, 1.0f), vec2(1.0f, -1.0f)} : UvMap{vec2(1.0f, 1.0f), vec2(-1.0f, -1.0f)},
        vec3(0.0f, 0.0f, sheet == 0.0f ? -side : side));
  }
}

}  // namespace

void add_atrium_architecture(Scene& scene, const ArchitectureMaterials& materials, const ArchitectureDetail& detail) {
  add_mesh(scene, make_floor(detail), materials.marble);
  add_mesh(scene, make_columns(detail), materials.stone);
  add_mesh(scene, make_arcades(detail), materials.stone);
  add_mesh(scene, make_gallery_floor(detail), materials.polished_stone);
  add_mesh(scene, make_balustrade(detail), materials.metal);
  add_mesh(scene, make_ceilings(detail), materials.plaster);
  add_mesh(scene, make_walls(detail), materials.brick);
  add_mesh(scene, make_beams(detail), materials.wood);
  Mesh red, blue;
  red.name = "drapes-red";
  blue.name = "drapes-blue";
  MeshBuilder red_builder(red), blue_builder(blue);
  int count = 0;
  for (const float side : {-1.0f, 1.0f})
    for (int bay = 0; bay < kBays; ++bay) {
      if (!bay_has_drape(bay)) continue;
      add_drape(count % 2 == 0 ? red_builder : blue_builder, bay_centre(bay), side, detail, 0.7f * static_cast<float>(count));
      ++count;
    }
  add_mesh(scene, std::move(red), materials.fabric_red);
  add_mesh(scene, std::move(blue), materials.fabric_blue);
}

}  // namespace glint::procedural
