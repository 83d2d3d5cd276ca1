// The web page in Debian's headless Chromium, driven as the desktop window's tests drive it: the
// same timed input file (passed by address, ?input=) and the window's dump printed to the console
// ("dump -"). The page is served from 127.0.0.1 by a small static server here; the browser runs
// WebGL2 through SwiftShader, with no network and no downloads of its own.
//   node --test tests/web/            with S4D_WEB_DIR=OUTDIR of scripts/build-web.sh
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import { chromium } from 'playwright-core';

const siteDir = process.env.S4D_WEB_DIR;
const shotDir = process.env.S4D_WEB_SHOTS || fs.mkdtempSync(path.join(os.tmpdir(), 's4d-web-shots-'));
const inputDir = fs.mkdtempSync(path.join(os.tmpdir(), 's4d-web-input-'));
const types = { '.html': 'text/html', '.js': 'text/javascript', '.wasm': 'application/wasm',
                '.data': 'application/octet-stream', '.txt': 'text/plain', '.json': 'application/json' };
let server, base, context, userDir;

before(async () => {
  assert.ok(siteDir && fs.existsSync(path.join(siteDir, 'index.html')),
            'S4D_WEB_DIR must name the folder scripts/build-web.sh made');
  server = http.createServer((req, res) => {
    const url = new URL(req.url, 'http://127.0.0.1');
    const rel = decodeURIComponent(url.pathname === '/' ? '/index.html' : url.pathname);
    const root = rel.startsWith('/t/') ? inputDir : siteDir;
    const file = path.join(root, rel.startsWith('/t/') ? rel.slice(3) : rel);
    if (!file.startsWith(root) || !fs.existsSync(file)) { res.writeHead(404); res.end(); return; }
    res.writeHead(200, { 'Content-Type': types[path.extname(file)] || 'application/octet-stream' });
    fs.createReadStream(file).pipe(res);
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  base = `http://127.0.0.1:${server.address().port}`;
  userDir = fs.mkdtempSync(path.join(os.tmpdir(), 's4d-chromium-'));
  // Without the networking flags Chromium's own connections are refused here and it stalls.
  context = await chromium.launchPersistentContext(userDir, {
    executablePath: process.env.S4D_CHROMIUM || '/usr/bin/chromium',
    headless: true,
    viewport: { width: 1280, height: 800 },
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
           '--disable-component-update', '--disable-sync', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  });
});

after(async () => {
  await context?.close();
  server?.close();
  fs.rmSync(userDir, { recursive: true, force: true });
});

// Opens the page with `query` and the input file `lines`; resolves with the page and the dumps
// once `dumps` of them were printed (or rejects after `timeout` ms with the console's tail).
async function runPage(name, query, lines, dumps, { timeout = 120000, page: reuse } = {}) {
  fs.writeFileSync(path.join(inputDir, `${name}.txt`), lines.join('\n') + '\n');
  const page = reuse || await context.newPage();
  const out = [], console_ = [];
  let resolveDone;
  const done = new Promise((resolve) => { resolveDone = resolve; });
  const onConsole = (msg) => {
    const text = msg.text();
    console_.push(text);
    if (text.startsWith('dump ')) {
      out.push(JSON.parse(text.slice(5)));
      if (out.length >= dumps) resolveDone();
    }
  };
  page.on('console', onConsole);
  page.on('pageerror', (e) => console_.push('pageerror: ' + e.message));
  const sep = query ? '&' : '';
  await page.goto(`${base}/index.html?${query}${sep}input=t/${name}.txt`);
  let timer;
  const timedOut = new Promise((_, reject) => {
    timer = setTimeout(() => reject(new Error(`${name}: ${out.length} of ${dumps} dumps after ${timeout} ms; ` +
                                              `console:\n${console_.slice(-25).join('\n')}`)), timeout);
  });
  try {
    await Promise.race([done, timedOut]);
  } finally {
    clearTimeout(timer);
    page.off('console', onConsole);
  }
  return { page, dumps: out, console: console_ };
}

// The share of pixels of a screenshot that are not the background: a blank or black page is ~0.
// With `rect` (the dump's view), of that rectangle only: the panels around it do not count.
async function litShare(page, file, rect = null) {
  await page.screenshot({ path: file });
  const rgba = await page.evaluate(async ([src, r]) => {
    const img = new Image();
    img.src = src;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = img.width; c.height = img.height;
    const g = c.getContext('2d');
    g.drawImage(img, 0, 0);
    const [x, y, w, h] = r ? [r.x, r.y, r.w, r.h].map(Math.round) : [0, 0, c.width, c.height];
    const d = g.getImageData(x, y, w, h).data;
    let lit = 0;
    for (let i = 0; i < d.length; i += 4) lit += d[i] + d[i + 1] + d[i + 2] > 150 ? 1 : 0;
    return lit / (d.length / 4);
  }, ['data:image/png;base64,' + fs.readFileSync(file).toString('base64'), rect]);
  return rgba;
}

// Forgets the autosaves earlier tests left in the browser's storage: their "Restore your work?"
// dialog would take the clicks and touches of a test that presses things. `page` is left on a
// blank document of the site (same origin), ready for runPage.
async function forgetAutosaves(page) {
  fs.writeFileSync(path.join(inputDir, 'blank.txt'), '');
  await page.goto(`${base}/t/blank.txt`);
  await page.evaluate(async () => {
    for (const d of await indexedDB.databases())
      await new Promise((resolve) => {
        const q = indexedDB.deleteDatabase(d.name);
        q.onsuccess = q.onerror = q.onblocked = resolve;
      });
  });
}

// move-view takes half-sides of the 3D view from its centre, as in tests/app/gui_smoke_test.cpp.
const viewAt = (x, y) => `move-view ${((x - 640) / 400).toFixed(5)} ${((400 - y) / 400).toFixed(5)}`;

// How far vertex v moved in R^4 between two dumps (their positions, 4 numbers a vertex).
const movedBetween = (from, to, v) => {
  const at = (d) => d.positions.slice(4 * v, 4 * v + 4);
  return Math.hypot(...at(to).map((x, k) => x - at(from)[k]));
};

// The start page's buttons, kept for the knot sketch test below (it presses one as a user).
let startCards = null;
test('the start page appears with no file', async () => {
  const { page, dumps } = await runPage('start', '', ['20 dump -'], 1);
  assert.equal(dumps[0].start_page, true);
  assert.ok(dumps[0].start_cards.length > 0, 'the start page offers examples');
  startCards = Object.fromEntries(dumps[0].start_cards.map((c) => [c.name, c]));
  assert.ok(startCards['Sketch a knot'], 'the start page has "Sketch a knot"');
  assert.ok(await litShare(page, path.join(shotDir, 'start.png')) > 0.02, 'the start page is drawn');
  await page.close();
});

// The scenarios the page carries in its data package: the checkout's.
const scenarios = fs.readdirSync(new URL('../../scenarios/', import.meta.url), { withFileTypes: true })
  .filter((e) => e.name.endsWith('.json')).map((e) => e.name);

test('every scenario opens and draws', async () => {
  assert.ok(scenarios.length >= 8, 'the site has the scenarios');
  for (const s of scenarios) {
    const { page, dumps } = await runPage(`open-${s}`, `open=scenarios/${s}`, ['3 key SPACE', '40 dump -'], 1);
    const d = dumps[0];
    assert.equal(d.error, '', `${s}: ${d.error}`);
    assert.equal(d.physics_error, '', `${s}: ${d.physics_error}`);
    assert.equal(d.simulating, true, `${s} simulates`);
    assert.ok(d.sim_steps > 0, `${s}: Space played it`);
    // In the view alone, whose background is below the threshold: an empty view lights nothing,
    // the thin ribbon of ribbon-falls-apart-4d 0.3 %, the chain 2 %.
    const lit = await litShare(page, path.join(shotDir, `${s}.png`), d.view);
    assert.ok(lit > 0.001, `${s} is drawn (${(100 * lit).toFixed(1)} % of the view lit)`);
    await page.close();
  }
});

test('a grab of the spun trefoil moves the vertex, and the live check finds no true intersection', async () => {
  const lines = ['3 key SPACE', '10 ' + viewAt(640, 400), '20 ' + viewAt(641, 400), '30 dump -', '31 press left'];
  for (let i = 1; i <= 30; ++i) lines.push(`${31 + 2 * i} ${viewAt(641 + 4 * i, 400 - i)}`);
  lines.push('110 dump -', '111 release left', '150 wait-sim 2', '151 dump -');
  const { page, dumps } = await runPage('grab', 'open=scenarios/spun-trefoil-tighten.json', lines, 3);
  const [before, during, afterRelease] = dumps;
  assert.ok(before.hits_under_cursor >= 1, 'the cursor is over the surface');
  const held = during.held_vertex;
  assert.ok(held >= 0, 'the press took hold of a vertex');
  const moved = movedBetween(before, during, held);
  assert.ok(moved > 0.15, `the held vertex followed the hand (moved ${moved})`);
  assert.equal(afterRelease.held_vertex, -1, 'released');
  assert.equal(afterRelease.checked, true, 'the live check ran');
  assert.equal(during.true_intersections, 0);
  assert.equal(afterRelease.true_intersections, 0);
  console.log(`spun trefoil in the page: real-time ratio ${afterRelease.real_time_ratio.toFixed(2)}, ` +
              `${afterRelease.steps_per_second.toFixed(0)} steps/s`);
  assert.ok(await litShare(page, path.join(shotDir, 'grab.png')) > 0.05);
  await page.close();
});

test('a session survives a reload through IndexedDB', async () => {
  const first = await runPage('autosave', 'open=scenarios/spun-trefoil-tighten.json&autosave-seconds=1',
                              ['3 key SPACE', '10 wait-sim 1', '11 dump -'], 1);
  // The autosave runs every second and copies itself to IndexedDB (asynchronously): give it time.
  await first.page.waitForTimeout(3000);
  const again = await runPage('reload', '', ['20 dump -'], 1, { page: first.page });
  const d = again.dumps[0];
  assert.equal(d.restore_offered, true, 'the page offers the work the last one left');
  assert.match(d.restore_offer.opened, /spun-trefoil-tighten/);
  await again.page.close();
});

// The Knot panel's name, with "(proven)" or not, as the dump gives it.
const shownName = (d) => d.knot_panels.shown ?? { name: '', proven: false };

test('a trefoil sketched in the page with the knot sketch tool is named 3_1', async () => {
  assert.ok(startCards, 'the start page test ran first');
  const b = startCards['Sketch a knot'];
  const cx = Math.round(b.x + b.w / 2), cy = Math.round(b.y + b.h / 2);
  // As tests/app/gui_smoke_test.cpp draws it on the desktop: the trefoil of Fig. 4, shift (under)
  // and ctrl (over) held by turns as the stroke meets the strands drawn before; Enter finishes.
  const l = [`3 move ${cx} ${cy}`, '5 press left', '7 release left', '10 ' + viewAt(640, 440),
             '14 ' + viewAt(640, 441), '20 press left'];
  // 240 points, one a frame (the desktop test draws 360, two frames each): the page's frames are
  // slower, and the CI budget is tight.
  const n = 240, first = 22;
  let under = false, over = false;
  for (let i = 0; i <= n; ++i) {
    const t = 2 * Math.PI * 1.03 * i / n;
    const frame = first + i;
    const wantUnder = -Math.sin(3 * t) < 0;
    if (wantUnder !== under) l.push(`${frame} ${wantUnder ? 'key-down' : 'key-up'} LEFT_SHIFT`);
    if (!wantUnder !== over) l.push(`${frame} ${!wantUnder ? 'key-down' : 'key-up'} LEFT_CONTROL`);
    under = wantUnder;
    over = !wantUnder;
    const x = 640 + 45 * (Math.sin(t) + 2 * Math.sin(2 * t)), y = 400 - 45 * (Math.cos(t) - 2 * Math.cos(2 * t));
    l.push(`${frame} ${viewAt(Math.round(x), Math.round(y))}`);
  }
  const end = first + n;
  l.push(`${end + 2} key-up LEFT_SHIFT`, `${end + 2} key-up LEFT_CONTROL`, `${end + 30} release left`,
         `${end + 32} dump -`, `${end + 40} key ENTER`, `${end + 42} wait`, `${end + 44} wait`, `${end + 46} dump -`);
  const fresh = await context.newPage();
  await forgetAutosaves(fresh);
  const { page, dumps } = await runPage('sketch', '', l, 2, { page: fresh });
  const [drawn, named] = dumps;
  assert.equal(drawn.tool, 'Sketch a knot');
  assert.equal(drawn.sketch.components, 1);
  assert.ok(drawn.sketch.crossings_chosen >= 3, 'each later passage crossed by a choice');
  assert.equal(named.objects, 1, named.status);
  assert.match(named.sketch.last_name, /^3_1/, named.sketch.last_gauss);
  assert.match(shownName(named).name, /^3_1/, named.status);
  assert.equal(shownName(named).proven, true, 'the desktop own engine proves the trefoil');
  await page.close();
});

// Table knots and links opened by address (?open=knot:NAME), then by the input file's `open`, named
// as the desktop's own engine names them: `shadow4d knot make NAME --out k.curve` then
// `shadow4d knot identify k.curve --engine own` (the page has no Regina; see docs/web.md).
const desktopNames = [
  ['4_1', '4_1 (DT 4a_1)', true],
  ['7_4', '7_4 (DT 7a_6)', true],
  ['10_123', '10_123 (DT 10a_121)', true],
  ['12n_242', '12n_242', true],
  ['L6a4', 'L6a4 (Borromean rings)', true],
  ['L7n1', 'L7n1', true],
];
test('table knots and links opened by address get the desktop own engine names', async () => {
  const lines = [];
  desktopNames.forEach(([name], i) => {
    const at = 10 + 20 * i;
    if (i > 0) lines.push(`${at} open knot:${name}`);
    lines.push(`${at + 4} wait`, `${at + 8} wait`, `${at + 12} dump -`);
  });
  const { page, dumps } = await runPage('table-names', `open=knot:${desktopNames[0][0]}`, lines, desktopNames.length);
  desktopNames.forEach(([name, want, proven], i) => {
    const d = dumps[i];
    assert.equal(d.error, '', `${name}: ${d.error}`);
    assert.equal(shownName(d).name, want, `${name}: ${d.status}`);
    assert.equal(shownName(d).proven, proven, `${name}: proven as on the desktop`);
  });
  await page.close();
});

// File > Save session (Ctrl+S) writes the session and the browser downloads it; File > Open
// (Ctrl+O) opens the browser's file picker, and the file chosen there opens as on the desktop.
test('a session saved by download opens back through the browser file picker', async () => {
  const page = await context.newPage();
  const later = [];
  let wake = () => {};
  page.on('console', (msg) => {
    if (!msg.text().startsWith('dump ')) return;
    later.push(JSON.parse(msg.text().slice(5)));
    wake();
  });
  const downloaded = page.waitForEvent('download', { timeout: 120000 });
  downloaded.catch(() => {});
  // Asked before the page runs: Playwright takes over the picker only once it is listening.
  const chooser = page.waitForEvent('filechooser', { timeout: 150000 });
  chooser.catch(() => {});  // awaited below; a failure before that must not leave it unhandled
  const lines = ['3 key SPACE', '10 wait-sim 0.3', '11 key SPACE', '20 dump -', '22 key-down LEFT_CONTROL', '23 key S',
                 '24 key-up LEFT_CONTROL', '28 type web-saved.s4d',
                 // Dear ImGui 1.86 sees a key only held over a frame: down and up on frames of their own.
                 '30 key-down ENTER', '32 key-up ENTER', '40 dump -'];
  for (let f = 60; f <= 3000; f += 20) lines.push(`${f} dump -`);
  const { dumps } = await runPage('save-open', 'open=scenarios/spun-trefoil-tighten.json', lines, 2, { page });
  const [saved, afterSave] = dumps;
  assert.equal(saved.playing, false, 'paused before saving');
  assert.match(afterSave.status, /saved the session .*web-saved\.s4d \(and downloaded\)/);
  const download = await downloaded;
  assert.equal(download.suggestedFilename(), 'web-saved.s4d');
  const file = path.join(inputDir, 'web-saved.s4d');
  await download.saveAs(file);
  assert.ok(fs.statSync(file).size > 1000, 'the download is the session');

  await page.keyboard.down('Control');
  await page.keyboard.press('KeyO', { delay: 100 });
  await page.keyboard.up('Control');
  await (await chooser).setFiles(file);
  const opened = await new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error('no dump after the open: ' + later.at(-1)?.status)), 60000);
    wake = () => {
      const d = later.at(-1);
      if (/opened the session/.test(d.status)) { clearTimeout(timer); resolve(d); }
    };
  });
  assert.equal(opened.error, '');
  assert.match(opened.status, /opened the session \/uploads\/web-saved\.s4d/);
  assert.equal(opened.positions.length, saved.positions.length);
  const worst = Math.max(...opened.positions.map((x, k) => Math.abs(x - saved.positions[k])));
  assert.ok(worst < 1e-9, `the opened session is the saved state (largest difference ${worst})`);
  assert.equal(opened.playing, false, 'paused, as saved');
  await page.close();
});

