// Drives `sunglint web`'s page in headless Chromium and checks what it draws, with Node's
// standard library only: Chromium's DevTools protocol over a pipe (as
// tests/report/check_page.mjs does: no npm package, no network, nothing to install beyond
// Debian's chromium and nodejs). WebGL 2 runs on SwiftShader, Chromium's CPU
// implementation, through ANGLE (--use-angle=swiftshader --enable-unsafe-swiftshader).
//
// Usage: node check_web.mjs JOBS.json [--chromium PATH] [--timeout S]
// JOBS.json: a list of jobs, each a browser tab that opens `page` (a file) with `query` at
// device scale 1, then runs its `steps` in order. A step may first set the page's fragment
// (`hash`: parameters applied without reloading, keeping the compiled shaders and the path
// table), then waits for document.title to read "ready" (or for the page's error), then:
//   "compare": [{"ref": PNG, "x0", "x1"}], "limit": 2, "fraction": 0.999, "screenshot": PNG
//       the canvas's pixels (a screenshot of the page at (0, 0), width x height: the canvas
//       alone with ui=0) in columns [x0, x1) against the reference picture's: at least
//       `fraction` of the pixels within `limit`/255 in every channel, and at least
//       `lit_fraction` of the lit ones (a channel above `limit` in either picture), of
//       which there must be `min_lit` at least (0 and 0 if not given);
//   "drop": FILE, "drop_name": NAME, "expect": TEXT
//       FILE dropped on the page as NAME: the page's error reads TEXT ("" for a scene the
//       page loads and lists);
//   "error": TEXT   the page shows TEXT as its error (a bad parameter);
//   "linear": {"ref": PFM, "max_relative_rmse": R}
//       the page's linear image (the display pipeline's input at exposure 0) against
//       `render --engine gl -o X.pfm`: RMSE over every channel of every pixel at most R
//       times the reference's root mean square;
//   "bench": N      N more renders of the frame shown: the page's timing (printed);
//   "eval": EXPR    the value of a script expression in the page (printed), equal to
//                   "eval_expect" when that is given.
// A reference that does not exist yet is waited for (the caller may render it meanwhile).
// A job fails on a console error, an uncaught exception, or a request for anything but a
// file: or data: URL (the page must work offline). Prints one line per step; exit 0 when
// all pass.
import { spawn } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { inflateSync } from 'node:zlib';

const args = process.argv.slice(2);
function option(name, fallback) {
  const k = args.indexOf(name);
  if (k < 0) return fallback;
  const v = args[k + 1];
  args.splice(k, 2);
  return v;
}
const chromium = option('--chromium', process.env.CHROMIUM || '/usr/bin/chromium');
const timeoutS = Number(option('--timeout', '300'));
if (args.length !== 1) {
  console.error('usage: node check_web.mjs JOBS.json [--chromium PATH] [--timeout S]');
  process.exit(2);
}
const jobs = JSON.parse(readFileSync(args[0], 'utf8'));

// ---- PNG: 8-bit grey, RGB or RGBA, not interlaced (what sunglint and Chromium write).
function readPng(bytes) {
  if (bytes.readUInt32BE(0) !== 0x89504e47) throw new Error('not a PNG');
  let pos = 8, w = 0, h = 0, ch = 0;
  const idat = [];
  while (pos < bytes.length) {
    const n = bytes.readUInt32BE(pos), kind = bytes.toString('latin1', pos + 4, pos + 8);
    const body = bytes.subarray(pos + 8, pos + 8 + n);
    if (kind === 'IHDR') {
      w = body.readUInt32BE(0);
      h = body.readUInt32BE(4);
      if (body[8] !== 8 || body[12] !== 0) throw new Error('unsupported PNG');
      ch = { 0: 1, 2: 3, 6: 4 }[body[9]];
    } else if (kind === 'IDAT') idat.push(body);
    pos += 12 + n;
  }
  const raw = inflateSync(Buffer.concat(idat));
  const stride = w * ch, rgb = new Uint8Array(w * h * 3);
  let prev = new Uint8Array(stride);
  for (let y = 0; y < h; y++) {
    const f = raw[y * (stride + 1)], line = Uint8Array.from(raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1)));
    for (let i = 0; i < stride; i++) {
      const a = i >= ch ? line[i - ch] : 0, b = prev[i], c = i >= ch ? prev[i - ch] : 0;
      const p = a + b - c, pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c);
      const pred = [0, a, b, (a + b) >> 1, pa <= pb && pa <= pc ? a : pb <= pc ? b : c][f];
      line[i] = (line[i] + pred) & 255;
    }
    for (let x = 0; x < w; x++) for (let c = 0; c < 3; c++) rgb[3 * (y * w + x) + c] = line[x * ch + (ch === 1 ? 0 : c)];
    prev = line;
  }
  return { w, h, rgb };
}

