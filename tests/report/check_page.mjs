// Opens an HTML page in headless Chromium and checks what a reader would see: the page
// loads with no console error, no uncaught exception and no failed load; every <img> has
// decoded pixels, and an <img class="crop"> (the report's crops at 2:1) is shown no
// smaller than its pixels; every <video> has decoded a frame and lasts at least 3 s; every
// chart canvas belongs to a Chart.js chart (their ids are printed) that has data and drew
// on its canvas, whose datasets all look different (colour, dash, fill, marker), whose
// axes of time are logarithmic and whose axis labels do not run into each other; a page
// with scene sections opens with a summary naming each scene. Saves a full-page
// screenshot. Exit status 0 when all checks pass.
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
  for (const v of videos) {
    if (v.readyState >= 1 && !(v.duration >= 3)) {
      problems.push('video lasts ' + v.duration.toFixed(2) + ' s (under 3 s): ' + v.getAttribute('src'));
    }
  }
  const canvases = [...document.querySelectorAll('canvas')];
  let labelsChecked = 0;
  if (canvases.length > 0) {
    if (typeof Chart === 'undefined') problems.push('charts: Chart.js is not loaded');
    else for (const c of canvases) {
      const chart = Chart.getChart(c);
      const id = c.id || '?';
      if (!chart) { problems.push('canvas without a chart: ' + id); continue; }
      // Data, and pixels drawn.
      const values = chart.data.datasets.flatMap((d) => d.data).filter((x) =>
        x !== null && x !== undefined && (typeof x !== 'object' || (x.x !== undefined && x.y !== undefined)));
      if (values.length === 0) problems.push('chart without data: ' + id);
      const px = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      let inked = 0;
      for (let i = 3; i < px.length; i += 4) if (px[i] > 0) ++inked;
      if (inked < 500) problems.push('chart drew ' + inked + ' pixels: ' + id);
      // Every dataset looks different from the others.
      const looks = new Map();
      for (const d of chart.data.datasets) {
        const fill = typeof d.backgroundColor === 'string' ? d.backgroundColor :
          (d.backgroundColor ? 'pattern' : '');
        const look = JSON.stringify([chart.config.type, d.borderColor || '', fill, d.borderDash || [],
          d.pointStyle || '']);
        if (looks.has(look)) problems.push('chart ' + id + ': ' + d.label + ' looks like ' + looks.get(look));
        else looks.set(look, d.label);
      }
      // Time is on logarithmic axes.
      for (const [key, scale] of Object.entries(chart.scales)) {
        const title = (scale.options.title && scale.options.title.text) || '';
        if (/(^|[^a-z])ms([^a-z]|$)/.test(title) && scale.type !== 'logarithmic') {
          problems.push('chart ' + id + ': the time axis ' + key + ' is ' + scale.type + ', not logarithmic');
        }
        // Tick labels: consecutive shown labels at least their size apart (2 px to spare).
        const font = Chart.helpers.toFont(scale.options.ticks.font);
        const g = chart.ctx;
        g.save();
        g.font = font.string;
        const shown = [];
        scale.ticks.forEach((t, i) => {
          const lines = [].concat(t.label === undefined ? [] : t.label).map(String).filter((x) => x !== '');
          if (lines.length === 0) return;
          shown.push({ text: lines.join(' / '), at: scale.getPixelForTick(i),
            width: Math.max(...lines.map((l) => g.measureText(l).width)), height: lines.length * font.lineHeight });
        });
        g.restore();
        const rotated = (scale.labelRotation || 0) * Math.PI / 180;
        for (let i = 1; i < shown.length; ++i) {
          const a = shown[i - 1], b = shown[i];
          const gap = Math.abs(b.at - a.at);
          const need = !scale.isHorizontal() ? (a.height + b.height) / 2 :
            rotated > 0.01 ? font.lineHeight / Math.sin(rotated) : (a.width + b.width) / 2 + 2;
          ++labelsChecked;
          if (gap < need - 0.5) {
            problems.push('chart ' + id + ': axis ' + key + ' labels overlap: "' + a.text + '" and "' +
              b.text + '" ' + gap.toFixed(1) + ' px apart, need ' + need.toFixed(1));
          }
        }
      }
    }
  }
  // The summary: first in the page, one item per scene section.
  const sections = document.querySelectorAll('section[id^="scene-"]').length;
  const summary = document.getElementById('summary');
  const summarised = summary ? summary.querySelectorAll('li[data-scene]').length : 0;
  if (sections > 0) {
    if (!summary) problems.push('no summary (section#summary)');
    else if (summarised !== sections) problems.push('the summary covers ' + summarised + ' of ' + sections + ' scenes');
    else if (document.querySelector('main > section') !== summary) problems.push('the summary is not the first section');
  }
  return { problems, images: imgs.length, crops, videos: videos.length, charts: canvases.length,
    chartIds: canvases.map((c) => c.id), summarised, labelsChecked };
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
    { problems: [], images: 0, crops: 0, videos: 0, charts: 0, chartIds: [], summarised: 0, labelsChecked: 0 };
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
  console.log(`check_page: summary of ${v.summarised} scenes; ${v.labelsChecked} pairs of axis labels apart`);
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
