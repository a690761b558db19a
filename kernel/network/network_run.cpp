#include "kernel/network/network_run.hpp"

#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/output_set.hpp"

namespace rigidfold {

NetworkRun run_network(const std::string& spec_path, int trace_steps, const std::string& crease_pattern_path,
                       const NetworkRunPlaces& places) {
  NetworkRun run;
  run.options.trace_steps = trace_steps;
  run.options.crease_pattern = !crease_pattern_path.empty();
  run.options.source = spec_path;
  if (std::string why; !run.options.IsValid(&why)) throw InputError(places.trace_steps, "must be in 0..10000");
  run.spec = read_network_json(spec_path);
  OutputSet outputs;
  outputs.add_input(places.spec, spec_path);
  if (run.options.crease_pattern) outputs.add_output(places.crease_pattern, crease_pattern_path);
  run.wrote_stdout = outputs.writes_stdout();
  try {
    run.analysis = analyse_network(run.spec, run.options);
  } catch (const InputError& e) {
    if (e.place() == "crease_pattern") throw InputError(places.crease_pattern, e.message());
    throw;
  }
  if (run.analysis.crease_pattern) outputs.stage(crease_pattern_path, write_fold_string(run.analysis.crease_pattern->pattern));
  outputs.commit();
  return run;
}

}  // namespace rigidfold
