// The scene loader's checks (src/scene/scene_load.cpp, src/scene/scene_limits.h) ported to
// JavaScript, for a scene file dropped on the web page: the same rules in the same order,
// so a malformed file gets the message `sunglint info FILE` prints, word for word (the
// web test runs both on every scene of tests/scenes/bad/ and compares). That takes a JSON
// reader of its own: JSON.parse reports neither the key path nor nlohmann's byte position
// of an error, nor duplicate keys, and accepts nothing but UTF-16; this one reads the file's
// bytes as nlohmann's lexer does (a UTF-8 BOM skipped, the error at the last byte read).
// Numbers are printed as C++'s ostream prints a double (%g, 6 significant digits).
//
// SunglintScene.parse(bytes, name) returns the scene (defaults applied, as sg::Scene) or
// throws an Error whose message is the CLI's, after "sunglint: ". Works in a page (a
// global) and in Node (module.exports).
'use strict';
const SunglintScene = (() => {
  const limits = {
    minWavelength: 1e-3, maxWavelength: 1e5, maxSteepness: 0.45, maxSlopeSum: 1000,
    maxAngularFrequency: 1e4, maxPhase: 1e6, maxTime: 1e7, minFps: 1e-3, maxFps: 1e6,
    maxShutter: 1.0, maxCameraDistance: 1e5, minCameraHeight: 1e-3, maxLookAtDistance: 1e7,
    minVfov: 1e-3, maxVfov: 179, minDirectionLength: 1e-12, maxDirectionLength: 1e12,
    minLightRadius: 1e-3, maxLightRadius: 89, maxRadiance: 1e10, maxSceneFileBytes: 64 * 1024 * 1024,
  };
  const kFormat = 'sunglint-scene/1', kFormat2 = 'sunglint-scene/2', kMaxImageSide = 16384;
  const kTwoPi = 6.283185307179586;

  class SceneError extends Error {}
  const fail = (path, rule) => { throw new SceneError(path + ': ' + rule); };
  const require = (ok, path, rule) => { if (!ok) fail(path, rule); };

  // A double as `std::ostream << double` prints it (printf's %g).
  function num(v) {
    if (Number.isNaN(v)) return 'nan';
    if (!Number.isFinite(v)) return v > 0 ? 'inf' : '-inf';
    if (v === 0) return Object.is(v, -0) ? '-0' : '0';
    const [mantissa, e] = v.toExponential(5).split('e');
    const exp = Number(e);
    if (exp < -4 || exp >= 6) {
      const m = mantissa.replace(/\.?0+$/, '');
      return m + 'e' + (exp < 0 ? '-' : '+') + String(Math.abs(exp)).padStart(2, '0');
    }
    const f = v.toFixed(5 - exp);
    return f.includes('.') ? f.replace(/\.?0+$/, '') : f;
  }

  // ---- JSON, as nlohmann's SAX parser reads it
  class JsonError extends Error {}
  function parseJson(bytes) {
    let pos = 0;
    if (bytes[0] === 0xef && bytes[1] === 0xbb && bytes[2] === 0xbf) pos = 3;
    const stack = [];  // {array, index, key, keys}
    const path = () => {
      let p = '';
      for (const f of stack) {
        if (f.array) p += '[' + f.index + ']';
        else if (f.key !== '') p += (p === '' ? '' : '.') + f.key;
      }
      return p;
    };
    const error = (at, reason) => {
      const e = new JsonError(reason || 'invalid JSON');
      e.at = at;
      e.path = path();
      throw e;
    };
    const value = () => { if (stack.length > 0 && stack[stack.length - 1].array) stack[stack.length - 1].index++; };
    const skipSpace = () => {
      while (pos < bytes.length && (bytes[pos] === 0x20 || bytes[pos] === 0x09 || bytes[pos] === 0x0a || bytes[pos] === 0x0d)) pos++;
    };
    const isDigit = (c) => c >= 0x30 && c <= 0x39;
    const hex = (c) => (isDigit(c) ? c - 0x30 : (c >= 0x61 && c <= 0x66) ? c - 87 : (c >= 0x41 && c <= 0x46) ? c - 55 : -1);
    // A token: {type, value, end}; `end` is the index of its last byte (an error there).
    function token() {
      skipSpace();
      const start = pos;
      if (pos >= bytes.length) return { type: 'eof', end: bytes.length };
      const c = bytes[pos];
      if ('{}[]:,'.includes(String.fromCharCode(c))) { pos++; return { type: String.fromCharCode(c), end: start }; }
      if (c === 0x22) return stringToken();
      if (c === 0x2d || isDigit(c)) return numberToken();
      for (const [word, v] of [['true', true], ['false', false], ['null', null]]) {
        if (c === word.charCodeAt(0)) {
          for (let k = 0; k < word.length; k++) {
            if (pos >= bytes.length) error(bytes.length);
            if (bytes[pos] !== word.charCodeAt(k)) error(pos);
            pos++;
          }
          return { type: 'literal', value: v, end: pos - 1 };
        }
      }
      error(pos);
    }
    function stringToken() {
      pos++;  // the opening quote
      const out = [];
      const next = () => (pos < bytes.length ? bytes[pos++] : (pos++, -1));
      const at = () => (pos - 1 < bytes.length ? pos - 1 : bytes.length);
      const codepoint = () => {
        let v = 0;
        for (let k = 0; k < 4; k++) {
          const d = hex(next());
          if (d < 0) error(at());
          v = v * 16 + d;
        }
        return v;
      };
      for (;;) {
        const c = next();
        if (c < 0) error(bytes.length);
        if (c === 0x22) break;
        if (c === 0x5c) {
          const e = next();
          const simple = { 0x22: '"', 0x5c: '\\', 0x2f: '/', 0x62: '\b', 0x66: '\f', 0x6e: '\n', 0x72: '\r', 0x74: '\t' };
          if (e in simple) { out.push(simple[e]); continue; }
          if (e !== 0x75) error(at());
          let cp = codepoint();
          if (cp >= 0xd800 && cp <= 0xdbff) {
            if (next() !== 0x5c) error(at());
            if (next() !== 0x75) error(at());
            const lo = codepoint();
            if (!(lo >= 0xdc00 && lo <= 0xdfff)) error(at());
            cp = 0x10000 + ((cp - 0xd800) << 10) + (lo - 0xdc00);
          } else if (cp >= 0xdc00 && cp <= 0xdfff) {
            error(at());
          }
          out.push(String.fromCodePoint(cp));
          continue;
        }
        if (c < 0x20) error(at());
        if (c < 0x80) { out.push(String.fromCharCode(c)); continue; }
        // UTF-8 (RFC 3629): the lead byte's ranges for each continuation byte.
        const ranges = c >= 0xc2 && c <= 0xdf ? [[0x80, 0xbf]]
          : c === 0xe0 ? [[0xa0, 0xbf], [0x80, 0xbf]]
          : (c >= 0xe1 && c <= 0xec) || c === 0xee || c === 0xef ? [[0x80, 0xbf], [0x80, 0xbf]]
          : c === 0xed ? [[0x80, 0x9f], [0x80, 0xbf]]
          : c === 0xf0 ? [[0x90, 0xbf], [0x80, 0xbf], [0x80, 0xbf]]
          : c >= 0xf1 && c <= 0xf3 ? [[0x80, 0xbf], [0x80, 0xbf], [0x80, 0xbf]]
          : c === 0xf4 ? [[0x80, 0x8f], [0x80, 0xbf], [0x80, 0xbf]] : null;
        if (!ranges) error(at());
        const seq = [c];
        for (const [lo, hi] of ranges) {
          const b = next();
          if (!(b >= lo && b <= hi)) error(at());
          seq.push(b);
        }
        out.push(new TextDecoder().decode(new Uint8Array(seq)));
      }
      return { type: 'string', value: out.join(''), end: pos - 1 };
    }
    function numberToken() {
      const start = pos;
      const at = () => (pos < bytes.length ? pos : bytes.length);
      const digits = () => { while (pos < bytes.length && isDigit(bytes[pos])) pos++; };
      if (bytes[pos] === 0x2d) pos++;
      if (pos >= bytes.length || !isDigit(bytes[pos])) error(at());
      if (bytes[pos] === 0x30) pos++; else digits();
      if (bytes[pos] === 0x2e) {
        pos++;
        if (pos >= bytes.length || !isDigit(bytes[pos])) error(at());
        digits();
      }
      if (bytes[pos] === 0x65 || bytes[pos] === 0x45) {
        pos++;
        if (bytes[pos] === 0x2b || bytes[pos] === 0x2d) pos++;
        if (pos >= bytes.length || !isDigit(bytes[pos])) error(at());
        digits();
      }
      const text = String.fromCharCode(...bytes.subarray(start, pos));
      const v = Number(text);
      if (!Number.isFinite(v)) error(pos - 1, 'number out of range');
      // An integer is nlohmann's int64 (or a double past its range): -0 is 0.
      const integer = !/[.eE]/.test(text);
      return { type: 'number', value: integer && v === 0 ? 0 : v, end: pos - 1 };
    }
    function parseValue(t) {
      if (t.type === '{') {
        const frame = { array: false, index: 0, key: '', keys: new Set() };
        stack.push(frame);
        const obj = {};
        let k = token();
        if (k.type === '}') { stack.pop(); value(); return obj; }
        for (;;) {
          if (k.type !== 'string') error(k.end);
          frame.key = k.value;
          if (frame.keys.has(k.value)) {
            const e = new JsonError('duplicate');
            e.duplicate = path();
            throw e;
          }
          frame.keys.add(k.value);
          const colon = token();
          if (colon.type !== ':') error(colon.end);
          obj[k.value] = parseValue(token());
          const sep = token();
          if (sep.type === '}') break;
          if (sep.type !== ',') error(sep.end);
          k = token();
        }
        stack.pop();
        value();
        return obj;
      }
      if (t.type === '[') {
        stack.push({ array: true, index: 0, key: '', keys: null });
        const arr = [];
        let v = token();
        if (v.type === ']') { stack.pop(); value(); return arr; }
        for (;;) {
          arr.push(parseValue(v));
          const sep = token();
          if (sep.type === ']') break;
          if (sep.type !== ',') error(sep.end);
          v = token();
        }
        stack.pop();
        value();
        return arr;
      }
      if (t.type === 'string' || t.type === 'number' || t.type === 'literal') {
        value();
        return t.value;
      }
      error(t.end);
    }
    const root = parseValue(token());
    const rest = token();
    if (rest.type !== 'eof') error(rest.end);
    return root;
  }

  function lineCol(bytes, at) {
    let line = 1, col = 1;
    for (let k = 0; k < at && k < bytes.length; k++) {
      if (bytes[k] === 0x0a) { line++; col = 1; } else col++;
    }
    return 'line ' + line + ', column ' + col;
  }

  // ---- the scene's keys (scene_load.cpp's ObjectReader and read_*)
  const isObject = (j) => j !== null && typeof j === 'object' && !Array.isArray(j);
  class ObjectReader {
    constructor(j, path) {
      if (!isObject(j)) fail(path === '' ? '(top level)' : path, 'must be an object');
      this.j = j;
      this.path = path;
      this.seen = new Set();
    }
    keyPath(key) { return this.path === '' ? key : this.path + '.' + key; }
    has(key) { return Object.prototype.hasOwnProperty.call(this.j, key); }
    get(key) {
      if (!this.has(key)) fail(this.keyPath(key), 'missing (required)');
      this.seen.add(key);
      return this.j[key];
    }
    number(key) { return asNumber(this.get(key), this.keyPath(key)); }
    numberOr(key, fallback) { return this.has(key) ? this.number(key) : fallback; }
    integer(key) {
      const p = this.keyPath(key);
      const v = asNumber(this.get(key), p);
      if (v !== Math.floor(v) || Math.abs(v) > 2e9) fail(p, 'must be an integer');
      return v;
    }
    booleanOr(key, fallback) {
      if (!this.has(key)) return fallback;
      const v = this.get(key);
      if (typeof v !== 'boolean') fail(this.keyPath(key), 'must be true or false');
      return v;
    }
    string(key) {
      const v = this.get(key);
      if (typeof v !== 'string') fail(this.keyPath(key), 'must be a string');
      return v;
    }
    choiceOr(key, options, fallback) {
      if (!this.has(key)) return fallback;
      const v = this.string(key);
      if (options.includes(v)) return v;
      fail(this.keyPath(key), 'must be one of ' + options.map((o) => '"' + o + '"').join(', ') + ' (got "' + v + '")');
    }
    vector(key, n) {
      const p = this.keyPath(key);
      const v = this.get(key);
      if (!Array.isArray(v) || v.length !== n) fail(p, 'must be an array of ' + n + ' numbers');
      return v.map((x, k) => asNumber(x, p + '[' + k + ']'));
    }
    object(key) { return new ObjectReader(this.get(key), this.keyPath(key)); }
    finish() {
      for (const k of Object.keys(this.j)) if (!this.seen.has(k)) fail(this.keyPath(k), 'unknown key');
    }
  }
  function asNumber(v, path) {
    if (typeof v !== 'number') fail(path, 'must be a number');
    if (!Number.isFinite(v)) fail(path, 'must be finite');
    return v;
  }

  const hypot3 = (v) => Math.hypot(v[0], v[1], v[2]);
  const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
  const len = (v) => Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  const normalize = (v) => { const s = 1 / len(v); return [v[0] * s, v[1] * s, v[2] * s]; };
  const cross = (a, b) => [a[1] * b[2] - b[1] * a[2], a[2] * b[0] - b[2] * a[0], a[0] * b[1] - b[0] * a[1]];

  function requireIn(v, lo, hi, path, unit, why = '') {
    if (!(v >= lo && v <= hi)) {
      fail(path, 'must be in [' + num(lo) + ', ' + num(hi) + ']' + (unit === '' ? '' : ' ' + unit) +
        (why === '' ? '' : ' (' + why + ')') + ', got ' + num(v));
    }
  }
  function requireDirection(v, path) {
    const l = hypot3(v);
    require(l >= limits.minDirectionLength, path, 'must not be zero-length');
    if (!(l <= limits.maxDirectionLength)) {
      fail(path, 'must have a length of at most ' + num(limits.maxDirectionLength) + ' (got ' + num(l) + ')');
    }
  }
  function checkRadiance(v, path) {
    require(v >= 0, path, 'must be >= 0');
    if (!(v <= limits.maxRadiance)) fail(path, 'must be at most ' + num(limits.maxRadiance) + ' (got ' + num(v) + ')');
    return v;
  }
  const kNeeds2 = 'needs "format": "' + kFormat2 + '"';
  function readRadiance(o, key, fallback, version) {
    if (!o.has(key)) return [fallback, fallback, fallback];
    const p = o.keyPath(key);
    const v = o.get(key);
    const shape = 'must be a number or an array of 3 numbers [r, g, b]';
    if (Array.isArray(v)) {
      require(version >= 2, p, 'an [r, g, b] radiance ' + kNeeds2);
      require(v.length === 3, p, shape);
      return v.map((x, k) => checkRadiance(asNumber(x, p + '[' + k + ']'), p + '[' + k + ']'));
    }
    if (version >= 2 && typeof v !== 'number') fail(p, shape);
    const g = checkRadiance(asNumber(v, p), p);
    return [g, g, g];
  }
  function readSky(o, version) {
    const z = o.has('zenith'), h = o.has('horizon');
    if (version < 2) for (const k of ['zenith', 'horizon', 'exponent']) require(!o.has(k), o.keyPath(k), kNeeds2);
    let sky;
    if (!z && !h) {
      require(!o.has('exponent'), o.keyPath('exponent'), 'needs the gradient sky (sky.zenith and sky.horizon)');
      const r = readRadiance(o, 'radiance', 0.0, version);
      sky = { zenith: r, horizon: r, exponent: 0.5, gradient: false };
    } else {
      require(!o.has('radiance'), o.keyPath('radiance'),
        'not allowed with sky.zenith and sky.horizon (a sky is constant or a gradient)');
      require(z, o.keyPath('zenith'), 'missing (required with sky.horizon)');
      require(h, o.keyPath('horizon'), 'missing (required with sky.zenith)');
      sky = { gradient: true };
      sky.zenith = readRadiance(o, 'zenith', 0.0, version);
      sky.horizon = readRadiance(o, 'horizon', 0.0, version);
      sky.exponent = o.numberOr('exponent', 0.5);
      require(sky.exponent > 0, o.keyPath('exponent'), 'must be > 0');
    }
    o.finish();
    return sky;
  }
  function readCamera(o) {
    const c = { position: o.vector('position', 3), look_at: o.vector('look_at', 3), up: o.vector('up', 3) };
    c.vfov_deg = o.number('vfov_deg');
    if (!(hypot3(c.position) <= limits.maxCameraDistance)) {
      fail(o.keyPath('position'), 'must be within ' + num(limits.maxCameraDistance) +
        ' m of the origin (got |position| = ' + num(hypot3(c.position)) + ' m)');
    }
    if (!(c.position[1] >= limits.minCameraHeight)) {
      fail(o.keyPath('position'), 'must be above the water at rest (y >= ' + num(limits.minCameraHeight) + ' m)');
    }
    if (!(hypot3(c.look_at) <= limits.maxLookAtDistance)) {
      fail(o.keyPath('look_at'), 'must be within ' + num(limits.maxLookAtDistance) +
        ' m of the origin (got |look_at| = ' + num(hypot3(c.look_at)) + ' m)');
    }
    require(len(sub(c.look_at, c.position)) > 1e-6, o.keyPath('look_at'), 'must differ from camera.position');
    requireDirection(c.up, o.keyPath('up'));
    require(len(cross(normalize(sub(c.look_at, c.position)), normalize(c.up))) > 1e-6, o.keyPath('up'),
      'must not be parallel to the viewing direction');
    requireIn(c.vfov_deg, limits.minVfov, limits.maxVfov, o.keyPath('vfov_deg'), 'degrees');
    o.finish();
    return c;
  }
  function readLight(o, version) {
    const l = { direction: o.vector('direction', 3) };
    requireDirection(l.direction, o.keyPath('direction'));
    l.angular_radius_deg = o.number('angular_radius_deg');
    requireIn(l.angular_radius_deg, limits.minLightRadius, limits.maxLightRadius, o.keyPath('angular_radius_deg'), 'degrees');
    l.radiance = readRadiance(o, 'radiance', 1.0, version);
    l.visible = o.booleanOr('visible', false);
    o.finish();
    return l;
  }
  function readWave(o) {
    const w = { amplitude: o.number('amplitude') };
    require(w.amplitude >= 0, o.keyPath('amplitude'), 'must be >= 0');
    w.wave_vector = o.vector('wave_vector', 2);
    const k = Math.sqrt(w.wave_vector[0] * w.wave_vector[0] + w.wave_vector[1] * w.wave_vector[1]);
    if (!(k >= kTwoPi / limits.maxWavelength && k <= kTwoPi / limits.minWavelength)) {
      fail(o.keyPath('wave_vector'), 'the wavelength 2 pi / |k| must be in [' + num(limits.minWavelength) + ', ' +
        num(limits.maxWavelength) + '] m (got ' + (k > 0 ? num(kTwoPi / k) + ' m' : '|k| = 0') + ')');
    }
    if (!(w.amplitude * k <= limits.maxSteepness)) {
      fail(o.keyPath('amplitude'), 'the steepness amplitude * |wave_vector| must be at most ' +
        num(limits.maxSteepness) + " (Stokes' limit of breaking), got " + num(w.amplitude * k));
    }
    w.angular_frequency = o.number('angular_frequency');
    requireIn(w.angular_frequency, -limits.maxAngularFrequency, limits.maxAngularFrequency, o.keyPath('angular_frequency'), 'rad/s');
    w.phase = o.numberOr('phase', 0.0);
    requireIn(w.phase, -limits.maxPhase, limits.maxPhase, o.keyPath('phase'), 'rad');
    o.finish();
    return w;
  }
  function readSurface(o, version) {
    const s = {};
    s.geometry = o.choiceOr('geometry', ['flat', 'displaced'], 'flat');
    s.fresnel = o.choiceOr('fresnel', ['none', 'schlick'], 'none');
    s.sea_radiance = readRadiance(o, 'sea_radiance', 0.0, version);
    const wpath = o.keyPath('waves');
    const waves = o.get('waves');
    require(Array.isArray(waves), wpath, 'must be an array of wave objects');
    let slopeSum = 0;
    s.waves = [];
    waves.forEach((w, k) => {
      const r = readWave(new ObjectReader(w, wpath + '[' + k + ']'));
      s.waves.push(r);
      slopeSum += r.amplitude * Math.sqrt(r.wave_vector[0] * r.wave_vector[0] + r.wave_vector[1] * r.wave_vector[1]);
    });
    if (!(slopeSum <= limits.maxSlopeSum)) {
      fail(wpath, 'the sum of the steepnesses amplitude * |wave_vector| must be at most ' +
        num(limits.maxSlopeSum) + ' (got ' + num(slopeSum) + ')');
    }
    o.finish();
    return s;
  }
  function readAnimation(o) {
    const T = limits.maxTime;
    const a = {};
    a.t0 = o.number('t0');
    requireIn(a.t0, -T, T, o.keyPath('t0'), 's');
    a.fps = o.number('fps');
    requireIn(a.fps, limits.minFps, limits.maxFps, o.keyPath('fps'), 'frames per second');
    a.frames = o.integer('frames');
    require(a.frames >= 1, o.keyPath('frames'), 'must be >= 1');
    a.shutter = o.number('shutter');
    requireIn(a.shutter, 0, limits.maxShutter, o.keyPath('shutter'), 'of the frame interval');
    const first = a.t0 - a.shutter / a.fps, last = a.t0 + (a.frames - 1) / a.fps;
    if (!(first >= -T)) {
      fail(o.keyPath('t0'), "frame 0's shutter opens at t0 - shutter / fps = " + num(first) + ' s, before -' + num(T) + ' s');
    }
    if (!(last <= T)) {
      fail(o.keyPath('frames'), 'the last frame is at t0 + (frames - 1) / fps = ' + num(last) + ' s, after ' + num(T) + ' s');
    }
    o.finish();
    return a;
  }

  // The file's name without folders and extension (std::filesystem::path::stem).
  function stem(name) {
    const base = name.split('/').pop();
    const dot = base.lastIndexOf('.');
    return dot > 0 ? base.slice(0, dot) : base;
  }

  // The scene in `bytes` (a Uint8Array: the file), or an Error with the CLI's message.
  function parse(bytes, name) {
    if (bytes.length > limits.maxSceneFileBytes) {
      throw new Error(name + ': cannot read: ' + bytes.length + ' bytes, more than the ' +
        limits.maxSceneFileBytes + ' allowed');
    }
    let j;
    try {
      j = parseJson(bytes);
    } catch (e) {
      if (!(e instanceof JsonError)) throw e;
      if (e.duplicate !== undefined) {
        throw new Error(name + ': ' + e.duplicate + ': duplicate key (JSON object keys must be unique)');
      }
      const at = lineCol(bytes, e.at);
      throw new Error(name + ': ' + (e.path === '' ? '' : e.path + ': ') + e.message + ' at ' + at);
    }
    try {
      const top = new ObjectReader(j, '');
      const format = top.string('format');
      require(format === kFormat || format === kFormat2, 'format',
        'must be "' + kFormat + '" or "' + kFormat2 + '" (got "' + format + '")');
      const version = format === kFormat ? 1 : 2;
      const s = {};
      s.name = top.has('name') ? top.string('name') : stem(name);
      {
        const img = top.object('image');
        s.width = img.integer('width');
        s.height = img.integer('height');
        require(s.width >= 1 && s.width <= kMaxImageSide, 'image.width', 'must be an integer in [1, ' + kMaxImageSide + ']');
        require(s.height >= 1 && s.height <= kMaxImageSide, 'image.height', 'must be an integer in [1, ' + kMaxImageSide + ']');
        img.finish();
      }
      s.camera = readCamera(top.object('camera'));
      s.light = readLight(top.object('light'), version);
      s.sky = top.has('sky') ? readSky(top.object('sky'), version)
        : { zenith: [0, 0, 0], horizon: [0, 0, 0], exponent: 0.5, gradient: false };
      s.surface = readSurface(top.object('surface'), version);
      s.animation = readAnimation(top.object('animation'));
      top.finish();
      return s;
    } catch (e) {
      if (e instanceof SceneError) throw new Error(name + ': ' + e.message);
      throw e;
    }
  }

  return { parse, num, limits };
})();
if (typeof module !== 'undefined') module.exports = SunglintScene;
