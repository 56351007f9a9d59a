// studio_security_test.mjs — what another local user or web page can do to a
// running `fabvdb studio`, tried with plain HTTP from node: requests without
// the token, with a wrong token, with a foreign Host, a WebSocket handshake
// with a foreign Origin or none, and a POST, are all refused; the page with
// the token is served under a Content-Security-Policy that allows only its
// own origin. The server is stopped by its PID and must exit 0.
// Usage: node studio_security_test.mjs FABVDB SHARED_DATA CHECKER WORK_DIR
import assert from 'node:assert/strict';
import http from 'node:http';
import { mkdirSync, rmSync } from 'node:fs';
import { startStudio } from './server.mjs';

const [fabvdb, shared, , work] = process.argv.slice(2);
const dir = `${work}/security`;
rmSync(dir, { recursive: true, force: true });
mkdirSync(dir, { recursive: true });

function request(url, { method = 'GET', headers = {} } = {}) {
  return new Promise((resolve) => {
    const u = new URL(url);
    const req = http.request({ host: u.hostname, port: u.port, path: u.pathname + u.search, method, headers }, (res) => {
      let body = '';
      res.on('data', (d) => { body += d; });
      res.on('end', () => resolve({ status: res.statusCode, body, headers: res.headers }));
    });
    req.on('upgrade', (res, socket) => { socket.destroy(); resolve({ status: res.statusCode, body: '' }); });
    // A refused handshake may be a closed connection rather than a status: 0.
    req.on('error', () => resolve({ status: 0, body: '' }));
    req.end();
  });
}

const upgrade = (origin) => ({
  Connection: 'Upgrade', Upgrade: 'websocket', 'Sec-WebSocket-Version': '13',
  'Sec-WebSocket-Key': 'dGhlIHNhbXBsZSBub25jZQ==', ...(origin ? { Origin: origin } : {}),
});

const studio = startStudio(fabvdb, `${shared}/meshes/sphere.obj`, `${dir}/out`, ['--low-res', '800', '--parts', '2']);
let passed = 0;
const check = async (name, body) => { await body(); ++passed; console.log(`ok ${passed} - ${name}`); };
try {
  const url = await studio.url;
  const u = new URL(url);
  const origin = `${u.protocol}//${u.host}`;
  const token = u.pathname.split('/')[1];
  const wrong = token.replace(/^./, (c) => (c === 'a' ? 'b' : 'a'));
  await check('the page with the token is served', async () => {
    const r = await request(url);
    assert.equal(r.status, 200);
    assert.match(r.body, /fabvdb studio/);
    // Scripts and connections only from this origin; no eval; no framing by another page.
    const csp = r.headers['content-security-policy'];
    assert.match(csp, /default-src 'self'/);
    assert.match(csp, /connect-src 'self' ws:\/\/127\.0\.0\.1:\d+ ws:\/\/localhost:\d+;/);
    assert.match(csp, /frame-ancestors 'none'/);
    assert.doesNotMatch(csp, /unsafe-eval/);
    assert.equal((await request(`${url}vendor/three.module.js`)).status, 200);
  });
  await check('no token: 403', async () => assert.equal((await request(`${origin}/`)).status, 403));
  await check('no token, a page path: 403', async () => assert.equal((await request(`${origin}/index.html`)).status, 403));
  await check('wrong token: 403', async () => assert.equal((await request(`${origin}/${wrong}/`)).status, 403));
  await check('foreign Host (DNS rebinding): 403', async () =>
    assert.equal((await request(url, { headers: { Host: `evil.example:${u.port}` } })).status, 403));
  await check('foreign Origin on a page request: 403', async () =>
    assert.equal((await request(url, { headers: { Origin: 'http://evil.example' } })).status, 403));
  await check('POST: refused', async () => assert.equal((await request(url, { method: 'POST' })).status, 405));
  await check('WebSocket with its own Origin: accepted (101)', async () =>
    assert.equal((await request(`${url}ws`, { headers: upgrade(origin) })).status, 101));
  await check('WebSocket with a foreign Origin: refused', async () =>
    assert.notEqual((await request(`${url}ws`, { headers: upgrade('http://evil.example') })).status, 101));
  await check('WebSocket without an Origin: refused', async () =>
    assert.notEqual((await request(`${url}ws`, { headers: upgrade(null) })).status, 101));
  await check('WebSocket without the token: refused', async () =>
    assert.notEqual((await request(`${origin}/${wrong}/ws`, { headers: upgrade(origin) })).status, 101));
} finally {
  const { code, signal } = await studio.stop();
  assert.equal(signal, null, `the studio died of ${signal}: ${studio.stderr()}`);
  assert.equal(code, 0, `the studio exited ${code}: ${studio.stderr()}`);
}
console.log(`${passed} passed, 0 failed`);
