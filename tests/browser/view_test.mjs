// `lsolid view`'s page as a maker uses it, in Chromium: the model drawn,
// the report, a save rebuilding it, an error shown at its line, a control
// changing the command line and the model, a download that checks.
//
//   node tests/browser/view_test.mjs LSOLID_BINARY SOURCE_DIR
//
// (ctest runs it as Browser.ViewPage; tests/browser/package.json names the
// one package it needs, installed by `npm ci --prefix tests/browser`.)
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { startBrowser, startView } from './view_page.mjs';

const lsolid = process.argv[2] && path.resolve(process.argv[2]);
const source = process.argv[3] && path.resolve(process.argv[3]);
if (!lsolid || !source) {
  console.error('usage: view_test.mjs LSOLID_BINARY SOURCE_DIR');
  process.exit(2);
}

const tree = (n) =>
  `n = ${n}\nδ = 25\nwidth: 1\nsize: 40mm\nω: A\nA → F[+A][-A]FA\n`;

const folder = fs.mkdtempSync(path.join(os.tmpdir(), 'lsolid-browser-'));
const file = path.join(folder, 'tree.ls');
let view;
let browser;
let page;
const consoleErrors = [];

before(async () => {
  fs.writeFileSync(file, tree(2));
  view = await startView(lsolid, folder, 'tree.ls');
  browser = await startBrowser();
  const context = await browser.newContext({
    acceptDownloads: true, viewport: { width: 1200, height: 800 } });
  page = await context.newPage();
  page.on('console', (m) => {
    if (m.type() === 'error') consoleErrors.push(m.text());
  });
  page.on('pageerror', (e) => consoleErrors.push(String(e)));
  await page.goto(view.url);
});

after(async () => {
  if (browser) await browser.close();
  if (view) assert.equal(await view.stop(), 0, view.log());
  fs.rmSync(folder, { recursive: true, force: true });
});

// The model version the page shows, once it shows one past `seen`.
async function modelAfter(seen, timeout = 60000) {
  await page.waitForFunction(
    (s) => Number(document.body.dataset.model || 0) > s &&
      document.getElementById('verdict').textContent !== 'building…',
    seen, { timeout });
  return page.evaluate(() => Number(document.body.dataset.model));
}

// The canvas's pixels whose colour is clearly not a grey: the model (brown,
// green, red where it overhangs) and not the background or the bed's grid.
async function colouredPixels() {
  // The page draws what changed at its next animation frame, after the
  // model's version is set: two frames on, the model is on the canvas (on
  // a loaded machine the first test once read the canvas before).
  await page.evaluate(() => new Promise(
    (done) => requestAnimationFrame(() => requestAnimationFrame(done))));
  return page.evaluate(() => {
    const canvas = document.getElementById('canvas');
    const copy = document.createElement('canvas');
    copy.width = canvas.width;
    copy.height = canvas.height;
    const context = copy.getContext('2d');
    context.drawImage(canvas, 0, 0);
    const { data } = context.getImageData(0, 0, copy.width, copy.height);
    let count = 0;
    for (let i = 0; i < data.length; i += 4) {
      const max = Math.max(data[i], data[i + 1], data[i + 2]);
      const min = Math.min(data[i], data[i + 1], data[i + 2]);
      if (max - min > 40) ++count;
    }
    return { count, total: data.length / 4 };
  });
}

// The report's value for `name` (its <dt>).
async function reportValue(name) {
  return page.evaluate((n) => {
    for (const dt of document.querySelectorAll('#report dt')) {
      if (dt.textContent === n) return dt.nextElementSibling.textContent;
    }
    return null;
  }, name);
}

let shown = 0;

test('draws the model and says it is printable', async () => {
  shown = await modelAfter(0);
  assert.equal(await page.textContent('#verdict'), 'printable');
  assert.equal(await reportValue('pieces'), '1');
  assert.equal(await reportValue('bed'), 'fits');
  const pixels = await colouredPixels();
  // The 40 mm tree fills a good part of the view, not a speck and not all.
  assert.ok(pixels.count > pixels.total * 0.01, JSON.stringify(pixels));
  assert.ok(pixels.count < pixels.total * 0.9, JSON.stringify(pixels));
  assert.equal(await page.textContent('#command'),
    'lsolid tree.ls -o tree.stl');
  assert.equal(await page.isVisible('#error'), false);
});

test('builds the file again when it is saved', async () => {
  const before = Number(await reportValue('triangles'));
  fs.writeFileSync(file, tree(3));
  shown = await modelAfter(shown);
  const now = Number(await reportValue('triangles'));
  assert.ok(now > before, `${now} triangles after ${before}`);
  assert.equal(await page.inputValue('#n'), '3');
});

test('shows an error at its line with a caret and keeps the model', async () => {
  fs.writeFileSync(file, tree(3) + 'A → F[+A\n');
  // writeFileSync truncates the file, then writes it: the server builds a
  // change once the file has stopped changing, but a loaded machine can
  // still show the empty file's error first. The saved file's is awaited.
  await page.waitForFunction(() => {
    const error = document.querySelector('#error');
    return !error.hidden && /tree\.ls:7:/.test(error.textContent);
  }, null, { timeout: 30000 });
  const text = await page.textContent('#error');
  assert.match(text, /tree\.ls:7:\d+: error: /);
  assert.match(text, /\n\s*\^/);
  assert.equal(Number(await page.evaluate(() => document.body.dataset.model)),
    shown);
  assert.ok((await colouredPixels()).count > 0);
  fs.writeFileSync(file, tree(3));
  shown = await modelAfter(shown);
  await page.waitForSelector('#error[hidden]', { state: 'attached' });
});

