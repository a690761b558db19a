// Resource limits as tests: every command on hostile input generated here (no big
// file is committed), run under a wall-clock limit and, outside sanitizer builds, under
// `ulimit -v` (2 GiB). Each case must end with its expected exit status - 2 with a message
// naming the place, or 0 with a checked answer - inside the limit; none may crash, hang,
// or exit 1 (internal error).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sys/stat.h>
#include <fcntl.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#include <thread>

#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_limits.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/sanitized.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

namespace fs = std::filesystem;

#ifdef RIGIDFOLD_TEST_ASAN
// ASan reserves terabytes of shadow address space, so ulimit -v cannot apply: its own limit on
// the resident set (above the 2 GiB, for ASan's shadow and quarantine) ends the process with a
// report instead. A sanitizer build runs several times slower.
constexpr int kSeconds = 60;
const std::string kMemoryLimit = "export ASAN_OPTIONS=\"${ASAN_OPTIONS:-}:hard_rss_limit_mb=3072\"; ";
#else
constexpr int kSeconds = 10;
const std::string kMemoryLimit = "ulimit -v 2097152; ";  // 2 GiB, in KiB
#endif

class Scratch {
 public:
  Scratch() : dir_(fs::temp_directory_path() / ("rigidfold_hostile_" + std::to_string(::getpid()))) {
    fs::create_directories(dir_);
  }
  ~Scratch() { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path(name), std::ios::binary) << text;
    return path(name);
  }

 private:
  fs::path dir_;
};

const Scratch& scratch() {
  static const Scratch s;
  return s;
}

struct Outcome {
  int status = -1;
  double seconds = 0;
  std::string out, err;
};

// Runs `rigidfold ARGS` under the limits; status 124 is the wall-clock limit (timeout).
Outcome run_limited(const std::string& args) {
  const auto start = std::chrono::steady_clock::now();
  const std::string command = "bash -c '" + kMemoryLimit + "exec timeout -s KILL " + std::to_string(kSeconds) + " " +
                              test::cli() + " " + args + "'";
  const test::CommandResult r = test::run_command(command);
  Outcome o;
  o.status = r.status;
  o.out = r.out;
  o.err = r.err;
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return o;
}

// The unit square with one diagonal, as FOLD text without its closing brace.
const std::string kSquareOpen =
    R"({"vertices_coords": [[0,0],[1,0],[1,1],[0,1]], "edges_vertices": [[0,1],[1,2],[2,3],[3,0],[0,2]],)"
    R"( "edges_assignment": ["B","B","B","B","V"])";

std::string nested_arrays(std::size_t depth) { return std::string(depth, '[') + std::string(depth, ']'); }

std::string square_with(const std::string& key, const std::string& value) {
  return kSquareOpen + ", \"" + key + "\": " + value + "}";
}

// A string spec of n identical vertices (forward) or deflection targets (design).
std::string string_spec(std::size_t n) {
  std::string s = R"({"segment_length": 1, "vertices": [)";
  for (std::size_t i = 0; i < n; ++i) s += std::string(i ? "," : "") + R"({"alpha1_deg":40,"alpha2_deg":50})";
  return s + "]}";
}

struct HostileCase {
  std::string name;
  std::string args;     // after `rigidfold`
  int status;           // expected exit status (2, or 0)
  std::string message;  // must appear on stderr (status 2) or stdout (status 0)
};

