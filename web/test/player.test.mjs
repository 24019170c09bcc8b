// The web player in Debian's chromium (headless, SwiftShader) against gfield-view's headless
// pictures of the same scenes, camera and size (the geometry field, gfield's BVH and
// three-mesh-bvh's); its messages for broken exports; its work counters against gfield-view
// --count-work's; the three.js example; and --export-web's refusals. Run by CTest (Web.Player) with GFIELD_VIEW, GFIELD and GFIELD_TMP set
// (tests/CMakeLists.txt); `npm test` in web/ after `npm ci`.

import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync, spawnSync } from 'node:child_process';
import { cpSync, existsSync, mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { launch, openPlayer, serve } from '../tools/browser.mjs';

const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const VIEW = process.env.GFIELD_VIEW ?? join(ROOT, 'build/runtime/gfield-view');
const CLI = process.env.GFIELD ?? join(ROOT, 'build/preprocess/gfield');
const TMP = join(process.env.GFIELD_TMP ?? join(ROOT, 'build/tests/tmp'), 'web');
const ASSETS = join(TMP, 'assets');
const SIZE = 160;  // the broken exports' and bad queries' page
const DEPTH = 4;

// Each scene at its own size (512 x 512), depth 4, in the three methods: PSNR floors against
// gfield-view's picture (three-mesh-bvh's against --intersect bvh's). They differ where
// SwiftShader and llvmpipe rasterise silhouette pixels apart, and then at every bounce seen
// through them; docs/web.md gives the measured figures.
const SCENES = [
  { name: 'mirror-torus-instances', meshes: ['spot', 'torus'], floor: { field: 35, bvh: 35 } },
  { name: 'textured-mirror', meshes: ['spot-painted', 'torus'], floor: { field: 35, bvh: 35 } },
  { name: 'davis-wyman-color-chart', meshes: ['spot'], floor: { field: 35, bvh: 35 } },
];

let browser;

function exportScene(name, out, size = []) {
  execFileSync(VIEW, [join(ROOT, 'data/scenes', `${name}.json`), '--assets', ASSETS, ...size,
                      '--export-web', out], { stdio: 'pipe' });
}

// mirror-torus-instances exported at SIZE x SIZE, once per run: the folder.
const SMALL = join(TMP, 'mirror-torus-small');
let smallExported = false;
function smallExport() {
  if (!smallExported) exportScene('mirror-torus-instances', SMALL, ['--size', `${SIZE}x${SIZE}`]);
  smallExported = true;
  return SMALL;
}

function psnr(a, b) {
  const run = spawnSync('compare', ['-metric', 'PSNR', a, b, 'null:'], { encoding: 'utf8' });
  const value = Number.parseFloat(run.stderr);
  assert.ok(Number.isFinite(value) || run.stderr.startsWith('inf'), `compare: ${run.stderr}`);
  return Number.isFinite(value) ? value : Infinity;
}

before(async () => {
  mkdirSync(ASSETS, { recursive: true });
  for (const mesh of new Set(SCENES.flatMap((s) => s.meshes)))
    if (!existsSync(join(ASSETS, `${mesh}.gfield.exr`)))
      execFileSync(CLI, ['build', join(ROOT, 'data/meshes', `${mesh}.obj`), '-o', join(ASSETS, mesh)],
                   { stdio: 'pipe' });
  browser = await launch();
});

after(async () => { await browser?.close(); });

for (const scene of SCENES) {
  test(`${scene.name}: the browser's pictures are the viewer's, field, BVH and three-mesh-bvh`, async () => {
    const out = join(TMP, scene.name);
    exportScene(scene.name, out);
    const [width, height] = JSON.parse(readFileSync(join(out, 'scene.json'), 'utf8')).size;
    const server = await serve(out);
    try {
      for (const method of ['field', 'bvh', 'three-mesh-bvh']) {
        const intersect = method === 'field' ? 'field' : 'bvh';
        const reference = join(TMP, `${scene.name}-${intersect}-viewer.png`);
        if (method !== 'three-mesh-bvh')
          execFileSync(VIEW, [join(ROOT, 'data/scenes', `${scene.name}.json`), '--assets', ASSETS,
                              '--headless', '--depth', `${DEPTH}`, '--intersect', intersect,
                              '-o', reference], { stdio: 'pipe' });
        const page = await openPlayer(browser, `${server.url}index.html?ui=0&depth=${DEPTH}&method=${method}`,
                                      width, height);
        assert.equal(page.title, 'ready', page.text);
        const shot = join(TMP, `${scene.name}-${method}-browser.png`);
        writeFileSync(shot, page.png);
        const db = psnr(shot, reference);
        console.log(`${scene.name}, ${method}, ${width} x ${height}: ${db.toFixed(2)} dB against ` +
                    `gfield-view, first frame after ${page.seconds.toFixed(2)} s`);
        assert.ok(db >= scene.floor[intersect], `${method}: ${db} dB < ${scene.floor[intersect]} dB`);
      }
      // Both BVHs are exact over the same triangles: the same picture but for float rounding.
      const same = psnr(join(TMP, `${scene.name}-three-mesh-bvh-browser.png`),
                        join(TMP, `${scene.name}-bvh-browser.png`));
      console.log(`${scene.name}: three-mesh-bvh against gfield's BVH in the browser: ${same} dB`);
      assert.ok(same >= 50, `three-mesh-bvh and gfield's BVH differ: ${same} dB`);
    } finally {
      await server.close();
    }
  });
}

// A broken copy of the mirror-torus export: `damage(folder)` breaks it; the page, opened with
// `query` (if given), must say `expected` (a regular expression) in its text and its title.
const BROKEN = [
  ['a truncated scene.bin.gz', (dir) => {
    const bin = readFileSync(join(dir, 'scene.bin.gz'));
    writeFileSync(join(dir, 'scene.bin.gz'), bin.subarray(0, bin.length >> 1));
  }, /scene\.bin\.gz: (damaged or truncated|holds \d+ bytes)/],
  ['another layout version', (dir) => {
    const manifest = JSON.parse(readFileSync(join(dir, 'scene.json'), 'utf8'));
    manifest.version = 99;
    writeFileSync(join(dir, 'scene.json'), JSON.stringify(manifest));
  }, /scene\.json: layout version 99; this player reads version 1/],
  ['no scene.json', (dir) => rmSync(join(dir, 'scene.json')), /scene\.json: cannot be fetched \(HTTP 404\)/],
  ['a damaged shader', (dir) => writeFileSync(join(dir, 'shaders/field_trace.frag'), '#version 300 es\nvoid main( {}\n'),
   /shaders\/field_trace\.frag: does not compile/],
  ['no three-mesh-bvh in the export', (dir) => {
    const manifest = JSON.parse(readFileSync(join(dir, 'scene.json'), 'utf8'));
    manifest.peers = {};
    writeFileSync(join(dir, 'scene.json'), JSON.stringify(manifest));
    rmSync(join(dir, 'vendor'), { recursive: true });
  }, /method=three-mesh-bvh: this export has no vendor\/three-mesh-bvh\.js/, 'method=three-mesh-bvh'],
  ['a vendor file gone', (dir) => rmSync(join(dir, 'vendor/three-mesh-bvh.js')),
   /vendor\/three-mesh-bvh\.js, vendor\/three\.core\.js: cannot be loaded/, 'method=three-mesh-bvh'],
];

test('a broken export is named in the page, not drawn blank', async () => {
  const good = smallExport();
  for (const [what, damage, expected, query = ''] of BROKEN) {
    const dir = join(TMP, 'broken');
    rmSync(dir, { recursive: true, force: true });
    cpSync(good, dir, { recursive: true });
    damage(dir);
    const server = await serve(dir);
    try {
      const page = await openPlayer(browser, `${server.url}index.html?ui=0&${query}`, SIZE, SIZE);
      assert.match(page.title, /^error: /, what);
      assert.match(page.title, expected, what);
      assert.match(page.text, expected, what);
    } finally {
      await server.close();
    }
  }
});

test('a bad query is named in the page', async () => {
  const dir = smallExport();
  const server = await serve(dir);
  try {
    for (const [query, expected] of [['size=12', /size=12: expected WxH/],
                                     ['mode=exact', /mode=exact: expected nearest, linear or refined/],
                                     ['method=rtx', /method=rtx: expected field, bvh, three-mesh-bvh/],
                                     ['depth=-1', /depth=-1: expected 0\.\.64/]]) {
      const page = await openPlayer(browser, `${server.url}index.html?ui=0&${query}`, SIZE, SIZE);
      assert.match(page.title, expected, query);
    }
  } finally {
    await server.close();
  }
});

test('the panel and the orbit camera redraw the frame', async () => {
  const dir = smallExport();
  const server = await serve(dir);
  const page = await browser.newPage();
  try {
    await page.setViewport({ width: 400, height: SIZE });
    await page.goto(`${server.url}index.html?depth=1`);
    await page.waitForFunction(() => document.title === 'ready', { timeout: 120000 });
    const frame = () => page.screenshot({ clip: { x: 0, y: 0, width: SIZE, height: SIZE } });
    const settle = () => page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
    const first = Buffer.from(await frame());
    await page.mouse.move(80, 80);
    await page.mouse.down();
    await page.mouse.move(120, 70, { steps: 4 });
    await page.mouse.up();
    await settle();
    const turned = Buffer.from(await frame());
    assert.ok(!turned.equals(first), 'a drag turns the camera');
    await page.select('#method', 'bvh');
    await settle();
    assert.equal(await page.evaluate(() => window.gfield.renderer.settings.method), 'bvh');
    const bvh = Buffer.from(await frame());
    await page.select('#method', 'three-mesh-bvh');
    await page.waitForFunction(() => window.gfield.renderer.settings.method === 'three-mesh-bvh',
                               { timeout: 60000 });
    await settle();
    const shots = [['bvh', bvh], ['three-mesh-bvh', Buffer.from(await frame())]].map(([name, png]) => {
      writeFileSync(join(TMP, `panel-${name}.png`), png);
      return join(TMP, `panel-${name}.png`);
    });
    assert.ok(psnr(...shots) >= 50, 'three-mesh-bvh draws gfield\'s BVH picture');
    assert.match(await page.$eval('#method', (s) => s.selectedOptions[0].text), /^three-mesh-bvh \d/);
    await page.select('#method', 'field');
    await settle();
    await page.select('#mode', 'nearest');
    await settle();
    const nearest = Buffer.from(await frame());
    assert.ok(!nearest.equals(turned), 'the panel redraws');
    await page.click('#count');
    assert.match(await page.$eval('#work', (e) => e.textContent),
                 /^\d+ lookups: [\d.]+ field \+ [\d.]+ image fetches, [\d.]+ Newton steps each\n\d+ secondary rays$/);
    assert.equal(await page.title(), 'ready');
  } finally {
    await page.close();
    await server.close();
  }
});

// gfield-view --count-work's totals of the small export's frame ("per sample: NAME N, ...").
function viewerWork(intersect) {
  const out = execFileSync(VIEW, [join(ROOT, 'data/scenes/mirror-torus-instances.json'), '--assets',
                                  ASSETS, '--headless', '--bench', '--count-work', '--frames', '1',
                                  '--pass', 'fragment', '--size', `${SIZE}x${SIZE}`, '--depth',
                                  `${DEPTH}`, '--intersect', intersect], { encoding: 'utf8' });
  const line = out.split('\n').find((l) => l.startsWith('per sample: '));
  assert.ok(line, out);
  const names = { 'field lookups': 'lookups', 'field texel fetches': 'field_fetches',
                  'image texel fetches': 'image_fetches', 'Newton steps': 'newton_steps',
                  'BVH traversals': 'bvh_traversals', 'BVH nodes': 'bvh_nodes',
                  'BVH triangles': 'bvh_triangles', 'counted rays': 'rays' };
  const totals = {};
  for (const [, name, n] of line.matchAll(/([A-Za-z ]+) (\d+)/g))
    if (names[name.trim()]) totals[names[name.trim()]] = Number(n);
  return totals;
}

test('the page counts the work gfield-view counts, and three-mesh-bvh\'s walks', async () => {
  const dir = smallExport();
  const server = await serve(dir);
  const page = await browser.newPage();
  try {
    await page.setViewport({ width: SIZE, height: SIZE });
    const counts = {};
    for (const method of ['field', 'bvh', 'three-mesh-bvh']) {
      await page.goto(`${server.url}index.html?ui=0&depth=${DEPTH}&method=${method}`);
      await page.waitForFunction(() => document.title === 'ready', { timeout: 120000 });
      counts[method] = (await page.evaluate(() => window.gfield.countWork())).totals;
    }
    for (const method of ['field', 'bvh']) {
      const viewer = viewerWork(method);
      console.log(`${method}: page ${JSON.stringify(counts[method])}, gfield-view ${JSON.stringify(viewer)}`);
      for (const [name, n] of Object.entries(viewer)) {
        // The two rasterisers cover silhouette pixels apart (docs/web.md), and a shadow ray whose
        // lookup doubts its miss on one GPU and not on the other searches its surface again
        // (some 30 Newton steps): within 3%.
        const page = counts[method][name];
        assert.ok(n === 0 ? page === 0 : Math.abs(page - n) <= 0.03 * n, `${method} ${name}: ${page} vs ${n}`);
      }
      assert.ok(viewer[method === 'field' ? 'lookups' : 'bvh_traversals'] > 1000, method);
    }
    // three-mesh-bvh walks where gfield's BVH does: the same rays, its own nodes and triangles.
    const [ours, peer] = [counts.bvh, counts['three-mesh-bvh']];
    console.log(`three-mesh-bvh: ${JSON.stringify(peer)}`);
    assert.ok(Math.abs(peer.bvh_traversals - ours.bvh_traversals) <= 0.005 * ours.bvh_traversals);
    assert.ok(peer.bvh_nodes >= peer.bvh_traversals && peer.bvh_triangles > 0, 'its walks counted');
    // Its own BVH, not gfield's: leaves of about 10 triangles test several times gfield's.
    assert.ok(peer.bvh_triangles > 2 * ours.bvh_triangles, 'three-mesh-bvh\'s walk, not gfield\'s');
    assert.equal(peer.lookups, 0);
  } finally {
    await page.close();
    await server.close();
  }
});

test('the three.js example draws the player\'s frame on three.js\'s context, its objects in depth with it', async () => {
  const dir = smallExport();
  const server = await serve(join(ROOT, 'web'), { scene: dir });
  try {
    const shots = {};
    for (const [name, url] of [['player', `scene/index.html?ui=0&depth=4`],
                               ['three', 'examples/three.html?scene=/scene/&overlay=0'],
                               ['overlay', 'examples/three.html?scene=/scene/'],
                               ['wall', 'examples/three.html?scene=/scene/&overlay=wall']]) {
      const page = await openPlayer(browser, server.url + url, SIZE, SIZE);
      assert.equal(page.title, 'ready', `${name}: ${page.text}`);
      shots[name] = join(TMP, `three-${name}.png`);
      writeFileSync(shots[name], page.png);
    }
    assert.ok(psnr(shots.three, shots.player) >= 50, 'the same frame as the player\'s');
    assert.ok(psnr(shots.overlay, shots.three) < 50, 'three.js drew its box over it');
    // The wall behind every gfield object shows only where none covers it (the shared depth):
    // every pixel is the player's or the wall's red, and both kinds are many.
    const rgb = (png) => execFileSync('convert', [png, '-depth', '8', 'rgb:-']);
    const [player, wall] = [rgb(shots.player), rgb(shots.wall)];
    let red = 0, same = 0;
    for (let i = 0; i < wall.length; i += 3) {
      if (wall[i] === 255 && wall[i + 1] === 0 && wall[i + 2] === 0) red++;
      else if (wall.subarray(i, i + 3).equals(player.subarray(i, i + 3))) same++;
    }
    const pixels = wall.length / 3;
    console.log(`three.js's wall behind the scene: ${red} red pixels, ${same} the player's, of ${pixels}`);
    assert.equal(red + same, pixels, 'every pixel the wall\'s or the player\'s');
    assert.ok(red > 0.1 * pixels && same > 0.1 * pixels, `${red} red, ${same} the player's`);
  } finally {
    await server.close();
  }
});

// A folder TMP/name holding copies of the geometry images and fields of `meshes`.
function copyAssets(name, meshes) {
  const dir = join(TMP, name);
  rmSync(dir, { recursive: true, force: true });
  mkdirSync(dir);
  for (const mesh of meshes)
    for (const kind of ['gimage', 'gfield'])
      writeFileSync(join(dir, `${mesh}.${kind}.exr`), readFileSync(join(ASSETS, `${mesh}.${kind}.exr`)));
  return dir;
}

test('--export-web refuses a folder that is not an export, and a damaged asset', () => {
  const taken = join(TMP, 'taken');
  rmSync(taken, { recursive: true, force: true });
  mkdirSync(taken);
  writeFileSync(join(taken, 'notes.txt'), 'mine');
  const scene = join(ROOT, 'data/scenes/mirror-torus-instances.json');
  let run = spawnSync(VIEW, [scene, '--assets', ASSETS, '--export-web', taken], { encoding: 'utf8' });
  assert.equal(run.status, 2);
  assert.match(run.stderr, /^gfield-view: .*taken: exists and is not an earlier web export; choose another folder\n$/);
  assert.equal(readFileSync(join(taken, 'notes.txt'), 'utf8'), 'mine');
  // Copies of the files, not of the asset folder's links (which lead to the builds themselves).
  const damaged = copyAssets('damaged-assets', ['spot', 'torus']);
  const field = join(damaged, 'torus.gfield.exr');
  writeFileSync(field, readFileSync(field).subarray(0, 4096));
  const fresh = join(TMP, 'no-export');
  rmSync(fresh, { recursive: true, force: true });
  run = spawnSync(VIEW, [scene, '--assets', damaged, '--export-web', fresh], { encoding: 'utf8' });
  assert.equal(run.status, 2);
  assert.equal(run.stderr.split('\n').length, 2, run.stderr);
  assert.match(run.stderr, /torus\.gfield\.exr/);
  assert.ok(!existsSync(fresh), 'no folder after a failed export');
});

test('a mesh exported without its field is traced by its BVH, as gfield-view traces it', async () => {
  const torusOnly = copyAssets('torus-assets', ['torus']);
  const scene = join(ROOT, 'data/scenes/mirror-torus-instances.json');
  const out = join(TMP, 'torus-fields-only');
  const run = spawnSync(VIEW, [scene, '--assets', torusOnly, '--size', `${SIZE}x${SIZE}`,
                               '--export-web', out], { encoding: 'utf8' });
  assert.equal(run.status, 0, run.stderr);
  assert.match(run.stderr, /spot\.obj: no geometry field .*: traced through its BVH in the web player/);
  const reference = join(TMP, 'torus-fields-only-viewer.png');
  execFileSync(VIEW, [scene, '--assets', torusOnly, '--headless', '--size', `${SIZE}x${SIZE}`,
                      '--depth', `${DEPTH}`, '-o', reference], { stdio: 'pipe' });
  const server = await serve(out);
  try {
    const page = await openPlayer(browser, `${server.url}index.html?ui=0&depth=${DEPTH}`, SIZE, SIZE);
    assert.equal(page.title, 'ready', page.text);
    const shot = join(TMP, 'torus-fields-only-browser.png');
    writeFileSync(shot, page.png);
    // At 160 x 160 silhouettes are a larger share of the pixels: every scene is 31-32 dB there.
    const db = psnr(shot, reference);
    console.log(`torus by its field, spots by their BVH, ${SIZE} x ${SIZE}: ${db.toFixed(2)} dB against gfield-view`);
    assert.ok(db >= 30, `${db} dB`);
  } finally {
    await server.close();
  }
});
