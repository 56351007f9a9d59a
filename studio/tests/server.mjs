// server.mjs — starts `fabvdb studio` for a test (no browser, its own output
// folder), reads the URL it prints, and stops it by its PID.
import { spawn } from 'node:child_process';

export function startStudio(fabvdb, model, outputDir, extra = []) {
  const args = ['studio', model, '--no-browser', '-o', outputDir, ...extra];
  const child = spawn(fabvdb, args, { stdio: ['ignore', 'pipe', 'pipe'], env: { ...process.env, CI: 'true' } });
  let stdout = '', stderr = '';
  child.stderr.on('data', (d) => { stderr += d; });
  const exited = new Promise((resolve) => child.on('exit', (code, signal) => resolve({ code, signal })));
  const url = new Promise((resolve, reject) => {
    child.stdout.on('data', (d) => {
      stdout += d;
      const m = stdout.match(/open (http:\/\/127\.0\.0\.1:\d+\/[0-9a-f]{32}\/)/);
      if (m) resolve(m[1]);
    });
    exited.then(({ code }) => reject(new Error(`fabvdb studio exited (${code}) before printing its URL: ${stderr}`)));
  });
  return {
    pid: child.pid,
    url,
    exited,
    stderr: () => stderr,
    async stop() {
      if (child.exitCode !== null || child.signalCode !== null) return exited;
      process.kill(child.pid, 'SIGTERM');
      const timer = setTimeout(() => { try { process.kill(child.pid, 'SIGKILL'); } catch { /* gone */ } }, 20000);
      const result = await exited;
      clearTimeout(timer);
      return result;
    },
  };
}
