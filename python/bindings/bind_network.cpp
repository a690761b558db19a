// Network bindings: a network of spherical linkages given by twists (kernel/network), analysed
// as `rigidfold network` does, returned as the object its --json prints (report/network_json.hpp).
// The GIL is released while the file is read and the network analysed.
#include <string>

#include "kernel/network/network_run.hpp"
#include "python/bindings/bindings.hpp"
#include "report/network_json.hpp"

namespace rigidfold::python {
namespace {

// A path given as str, bytes or os.PathLike, as the CLI would receive it.
std::string network_path_text(const py::object& path) {
  return py::module_::import("os").attr("fspath")(path).cast<std::string>();
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
          const NetworkRun run =
              run_network(spec_path, trace_steps, crease_pattern_path, {"spec", "trace_steps", "out"});
          j = report::network_json(spec_path, run.spec, run.analysis, run.options, crease_pattern_path);
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
