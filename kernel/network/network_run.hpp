#pragma once
// run_network: the front door of `rigidfold network` and rigidfold.network(). The request is
// checked, the network file read, the network analysed (network_analysis.hpp), and its crease
// pattern written on request: the output is declared before any work (it may not replace the
// network file) and written only after the analysis passed its checks, never in part.
// The places its InputErrors name are the caller's: the CLI's flags or Python's keywords.
#include <string>

#include "kernel/network/network_analysis.hpp"
#include "kernel/network/network_json.hpp"

namespace rigidfold {

struct NetworkRunPlaces {
  std::string spec = "NETWORK";          // the network file
  std::string trace_steps = "--trace";
  std::string crease_pattern = "--out";  // the crease pattern's file
};

struct NetworkRun {
  NetworkAnalysisOptions options;  // as run (trace_steps, crease_pattern, source)
  NetworkSpec spec;
  NetworkAnalysis analysis;
  bool wrote_stdout = false;       // the crease pattern went to standard output ("-")
};

// crease_pattern_path: "" for none. Throws InputError naming places.trace_steps (out of
// 0..10000), places.crease_pattern (no crease pattern for this network, or an output that
// cannot be written) or the file's JSON path; NoAnswerError as analyse_network.
NetworkRun run_network(const std::string& spec_path, int trace_steps, const std::string& crease_pattern_path,
                       const NetworkRunPlaces& places = {});

}  // namespace rigidfold
