// docs/architecture.md's layering rule, "dependencies pointing down only", checked on the code: the
// #include "folder/..." lines of every file under src/'s folders make a graph of those folders,
// which must have no cycle. viewer/ sits above app/ (`glint view` is built on app/'s frame loop and
// render options; src/main.cpp, above every folder, hands the view command to app's run_cli), so
// app/ includes nothing of viewer/.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace glint {
namespace {

namespace fs = std::filesystem;

// Edge "from -> to" with one include line that makes it ("src/rt/x.cpp:4").
using Graph = std::map<std::string, std::map<std::string, std::string>>;

Graph include_graph(const fs::path& src) {
  std::set<std::string> folders;
  for (const fs::directory_entry& entry : fs::directory_iterator(src))
    if (entry.is_directory()) folders.insert(entry.path().filename().string());
  const std::regex include(R"(^\s*#\s*include\s*"([A-Za-z0-9_]+)/)");
  Graph graph;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(src)) {
    if (!entry.is_regular_file()) continue;
    const std::string extension = entry.path().extension().string();
    if (extension != ".h" && extension != ".cpp" && extension != ".cu" && extension != ".cuh" && extension != ".in")
      continue;
    const std::string folder = fs::relative(entry.path(), src).begin()->string();
    if (!folders.contains(folder)) continue;
    std::ifstream file(entry.path());
    std::string line;
    for (int number = 1; std::getline(file, line); ++number) {
      std::smatch match;
      if (!std::regex_search(line, match, include) || !folders.contains(match[1].str())) continue;
      const std::string from = folder, to = match[1].str();
      if (from != to)
        graph[from].emplace(to, fs::relative(entry.path(), src.parent_path()).string() + ":" + std::to_string(number));
    }
  }
  return graph;
}

// One cycle of `graph` as "a -> b (file:line) -> a (file:line)", or nullopt when it has none.
std::optional<std::string> find_cycle(const Graph& graph) {
  std::map<std::string, int> state;  // 0 unseen, 1 on the path, 2 done
  std::vector<std::string> path;
  std::optional<std::string> cycle;
  const auto visit = [&](const auto& self, const std::string& node) -> void {
    state[node] = 1;
    path.push_back(node);
    if (const auto edges = graph.find(node); edges != graph.end()) {
      for (const auto& [next, where] : edges->second) {
        if (cycle) break;
        if (state[next] == 1) {
          const auto start = std::find(path.begin(), path.end(), next);
          std::string text = *start;
          for (auto it = start; it != path.end(); ++it) {
            const std::string& to = it + 1 == path.end() ? next : *(it + 1);
            text += " -> " + to + " (" + graph.at(*it).at(to) + ")";
          }
          cycle = text;
        } else if (state[next] == 0) {
          self(self, next);
        }
      }
    }
    path.pop_back();
    state[node] = 2;
  };
  for (const auto& [node, edges] : graph)
    if (!cycle && state[node] == 0) visit(visit, node);
  return cycle;
}

TEST(FolderDependencies, TheCheckFindsACycleAndPassesALayering) {
  Graph layered{{"app", {{"render", "a"}, {"core", "b"}}}, {"render", {{"core", "c"}}}};
  EXPECT_EQ(find_cycle(layered), std::nullopt);
  layered["core"]["app"] = "src/core/x.h:3";
  EXPECT_EQ(find_cycle(layered), "app -> core (b) -> app (src/core/x.h:3)");
}

TEST(FolderDependencies, SrcFoldersIncludeEachOtherWithoutACycle) {
  const Graph graph = include_graph(fs::path(GLINT_SOURCE_DIR) / "src");
  ASSERT_TRUE(graph.contains("rt") && graph.contains("app")) << "src/ was not read";
  const std::optional<std::string> cycle = find_cycle(graph);
  EXPECT_EQ(cycle, std::nullopt) << "folder-level include cycle: " << *cycle;
}

TEST(FolderDependencies, ViewerSitsAboveApp) {
  const Graph graph = include_graph(fs::path(GLINT_SOURCE_DIR) / "src");
  ASSERT_TRUE(graph.contains("viewer"));
  EXPECT_TRUE(graph.at("viewer").contains("app")) << "the viewer runs app/'s frame loop";
  if (graph.at("app").contains("viewer")) ADD_FAILURE() << "app/ includes viewer/: " << graph.at("app").at("viewer");
}

TEST(FolderDependencies, RtKnowsNoBackendOutsideIt) {
  const Graph graph = include_graph(fs::path(GLINT_SOURCE_DIR) / "src");
  for (const char* backend_folder : {"cuda", "optix", "gl_rt", "backends", "gl"})
    EXPECT_FALSE(graph.at("rt").contains(backend_folder))
        << "rt/ includes " << backend_folder << "/: " << graph.at("rt").at(backend_folder);
  for (const char* folder : {"rt", "cuda", "optix", "gl_rt"})
    EXPECT_FALSE(graph.at(folder).contains("backends")) << folder << "/ includes the registry above it";
}

}  // namespace
}  // namespace glint
