// rigidfold._core: the extension module entry and the exception translation. Each area binds
// itself in its own file (bind_*.cpp).
#include <pybind11/pybind11.h>

#include <chrono>

#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/no_answer_error.hpp"
#include "python/bindings/bindings.hpp"
#include "rigidfold_version.hpp"

namespace rigidfold::python {

rigidfold::ProgressSink interrupt_on_signal() {
  // Python runs signal handlers on its main thread only: work started on another thread gets no
  // sink (and no cost).
  const py::module_ threading = py::module_::import("threading");
  if (!threading.attr("main_thread")().is(threading.attr("current_thread")())) return {};
  // At most every 50 ms: the GIL is taken only then, so that other Python threads are not slowed.
  auto last = std::chrono::steady_clock::now();
  return [last](const std::string&) mutable {
    const auto now = std::chrono::steady_clock::now();
    if (now - last < std::chrono::milliseconds(50)) return;
    last = now;
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw rigidfold::WorkInterrupted{};  // the handler's exception stays set
  };
}

py::object json_to_python(const nlohmann::ordered_json& j) {
  return py::module_::import("json").attr("loads")(j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace));
}

}  // namespace rigidfold::python

PYBIND11_MODULE(_core, m) {
  namespace py = pybind11;
  using namespace rigidfold::python;
  m.doc() =
      "rigidfold kernel bindings. Units: fold angles and sector angles in radians; FOLD sign "
      "(valley > 0, mountain < 0, 0 flat); lengths in the file's units.";

  // Bad input: the same place-naming message as the CLI's exit-2 line ("FILE: JSON_PATH: what").
  static py::exception<rigidfold::InputError> input_error(m, "InputError", PyExc_ValueError);
  input_error.doc() =
      "Bad input (file, JSON, parameter). str(e) names the place, e.g. "
      "'bad.fold: edges_vertices[2][1]: vertex index 9 out of range (4 vertices)'; e.place is the place alone.";
  // No result passes its own check (the CLI's exit status 3); e.residual is the best residual reached.
  static py::exception<rigidfold::NoAnswerError> no_answer_error(m, "NoAnswerError", PyExc_RuntimeError);
  no_answer_error.doc() =
      "The computation ran on valid input but no result passes its own check; e.residual is the "
      "best residual reached (NaN when none), in the units the message states.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const rigidfold::InputError& e) {
      py::object exc = py::handle(input_error.ptr())(py::str(e.what()));
      exc.attr("place") = py::str(e.place());
      PyErr_SetObject(input_error.ptr(), exc.ptr());
    } catch (const rigidfold::NoAnswerError& e) {
      py::object exc = py::handle(no_answer_error.ptr())(py::str(e.what()));
      exc.attr("residual") = py::float_(e.residual());
      PyErr_SetObject(no_answer_error.ptr(), exc.ptr());
    } catch (const rigidfold::WorkInterrupted&) {
      // PyErr_CheckSignals set the signal handler's exception (KeyboardInterrupt for Ctrl-C).
      if (!PyErr_Occurred()) PyErr_SetNone(PyExc_KeyboardInterrupt);
    }
  });

  m.attr("__version__") = rigidfold::kRigidfoldVersion;  // the CLI's provenance "rigidfold_version"
  m.attr("__commit__") = rigidfold::kRigidfoldCommit;

  bind_pattern(m);
  bind_analysis(m);
  bind_vertex(m);
  bind_design(m);
  bind_energy(m);
  bind_thick(m);
  bind_sorce(m);
  bind_metamaterial(m);
  bind_network(m);
  bind_formats(m);
  bind_repair(m);
}