std::vector<HostileCase> hostile_cases() {
  const Scratch& s = scratch();
  std::vector<HostileCase> c;
  const std::string deep = s.write("deep_unknown.fold", square_with("x", nested_arrays(200000)));
  const std::string deep_frames = s.write("deep_frames.fold", square_with("file_frames", "[" + nested_arrays(200000) + "]"));
  const std::string angles = s.write("angles.json", R"({"4": 30})");
  c.push_back({"deep JSON in an unknown key: info", "info " + deep, 2, deep + ": JSON nested deeper than 512"});
  c.push_back({"deep JSON in file_frames: fold --out", "fold " + deep_frames + " --angles " + angles + " --out " + s.path("o.fold"), 2,
               deep_frames + ": JSON nested deeper than 512"});
  c.push_back({"deep JSON in file_frames: trace --out", "trace " + deep_frames + " --out " + s.path("t.fold"), 2,
               deep_frames + ": JSON nested deeper than 512"});
  const std::string square = s.write("square.fold", kSquareOpen + "}");
  const std::string deep_angles = s.write("deep_angles.json", "{\"4\": " + nested_arrays(100000) + "}");
  c.push_back({"deep angles JSON", "fold " + square + " --angles " + deep_angles + " --out " + s.path("o.fold"), 2,
               deep_angles + ": JSON nested deeper than 512"});
  const std::string deep_spec = s.write("deep_spec.json", "{\"vertices\": " + nested_arrays(100000) + "}");
  c.push_back({"deep string spec", "string forward " + deep_spec + " --theta 10", 2, deep_spec + ": JSON nested deeper"});
  c.push_back({"deep string target", "string design " + deep_spec + " --out " + s.path("d.fold"), 2, deep_spec + ": JSON nested deeper"});

  // Numbers past a double.
  const std::string huge_spec = s.write("huge_spec.json", R"({"segment_length": 1e999, "vertices": [{"alpha1_deg": 40, "alpha2_deg": 50}]})");
  c.push_back({"1e999 in a string spec", "string forward " + huge_spec + " --theta 10", 2, huge_spec + ": not valid JSON"});
  const std::string huge_target =
      s.write("huge_target.json", R"({"kind": "curve", "helix": {"radius": 1e999, "rise": 1, "step_deg": 10, "count": 10}})");
  c.push_back({"1e999 in a string target", "string design " + huge_target + " --out " + s.path("d.fold"), 2, huge_target + ": not valid JSON"});
  const std::string huge_angles = s.write("huge_angles.json", R"({"4": -1e999})");
  c.push_back({"-1e999 in angles", "fold " + square + " --angles " + huge_angles + " --out " + s.path("o.fold"), 2,
               huge_angles + ": not valid JSON"});

  // Sizes past the documented limits, refused before the work.
  const std::string miura = std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled/miura_3x3_perturbed.fold";
  c.push_back({"trace --steps 1000000", "trace " + miura + " --general --steps 1000000 --out " + s.path("t.fold"), 2,
               "--steps: must be between 1 and"});
  const std::string helix =
      s.write("helix.json", R"({"kind": "curve", "helix": {"radius": 0.15, "rise": 1, "step_deg": 172, "count": 1000000}})");
  c.push_back({"string design helix of 1e6 points", "string design " + helix + " --out " + s.path("d.fold"), 2,
               helix + ": /helix/count: must be an integer in [3, "});
  c.push_back({"generate miura 2000 x 2000", "generate miura --rows 2000 --cols 2000 --out " + s.path("g.fold"), 2,
               "--rows: --rows x --cols = 4000000 cells, over the limit of " + std::to_string(kMaxGeneratedMiuraCells)});
  c.push_back({"generate square-twist tessellation 500 x 500",
               "generate square-twist-tessellation --rows 500 --cols 500 --out " + s.path("g.fold"), 2,
               "--rows: --rows x --cols = 250000 cells, over the limit of " + std::to_string(kMaxGeneratedTwistCells)});
  const std::string nlopt_helix = s.write(
      "nlopt_helix.json", R"({"kind": "curve", "method": "nlopt", "helix": {"radius": 3, "rise": 0.3, "step_deg": 20, "count": 102}})");
  c.push_back({"string design by NLopt past its vertex limit", "string design " + nlopt_helix + " --out " + s.path("d.fold"), 2,
               nlopt_helix + ": /helix/count: 100 vertices: the NLopt fit"});
  const std::string long_spec = s.write("long_spec.json", string_spec(kMaxStringVertices + 1));
  c.push_back({"string forward past the vertex limit", "string forward " + long_spec + " --theta 10", 2,
               long_spec + ": /vertices: has " + std::to_string(kMaxStringVertices + 1) + " vertices; the limit is"});

  // Inputs that are not regular files: refused at once, never read.
  const std::string fifo = s.path("pipe.fold");
  ::mkfifo(fifo.c_str(), 0600);
  c.push_back({"info on a FIFO", "info " + fifo, 2, fifo + ": is a FIFO (named pipe); input must be a regular file"});
  fs::create_directories(s.path("fifo_dir"));
  fs::copy_file(square, s.path("fifo_dir/a.fold"), fs::copy_options::overwrite_existing);
  ::mkfifo(s.path("fifo_dir/b.fold").c_str(), 0600);
  c.push_back({"report on a directory holding a FIFO named *.fold", "report " + s.path("fifo_dir") + " --out " + s.path("report_out"), 2,
               "b.fold: is a FIFO"});
  c.push_back({"info /dev/zero", "info /dev/zero", 2, "/dev/zero: is a character device"});
  c.push_back({"string design /dev/urandom", "string design /dev/urandom --out " + s.path("d.fold"), 2, "/dev/urandom: is a character device"});
  c.push_back({"fold --angles /dev/zero", "fold " + square + " --angles /dev/zero --out " + s.path("o.fold"), 2, "/dev/zero: is a character device"});
  c.push_back({"info on a directory", "info " + s.path("fifo_dir"), 2, "is a directory"});
  const std::string sparse = s.path("sparse.fold");
  fs::resize_file(s.write("sparse.fold", ""), (kMaxInputFileBytes) + 1);  // a hole: no disk used
  c.push_back({"file past the size limit", "info " + sparse, 2, sparse + ": file is " + std::to_string(kMaxInputFileBytes + 1) + " bytes"});
  c.push_back({"output onto /dev/null (written in place, never replaced)", "fold " + square + " --angles " + angles + " --out /dev/null", 0,
               "-> /dev/null"});

  // Values of the wrong type in keys a command reads.
  fs::create_directories(s.path("title_dir"));
  const std::string titled = s.write("title_dir/t.fold", square_with("file_title", "5"));
  c.push_back({"report: file_title not a string", "report " + s.path("title_dir") + " --out " + s.path("title_out"), 2,
               titled + ": file_title: must be a string, found number"});
  fs::create_directories(s.path("frame_title_dir"));
  const std::string frame_titled = s.write("frame_title_dir/t.fold", square_with("frame_title", "[1]"));
  c.push_back({"report: frame_title not a string", "report " + s.path("frame_title_dir") + " --out " + s.path("title_out"), 2,
               frame_titled + ": frame_title: must be a string, found array"});
  return c;
}

