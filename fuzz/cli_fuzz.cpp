// libFuzzer targets that drive whole `rigidfold` commands in-process through run_cli (the
// same exit-status mapping as the executable), one target per user-input entry. This file is
// compiled once and linked into each target; the target's name (argv[0]) picks its entry:
//   entry 1  angles_json_fuzz    fold BUNDLED.fold --angles INPUT --out O.fold, then --target INPUT
//   entry 2  string_spec_fuzz    string forward INPUT --theta 20 --out O.fold
//   entry 3  string_target_fuzz  string design INPUT --out O.fold
//   entry 4  cli_flags_fuzz      generate|trace|vertex|waterbomb|assignments|energy|metamaterial|check|thick|sorce|repair + flags
//   entry 5  sorce_spec_fuzz     sorce VERTEX_A.fold --thickness 0.1 --offsets INPUT --out DIR
//   entry 6  network_json_fuzz   network INPUT --json --trace 4
// The input is written to a file in a private temporary directory. A bad input must end in exit 2 and a good one in 0; exit 1 ("internal
// error", an exception that is not bad input) aborts, so libFuzzer reports it with the
// input, like a crash.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "app/commands.hpp"

namespace {

// The entry of this target (1..6 above), from its name.
int g_entry = 0;

int entry_of(const std::string& program) {
  const std::string name = program.substr(program.find_last_of('/') + 1);
  const char* names[] = {"angles_json_fuzz", "string_spec_fuzz", "string_target_fuzz",
                         "cli_flags_fuzz", "sorce_spec_fuzz", "network_json_fuzz"};
  for (int i = 0; i < 6; ++i)
    if (name == names[i]) return i + 1;
  std::fprintf(stderr, "cli_fuzz: %s is not one of the targets of fuzz/CMakeLists.txt\n", name.c_str());
  std::abort();
}

struct NullBuffer : std::streambuf {
  int overflow(int c) override { return c; }
  std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};

// The bundled pattern that the angles and flags targets fold and trace.
const std::string kPattern = std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled/miura_3x3_perturbed.fold";
// The bundled waterbomb base and its rest state, for the energy command's flags.
const std::string kWaterbomb = std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled/waterbomb_base.fold";
const std::string kWaterbombRest = std::string(RIGIDFOLD_SOURCE_DIR) + "/data/energy/waterbomb_base_rest60.json";
// The seed 002 vertex A, for the sorce command (its flags, and its --offsets SPEC.json).
const std::string kVertexA = std::string(RIGIDFOLD_SOURCE_DIR) + "/data/sorce/vertex_a.fold";
// A flat-foldable Miura-ori, for the thick command's flags (every --hinges runs on it).
const std::string kMiura = std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled/miura_4x4_alpha60.fold";

// The private temporary directory every run writes in (created once). The flags target
// also makes it the working directory, so that the relative paths its tokens may name stay
// inside it; run it with absolute corpus paths and -artifact_prefix (as .ci/run does).
const std::string& private_directory() {
  static const std::string dir = [] {
    char name[] = "/tmp/rigidfold_fuzz_XXXXXX";
    if (!::mkdtemp(name)) std::abort();
    static NullBuffer null;
    std::cout.rdbuf(&null);
    std::cerr.rdbuf(&null);
    if (g_entry == 4 && ::chdir(name) != 0) std::abort();
    return std::string(name);
  }();
  return dir;
}

std::string in_private(const std::string& name) { return private_directory() + "/" + name; }

void write_input(const std::uint8_t* data, std::size_t size) {
  std::ofstream out(in_private("input.json"), std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

// Flags target: the input is tokens separated by newlines; the first byte picks the
// command. Tokens with '/' are dropped, so every path stays inside the private directory.
// Flags whose only effect is more work of the same kind (waterbomb --curve/--samples: up to
// 2001 loaded equilibria on a 360-crease vertex; energy --starts: up to 1000 minimisations)
// and sorce --optimize/--steps: a search of ~200 joint designs, a trace of up to 2000 steps;
// waterbomb --sweep-*: up to 400 analyses, and --plot: a Python process per run; metamaterial
// --cross-check: a traced tessellation of up to 2000 steps; energy --barriers: a string
// method per pair of stable states, 1.7 s in Release on the bundled base; metamaterial
// --stacked-steps: up to 200 traced steps per layer; repair --max-added: 2 searches ~600 pairs of
// added creases, each a check) are dropped too, and waterbomb
// --n is held at most 24 (n = 180 checks each state on a 360-crease vertex: ~6 s in Release,
// far more under ASan), 4 for a split-fold base (see below): a legal run of minutes would
// count as a libFuzzer timeout (-timeout=30).
std::vector<std::string> flag_args(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> args{"rigidfold"};
  if (size == 0) return args;
  switch (data[0] % 13) {  // every case reachable (with % 10, check was not: sorce took 9)
    case 0: args.insert(args.end(), {"generate"}); break;
    case 1: args.insert(args.end(), {"trace", kPattern}); break;
    case 2: args.insert(args.end(), {"trace", kPattern, "--general"}); break;
    case 3: args.insert(args.end(), {"vertex"}); break;
    case 4: args.insert(args.end(), {"waterbomb"}); break;
    case 5: args.insert(args.end(), {"assignments", kPattern}); break;
    case 6: args.insert(args.end(), {"energy", kWaterbomb, "--rest", kWaterbombRest}); break;
    case 7: args.insert(args.end(), {"metamaterial"}); break;
    case 8: args.insert(args.end(), {"thick", kMiura}); break;
    case 9: args.insert(args.end(), {"sorce", kVertexA}); break;
    case 11: args.insert(args.end(), {"repair", kPattern}); break;
    case 12: args.insert(args.end(), {"repair", kPattern, "--add-creases", "--max-added", "1"}); break;
    default: args.insert(args.end(), {"check", kPattern}); break;  // 10
  }
  std::string token;
  const auto flush = [&] {
    const bool costly = token.rfind("--curve", 0) == 0 || token.rfind("--samples", 0) == 0 || token.rfind("--starts", 0) == 0 ||
                        token.rfind("--optimize", 0) == 0 || token.rfind("--steps", 0) == 0 ||
                        token.rfind("--sweep", 0) == 0 || token.rfind("--cross-check", 0) == 0 ||
                        token.rfind("--barriers", 0) == 0 || token.rfind("--stacked-steps", 0) == 0 ||
                        token.rfind("--max-added", 0) == 0 ||
                        (args.size() > 1 && args[1] == "waterbomb" && token.rfind("--plot", 0) == 0);
    if (!token.empty() && !costly && token.find('/') == std::string::npos && token.find('\0') == std::string::npos &&
        args.size() < 24)
      args.push_back(token);
    token.clear();
  };
  for (std::size_t i = 1; i < size; ++i) {
    if (data[i] == '\n') flush();
    else token.push_back(static_cast<char>(data[i]));
  }
  flush();
  if (args.size() > 1 && args[1] == "waterbomb") {
    // A split-fold base checks every state on the 4n-crease general model, and the sanitizer
    // build runs it ~100x slower than Release: n = 4 takes 1.8 s there, n = 6 8.8 s, n = 4 with
    // --target-switching-force (a search of such analyses) 11 s, n = 12 with it past the 30 s
    // timeout. With --split-deg, --n is held at 4 and --target-switching-force is dropped.
    bool split = false;
    for (const std::string& a : args) split = split || a.rfind("--split-deg", 0) == 0;
    if (split)
      args.erase(std::remove_if(args.begin() + 2, args.end(),
                                [](const std::string& a) { return a.rfind("--target-switching-force", 0) == 0; }),
                 args.end());
    const int most = split ? 4 : 24;
    for (std::size_t i = 2; i < args.size(); ++i) {
      // The value of --n, as "--n V" or "--n=V", read the way a number may be written (hex,
      // exponent): anything that could be more than 24 becomes 24.
      std::string* value = nullptr;
      std::string prefix;
      if (args[i] == "--n" && i + 1 < args.size()) value = &args[i + 1];
      if (args[i].rfind("--n=", 0) == 0) {
        value = &args[i];
        prefix = "--n=";
      }
      if (!value) continue;
      const std::string text = value->substr(prefix.size());
      const double as_double = std::strtod(text.c_str(), nullptr);
      const long long as_integer = std::strtoll(text.c_str(), nullptr, 0);
      if (!(as_double <= most) || as_integer > most || text.size() > 3) *value = prefix + std::to_string(most);
    }
  }
  return args;
}

// Runs one command line; 0 done, 2 bad input, 3 no answer passed the command's own check
// (app/main.cpp); 1 or anything else is an internal error, and aborts.
void run(const std::vector<std::string>& args) {
  std::vector<const char*> argv;
  for (const auto& a : args) argv.push_back(a.c_str());
  const int status = rigidfold::cli::run_cli(static_cast<int>(argv.size()), argv.data());
  if (status != 0 && status != 2 && status != 3) {
    std::fprintf(stderr, "run_cli returned %d (internal error) for:", status);
    for (const auto& a : args) std::fprintf(stderr, " '%s'", a.c_str());
    std::fprintf(stderr, "\n");
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  g_entry = entry_of(*argc > 0 ? (*argv)[0] : "");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input = in_private("input.json"), out = in_private("out.fold");
  std::vector<std::string> args;
  switch (g_entry) {
    case 1:
      write_input(data, size);
      args = {"rigidfold", "fold", kPattern, "--angles", input, "--out", out, "--obj", in_private("out.obj")};
      break;
    case 2:
      write_input(data, size);
      args = {"rigidfold", "string", "forward", input, "--theta", "20", "--out", out, "--svg", in_private("out.svg")};
      break;
    case 3:
      write_input(data, size);
      args = {"rigidfold", "string", "design", input, "--out", out};
      break;
    case 5:
      write_input(data, size);
      args = {"rigidfold", "sorce", kVertexA, "--thickness", "0.1", "--drive", "1", "--to", "180", "--offsets", input, "--out",
              in_private("sorce")};
      break;
    case 6:
      write_input(data, size);
      args = {"rigidfold", "network", input, "--json", "--trace", "4"};
      break;
    default:
      args = flag_args(data, size);
      break;
  }
  run(args);
  // The same file as the target of `fold --target` (the same reader, then the nearest closed state).
  if (g_entry == 1) run({"rigidfold", "fold", kPattern, "--target", input, "--out", out});
  return 0;
}
