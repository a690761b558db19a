// End-to-end test of the built viewer in headless chromium:
//   node test/e2e.mjs VIEWER_DIR [--set NAME] [--screenshot OUT.png]
// Loads a trace, moves the slider with the keyboard, and asserts on the
// rendered canvas: the image changes between the first and last frame, it
// shows red and blue creases, and the number of creases drawn equals the
// FOLD file's count of M/V/B edges (counted here from the file itself, not
// with the viewer's parser). Also checks the numbers shown (residual of the
// frame, fold angle of a picked crease) against the file, the jumps to
// located bifurcations, and the interference overlay; then writes a PNG.
// Exit 0 pass, 1 fail, 77 skip (no chromium).
import fs from 'node:fs';
import path from 'node:path';
import { findChromium, launch, openViewer } from './browser.mjs';

const args = process.argv.slice(2);
const dir = args[0];
const opt = (name) => { const i = args.indexOf(name); return i >= 0 ? args[i + 1] : undefined; };
if (!dir) {
  console.error('usage: node test/e2e.mjs VIEWER_DIR [--set NAME] [--screenshot OUT.png]');
  process.exit(2);
}
const exe = findChromium();
if (!exe) {
  console.log('SKIP Viewer.EndToEnd: no chromium found (/usr/bin/chromium; set CHROMIUM=...); install it with bash viewer/bootstrap_viewer.sh');
  process.exit(77);
}

let failures = 0;
function check(ok, what) {
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
  if (!ok) failures += 1;
}

const index = JSON.parse(fs.readFileSync(path.join(dir, 'index.json'), 'utf8'));
const readFold = (file) => JSON.parse(fs.readFileSync(path.join(dir, 'traces', file), 'utf8'));
const mvbCount = (fold) => fold.edges_assignment.filter((k) => k === 'M' || k === 'V' || k === 'B').length;

// Pixel statistics of the WebGL canvas, computed in the page (the canvas is
// created with preserveDrawingBuffer, so the last render can be read back).
// Snapshots stay in the page; only counts come back.
async function snapshot(page, name) {
  return page.evaluate((name) => {
    const c = document.getElementById('canvas');
    const t = document.createElement('canvas');
    t.width = c.width;
    t.height = c.height;
    const g = t.getContext('2d');
    g.drawImage(c, 0, 0);
    const d = g.getImageData(0, 0, t.width, t.height).data;
    window.__snaps = window.__snaps || {};
    window.__snaps[name] = d;
    const n = { pixels: t.width * t.height, nonBackground: 0, red: 0, blue: 0, orange: 0 };
    for (let i = 0; i < d.length; i += 4) {
      const [r, gg, b] = [d[i], d[i + 1], d[i + 2]];
      if (r < 250 || gg < 250 || b < 250) n.nonBackground += 1;
      if (r > 180 && gg < 70 && b < 70) n.red += 1;
      if (b > 180 && r < 70 && gg < 70) n.blue += 1;
      // The overlay's orange over grey paper; neither crease red nor the back's tan.
      if (r > 180 && r - b > 90 && gg < r - 30 && gg > b + 20) n.orange += 1;
    }
    return n;
  }, name);
}

async function differing(page, a, b) {
  return page.evaluate(([a, b]) => {
    const x = window.__snaps[a];
    const y = window.__snaps[b];
    let n = 0;
    for (let i = 0; i < x.length; i += 4) {
      if (Math.abs(x[i] - y[i]) + Math.abs(x[i + 1] - y[i + 1]) + Math.abs(x[i + 2] - y[i + 2]) > 24) n += 1;
    }
    return n;
  }, [a, b]);
}

const dataset = (page) => page.evaluate(() => ({ ...document.getElementById('view').dataset }));