TEST(HostileInput, EveryCaseEndsWithItsStatusInsideTheLimits) {
  for (const HostileCase& h : hostile_cases()) {
    const Outcome o = run_limited(h.args);
    EXPECT_NE(o.status, 1) << h.name << ": internal error: " << o.err;
    EXPECT_NE(o.status, 124) << h.name << ": wall-clock limit";
    EXPECT_EQ(o.status, h.status) << h.name << ": " << o.err;
    const std::string& text = h.status == 0 ? o.out : o.err;
    EXPECT_NE(text.find(h.message), std::string::npos) << h.name << ": " << text;
    EXPECT_LT(o.seconds, kSeconds) << h.name;
  }
}

// Depth 512 (the limit, top-level object included) is legal and kept through a round trip;
// one more level is refused.
TEST(HostileInput, JsonDepthLimitIsExact) {
  const Scratch& s = scratch();
  const std::string at_limit = s.write("depth512.fold", square_with("x", nested_arrays(kMaxJsonDepth - 1)));
  const std::string past = s.write("depth513.fold", square_with("x", nested_arrays(kMaxJsonDepth)));
  const std::string angles = s.write("angles512.json", R"({"4": 30})");
  const std::string out = s.path("depth512_out.fold");
  const Outcome ok = run_limited("fold " + at_limit + " --angles " + angles + " --out " + out);
  ASSERT_EQ(ok.status, 0) << ok.err;
  const CreasePattern back = read_fold(out);
  ASSERT_TRUE(back.extra.contains("x"));
  const nlohmann::ordered_json* v = &back.extra["x"];
  int depth = 0;
  while (v->is_array() && !v->empty()) {
    v = &v->front();
    ++depth;
  }
  EXPECT_EQ(depth + 1, kMaxJsonDepth - 1);  // the innermost array is empty
  const Outcome refused = run_limited("info " + past);
  EXPECT_EQ(refused.status, 2) << refused.err;
  EXPECT_NE(refused.err.find(past + ": JSON nested deeper than 512"), std::string::npos) << refused.err;
}

