// three.js scene for one traced pattern: shaded panels (front and back in
// different colours, as paper), creases as coloured lines, panels in facet
// interference overlaid, one picked crease highlighted. Renders on demand
// (after a change) rather than in a loop, so an idle page costs nothing.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { CREASE_KINDS } from './fold.js';

// Origami Simulator's colours: mountain red, valley blue, boundary black,
// flat facet yellow, unassigned magenta, cut green.
export const KIND_COLOURS = {
  M: 0xff0000, V: 0x0000ff, B: 0x000000, F: 0xffff00, U: 0xff00ff, C: 0x00ff00, J: 0x00ff00,
};
const PICK_COLOUR = 0x00c000;
const FRONT_COLOUR = 0xe8e8f0;
const BACK_COLOUR = 0xf4e3b0;
const INTERFERENCE_COLOUR = 0xff8800;
export const BACKGROUND = 0xffffff;

// Triangulates each face once, on the key frame's (flat) coordinates: panels
// are rigid, so the same triangles stay valid in every folded frame. Faces are
// projected on their best-fit plane first so 3D key frames (tubes) work too.
function triangulateFaces(faces, coords) {
  const tris = [];
  const faceOfTri = [];
  faces.forEach((face, fi) => {
    if (face.length < 3) return;
    const p = face.map((v) => new THREE.Vector3(coords[3 * v], coords[3 * v + 1], coords[3 * v + 2]));
    const n = new THREE.Vector3();
    for (let k = 0; k < p.length; ++k) {
      const a = p[k];
      const b = p[(k + 1) % p.length];
      n.x += (a.y - b.y) * (a.z + b.z);
      n.y += (a.z - b.z) * (a.x + b.x);
      n.z += (a.x - b.x) * (a.y + b.y);
    }
    if (n.lengthSq() === 0) return;
    n.normalize();
    const u = new THREE.Vector3().crossVectors(n, Math.abs(n.x) < 0.9 ? new THREE.Vector3(1, 0, 0) : new THREE.Vector3(0, 1, 0)).normalize();
    const w = new THREE.Vector3().crossVectors(n, u);
    const contour = p.map((q) => new THREE.Vector2(q.dot(u), q.dot(w)));
    for (const [i, j, k] of THREE.ShapeUtils.triangulateShape(contour, [])) {
      tris.push(face[i], face[j], face[k]);
      faceOfTri.push(fi);
    }
  });
  return { tris, faceOfTri };
}

