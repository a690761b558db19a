// What the viewer knows about each frame of a branch beyond its geometry:
// events at that step and the panels in facet interference. All of it comes
// from the catalogue (trace/check summaries), and from a frame's
// rigidfold:interfering_faces should trace ever write it.

// Per frame: { events: [...], interferingFaces: [face ids], notes: [text] }.
export function frameAnnotations(trace, branch) {
  const out = trace.frames.map((f) => ({ events: [], interferingFaces: new Set(f.interferingFaces), notes: [] }));
  for (const e of branch.events || []) {
    const a = out[e.step];
    if (!a) continue;
    a.events.push(e);
    // Local interference: a crease at +-180 deg puts its two panels face to face.
    if (e.kind === 'interference' && e.edge !== undefined) {
      for (const f of trace.edgeFaces[e.edge] || []) a.interferingFaces.add(f);
    }
  }
  // Global interference (faces crossing) is located by check at a driving
  // angle; mark the frames that reach it, and say so on the last frame when
  // the branch stops before it.
  const gi = branch.globalInterference;
  if (gi && branch.drivingCrease !== undefined) {
    const d = gi.fromDrivingDeg;
    let reached = false;
    trace.frames.forEach((f, i) => {
      const x = f.foldAngleDeg ? f.foldAngleDeg[branch.drivingCrease] : 0;
      if (d !== undefined && Math.sign(x) === Math.sign(d) && Math.abs(x) >= Math.abs(d)) {
        gi.faces.forEach((fc) => out[i].interferingFaces.add(fc));
        reached = true;
      }
    });
    if (!reached) {
      const last = out[out.length - 1];
      last.notes.push(`faces ${gi.faces.join(' and ')} cross from driving angle ${d === undefined ? '?' : d.toFixed(3)} deg (beyond this branch's last frame)`);
    }
  }
  return out.map((a) => ({ ...a, interferingFaces: [...a.interferingFaces] }));
}

// Jump targets for a located point: every branch that arrives there (its
// last frame) or leaves from it (its first folded frame, step 1).
export function jumpsTo(set, point) {
  const jumps = [];
  set.branches.forEach((b, bi) => {
    if (b.toPoint === point) jumps.push({ branchIndex: bi, frame: b.frames - 1, label: `branch ${b.id} arrives` });
    if (b.fromPoint === point) jumps.push({ branchIndex: bi, frame: Math.min(1, b.frames - 1), label: `branch ${b.id} leaves` });
  });
  return jumps;
}
