// Network bindings: a network of spherical linkages given by twists (kernel/network), analysed
// as `rigidfold network` does, returned as the object its --json prints (report/network_json.hpp).
// The GIL is released while the file is read and the network analysed.
#include <string>

#include "kernel/network/network_analysis.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/output_set.hpp"
#include "python/bindings/bindings.hpp"
#include "report/network_json.hpp"

namespace rigidfold::python {
namespace {

// A path given as str, bytes or os.PathLike, as the CLI would receive it.
std::string network_path_text(const py::object& path) {
  return py::module_::import("os").attr("fspath")(path).cast<std::string>();
}

// The steps of the CLI's callback with the Python names for the places in errors: spec_path
// the network file, trace_steps (--trace), crease_pattern_path (--out; "" for none).
nlohmann::ordered_json analysed_network_json(const std::string& spec_path, int trace_steps, const std::string& crease_pattern_path) {
  NetworkAnalysisOptions options;
  options.trace_steps = trace_steps;
  options.crease_pattern = !crease_pattern_path.empty();
  options.source = spec_path;
  if (std::string why; !options.IsValid(&why)) throw InputError("trace_steps", "must be in 0..10000");
  const NetworkSpec spec = read_network_json(spec_path);
  // Declared before any work, as the CLI does: the crease pattern may not replace the network file.
  OutputSet outputs;
  outputs.add_input("spec", spec_path);
  if (options.crease_pattern) outputs.add_output("out", crease_pattern_path);
  NetworkAnalysis analysis;
  try {
    analysis = analyse_network(spec, options);
  } catch (const InputError& e) {
    if (e.place() == "crease_pattern") throw InputError("out", e.message());
    throw;
  }
  if (analysis.crease_pattern) outputs.stage(crease_pattern_path, write_fold_string(analysis.crease_pattern->pattern));
  outputs.commit();
  return report::network_json(spec_path, spec, analysis, options, crease_pattern_path);
}

}  // namespace

void bind_network(py::module_& m) {
  m.def(
      "network",
      [](const py::object& spec, int trace_steps, const py::object& out) {
        const std::string spec_path = network_path_text(spec);
        const std::string crease_pattern_path = out.is_none() ? std::string() : network_path_text(out);
        nlohmann::ordered_json j;
        {
          py::gil_scoped_release release;
          j = analysed_network_json(spec_path, trace_steps, crease_pattern_path);
        }
        return json_to_python(j);
      },
      py::arg("spec"), py::arg("trace_steps") = 0, py::arg("out") = py::none(),
      "A network of spherical linkages given by twists (docs/cli/network.md): a closed configuration with the "
      "input joint at input.start_deg, the mobility there, the verdict, as the dict `rigidfold network --json` "
      "prints (without its 'provenance'): network, description, model, joints, linkages, equations, "
      "closure_tolerance_rad, rank_tolerance_relative, flat_vertices_2_33, configuration, mobility, verdict, "
      "verdict_class, and on request crease_pattern and trace. Angles in degrees (keys ending in _deg).\n"
      "spec: the network JSON file (str or os.PathLike). trace_steps (`--trace`, 0..10000): trace the input "
      "to input.end_deg in this many equal steps. out (`--out`): write the assembly of four 4R linkages as a "
      "FOLD crease pattern there (a mobile network of flat vertices around a flat central panel). "
      "Raises InputError (the place named: the file's JSON path, 'trace_steps' or 'out'), NoAnswerError.");
}

}  // namespace rigidfold::python
