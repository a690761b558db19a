// Nothing of the user's is lost. Every command that writes
// files, run on inputs generated here, for each class of ordinary mistake: an output that is
// an input, two outputs on one path, a failure after an earlier output, special files and
// symlinks at an output path, ambiguous JSON, invalid file_frames, no answer with --out.
// After every run: the inputs are byte-identical, no pre-existing output changed unless the
// command succeeded, no special file replaced, no temporary left. Also: every FOLD the CLI
// writes reads back through read_fold and has the FOLD 1.2 types; two concurrent writers
// leave one complete file.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include "kernel/pattern/fold_io.hpp"
#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

class Scratch {
 public:
  Scratch()
      : dir_(fs::temp_directory_path() / ("rigidfold_outputs_" + std::to_string(::getpid()) + "_" + std::to_string(counter_++))) {
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  ~Scratch() { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string write(const std::string& name, const std::string& text) const {
    fs::create_directories(fs::path(path(name)).parent_path());
    std::ofstream(path(name), std::ios::binary) << text;
    return path(name);
  }
  const fs::path& dir() const { return dir_; }

 private:
  static inline int counter_ = 0;
  fs::path dir_;
};

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Every entry under a directory, not following links: its type, and its bytes (regular
// files) or target (links). Two equal snapshots mean nothing was created, removed, replaced
// or changed.
struct Entry {
  mode_t type = 0;
  std::string content;
  bool operator==(const Entry& o) const { return type == o.type && content == o.content; }
};
using Snapshot = std::map<std::string, Entry>;

Snapshot snapshot(const fs::path& dir) {
  Snapshot s;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    struct stat st {};
    ::lstat(e.path().c_str(), &st);
    Entry x;
    x.type = st.st_mode & S_IFMT;
    if (S_ISREG(st.st_mode)) x.content = slurp(e.path().string());
    if (S_ISLNK(st.st_mode)) x.content = fs::read_symlink(e.path()).string();
    s[fs::relative(e.path(), dir).string()] = x;
  }
  return s;
}

std::string describe(const Snapshot& before, const Snapshot& after) {
  std::string d;
  for (const auto& [k, v] : after)
    if (!before.count(k)) d += " new:" + k;
    else if (!(before.at(k) == v)) d += " changed:" + k;
  for (const auto& [k, v] : before)
    if (!after.count(k)) d += " removed:" + k;
  return d;
}

std::vector<std::string> temporaries(const fs::path& dir) {
  std::vector<std::string> t;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().filename().string().find(".tmp.") != std::string::npos) t.push_back(e.path().string());
  return t;
}

test::CommandResult run(const std::string& args) { return test::run_command(test::cli() + " " + args); }

// The unit square with one valley diagonal.
const std::string kSquare =
    R"({"file_spec": 1.2, "vertices_coords": [[0,0],[1,0],[1,1],[0,1]], "edges_vertices": [[0,1],[1,2],[2,3],[3,0],[0,2]],)"
    R"( "edges_assignment": ["B","B","B","B","V"]})";

std::string square_with(const std::string& key_value) { return kSquare.substr(0, kSquare.size() - 1) + ", " + key_value + "}"; }

// A failed run: exit 2 naming every string in `names`, and the scratch directory exactly as
// before (inputs and earlier outputs unchanged, nothing new, no temporary).
void expect_refused(const Scratch& s, const std::string& args, const std::vector<std::string>& names, int status = 2) {
  const Snapshot before = snapshot(s.dir());
  const test::CommandResult r = run(args);
  EXPECT_EQ(r.status, status) << args << "\n" << r.err;
  for (const std::string& n : names) EXPECT_NE(r.err.find(n), std::string::npos) << args << ": stderr lacks '" << n << "': " << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
  const Snapshot after = snapshot(s.dir());
  EXPECT_TRUE(before == after) << args << ":" << describe(before, after);
}

struct Fixture {
  Scratch s;
  std::string square, angles, spec, target;
  Fixture() {
    square = s.write("sq.fold", kSquare);
    angles = s.write("a.json", R"({"4": 30})");
    spec = s.write("spec.json", R"({"vertices": [{"alpha1_deg": 40, "alpha2_deg": 50}, {"alpha1_deg": 45, "alpha2_deg": 55}], "segment_length": 1})");
    target = s.write("target.json", R"({"kind": "deflections", "theta_deg": 30, "segment_length": 1,)"
                                    R"( "vertices": [{"phi_deg": 35, "psi_deg": 5}, {"phi_deg": -30, "psi_deg": -8}]})");
  }
};

// ---- an output path that is an input -----------------------------------------------------

TEST(OutputSafety, AnOutputThatIsAnInputIsRefusedBeforeAnyWork) {
  Fixture f;
  const Scratch& s = f.s;
  fs::create_directories(s.path("sub"));
  fs::create_symlink(f.square, s.path("link.fold"));
  const std::string fold = "fold " + f.square + " --angles " + f.angles;
  expect_refused(s, fold + " --out " + s.path("f.fold") + " --obj " + f.square, {"--obj", "PATTERN", "same file as the input"});
  expect_refused(s, fold + " --out " + f.angles, {"--out", "--angles"});
  expect_refused(s, fold + " --out " + s.path("link.fold"), {"--out", "PATTERN"});             // through a symlink
  expect_refused(s, fold + " --out " + s.path("sub/../sq.fold"), {"--out", "PATTERN"});        // through ..
  expect_refused(s, "trace " + f.square + " --csv " + f.square, {"--csv", "PATTERN"});
  expect_refused(s, "trace " + f.square + " --out " + s.path("link.fold"), {"--out", "PATTERN"});
  expect_refused(s, "string forward " + f.spec + " --theta 20 --out " + f.spec, {"--out", "SPEC"});
  expect_refused(s, "string design " + f.target + " --out " + s.path("d.fold") + " --svg " + f.target, {"--svg", "TARGET"});
  // network reads a JSON and writes a FOLD: the same file, a symlink, a hard link or a path through ..
  const std::string net = s.write("net.json", slurp(std::string(RIGIDFOLD_SOURCE_DIR) + "/data/network/a4_R4R9R12.json"));
  fs::create_symlink(net, s.path("net_link.json"));
  fs::create_hard_link(net, s.path("net_hard.json"));
  for (const std::string& out : {net, s.path("net_link.json"), s.path("net_hard.json"), s.path("sub/../net.json")})
    expect_refused(s, "network " + net + " --out " + out, {"--out", "NETWORK"});
}

// report DIR --out DIR would overwrite the user's own a.folded.fold and read its own outputs
// on the next run; an output linked to a pattern would overwrite it.
TEST(OutputSafety, ReportOutputNeverAnInput) {
  Scratch s;
  const std::string folded = square_with(R"("edges_foldAngle": [0,0,0,0,30])");
  s.write("in/a.fold", folded);
  s.write("in/a.folded.fold", folded);  // the user's own file, an input here
  expect_refused(s, "report " + s.path("in") + " --out " + s.path("in"), {"--out", "DIR", "same directory as the input"});
  fs::create_directories(s.path("out"));
  fs::create_symlink(s.path("in/a.fold"), s.path("out/a.folded.fold"));
  expect_refused(s, "report " + s.path("in") + " --out " + s.path("out"), {"--out", "DIR", "a.fold"});
  // A good run writes the report and the folded state beside it, and touches no input.
  fs::remove(s.path("out/a.folded.fold"));
  const Snapshot inputs = snapshot(s.path("in"));
  const test::CommandResult r = run("report " + s.path("in") + " --out " + s.path("out"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(inputs == snapshot(s.path("in")));
  EXPECT_EQ(read_fold(s.path("out/a.folded.fold")).extra["file_frames"].size(), 1u);
  EXPECT_TRUE(fs::exists(s.path("out/report.json")));
  EXPECT_TRUE(temporaries(s.dir()).empty());
}

// ---- two outputs on one path ---------------------------------------------------------------

TEST(OutputSafety, TwoOutputsOnOnePathAreRefused) {
  Fixture f;
  const Scratch& s = f.s;
  s.write("old.fold", "old");
  fs::create_hard_link(s.path("old.fold"), s.path("hard.fold"));
  const std::string fold = "fold " + f.square + " --angles " + f.angles;
  expect_refused(s, fold + " --out " + s.path("same") + " --obj " + s.path("same"), {"--obj", "--out", "two outputs on one path"});
  expect_refused(s, fold + " --out " + s.path("old.fold") + " --obj " + s.path("hard.fold"), {"--obj", "--out"});  // one inode
  expect_refused(s, fold + " --out - --obj -", {"--obj", "--out"});
  expect_refused(s, "trace " + f.square + " --out " + s.path("t") + " --csv " + s.path("./t"), {"--csv", "--out"});
  expect_refused(s, "string forward " + f.spec + " --theta 20 --out " + s.path("x") + " --svg " + s.path("x"), {"--svg", "--out"});
}

// ---- a failure leaves every earlier output as it was --------------------------------------

TEST(OutputSafety, AFailedCommandReplacesNothing) {
  Fixture f;
  const Scratch& s = f.s;
  s.write("f.fold", "old");
  s.write("f.obj", "old obj");
  const std::string fold = "fold " + f.square + " --angles " + f.angles + " --out " + s.path("f.fold");
  // The second output cannot be written: a missing directory (found before the work) ...
  expect_refused(s, fold + " --obj " + s.path("missing/x.obj"), {"--obj", "does not exist"});
  // ... a device that fails at the write (/dev/full: ENOSPC), after f.fold was staged ...
  if (fs::exists("/dev/full")) expect_refused(s, fold + " --obj /dev/full", {"--obj", "/dev/full"});
  // ... or bad input found during the work.
  const std::string bad_angles = s.write("bad.json", R"({"4": 500})");
  const std::string bad = "fold " + f.square + " --angles " + bad_angles + " --out " + s.path("f.fold") + " --obj " + s.path("f.obj");
  expect_refused(s, bad, {bad_angles});
  // Success replaces both.
  ASSERT_EQ(run(fold + " --obj " + s.path("f.obj")).status, 0);
  EXPECT_EQ(read_fold(s.path("f.fold")).num_edges(), 5);
  EXPECT_EQ(slurp(s.path("f.obj")).rfind("# rigidfold", 0), 0u);
  EXPECT_TRUE(temporaries(s.dir()).empty());
}

// ---- special files at an output path --------------------------------------------------------

mode_t lstat_type(const std::string& path) {
  struct stat st {};
  return ::lstat(path.c_str(), &st) == 0 ? (st.st_mode & S_IFMT) : 0;
}

TEST(OutputSafety, DevicesAndFifosAreWrittenInPlaceAndSymlinksFollowed) {
  Fixture f;
  const Scratch& s = f.s;
  const std::string fold = "fold " + f.square + " --angles " + f.angles;
  // /dev/null and a private copy of it (mknod needs CAP_MKNOD: root in the CI container).
  {
    const test::CommandResult r = run(fold + " --out /dev/null --obj /dev/null");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(lstat_type("/dev/null"), S_IFCHR);
  }
  const std::string node = s.path("null_node");
  if (::mknod(node.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0) {
    const test::CommandResult r = run(fold + " --out " + node);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(lstat_type(node), S_IFCHR);
    const test::CommandResult t = run("trace " + f.square + " --out " + node + " --csv " + node + " --branch all --general");
    EXPECT_EQ(t.status, 0) << t.err;
    EXPECT_EQ(lstat_type(node), S_IFCHR);
  }
  // A FIFO with a reader gets the whole FOLD and stays a FIFO.
  const std::string fifo = s.path("pipe");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = slurp(fifo); });
  const test::CommandResult r = run(fold + " --out " + fifo);
  const int unblock = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);  // ends the reader if nothing came
  if (unblock >= 0) ::close(unblock);
  reader.join();
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(parse_fold(received, "from the FIFO").num_edges(), 5);
  EXPECT_EQ(lstat_type(fifo), S_IFIFO);
  // A FIFO nobody reads: exit 2 after a bounded wait, the earlier output untouched.
  s.write("keep.fold", "old");
  expect_refused(s, fold + " --out " + s.path("keep.fold") + " --obj " + fifo, {"--obj", "FIFO has no reader"});
  // A symlink stays a link; its target gets the new file. A dangling one creates its target.
  s.write("target.fold", "old");
  fs::create_symlink(s.path("target.fold"), s.path("link.fold"));
  fs::create_symlink(s.path("created.fold"), s.path("dangling.fold"));
  ASSERT_EQ(run(fold + " --out " + s.path("link.fold") + " --obj " + s.path("dangling.fold")).status, 0);
  EXPECT_EQ(lstat_type(s.path("link.fold")), S_IFLNK);
  EXPECT_EQ(fs::read_symlink(s.path("link.fold")), s.path("target.fold"));
  EXPECT_EQ(read_fold(s.path("target.fold")).num_edges(), 5);
  EXPECT_EQ(lstat_type(s.path("dangling.fold")), S_IFLNK);
  EXPECT_EQ(slurp(s.path("created.fold")).rfind("# rigidfold", 0), 0u);
  // A directory is refused.
  fs::create_directories(s.path("dir.fold"));
  expect_refused(s, fold + " --out " + s.path("dir.fold"), {"--out", "is a directory"});
  EXPECT_TRUE(temporaries(s.dir()).empty());
}

TEST(OutputSafety, DashIsStandardOutput) {
  Fixture f;
  const test::CommandResult r = run("fold " + f.square + " --angles " + f.angles + " --out - --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const CreasePattern p = parse_fold(r.out, "stdout");  // the FOLD alone: the summary went to stderr
  EXPECT_EQ(p.extra["file_frames"].size(), 1u);
  EXPECT_NE(r.err.find("closure_mismatch"), std::string::npos) << r.err;
  const test::CommandResult g = run("generate miura --rows 2 --cols 2 --out -");
  ASSERT_EQ(g.status, 0) << g.err;
  EXPECT_EQ(parse_fold(g.out, "stdout").num_vertices(), 9);
}

// A legal file name of NAME_MAX bytes: its temporary is cut to fit, and the write succeeds.
TEST(OutputSafety, LongestLegalNameIsWritten) {
  Fixture f;
  const long name_max = ::pathconf(f.s.dir().c_str(), _PC_NAME_MAX);
  ASSERT_GT(name_max, 20);
  const std::string out = f.s.path(std::string(static_cast<std::size_t>(name_max) - 5, 'n') + ".fold");
  const test::CommandResult r = run("fold " + f.square + " --angles " + f.angles + " --out " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read_fold(out).num_edges(), 5);
  EXPECT_TRUE(temporaries(f.s.dir()).empty());
}

// ---- ambiguous JSON and invalid structure ---------------------------------------------------

TEST(OutputSafety, DuplicateKeysAreRefusedWithTheirPath) {
  Fixture f;
  const Scratch& s = f.s;
  const std::string twice = s.write("twice.fold", square_with(R"("edges_assignment": ["B","B","B","B","M"])"));
  expect_refused(s, "info " + twice, {twice + ": edges_assignment: duplicate key \"edges_assignment\""});
  const std::string nested = s.write(
      "nested.fold", square_with(R"("file_frames": [{"frame_title": "a"}, {"frame_title": "b", "frame_title": "c"}])"));
  expect_refused(s, "trace " + nested + " --out " + s.path("t.fold"), {nested + ": file_frames[1].frame_title: duplicate key"});
  const std::string angles = s.write("twice.json", R"({"4": 30, "4": -30})");
  expect_refused(s, "fold " + f.square + " --angles " + angles + " --out " + s.path("o.fold"), {angles + ": 4: duplicate key"});
  const std::string spec = s.write("twice_spec.json", R"({"segment_length": 1, "segment_length": 2, "vertices": [{"alpha1_deg": 40, "alpha2_deg": 50}]})");
  expect_refused(s, "string forward " + spec + " --theta 10 --out " + s.path("o.fold"), {spec + ": segment_length: duplicate key"});
  const std::string target = s.write("twice_target.json", R"({"kind": "deflections", "vertices": [{"phi_deg": 1, "phi_deg": 2}]})");
  expect_refused(s, "string design " + target + " --out " + s.path("o.fold"), {target + ": vertices[0].phi_deg: duplicate key"});
}

TEST(OutputSafety, InvalidFileFramesAreRefusedBeforeAnythingIsCopied) {
  Fixture f;
  const Scratch& s = f.s;
  struct Case {
    std::string frames, place, what;
  };
  const std::vector<Case> cases{
      {R"([{"frame_parent": 1}])", "file_frames[0].frame_parent", "its own parent"},
      {R"([{"frame_parent": 2}, {"frame_parent": 1}])", "file_frames[0].frame_parent", "cycle"},
      {R"([{"frame_parent": 0}, {"frame_parent": 3}, {"frame_parent": 2}])", "file_frames[1].frame_parent", "cycle"},
      {R"([{"frame_parent": "x"}])", "file_frames[0].frame_parent", "integer"},
      {R"([{"frame_parent": 2}])", "file_frames[0].frame_parent", "out of range"},
      {R"([{"frame_parent": -1}])", "file_frames[0].frame_parent", "negative"},
      {R"([{"frame_parent": 0.5}])", "file_frames[0].frame_parent", "integer"},
      {R"([{}, 7])", "file_frames[1]", "must be a frame object"},
      {R"({"a": 1})", "file_frames", "must be an array"},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::string file = s.write("frames" + std::to_string(i) + ".fold", square_with("\"file_frames\": " + cases[i].frames));
    expect_refused(s, "trace " + file + " --out " + s.path("t.fold"), {file + ": " + cases[i].place, cases[i].what});
    expect_refused(s, "fold " + file + " --angles " + f.angles + " --out " + s.path("o.fold"), {file + ": " + cases[i].place});
  }
  // A valid tree of frames is kept, and trace adds its frames after them.
  ASSERT_EQ(run("generate miura --rows 2 --cols 2 --out " + s.path("m.fold")).status, 0);
  Json m = Json::parse(slurp(s.path("m.fold")));
  m["file_frames"] = Json::parse(R"([{"frame_parent": 0}, {"frame_parent": 1}])");
  const std::string good = s.write("good.fold", m.dump());
  const test::CommandResult r = run("trace " + good + " --steps 3 --out " + s.path("t.fold"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read_fold(s.path("t.fold")).extra["file_frames"].size(), 5u);
}

// ---- exit 0 only with the asked-for file ------------------------------------------------------

// A single vertex of degree 64 (DOF 61): the general solver traces nothing. With --out that
// is "no answer" (exit 3) and no file; without an output it is a report (exit 0).
TEST(OutputSafety, TraceThatTracesNothingWithOutExits3) {
  Scratch s;
  const int n = 64;
  std::string coords = "[0,0]", edges, letters;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * 3.14159265358979323846 * (k + 0.1 * (k % 3)) / n;
    coords += ",[" + std::to_string(std::cos(a)) + "," + std::to_string(std::sin(a)) + "]";
    edges += std::string(k ? "," : "") + "[0," + std::to_string(k + 1) + "],[" + std::to_string(k + 1) + "," + std::to_string((k + 1) % n + 1) + "]";
    letters += std::string(k ? "," : "") + "\"U\",\"B\"";
  }
  const std::string star = s.write("star.fold", "{\"vertices_coords\": [" + coords + "], \"edges_vertices\": [" + edges +
                                                    "], \"edges_assignment\": [" + letters + "]}");
  s.write("t.fold", "old");
  expect_refused(s, "trace " + star + " --out " + s.path("t.fold") + " --csv " + s.path("t.csv"),
                 {"no answer within tolerance", "nothing traced", "residual"}, 3);
  const test::CommandResult r = run("trace " + star + " --json");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["traced"], false);
}

// ---- every FOLD written reads back, with the FOLD 1.2 types ----------------------------------

void expect_fold_types(const Json& doc, const std::string& what, bool frame);

void expect_string_array(const Json& v, const std::string& what) {
  ASSERT_TRUE(v.is_array()) << what;
  for (const auto& x : v) EXPECT_TRUE(x.is_string()) << what;
}

void expect_index_arrays(const Json& v, std::size_t count, std::size_t fixed, const std::string& what) {
  ASSERT_TRUE(v.is_array()) << what;
  for (const auto& row : v) {
    ASSERT_TRUE(row.is_array()) << what;
    if (fixed) {
      EXPECT_EQ(row.size(), fixed) << what;
    }
    for (const auto& i : row) EXPECT_TRUE(i.is_number_unsigned() && i.get<std::size_t>() < count) << what << ": " << i;
  }
}

// FOLD 1.2 (https://github.com/edemaine/fold/blob/main/doc/spec.md): the type of every key
// the spec defines; any other key carries a "namespace:" prefix.
void expect_fold_types(const Json& doc, const std::string& what, bool frame) {
  ASSERT_TRUE(doc.is_object()) << what;
  static const std::set<std::string> file_keys{"file_spec", "file_creator", "file_author", "file_title", "file_description",
                                               "file_classes", "file_frames"};
  static const std::set<std::string> frame_keys{"frame_author", "frame_title", "frame_description", "frame_classes",
                                                "frame_attributes", "frame_unit", "frame_parent", "frame_inherit",
                                                "vertices_coords", "edges_vertices", "edges_assignment", "edges_foldAngle",
                                                "edges_length", "faces_vertices", "faces_edges"};
  std::size_t nv = 0;
  if (doc.contains("vertices_coords")) {
    const Json& vc = doc["vertices_coords"];
    ASSERT_TRUE(vc.is_array()) << what;
    nv = vc.size();
    for (const auto& c : vc) {
      ASSERT_TRUE(c.is_array() && (c.size() == 2 || c.size() == 3)) << what;
      for (const auto& x : c) EXPECT_TRUE(x.is_number() && std::isfinite(x.get<double>())) << what;
    }
  }
  for (auto it = doc.begin(); it != doc.end(); ++it) {
    const std::string& k = it.key();
    const Json& v = it.value();
    const std::string at = what + ": " + k;
    if (!frame && file_keys.count(k)) {
      if (k == "file_spec") EXPECT_TRUE(v.is_number()) << at;
      else if (k == "file_classes") expect_string_array(v, at);
      else if (k == "file_frames") {
        ASSERT_TRUE(v.is_array()) << at;
        for (std::size_t i = 0; i < v.size(); ++i) {
          expect_fold_types(v[i], at + "[" + std::to_string(i) + "]", true);
          if (v[i].contains("frame_parent")) {
            const Json& parent = v[i]["frame_parent"];
            EXPECT_TRUE(parent.is_number_unsigned() && parent.get<std::size_t>() <= v.size() && parent.get<std::size_t>() != i + 1) << at;
          }
        }
      } else EXPECT_TRUE(v.is_string()) << at;
      continue;
    }
    if (!frame_keys.count(k)) {
      EXPECT_NE(k.find(':'), std::string::npos) << at << ": not a FOLD key and no namespace prefix";
      continue;
    }
    if (k == "frame_classes" || k == "frame_attributes") expect_string_array(v, at);
    else if (k == "frame_parent") EXPECT_TRUE(v.is_number_unsigned()) << at;
    else if (k == "frame_inherit") EXPECT_TRUE(v.is_boolean()) << at;
    else if (k == "edges_vertices") expect_index_arrays(v, nv ? nv : SIZE_MAX, 2, at);
    else if (k == "faces_vertices") expect_index_arrays(v, nv ? nv : SIZE_MAX, 0, at);
    else if (k == "edges_assignment") {
      ASSERT_TRUE(v.is_array()) << at;
      for (const auto& a : v) EXPECT_TRUE(a.is_string() && a.get<std::string>().size() == 1 &&
                                          std::string("BMVFUCJ").find(a.get<std::string>()) != std::string::npos)
                                  << at << ": " << a;
    } else if (k == "edges_foldAngle" || k == "edges_length") {
      ASSERT_TRUE(v.is_array()) << at;
      for (const auto& a : v) {
        ASSERT_TRUE(a.is_number() && std::isfinite(a.get<double>())) << at << ": " << a;
        if (k == "edges_foldAngle") {
          EXPECT_LE(std::fabs(a.get<double>()), 180.0) << at;
        }
      }
    } else if (k != "vertices_coords") {
      EXPECT_TRUE(v.is_string()) << at;
    }
  }
  if (doc.contains("edges_vertices"))
    for (const char* per_edge : {"edges_assignment", "edges_foldAngle"})
      if (doc.contains(per_edge)) {
        EXPECT_EQ(doc[per_edge].size(), doc["edges_vertices"].size()) << what << ": " << per_edge;
      }
}

void expect_fold_reads_back(const std::string& path) {
  SCOPED_TRACE(path);
  const CreasePattern p = read_fold(path);  // our own reader: validation, file_frames, no duplicate keys
  EXPECT_GT(p.num_edges(), 0);
  expect_fold_types(Json::parse(slurp(path)), path, false);
}

TEST(OutputSafety, EveryFoldTheCliWritesReadsBackWithFold12Types) {
  Fixture f;
  const Scratch& s = f.s;
  std::vector<std::string> written;
  auto ok = [&](const std::string& args, const std::vector<std::string>& outs) {
    const test::CommandResult r = run(args);
    ASSERT_EQ(r.status, 0) << args << "\n" << r.err;
    for (const auto& o : outs) written.push_back(o);
  };
  for (const std::string kind : {"miura --rows 2 --cols 3 --fold-deg 40", "miura-tube --rows 2", "square-twist --type 1M",
                                 "square-twist-tessellation --rows 2 --cols 2", "waterbomb", "corrugated-p", "corrugated-q"}) {
    const std::string out = s.path("gen_" + std::to_string(written.size()) + ".fold");
    ok("generate " + kind + " --out " + out, {out});
  }
  ok("generate bundle --out-dir " + s.path("bundle"), {});
  for (const auto& e : fs::directory_iterator(s.path("bundle"))) written.push_back(e.path().string());
  ok("fold " + f.square + " --angles " + f.angles + " --out " + s.path("folded.fold"), {s.path("folded.fold")});
  ok("trace " + s.path("gen_0.fold") + " --steps 3 --out " + s.path("trace_miura.fold"), {s.path("trace_miura.fold")});
  const std::string twist = s.path("gen_2.fold");
  ok("trace " + twist + " --general --branch all --out " + s.path("branches.fold"), {});
  for (const auto& e : fs::directory_iterator(s.dir()))
    if (e.path().filename().string().rfind("branches.b", 0) == 0) written.push_back(e.path().string());
  ok("string forward " + f.spec + " --theta 20 --out " + s.path("string.fold"), {s.path("string.fold")});
  ok("string design " + f.target + " --out " + s.path("design.fold"), {s.path("design.fold")});
  fs::create_directories(s.path("report_in"));
  fs::copy_file(s.path("gen_0.fold"), s.path("report_in/m.fold"));
  ok("report " + s.path("report_in") + " --out " + s.path("report_out"), {s.path("report_out/m.folded.fold")});
  EXPECT_GE(written.size(), 20u);
  for (const auto& w : written) expect_fold_reads_back(w);
  EXPECT_TRUE(temporaries(s.dir()).empty());
}

// ---- concurrent writers ----------------------------------------------------------------------

pid_t spawn(const std::vector<std::string>& args) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, 1);
    ::dup2(null, 2);
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  return pid;
}

