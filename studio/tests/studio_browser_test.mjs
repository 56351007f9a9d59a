// studio_browser_test.mjs — the studio in a real browser (Debian's chromium,
// WebGL on the CPU through SwiftShader, driven by playwright-core): loads the
// shared bunny, waits for the parts, paints a no-cut stroke across a part
// boundary with the mouse, draws a closed cut of clicked points around a
// patch inside a part, merges the patch back by clicking the two parts,
// undoes the merge with Ctrl+Z, saves with Ctrl+S; the saved decomposition
// passes the independent checks (CHECKER), its edit list replayed by
// `fabvdb decompose --edits` gives the same labels, a bad message (oversized,
// malformed edit, an edit that does not apply) is refused and leaves the
// session as it was; Make molds shows its progress and Cancel stops it with an
// error in the page and the session as it was; Make molds run to the end
// shows the pieces, and each cast part and mold piece passes the independent
// checks (CHECKER --cast); the draft map arrives for a part's direction; U
// cycles the view's up axis;
// screenshots are written to WORK_DIR/browser/studio.png and studio-molds.png.
// Usage: node studio_browser_test.mjs FABVDB SHARED_DATA CHECKER WORK_DIR
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdirSync, readFileSync, rmSync } from 'node:fs';
import { chromium } from 'playwright-core';
import { startStudio } from './server.mjs';

const [fabvdb, shared, checker, work] = process.argv.slice(2);
const dir = `${work}/browser`;
rmSync(dir, { recursive: true, force: true });
mkdirSync(dir, { recursive: true });
const model = `${shared}/meshes/bunny.off`;
const settings = ['--low-res', '3000', '--parts', '3'];

let passed = 0;
const step = (name) => { ++passed; console.log(`ok ${passed} - ${name}`); };

