// main.js — the studio page: connects to the server, keeps the current
// decomposition (S_low, labels, sides, deformation, state), colours the view
// by parts / deformation / draft map, fills the panel, routes the tools'
// edits and the keyboard shortcuts, and measures each edit's latency from the
// stroke's end to the recoloured parts drawn (performance.now). window.studio
// exposes the state for the browser tests.
import { Connection } from './connection.js';
import { Viewer } from './viewer.js';
import { Tools, toolHelp } from './tools.js';
import { partColor, heatColor, draftClasses, cssColor } from './colors.js';

const $ = (id) => document.getElementById(id);

class Studio {
  constructor() {
    this.viewer = new Viewer($('view'));
    this.tools = new Tools(this.viewer, this);
    this.labels = null;
    this.sides = null;
    this.heat = null;
    this.draft = null;
    this.state = null;
    this.mode = 'parts';
    this.selectedPart = 0;
    this.busy = true;
    this.pending = new Map(); // seq -> {op, started}
    this.latencies = [];
    this.errors = [];
    this.saved = null;
    this.molded = null;
    this.connection = new Connection({
      open: () => this.status('connected; waiting for the decomposition…'),
      close: () => this.status('disconnected (the studio was stopped?)'),
      message: (m) => this.message(m),
      mesh: (m) => this.mesh(m),
      labels: (l) => { this.labels = l.labels; this.sides = l.sides; this.heat = l.heat; this.partCount = l.parts; },
      draft: (d) => { this.draft = d; this.recolor(); this.drawLegend(); },
      piece: (p) => this.piece(p),
    });
    this.wirePanel();
    this.tools.select('orbit');
  }

  status(text) { $('status').textContent = text; }

  showError(text) {
    this.errors.push(text);
    $('error').hidden = false;
    $('error').textContent = text;
    clearTimeout(this.errorTimer);
    this.errorTimer = setTimeout(() => { $('error').hidden = true; }, 8000);
  }

  send(op, args = '') {
    const seq = this.connection.send(op, args);
    this.pending.set(seq, { op, started: performance.now() });
    return seq;
  }

  edit(edit) {
    if (this.busy) return;
    this.send('edit', JSON.stringify(edit));
  }

  mesh({ positions, triangles }) {
    const first = !this.viewer.model;
    this.viewer.setMesh(positions, triangles);
    if (first) this.tools.setRadius(this.viewer.size / 40);
  }

  message(m) {
    const request = this.pending.get(m.seq);
    if (m.type === 'progress') {
      this.setBusy(true);
      $('progress').hidden = false;
      $('progress-stage').textContent = `${m.stage} ${(100 * m.fraction).toFixed(0)}%`;
      $('progress-fill').style.width = `${100 * m.fraction}%`;
    } else if (m.type === 'busy') {
      this.setBusy(true);
      $('progress').hidden = false;
    } else if (m.type === 'state') {
      this.state = m;
      this.setBusy(false);
      this.draft = null;
      if (this.selectedPart >= m.parts.length) this.selectedPart = 0;
      if (this.mode === 'draft') this.requestDraft();
      this.recolor(null, false);
      this.viewer.setLines(m.parting_lines, m.boundaries, $('lines').checked && !this.viewer.pieces.visible);
      this.viewer.render();
      this.fillPanel();
      if (request) {
        this.viewer.waitDrawn();
        const pageMs = performance.now() - request.started;
        if (request.op === 'edit' || request.op === 'undo' || request.op === 'redo') {
          const record = { op: request.op, page_ms: pageMs, server_ms: m.server_ms, library_ms: m.library_ms };
          this.latencies.push(record);
          $('latency').textContent = `last ${request.op}: ${pageMs.toFixed(1)} ms in the page, ` +
            `${m.server_ms.toFixed(1)} ms on the server, ${m.library_ms.toFixed(1)} ms in the library`;
        }
        this.pending.delete(m.seq);
      }
      this.status(`${m.parts.length} parts, ${m.triangles} triangles on S_low; ${m.edits} edits`);
    } else if (m.type === 'error') {
      if (m.op === 'rerun' || m.op === 'decompose' || m.op === 'mold') this.setBusy(false);
      if (m.op === 'decompose') this.status('the decomposition failed');
      this.showError(`${m.op}: ${m.message}`);
      this.pending.delete(m.seq);
      this.recolor();
    } else if (m.type === 'saved') {
      this.saved = m;
      $('saved').textContent = `saved ${m.decomposition} and ${m.edits}`;
      this.pending.delete(m.seq);
    } else if (m.type === 'molded') {
      this.molded = m;
      this.setBusy(false);
      $('molds-visible').disabled = false;
      $('molds-visible').checked = true;
      this.showPieces(true);
      $('saved').textContent = `molds in ${m.folder}: ` +
        m.parts.map((p) => `part ${p.id} ${p.weight.toFixed(1)} g`).join(', ');
      this.pending.delete(m.seq);
    }
  }

