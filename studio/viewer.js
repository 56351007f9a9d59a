// viewer.js — the 3-D view: S_low as a flat-shaded mesh with one colour per
// triangle (non-indexed, so triangle t owns vertices 3t..3t+2; the shading is
// baked into the colours, from a light beside the camera, re-baked when an
// orbit ends: the cheapest fragment work, which matters with WebGL on the
// CPU, and 1 byte per channel to upload after an edit), the parting
// lines and part boundaries as line overlays, the brush cursor and stroke
// highlight, click markers of a cut, and the mold pieces. Picking and brush
// queries go through a three-mesh-bvh tree (refitted when S_low moves).
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/OrbitControls.js';
import { acceleratedRaycast, computeBoundsTree, disposeBoundsTree } from 'three-mesh-bvh';

THREE.Mesh.prototype.raycast = acceleratedRaycast;
THREE.BufferGeometry.prototype.computeBoundsTree = computeBoundsTree;
THREE.BufferGeometry.prototype.disposeBoundsTree = disposeBoundsTree;

export class Viewer {
  constructor(container) {
    this.container = container;
    // No multisampling: with WebGL on the CPU (SwiftShader) it doubles the
    // time of a frame; the part boundaries are drawn as lines anyway.
    this.renderer = new THREE.WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(window.devicePixelRatio);
    container.appendChild(this.renderer.domElement);
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(0xf4f4f2);
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.1, 1e5);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.addEventListener('change', () => this.render());
    this.controls.addEventListener('end', () => { if (this.model) { this.bakeShading(); this.render(); } });
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x667788, 1.6));
    const sun = new THREE.DirectionalLight(0xffffff, 1.4);
    sun.position.set(1, 2, 3);
    this.camera.add(sun);
    this.scene.add(this.camera);
    this.model = null;
    this.up = 'z';
    this.lines = new THREE.Group();
    this.boundaryMaterial = new THREE.LineBasicMaterial({ color: 0x111111 });
    this.partingMaterial = new THREE.LineBasicMaterial({ color: 0xffffff });
    this.scene.add(this.lines);
    this.overlay = new THREE.Group();
    this.scene.add(this.overlay);
    this.pieces = new THREE.Group();
    this.pieces.visible = false;
    this.scene.add(this.pieces);
    this.cursor = new THREE.Mesh(new THREE.RingGeometry(0.92, 1, 48),
                                 new THREE.MeshBasicMaterial({ color: 0x111111, side: THREE.DoubleSide, depthTest: false }));
    this.cursor.visible = false;
    this.cursor.renderOrder = 10;
    this.scene.add(this.cursor);
    this.raycaster = new THREE.Raycaster();
    this.raycaster.firstHitOnly = true;
    this.pixel = new Uint8Array(4);
    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
  }

  resize() {
    const w = this.container.clientWidth || 1, h = this.container.clientHeight || 1;
    this.renderer.setSize(w, h);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.render();
  }

  render() { this.renderer.render(this.scene, this.camera); }

  // Returns once the frame rendered last is drawn (a one-pixel read-back), so
  // that an edit's latency includes the drawing, not only its submission.
  waitDrawn() {
    const gl = this.renderer.getContext();
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, this.pixel);
  }

  // S_low from the server: positions (3 per vertex), triangles (3 per triangle).
  setMesh(positions, triangles) {
    const nt = triangles.length / 3;
    const first = !this.model;
    const flat = first ? new Float32Array(9 * nt) : this.model.geometry.getAttribute('position').array;
    for (let t = 0, at = 0; t < nt; ++t)
      for (let k = 0; k < 3; ++k, at += 3) {
        const v = 3 * triangles[3 * t + k];
        flat[at] = positions[v];
        flat[at + 1] = positions[v + 1];
        flat[at + 2] = positions[v + 2];
      }
    if (first) {
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(flat, 3));
      geometry.setAttribute('color', new THREE.BufferAttribute(new Uint8Array(9 * nt), 3, true));
      geometry.computeBoundsTree();
      this.model = new THREE.Mesh(geometry, new THREE.MeshBasicMaterial({
        vertexColors: true, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 }));
      this.scene.add(this.model);
      this.triangleCount = nt;
      this.baseColors = new Float32Array(3 * nt).fill(0.8);
      this.shade = new Float32Array(nt);
      this.positions = positions.slice();
      this.triangles = triangles.slice();
      this.frame();
    } else {
      this.model.geometry.getAttribute('position').needsUpdate = true;
      this.model.geometry.boundsTree.refit();
      this.positions = positions.slice();
    }
    this.bakeShading();
    // A moved S_low comes with the labels and state of its edit, drawn then.
    if (first) this.render();
  }

  // Per-triangle brightness: a light from above the camera's side (flat
  // shading), a sky term from +z, and an ambient floor; then the colours.
  bakeShading() {
    const p = this.model.geometry.getAttribute('position').array;
    const eye = this.camera.position.clone().sub(this.controls.target).normalize();
    const light = eye.add(this.camera.up.clone().multiplyScalar(0.6)).normalize();
    for (let t = 0; t < this.triangleCount; ++t) {
      const o = 9 * t;
      const ax = p[o + 3] - p[o], ay = p[o + 4] - p[o + 1], az = p[o + 5] - p[o + 2];
      const bx = p[o + 6] - p[o], by = p[o + 7] - p[o + 1], bz = p[o + 8] - p[o + 2];
      const nx = ay * bz - az * by, ny = az * bx - ax * bz, nz = ax * by - ay * bx;
      const length = Math.hypot(nx, ny, nz) || 1;
      const facing = (nx * light.x + ny * light.y + nz * light.z) / length;
      const sky = 0.5 + 0.5 * nz / length;
      this.shade[t] = 0.3 + 0.12 * sky + 0.63 * Math.max(0, facing);
    }
    this.applyColors();
  }

  applyColors() {
    const attribute = this.model.geometry.getAttribute('color');
    const array = attribute.array, base = this.baseColors, shade = this.shade;
    for (let t = 0; t < this.triangleCount; ++t) {
      const s = 255 * shade[t];
      const r = Math.min(255, s * base[3 * t]), g = Math.min(255, s * base[3 * t + 1]), b = Math.min(255, s * base[3 * t + 2]);
      for (let k = 9 * t; k < 9 * t + 9; k += 3) { array[k] = r; array[k + 1] = g; array[k + 2] = b; }
    }
    attribute.needsUpdate = true;
  }

  // Points the camera at `object` (S_low, or the mold pieces) from the front
  // right and above, with this.up ('z', 'y' or 'x') up; the model's size
  // (brush radii) is S_low's.
  frame(object = this.model) {
    const box = new THREE.Box3().setFromObject(object);
    const center = box.getCenter(new THREE.Vector3());
    const size = box.getSize(new THREE.Vector3()).length();
    if (object === this.model) this.size = size;
    const view = { z: [[0.55, -0.75, 0.45], [0, 0, 1]], y: [[0.55, 0.45, 0.75], [0, 1, 0]],
                   x: [[0.45, 0.55, 0.75], [1, 0, 0]] }[this.up];
    this.controls.target.copy(center);
    this.camera.position.copy(center).add(new THREE.Vector3(...view[0]).multiplyScalar(1.1 * size));
    this.camera.up.set(...view[1]);
    this.camera.near = size / 1000;
    this.camera.far = size * 100;
    this.camera.updateProjectionMatrix();
    this.controls.update();
  }

  // colors: Float32Array of 3 per triangle (kept; shaded when drawn).
  setColors(colors) {
    this.baseColors.set(colors);
    this.applyColors();
  }

  // lines: [{part, points: [x,y,z,...]}]; style: {color, width}.
  setLines(parting, boundaries, visible) {
    for (const line of this.lines.children) line.geometry.dispose();
    this.lines.clear();
    const add = (list, material) => {
      let count = 0;
      for (const line of list) count += Math.max(0, line.points.length / 3 - 1);
      const segments = new Float32Array(6 * count);
      let at = 0;
      for (const line of list)
        for (let i = 0; i + 5 < line.points.length; i += 3, at += 6)
          for (let k = 0; k < 6; ++k) segments[at + k] = line.points[i + k];
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(segments, 3));
      this.lines.add(new THREE.LineSegments(geometry, material));
    };
    add(boundaries, this.boundaryMaterial);
    add(parting, this.partingMaterial);
    this.lines.visible = visible;
  }

  // The triangle and point under a pointer event, or null.
  pick(event) {
    if (!this.model) return null;
    const rect = this.renderer.domElement.getBoundingClientRect();
    const ndc = new THREE.Vector2(((event.clientX - rect.left) / rect.width) * 2 - 1,
                                  -((event.clientY - rect.top) / rect.height) * 2 + 1);
    this.raycaster.setFromCamera(ndc, this.camera);
    const hit = this.raycaster.intersectObject(this.model)[0];
    if (!hit) return null;
    const index = this.model.geometry.index;
    const triangle = index ? Math.floor(index.getX(3 * hit.faceIndex) / 3) : hit.faceIndex;
    return { point: hit.point.clone(), normal: hit.face.normal.clone(), triangle };
  }

  centroid(t) {
    const p = this.model.geometry.getAttribute('position').array;
    return [0, 1, 2].map((k) => (p[9 * t + k] + p[9 * t + 3 + k] + p[9 * t + 6 + k]) / 3);
  }

  // Triangles with a corner within radius of point (BVH shapecast).
  trianglesNear(point, radius) {
    const sphere = new THREE.Sphere(point, radius);
    const found = [];
    const index = this.model.geometry.index;
    this.model.geometry.boundsTree.shapecast({
      intersectsBounds: (box) => sphere.intersectsBox(box),
      intersectsTriangle: (tri, i) => {
        if (sphere.containsPoint(tri.a) || sphere.containsPoint(tri.b) || sphere.containsPoint(tri.c))
          found.push(index ? Math.floor(index.getX(3 * i) / 3) : i);
        return false;
      },
    });
    return found;
  }

  showCursor(hit, radius) {
    if (!hit) { this.cursor.visible = false; return; }
    this.cursor.visible = true;
    this.cursor.position.copy(hit.point);
    this.cursor.scale.setScalar(radius);
    this.cursor.lookAt(hit.point.clone().add(hit.normal));
  }

  // Markers and a polyline through the cut's points.
  setOverlay(points, closed) {
    this.overlay.clear();
    if (!points.length) { this.render(); return; }
    const r = this.size / 250;
    for (const p of points) {
      const dot = new THREE.Mesh(new THREE.SphereGeometry(r, 12, 8), new THREE.MeshBasicMaterial({ color: 0xd01818, depthTest: false }));
      dot.position.copy(p);
      dot.renderOrder = 11;
      this.overlay.add(dot);
    }
    const path = closed && points.length > 2 ? [...points, points[0]] : points;
    const line = new THREE.Line(new THREE.BufferGeometry().setFromPoints(path),
                                new THREE.LineBasicMaterial({ color: 0xd01818, depthTest: false }));
    line.renderOrder = 11;
    this.overlay.add(line);
    this.render();
  }

  // A mold piece: role 0 part, 1 top mold, 2 bottom mold; pulled apart along d.
  addPiece(piece, direction, color) {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(piece.positions.slice(), 3));
    geometry.setIndex(new THREE.BufferAttribute(piece.triangles.slice(), 1));
    geometry.computeVertexNormals();
    const material = new THREE.MeshStandardMaterial({
      color: new THREE.Color(...color), roughness: 0.6,
      transparent: piece.role !== 0, opacity: piece.role === 0 ? 1 : 0.45, side: THREE.DoubleSide });
    const mesh = new THREE.Mesh(geometry, material);
    const offset = (piece.role === 1 ? 1 : piece.role === 2 ? -1 : 0) * 0.35 * this.size;
    mesh.position.set(direction[0] * offset, direction[1] * offset, direction[2] * offset);
    this.pieces.add(mesh);
  }

  clearPieces() {
    for (const mesh of this.pieces.children) mesh.geometry.dispose();
    this.pieces.clear();
  }
}
