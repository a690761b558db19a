// Seed 003 §3.2.3, Fig 3-9 (the mixed tessellation of Fig 3-9(b)
// is non-rigid). The 5 x 5-panel double-corrugated sheet (data/generators/corrugated_tessellation.hpp)
// has 16 interior vertices; its four corner windows are unit P and decide every letter. The
// figure is lost, so the test searches every choice of the four corner P assignments (32
// flat-foldable ones each: corrugated_flat_foldable_assignments and their flips), keeps the
// choices whose shared creases agree, and:
//   - their number equals the count of the kernel's assignment enumeration of the sheet
//     (Maekawa + big-little-big per vertex, found by its own backtracking);
//   - for every choice with four rigid corner windows (the seed builds Fig 3-9(a)-(c) so),
//     the kernel's verdict on the whole sheet (check_foldability, the `rigidfold check` front
//     door) is "foldable" iff each of the nine windows, checked as its own pattern, is; a
//     corner window's kernel verdict equals the loop-gain rule of the P unit
//     (CorrugatedChoice::rigid);
//   - Fig 3-9(b): four rigid corner windows from two P assignments (two each, as the seed's
//     "two P1 patterns and P2 patterns"), with a non-rigid derived P-shaped and a non-rigid
//     derived Q-shaped window (the seed's "P6 and Q6 are nonrigid"): the sheet is not rigidly
//     foldable, with a proof (a cycle of multiplier ties whose loop gain is not 1); Fig
//     3-9(a)/(c): all nine windows rigid, the sheet foldable with 1 DOF.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "data/generators/corrugated_tessellation.hpp"
#include "data/generators/double_corrugated.hpp"
#include "data/generators/generator_common.hpp"
#include "kernel/analysis/assignment_enumeration.hpp"
#include "kernel/analysis/foldability_report.hpp"
#include "kernel/pattern/assignment.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/topology.hpp"
#include "tests/support/run_command.hpp"