// The --steps limit scales with the pattern: a pattern of E edges, V vertices, F faces may
// take kMaxTraceStepValues / (E + 3V + 16F) steps; the message says how many.
TEST(HostileInput, TraceStepsLimitScalesWithThePattern) {
  const std::string miura = std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled/miura_12x12_folded.fold";
  const CreasePattern p = read_fold(miura);
  const std::int64_t per_step = p.num_edges() + 3 * std::int64_t{p.num_vertices()} + 16 * std::int64_t{p.num_faces()};
  const std::int64_t most = kMaxTraceStepValues / per_step;
  ASSERT_LT(most, kMaxTraceSteps);
  const Outcome o = run_limited("trace " + miura + " --steps " + std::to_string(most + 1) + " --out " + scratch().path("never.fold"));
  EXPECT_EQ(o.status, 2) << o.err;
  EXPECT_NE(o.err.find("--steps: " + std::to_string(most + 1) + " steps"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("use at most " + std::to_string(most) + " steps"), std::string::npos) << o.err;
  EXPECT_FALSE(fs::exists(scratch().path("never.fold")));
}

// Patterns with no interior vertex, or in several components, or with one vertex of degree
// 20: the general solver answers (no crash) with the DOF counted by hand. Creases that meet
// no interior vertex fold independently (DOF = their number); a single generic vertex of
// degree n has n - 3 DOF (one SO(3) closure).
TEST(HostileInput, GeneralSolverOnStripsComponentsAndHighDegree) {
  const Scratch& s = scratch();
  const std::string strip = s.write("strip.fold",
                                    R"({"vertices_coords": [[0,0],[1,0],[2,0],[3,0],[3,1],[2,1],[1,1],[0,1]],)"
                                    R"( "edges_vertices": [[0,1],[1,2],[2,3],[3,4],[4,5],[5,6],[6,7],[7,0],[1,6],[2,5]],)"
                                    R"( "edges_assignment": ["B","B","B","B","B","B","B","B","M","V"]})");
  const std::string two = s.write("two_squares.fold",
                                  R"({"vertices_coords": [[0,0],[1,0],[1,1],[0,1],[3,0],[4,0],[4,1],[3,1]],)"
                                  R"( "edges_vertices": [[0,1],[1,2],[2,3],[3,0],[0,2],[4,5],[5,6],[6,7],[7,4],[4,6]],)"
                                  R"( "edges_assignment": ["B","B","B","B","V","B","B","B","B","M"]})");
  std::string star = R"({"vertices_coords": [[0,0])";
  std::string edges, letters;
  const int n = 20;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * 3.14159265358979323846 * k / n;
    star += ",[" + std::to_string(std::cos(a)) + "," + std::to_string(std::sin(a)) + "]";
    edges += std::string(k ? "," : "") + "[0," + std::to_string(k + 1) + "],[" + std::to_string(k + 1) + "," + std::to_string((k + 1) % n + 1) + "]";
    letters += std::string(k ? "," : "") + (k % 2 ? "\"M\",\"B\"" : "\"V\",\"B\"");
  }
  const std::string degree20 = s.write("degree20.fold", star + "], \"edges_vertices\": [" + edges + "], \"edges_assignment\": [" + letters + "]}");
  struct Expect {
    std::string file, flags;
    int dof;
  };
  for (const Expect& e : {Expect{strip, "", 2}, Expect{strip, " --ignore-assignment", 2}, Expect{two, "", 2},
                          Expect{two, " --ignore-assignment", 2}, Expect{degree20, " --ignore-assignment", n - 3}}) {
    const Outcome o = run_limited("check --general --json " + e.file + e.flags);
    ASSERT_EQ(o.status, 0) << e.file << e.flags << ": " << o.err;
    const auto j = nlohmann::json::parse(o.out);
    EXPECT_EQ(j["verdict_class"], "foldable") << e.file << e.flags;
    EXPECT_EQ(j["dof"], e.dof) << e.file << e.flags;
  }
  for (const std::string& f : {strip, two, degree20}) {
    const Outcome o = run_limited("trace --general --branch all --json " + f);
    EXPECT_EQ(o.status, 0) << f << ": " << o.err;
  }
}

// True once a temporary of `name` (".<name>.tmp.XXXXXX", kernel/pattern/output_set.hpp)
// exists in dir.
bool temporary_exists(const fs::path& dir, const std::string& name) {
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().rfind("." + name + ".tmp.", 0) == 0) return true;
  return false;
}

