// Opens an HTML page in headless Chromium and checks what a reader would see: the page
// loads with no console error, no uncaught exception and no failed load; every <img> has
// decoded pixels, and an <img class="crop"> (the report's crops at 2:1) is shown no
// smaller than its pixels; every <video> has decoded a frame; every chart canvas belongs
// to a Chart.js chart (their ids are printed). Saves a full-page screenshot. Exit status 0 when all checks pass.
//
// Chromium is driven through the Chrome DevTools Protocol over a pipe
// (--remote-debugging-pipe: JSON messages ending in a NUL byte on file descriptors 3 and
// 4), so the check needs Node's standard library only: no npm package, no network.
//
// Usage: node check_page.mjs PAGE.html SCREENSHOT.png [--chromium PATH] [--timeout S]
import { spawn } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

const args = process.argv.slice(2);
function option(name, fallback) {
  const k = args.indexOf(name);
  if (k < 0) return fallback;
  const v = args[k + 1];
  args.splice(k, 2);
  return v;
}
const chromium = option('--chromium', process.env.CHROMIUM || '/usr/bin/chromium');
const timeoutS = Number(option('--timeout', '90'));
if (args.length !== 2) {
  console.error('usage: node check_page.mjs PAGE.html SCREENSHOT.png [--chromium PATH] [--timeout S]');
  process.exit(2);
}
const page = resolve(args[0]);
const screenshot = resolve(args[1]);

const profile = mkdtempSync(join(tmpdir(), 'sg-chromium-'));
const browser = spawn(chromium, [
  '--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync',
  '--disable-extensions', '--mute-audio', '--hide-scrollbars',
  '--autoplay-policy=no-user-gesture-required',
  `--user-data-dir=${profile}`, '--remote-debugging-pipe', 'about:blank',
], { stdio: ['ignore', 'ignore', 'pipe', 'pipe', 'pipe'] });

let stderrTail = '';
browser.stderr.on('data', (d) => { stderrTail = (stderrTail + d.toString()).slice(-4000); });

const problems = [];
let finished = false;
function finish(code) {
  if (finished) return;
  finished = true;
  try { browser.kill('SIGKILL'); } catch (e) { /* already gone */ }
  try { rmSync(profile, { recursive: true, force: true }); } catch (e) { /* best effort */ }
  process.exit(code);
}
const timer = setTimeout(() => {
  console.error(`check_page: timed out after ${timeoutS} s\n${stderrTail}`);
  finish(1);
}, timeoutS * 1000);
browser.on('error', (e) => {
  console.error(`check_page: cannot start ${chromium}: ${e.message}`);
  finish(1);
});
browser.on('exit', (code, signal) => {
  if (!finished) {
    console.error(`check_page: chromium exited early (${code ?? signal})\n${stderrTail}`);
    finish(1);
  }
});

// --- the protocol: requests with ids, responses and events, NUL-separated JSON.
const toBrowser = browser.stdio[3];
const fromBrowser = browser.stdio[4];
let nextId = 1;
const pending = new Map();
const listeners = [];
let buffer = '';
fromBrowser.on('data', (chunk) => {
  buffer += chunk.toString('utf8');
  let end;
  while ((end = buffer.indexOf('\0')) >= 0) {
    const msg = JSON.parse(buffer.slice(0, end));
    buffer = buffer.slice(end + 1);
    if (msg.id !== undefined && pending.has(msg.id)) {
      const { ok, fail, method } = pending.get(msg.id);
      pending.delete(msg.id);
      if (msg.error) fail(new Error(`${method}: ${msg.error.message}`));
      else ok(msg.result);
    } else if (msg.method) {
      for (const l of listeners) l(msg);
    }
  }
});
function send(method, params = {}, sessionId = undefined) {
  const id = nextId++;
  const msg = { id, method, params };
  if (sessionId) msg.sessionId = sessionId;
  toBrowser.write(JSON.stringify(msg) + '\0');
  return new Promise((ok, fail) => pending.set(id, { ok, fail, method }));
}
function waitFor(method, sessionId) {
  return new Promise((ok) => {
    const l = (msg) => {
      if (msg.method === method && msg.sessionId === sessionId) {
        listeners.splice(listeners.indexOf(l), 1);
        ok(msg.params);
      }
    };
    listeners.push(l);
  });
}