namespace rigidfold::generators {
namespace { namespace RIGIDFOLD_UNITY_ID {

using A = Assignment;

struct Option {
  std::vector<A> letters;
  std::array<int, 4> odd{};
  bool rigid = false;
  int klass = 0;  // odd-joint pattern index (flip ignored)
};

std::vector<Option> p_options() {
  std::vector<Option> out;
  int k = 0;
  for (const auto& c : corrugated_flat_foldable_assignments(CorrugatedUnit::P)) {
    Option o{c.assignment, c.odd_joint, c.rigid, k};
    out.push_back(o);
    for (A& a : o.letters) a = a == A::Mountain ? A::Valley : A::Mountain;
    out.push_back(o);
    ++k;
  }
  return out;
}

bool foldable(const FoldabilityReport& r) { return r.verdict == FoldabilityClass::kFoldable; }

// Every choice of the four corners' options whose shared creases agree (backtracking).
std::vector<std::array<int, 4>> consistent_choices(const std::vector<Option>& options) {
  std::array<std::array<int, 12>, 4> edges;
  for (int k = 0; k < 4; ++k) edges[k] = corrugated_tessellation_corner_edges(k);
  std::vector<std::array<int, 4>> choices;
  std::map<int, A> set;
  std::array<int, 4> pick{};
  std::function<void(int)> search = [&](int k) {
    if (k == 4) {
      choices.push_back(pick);
      return;
    }
    for (int o = 0; o < static_cast<int>(options.size()); ++o) {
      bool ok = true;
      for (int c = 0; c < 12 && ok; ++c) {
        const auto it = set.find(edges[k][c]);
        ok = it == set.end() || it->second == options[o].letters[c];
      }
      if (!ok) continue;
      std::vector<int> added;
      for (int c = 0; c < 12; ++c)
        if (set.emplace(edges[k][c], options[o].letters[c]).second) added.push_back(edges[k][c]);
      pick[k] = o;
      search(k + 1);
      for (int e : added) set.erase(e);
    }
  };
  search(0);
  return choices;
}

TEST(CorrugatedTessellation, Fig3_9MixedTessellationIsNotRigid) {
  const CorrugatedParams params;  // alpha 135 deg, beta 60 deg (the seed's example)
  const auto options = p_options();
  ASSERT_EQ(options.size(), 32u);
  const std::vector<std::array<int, 4>> choices = consistent_choices(options);
  ASSERT_FALSE(choices.empty());

  // The kernel's own enumeration of the sheet finds the same number of assignments.
  {
    std::array<std::vector<A>, 4> any;
    for (int k = 0; k < 4; ++k) any[k] = options[choices[0][k]].letters;
    const CreasePattern sheet = corrugated_tessellation(params, any);
    AssignmentEnumerationOptions eo;
    eo.max_verdicts = 0;
    const AssignmentEnumeration en = enumerate_assignments(sheet, build_topology(sheet), eo);
    ASSERT_TRUE(en.complete);
    EXPECT_EQ(en.assignments, static_cast<long>(choices.size()));
  }

  const auto windows = corrugated_tessellation_windows();
  int rigid_corner_choices = 0, all_rigid = 0, mixed = 0;
  bool found_b = false, found_a = false;
  for (const auto& ch : choices) {
    bool corners_rigid = true;
    for (int k = 0; k < 4; ++k) corners_rigid = corners_rigid && options[ch[k]].rigid;
    if (!corners_rigid) continue;
    ++rigid_corner_choices;
    std::array<std::vector<A>, 4> letters;
    for (int k = 0; k < 4; ++k) letters[k] = options[ch[k]].letters;
    const CreasePattern sheet = corrugated_tessellation(params, letters);
    const FoldabilityReport whole = check_foldability(sheet, build_topology(sheet));
    std::array<bool, 9> window_rigid{};
    bool every = true, p_bad = false, q_bad = false;
    for (const auto& w : windows) {
      const CreasePattern wp = corrugated_tessellation_window(params, sheet, w.wa, w.wb);
      const FoldabilityReport r = check_foldability(wp, build_topology(wp));
      ASSERT_TRUE(r.verdict == FoldabilityClass::kFoldable || r.verdict == FoldabilityClass::kNotFoldableProof)
          << "window " << w.wa << "," << w.wb << ": " << r.reason;
      window_rigid[3 * w.wb + w.wa] = foldable(r);
      every = every && foldable(r);
      const bool corner = w.wa % 2 == 0 && w.wb % 2 == 0;
      if (corner) {
        const int k = (w.wa / 2) + 2 * (w.wb / 2);
        EXPECT_EQ(foldable(r), options[ch[k]].rigid) << "corner window " << k;
      } else if (!foldable(r)) {
        (w.p_shaped ? p_bad : q_bad) = true;
      }
    }
    ASSERT_TRUE(whole.verdict == FoldabilityClass::kFoldable || whole.verdict == FoldabilityClass::kNotFoldableProof)
        << whole.reason;
    EXPECT_EQ(foldable(whole), every) << whole.reason;
    EXPECT_TRUE(whole.is_proof) << whole.reason;
    if (every) {
      ++all_rigid;
      EXPECT_EQ(whole.dof, 1);
      found_a = true;
    } else {
      ++mixed;
      ASSERT_TRUE(whole.obstruction.has_value());
      ASSERT_TRUE(whole.obstruction->exact.has_value()) << whole.reason;
      EXPECT_EQ(whole.obstruction->exact->kind, Obstruction::Kind::kLoopGain) << whole.reason;
      EXPECT_GT(std::fabs(whole.obstruction->exact->loop_gain - 1.0), 1e-6) << whole.reason;
      // Fig 3-9(b): two P assignments, two corners each; a non-rigid derived P and Q window.
      std::map<int, int> per_class;
      for (int k = 0; k < 4; ++k) ++per_class[options[ch[k]].klass];
      const bool two_two = per_class.size() == 2 && per_class.begin()->second == 2;
      if (two_two && p_bad && q_bad && !found_b) {
        found_b = true;
        std::string text;
        for (const auto& l : letters) {
          for (A a : l) text += assignment_letter(a);
          text += ' ';
        }
        RecordProperty("fig3_9b_corners", text);
        std::printf("[ fig 3-9(b) ] corners %s: %s\n", text.c_str(), whole.reason.c_str());
      }
    }
  }
  std::printf("[ corrugated ] %zu consistent sheets, %d with rigid corners: %d rigid, %d not\n", choices.size(),
              rigid_corner_choices, all_rigid, mixed);
  EXPECT_TRUE(found_a) << "no sheet with all nine windows rigid (Fig 3-9(a)/(c))";
  EXPECT_TRUE(found_b) << "no sheet like Fig 3-9(b)";
  EXPECT_GT(mixed, 0);
}

// The header's claims on the windows: the corner windows are translated copies of unit P,
// windows (1, 0) and (1, 2) of unit Q (corrugated_unit), with the sheet's letters on the
// unit's interior creases; p_shaped follows the central panel's angle.
TEST(CorrugatedTessellation, WindowsAreTranslatedUnits) {
  const CorrugatedParams params;
  const auto options = p_options();
  const auto choices = consistent_choices(options);
  ASSERT_FALSE(choices.empty());
  std::array<std::vector<A>, 4> corners;
  for (int k = 0; k < 4; ++k) corners[k] = options[choices.back()[k]].letters;
  const CreasePattern sheet = corrugated_tessellation(params, corners);
  for (const auto& w : corrugated_tessellation_windows()) {
    const CreasePattern wp = corrugated_tessellation_window(params, sheet, w.wa, w.wb);
    // Central panel angle at the window's first central vertex (node (1, 1) of the window).
    const Eigen::Vector3d c = wp.vertices[5], ui = wp.vertices[6] - c, vj = wp.vertices[9] - c;
    const double angle = std::acos(ui.normalized().dot(vj.normalized()));
    const bool alpha_like = std::fabs(angle - params.alpha) < 1e-12 || std::fabs(angle - (std::numbers::pi - params.alpha)) < 1e-12;
    EXPECT_EQ(alpha_like, w.p_shaped) << w.wa << "," << w.wb;
    const bool corner = w.wa % 2 == 0 && w.wb % 2 == 0, q_copy = w.wa == 1 && w.wb != 1;
    if (!corner && !q_copy) continue;
    const CorrugatedUnit unit = corner ? CorrugatedUnit::P : CorrugatedUnit::Q;
    std::vector<A> interior;
    for (int e : corrugated_interior_edges(unit)) interior.push_back(wp.assignments[e]);
    const CreasePattern ref = corrugated_unit(unit, params, interior);
    ASSERT_EQ(ref.num_vertices(), wp.num_vertices());
    for (int v = 0; v < ref.num_vertices(); ++v)
      EXPECT_LE(((wp.vertices[v] - wp.vertices[0]) - (ref.vertices[v] - ref.vertices[0])).norm(), 1e-12)
          << w.wa << "," << w.wb << " vertex " << v;
    for (int e = 0; e < ref.num_edges(); ++e) EXPECT_EQ(wp.assignments[e], ref.assignments[e]) << w.wa << "," << w.wb;
    if (corner) {
      const int k = w.wa / 2 + 2 * (w.wb / 2);
      EXPECT_EQ(interior, corners[k]) << "corner " << k;
    }
  }
}

TEST(CorrugatedTessellation, BadInputNamesThePlace) {
  const CorrugatedParams params;
  const auto options = p_options();
  const auto choices = consistent_choices(options);
  ASSERT_FALSE(choices.empty());
  auto place = [&](const std::array<std::vector<A>, 4>& corners, CorrugatedParams p) -> std::string {
    try {
      corrugated_tessellation(p, corners);
    } catch (const InputError& e) {
      return e.place();
    }
    return "none";
  };
  std::array<std::vector<A>, 4> corners;
  for (int k = 0; k < 4; ++k) corners[k] = options[choices[0][k]].letters;
  EXPECT_EQ(place(corners, params), "none");
  std::array<std::vector<A>, 4> short_one = corners;
  short_one[2].pop_back();
  EXPECT_EQ(place(short_one, params), "corners");
  std::array<std::vector<A>, 4> flat = corners;
  flat[1][3] = A::Flat;
  EXPECT_EQ(place(flat, params), "corners");
  CorrugatedParams bad = params;
  bad.beta = 0.1;
  EXPECT_EQ(place(corners, bad), "beta");
  // Two corners that disagree on a shared crease: the message names both windows.
  std::array<std::vector<A>, 4> clash = corners;
  for (A& a : clash[1]) a = a == A::Mountain ? A::Valley : A::Mountain;
  try {
    corrugated_tessellation(params, clash);
    ADD_FAILURE() << "a flipped neighbour was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.place(), "corners");
    EXPECT_NE(std::string(e.what()).find("window (0, 0)"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("window (2, 0)"), std::string::npos) << e.what();
  }
}

// The bundled sheets data/metamaterial/corrugated_fig3-9b.fold (the letters the search above
// reports first for Fig 3-9(b)) and corrugated_all_p1_rigid.fold (every corner window the
// bundled rigid P, odd joints 4 3 4 3): they are the generator's output, and `rigidfold check`
// (the front door) says not foldable with a loop-gain proof, and foldable with 1 DOF.
TEST(CorrugatedTessellation, BundledFig3_9bSheetThroughTheCheckCommand) {
  const CorrugatedParams params;
  struct Case {
    const char* file;
    std::array<const char*, 4> corners;
    bool rigid;
  };
  const Case cases[] = {
      {"corrugated_fig3-9b.fold", {"MVVMMVMMMVMM", "VMMVMVMMMVMM", "VMMVVMVVVMVV", "MVVMVMVVVMVV"}, false},
      {"corrugated_all_p1_rigid.fold", {"MVVMMVVVVMMM", "MVVMMVVVVMMM", "MVVMMVVVVMMM", "MVVMMVVVVMMM"}, true},
  };
  for (const Case& c : cases) {
    const std::string path = std::string(RIGIDFOLD_SOURCE_DIR) + "/data/metamaterial/" + c.file;
    std::array<std::vector<A>, 4> corners;
    for (int k = 0; k < 4; ++k) corners[k] = parse_assignment_letters(c.corners[k], "corners");
    const CreasePattern made = corrugated_tessellation(params, corners);
    const CreasePattern read = read_fold(path);
    ASSERT_EQ(read.num_edges(), made.num_edges()) << c.file;
    for (int e = 0; e < made.num_edges(); ++e) EXPECT_EQ(read.assignments[e], made.assignments[e]) << c.file << " edge " << e;
    for (int v = 0; v < made.num_vertices(); ++v)
      EXPECT_LE((read.vertices[v] - made.vertices[v]).norm(), 1e-15) << c.file << " vertex " << v;
    const auto r = test::run_command(test::cli() + " check --json " + path);
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["rigidly_foldable"].get<bool>(), c.rigid) << r.out.substr(0, 400);
    EXPECT_TRUE(j["is_proof"].get<bool>()) << r.out.substr(0, 400);
    EXPECT_EQ(j["model"], "multiplier-propagation");
    EXPECT_EQ(j["dof"].get<int>(), c.rigid ? 1 : 0);
    const FoldabilityReport direct = check_foldability(read, build_topology(read));
    EXPECT_EQ(direct.verdict, c.rigid ? FoldabilityClass::kFoldable : FoldabilityClass::kNotFoldableProof) << direct.reason;
    EXPECT_TRUE(direct.is_proof);
    EXPECT_EQ(direct.dof, c.rigid ? 1 : 0);
    const std::string text = test::run_command(test::cli() + " check " + path).out;
    EXPECT_NE(text.find(c.rigid ? ": foldable" : ": not foldable (proof)"), std::string::npos) << text;
    if (!c.rigid) {
      EXPECT_NE(text.find("loop gain"), std::string::npos) << text;
    }
  }
}

}}  // namespace
}  // namespace rigidfold::generators