  setBusy(busy) {
    this.busy = busy;
    if (!busy) $('progress').hidden = true;
    for (const id of ['undo', 'redo', 'rerun', 'save', 'mold']) $(id).disabled = busy;
    document.body.classList.toggle('busy', busy);
  }

  piece(p) {
    if (!this.molded && !this.receivingPieces) { this.viewer.clearPieces(); this.receivingPieces = true; }
    const part = this.state.parts[p.part];
    const direction = part ? part.direction : [0, 0, 1];
    const color = partColor(p.part).map((c) => (p.role === 0 ? c : 0.5 + 0.5 * c));
    this.viewer.addPiece(p, direction, color);
  }

  // The next up axis (z, y, x): models made y-up otherwise lie on their side.
  cycleUp() {
    this.viewer.up = { z: 'y', y: 'x', x: 'z' }[this.viewer.up];
    $('up').textContent = `up: ${this.viewer.up}`;
    this.viewer.frame(this.viewer.pieces.visible ? this.viewer.pieces : this.viewer.model);
    this.viewer.bakeShading();
    this.viewer.render();
  }

  showPieces(on) {
    this.viewer.pieces.visible = on;
    this.viewer.model.visible = !on;
    this.viewer.lines.visible = !on && $('lines').checked;
    this.viewer.frame(on ? this.viewer.pieces : this.viewer.model);
    this.viewer.bakeShading();
    this.viewer.render();
  }

  // Colours of the current mode; `highlight`: triangles of a stroke in progress.
  recolor(highlight = null, render = true) {
    if (!this.labels || !this.viewer.model) return;
    const n = this.labels.length;
    if (this.colors?.length !== 3 * n) this.colors = new Float32Array(3 * n);
    const colors = this.colors;
    const sides = $('sides').checked;
    let highest = 0;
    if (this.mode === 'heat') for (let t = 0; t < n; ++t) highest = Math.max(highest, this.heat[t]);
    const palette = new Map();
    for (let t = 0; t < n; ++t) {
      let c, scale = 1, lift = 0;
      if (this.mode === 'heat') c = heatColor(highest > 0 ? this.heat[t] / highest : 0);
      else if (this.mode === 'draft' && this.draft) c = draftClasses[this.draft[t]].color;
      else {
        const label = this.labels[t];
        c = palette.get(label);
        if (!c) palette.set(label, (c = partColor(label)));
        if (sides && !this.sides[t]) scale = 0.55;
        if (this.highlightedPart !== undefined && label === this.highlightedPart) { scale *= 0.5; lift = 0.5; }
      }
      colors[3 * t] = lift + scale * c[0];
      colors[3 * t + 1] = lift + scale * c[1];
      colors[3 * t + 2] = lift + scale * c[2];
    }
    if (highlight) for (const t of highlight) colors.set([0.95, 0.25, 0.75], 3 * t);
    this.viewer.setColors(colors);
    if (render) this.viewer.render();
    this.heatRange = [0, highest];
  }

  highlightPart(part) {
    this.highlightedPart = part;
    this.recolor();
    this.highlightedPart = undefined;
  }

  requestDraft() {
    const part = this.state?.parts[this.selectedPart];
    if (!part) return;
    const d = part.direction;
    this.send('draft', `${d[0]} ${d[1]} ${d[2]} ${this.state.draft_degrees}`);
  }

  drawLegend() {
    const legend = $('legend');
    legend.innerHTML = '';
    if (this.mode === 'heat') {
      const canvas = document.createElement('canvas');
      canvas.width = 256;
      canvas.height = 1;
      const g = canvas.getContext('2d');
      for (let i = 0; i < 256; ++i) { g.fillStyle = cssColor(heatColor(i / 255)); g.fillRect(i, 0, 1, 1); }
      legend.append('deformation (energy per unit-cube area)', canvas);
      const ends = document.createElement('div');
      ends.className = 'ends';
      ends.innerHTML = `<span>0</span><span>${(this.heatRange?.[1] ?? 0).toPrecision(3)}</span>`;
      legend.append(ends);
    } else if (this.mode === 'draft') {
      const counts = [0, 0, 0, 0];
      if (this.draft) for (const c of this.draft) ++counts[c];
      const total = this.draft ? this.draft.length : 1;
      const part = this.state?.parts[this.selectedPart];
      legend.innerHTML = `draft map for part ${this.selectedPart}'s direction d = ` +
        `(${part ? part.direction.map((x) => x.toFixed(2)).join(', ') : '–'}), draft ${this.state?.draft_degrees ?? '–'}°<br>` +
        draftClasses.map((k, i) => `<span class="swatch" style="background:${cssColor(k.color)}"></span> ${k.name}: ` +
          `${(100 * counts[i] / total).toFixed(1)}%`).join('<br>');
    } else {
      legend.textContent = $('sides').checked ? 'each part its colour; M⁻ (the half pulled along −d) darker' : 'each part its colour';
    }
  }