const t0 = Date.now();
const browser = await launch(exe);
try {
  const setName = opt('--set') || index.sets[0].name;
  const set = index.sets.find((s) => s.name === setName);
  if (!set) throw new Error(`no set ${setName} in ${dir}/index.json`);
  // The longest branch: the most frames to move through.
  const branch = set.branches.reduce((a, b) => (b.frames > a.frames ? b : a));
  const fold = readFold(branch.file);
  const { page, errors } = await openViewer(browser, dir, `?set=${encodeURIComponent(set.name)}&branch=${branch.id}`);
  const webgl = await page.evaluate(() => !!document.getElementById('canvas').getContext('webgl2'));
  check(webgl, 'WebGL context available (SwiftShader)');

  let ds = await dataset(page);
  check(ds.set === set.name && ds.branch === String(branch.id), `loaded ${set.name} branch ${branch.id} (${branch.frames} frames)`);
  check(Number(ds.creasesDrawn) === mvbCount(fold),
    `creases drawn ${ds.creasesDrawn} = M/V/B edges in ${branch.file} ${mvbCount(fold)}`);

  // Move the slider the way a user does: focus it, Home, then End.
  const slider = page.locator('#step');
  await slider.focus();
  await page.keyboard.press('Home');
  ds = await dataset(page);
  check(ds.frame === '0', `Home puts the slider at frame 0 (got ${ds.frame})`);
  const first = await snapshot(page, 'first');
  check(first.nonBackground > 0.01 * first.pixels, `frame 0 drawn (${first.nonBackground} of ${first.pixels} pixels not background)`);
  await page.keyboard.press('ArrowRight');
  ds = await dataset(page);
  check(ds.frame === '1', `ArrowRight moves to frame 1 (got ${ds.frame})`);
  const second = await snapshot(page, 'second');
  await page.keyboard.press('End');
  ds = await dataset(page);
  const last = branch.frames - 1;
  check(ds.frame === String(last), `End moves to the last frame ${last} (got ${ds.frame})`);
  const end = await snapshot(page, 'end');
  const changed = await differing(page, 'first', 'end');
  check(changed > 0.005 * end.pixels, `pixels change between frame 0 and ${last}: ${changed} pixels`);
  check(second.nonBackground > 0 && end.nonBackground > 0.01 * end.pixels, `last frame drawn (${end.nonBackground} pixels)`);
  check(first.red > 0 && first.blue > 0, `red (mountain) and blue (valley) creases on screen: ${first.red} red, ${first.blue} blue pixels`);

  // The numbers of the last frame: its residual as the file gives it.
  const frameObj = fold.file_frames[last - 1];
  const shownResidual = await page.locator('#residual').getAttribute('data-value');
  check(Number(shownResidual) === frameObj['rigidfold:max_residual_rad'],
    `residual shown ${shownResidual} = file's rigidfold:max_residual_rad ${frameObj['rigidfold:max_residual_rad']}`);

  // Pick a crease by clicking it, in a middle frame (not flat, not folded
  // onto itself), and read its fold angle against the file.
  const mid = Math.max(1, Math.floor(last / 2));
  await page.evaluate((m) => window.rigidfoldViewer.showFrame(m), mid);
  const e = branch.drivingCrease ?? fold.edges_assignment.findIndex((k) => k === 'M' || k === 'V');
  const [x, y] = await page.evaluate((e) => window.rigidfoldViewer.edgeOnScreen(e), e);
  await page.locator('#canvas').click({ position: { x, y } });
  const picked = await page.locator('#crease').inputValue();
  const shownAngle = await page.locator('#pick-info').getAttribute('data-fold-angle-deg');
  const fileAngle = fold.file_frames[mid - 1].edges_foldAngle[Number(picked)];
  check(picked === String(e), `click on crease ${e} picks it (picked ${picked})`);
  check(Number(shownAngle) === fileAngle, `fold angle shown ${shownAngle} deg = file's edges_foldAngle ${fileAngle}`);

  // Interference overlay: a branch with an interference event at its end.
  const hit = set.branches.find((b) => (b.events || []).some((ev) => ev.kind === 'interference' && ev.step === b.frames - 1));
  if (hit) {
    await page.locator('#branch').selectOption(String(set.branches.indexOf(hit)));
    await slider.focus();
    await page.keyboard.press('End');
    ds = await dataset(page);
    const shot = await snapshot(page, 'interference');
    check(Number(ds.interferingFaces) > 0 && shot.orange > 0,
      `branch ${hit.id} last frame: ${ds.interferingFaces} panels in interference highlighted (${shot.orange} orange pixels)`);
  } else {
    console.log(`note: no branch of ${set.name} ends in an interference event; overlay not checked`);
  }

  // Jump to a located bifurcation: the branch and frame shown must be one
  // that arrives at or leaves from that point in the check summary.
  const jump = page.locator('button.jump').first();
  if ((set.points || []).some((p) => p.kind === 'bifurcation') && await jump.count()) {
    const point = Number(await jump.getAttribute('data-point'));
    await jump.click();
    ds = await dataset(page);
    const b = set.branches.find((bb) => String(bb.id) === ds.branch);
    const ok = b && ((b.toPoint === point && ds.frame === String(b.frames - 1)) || (b.fromPoint === point && ds.frame === String(Math.min(1, b.frames - 1))));
    check(ok, `jump to bifurcation point ${point} shows branch ${ds.branch} frame ${ds.frame}`);
  } else {
    console.log(`note: no located bifurcation in ${set.name}; jumps not checked`);
  }

  // Every other set: selecting it through the menu draws its file's creases.
  for (let i = 0; i < index.sets.length; ++i) {
    const s = index.sets[i];
    if (s.name === set.name) continue;
    await page.locator('#set').selectOption(String(i));
    ds = await dataset(page);
    const f = readFold(s.branches[0].file);
    check(ds.set === s.name && Number(ds.creasesDrawn) === mvbCount(f),
      `set ${s.name}: creases drawn ${ds.creasesDrawn} = M/V/B edges ${mvbCount(f)}`);
  }

  // Back to the tested branch at its last frame for the screenshot.
  await page.locator('#set').selectOption(String(index.sets.indexOf(set)));
  await page.locator('#branch').selectOption(String(set.branches.indexOf(branch)));
  await slider.focus();
  await page.keyboard.press('End');
  const png = opt('--screenshot');
  if (png) {
    await page.screenshot({ path: png });
    check(fs.statSync(png).size > 10000, `screenshot written: ${png} (${fs.statSync(png).size} bytes)`);
  }
  check(errors.length === 0, `no page errors${errors.length ? `: ${errors.join('; ')}` : ''}`);
} catch (err) {
  check(false, err.stack || String(err));
} finally {
  await browser.close();
}
console.log(`${failures === 0 ? 'PASS' : 'FAILED'} (${failures} failure(s), ${((Date.now() - t0) / 1000).toFixed(1)} s in the browser)`);
process.exit(failures === 0 ? 0 : 1);
