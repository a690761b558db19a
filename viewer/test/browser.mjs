// Shared by the end-to-end test and the main job's screenshot: finds
// Debian's chromium and launches it headless through playwright-core, with
// WebGL on SwiftShader (software) since CI has no GPU.
import fs from 'node:fs';
import { chromium } from 'playwright-core';

export function findChromium() {
  const candidates = [process.env.CHROMIUM, '/usr/bin/chromium', '/usr/bin/chromium-browser', '/usr/lib/chromium/chromium'];
  return candidates.find((p) => p && fs.existsSync(p)) || null;
}

export async function launch(executablePath) {
  return chromium.launch({
    executablePath,
    headless: true,
    // --no-sandbox: CI runs as root, where chromium's sandbox refuses to start.
    args: ['--no-sandbox', '--use-gl=angle', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist'],
  });
}

// Opens the built viewer's index.html from disk and waits until it is ready.
export async function openViewer(browser, dir, query = '', size = { width: 1200, height: 800 }) {
  const page = await browser.newPage({ viewport: size });
  const errors = [];
  page.on('pageerror', (err) => errors.push(`page error: ${err.message}`));
  page.on('console', (msg) => { if (msg.type() === 'error') errors.push(`console error: ${msg.text()}`); });
  const url = `file://${fs.realpathSync(dir)}/index.html${query}`;
  await page.goto(url);
  try {
    await page.waitForSelector('#view[data-ready="true"]', { timeout: 30000 });
  } catch (err) {
    throw new Error(`viewer did not become ready at ${url}: ${errors.join('; ') || err.message}`);
  }
  return { page, errors };
}