// Two processes writing different patterns to one path at once: the file is one of the two,
// whole, never a mix, and no temporary is left.
TEST(OutputSafety, TwoConcurrentWritersLeaveOneCompleteFile) {
  Scratch s;
  const std::string cli = test::cli();
  const std::string a = s.path("a.fold"), b = s.path("b.fold"), both = s.path("both.fold");
  ASSERT_EQ(run("generate miura --rows 60 --cols 60 --out " + a).status, 0);
  ASSERT_EQ(run("generate miura --rows 61 --cols 59 --out " + b).status, 0);
  const std::string text_a = slurp(a), text_b = slurp(b);
  ASSERT_NE(text_a, text_b);
  std::set<std::string> winners;
  for (int round = 0; round < 6; ++round) {
    const pid_t p1 = spawn({cli, "generate", "miura", "--rows", "60", "--cols", "60", "--out", both});
    const pid_t p2 = spawn({cli, "generate", "miura", "--rows", "61", "--cols", "59", "--out", both});
    int st1 = 0, st2 = 0;
    ASSERT_EQ(::waitpid(p1, &st1, 0), p1);
    ASSERT_EQ(::waitpid(p2, &st2, 0), p2);
    EXPECT_TRUE(WIFEXITED(st1) && WEXITSTATUS(st1) == 0);
    EXPECT_TRUE(WIFEXITED(st2) && WEXITSTATUS(st2) == 0);
    const std::string text = slurp(both);
    EXPECT_TRUE(text == text_a || text == text_b) << "round " << round << ": a mix of " << text.size() << " bytes";
    winners.insert(text == text_a ? "a" : "b");
    EXPECT_TRUE(temporaries(s.dir()).empty());
  }
}

}}  // namespace
}  // namespace rigidfold