  fillPanel() {
    const s = this.state;
    $('total').textContent = s.total_energy.toPrecision(4);
    $('gamma-now').textContent = s.gamma.toPrecision(3);
    $('warning').hidden = !s.over_gamma;
    $('total').style.color = s.over_gamma ? '#c04000' : '#207020';
    if (document.activeElement?.tagName !== 'INPUT') {
      $('gamma').value = s.gamma;
      $('part-count').value = s.parts_setting;
      $('draft').value = s.draft_degrees;
    }
    $('undo').disabled = s.undo === 0;
    $('redo').disabled = s.redo === 0;
    const body = $('parts').querySelector('tbody');
    body.innerHTML = '';
    for (const p of s.parts) {
      const row = document.createElement('tr');
      if (p.id === this.selectedPart) row.className = 'selected';
      row.innerHTML = `<td><span class="swatch" style="background:${cssColor(partColor(p.id))}"></span></td>` +
        `<td>${p.id}</td><td>${p.direction.map((x) => x.toFixed(2)).join(' ')}</td>` +
        `<td>${p.energy.toPrecision(3)}</td><td>${p.area.toPrecision(3)}</td>`;
      row.addEventListener('click', () => {
        this.selectedPart = p.id;
        this.fillPanel();
        if (this.mode === 'draft') this.requestDraft();
      });
      body.append(row);
    }
    this.drawLegend();
  }

  toolChanged(tool) {
    for (const b of document.querySelectorAll('[data-tool]')) b.classList.toggle('active', b.dataset.tool === tool);
    $('tool-help').textContent = toolHelp[tool];
    this.viewer.showCursor(null);
    this.viewer.render();
  }

  radiusChanged(radius) { $('radius').textContent = radius.toPrecision(3); }

  rerun() {
    const gamma = parseFloat($('gamma').value), parts = parseInt($('part-count').value || '0', 10);
    const draft = parseFloat($('draft').value);
    if (!(gamma > 0) || !(parts >= 0) || !(draft >= 0 && draft <= 30)) {
      this.showError('re-run: γ must be > 0, parts >= 0 (0: automatic), draft in [0, 30]');
      return;
    }
    this.setBusy(true);
    $('progress').hidden = false;
    this.send('rerun', `${gamma} ${parts} ${draft}`);
  }

  wirePanel() {
    for (const b of document.querySelectorAll('[data-tool]')) b.addEventListener('click', () => this.tools.select(b.dataset.tool));
    $('undo').addEventListener('click', () => this.send('undo'));
    $('redo').addEventListener('click', () => this.send('redo'));
    $('rerun').addEventListener('click', () => this.rerun());
    $('save').addEventListener('click', () => this.send('save'));
    $('mold').addEventListener('click', () => {
      this.molded = null;
      this.receivingPieces = false;
      this.setBusy(true);
      $('progress').hidden = false;
      $('progress-stage').textContent = '';
      $('progress-fill').style.width = '0';
      this.send('mold');
    });
    $('cancel').addEventListener('click', () => this.connection.send('cancel'));
    for (const r of document.querySelectorAll('input[name=colour]'))
      r.addEventListener('change', () => {
        this.mode = r.value;
        if (this.mode === 'draft') this.requestDraft();
        this.recolor();
        this.drawLegend();
      });
    $('sides').addEventListener('change', () => { this.recolor(); this.drawLegend(); });
    $('lines').addEventListener('change', () => { this.viewer.lines.visible = $('lines').checked; this.viewer.render(); });
    $('molds-visible').addEventListener('change', () => this.showPieces($('molds-visible').checked));
    $('up').addEventListener('click', () => this.cycleUp());
    window.addEventListener('keydown', (e) => this.key(e));
  }

  key(e) {
    if (e.target.tagName === 'INPUT') return;
    const ctrl = e.ctrlKey || e.metaKey;
    const k = e.key.toLowerCase();
    if (ctrl && k === 'z') { e.preventDefault(); if (!this.busy) this.send(e.shiftKey ? 'redo' : 'undo'); }
    else if (ctrl && k === 'y') { e.preventDefault(); if (!this.busy) this.send('redo'); }
    else if (ctrl && k === 's') { e.preventDefault(); if (!this.busy) this.send('save'); }
    else if (ctrl) return;
    else if (k === 'o') this.tools.select('orbit');
    else if (k === 'n') this.tools.select('no_cut');
    else if (k === 's') this.tools.select('smooth');
    else if (k === 'c') this.tools.select('cut');
    else if (k === 'm') this.tools.select('merge');
    else if (k === 'r') { if (!this.busy) this.rerun(); }
    else if (k === 'u') this.cycleUp();
    else if (e.key === 'Enter') this.tools.applyCut(e.shiftKey);
    else if (e.key === 'Backspace') this.tools.dropCutPoint();
    else if (e.key === 'Escape') this.tools.clear();
  }
}

window.studio = new Studio();