export class FoldScene {
  constructor(canvas) {
    this.canvas = canvas;
    // preserveDrawingBuffer keeps the last image readable (test, screenshots).
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(1);
    this.renderer.setClearColor(BACKGROUND, 1);
    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(35, 1, 0.01, 1000);
    this.camera.up.set(0, 0, 1); // the pattern lies in the xy-plane, seen from +z
    this.scene.add(this.camera);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x808080, 1.6));
    const sun = new THREE.DirectionalLight(0xffffff, 1.6);
    sun.position.set(0.3, 0.5, 1);
    this.camera.add(sun); // light follows the view, so no side is ever black
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.addEventListener('change', () => this.render());
    this.group = null;
    this.trace = null;
    this.frame = 0;
    this.picked = -1;
    this.stats = { creasesDrawn: {}, mvbDrawn: 0, trianglesDrawn: 0, interferingFaces: 0 };
  }

  resize(width, height) {
    this.renderer.setSize(width, height, false);
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
    this.render();
  }

  // Builds the geometry of a parsed trace (see fold.js parseFold).
  setTrace(trace) {
    if (this.group) {
      this.scene.remove(this.group);
      this.group.traverse((o) => { if (o.geometry) o.geometry.dispose(); if (o.material) o.material.dispose(); });
    }
    this.trace = trace;
    this.picked = -1;
    this.frame = 0; // the previous trace's frame may not exist in this one
    this.group = new THREE.Group();

    // Panels: non-indexed triangles (3 own vertices each) so an overlay can
    // pick out single faces; flat shading gives each panel one normal.
    const { tris, faceOfTri } = triangulateFaces(trace.faces, trace.frames[0].coords);
    this.tris = tris;
    this.faceOfTri = faceOfTri;
    const panelPos = new THREE.BufferAttribute(new Float32Array(3 * tris.length), 3);
    const panels = new THREE.BufferGeometry();
    panels.setAttribute('position', panelPos);
    // Faces are pushed back a little so creases drawn on them stay visible.
    const paper = (colour, side) => new THREE.MeshStandardMaterial({
      color: colour, side, flatShading: true, roughness: 0.9, metalness: 0,
      polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1,
    });
    this.group.add(new THREE.Mesh(panels, paper(FRONT_COLOUR, THREE.FrontSide)));
    this.group.add(new THREE.Mesh(panels, paper(BACK_COLOUR, THREE.BackSide)));
    // Interference overlay shares the panel positions; its index selects faces.
    const overlay = new THREE.BufferGeometry();
    overlay.setAttribute('position', panelPos);
    overlay.setIndex([]);
    this.group.add(new THREE.Mesh(overlay, new THREE.MeshBasicMaterial({
      color: INTERFERENCE_COLOUR, side: THREE.DoubleSide, transparent: true, opacity: 0.6,
      polygonOffset: true, polygonOffsetFactor: 0.5, polygonOffsetUnits: 0.5,
    })));
    this.panelPos = panelPos;
    this.overlay = overlay;

    // Creases: one segment per drawn edge, coloured by its assignment (as
    // Origami Simulator, the letter and not the current sign decides).
    this.drawnEdges = [];
    trace.edges.forEach((_, e) => { if (KIND_COLOURS[trace.assignment[e]] !== undefined) this.drawnEdges.push(e); });
    const linePos = new THREE.BufferAttribute(new Float32Array(6 * this.drawnEdges.length), 3);
    const lineCol = new Float32Array(6 * this.drawnEdges.length);
    const c = new THREE.Color();
    this.drawnEdges.forEach((e, k) => {
      c.setHex(KIND_COLOURS[trace.assignment[e]]);
      lineCol.set([c.r, c.g, c.b, c.r, c.g, c.b], 6 * k);
    });
    const lines = new THREE.BufferGeometry();
    lines.setAttribute('position', linePos);
    lines.setAttribute('color', new THREE.BufferAttribute(lineCol, 3));
    this.group.add(new THREE.LineSegments(lines, new THREE.LineBasicMaterial({ vertexColors: true })));
    this.linePos = linePos;
    this.lines = lines;
    // The picked crease is drawn again on top, in green, with depth test off.
    const pick = new THREE.BufferGeometry();
    pick.setAttribute('position', new THREE.BufferAttribute(new Float32Array(6), 3));
    this.pickLine = new THREE.LineSegments(pick, new THREE.LineBasicMaterial({ color: PICK_COLOUR, depthTest: false }));
    this.pickLine.visible = false;
    this.pickLine.renderOrder = 1;
    this.group.add(this.pickLine);

    this.scene.add(this.group);
    this.updateStats();
    this.fitCamera();
  }

  // Counts what the geometry holds (not what the file says), so the test
  // compares the file against what was actually handed to WebGL.
  updateStats() {
    const drawn = {};
    const segs = this.lines.getAttribute('position').count / 2;
    for (let k = 0; k < segs; ++k) {
      const kind = this.trace.assignment[this.drawnEdges[k]];
      drawn[kind] = (drawn[kind] || 0) + 1;
    }
    this.stats = {
      creasesDrawn: drawn,
      mvbDrawn: CREASE_KINDS.reduce((s, k) => s + (drawn[k] || 0), 0),
      trianglesDrawn: this.panelPos.count / 3,
      interferingFaces: 0,
    };
  }

  // Frames the bounding sphere of every frame, viewed from above at a slant.
  fitCamera() {
    const box = new THREE.Box3();
    const v = new THREE.Vector3();
    for (const f of this.trace.frames) {
      for (let i = 0; i < f.coords.length; i += 3) box.expandByPoint(v.set(f.coords[i], f.coords[i + 1], f.coords[i + 2]));
    }
    const sphere = box.getBoundingSphere(new THREE.Sphere());
    const r = Math.max(sphere.radius, 1e-9);
    const dist = r / Math.sin(THREE.MathUtils.degToRad(this.camera.fov / 2)) * 1.05;
    const dir = new THREE.Vector3(0.45, -1, 1.3).normalize();
    this.camera.position.copy(sphere.center).addScaledVector(dir, dist);
    this.camera.near = dist / 100;
    this.camera.far = dist * 10;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(sphere.center);
    this.controls.update();
  }

  // Shows frame i; `interfering` lists faces to highlight.
  showFrame(i, interfering = []) {
    const f = this.trace.frames[i];
    this.frame = i;
    const x = f.coords;
    const pp = this.panelPos.array;
    this.tris.forEach((v, k) => { pp[3 * k] = x[3 * v]; pp[3 * k + 1] = x[3 * v + 1]; pp[3 * k + 2] = x[3 * v + 2]; });
    this.panelPos.needsUpdate = true;
    this.group.children[0].geometry.computeBoundingSphere();
    const lp = this.linePos.array;
    this.drawnEdges.forEach((e, k) => {
      const [a, b] = this.trace.edges[e];
      lp.set([x[3 * a], x[3 * a + 1], x[3 * a + 2], x[3 * b], x[3 * b + 1], x[3 * b + 2]], 6 * k);
    });
    this.linePos.needsUpdate = true;
    this.lines.computeBoundingSphere();
    const faces = new Set(interfering);
    const index = [];
    this.faceOfTri.forEach((fi, t) => { if (faces.has(fi)) index.push(3 * t, 3 * t + 1, 3 * t + 2); });
    this.overlay.setIndex(index);
    this.stats.interferingFaces = faces.size;
    this.updatePick();
    this.render();
  }

  setPicked(e) {
    this.picked = e;
    this.updatePick();
    this.render();
  }

  updatePick() {
    if (this.picked < 0) { this.pickLine.visible = false; return; }
    const x = this.trace.frames[this.frame].coords;
    const [a, b] = this.trace.edges[this.picked];
    const attr = this.pickLine.geometry.getAttribute('position');
    attr.array.set([x[3 * a], x[3 * a + 1], x[3 * a + 2], x[3 * b], x[3 * b + 1], x[3 * b + 2]]);
    attr.needsUpdate = true;
    this.pickLine.geometry.computeBoundingSphere();
    this.pickLine.visible = true;
  }

  // Screen position (CSS pixels, relative to the canvas) of a point.
  toScreen(x, y, z) {
    const p = new THREE.Vector3(x, y, z).project(this.camera);
    const r = this.canvas.getBoundingClientRect();
    return [(p.x + 1) / 2 * r.width, (1 - p.y) / 2 * r.height];
  }

  // Midpoint of edge e on screen in the current frame (used by the test).
  edgeOnScreen(e) {
    const x = this.trace.frames[this.frame].coords;
    const [a, b] = this.trace.edges[e];
    const pa = this.toScreen(x[3 * a], x[3 * a + 1], x[3 * a + 2]);
    const pb = this.toScreen(x[3 * b], x[3 * b + 1], x[3 * b + 2]);
    return [(pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2];
  }

  // The drawn edge nearest to a canvas point, within `tolerance` pixels, or
  // -1. Picking in screen space is exact for 1-pixel lines, unlike raycasting.
  pickEdge(px, py, tolerance = 8) {
    const x = this.trace.frames[this.frame].coords;
    let best = -1;
    let bestD = tolerance;
    for (const e of this.drawnEdges) {
      const [a, b] = this.trace.edges[e];
      const [ax, ay] = this.toScreen(x[3 * a], x[3 * a + 1], x[3 * a + 2]);
      const [bx, by] = this.toScreen(x[3 * b], x[3 * b + 1], x[3 * b + 2]);
      const dx = bx - ax;
      const dy = by - ay;
      const len2 = dx * dx + dy * dy;
      const t = len2 > 0 ? Math.min(1, Math.max(0, ((px - ax) * dx + (py - ay) * dy) / len2)) : 0;
      const d = Math.hypot(px - (ax + t * dx), py - (ay + t * dy));
      if (d < bestD) { bestD = d; best = e; }
    }
    return best;
  }

  render() {
    if (this.trace) this.renderer.render(this.scene, this.camera);
  }
}
