// The catalogue of traces the page offers: FOLD files grouped into sets (one
// set per pattern traced), each with its branches, plus what the optional
// JSON summaries add. Built once by build.mjs and written as index.json.
//
// Inputs the build accepts:
//  - FOLD files from `rigidfold trace P --out T.fold`: T.fold (one branch) or
//    T.b<ID>.fold (`--branch all` with the general solver, one per branch);
//  - `rigidfold trace ... --json` output (has "outputs"): per branch its
//    stop reason and events (M/V switches, creases reaching 180 deg);
//  - `rigidfold check P --json` output (has "bifurcations"): the branch graph
//    (from_point, to_point), the located bifurcations, global interference.
// The FOLD files alone carry none of these (see the README in viewer/).

const baseName = (p) => p.split(/[\\/]/).pop();

// Splits "T.b12.fold" into { set: "T", branch: 12 }, "T.fold" into { set: "T", branch: null }.
export function splitTraceName(file) {
  const b = baseName(file);
  const m = /^(.*)\.b(\d+)\.fold$/.exec(b);
  if (m) return { set: m[1], branch: Number(m[2]) };
  return { set: b.replace(/\.fold$/, ''), branch: null };
}

// folds: [{ file (name written in the output), fold (parsed JSON) }]
// summaries: parsed JSON objects (trace or check output), any order.
export function buildCatalogue(folds, summaries) {
  const traceSums = summaries.filter((s) => Array.isArray(s.outputs));
  const checkSums = summaries.filter((s) => Array.isArray(s.bifurcations) && Array.isArray(s.branches));
  const sets = new Map();
  for (const { file, fold, source } of folds) {
    const { set, branch } = splitTraceName(file);
    if (!sets.has(set)) sets.set(set, { name: set, title: fold.file_title || set, branches: [] });
    const s = sets.get(set);
    // A trace summary belongs to this set when it lists this file as output.
    const ts = traceSums.find((t) => t.outputs.some((o) => baseName(o) === baseName(source || file)));
    if (ts && !s.trace) s.trace = ts;
    s.branches.push({ id: branch, file, frames: 1 + (fold.file_frames ? fold.file_frames.length : 0) });
  }
  for (const s of sets.values()) {
    s.branches.sort((a, b) => (a.id ?? 0) - (b.id ?? 0));
    const ts = s.trace;
    delete s.trace;
    if (ts) {
      s.pattern = ts.file;
      s.model = ts.model;
      s.note = ts.note || '';
      // Single-branch traces print the branch at the top level, not in "branches".
      const tb = Array.isArray(ts.branches) && ts.branches.length ? ts.branches : [ts];
      for (const b of s.branches) {
        const t = tb.find((x) => (x.branch ?? 0) === (b.id ?? ts.branch ?? 0)) || (tb.length === 1 ? tb[0] : null);
        if (b.id === null && t) b.id = t.branch ?? 0;
        if (!t) continue;
        b.drivingCrease = t.driving_crease;
        b.stoppedBy = t.stopped_by;
        b.maxResidual = t.max_residual;
        b.events = (t.events || []).map((e) => ({ step: e.step, kind: e.kind, edge: e.edge, angleDeg: e.angle_deg }));
      }
    }
    // A check summary belongs to the set whose trace read the same pattern.
    const cs = checkSums.find((c) => s.pattern && (c.file === s.pattern || baseName(c.file) === baseName(s.pattern)))
      || checkSums.find((c) => baseName(c.file).replace(/\.(fold|svg)$/, '') === s.name);
    if (cs) {
      s.verdict = cs.verdict_class;
      s.points = cs.bifurcations.map((p) => ({
        point: p.point, kind: p.kind, parameterDeg: p.parameter, parameterCrease: p.parameter_crease,
        boundRad: p.location_error_bound_rad, kernelDimension: p.kernel_dimension, tangentLines: p.tangent_lines,
      }));
      for (const b of s.branches) {
        const c = cs.branches.find((x) => x.id === b.id);
        if (!c) continue;
        b.fromPoint = c.from_point;
        b.toPoint = c.to_point;
        if (c.global_interference) {
          b.globalInterference = { faces: c.global_interference.faces, fromDrivingDeg: c.global_interference.from_driving_deg };
        }
      }
    }
  }
  return { sets: [...sets.values()] };
}
