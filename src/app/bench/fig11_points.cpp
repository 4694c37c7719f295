#include "app/bench/fig11_points.h"

#include <string>
#include <vector>

namespace glint::bench {
namespace {

const nlohmann::json* done_cell(const nlohmann::json& cells, const std::string& structure,
                                std::initializer_list<const char*> figures, const std::string& update) {
  for (const char* figure : figures)
    for (const nlohmann::json& cell : cells)
      if (cell["figure"] == figure && cell["structure"] == structure && cell["update"] == update &&
          cell["status"] == "done" && cell["kind"] == "frame_times")
        return &cell;
  return nullptr;
}

nlohmann::json number_at(const nlohmann::json& object, const char* outer, const char* inner) {
  if (!object.contains(outer) || !object[outer].is_object() || !object[outer].contains(inner)) return nullptr;
  const nlohmann::json& value = object[outer][inner];
  return value.is_number() ? value : nlohmann::json(nullptr);
}

}  // namespace

nlohmann::json fig11_points(const nlohmann::json& cells) {
  std::vector<std::string> structures;
  for (const nlohmann::json& cell : cells) {
    const std::string structure = cell["structure"].get<std::string>();
    if (cell["figure"] == "fig12" || cell["kind"] != "frame_times" || structure.empty()) continue;
    bool seen = false;
    for (const std::string& known : structures) seen = seen || known == structure;
    if (!seen) structures.push_back(structure);
  }
  nlohmann::json points = nlohmann::json::array();
  for (const std::string& structure : structures) {
    const nlohmann::json* render = done_cell(cells, structure, {"fig5", "fig8"}, "");
    if (render == nullptr) continue;
    const nlohmann::json* rebuild = done_cell(cells, structure, {"fig7", "fig9"}, "rebuild");
    nlohmann::json point = {{"structure", structure},
                            {"render_ms", number_at(*render, "frame_ms", "mean")},
                            {"render_cell", (*render)["id"]},
                            {"rebuild_ms", rebuild ? number_at(*rebuild, "mean_ms", "accel_update") : nullptr},
                            {"rebuild_cell", rebuild ? (*rebuild)["id"] : nlohmann::json(nullptr)},
                            {"build_ms", number_at(*render, "ray_tracer", "build_ms")}};
    if (point["render_ms"].is_null()) continue;
    points.push_back(std::move(point));
  }
  return points;
}

}  // namespace glint::bench
