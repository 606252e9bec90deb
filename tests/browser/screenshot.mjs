// A picture of `lsolid view` for the documentation:
//
//   node tests/browser/screenshot.mjs LSOLID_BINARY FILE.ls OUT.png [options…]
//
// opens FILE.ls in the viewer (options as `lsolid view` takes them), waits
// for the model and saves the page as OUT.png.
import path from 'node:path';
import { startBrowser, startView } from './view_page.mjs';

const [binary, file, out, ...options] = process.argv.slice(2);
if (!out) {
  console.error('usage: screenshot.mjs LSOLID_BINARY FILE.ls OUT.png [options…]');
  process.exit(2);
}
const view = await startView(path.resolve(binary), path.dirname(path.resolve(file)),
  path.basename(file), options);
const browser = await startBrowser();
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 760 } });
  await page.goto(view.url);
  await page.waitForFunction(() => Number(document.body.dataset.model || 0) > 0 &&
    document.getElementById('verdict').textContent !== 'building…',
  null, { timeout: 600000 });
  await page.waitForTimeout(500);
  await page.screenshot({ path: out });
} finally {
  await browser.close();
  await view.stop();
}