// ---- PFM (what `sunglint render -o X.pfm` writes): "Pf" grey or "PF" RGB, rows bottom up.
function readPfm(bytes) {
  let pos = 0;
  const token = () => {
    while (/\s/.test(String.fromCharCode(bytes[pos]))) pos++;
    const start = pos;
    while (!/\s/.test(String.fromCharCode(bytes[pos]))) pos++;
    return bytes.toString('latin1', start, pos);
  };
  const kind = token(), w = Number(token()), h = Number(token()), scale = Number(token());
  pos++;
  const ch = kind === 'PF' ? 3 : 1;
  const data = bytes.subarray(pos);
  const at = (i) => (scale < 0 ? data.readFloatLE(4 * i) : data.readFloatBE(4 * i));
  return { w, h, value: (x, y, c) => at(((h - 1 - y) * w + x) * ch + (ch === 3 ? c : 0)) };
}

// ---- the browser, through the DevTools protocol (JSON messages ending in NUL, fds 3 and 4)
const profile = mkdtempSync(join(tmpdir(), 'sg-web-'));
const browser = spawn(chromium, [
  '--headless=new', '--no-sandbox', '--use-gl=angle', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
  '--ignore-gpu-blocklist', '--disable-quic', '--no-first-run', '--disable-background-networking',
  '--disable-component-update', '--disable-sync', '--disable-extensions', '--mute-audio', '--hide-scrollbars',
  '--allow-file-access-from-files', `--user-data-dir=${profile}`, '--remote-debugging-pipe', 'about:blank',
], { stdio: ['ignore', 'ignore', 'pipe', 'pipe', 'pipe'] });
let stderrTail = '';
browser.stderr.on('data', (d) => { stderrTail = (stderrTail + d.toString()).slice(-4000); });
let finished = false;
function finish(code) {
  if (finished) return;
  finished = true;
  try { browser.kill('SIGKILL'); } catch (e) { /* gone */ }
  try { rmSync(profile, { recursive: true, force: true }); } catch (e) { /* best effort */ }
  process.exit(code);
}
const timer = setTimeout(() => { console.error(`check_web: timed out after ${timeoutS} s\n${stderrTail}`); finish(1); }, timeoutS * 1000);
browser.on('error', (e) => { console.error(`check_web: cannot start ${chromium}: ${e.message}`); finish(1); });
browser.on('exit', (code, signal) => {
  if (!finished) { console.error(`check_web: chromium exited early (${code ?? signal})\n${stderrTail}`); finish(1); }
});
let nextId = 1, buffer = '';
const pending = new Map(), listeners = [];
browser.stdio[4].on('data', (chunk) => {
  buffer += chunk.toString('utf8');
  let end;
  while ((end = buffer.indexOf('\0')) >= 0) {
    const msg = JSON.parse(buffer.slice(0, end));
    buffer = buffer.slice(end + 1);
    if (msg.id !== undefined && pending.has(msg.id)) {
      const { ok, fail, method } = pending.get(msg.id);
      pending.delete(msg.id);
      if (msg.error) fail(new Error(`${method}: ${msg.error.message}`)); else ok(msg.result);
    } else if (msg.method) for (const l of listeners) l(msg);
  }
});
function send(method, params = {}, sessionId = undefined) {
  const id = nextId++;
  browser.stdio[3].write(JSON.stringify(sessionId ? { id, method, params, sessionId } : { id, method, params }) + '\0');
  return new Promise((ok, fail) => pending.set(id, { ok, fail, method }));
}
const sleep = (ms) => new Promise((ok) => setTimeout(ok, ms));
// A reference file's bytes once it exists: the caller may still be rendering it while the
// page compiles (sunglint writes a file whole, through a rename, so existing is finished).
async function whenWritten(path) {
  while (!existsSync(path)) await sleep(100);
  return readFileSync(path);
}

