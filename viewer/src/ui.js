// The page's controls: pattern and branch selection, the step slider and
// play button, jumps to located points, the numbers of the frame and of the
// picked crease. Reads and writes only the DOM of index.html; every change
// goes through the callbacks the main module gives.

const $ = (id) => document.getElementById(id);
const fmt = (x, digits = 6) => (x === null || x === undefined ? 'not in file' : Number(x).toPrecision(digits));
const esc = (s) => String(s).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' }[c]));

export class Controls {
  // callbacks: { onSet(i), onBranch(i), onFrame(i), onPick(edge), onJump(branchIndex, frame) }
  constructor(callbacks) {
    this.cb = callbacks;
    this.playing = null;
    $('set').addEventListener('change', (ev) => this.cb.onSet(Number(ev.target.value)));
    $('branch').addEventListener('change', (ev) => this.cb.onBranch(Number(ev.target.value)));
    $('step').addEventListener('input', (ev) => this.cb.onFrame(Number(ev.target.value)));
    $('crease').addEventListener('change', (ev) => {
      const v = ev.target.value.trim();
      this.cb.onPick(v === '' ? -1 : Number(v));
    });
    $('play').addEventListener('click', () => this.togglePlay());
  }

  setSets(sets, selected) {
    $('set').innerHTML = sets.map((s, i) => `<option value="${i}">${esc(s.name)}</option>`).join('');
    $('set').value = String(selected);
  }

  // Shows the set's branches and, when the check summary is there, its
  // located points with a jump per branch arriving or leaving.
  setBranches(set, selected, jumpsTo) {
    $('branch').innerHTML = set.branches.map((b, i) => {
      const ends = b.fromPoint !== undefined ? `, point ${b.fromPoint} to ${b.toPoint ?? 'open end'}` : '';
      return `<option value="${i}">branch ${b.id ?? '?'} (${b.frames - 1} steps${ends})</option>`;
    }).join('');
    $('branch').value = String(selected);
    $('set-info').innerHTML = [
      set.title && esc(set.title),
      set.model && `model: ${esc(set.model)}`,
      set.verdict && `verdict: ${esc(set.verdict)}`,
      set.note && esc(set.note),
    ].filter(Boolean).join('<br>');
    // Only bifurcations get jumps: every branch leaves the flat state, so
    // its list would be the branch menu again.
    const pts = (set.points || []).filter((p) => p.kind === 'bifurcation');
    const box = $('points');
    if (!set.points) {
      box.innerHTML = '<i>no check summary given: bifurcations unknown</i>';
      return;
    }
    if (pts.length === 0) {
      box.innerHTML = `<i>no bifurcation located (${set.points.length} point${set.points.length === 1 ? '' : 's'} listed by check: ${set.points.map((p) => esc(p.kind.split(':')[0])).join(', ')})</i>`;
      return;
    }
    box.innerHTML = '';
    for (const p of pts) {
      const div = document.createElement('div');
      div.className = 'point';
      const where = p.parameterCrease !== undefined ? `crease ${p.parameterCrease} at ${fmt(p.parameterDeg, 8)} deg` : '';
      div.innerHTML = `<b>point ${p.point}</b> ${esc(p.kind)} ${where}<br>error bound ${fmt(p.boundRad, 3)} rad, kernel dimension ${p.kernelDimension}, ${p.tangentLines} tangent lines<br>`;
      for (const j of jumpsTo(set, p.point)) {
        const btn = document.createElement('button');
        btn.textContent = j.label;
        btn.className = 'jump';
        btn.dataset.point = String(p.point);
        btn.addEventListener('click', () => this.cb.onJump(j.branchIndex, j.frame));
        div.appendChild(btn);
      }
      box.appendChild(div);
    }
  }

  setBranchInfo(branch) {
    const rows = [];
    if (branch.stoppedBy) rows.push(`stopped by: ${esc(branch.stoppedBy)}`);
    if (branch.drivingCrease !== undefined) rows.push(`driving crease ${branch.drivingCrease}`);
    if (branch.maxResidual !== undefined) rows.push(`max residual ${fmt(branch.maxResidual, 3)} rad`);
    $('branch-info').innerHTML = rows.join('<br>') || '<i>no trace summary given</i>';
  }

  setFrameRange(count, frame) {
    $('step').max = String(count - 1);
    $('step').value = String(frame);
  }

  // The numbers of the shown frame: title, residual, mismatch, events.
  showFrame(trace, frame, annotation, branch) {
    const f = trace.frames[frame];
    $('step').value = String(frame);
    $('step-label').textContent = `${frame} / ${trace.frames.length - 1}`;
    $('frame-title').textContent = f.title;
    $('residual').textContent = f.isKey ? 'key frame (crease pattern)' : `${fmt(f.residualRad, 4)} rad`;
    $('residual').dataset.value = f.residualRad === null ? '' : String(f.residualRad);
    $('mismatch').textContent = f.isKey ? '' : fmt(f.mismatch, 4);
    if (branch && branch.drivingCrease !== undefined && f.foldAngleDeg) {
      $('drive').textContent = `crease ${branch.drivingCrease} at ${fmt(f.foldAngleDeg[branch.drivingCrease], 8)} deg`;
    } else {
      $('drive').textContent = '';
    }
    // Grouped by kind: a flat-folded step can have an event on every crease.
    const byKind = new Map();
    for (const e of annotation.events) {
      if (!byKind.has(e.kind)) byKind.set(e.kind, []);
      byKind.get(e.kind).push(e.edge);
    }
    const ev = [...byKind].map(([kind, edges]) => `${kind.replace('_', ' ')}: crease${edges.length > 1 ? 's' : ''} ${edges.join(', ')}`);
    if (annotation.interferingFaces.length) ev.push(`interfering panels: ${annotation.interferingFaces.join(', ')}`);
    ev.push(...annotation.notes);
    $('events').innerHTML = ev.map(esc).join('<br>') || '<i>none</i>';
  }

  // The picked crease's number: its fold angle in the shown frame.
  showPick(trace, frame, edge) {
    const box = $('pick-info');
    if (edge < 0 || edge >= trace.edges.length) {
      $('crease').value = '';
      box.textContent = 'click a crease, or type its index';
      box.dataset.foldAngleDeg = '';
      return;
    }
    $('crease').value = String(edge);
    const f = trace.frames[frame];
    const rho = f.foldAngleDeg ? f.foldAngleDeg[edge] : (f.isKey ? 0 : null);
    const [a, b] = trace.edges[edge];
    box.textContent = `crease ${edge} (${trace.assignment[edge]}, vertices ${a}-${b}): fold angle ${rho === null ? 'not in file' : `${fmt(rho, 10)} deg`}`;
    box.dataset.foldAngleDeg = rho === null ? '' : String(rho);
  }

  togglePlay() {
    if (this.playing) {
      clearInterval(this.playing);
      this.playing = null;
      $('play').textContent = 'play';
      return;
    }
    $('play').textContent = 'pause';
    this.playing = setInterval(() => {
      const s = $('step');
      const next = Number(s.value) >= Number(s.max) ? 0 : Number(s.value) + 1;
      this.cb.onFrame(next);
    }, 80);
  }
}