// SIGINT/SIGTERM while `trace --out` computes, and while it writes (the signal sent as soon
// as the temporary appears): the old file stays, or the new one is complete (the run
// finished first); never a partial file, never a temporary left over.
// File names are bytes; JSON strings must be UTF-8. A path that is not UTF-8 is a legal name:
// the command does its work, writes the file under its real name, and its JSON names it with
// U+FFFD (before the fix every --json run with such a path ended in "internal error" after
// its files were written: cli_flags_fuzz found it on `sorce --out`).
TEST(HostileInput, NonUtf8PathsAreLegalAndTheirJsonStaysValid) {
  const std::string odd = "odd\xb2";
  const std::string pattern = scratch().path(odd + ".fold");
  fs::copy_file(std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled/miura_3x3_perturbed.fold", pattern,
                fs::copy_options::overwrite_existing);
  struct Case {
    std::string args, written;
  };
  const std::vector<Case> cases{
      {"check --json " + pattern, ""},
      {"info --json " + pattern, ""},
      {"export --json " + pattern + " --svg " + scratch().path(odd + ".svg"), scratch().path(odd + ".svg")},
      {"sorce --json " + std::string(RIGIDFOLD_SOURCE_DIR) + "/data/sorce/vertex_a.fold --thickness 0.1 --out " +
           scratch().path(odd + "_sorce"),
       scratch().path(odd + "_sorce/sorce.json")},
      {"metamaterial --json --unit element1 --plot " + scratch().path(odd + "_plot"), scratch().path(odd + "_plot")},
  };
  for (const Case& c : cases) {
    const Outcome o = run_limited(c.args);
    ASSERT_EQ(o.status, 0) << c.args << "\n" << o.err;
    const nlohmann::json j = nlohmann::json::parse(o.out);  // throws (fails the test) if not valid JSON
    EXPECT_NE(j.dump().find("odd\xef\xbf\xbd"), std::string::npos) << c.args << ": the path is named with U+FFFD";
    if (!c.written.empty()) {
      EXPECT_TRUE(fs::exists(c.written)) << c.args;
    }
  }
}

TEST(HostileInput, InterruptedTraceLeavesTheOldFileOrTheWholeNewOne) {
  const std::string miura = std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled/miura_12x12_folded.fold";
  const fs::path dir = scratch().path("interrupt");
  fs::create_directories(dir);
  const std::string out = (dir / "t.fold").string();
  const std::string cli = test::cli();
  const int steps = 600;
  // One run, signalled during the trace or as soon as the temporary appears; true when the
  // signal was sent while the temporary existed (inside the write window).
  const auto run_once = [&](int sig, bool during_write) {
    const std::string what = "signal " + std::to_string(sig) + (during_write ? " during the write" : " during the trace");
    std::ofstream(out) << "old";
    const pid_t pid = ::fork();
    if (pid < 0) {
      ADD_FAILURE() << "fork failed";
      return false;
    }
    if (pid == 0) {
      const int null = ::open("/dev/null", O_WRONLY);
      ::dup2(null, 1);
      ::dup2(null, 2);
      ::execl(cli.c_str(), cli.c_str(), "trace", miura.c_str(), "--steps", std::to_string(steps).c_str(), "--out", out.c_str(),
              nullptr);
      ::_exit(127);
    }
    int status = 0;
    bool hit = false;
    bool reaped = false;  // the poll below collected the child already (it finished before the write was seen)
    if (during_write) {
      // Generous: the trace before the write may take long on a loaded machine.
      const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(6 * kSeconds);
      while (!temporary_exists(dir, "t.fold") && std::chrono::steady_clock::now() < give_up) {
        if (::waitpid(pid, &status, WNOHANG) == pid) {
          reaped = true;
          break;
        }
        std::this_thread::sleep_for(std::chrono::microseconds(200));
      }
      hit = temporary_exists(dir, "t.fold");
    } else {
      std::this_thread::sleep_for(std::chrono::milliseconds(30));
    }
    if (!reaped) {
      ::kill(pid, sig);  // harmless if it already exited (not yet reaped)
      EXPECT_EQ(::waitpid(pid, &status, 0), pid) << what;
    }  // a reaped pid is not signalled: the number may belong to another process by now
    const bool finished = WIFEXITED(status) && WEXITSTATUS(status) == 0;
    EXPECT_TRUE(finished || (WIFSIGNALED(status) && WTERMSIG(status) == sig)) << what;
    const std::string text = read_text_file(out);
    if (text != "old") {
      const CreasePattern p = read_fold(out);  // complete: it parses, with every step's frame
      EXPECT_EQ(p.extra["file_frames"].size(), static_cast<std::size_t>(steps)) << what;
    }
    EXPECT_FALSE(temporary_exists(dir, "t.fold")) << what << ": temporary left behind";
    return hit;
  };
  for (int sig : {SIGINT, SIGTERM}) {
    run_once(sig, false);
    // The write window is tens of ms: a run whose poll missed it (a loaded machine) is
    // repeated, so that the check below does not rest on one race.
    bool hit = false;
    for (int attempt = 0; attempt < 8 && !hit; ++attempt) hit = run_once(sig, true);
    EXPECT_TRUE(hit) << "signal " << sig << ": the temporary was never seen before the signal in 8 runs";
  }
}

}}  // namespace
}  // namespace rigidfold