test('a control changes the command line and the model', async () => {
  await page.fill('#n', '1');
  await page.dispatchEvent('#n', 'change');
  await page.waitForFunction(
    () => document.getElementById('command').textContent.includes(' -n 1 '));
  assert.equal(await page.textContent('#command'),
    'lsolid tree.ls -n 1 -o tree.stl');
  shown = await modelAfter(shown);
  assert.equal(await page.textContent('#verdict'), 'printable');
  await page.click('#reset');
  await page.waitForFunction(() =>
    document.getElementById('command').textContent ===
      'lsolid tree.ls -o tree.stl');
  shown = await modelAfter(shown);
  assert.equal(await page.inputValue('#n'), '3');
});

test('downloads the model shown, and it checks', async () => {
  const [download] = await Promise.all([
    page.waitForEvent('download'),
    page.click('#download-stl'),
  ]);
  assert.equal(download.suggestedFilename(), 'tree.stl');
  const saved = path.join(folder, 'downloaded.stl');
  await download.saveAs(saved);
  const report = JSON.parse(execFileSync(lsolid, ['check', '--json', saved],
    { encoding: 'utf8' }));
  assert.equal(report.printable, true);
  assert.equal(String(report.triangles), await reportValue('triangles'));
});

test('keeps a refused value as typed, beside its error', async () => {
  // It once snapped back to the last good value while the error named 0.
  await page.fill('#wall', '0');
  await page.dispatchEvent('#wall', 'change');
  await page.waitForSelector('#error:not([hidden])', { timeout: 30000 });
  assert.match(await page.textContent('#error'), /--wall/);
  assert.equal(await page.inputValue('#wall'), '0');
  await page.click('#reset');
  await page.waitForSelector('#error[hidden]',
    { state: 'attached', timeout: 60000 });
  shown = await modelAfter(shown);
  assert.equal(await page.inputValue('#wall'), '0.8');
});

test('keeps the downloads in view, breaks the command line between words, ' +
     'and shows overhangs from above', async () => {
  const defines = Array.from({ length: 8 },
    (_, i) => `#define LENGTH${i} ${i + 1}`).join('\n');
  fs.writeFileSync(file, defines +
    '\nn = 0\nwidth: 0.3\nsize: 40mm\nω: F(LENGTH2)[+(90)F(LENGTH1)][&(90)F(LENGTH1)]F(LENGTH0)\n');
  shown = await modelAfter(shown);
  await page.waitForFunction(
    () => document.querySelectorAll('#constants label').length === 8);
  // With a slider for each constant the downloads once fell below the fold.
  const bottom = await page.evaluate(() =>
    document.getElementById('download-scad').getBoundingClientRect().bottom);
  assert.ok(bottom <= 800, `the downloads end at ${bottom} px of 800`);
  assert.deepEqual(await page.evaluate(() => {
    const s = getComputedStyle(document.getElementById('command'));
    return [s.wordBreak, s.overflowWrap];
  }), ['normal', 'break-word']);
  // The horizontal branch overhangs: its faces show through the model.
  assert.notEqual(await reportValue('overhang'), null);
  assert.ok(Number(await page.evaluate(
    () => document.body.dataset.overhangOverlay)) > 0);
  fs.writeFileSync(file, tree(3));
  shown = await modelAfter(shown);
});

test('shows the skeleton at once, then the build\'s progress', async () => {
  // The bush of ABOP fig. 1.25 at n = 7: 3,891 segments, whose solid takes
  // minutes; its skeleton is drawn long before.
  const bushFolder = fs.mkdtempSync(path.join(os.tmpdir(), 'lsolid-bush-'));
  fs.copyFileSync(path.join(source, 'printables/abop-1.25-bush.ls'),
    path.join(bushFolder, 'bush.ls'));
  const bush = await startView(lsolid, bushFolder, 'bush.ls', ['-n', '7']);
  const other = await browser.newPage();
  try {
    await other.goto(bush.url);
    await other.waitForFunction(
      () => Number(document.body.dataset.skeleton || 0) > 0, null,
      { timeout: 30000 });
    assert.equal(await other.evaluate(() => document.body.dataset.model), '0');
    assert.equal(await other.isVisible('#progress'), true);
    assert.match(await other.textContent('#stage'), /^(skeleton|parts|union)$/);
    assert.equal(await other.textContent('#verdict'), 'building…');
    // A quick model (n = 2), then n = 7 again: its skeleton is drawn over
    // the n = 2 model, faded, while the solid is built.
    await other.fill('#n', '2');
    await other.dispatchEvent('#n', 'change');
    await other.waitForFunction(
      () => Number(document.body.dataset.model || 0) > 0 &&
        document.body.dataset.faded === '0', null, { timeout: 60000 });
    const quick = await other.evaluate(() => document.body.dataset.model);
    const skeleton = await other.evaluate(() => document.body.dataset.skeleton);
    await other.fill('#n', '7');
    await other.dispatchEvent('#n', 'change');
    await other.waitForFunction(
      (s) => document.body.dataset.skeleton !== s, skeleton, { timeout: 30000 });
    assert.equal(await other.evaluate(() => document.body.dataset.model), quick);
    assert.equal(await other.evaluate(() => document.body.dataset.faded), '1');
    assert.equal(await other.isVisible('#progress'), true);
  } finally {
    await other.close();
    assert.equal(await bush.stop(), 0, bush.log());
    fs.rmSync(bushFolder, { recursive: true, force: true });
  }
});

test('logs no error in the page', () => {
  assert.deepEqual(consoleErrors, []);
});
