// connection.js — the studio's one WebSocket: sends "SEQ OP ARGS" text
// messages (tools/studio/studio_server.h), decodes the binary frames (S_low mesh,
// labels/sides/deformation, draft map, mold pieces) and hands every message
// to the listeners given. The token is the first segment of the page's path.

export class Connection {
  constructor(handlers) {
    this.handlers = handlers;
    this.seq = 0;
    const base = location.pathname.endsWith('/') ? location.pathname : location.pathname + '/';
    this.socket = new WebSocket(`ws://${location.host}${base}ws`);
    this.socket.binaryType = 'arraybuffer';
    this.socket.onopen = () => handlers.open?.();
    this.socket.onclose = () => handlers.close?.();
    this.socket.onmessage = (event) => {
      if (typeof event.data === 'string') handlers.message?.(JSON.parse(event.data));
      else this.decode(event.data);
    };
  }

  // Sends one operation; returns its sequence number.
  send(op, args = '') {
    const seq = ++this.seq;
    this.socket.send(args === '' ? `${seq} ${op}` : `${seq} ${op} ${args}`);
    return seq;
  }

  decode(buffer) {
    const view = new DataView(buffer);
    const kind = view.getUint32(0, true);
    if (kind === 1) {
      const nv = view.getUint32(4, true), nt = view.getUint32(8, true);
      this.handlers.mesh?.({
        positions: new Float32Array(buffer, 12, 3 * nv),
        triangles: new Uint32Array(buffer, 12 + 12 * nv, 3 * nt),
      });
    } else if (kind === 2) {
      const nt = view.getUint32(4, true), parts = view.getUint32(8, true);
      this.handlers.labels?.({
        parts,
        labels: new Int32Array(buffer, 12, nt),
        heat: new Float32Array(buffer, 12 + 4 * nt, nt),
        sides: new Uint8Array(buffer, 12 + 8 * nt, nt),
      });
    } else if (kind === 3) {
      const nt = view.getUint32(4, true);
      this.handlers.draft?.(new Uint8Array(buffer, 8, nt));
    } else if (kind === 4) {
      const role = view.getUint32(4, true), part = view.getUint32(8, true);
      const nv = view.getUint32(12, true), nt = view.getUint32(16, true);
      this.handlers.piece?.({
        role, part,
        positions: new Float32Array(buffer, 20, 3 * nv),
        triangles: new Uint32Array(buffer, 20 + 12 * nv, 3 * nt),
      });
    }
  }
}
