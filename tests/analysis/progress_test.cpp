// Progress reports (kernel/analysis/progress.hpp): the general model, the branch explorer, a
// general trace and the string design call the sink as they work, and a sink changes no
// result. The CLI shows them on stderr only when asked or on a terminal, never on stdout.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "kernel/analysis/foldability_report.hpp"
#include "kernel/analysis/trace_motion.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/topology.hpp"
#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

const std::string kSquareTwist = std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled/square_twist_30_type4.fold";
const std::string kMiura = std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled/miura_4x4_alpha60.fold";

bool any_starts_with(const std::vector<std::string>& lines, const std::string& prefix) {
  return std::any_of(lines.begin(), lines.end(), [&](const std::string& l) { return l.rfind(prefix, 0) == 0; });
}

TEST(Progress, GeneralCheckReportsEachStageAndChangesNothing) {
  const CreasePattern p = read_fold(kSquareTwist);
  const Topology t = build_topology(p, kSquareTwist);
  FoldabilityOptions quiet;
  quiet.force_general = true;
  FoldabilityOptions watched = quiet;
  std::vector<std::string> lines;
  watched.progress = [&](const std::string& m) { lines.push_back(m); };
  const FoldabilityReport a = check_foldability(p, t, quiet);
  const FoldabilityReport b = check_foldability(p, t, watched);

  EXPECT_TRUE(any_starts_with(lines, "choosing the model"));
  EXPECT_TRUE(any_starts_with(lines, "model: "));
  EXPECT_TRUE(any_starts_with(lines, "general search: start 1 of "));
  EXPECT_TRUE(any_starts_with(lines, "general model: tracing candidate 1 of "));
  EXPECT_TRUE(any_starts_with(lines, "branch explorer: branch 0, "));
  // Every continuation point of the certificate and of the explorer is one update.
  EXPECT_GT(lines.size(), b.branches.size());

  ASSERT_EQ(a.verdict, b.verdict);
  EXPECT_EQ(a.dof, b.dof);
  ASSERT_EQ(a.branches.size(), b.branches.size());
  for (std::size_t k = 0; k < a.branches.size(); ++k) ASSERT_EQ(a.branches[k].path.size(), b.branches[k].path.size());
  EXPECT_EQ(a.max_residual, b.max_residual);  // the same arithmetic, bit for bit
  EXPECT_EQ(a.points.size(), b.points.size());
}

TEST(Progress, GeneralTraceReportsContinuationAndEveryOutputStep) {
  const CreasePattern p = read_fold(kMiura);
  const Topology t = build_topology(p, kMiura);
  TraceRequest rq;
  rq.force_general = true;
  rq.steps = 6;
  rq.to = to_radians(120.0);
  std::vector<std::string> lines;
  rq.progress = [&](const std::string& m) { lines.push_back(m); };
  const MotionTrace m = trace_motion(p, t, rq);
  ASSERT_EQ(m.branches.size(), 1u);
  ASSERT_TRUE(m.branches[0].traced);
  EXPECT_TRUE(any_starts_with(lines, "trace: first folded point"));
  EXPECT_TRUE(any_starts_with(lines, "trace: continuation, crease "));
  for (int k = 1; k <= 6; ++k)
    EXPECT_TRUE(any_starts_with(lines, "trace: output step " + std::to_string(k) + " of 6")) << k;
  EXPECT_TRUE(any_starts_with(lines, "trace: placing the faces"));
}

// The CLI: RIGIDFOLD_PROGRESS=always puts the updates on stderr (stdout stays the same JSON);
// never, and a stderr that is no terminal, show none.
TEST(ProgressCli, ShownOnStderrOnlyWhenAskedAndStdoutUnchanged) {
  const std::string check = test::cli() + " check " + kSquareTwist + " --general --json";
  const test::CommandResult shown = test::run_command("RIGIDFOLD_PROGRESS=always " + check);
  const test::CommandResult hidden = test::run_command("RIGIDFOLD_PROGRESS=never " + check);
  const test::CommandResult plain = test::run_command(check);
  ASSERT_EQ(shown.status, 0) << shown.err;
  ASSERT_EQ(hidden.status, 0) << hidden.err;
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_NE(shown.err.find("rigidfold check [0 s]: choosing the model\n"), std::string::npos) << shown.err;
  EXPECT_EQ(hidden.err, "");
  EXPECT_EQ(plain.err, "");  // stderr is a file here, not a terminal
  const auto a = nlohmann::json::parse(shown.out), b = nlohmann::json::parse(hidden.out);
  EXPECT_EQ(a["verdict"], b["verdict"]);
  EXPECT_EQ(a["dof"], b["dof"]);
  EXPECT_EQ(a["branches"].size(), b["branches"].size());

  const std::filesystem::path out =
      std::filesystem::temp_directory_path() / ("rigidfold_progress_" + std::to_string(::getpid()) + ".fold");
  const test::CommandResult design = test::run_command("RIGIDFOLD_PROGRESS=always " + test::cli() + " string design " +
                                                       RIGIDFOLD_SOURCE_DIR + "/data/strings/target_points.json --out " +
                                                       out.string() + " --json");
  std::filesystem::remove(out);
  ASSERT_EQ(design.status, 0) << design.err;
  EXPECT_NE(design.err.find("rigidfold string design [0 s]: string design: closed-form grid, cell 1 of "), std::string::npos)
      << design.err;
}

}}  // namespace
}  // namespace rigidfold