// The window follows the browser window's size: the dump's window, the view and every panel
// inside it after page.setViewportSize, smaller and then larger.
test('the page follows the browser window size and keeps the panels inside', async () => {
  const page = await context.newPage();
  const sizes = [[1280, 800], [900, 640], [1500, 900]];
  const seen = [];
  page.on('console', (msg) => { if (msg.text().startsWith('dump ')) seen.push(JSON.parse(msg.text().slice(5))); });
  const lines = [];
  for (let f = 20; f <= 2400; f += 10) lines.push(`${f} dump -`);
  await runPage('resize', 'open=knot:3_1', lines, 1, { page });
  for (const [w, h] of sizes) {
    await page.setViewportSize({ width: w, height: h });
    const at = seen.length;
    const deadline = Date.now() + 20000;
    let d;
    while (Date.now() < deadline) {
      d = seen.slice(at).find((x) => x.window.w === w && x.window.h === h);
      if (d) break;
      await page.waitForTimeout(100);
    }
    assert.ok(d, `the window became ${w}x${h} (last: ${JSON.stringify(seen.at(-1)?.window)})`);
    // One more dump, once the layout of the new size has been drawn.
    const settled = seen.length;
    while (seen.length < settled + 2 && Date.now() < deadline) await page.waitForTimeout(50);
    d = seen.at(-1);
    const inside = (r, name) => assert.ok(r.x >= -1 && r.y >= -1 && r.x + r.w <= w + 1 && r.y + r.h <= h + 1,
                                          `${name} ${JSON.stringify(r)} inside ${w}x${h}`);
    inside(d.view, 'the view');
    // The layout's parts (a dialog open over it keeps its place, as a desktop window's does).
    const parts = d.panels.filter((p) => ['MainMenuBar', 'left column', 'right column', 'instruction',
                                           'status line'].includes(p.name));
    assert.ok(parts.length >= 4, JSON.stringify(d.panels.map((p) => p.name)));
    for (const p of parts) inside(p, p.name);
    const canvas = await page.evaluate(() => [document.getElementById('canvas').width, document.getElementById('canvas').height]);
    assert.deepEqual(canvas, [w, h], 'the canvas draws at the new size');
  }
  await page.close();
});