async function runJob(job) {
  const problems = [];
  const { targetId } = await send('Target.createTarget', { url: 'about:blank' });
  const { sessionId } = await send('Target.attachToTarget', { targetId, flatten: true });
  const listener = (msg) => {
    if (msg.sessionId !== sessionId) return;
    const p = msg.params;
    if (msg.method === 'Runtime.exceptionThrown') {
      problems.push(`uncaught exception: ${(p.exceptionDetails.exception || {}).description || p.exceptionDetails.text}`);
    } else if (msg.method === 'Runtime.consoleAPICalled' && (p.type === 'error' || p.type === 'assert')) {
      problems.push(`console.${p.type}: ${p.args.map((a) => a.value ?? a.description).join(' ')}`);
    } else if (msg.method === 'Network.requestWillBeSent' && !/^(file|data):/.test(p.request.url)) {
      problems.push(`network request: ${p.request.url}`);
    }
  };
  listeners.push(listener);
  const evaluate = async (expression) => {
    const r = await send('Runtime.evaluate', { expression, awaitPromise: true, returnByValue: true }, sessionId);
    if (r.exceptionDetails) throw new Error(`page script: ${r.exceptionDetails.text} ${(r.exceptionDetails.exception || {}).description || ''}`);
    return r.result.value;
  };
  const settle = async () => {
    for (;;) {
      const s = await evaluate(`({ title: document.title, error: (document.getElementById('error') || {}).textContent || '' })`)
        .catch(() => ({ title: '', error: '' }));
      if (s.title === 'ready' || s.error !== '') return s;
      await sleep(100);
    }
  };
  try {
    await send('Runtime.enable', {}, sessionId);
    await send('Network.enable', {}, sessionId);
    await send('Page.enable', {}, sessionId);
    await send('Emulation.setDeviceMetricsOverride',
      { width: Math.max(job.width || 0, 800), height: Math.max(job.height || 0, 600), deviceScaleFactor: 1, mobile: false }, sessionId);
    const url = pathToFileURL(resolve(job.page)).href + (job.query ? '?' + job.query : '');
    let t0 = Date.now();
    await send('Page.navigate', { url }, sessionId);
    for (const [n, step] of job.steps.entries()) {
      if (step.hash !== undefined) {
        t0 = Date.now();
        await evaluate(`document.title = 'waiting'; location.hash = ${JSON.stringify(step.hash)}`);
      }
      const state = await settle();
      const name = `${job.name}${step.hash !== undefined ? ' #' + step.hash : ''}`;
      let line = `${name}: ${state.title === 'ready' ? 'ready' : 'error'} after ${((Date.now() - t0) / 1000).toFixed(1)} s`;
      const problem = (text) => problems.push(`${name}: ${text}`);
      if (step.error !== undefined) {
        if (state.error !== step.error) problem(`the page shows\n    ${state.error}\n  wanted\n    ${step.error}`);
        line += `; error: ${state.error}`;
      } else if (state.title !== 'ready') {
        problem(`the page shows an error: ${state.error}`);
      }
      if (step.drop) {
        const b64 = readFileSync(step.drop).toString('base64');
        const shown = await evaluate(`(async () => {
          const bytes = Uint8Array.from(atob(${JSON.stringify(b64)}), (c) => c.charCodeAt(0));
          const dt = new DataTransfer();
          dt.items.add(new File([bytes], ${JSON.stringify(step.drop_name)}));
          document.getElementById('error').textContent = '';
          const scenes = document.getElementById('scene').options.length;
          document.dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
          // Until the page shows an error or lists the scene.
          for (let i = 0; i < 200 && document.getElementById('error').textContent === '' &&
               document.getElementById('scene').options.length === scenes; i++) await new Promise((ok) => setTimeout(ok, 50));
          return document.getElementById('error').textContent;
        })()`);
        if (shown !== step.expect) problem(`dropped ${step.drop_name}: the page shows\n    ${shown}\n  the CLI prints\n    ${step.expect}`);
        line += `; dropped ${step.drop_name}: ${shown !== step.expect ? 'a different message' : shown === '' ? 'loaded' : "the CLI's message"}`;
      }
      if (step.compare && state.title === 'ready') {
        const shot = await send('Page.captureScreenshot',
          { format: 'png', clip: { x: 0, y: 0, width: job.width, height: job.height, scale: 1 } }, sessionId);
        const png = Buffer.from(shot.data, 'base64');
        if (step.screenshot) writeFileSync(step.screenshot, png);
        const page = readPng(png);
        if (page.w !== job.width || page.h !== job.height) problem(`screenshot is ${page.w}x${page.h}`);
        const limit = step.limit ?? 2, want = step.fraction ?? 0.999;
        for (const c of step.compare) {
          const ref = readPng(await whenWritten(c.ref));
          if (ref.w !== page.w || ref.h !== page.h) { problem(`${c.ref} is ${ref.w}x${ref.h}`); continue; }
          // Every pixel, and the lit ones (a channel above `limit` in either picture): on a
          // dark scene the glints are few, and 0.1% of the pixels could hide all of them.
          let within = 0, total = 0, max = 0, lit = 0, litWithin = 0;
          for (let y = 0; y < page.h; y++) {
            for (let x = c.x0; x < c.x1; x++) {
              let d = 0, peak = 0;
              for (let k = 0; k < 3; k++) {
                const a = page.rgb[3 * (y * page.w + x) + k], b = ref.rgb[3 * (y * page.w + x) + k];
                d = Math.max(d, Math.abs(a - b));
                peak = Math.max(peak, a, b);
              }
              max = Math.max(max, d);
              total++;
              if (d <= limit) within++;
              if (peak > limit) {
                lit++;
                if (d <= limit) litWithin++;
              }
            }
          }
          const fraction = within / total, litFraction = lit > 0 ? litWithin / lit : 1;
          line += `; columns ${c.x0}-${c.x1} vs ${c.ref.split('/').pop()}: ${(100 * fraction).toFixed(3)}% within ${limit}/255` +
            ` (lit: ${litWithin} of ${lit}), max ${max}/255`;
          if (fraction < want) problem(`columns ${c.x0}-${c.x1}: ${(100 * fraction).toFixed(3)}% of pixels within ${limit}/255 of ${c.ref} (max ${max}/255), wanted ${100 * want}%`);
          if (litFraction < (step.lit_fraction ?? 0)) problem(`columns ${c.x0}-${c.x1}: ${litWithin} of the ${lit} lit pixels within ${limit}/255 of ${c.ref}, wanted ${100 * step.lit_fraction}%`);
          if (lit < (step.min_lit ?? 0)) problem(`columns ${c.x0}-${c.x1}: ${lit} lit pixels, fewer than ${step.min_lit}: a blank picture?`);
        }
      }
      if (step.linear && state.title === 'ready') {
        // The linear image against `render --engine gl -o X.pfm`: RMSE over all channels,
        // relative to the reference's root mean square.
        const page = new Float32Array(Buffer.from(await evaluate('window.sunglintPage.linear()'), 'base64').buffer.slice(0));
        const ref = readPfm(await whenWritten(step.linear.ref));
        let se = 0, ss = 0;
        for (let y = 0; y < ref.h; y++) {
          for (let x = 0; x < ref.w; x++) {
            for (let c = 0; c < 3; c++) {
              const a = page[3 * (y * ref.w + x) + c], b = ref.value(x, y, c);
              se += (a - b) * (a - b);
              ss += b * b;
            }
          }
        }
        const rel = Math.sqrt(se / Math.max(ss, 1e-300));
        line += `; linear vs ${step.linear.ref.split('/').pop()}: relative RMSE ${rel.toExponential(2)}`;
        if (!(rel <= step.linear.max_relative_rmse)) problem(`linear image: relative RMSE ${rel.toExponential(2)} against ${step.linear.ref}, more than ${step.linear.max_relative_rmse}`);
      }
      if (step.bench) line += '; bench ' + JSON.stringify(await evaluate(`window.sunglintPage.bench(${step.bench})`));
      if (step.eval) {
        const value = JSON.stringify(await evaluate(step.eval));
        line += '; ' + step.eval + ' = ' + value;
        if (step.eval_expect !== undefined && value !== JSON.stringify(step.eval_expect)) {
          problem(`${step.eval} is ${value}, wanted ${JSON.stringify(step.eval_expect)}`);
        }
      }
      console.log(line);
    }
  } catch (e) {
    problems.push(`${job.name}: ${e.message}`);
  }
  listeners.splice(listeners.indexOf(listener), 1);
  await send('Target.closeTarget', { targetId }).catch(() => {});
  for (const p of problems) console.log(`PROBLEM ${p}`);
  return problems.length === 0;
}

(async () => {
  let ok = true;
  for (const job of jobs) ok = (await runJob(job)) && ok;
  clearTimeout(timer);
  await send('Browser.close').catch(() => {});
  finish(ok ? 0 : 1);
})().catch((e) => { console.error(`check_web: ${e.message}\n${stderrTail}`); finish(1); });