// What the page must satisfy once loaded; returns a list of problems (strings).
const pageChecks = `(async () => {
  const problems = [];
  const deadline = Date.now() + 20000;
  const settle = (ok) => new Promise((done) => {
    const poll = () => (ok() || Date.now() > deadline) ? done() : setTimeout(poll, 50);
    poll();
  });
  const imgs = [...document.images];
  await settle(() => imgs.every((i) => i.complete));
  for (const i of imgs) {
    if (!i.complete || i.naturalWidth === 0) problems.push('image does not load: ' + i.getAttribute('src'));
    else if (i.classList.contains('crop') && i.getBoundingClientRect().width < i.naturalWidth) {
      problems.push('crop shown shrunk: ' + i.getAttribute('src'));
    }
  }
  const crops = imgs.filter((i) => i.classList.contains('crop')).length;
  const videos = [...document.querySelectorAll('video')];
  await settle(() => videos.every((v) => v.error || v.readyState >= 2));
  for (const v of videos) {
    const src = v.currentSrc || v.getAttribute('src') || (v.querySelector('source') || {}).src;
    if (v.error) problems.push('video fails (' + v.error.code + ' ' + v.error.message + '): ' + src);
    else if (v.readyState < 2) problems.push('video has no decoded frame: ' + src);
  }
  const canvases = [...document.querySelectorAll('canvas')];
  if (canvases.length > 0) {
    if (typeof Chart === 'undefined') problems.push('charts: Chart.js is not loaded');
    else for (const c of canvases) {
      if (!Chart.getChart(c)) problems.push('canvas without a chart: ' + (c.id || '?'));
    }
  }
  return { problems, images: imgs.length, crops, videos: videos.length, charts: canvases.length,
    chartIds: canvases.map((c) => c.id) };
})()`;

(async () => {
  const { targetId } = await send('Target.createTarget', { url: 'about:blank' });
  const { sessionId } = await send('Target.attachToTarget', { targetId, flatten: true });
  listeners.push((msg) => {
    if (msg.sessionId !== sessionId) return;
    const p = msg.params;
    if (msg.method === 'Runtime.exceptionThrown') {
      const d = p.exceptionDetails;
      problems.push(`uncaught exception: ${(d.exception && d.exception.description) || d.text} (${d.url || ''}:${d.lineNumber})`);
    } else if (msg.method === 'Runtime.consoleAPICalled' && (p.type === 'error' || p.type === 'assert')) {
      problems.push(`console.${p.type}: ${p.args.map((a) => a.value ?? a.description).join(' ')}`);
    } else if (msg.method === 'Log.entryAdded' && p.entry.level === 'error') {
      problems.push(`console error: ${p.entry.text} ${p.entry.url || ''}`);
    } else if (msg.method === 'Network.loadingFailed' && !p.canceled) {
      problems.push(`load failed: ${p.errorText} (request ${p.requestId})`);
    }
  });
  await send('Runtime.enable', {}, sessionId);
  await send('Log.enable', {}, sessionId);
  await send('Network.enable', {}, sessionId);
  await send('Page.enable', {}, sessionId);
  await send('Emulation.setDeviceMetricsOverride',
    { width: 1280, height: 900, deviceScaleFactor: 1, mobile: false }, sessionId);
  const loaded = waitFor('Page.loadEventFired', sessionId);
  const nav = await send('Page.navigate', { url: pathToFileURL(page).href }, sessionId);
  if (nav.errorText) problems.push(`navigation failed: ${nav.errorText}`);
  await loaded;
  const r = await send('Runtime.evaluate',
    { expression: pageChecks, awaitPromise: true, returnByValue: true }, sessionId);
  if (r.exceptionDetails) problems.push(`page checks threw: ${r.exceptionDetails.text}`);
  const v = (r.result && r.result.value) ||
    { problems: [], images: 0, crops: 0, videos: 0, charts: 0, chartIds: [] };
  problems.push(...v.problems);
  // Full-page screenshot: grow the viewport to the content's height (capped).
  const m = await send('Page.getLayoutMetrics', {}, sessionId);
  const height = Math.min(16000, Math.ceil((m.cssContentSize || m.contentSize).height));
  await send('Emulation.setDeviceMetricsOverride',
    { width: 1280, height, deviceScaleFactor: 1, mobile: false }, sessionId);
  const shot = await send('Page.captureScreenshot', { format: 'png' }, sessionId);
  writeFileSync(screenshot, Buffer.from(shot.data, 'base64'));
  // Events that arrive late (a failed load after 'load') still count.
  await new Promise((ok) => setTimeout(ok, 200));
  clearTimeout(timer);
  console.log(`check_page: ${v.images} images, ${v.videos} videos, ${v.charts} charts; screenshot ${screenshot}`);
  console.log(`check_page: ${v.crops} crops; charts ${v.chartIds.join(' ')}`);
  if (problems.length > 0) {
    for (const p of problems) console.log(`PROBLEM ${p}`);
    finish(1);
  }
  await send('Browser.close').catch(() => {});
  finish(0);
})().catch((e) => {
  console.error(`check_page: ${e.message}\n${stderrTail}`);
  finish(1);
});
