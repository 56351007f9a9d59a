// tools.js — the four editing tools on the 3-D view (thesis §3.5, as in
// Meshmixer and SOLIDWORKS Mold Tools): the no-cut and smooth brushes (drag
// to paint, mouse wheel sets the radius, the painted triangles highlighted;
// one stroke = one edit), the cut (click points on the surface, Enter
// applies, Shift+Enter closes the loop, Backspace drops the last point) and
// the merge (click two parts). While a tool is on, the left button edits and
// the right button orbits; the Orbit tool gives the left button back to the view.

export const toolHelp = {
  orbit: 'Left drag orbits, right drag pans, wheel zooms.',
  no_cut: 'Paint across a boundary: the painted region ends up in one part. Wheel: radius.',
  smooth: 'Paint along a part boundary to smooth it there. Wheel: radius.',
  cut: 'Click points on the surface; Enter cuts, Shift+Enter closes the loop, Backspace undoes a point.',
  merge: 'Click a part, then a neighbouring part: they become one.',
};

export class Tools {
  constructor(viewer, studio) {
    this.viewer = viewer;
    this.studio = studio;
    this.tool = 'orbit';
    this.radius = 1;
    this.stroke = null;
    this.cutPoints = [];
    this.mergeFirst = null;
    const canvas = viewer.renderer.domElement;
    canvas.addEventListener('pointerdown', (e) => this.down(e));
    canvas.addEventListener('pointermove', (e) => this.move(e));
    canvas.addEventListener('pointerup', (e) => this.up(e));
    canvas.addEventListener('pointerleave', () => { viewer.showCursor(null); viewer.render(); });
    canvas.addEventListener('wheel', (e) => this.wheel(e), { passive: false, capture: true });
  }

  setRadius(radius) {
    this.radius = radius;
    this.studio.radiusChanged(radius);
  }

  brush() { return this.tool === 'no_cut' || this.tool === 'smooth'; }

  select(tool) {
    this.tool = tool;
    this.clear();
    const controls = this.viewer.controls;
    // Tools take the left button; the right button orbits meanwhile.
    controls.mouseButtons.LEFT = tool === 'orbit' ? 0 : -1;
    controls.mouseButtons.RIGHT = tool === 'orbit' ? 2 : 0;
    this.studio.toolChanged(tool);
  }

  clear() {
    this.stroke = null;
    this.cutPoints = [];
    this.mergeFirst = null;
    this.viewer.setOverlay([], false);
    this.studio.recolor();
  }

  down(event) {
    if (event.button !== 0 || this.tool === 'orbit' || this.studio.busy) return;
    const hit = this.viewer.pick(event);
    if (!hit) return;
    if (this.brush()) {
      this.stroke = { points: [hit.point], highlighted: new Set() };
      this.paint(hit.point);
      this.viewer.renderer.domElement.setPointerCapture(event.pointerId);
    } else if (this.tool === 'cut') {
      this.cutPoints.push(hit.point);
      this.viewer.setOverlay(this.cutPoints, false);
    } else if (this.tool === 'merge') {
      const part = this.studio.labels[hit.triangle];
      if (this.mergeFirst === null) {
        this.mergeFirst = hit.triangle;
        this.studio.highlightPart(part);
      } else if (this.studio.labels[this.mergeFirst] === part) {
        this.studio.showError('merge: click a different part');
      } else {
        const a = this.viewer.centroid(this.mergeFirst), b = this.viewer.centroid(hit.triangle);
        this.mergeFirst = null;
        this.studio.edit({ type: 'merge', points: [a, b] });
      }
    }
  }

  paint(point) {
    for (const t of this.viewer.trianglesNear(point, this.radius)) this.stroke.highlighted.add(t);
    this.studio.recolor(this.stroke.highlighted);
  }

  move(event) {
    if (!this.brush()) return;
    const hit = this.viewer.pick(event);
    this.viewer.showCursor(hit, this.radius);
    if (this.stroke && hit) {
      const last = this.stroke.points[this.stroke.points.length - 1];
      if (last.distanceTo(hit.point) > this.radius / 3 && this.stroke.points.length < 1000) {
        this.stroke.points.push(hit.point);
        this.paint(hit.point);
      }
    }
    this.viewer.render();
  }

  up(event) {
    if (!this.stroke || event.button !== 0) return;
    const points = this.stroke.points.map((p) => [p.x, p.y, p.z]);
    this.stroke = null;
    this.studio.edit({ type: this.tool, points, radius: this.radius });
  }

  applyCut(closed) {
    if (this.tool !== 'cut' || this.cutPoints.length < 2) return;
    const points = this.cutPoints.map((p) => [p.x, p.y, p.z]);
    this.cutPoints = [];
    this.viewer.setOverlay([], false);
    this.studio.edit({ type: 'cut', points, closed });
  }

  dropCutPoint() {
    this.cutPoints.pop();
    this.viewer.setOverlay(this.cutPoints, false);
  }

  wheel(event) {
    if (!this.brush() || event.shiftKey) return;
    event.preventDefault();
    event.stopImmediatePropagation();
    this.setRadius(Math.max(this.viewer.size / 500, this.radius * (event.deltaY > 0 ? 1 / 1.1 : 1.1)));
    this.viewer.showCursor(this.viewer.pick(event), this.radius);
    this.viewer.render();
  }
}
