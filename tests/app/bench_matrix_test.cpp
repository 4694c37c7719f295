// The paper's experiment matrix of `glint bench`: every figure's cells, the reasons cells are
// skipped (never dropped), the frames each cell measures, and the flag lists.
#include "app/bench/paper_matrix.h"
#include "app/bench_command.h"

#include "support/error_of.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

namespace glint::bench {
namespace {

MatrixOptions options_for(const std::vector<std::string>& backends, const std::vector<std::string>& accels) {
  MatrixOptions options;
  options.structures = structures_of(backends, accels);
  return options;
}

const Cell& find(const std::vector<Cell>& cells, const std::string& id) {
  const auto found = std::find_if(cells.begin(), cells.end(), [&](const Cell& c) { return c.id == id; });
  if (found == cells.end()) throw std::runtime_error("no cell " + id);
  return *found;
}

TEST(BenchMatrix, StructuresApplyAccelsOnlyToBackendsWithGlintsBuilders) {
  const std::vector<Structure> structures = structures_of({"cpu", "embree", "cuda", "optix"}, {"sah", "lbvh"});
  std::vector<std::string> labels;
  for (const Structure& s : structures) labels.push_back(s.label());
  EXPECT_EQ(labels, (std::vector<std::string>{"cpu-sah", "cpu-lbvh", "embree", "cuda-sah", "cuda-lbvh", "optix"}));
}

TEST(BenchMatrix, EveryFigureHasItsCellsWithUniqueIds) {
  const std::vector<Cell> cells = paper_matrix(options_for({"cpu", "embree"}, {"sah", "lbvh"}));
  std::set<std::string> ids;
  std::map<std::string, int> per_figure;
  for (const Cell& cell : cells) {
    EXPECT_TRUE(ids.insert(cell.id).second) << "repeated id " << cell.id;
    EXPECT_EQ(cell.id.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789-"), std::string::npos) << cell.id;
    ++per_figure[cell.figure];
  }
  // 3 structures; deforming figures x 2 update policies; fig12: 2 scenes x 3 modes.
  EXPECT_EQ(per_figure, (std::map<std::string, int>{{"fig5", 3}, {"fig7", 6}, {"fig8", 3}, {"fig9", 6}, {"fig10", 6},
                                                     {"fig12", 6}, {"table1", 1}, {"table2", 1}}));
  for (const Cell& cell : cells) EXPECT_FALSE(cell.skip_reason) << cell.id << ": " << *cell.skip_reason;
}

TEST(BenchMatrix, CellsMeasureWhatThePaperMeasured) {
  const std::vector<Cell> cells = paper_matrix(options_for({"cpu"}, {"sah"}));
  const Cell& fig5 = find(cells, "fig5-cpu-sah");
  EXPECT_EQ(fig5.scene, "atrium");
  EXPECT_EQ(fig5.reflections, "hybrid");
  EXPECT_FALSE(fig5.deform);
  EXPECT_EQ(fig5.update, "");
  const Cell& fig7 = find(cells, "fig7-cpu-sah-refit");
  EXPECT_TRUE(fig7.deform);
  EXPECT_EQ(fig7.update, "refit");
  EXPECT_EQ(find(cells, "fig9-cpu-sah-rebuild").scene, "atrium-simple");
  const Cell& fig10 = find(cells, "fig10-cpu-sah-rebuild");
  EXPECT_EQ(fig10.reflections, "rt");
  EXPECT_TRUE(fig10.trace_deformable_only);
  EXPECT_EQ(fig10.scene, "atrium-simple") << "the paper compares Fig. 10 with Fig. 9";
  EXPECT_EQ(find(cells, "fig12-deforming-ssr").structure.label(), "cpu-sah")
      << "ssr deforms the meshes where the traced modes do";
  EXPECT_EQ(find(cells, "fig12-deforming-ssr").update, "") << "ssr has no structure to update";
  EXPECT_EQ(find(cells, "fig12-deforming-rt").update, "rebuild") << "the first of --updates";
  const Cell& table1 = find(cells, "table1-static");
  EXPECT_EQ(table1.kind, CellKind::quality);
  EXPECT_EQ(table1.scene, "atrium");
  EXPECT_FALSE(table1.deform);
  const Cell& table2 = find(cells, "table2-deforming");
  EXPECT_EQ(table2.scene, "atrium-simple");
  EXPECT_TRUE(table2.deform);
}

TEST(BenchMatrix, UnavailableBackendsAndUnrefittableStructuresAreSkippedWithTheReason) {
  MatrixOptions options = options_for({"cuda", "cpu"}, {"sbvh", "sah"});
  options.unavailable_backends["cuda"] = "no CUDA device";
  const std::vector<Cell> cells = paper_matrix(options);
  const Cell& cuda = find(cells, "fig5-cuda-sah");
  ASSERT_TRUE(cuda.skip_reason);
  EXPECT_NE(cuda.skip_reason->find("no CUDA device"), std::string::npos);
  ASSERT_TRUE(find(cells, "fig7-cpu-sbvh-refit").skip_reason);
  EXPECT_NE(find(cells, "fig7-cpu-sbvh-refit").skip_reason->find("sbvh cannot be refitted"), std::string::npos);
  EXPECT_FALSE(find(cells, "fig7-cpu-sbvh-rebuild").skip_reason);
  EXPECT_FALSE(find(cells, "fig5-cpu-sbvh").skip_reason) << "a static cell never refits";
  // Fig. 12 and the tables take the first available structure: cuda is not, so cpu-sbvh.
  EXPECT_EQ(find(cells, "fig12-static-hybrid").structure.label(), "cpu-sbvh");
  EXPECT_EQ(find(cells, "table2-deforming").structure.label(), "cpu-sbvh");
}

TEST(BenchMatrix, OneSceneForBothRolesSkipsTheRepeatedFigures) {
  MatrixOptions options = options_for({"cpu"}, {"sah"});
  options.scene = options.simple_scene = "atrium-simple";
  const std::vector<Cell> cells = paper_matrix(options);
  ASSERT_TRUE(find(cells, "fig8-cpu-sah").skip_reason);
  EXPECT_NE(find(cells, "fig9-cpu-sah-refit").skip_reason->find("same scene"), std::string::npos);
  EXPECT_FALSE(find(cells, "fig5-cpu-sah").skip_reason);
  EXPECT_FALSE(find(cells, "fig10-cpu-sah-refit").skip_reason);
}

TEST(BenchMatrix, NoBackendAvailableSkipsTracedCellsButNotSsr) {
  MatrixOptions options = options_for({"optix"}, {"sah"});
  options.unavailable_backends["optix"] = "not in this build";
  const std::vector<Cell> cells = paper_matrix(options);
  EXPECT_FALSE(find(cells, "fig12-static-ssr").skip_reason);
  EXPECT_TRUE(find(cells, "fig12-static-rt").skip_reason);
  EXPECT_TRUE(find(cells, "table1-static").skip_reason);
}

TEST(BenchMatrix, FramesFollowStrideAndLimit) {
  EXPECT_EQ(strided_frames(4900, 4900, 1225), (std::vector<int>{0, 1225, 2450, 3675}));
  EXPECT_EQ(strided_frames(4900, 10, 3), (std::vector<int>{0, 3, 6, 9}));
  EXPECT_EQ(strided_frames(5, 4900, 2), (std::vector<int>{0, 2, 4})) << "a short walkthrough ends the list";
  EXPECT_EQ(strided_frames(4900, 4900, 1).size(), 4900u);
  EXPECT_NE(testing::error_of([] { (void)strided_frames(100, 10, 0); }).find("--stride 0"), std::string::npos);
  EXPECT_EQ(quality_frames(4900), (std::vector<int>{1800, 2100, 2300, 4400}));
  EXPECT_EQ(quality_frames(2200), (std::vector<int>{1800, 2100}));
  EXPECT_TRUE(quality_frames(100).empty());
}

TEST(BenchMatrix, NameListsAreCheckedAgainstTheKnownNames) {
  EXPECT_EQ(parse_name_list("--backends", " cpu , embree", {"cpu", "embree"}), (std::vector<std::string>{"cpu", "embree"}));
  EXPECT_NE(testing::error_of([] { (void)parse_name_list("--backends", "cpu,vulkan", {"cpu", "embree"}); })
                .find("unknown name \"vulkan\" (known: cpu, embree)"),
            std::string::npos);
  EXPECT_NE(testing::error_of([] { (void)parse_name_list("--accels", "sah,,lbvh"); }).find("empty item"),
            std::string::npos);
  EXPECT_NE(testing::error_of([] { (void)parse_name_list("--updates", "refit,refit"); }).find("listed twice"),
            std::string::npos);
}

TEST(BenchMatrix, QuickFillsInOnlyTheFlagsNotGiven) {
  BenchOptions options;
  options.quick = true;
  options.given = {"--width", "--accels"};
  options.width = 200;
  options.accels = "lbvh";
  const BenchOptions quick = with_quick_defaults(options);
  EXPECT_EQ(quick.width, 200);
  EXPECT_EQ(quick.accels, "lbvh");
  EXPECT_EQ(quick.height, 54);
  EXPECT_EQ(quick.backends, "cpu");
  EXPECT_EQ(quick.scene, "atrium-simple");
  const BenchOptions full = with_quick_defaults(BenchOptions{});
  EXPECT_EQ(full.width, 1280) << "without --quick nothing changes";
}

}  // namespace
}  // namespace glint::bench
