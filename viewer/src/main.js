// Entry point: reads the embedded catalogue and traces (traces.js, written
// by build.mjs, so the page works from file:// without fetch), wires the
// scene and the controls, and exposes window.rigidfoldViewer for tests.
import { parseFold } from './fold.js';
import { FoldScene } from './scene.js';
import { Controls } from './ui.js';
import { frameAnnotations, jumpsTo } from './branch.js';

const data = window.RIGIDFOLD_DATA;
const view = document.getElementById('view');
const canvas = document.getElementById('canvas');
const scene = new FoldScene(canvas);
const state = { set: 0, branch: 0, frame: 0, picked: -1, trace: null, annotations: null };
const parsed = new Map(); // file -> parsed trace, parsed on first use

function currentSet() { return data.index.sets[state.set]; }
function currentBranch() { return currentSet().branches[state.branch]; }

// Publishes what the test reads as data attributes on the view.
function publish() {
  view.dataset.set = currentSet().name;
  view.dataset.branch = String(currentBranch().id);
  view.dataset.frame = String(state.frame);
  view.dataset.creasesDrawn = String(scene.stats.mvbDrawn);
  view.dataset.interferingFaces = String(scene.stats.interferingFaces);
}

function showFrame(i) {
  state.frame = Math.max(0, Math.min(i, state.trace.frames.length - 1));
  const a = state.annotations[state.frame];
  scene.showFrame(state.frame, a.interferingFaces);
  controls.showFrame(state.trace, state.frame, a, currentBranch());
  controls.showPick(state.trace, state.frame, state.picked);
  publish();
}

// keepView: another branch of the same pattern, so keep camera and pick.
function selectBranch(i, frame = 0, keepView = true) {
  state.branch = i;
  const b = currentBranch();
  if (!parsed.has(b.file)) parsed.set(b.file, parseFold(data.folds[b.file]));
  const trace = parsed.get(b.file);
  state.trace = trace;
  state.annotations = frameAnnotations(trace, b);
  const cam = scene.camera.position.clone();
  const target = scene.controls.target.clone();
  scene.setTrace(trace);
  if (keepView) {
    scene.camera.position.copy(cam);
    scene.controls.target.copy(target);
    scene.controls.update();
  } else {
    state.picked = -1;
  }
  scene.setPicked(state.picked);
  document.getElementById('branch').value = String(i);
  controls.setBranchInfo(b);
  controls.setFrameRange(trace.frames.length, frame);
  showFrame(frame);
}

function selectSet(i, branch = 0, frame = 0) {
  state.set = i;
  document.getElementById('set').value = String(i);
  controls.setBranches(currentSet(), branch, jumpsTo);
  selectBranch(branch, frame, false);
}

function pick(edge) {
  state.picked = Number.isInteger(edge) && edge >= 0 && edge < state.trace.edges.length ? edge : -1;
  scene.setPicked(state.picked);
  controls.showPick(state.trace, state.frame, state.picked);
}

const controls = new Controls({
  onSet: (i) => selectSet(i),
  onBranch: (i) => selectBranch(i, 0),
  onFrame: (i) => showFrame(i),
  onPick: pick,
  onJump: (bi, frame) => selectBranch(bi, frame),
});

// A click (not a drag of the orbit controls) picks the nearest crease.
let down = null;
canvas.addEventListener('pointerdown', (ev) => { down = [ev.clientX, ev.clientY]; });
canvas.addEventListener('pointerup', (ev) => {
  if (!down || Math.hypot(ev.clientX - down[0], ev.clientY - down[1]) > 3) return;
  const r = canvas.getBoundingClientRect();
  const e = scene.pickEdge(ev.clientX - r.left, ev.clientY - r.top);
  if (e >= 0) pick(e);
});

function fit() {
  const r = view.getBoundingClientRect();
  scene.resize(Math.max(1, Math.floor(r.width)), Math.max(1, Math.floor(r.height)));
}
window.addEventListener('resize', fit);

// Start from ?set=NAME&branch=ID&step=N|last&crease=E when given (the main job's screenshot).
function start() {
  const sets = data.index.sets;
  if (!sets.length) {
    document.getElementById('frame-title').textContent = 'no trace in this build';
    return;
  }
  const q = new URLSearchParams(window.location.search);
  const si = Math.max(0, sets.findIndex((s) => s.name === q.get('set')));
  const bi = q.has('branch') ? Math.max(0, sets[si].branches.findIndex((b) => String(b.id) === q.get('branch'))) : 0;
  controls.setSets(sets, si);
  fit();
  selectSet(si, bi, 0);
  if (q.has('step')) showFrame(q.get('step') === 'last' ? state.trace.frames.length - 1 : Number(q.get('step')));
  if (q.has('crease')) pick(Number(q.get('crease')));
  window.rigidfoldViewer = {
    ready: true,
    state,
    get stats() { return scene.stats; },
    get trace() { return state.trace; },
    edgeOnScreen: (e) => scene.edgeOnScreen(e),
    selectSet: (name, branch = 0) => selectSet(sets.findIndex((s) => s.name === name), branch),
    showFrame,
  };
  view.dataset.ready = 'true';
}

start();
