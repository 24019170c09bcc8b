// The web benchmark (not a test): ms per frame of the player's three methods on exported scenes
// in Debian's chromium (SwiftShader here), same run: the geometry field, gfield's BVH and
// three-mesh-bvh's (both exact; the same shaders but for how a ray meets a mesh). Prints a
// Markdown table.
//
//   node tools/bench.mjs [--size WxH] [--depth N] [--frames N] EXPORT_DIR...
//
// Each cell: the median of N frames drawn one after another after a first one (shader
// compilation), min-max in brackets; then field / three-mesh-bvh, and three-mesh-bvh's BVH
// build in the page (ms) and its texture bytes. A second table: each method's work in one
// counting frame (FieldRenderer.countWork).

import { launch, serve } from './browser.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const at = args.indexOf(name);
  return at < 0 ? fallback : args.splice(at, 2)[1];
};
const size = option('--size', '256x256');
const depth = option('--depth', '4');
const frames = Number(option('--frames', '5'));
const [width, height] = size.split('x').map(Number);
if (args.length === 0 || !(width > 0 && height > 0) || !(frames > 0)) {
  console.error('usage: node tools/bench.mjs [--size WxH] [--depth N] [--frames N] EXPORT_DIR...');
  process.exit(2);
}

const browser = await launch();
const median = (v) => [...v].sort((a, b) => a - b)[v.length >> 1];

// ms per frame of `method` on the export served at `url`: { median, min, max, renderer, peer }
// (peer: three-mesh-bvh's version, build ms and bytes, for that method).
async function time(url, method) {
  const page = await browser.newPage();
  await page.setViewport({ width, height });
  await page.goto(`${url}index.html?ui=0&size=${size}&depth=${depth}&method=${method}`);
  await page.waitForFunction(() => document.title === 'ready' || document.title.startsWith('error'),
                             { timeout: 300000 });
  const title = await page.title();
  if (title !== 'ready') throw new Error(`${url}: ${title}`);
  const ms = await page.evaluate((n) => Array.from({ length: n }, () => window.gfield.frame()), frames);
  const renderer = await page.evaluate(() => window.gfield.rendererName);
  const peer = await page.evaluate(() => window.gfield.threeMeshBvh());
  const work = await page.evaluate(() => window.gfield.countWork());
  await page.close();
  return { median: median(ms), min: Math.min(...ms), max: Math.max(...ms), renderer, peer, work };
}

const rows = [];
const workRows = [];
let renderer = '';
let version = '';
for (const dir of args) {
  const server = await serve(dir);
  try {
    const field = await time(server.url, 'field');
    const bvh = await time(server.url, 'bvh');
    const peer = await time(server.url, 'three-mesh-bvh');
    renderer = field.renderer;
    version = peer.peer.version;
    const name = dir.replace(/\/$/, '').split('/').pop();
    const cell = (t) => `${t.median.toFixed(1)} (${t.min.toFixed(1)}-${t.max.toFixed(1)})`;
    rows.push(`| ${name} | ${cell(field)} | ${cell(bvh)} | ` +
              `${cell(peer)} | ${(field.median / peer.median).toFixed(2)} | ` +
              `${peer.peer.buildMs.toFixed(0)} ms, ${(peer.peer.bytes / 2 ** 20).toFixed(1)} MiB |`);
    const walk = (w) => `${w.per_traversal.nodes.toFixed(1)} nodes, ` +
                        `${w.per_traversal.triangles.toFixed(1)} triangles`;
    const f = field.work.per_lookup;
    workRows.push(`| ${name} | ${field.work.totals.lookups} | ` +
                  `${f.field_fetches.toFixed(1)} + ${f.image_fetches.toFixed(1)}, ` +
                  `${f.newton_steps.toFixed(1)} Newton | ${walk(bvh.work)} | ${walk(peer.work)} |`);
  } finally {
    await server.close();
  }
}
await browser.close();
console.log(`ms per frame, ${size}, depth ${depth}, refined lookup, median of ${frames} (min-max); ` +
            `three-mesh-bvh ${version}; ${renderer}\n`);
console.log('| export | field | gfield BVH | three-mesh-bvh | field / three-mesh-bvh | ' +
            'three-mesh-bvh build, textures |\n|---|---|---|---|---|---|');
console.log(rows.join('\n'));
console.log('\nwork of one frame: field fetches (field + image texels) and Newton steps per lookup; ' +
            'nodes and triangles tested per BVH walk\n');
console.log('| export | field lookups | field per lookup | gfield BVH per walk | ' +
            'three-mesh-bvh per walk |\n|---|---|---|---|---|');
console.log(workRows.join('\n'));
