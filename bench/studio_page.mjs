// Studio latency, end to end: for each model, `fabvdb studio` (default S_low,
// 10 000 triangles) driven in Debian's chromium (SwiftShader WebGL, as the
// browser tests), each edit type sent as the page's tools send it and timed
// in the page with performance.now from the send to the recoloured, rendered
// parts, next to the server's time (message in to state out) and the
// library's. Prints the medians per edit type. --pause MS waits MS before
// each edit, as a person does between strokes: back to back, the previous
// frame's drawing (WebGL on the same two cores here) still competes with
// the next edit's work.
// Usage: node bench/studio_page.mjs BUILD_DIR [--pause MS] [model ...]  (run from
// the source tree; needs studio/node_modules from npm ci)
import { createRequire } from 'node:module';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { startStudio } from '../studio/tests/server.mjs';

const require = createRequire(new URL('../studio/package.json', import.meta.url));
const { chromium } = require('playwright-core');
const [build, ...rest] = process.argv.slice(2);
const pauseAt = rest.indexOf('--pause');
const pause = pauseAt >= 0 ? Number(rest[pauseAt + 1]) : 0;
const only = pauseAt >= 0 ? rest.filter((_, i) => i !== pauseAt && i !== pauseAt + 1) : rest;
const shared = new URL('../../shared/data/meshes/', import.meta.url).pathname;
const models = { bunny: 'bunny.off', kitten: 'kitten.obj', fertility: 'fertility.off', airplane: 'airplane.obj' };
const repeat = 5;
const median = (v) => { const s = [...v].sort((a, b) => a - b); return s.length ? s[Math.floor((s.length - 1) / 2)] : NaN; };

console.log(`end-to-end latency per edit (ms, median of up to 5, ${pause} ms before each edit): ` +
            'page (send -> recoloured) / server / library');
const browser = await chromium.launch({ executablePath: '/usr/bin/chromium',
                                        args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-sandbox'] });
try {
  for (const [name, file] of Object.entries(models)) {
    if (only.length && !only.includes(name)) continue;
    const out = mkdtempSync(`${tmpdir()}/studio-bench-`);
    const studio = startStudio(`${build}/fabvdb`, `${shared}${file}`, out, []);
    try {
      // bypassCSP: playwright's waitForFunction evaluates a string, which the page's CSP forbids.
      const page = await browser.newPage({ viewport: { width: 1280, height: 800 }, bypassCSP: true });
      await page.goto(await studio.url);
      await page.waitForFunction(() => window.studio?.state && window.studio.viewer.model, null, { timeout: 900000 });
      const result = await page.evaluate(async ([repeat, pause]) => {
        const s = window.studio;
        const wait = () => new Promise((resolve) => {
          const poll = () => (s.pending.size === 0 ? resolve() : setTimeout(poll, 1));
          poll();
        });
        const run = async (op, args) => { await new Promise((r) => setTimeout(r, pause)); s.send(op, args); await wait(); };
        const edit = async (e) => { await new Promise((r) => setTimeout(r, pause)); s.edit(e); await wait(); };
        const radius = s.viewer.size / 40;
        // Boundary points to stroke at, and every point of the lines (how deep in its part a cut lies).
        const boundary = [], boundaryPoints = [];
        for (const l of s.state.boundaries) {
          for (let i = 0; i < l.points.length; i += 3 * Math.max(1, Math.floor(l.points.length / 9))) boundary.push(l.points.slice(i, i + 3));
          for (let i = 0; i < l.points.length; i += 3) boundaryPoints.push(l.points.slice(i, i + 3));
        }
        const records = [];
        const take = (kind) => { const l = s.latencies[s.latencies.length - 1]; records.push({ kind, ...l }); };
        for (let r = 0; r < repeat; ++r) {
          const p = boundary[Math.floor(r * boundary.length / repeat)];
          const before = s.latencies.length;
          await edit({ type: 'no_cut', points: [p], radius });
          if (s.latencies.length > before) { take('no_cut'); await run('undo'); take('undo'); await run('redo'); take('redo'); await run('undo'); }
          const b2 = s.latencies.length;
          await edit({ type: 'smooth', points: [p], radius });
          if (s.latencies.length > b2) { take('smooth'); await run('undo'); }
        }
        // Cuts around patches deep in the largest part (each ring within the
        // part: 0.4 of its centre's depth), and the merges back.
        const largest = [...s.state.parts].sort((a, b) => b.triangles - a.triangles)[0].id;
        const deep = [];
        for (let t = 0; t < s.labels.length; ++t) {
          if (s.labels[t] !== largest) continue;
          const c = s.viewer.centroid(t);
          let d = Infinity;
          for (const b of boundaryPoints) d = Math.min(d, Math.hypot(c[0] - b[0], c[1] - b[1], c[2] - b[2]));
          deep.push([d, t]);
        }
        deep.sort((a, b) => b[0] - a[0]);
        const pos = s.viewer.model.geometry.getAttribute('position').array;
        for (let r = 0; r < repeat; ++r) {
          const [depth, t] = deep[Math.floor(r * Math.min(deep.length, 50) / repeat)];
          const c = s.viewer.centroid(t);
          const a = [0, 1, 2].map((k) => pos[9 * t + k]), b = [0, 1, 2].map((k) => pos[9 * t + 3 + k]), e = [0, 1, 2].map((k) => pos[9 * t + 6 + k]);
          const sub = (x, y) => x.map((v, i) => v - y[i]);
          const cross = (x, y) => [x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]];
          const unit = (x) => { const l = Math.hypot(...x); return x.map((v) => v / l); };
          const n = unit(cross(sub(b, a), sub(e, a)));
          const u = unit(Math.abs(n[0]) < 0.9 ? cross(n, [1, 0, 0]) : cross(n, [0, 1, 0]));
          const v = cross(n, u);
          const ring = Math.min(0.4 * depth, 3 * radius);
          const points = [];
          for (let i = 0; i < 12; ++i) {
            const w = 2 * Math.PI * i / 12;
            points.push(c.map((x, k) => x + ring * (Math.cos(w) * u[k] + Math.sin(w) * v[k])));
          }
          const before = s.latencies.length;
          await edit({ type: 'cut', points, closed: true });
          if (s.latencies.length === before) continue;
          take('cut');
          const b2 = s.latencies.length;
          await edit({ type: 'merge', points: [c, c.map((x, k) => x + 1.6 * ring * u[k])] });
          if (s.latencies.length > b2) { take('merge'); await run('undo'); }
          await run('undo');
        }
        return { records, triangles: s.state.triangles, parts: s.state.parts.length, errors: s.errors };
      }, [repeat, pause]);
      const kinds = ['no_cut', 'cut', 'merge', 'smooth', 'undo', 'redo'];
      const cell = (k, f) => median(result.records.filter((x) => x.kind === k).map((x) => x[f]));
      console.log(`${name.padEnd(10)} S_low ${result.triangles}, ${result.parts} parts: ` +
        kinds.map((k) => `${k} ${cell(k, 'page_ms').toFixed(1)}/${cell(k, 'server_ms').toFixed(1)}/${cell(k, 'library_ms').toFixed(1)}`).join('  '));
      if (result.errors.length) console.log(`  refused edits: ${result.errors.join(' | ')}`);
      await page.close();
    } finally {
      await studio.stop();
      rmSync(out, { recursive: true, force: true });
    }
  }
} finally {
  await browser.close();
}
