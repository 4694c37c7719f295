#pragma once
// The cells of `glint bench --experiment paper`: one cell per measured series of the paper's
// Figs. 5, 7-10 and 12 and per quality table (I, II), over the structures the user asked for.
// A cell that cannot run here (its backend is unavailable, its structure cannot be refitted, it
// would repeat another cell) is kept in the matrix with the reason, so it is reported, never dropped.
//
//   fig5   full scene, static                  hybrid  every structure
//   fig7   full scene, deforming               hybrid  every structure x update policy
//   fig8   simple scene, static                hybrid  every structure
//   fig9   simple scene, deforming             hybrid  every structure x update policy
//   fig10  simple scene, deforming, rays see   rt      every structure x update policy
//          only the deforming meshes
//   fig12  simple scene, static and deforming  ssr, hybrid, rt  the first available structure
//   table1 full scene, static                  ssr and hybrid against rt at the paper's frames
//   table2 simple scene, deforming             ssr and hybrid against rt at the paper's frames
// As in the paper, Figs. 9, 10 and 12 and Table II use the simplified scene (Fig. 10's "gains" are
// measured against Fig. 9).
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace glint::bench {

// The quality tables' frames (Tables I and II, Fig. 4).
inline constexpr int kPaperQualityFrames[] = {1800, 2100, 2300, 4400};

// What rays are traced by, as the figures' legends name it: "cpu-sah", "embree", "optix".
struct Structure {
  std::string backend;  // backends::make_ray_tracer name
  std::string accel;    // glint's structure for backends that take glint's builders; "" otherwise
  std::string label() const { return accel.empty() ? backend : backend + "-" + accel; }
};

enum class CellKind { frame_times, quality };

struct Cell {
  std::string id;      // unique and file-name safe: "fig7-cpu-sah-refit", "table1-static"
  std::string figure;  // "fig5" ... "fig12", "table1", "table2"
  CellKind kind = CellKind::frame_times;
  std::string scene;        // as given on the command line (preset name or file)
  std::string reflections;  // frame_times: ssr|hybrid|rt; quality: "" (renders all three)
  Structure structure;      // ssr cells trace nothing; their backend only decides where meshes deform
  std::string update;       // rebuild|refit for deforming cells, "" for static ones
  bool deform = false;
  bool trace_deformable_only = false;  // fig10
  std::optional<std::string> skip_reason;
};

struct MatrixOptions {
  std::string scene = "atrium";
  std::string simple_scene = "atrium-simple";
  std::vector<Structure> structures;                      // backends x accels, in the order asked
  std::vector<std::string> updates = {"rebuild", "refit"};
  std::map<std::string, std::string> unavailable_backends;  // backend -> why it cannot run here
};

// The structures of `backends` x `accels`: accels apply to the backends that take glint's builders
// (backends::Backend::takes_glint_builders); the others build their own and make one structure each.
std::vector<Structure> structures_of(const std::vector<std::string>& backends, const std::vector<std::string>& accels);

// The measured frames of a frame-times cell: 0, stride, 2 stride, ... below min(limit,
// walkthrough_frames). glint::Error for a limit or stride below 1.
std::vector<int> strided_frames(int walkthrough_frames, int limit, int stride);
// The quality tables' frames that a walkthrough of `walkthrough_frames` frames has.
std::vector<int> quality_frames(int walkthrough_frames);

// Every cell of the paper's experiment, in the order they run (figures, then tables).
std::vector<Cell> paper_matrix(const MatrixOptions& options);

}  // namespace glint::bench
