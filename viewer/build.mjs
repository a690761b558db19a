// Builds the self-contained viewer folder:
//   node build.mjs OUT_DIR [TRACE.fold | TRACE_SUMMARY.json | CHECK.json ...]
// writes OUT_DIR/index.html, viewer.js (three.js and src/ bundled by
// esbuild), traces/ (the FOLD and JSON files as given), index.json (the
// catalogue, see src/catalogue.js) and traces.js, which embeds the catalogue
// and every FOLD so the page works from file:// (no fetch) as well as from
// any static server. Nothing is fetched at run time.
import { build } from 'esbuild';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { buildCatalogue } from './src/catalogue.js';

const here = path.dirname(fileURLToPath(import.meta.url));
const [outDir, ...inputs] = process.argv.slice(2);
if (!outDir) {
  console.error('usage: node build.mjs OUT_DIR [TRACE.fold | SUMMARY.json ...]');
  process.exit(2);
}

function readJson(file) {
  try {
    return JSON.parse(fs.readFileSync(file, 'utf8'));
  } catch (err) {
    console.error(`viewer build: ${file}: ${err.message}`);
    process.exit(2);
  }
}

// Writes to a temporary name, then renames: no partial file on failure.
function writeAtomic(file, text) {
  fs.writeFileSync(`${file}.tmp`, text);
  fs.renameSync(`${file}.tmp`, file);
}

const folds = [];
const summaries = [];
const used = new Set();
for (const file of inputs) {
  const json = readJson(file);
  if (file.endsWith('.fold')) {
    const name = path.basename(file);
    if (used.has(name)) {
      console.error(`viewer build: two traces named ${name}; give them different --out names`);
      process.exit(2);
    }
    used.add(name);
    folds.push({ file: name, source: file, fold: json });
  } else {
    summaries.push(json);
  }
}

fs.mkdirSync(path.join(outDir, 'traces'), { recursive: true });
const catalogue = buildCatalogue(folds, summaries);
for (const file of inputs) fs.copyFileSync(file, path.join(outDir, 'traces', path.basename(file)));
writeAtomic(path.join(outDir, 'index.json'), `${JSON.stringify(catalogue, null, 1)}\n`);
const embedded = { index: catalogue, folds: Object.fromEntries(folds.map((f) => [f.file, f.fold])) };
writeAtomic(path.join(outDir, 'traces.js'), `window.RIGIDFOLD_DATA = ${JSON.stringify(embedded)};\n`);

await build({
  entryPoints: [path.join(here, 'src', 'main.js')],
  bundle: true,
  format: 'iife',
  minify: true,
  target: 'es2020',
  outfile: path.join(outDir, 'viewer.js'),
  logLevel: 'warning',
});
fs.copyFileSync(path.join(here, 'index.html'), path.join(outDir, 'index.html'));
const n = catalogue.sets.reduce((s, x) => s + x.branches.length, 0);
console.log(`viewer: ${catalogue.sets.length} pattern(s), ${n} branch trace(s) in ${path.join(outDir, 'index.html')}`);
