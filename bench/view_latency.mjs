// How long a maker waits in `lsolid view`: from saving the file to the page
// drawing the new skeleton or the new solid, or from opening the page to
// its first skeleton.
//
//   (cd tests/browser && npm ci)
//   node bench/view_latency.mjs LSOLID_BINARY FILE.ls N skeleton|model|open TIMES
//
// Copies FILE.ls to a temporary folder and serves it at n = N to headless
// Chromium. With `open`, opens the page TIMES times and prints how long each
// took to draw the skeleton, and when the page's scripts had run. With
// `skeleton` or `model`, opens it once, then saves the file TIMES times,
// each with another value in place of its first angle (`δ=…`), waiting for
// the page's data-skeleton or data-model attribute to change; the pauses
// between saves vary so that some saves land while a build is in flight.
// Prints each wait and the median, in milliseconds.
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { startBrowser, startView } from '../tests/browser/view_page.mjs';

const [binary, source, n = '7', what = 'skeleton', count = '9'] =
  process.argv.slice(2);
if (!source || !['skeleton', 'model', 'open'].includes(what)) {
  console.error('usage: view_latency.mjs LSOLID_BINARY FILE.ls N skeleton|model|open TIMES');
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

// Opens the page `times` times, each time waiting for its first skeleton.
async function opening(times) {
  const waits = [];
  for (let i = 0; i < times; ++i) {
    const page = await browser.newPage();
    const start = Date.now();
    await page.goto(view.url);
    await page.waitForFunction(() => document.body.dataset.skeleton !== '0', null,
      { polling: 'raf', timeout: 600000 });
    waits.push(Date.now() - start);
    const ran = await page.evaluate(() => Math.round(
      performance.getEntriesByType('navigation')[0].domContentLoadedEventEnd));
    console.log(`open -> skeleton drawn ${waits.at(-1)} ms (scripts run at ${ran} ms)`);
    await page.close();
  }
  return waits;
}

// Saves the file `times` times, each time waiting for the page's `attribute`.
async function saving(times, attribute) {
  const page = await browser.newPage();
  await page.goto(view.url);
  await page.waitForFunction((a) => document.body.dataset[a] !== '0', attribute,
    { timeout: 600000 });
  const waits = [];
  for (let i = 0; i < times; ++i) {
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
  console.log(`save -> ${attribute} drawn (ms): ${waits.join(' ')}`);
  return waits;
}

try {
  const waits = what === 'open' ? await opening(Number(count))
    : await saving(Number(count), what);
  const sorted = [...waits].sort((a, b) => a - b);
  console.log(`median ${sorted[Math.floor(sorted.length / 2)]} ms`);
} finally {
  await browser.close();
  await view.stop();
  fs.rmSync(folder, { recursive: true, force: true });
}
