#include "kernel/thick/thick_run.hpp"

#include <cmath>
#include <cstdio>

#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/length_scale.hpp"
#include "kernel/pattern/no_answer_error.hpp"
#include "kernel/thick/thick_slabs.hpp"

namespace rigidfold {

ThickRun run_thick(const CreasePattern& flat, const Topology& topology, const ThickRunRequest& request) {
  if (topology.interior_vertices.empty()) throw InputError("pattern", "no interior vertex: nothing for thickness to change");
  require_flat_pattern(flat);  // before the zero-thickness trace, which would run on a folded form
  if (!std::isfinite(request.thickness) || !(request.thickness > 0)) throw InputError("thickness", "must be a finite number > 0");
  ThickRun run;
  run.request.thickness = std::ldexp(request.thickness, -flat.length_exponent);  // file units -> internal units
  Eigen::Vector3d lo = flat.vertices[0], hi = flat.vertices[0];
  for (const Eigen::Vector3d& v : flat.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  if (!(run.request.thickness <= (hi - lo).norm())) {
    char m[160];
    std::snprintf(m, sizeof m, "must be at most the pattern's diagonal, %.17g", to_file_units(flat, (hi - lo).norm()));
    throw InputError("thickness", m);
  }
  run.request.hinges = request.hinges;
  run.request.zero = zero_thickness_samples(flat, topology, 17, 1.5707963267948966, request.reverse);
  run.report = thick_report(flat, topology, run.request);
  if (request.slabs_at) {
    ThickSlabsAt at;
    at.state = thick_state_at(run.report, *request.slabs_at);
    at.placed = place_thick_sheet(run.report, at.state.rho);
    if (!(at.placed.relative_mismatch() <= 1e-9)) {
      char m[200];
      std::snprintf(m, sizeof m, "the thick sheet placed at %.9g deg leaves cracks of %.3g of its size (> 1e-9)",
                    *request.slabs_at * 180 / 3.141592653589793, at.placed.relative_mismatch());
      throw NoAnswerError(m, at.placed.relative_mismatch());
    }
    at.polygons = slab_polygons(flat, run.report, run.report.slabs.empty() ? panel_slabs(flat, topology, run.report) : run.report.slabs,
                                at.placed);
    run.at = std::move(at);
  }
  return run;
}

}  // namespace rigidfold
