// `lsolid view` and Debian's Chromium, started for a test or a screenshot:
// the server on a free port, the browser headless with WebGL drawn by
// SwiftShader (no GPU needed), one page open on the server.
import { spawn } from 'node:child_process';
import net from 'node:net';
import { chromium } from 'playwright-core';

export const chromiumPath = process.env.LSOLID_CHROMIUM || '/usr/bin/chromium';

// A port no one listens on now.
async function freePort() {
  return new Promise((resolve, reject) => {
    const server = net.createServer();
    server.on('error', reject);
    server.listen(0, '127.0.0.1', () => {
      const { port } = server.address();
      server.close(() => resolve(port));
    });
  });
}

// Starts `lsolid view file options…` in `folder`; resolves once it answers.
export async function startView(lsolid, folder, file, options = []) {
  const port = await freePort();
  const child = spawn(lsolid, ['view', file, '--port', String(port), ...options],
    { cwd: folder, stdio: ['ignore', 'pipe', 'pipe'] });
  let log = '';
  child.stdout.on('data', (d) => { log += d; });
  child.stderr.on('data', (d) => { log += d; });
  const url = `http://127.0.0.1:${port}/`;
  for (let i = 0; i < 200; ++i) {
    try {
      const r = await fetch(url + 'status');
      if (r.ok) {
        return {
          url, child, log: () => log,
          stop: () => new Promise((resolve) => {
            if (child.exitCode !== null) return resolve(child.exitCode);
            child.once('exit', (code) => resolve(code));
            child.kill('SIGINT');
          }),
        };
      }
    } catch {
      // not listening yet
    }
    if (child.exitCode !== null) break;
    await new Promise((r) => setTimeout(r, 50));
  }
  child.kill('SIGKILL');
  throw new Error(`lsolid view did not start:\n${log}`);
}

// Chromium, headless, drawing WebGL in software.
export async function startBrowser() {
  return chromium.launch({
    executablePath: chromiumPath,
    headless: true,
    args: ['--no-sandbox', '--use-angle=swiftshader',
      '--enable-unsafe-swiftshader', '--disable-background-networking',
      '--disable-component-update', '--no-first-run'],
  });
}