const studio = startStudio(fabvdb, model, `${dir}/out`, settings);
const browser = await chromium.launch({
  executablePath: '/usr/bin/chromium',
  args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-sandbox'],
});
try {
  const url = await studio.url;
  // bypassCSP: playwright's waitForFunction with an argument evaluates a string, which the page's CSP forbids.
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 }, bypassCSP: true });
  const pageErrors = [];
  page.on('pageerror', (e) => pageErrors.push(String(e)));
  await page.goto(url);
  await page.waitForFunction(() => window.studio?.state && window.studio.viewer.model, null, { timeout: 600000 });
  const first = await page.evaluate(() => ({ parts: studio.state.parts.length, triangles: studio.state.triangles }));
  assert.equal(first.parts, 3);
  step(`the page shows ${first.parts} parts on ${first.triangles} triangles`);

  // Aims the camera at a point along its outward normal; returns the screen
  // position of the point and the pixels per mm there.
  const aim = (point) => page.evaluate((p) => {
    const v = studio.viewer;
    const V = v.camera.position.constructor;
    const pos = v.model.geometry.getAttribute('position').array;
    let best = 0, bestD = Infinity;
    for (let t = 0; t < pos.length / 9; ++t) {
      const c = studio.viewer.centroid(t);
      const d = (c[0] - p[0]) ** 2 + (c[1] - p[1]) ** 2 + (c[2] - p[2]) ** 2;
      if (d < bestD) { bestD = d; best = t; }
    }
    const a = new V(pos[9 * best], pos[9 * best + 1], pos[9 * best + 2]);
    const b = new V(pos[9 * best + 3], pos[9 * best + 4], pos[9 * best + 5]);
    const c = new V(pos[9 * best + 6], pos[9 * best + 7], pos[9 * best + 8]);
    const n = b.clone().sub(a).cross(c.clone().sub(a)).normalize();
    const P = new V(...p);
    v.controls.target.copy(P);
    v.camera.position.copy(P).addScaledVector(n, 0.45 * v.size);
    v.camera.up.set(...(Math.abs(n.z) > 0.9 ? [0, 1, 0] : [0, 0, 1]));
    v.controls.update();
    v.render();
    const rect = v.renderer.domElement.getBoundingClientRect();
    const screen = (q) => { const s = q.clone().project(v.camera); return [rect.left + (s.x + 1) / 2 * rect.width, rect.top + (1 - s.y) / 2 * rect.height]; };
    const tangent = new V(1, 0, 0).cross(n).lengthSq() > 0.1 ? new V(1, 0, 0).cross(n).normalize() : new V(0, 1, 0).cross(n).normalize();
    const [x, y] = screen(P);
    const [x2, y2] = screen(P.clone().addScaledVector(tangent, 1));
    return { x, y, pxPerMm: Math.hypot(x2 - x, y2 - y), n: [n.x, n.y, n.z] };
  }, point);
  const pickAt = (x, y) => page.evaluate(([cx, cy]) => {
    const hit = studio.viewer.pick({ clientX: cx, clientY: cy });
    return hit ? { point: [hit.point.x, hit.point.y, hit.point.z], triangle: hit.triangle } : null;
  }, [x, y]);
  const dist = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
  const waitEdits = (count) => page.waitForFunction((c) => studio.state.edits === c && studio.pending.size === 0, count, { timeout: 60000 });

  // 1. A no-cut stroke across a boundary.
  const boundary = await page.evaluate(() => {
    const lines = [...studio.state.boundaries].sort((a, b) => b.points.length - a.points.length);
    return lines.map((l) => { const i = 3 * Math.floor(l.points.length / 6); return l.points.slice(i, i + 3); });
  });
  const radius = await page.evaluate(() => studio.tools.radius);
  let target = null;
  for (const p of boundary) {
    const at = await aim(p);
    const hit = await pickAt(at.x, at.y);
    if (hit && dist(hit.point, p) < radius / 4) { target = { p, ...at }; break; }
  }
  assert.ok(target, 'no boundary point is visible from its normal');
  const crossed = await page.evaluate(([p, r]) => {
    const seen = new Set();
    for (let t = 0; t < studio.labels.length; ++t) {
      const c = studio.viewer.centroid(t);
      if (Math.hypot(c[0] - p[0], c[1] - p[1], c[2] - p[2]) <= r) seen.add(studio.labels[t]);
    }
    return seen.size;
  }, [target.p, radius]);
  assert.ok(crossed >= 2, 'the brush does not cross a boundary');
  await page.keyboard.press('n');
  await page.mouse.move(target.x - 4, target.y);
  await page.mouse.down();
  await page.mouse.move(target.x, target.y, { steps: 3 });
  await page.mouse.move(target.x + 4, target.y, { steps: 3 });
  await page.mouse.up();
  await waitEdits(1);
  const oneAfter = await page.evaluate(([p, r]) => {
    const seen = new Set();
    for (let t = 0; t < studio.labels.length; ++t) {
      const c = studio.viewer.centroid(t);
      if (Math.hypot(c[0] - p[0], c[1] - p[1], c[2] - p[2]) <= r * 0.9) seen.add(studio.labels[t]);
    }
    return seen.size;
  }, [target.p, radius]);
  assert.equal(oneAfter, 1, 'the painted region is not in one part');
  step('a no-cut stroke across a boundary leaves the painted region in one part');

  // 2. A closed cut of clicked points around a patch deep inside the largest part.
  const deep = await page.evaluate(() => {
    const s = studio.state;
    const largest = [...s.parts].sort((a, b) => b.triangles - a.triangles)[0].id;
    const bpts = [];
    for (const l of s.boundaries) for (let i = 0; i < l.points.length; i += 3) bpts.push(l.points.slice(i, i + 3));
    let best = null, bestD = -1;
    for (let t = 0; t < studio.labels.length; ++t) {
      if (studio.labels[t] !== largest) continue;
      const c = studio.viewer.centroid(t);
      let d = Infinity;
      for (const b of bpts) d = Math.min(d, Math.hypot(c[0] - b[0], c[1] - b[1], c[2] - b[2]));
      if (d > bestD) { bestD = d; best = c; }
    }
    return { centre: best, depth: bestD, parts: s.parts.length };
  });
  const around = await aim(deep.centre);
  // Points on the tangent plane at the centre, and where they are on the screen.
  const unit = (x) => { const l = Math.hypot(...x); return x.map((q) => q / l); };
  const cross = (x, y) => [x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]];
  const u = unit(cross(around.n, Math.abs(around.n[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0]));
  const w = cross(around.n, u);
  // The surface point nearest the tangent-plane point at radius r and angle a round the centre
  // (the centroid of the nearest S_low triangle).
  const onSurface = (r, a) => page.evaluate((p) => {
    let best = null, bestD = Infinity;
    for (let t = 0; t < studio.labels.length; ++t) {
      const c = studio.viewer.centroid(t);
      const d = Math.hypot(c[0] - p[0], c[1] - p[1], c[2] - p[2]);
      if (d < bestD) { bestD = d; best = c; }
    }
    return best;
  }, deep.centre.map((c, k) => c + r * (Math.cos(a) * u[k] + Math.sin(a) * w[k])));
  const project = (points) => page.evaluate((pts) => {
    const v = studio.viewer;
    const V = v.camera.position.constructor;
    const rect = v.renderer.domElement.getBoundingClientRect();
    return pts.map((p) => {
      const q = new V(...p).project(v.camera);
      return [rect.left + (q.x + 1) / 2 * rect.width, rect.top + (1 - q.y) / 2 * rect.height];
    });
  }, points);
  const largest = await page.evaluate(() => [...studio.state.parts].sort((a, b) => b.triangles - a.triangles)[0].id);
  // `at` when a click there lands on the surface within `tolerance` of `intended` and in the
  // largest part; else null.
  const landing = async (at, intended, tolerance) => {
    const hit = await pickAt(...at);
    if (!hit || dist(hit.point, intended) > tolerance) return null;
    const label = await page.evaluate((t) => studio.labels[t], hit.triangle);
    return label === largest ? at : null;
  };
  // The largest ring (up to 0.4 of the depth) of 10 surface points whose clicks all land where
  // meant, and a click outside it, still in the part, for the merge.
  let ring = null, outside = null;
  for (const k of [0.4, 0.3, 0.22, 0.16, 0.12, 0.08]) {
    const r = k * deep.depth;
    const points = [];
    for (let i = 0; i < 10; ++i) points.push(await onSurface(r, (2 * Math.PI * i) / 10));
    const screen = await project(points);
    const landed = [];
    for (let i = 0; i < 10; ++i) landed.push(await landing(screen[i], points[i], 0.2 * r));
    if (landed.some((x) => !x)) continue;
    outside = null;
    for (let i = 0; i < 8 && !outside; ++i) {
      const p = await onSurface(1.8 * r, (2 * Math.PI * i) / 8);
      outside = await landing((await project([p]))[0], p, 0.2 * r);
    }
    if (!outside) continue;
    ring = screen;
    break;
  }
  assert.ok(ring, 'no ring of clicks around the patch lands on the part');
  await page.keyboard.press('c');
  for (const [x, y] of ring) await page.mouse.click(x, y);
  assert.equal(await page.evaluate(() => studio.tools.cutPoints.length), 10, 'a click of the cut missed the surface');
  await page.keyboard.press('Shift+Enter');
  await waitEdits(2);
  const afterCut = await page.evaluate(() => studio.state.parts.length);
  assert.equal(afterCut, deep.parts + 1, 'the closed cut did not split off one part');
  const patch = await page.evaluate(([x, y]) => studio.labels[studio.viewer.pick({ clientX: x, clientY: y }).triangle],
                                    [around.x, around.y]);
  const patchSize = await page.evaluate((p) => studio.state.parts[p].triangles, patch);
  assert.ok(patchSize < 0.5 * first.triangles, 'the cut-off patch is not the small piece inside the ring');
  step(`a closed cut of 10 clicked points splits off a patch of ${patchSize} triangles (${deep.parts} -> ${afterCut} parts)`);

  // 3. Merge: click the patch, then the part around it.
  await page.keyboard.press('m');
  await page.mouse.click(around.x, around.y);
  await page.mouse.click(...outside);
  await waitEdits(3);
  assert.equal(await page.evaluate(() => studio.state.parts.length), deep.parts);
  step('merging the patch with the part around it by two clicks');

  // 4. Undo with Ctrl+Z.
  await page.keyboard.press('Control+z');
  await waitEdits(2);
  assert.equal(await page.evaluate(() => studio.state.parts.length), afterCut);
  step('Ctrl+Z undoes the merge');

  // 5. Bad messages: oversized, malformed, not applicable; the session unchanged.
  const before = await page.evaluate(() => ({ energy: studio.state.total_energy, labels: Array.from(studio.labels) }));
  const bad = await page.evaluate(async () => {
    const url = `ws://${location.host}${location.pathname}ws`;
    const talk = (messages, until) => new Promise((resolve) => {
      const ws = new WebSocket(url);
      ws.binaryType = 'arraybuffer';
      const got = [];
      let closed = false;
      ws.onopen = () => messages.forEach((m) => ws.send(m));
      ws.onmessage = (e) => {
        if (typeof e.data !== 'string') return;
        got.push(JSON.parse(e.data));
        if (until(got)) { ws.close(); resolve({ got, closed }); }
      };
      ws.onclose = () => { closed = true; resolve({ got, closed }); };
      setTimeout(() => resolve({ got, closed, timeout: true }), 20000);
    });
    const errors = (got) => got.filter((m) => m.type === 'error');
    const oversized = await talk(['x'.repeat(300000)], (g) => false);
    const malformed = await talk(['7 edit {"type": "cut", "points": [[0, 0'], (g) => errors(g).length >= 1);
    const unknown = await talk(['8 edit {"type": "fold", "points": [[0, 0, 0]]}'], (g) => errors(g).length >= 1);
    const c = studio.viewer.centroid(0), d = studio.viewer.centroid(1);
    const same = await talk([`9 edit ${JSON.stringify({ type: 'merge', points: [c, c] })}`], (g) => errors(g).length >= 1);
    const garbage = await talk(['hello'], (g) => errors(g).length >= 1);
    const state = await talk([], (g) => g.some((m) => m.type === 'state'));
    return { oversized, malformed, unknown, same, garbage, state: state.got.find((m) => m.type === 'state') };
  });
  // civetweb may close on a frame this large before the handler sees it, or hand it over in
  // pieces (refused as not whole): either way the connection is closed and nothing applied.
  assert.ok(bad.oversized.closed, 'an oversized message does not close the connection');
  assert.ok(!bad.oversized.got.some((m) => m.type === 'state' && m.seq !== 0), 'an oversized message changed the session');
  assert.match(bad.malformed.got.find((m) => m.type === 'error').message, /not valid JSON/);
  assert.match(bad.unknown.got.find((m) => m.type === 'error').message, /unknown type "fold"/);
  assert.match(bad.same.got.find((m) => m.type === 'error').message, /same part/);
  assert.ok(bad.garbage.got.find((m) => m.type === 'error'));
  assert.equal(bad.state.edits, 2);
  assert.equal(bad.state.total_energy, before.energy);
  const after = await page.evaluate(() => Array.from(studio.labels));
  assert.deepEqual(after, before.labels);
  step('oversized, malformed, unknown and inapplicable messages get errors; the session is unchanged');

  // 6. Save with Ctrl+S; the independent checks and the replay.
  await page.keyboard.press('Control+s');
  await page.waitForFunction(() => studio.saved, null, { timeout: 60000 });
  const saved = await page.evaluate(() => studio.saved);
  execFileSync(checker, [saved.decomposition], { stdio: 'inherit' });
  step('the saved decomposition passes the independent checks (disjoint, covering, connected, M+/M- connected)');
  const edits = JSON.parse(readFileSync(saved.edits, 'utf8'));
  assert.deepEqual(edits.edits.map((e) => e.type), ['no_cut', 'cut']);
  execFileSync(fabvdb, ['decompose', model, ...settings, '--edits', saved.edits, '-o', `${dir}/replay`, '-q']);
  const replayed = JSON.parse(readFileSync(`${dir}/replay/decomposition.json`, 'utf8'));
  const ours = JSON.parse(readFileSync(saved.decomposition, 'utf8'));
  assert.deepEqual(replayed.part_of_triangle, ours.part_of_triangle);
  step('fabvdb decompose --edits replays the saved edit list to the same parts');

  // 7. Make molds, cancelled once its progress shows: an error in the page, the session as it was.
  await page.click('#mold');
  await page.waitForFunction(() => document.getElementById('progress-stage').textContent !== '', null, { timeout: 120000 });
  const stage = await page.evaluate(() => document.getElementById('progress-stage').textContent);
  await page.click('#cancel');
  await page.waitForFunction(() => !studio.busy, null, { timeout: 120000 });
  const cancelled = await page.evaluate(() => ({ error: studio.errors[studio.errors.length - 1], molded: studio.molded,
                                                 labels: Array.from(studio.labels) }));
  assert.equal(cancelled.molded, null);
  assert.match(cancelled.error, /^mold: .*cancel/i);
  assert.deepEqual(cancelled.labels, before.labels);
  step(`Make molds shows its progress (${stage}) and Cancel stops it: ${cancelled.error}`);

  // 7b. Make molds to the end: the pieces are shown, and each cast part and
  // its two mold pieces pass the independent checks along the part's direction.
  await page.click('#mold');
  await page.waitForFunction(() => studio.molded, null, { timeout: 600000 });
  const made = await page.evaluate(() => ({ molded: studio.molded, pieces: studio.viewer.pieces.children.length,
                                            shown: studio.viewer.pieces.visible,
                                            directions: studio.state.parts.map((p) => p.direction) }));
  assert.equal(made.molded.parts.length, made.directions.length);
  assert.equal(made.pieces, 3 * made.directions.length);
  assert.ok(made.shown);
  for (const part of made.molded.parts) {
    const id = String(part.id).padStart(2, '0');
    const folder = made.molded.folder;
    execFileSync(checker, ['--cast', `${folder}/parts/part_${id}.stl`, `${folder}/molds/part_${id}_top.stl`,
                           `${folder}/molds/part_${id}_bottom.stl`, ...made.directions[part.id].map(String)],
                 { stdio: 'inherit' });
    assert.ok(part.weight > 0);
  }
  await page.screenshot({ path: `${dir}/studio-molds.png` });
  await page.click('#molds-visible');
  step(`Make molds to the end: ${made.pieces} pieces shown, each part and mold piece passes the independent checks; ` +
       `screenshot ${dir}/studio-molds.png`);

  // 8. The draft map for a part's direction, and a screenshot.
  await page.check('input[value=draft]');
  await page.waitForFunction(() => studio.draft && studio.draft.length === studio.labels.length, null, { timeout: 60000 });
  await page.check('input[value=parts]');
  // U cycles the up axis z -> y -> x -> z, for models made y-up or x-up
  // (keys go to the view, not to a focused input).
  await page.evaluate(() => document.activeElement.blur());
  const ups = [];
  for (let i = 0; i < 3; ++i) {
    await page.keyboard.press('u');
    ups.push(await page.evaluate(() => [document.getElementById('up').textContent,
                                        studio.viewer.camera.up.toArray().join(',')]));
  }
  assert.deepEqual(ups, [['up: y', '0,1,0'], ['up: x', '1,0,0'], ['up: z', '0,0,1']]);
  step('U cycles the up axis: y, x, z');
  await page.keyboard.press('o');
  await page.evaluate(() => { studio.viewer.frame(); studio.viewer.render(); });
  await page.screenshot({ path: `${dir}/studio.png` });
  step(`draft map received; screenshot ${dir}/studio.png`);
  const latencies = await page.evaluate(() => studio.latencies);
  for (const l of latencies)
    console.log(`# ${l.op}: page ${l.page_ms.toFixed(1)} ms, server ${l.server_ms.toFixed(1)} ms, library ${l.library_ms.toFixed(1)} ms`);
  assert.deepEqual(pageErrors, []);
} finally {
  await browser.close();
  const { code, signal } = await studio.stop();
  assert.equal(signal, null, `the studio died of ${signal}: ${studio.stderr()}`);
  assert.equal(code, 0, `the studio exited ${code}: ${studio.stderr()}`);
}
console.log(`${passed} passed, 0 failed`);
