// The page around the kernel's host (host.js): the controls, the URL parameters, the split
// view's divider, the zoom lens, the frame-time readout, scene files dropped on the page.
// docs/web.md lists the parameters. They are read from the query and then the fragment
// (#...), whose keys win; a new fragment applies at once, without reloading, so the
// compiled shaders and the path table are kept. Scripted runs (the tests) use
// `ui=0&paused=1` and wait for document.title to read "ready", set once the requested
// frame is drawn (and reset while a new fragment's frame is drawn).
'use strict';
(() => {
  const data = window.SUNGLINT_DATA;
  const $ = (id) => document.getElementById(id);
  let params = new URLSearchParams();
  const showError = (text) => {
    $('error').textContent = text;
    $('error').hidden = text === '';
  };
  const encoder = new TextEncoder();

  // The page's state: what the next frame shows.
  const state = {
    scenes: [], scene: 0, frame: 0, position: 0, playing: true, speed: 1,
    left: null, right: null, split: false, divider: 0, exposure: 0, glare: data.display.glare_on,
    elevation: 0, azimuth: 0, lens: false, zoom: 4, dirty: true, ready: false,
  };
  const timing = {};
  let renderer;

  // A URL parameter that must be an integer in [lo, hi] (null when absent).
  function intParam(name, lo, hi) {
    if (!params.has(name)) return null;
    const v = Number(params.get(name));
    if (!Number.isInteger(v) || v < lo || v > hi) {
      throw new Error(name + '=' + params.get(name) + ': must be an integer in [' + lo + ', ' + hi + ']');
    }
    return v;
  }
  function variant(id, name) {
    const v = data.methods.find((m) => m.id === id);
    if (!v) throw new Error(name + '=' + id + ': not one of ' + data.methods.map((m) => m.id).join(', '));
    return v;
  }
  let sizeParam = [null, null];
  // The image size: the URL's (one of the two: the other follows the aspect ratio, as
  // `render --width` does), else the page's for its scenes (sunglint web --width), else the
  // scene file's (a dropped scene).
  const size = () => {
    const s = state.scenes[state.scene], page = data.scenes[state.scene] || s;
    const [w, h] = sizeParam;
    if (w && h) return [w, h];
    if (w) return [w, Math.max(1, Math.round(w * page.height / page.width))];
    if (h) return [Math.max(1, Math.round(h * page.width / page.height)), h];
    return [page.width, page.height];
  };

  // The light's angles (viewer/view_edits.cpp): elevation above the horizontal, azimuth from
  // -z towards +x, in degrees.
  function sunAngles(s) {
    const d = s.light.direction, l = Math.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    const el = Math.asin(Math.min(1, Math.max(-1, d[1] / l))) * 180 / Math.PI;
    const az = d[0] === 0 && d[2] === 0 ? 0 : Math.atan2(d[0] / l, -d[2] / l) * 180 / Math.PI;
    return [el, az];
  }
  // The scene with the page's light edits; the file's direction exactly when unedited.
  function edited() {
    const s = state.scenes[state.scene];
    const [el0, az0] = sunAngles(s);
    if (Math.abs(state.elevation - el0) < 1e-9 && Math.abs(state.azimuth - az0) < 1e-9) return s;
    const el = state.elevation * Math.PI / 180, az = state.azimuth * Math.PI / 180;
    const light = { ...s.light, direction: [Math.cos(el) * Math.sin(az), Math.sin(el), -Math.cos(el) * Math.cos(az)] };
    return { ...s, light };
  }

  function selectScene(index) {
    state.scene = index;
    const s = state.scenes[index];
    [state.elevation, state.azimuth] = sunAngles(s);
    state.frame = Math.min(state.frame, s.animation.frames - 1);
    state.position = state.frame;
    const [w, h] = size();
    state.divider = Math.round(w / 2);
    syncControls();
    state.dirty = true;
  }

  function syncControls() {
    const s = state.scenes[state.scene];
    const [w, h] = size();
    $('scene').value = String(state.scene);
    $('frame').max = String(s.animation.frames - 1);
    $('frame').value = String(state.frame);
    $('frame-out').textContent = state.frame + ' / ' + (s.animation.frames - 1);
    $('play').textContent = state.playing ? 'pause' : 'play';
    $('method').value = state.left.id;
    $('split-on').checked = state.split;
    $('split').value = state.right.id;
    $('split').disabled = !state.split;
    $('exposure').value = String(state.exposure);
    $('exposure-out').textContent = state.exposure.toFixed(1);
    $('glare').checked = state.glare;
    $('elevation').value = String(state.elevation);
    $('elevation-out').textContent = state.elevation.toFixed(1) + '\u00b0';
    $('azimuth').value = String(state.azimuth);
    $('azimuth-out').textContent = state.azimuth.toFixed(1) + '\u00b0';
    const canvas = $('canvas');
    canvas.style.width = w + 'px';
    canvas.style.height = h + 'px';
    $('view').style.width = w + 'px';
    $('view').style.height = h + 'px';
    $('divider').hidden = !state.split;
    $('divider').style.left = state.divider + 'px';
    $('label-left').textContent = state.left.label;
    $('label-right').textContent = state.right.label;
    $('info').textContent = s.name + ', ' + w + 'x' + h + ', ' + s.surface.waves.length + ' waves';
  }

  function draw() {
    const s = edited();
    const [w, h] = size();
    const t0 = performance.now();
    renderer.resize(w, h);
    renderer.kernel(s, state.frame, state.left, timing);
    renderer.display(s, 0, state.exposure, state.glare);
    if (state.split) {
      renderer.kernel(s, state.frame, state.right, timing);
      renderer.display(s, 1, state.exposure, state.glare);
    }
    renderer.compose(state.split ? state.divider : w);
    const gl = renderer.gl;
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));  // waits for the GPU
    timing.frame = performance.now() - t0;
    renderer.pollTimer();
    showTiming();
    drawLens();
  }

  function showTiming() {
    const ms = (v) => (v === undefined ? '...' : v < 10 ? v.toFixed(2) : v.toFixed(1));
    const sides = state.split ? [state.left, state.right] : [state.left];
    const gpu = renderer.timer
      ? 'GPU (timer query): ' + sides.map((v) => v.label + ' ' + ms(timing[v.id]) + ' ms').join(', ')
      : 'GPU time: this browser has no timer query (EXT_disjoint_timer_query_webgl2)';
    const tables = renderer.tablesMs === undefined ? '' : '; path table made in ' + ms(renderer.tablesMs) + ' ms';
    $('timing').textContent = gpu + '; frame in all ' + ms(timing.frame) + ' ms' + tables;
  }

  // The zoom lens: the canvas's pixels around the cursor, magnified, nearest.
  let cursor = null;
  function drawLens() {
    const lens = $('lens');
    lens.hidden = !state.lens || !cursor;
    if (lens.hidden) return;
    const c = lens.getContext('2d');
    c.imageSmoothingEnabled = false;
    const side = lens.width / state.zoom;
    c.fillStyle = '#000';
    c.fillRect(0, 0, lens.width, lens.height);
    c.drawImage($('canvas'), cursor[0] - side / 2, cursor[1] - side / 2, side, side, 0, 0, lens.width, lens.height);
    lens.style.left = Math.round(cursor[0] + 16) + 'px';
    lens.style.top = Math.round(cursor[1] + 16) + 'px';
  }

  let last = null;
  function tick(now) {
    const s = state.scenes[state.scene];
    if (state.playing && last !== null) {
      // Real time while the frames keep up, one frame per drawing when they do not.
      state.position += Math.min(1, (now - last) / 1000 * s.animation.fps * state.speed);
      const f = Math.floor(state.position) % s.animation.frames;
      state.position %= s.animation.frames;
      if (f !== state.frame) {
        state.frame = f;
        state.dirty = true;
        $('frame').value = String(f);
        $('frame-out').textContent = f + ' / ' + (s.animation.frames - 1);
      }
    }
    last = now;
    if (state.dirty) {
      state.dirty = false;
      try {
        draw();
      } catch (e) {
        showError('sunglint: ' + e.message);
        state.playing = false;
        requestAnimationFrame(tick);
        return;
      }
      if (!state.ready) {
        state.ready = true;
        document.title = 'ready';
      }
    } else if (renderer.pending.length > 0) {
      renderer.pollTimer();
      showTiming();
    }
    requestAnimationFrame(tick);
  }

  function controls() {
    const on = (id, event, f) => $(id).addEventListener(event, (e) => { f(e); syncControls(); state.dirty = true; });
    data.methods.forEach((m) => {
      for (const id of ['method', 'split']) $(id).add(new Option(m.label, m.id));
    });
    state.scenes.forEach((s, i) => $('scene').add(new Option(s.name, String(i))));
    on('scene', 'change', () => selectScene(Number($('scene').value)));
    on('method', 'change', () => { state.left = variant($('method').value, 'method'); });
    on('split', 'change', () => { state.right = variant($('split').value, 'split'); });
    on('split-on', 'change', () => { state.split = $('split-on').checked; });
    on('play', 'click', () => { state.playing = !state.playing; state.position = state.frame; });
    const step = (d) => {
      const n = state.scenes[state.scene].animation.frames;
      state.playing = false;
      state.frame = (state.frame + d + n) % n;
      state.position = state.frame;
    };
    on('prev', 'click', () => step(-1));
    on('next', 'click', () => step(1));
    on('frame', 'input', () => { state.frame = Number($('frame').value); state.position = state.frame; });
    on('speed', 'change', () => { state.speed = Number($('speed').value); });
    on('exposure', 'input', () => { state.exposure = Number($('exposure').value); });
    on('glare', 'change', () => { state.glare = $('glare').checked; });
    on('elevation', 'input', () => { state.elevation = Number($('elevation').value); });
    on('azimuth', 'input', () => { state.azimuth = Number($('azimuth').value); });
    on('sun-reset', 'click', () => { [state.elevation, state.azimuth] = sunAngles(state.scenes[state.scene]); });
    on('lens-on', 'change', () => { state.lens = $('lens-on').checked; });
    on('zoom', 'change', () => { state.zoom = Number($('zoom').value); });
    document.addEventListener('keydown', (e) => {
      if (e.target.tagName === 'INPUT' && e.target.type !== 'range' && e.target.type !== 'checkbox') return;
      if (e.key === ' ') { e.preventDefault(); $('play').click(); }
      if (e.key === 'ArrowLeft') $('prev').click();
      if (e.key === 'ArrowRight') $('next').click();
      if (e.key === 'z') $('lens-on').click();
    });
    // The divider: dragged on its line.
    const divider = $('divider');
    divider.addEventListener('pointerdown', (e) => { divider.setPointerCapture(e.pointerId); });
    divider.addEventListener('pointermove', (e) => {
      if (!divider.hasPointerCapture(e.pointerId)) return;
      const r = $('canvas').getBoundingClientRect();
      state.divider = Math.max(0, Math.min(size()[0], Math.round((e.clientX - r.left) * size()[0] / r.width)));
      syncControls();
      state.dirty = true;
    });
    $('view').addEventListener('pointermove', (e) => {
      const r = $('canvas').getBoundingClientRect();
      cursor = [(e.clientX - r.left) * size()[0] / r.width, (e.clientY - r.top) * size()[1] / r.height];
      drawLens();
    });
    $('view').addEventListener('pointerleave', () => { cursor = null; drawLens(); });
    // A scene file dropped anywhere on the page: checked as `sunglint` checks it.
    document.addEventListener('dragover', (e) => e.preventDefault());
    document.addEventListener('drop', async (e) => {
      e.preventDefault();
      const file = e.dataTransfer.files[0];
      if (!file) return;
      try {
        const s = SunglintScene.parse(new Uint8Array(await file.arrayBuffer()), file.name);
        if (s.camera.keyframes) {
          throw new Error(file.name + ': camera.keyframes: the page renders a fixed camera (a moving one: sunglint render)');
        }
        state.scenes.push(s);
        $('scene').add(new Option(s.name + ' (dropped)', String(state.scenes.length - 1)));
        selectScene(state.scenes.length - 1);
        showError('');
      } catch (err) {
        showError('sunglint: ' + err.message);
      }
    });
  }

  // Renders `n` more times the frame shown with each side's method and resolves to the
  // median GPU times (ms, timer queries) by method, and the wall time per frame.
  async function bench(n) {
    const times = {}, wall = [];
    const sides = state.split ? [state.left, state.right] : [state.left];
    for (let i = 0; i < n; i++) {
      const t = {};
      const t0 = performance.now();
      for (const [k, v] of sides.entries()) {
        renderer.kernel(edited(), state.frame, v, t);
        renderer.display(edited(), k, state.exposure, state.glare);
      }
      renderer.compose(state.split ? state.divider : size()[0]);
      renderer.gl.readPixels(0, 0, 1, 1, renderer.gl.RGBA, renderer.gl.UNSIGNED_BYTE, new Uint8Array(4));
      wall.push(performance.now() - t0);
      while (renderer.pending.length > 0) {
        await new Promise((ok) => setTimeout(ok, 5));
        renderer.pollTimer();
      }
      for (const [id, ms] of Object.entries(t)) (times[id] = times[id] || []).push(ms);
    }
    const median = (a) => a.slice().sort((x, y) => x - y)[Math.floor(a.length / 2)];
    const out = { wall: median(wall), timer: !!renderer.timer };
    for (const [id, a] of Object.entries(times)) out[id] = median(a);
    return out;
  }

  // The URL's parameters (docs/web.md), checked: a bad one is an error on the page.
  function applyParams() {
    params = new URLSearchParams(location.search);
    for (const [k, v] of new URLSearchParams(location.hash.slice(1))) params.set(k, v);
    sizeParam = [intParam('width', 1, 16384), intParam('height', 1, 16384)];
    const name = params.get('scene');
    const index = name === null ? 0 : state.scenes.findIndex((s) => s.name === name);
    if (index < 0) throw new Error('scene=' + name + ': not one of ' + state.scenes.map((s) => s.name).join(', '));
    state.left = variant(params.get('method') || data.default_method, 'method');
    state.split = params.has('split') && params.get('split') !== 'none';
    state.right = variant(state.split ? params.get('split') : data.default_split, 'split');
    state.exposure = params.has('exposure') ? Number(params.get('exposure')) : data.display.exposure;
    if (!Number.isFinite(state.exposure)) throw new Error('exposure=' + params.get('exposure') + ': must be a number');
    state.playing = params.get('paused') !== '1';
    document.body.classList.toggle('bare', params.get('ui') === '0');
    selectScene(index);
    const frame = intParam('frame', 0, state.scenes[index].animation.frames - 1);
    if (frame !== null) state.frame = state.position = frame;
    const divider = intParam('divider', 0, size()[0]);
    if (divider !== null) state.divider = divider;
    syncControls();
  }

  try {
    for (const s of data.scenes) state.scenes.push(SunglintScene.parse(encoder.encode(s.text), s.file));
    renderer = new SunglintHost.Renderer($('canvas'), data, window.SUNGLINT_SHADERS);
    state.left = variant(data.default_method, 'method');
    state.right = variant(data.default_split, 'split');
    controls();
    applyParams();
    window.addEventListener('hashchange', () => {
      try {
        document.title = 'drawing';
        state.ready = false;
        showError('');
        applyParams();
        state.dirty = true;
      } catch (e) {
        showError('sunglint: ' + e.message);
      }
    });
    // For scripts: the linear image shown (one side) as base64 float32 RGB, row 0 on top.
    const linear = () => {
      const bytes = new Uint8Array(renderer.readLinear().buffer);
      let s = '';
      for (let i = 0; i < bytes.length; i += 8192) s += String.fromCharCode(...bytes.subarray(i, i + 8192));
      return btoa(s);
    };
    window.sunglintPage = { state, timing, bench, renderer, linear };
    requestAnimationFrame(tick);
  } catch (e) {
    showError('sunglint: ' + e.message);
  }
})();