// A touch screen (CDP Input.dispatchTouchEvent): one finger grabs and moves a vertex of the spun
// trefoil as the mouse does in the grab test; two fingers spreading to three times their distance zoom the view 3x.
test('one finger grabs a vertex, two fingers pinch-zoom the view', async () => {
  const page = await context.newPage();
  await forgetAutosaves(page);
  const seen = [];
  page.on('console', (msg) => { if (msg.text().startsWith('dump ')) seen.push(JSON.parse(msg.text().slice(5))); });
  const lines = ['3 key SPACE'];
  for (let f = 10; f <= 3000; f += 10) lines.push(`${f} dump -`);
  await runPage('touch', 'open=scenarios/spun-trefoil-tighten.json', lines, 1, { page });
  const cdp = await page.context().newCDPSession(page);
  const touch = (type, points) => cdp.send('Input.dispatchTouchEvent', {
    type, touchPoints: points.map(([x, y], id) => ({ x, y, id, radiusX: 2, radiusY: 2, force: 1 })) });
  // The next dump after now (the page's frames go on while the test waits).
  const next = async () => {
    const at = seen.length;
    const deadline = Date.now() + 20000;
    while (seen.length <= at + 1 && Date.now() < deadline) await page.waitForTimeout(20);
    return seen.at(-1);
  };
  const first = await next();
  const cx = first.view.x + first.view.w / 2 + 1, cy = first.view.y + first.view.h / 2;
  await touch('touchStart', [[cx, cy]]);
  await next();  // the finger rests a moment before it drags, as the grab test's mouse does
  for (let i = 1; i <= 30; ++i) await touch('touchMove', [[cx + 4 * i, cy - i]]);
  const during = await next();
  await touch('touchEnd', []);
  const released = await next();
  const held = during.held_vertex;
  assert.ok(held >= 0, 'the finger took hold of a vertex');
  const moved = movedBetween(first, during, held);
  assert.ok(moved > 0.15, `the held vertex followed the finger (moved ${moved})`);
  assert.equal(released.held_vertex, -1, 'lifting the finger lets go');
  assert.equal(during.true_intersections, 0);

  const zoom0 = released.zoom;
  const y = cy + 100;
  await touch('touchStart', [[cx - 40, y], [cx + 40, y]]);
  for (let i = 1; i <= 10; ++i) await touch('touchMove', [[cx - 40 - 8 * i, y], [cx + 40 + 8 * i, y]]);
  await touch('touchEnd', []);
  const pinched = await next();
  assert.ok(Math.abs(pinched.zoom / zoom0 - 3) < 0.05, `spreading two fingers three times as far zooms 3x (${zoom0} -> ${pinched.zoom})`);
  assert.equal(pinched.held_vertex, -1, 'two fingers grab nothing');
  // The page's sound: Web Audio, resumed when the first finger lifted (a user's gesture), asks the
  // app's cue mixer for samples (the cues themselves come from Explore's passes, not from a grab).
  assert.match(pinched.audio.status, /Web Audio/);
  assert.ok(pinched.audio.frames_rendered > 0, `Web Audio asked for samples (${JSON.stringify(pinched.audio)})`);
  await page.close();
});
