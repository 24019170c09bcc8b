// What the web tests and the benchmark page share: a static server for an exported folder and
// Debian's chromium driven headless through puppeteer-core (WebGL2 on SwiftShader; nothing is
// downloaded). GFIELD_CHROMIUM names another browser binary.

import { createServer } from 'node:http';
import { readFile } from 'node:fs/promises';
import { extname, join, normalize } from 'node:path';
import puppeteer from 'puppeteer-core';

const TYPES = { '.html': 'text/html', '.js': 'text/javascript', '.json': 'application/json',
                '.gz': 'application/gzip' };

/**
 * Serves folder `root` on 127.0.0.1, and folder mounts[PREFIX] under /PREFIX/; resolves to
 * { url, close() }.
 */
export function serve(root, mounts = {}) {
  const server = createServer(async (request, response) => {
    let path = normalize(decodeURIComponent(new URL(request.url, 'http://x').pathname));
    let base = root;
    for (const [prefix, folder] of Object.entries(mounts))
      if (path.startsWith(`/${prefix}/`)) [base, path] = [folder, path.slice(prefix.length + 1)];
    try {
      const body = await readFile(join(base, path.endsWith('/') ? `${path}index.html` : path));
      response.writeHead(200, { 'content-type': TYPES[extname(path)] ?? 'text/plain' });
      response.end(body);
    } catch {
      response.writeHead(404);
      response.end();
    }
  });
  return new Promise((resolve) => server.listen(0, '127.0.0.1', () => resolve({
    url: `http://127.0.0.1:${server.address().port}/`,
    close: () => new Promise((done) => { server.close(done); server.closeAllConnections(); }),
  })));
}

/** Debian's chromium, headless, WebGL2 on SwiftShader. */
export function launch() {
  return puppeteer.launch({
    executablePath: process.env.GFIELD_CHROMIUM || '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--enable-unsafe-swiftshader', '--use-angle=swiftshader',
           '--ignore-gpu-blocklist', '--disable-dev-shm-usage'],
  });
}

/**
 * Opens `url` in a new page of `browser` with a viewport of width x height, waits until the
 * player's title says "ready" or "error: ..." (at most `timeout` ms) and returns
 * { title, seconds, png } (png: the viewport's top-left width x height, null on error).
 */
export async function openPlayer(browser, url, width, height, timeout = 120000) {
  const page = await browser.newPage();
  await page.setViewport({ width, height, deviceScaleFactor: 1 });
  const start = performance.now();
  await page.goto(url);
  await page.waitForFunction(() => document.title === 'ready' || document.title.startsWith('error'),
                             { timeout, polling: 50 });
  const seconds = (performance.now() - start) / 1000;
  const title = await page.title();
  const png = title === 'ready'
      ? Buffer.from(await page.screenshot({ clip: { x: 0, y: 0, width, height } }))
      : null;
  const text = await page.evaluate(() => document.body.innerText);
  await page.close();
  return { title, seconds, png, text };
}
