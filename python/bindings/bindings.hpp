#pragma once
// Shared declarations of the rigidfold._core bindings. Each bind_*.cpp binds one area; they are
// thin: conversions between the kernel's types and Python (numpy arrays, lists, dicts) only.
#include <pybind11/pybind11.h>

#include <string>

#include <nlohmann/json.hpp>

namespace rigidfold::python {

namespace py = pybind11;

void bind_pattern(py::module_& m);   // CreasePattern, FOLD load/save, generators
void bind_analysis(py::module_& m);  // check, trace, enumerate_assignments
void bind_vertex(py::module_& m);    // flat-foldable degree-4 closed forms, the closure system
void bind_design(py::module_& m);    // waterbomb bistability

// A JSON value as plain Python objects (dict, list, float, int, str, bool, None), through the
// standard json module so that numbers keep their exact values.
py::object json_to_python(const nlohmann::ordered_json& j);

}  // namespace rigidfold::python
