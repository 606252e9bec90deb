// How long a maker waits in `lsolid view`: from saving the file to the page
// drawing the new skeleton or the new solid.
//
//   (cd tests/browser && npm ci)
//   node bench/view_latency.mjs LSOLID_BINARY FILE.ls N skeleton|model SAVES
//
// copies FILE.ls to a temporary folder, opens it in the viewer at n = N in
// headless Chromium, then saves it SAVES times, each with another value in
// place of its first angle (`δ=…`), waiting for the page's data-skeleton
// or data-model attribute to change; the pauses between saves vary so that
// some saves land while a build is in flight. Prints each wait and the
// median, in milliseconds.
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { startBrowser, startView } from '../tests/browser/view_page.mjs';

const [binary, source, n = '7', what = 'skeleton', count = '9'] =
  process.argv.slice(2);
if (!source || !['skeleton', 'model'].includes(what)) {
  console.error('usage: view_latency.mjs LSOLID_BINARY FILE.ls N skeleton|model SAVES');
  process.exit(2);
}
const folder = fs.mkdtempSync(path.join(os.tmpdir(), 'lsolid-view-latency-'));
const file = path.join(folder, path.basename(source));
const original = fs.readFileSync(source, 'utf8');
const angle = /δ\s*=\s*([0-9.]+)/.exec(original);
if (!angle) {
  console.error(`${source}: no 'δ = angle' to change`);
  process.exit(2);
}
fs.writeFileSync(file, original);
const view = await startView(path.resolve(binary), folder, path.basename(file), ['-n', n]);
const browser = await startBrowser();
try {
  const page = await browser.newPage();
  await page.goto(view.url);
  const attribute = what;
  await page.waitForFunction((a) => document.body.dataset[a] !== '0', attribute,
    { timeout: 600000 });
  const waits = [];
  for (let i = 0; i < Number(count); ++i) {
    const before = await page.evaluate((a) => document.body.dataset[a], attribute);
    const changed = original.replace(angle[0], angle[0].replace(angle[1],
      String(Number(angle[1]) - 2.5 + i * 0.5)));
    const start = Date.now();
    fs.writeFileSync(file, changed);
    await page.waitForFunction(([a, b]) => document.body.dataset[a] !== b,
      [attribute, before], { timeout: 600000 });
    waits.push(Date.now() - start);
    await page.waitForTimeout(300 + (i % 3) * 700);
  }
  const sorted = [...waits].sort((a, b) => a - b);
  console.log(`save -> ${what} drawn (ms): ${waits.join(' ')}; ` +
    `median ${sorted[Math.floor(sorted.length / 2)]}`);
} finally {
  await browser.close();
  await view.stop();
  fs.rmSync(folder, { recursive: true, force: true });
}
