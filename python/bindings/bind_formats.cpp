// Format bindings: crease patterns as the SVG and DXF texts `rigidfold export` writes
// (kernel/pattern/svg_writer.hpp, dxf_writer.hpp). Reading SVG and ORIPA .opx is `load`.
#include <pybind11/stl.h>

#include <string>

#include "kernel/pattern/dxf_writer.hpp"
#include "kernel/pattern/svg_writer.hpp"
#include "python/bindings/bindings.hpp"

namespace rigidfold::python {

void bind_formats(py::module_& m) {
  m.def("svg_text", &write_svg_string, py::arg("pattern"), py::arg("source") = "pattern",
        "The pattern's crease pattern as SVG text in Origami Simulator's convention (the inverse of load() on an "
        ".svg: colours per letter, stroke opacity |fold angle| / 180 deg, SVG y = -FOLD y, coordinates that read "
        "back bit for bit); a 3D folded form is written as its flat development. The text `rigidfold export "
        "--svg` writes. Raises InputError (a tube or sheet with holes, several pieces, a J edge, ...).");
  m.def("dxf_text", &write_dxf_string, py::arg("pattern"), py::arg("source") = "pattern",
        "The pattern's crease pattern as ASCII DXF R12 text (one LINE per edge on a layer per letter), the text "
        "`rigidfold export --dxf` writes.");
}

}  // namespace rigidfold::python
