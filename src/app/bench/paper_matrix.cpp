#include "app/bench/paper_matrix.h"

#include "backends/registry.h"
#include "core/error.h"
#include "rt/blas_structure.h"

#include <fmt/format.h>

#include <algorithm>

namespace glint::bench {
namespace {

// Why `structure` cannot run a cell with `update` (deforming cells), if it cannot.
std::optional<std::string> skip_reason(const MatrixOptions& options, const Structure& structure,
                                       const std::string& update) {
  if (const auto found = options.unavailable_backends.find(structure.backend);
      found != options.unavailable_backends.end())
    return fmt::format("backend {} unavailable: {}", structure.backend, found->second);
  if (structure.accel == "sbvh" && (update == "refit" || update == "auto"))
    return std::string("sbvh cannot be refitted (its spatial splits reference triangles in several leaves)");
  if (structure.accel == rt::kKdTreeStructureName && (update == "refit" || update == "auto"))
    return std::string("kdtree cannot be refitted (a triangle is referenced by every cell it crosses)");
  if (structure.accel == rt::kKdTreeStructureName && structure.backend == "gl")
    return std::string("the gl backend traces BVHs only (kdtree: cpu and cuda backends)");
  return std::nullopt;
}

std::optional<Structure> first_available(const MatrixOptions& options) {
  for (const Structure& structure : options.structures)
    if (!options.unavailable_backends.contains(structure.backend)) return structure;
  return std::nullopt;
}

class MatrixBuilder {
public:
  explicit MatrixBuilder(const MatrixOptions& options) : options_(options) {}

  void per_structure(const std::string& figure, const std::string& scene, const std::string& reflections,
                     bool deform, bool deformable_only, const std::optional<std::string>& repeats) {
    for (const Structure& structure : options_.structures) {
      for (const std::string& update : deform ? options_.updates : std::vector<std::string>{""}) {
        Cell cell = make(figure, scene, reflections, structure, update, deform);
        cell.id = figure + "-" + structure.label() + (update.empty() ? "" : "-" + update);
        cell.trace_deformable_only = deformable_only;
        cell.skip_reason = repeats ? repeats : skip_reason(options_, structure, update);
        cells_.push_back(std::move(cell));
      }
    }
  }

  void fig12() {
    const std::optional<Structure> structure = first_available(options_);
    for (const bool deform : {false, true}) {
      const std::string update = deform ? options_.updates.front() : "";
      for (const char* mode : {"ssr", "hybrid", "rt"}) {
        const bool traces = std::string(mode) != "ssr";
        // ssr traces no rays, but keeps the structure's backend: it decides where the meshes deform
        // (a cuda structure deforms them on the GPU), which must match the other two modes.
        Cell cell = make("fig12", options_.simple_scene, mode, structure.value_or(Structure{}), traces ? update : "",
                         deform);
        cell.id = fmt::format("fig12-{}-{}", deform ? "deforming" : "static", mode);
        if (traces && !structure) cell.skip_reason = "no backend of --backends is available";
        else if (traces) cell.skip_reason = skip_reason(options_, *structure, update);
        cells_.push_back(std::move(cell));
      }
    }
  }

  void table(const std::string& figure, const std::string& scene, bool deform) {
    const std::optional<Structure> structure = first_available(options_);
    const std::string update = deform ? options_.updates.front() : "";
    Cell cell = make(figure, scene, "", structure.value_or(Structure{}), update, deform);
    cell.kind = CellKind::quality;
    cell.id = figure + (deform ? "-deforming" : "-static");
    cell.skip_reason = structure ? skip_reason(options_, *structure, update)
                                 : std::optional<std::string>("no backend of --backends is available");
    cells_.push_back(std::move(cell));
  }

  std::vector<Cell> take() { return std::move(cells_); }

private:
  static Cell make(const std::string& figure, const std::string& scene, const std::string& reflections,
                   const Structure& structure, const std::string& update, bool deform) {
    Cell cell;
    cell.figure = figure;
    cell.scene = scene;
    cell.reflections = reflections;
    cell.structure = structure;
    cell.update = update;
    cell.deform = deform;
    return cell;
  }

  const MatrixOptions& options_;
  std::vector<Cell> cells_;
};

}  // namespace

std::vector<Structure> structures_of(const std::vector<std::string>& backends, const std::vector<std::string>& accels) {
  std::vector<Structure> structures;
  for (const std::string& backend : backends) {
    if (!backends::find_backend(backend).takes_glint_builders) {
      structures.push_back({backend, ""});
      continue;
    }
    for (const std::string& accel : accels) structures.push_back({backend, accel});
  }
  return structures;
}

std::vector<int> strided_frames(int walkthrough_frames, int limit, int stride) {
  if (limit < 1) fail("--frames {} must be at least 1", limit);
  if (stride < 1) fail("--stride {} must be at least 1", stride);
  std::vector<int> frames;
  for (int frame = 0; frame < std::min(limit, walkthrough_frames); frame += stride) frames.push_back(frame);
  return frames;
}

std::vector<int> quality_frames(int walkthrough_frames) {
  std::vector<int> frames;
  for (const int frame : kPaperQualityFrames)
    if (frame < walkthrough_frames) frames.push_back(frame);
  return frames;
}

std::vector<Cell> paper_matrix(const MatrixOptions& options) {
  if (options.structures.empty()) fail("bench: no structure to measure (--backends and --accels are empty)");
  if (options.updates.empty()) fail("bench: no update policy to measure (--updates is empty)");
  // With one scene for both roles, Figs. 8 and 9 would measure Figs. 5 and 7 again.
  std::optional<std::string> repeats;
  if (options.scene == options.simple_scene)
    repeats = fmt::format("same scene as fig5/fig7 (--scene and --simple-scene are both {})", options.scene);

  MatrixBuilder matrix(options);
  matrix.per_structure("fig5", options.scene, "hybrid", false, false, std::nullopt);
  matrix.per_structure("fig7", options.scene, "hybrid", true, false, std::nullopt);
  matrix.per_structure("fig8", options.simple_scene, "hybrid", false, false, repeats);
  matrix.per_structure("fig9", options.simple_scene, "hybrid", true, false, repeats);
  matrix.per_structure("fig10", options.simple_scene, "rt", true, true, std::nullopt);
  matrix.fig12();
  matrix.table("table1", options.scene, false);
  matrix.table("table2", options.simple_scene, true);
  return matrix.take();
}

}  // namespace glint::bench
