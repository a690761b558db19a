// FOLD parsing for the viewer: turns a multi-frame FOLD written by
// `rigidfold trace --out` into flat arrays the scene can use directly.
// Pure JavaScript (no DOM, no three.js) so the node build script and the
// end-to-end test read files exactly as the page does.

// Kinds drawn as creases and counted by the test (Origami Simulator's M/V/B).
export const CREASE_KINDS = ['M', 'V', 'B'];

// Resolves frame `i` of a FOLD object, 0 being the top level (the key frame).
// FOLD's frame_inherit means "take every key the frame does not set from its
// parent", so resolve the parent first, then overlay the frame's own keys.
function resolveFrame(fold, i, cache) {
  if (cache[i]) return cache[i];
  let frame;
  if (i === 0) {
    frame = { ...fold };
    delete frame.file_frames;
  } else {
    const own = fold.file_frames[i - 1];
    const parent = own.frame_inherit && Number.isInteger(own.frame_parent)
      && own.frame_parent >= 0 && own.frame_parent < i
      ? resolveFrame(fold, own.frame_parent, cache) : {};
    frame = { ...parent, ...own };
  }
  cache[i] = frame;
  return frame;
}

// Returns the edges around each face as [edge indices], from faces_vertices:
// a face's boundary step (a, b) is the edge whose endpoints are {a, b}.
export function edgeFaces(edgesVertices, facesVertices) {
  const key = (a, b) => (a < b ? `${a},${b}` : `${b},${a}`);
  const byKey = new Map();
  edgesVertices.forEach(([a, b], e) => byKey.set(key(a, b), e));
  const faces = edgesVertices.map(() => []);
  facesVertices.forEach((f, fi) => {
    for (let k = 0; k < f.length; ++k) {
      const e = byKey.get(key(f[k], f[(k + 1) % f.length]));
      if (e !== undefined) faces[e].push(fi);
    }
  });
  return faces;
}

// Counts edges per assignment letter (missing assignment counts as 'U').
export function countKinds(assignment, edgeCount) {
  const counts = {};
  for (let e = 0; e < edgeCount; ++e) {
    const k = (assignment && assignment[e]) || 'U';
    counts[k] = (counts[k] || 0) + 1;
  }
  return counts;
}

// Parses a FOLD object into
//   { title, edges, assignment, faces, edgeFaces, kindCounts,
//     frames: [{ index, title, isKey, coords (Float64Array, 3 per vertex),
//                foldAngleDeg (array or null), residualRad, mismatch }] }
// Frame 0 is the key frame (the crease pattern); trace writes one
// foldedForm frame per step after it.
export function parseFold(fold) {
  if (!fold || !Array.isArray(fold.vertices_coords) || !Array.isArray(fold.edges_vertices)) {
    throw new Error('not a FOLD file: vertices_coords or edges_vertices missing');
  }
  const edges = fold.edges_vertices;
  const assignment = fold.edges_assignment || edges.map(() => 'U');
  const faces = fold.faces_vertices || [];
  const frameCount = 1 + (Array.isArray(fold.file_frames) ? fold.file_frames.length : 0);
  const cache = [];
  const frames = [];
  for (let i = 0; i < frameCount; ++i) {
    const f = resolveFrame(fold, i, cache);
    const coords = new Float64Array(3 * f.vertices_coords.length);
    f.vertices_coords.forEach((p, v) => {
      coords[3 * v] = p[0];
      coords[3 * v + 1] = p[1];
      coords[3 * v + 2] = p.length > 2 ? p[2] : 0;
    });
    // The key frame inherits nothing: a fold angle there is the file's own.
    const own = i === 0 ? fold : fold.file_frames[i - 1];
    frames.push({
      index: i,
      title: f.frame_title || (i === 0 ? 'crease pattern' : `frame ${i}`),
      isKey: i === 0,
      coords,
      foldAngleDeg: Array.isArray(f.edges_foldAngle) ? f.edges_foldAngle : null,
      residualRad: typeof own['rigidfold:max_residual_rad'] === 'number' ? own['rigidfold:max_residual_rad'] : null,
      mismatch: typeof own['rigidfold:closure_mismatch'] === 'number' ? own['rigidfold:closure_mismatch'] : null,
      // Not written by trace yet (see README): faces in interference at this frame.
      interferingFaces: Array.isArray(own['rigidfold:interfering_faces']) ? own['rigidfold:interfering_faces'].flat() : [],
    });
  }
  return {
    title: fold.file_title || '',
    edges,
    assignment,
    faces,
    edgeFaces: edgeFaces(edges, faces),
    kindCounts: countKinds(assignment, edges.length),
    frames,
  };
}
