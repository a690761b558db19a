#pragma once
// Shared declarations of the rigidfold._core bindings. Each bind_*.cpp binds one area; they are
// thin: conversions between the kernel's types and Python (numpy arrays, lists, dicts) only.
#include <pybind11/pybind11.h>

#include <string>

#include <nlohmann/json.hpp>

#include "kernel/analysis/progress.hpp"

namespace rigidfold::python {

namespace py = pybind11;

void bind_pattern(py::module_& m);   // CreasePattern, FOLD load/save, generators
void bind_analysis(py::module_& m);  // check, trace, enumerate_assignments
void bind_vertex(py::module_& m);    // flat-foldable degree-4 closed forms, the closure system
void bind_design(py::module_& m);    // waterbomb bistability
void bind_energy(py::module_& m);    // stable states of any pattern with crease springs
void bind_thick(py::module_& m);     // thick-panel vertices (seed 003 ch. 4)
void bind_sorce(py::module_& m);     // SORCE rolling joints (seed 002)
void bind_metamaterial(py::module_& m);  // metamaterial units and stacks (seed 003 3.2.3, 3.3.2)
void bind_network(py::module_& m);   // networks of spherical linkages (seed 003 ch. 2)
void bind_formats(py::module_& m);   // SVG and DXF text of a crease pattern
void bind_repair(py::module_& m);    // repair, add_creases, nearest_closed_state (design for any pattern)

// A progress sink (kernel/analysis/progress.hpp) that runs Python's signal handlers at each unit
// of the kernel's work, the GIL held only for that: Ctrl-C during a long check or trace raises
// KeyboardInterrupt within one unit of work instead of after the whole run.
rigidfold::ProgressSink interrupt_on_signal();

// A JSON value as plain Python objects (dict, list, float, int, str, bool, None), through the
// standard json module so that numbers keep their exact values.
py::object json_to_python(const nlohmann::ordered_json& j);

}  // namespace rigidfold::python
