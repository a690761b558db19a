// Writes a PNG of the built viewer: node test/screenshot.mjs VIEWER_DIR OUT.png [?QUERY]
// QUERY selects what is shown (set=NAME&branch=ID&step=N|last&crease=E).
import { findChromium, launch, openViewer } from './browser.mjs';

const [dir, png, query = ''] = process.argv.slice(2);
if (!dir || !png) {
  console.error('usage: node test/screenshot.mjs VIEWER_DIR OUT.png [?set=NAME&branch=ID&step=N]');
  process.exit(2);
}
const exe = findChromium();
if (!exe) {
  console.error('viewer screenshot: no chromium found (/usr/bin/chromium, or CHROMIUM=...); run bash viewer/bootstrap_viewer.sh');
  process.exit(1);
}
const browser = await launch(exe);
try {
  const { page, errors } = await openViewer(browser, dir, query);
  await page.screenshot({ path: png });
  if (errors.length) throw new Error(errors.join('; '));
  console.log(`viewer: screenshot ${png}`);
} finally {
  await browser.close();
}
