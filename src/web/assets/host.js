// sunglint's shading kernel in a browser: the minimal host of the kernel in WebGL 2, written
// to be read first by whoever ports the kernel (docs/porting.md). It does what every host
// does (docs/porting.md, "What the host computes per frame"): builds one frame's inputs from
// a scene in double (JavaScript's numbers) -- the camera-relative frame, the waves sorted by
// |k| with their phases reduced on the host, the rotations to the shutter's instants, the
// suffix sums -- uploads them as uniforms of the kernel's own structs and a float texture,
// and draws the kernel's GLSL (src/kernel/*.glsl, compiled as GLSL ES 3.00 fragment
// shaders: kernel/glsl_es_prelude.glsl) one fragment per pixel, then the display pipeline's
// passes (image/display.glsl). It also makes the path table S from the fine grids of F
// the page carries, with the kernel's functions (kernel/path_table_gen.glsl).
//
// Nothing of the shading is written here: every formula of a pixel is the kernel's GLSL.
// What is here mirrors host code: shading/kernel_frame.cpp (the frame's inputs),
// scene/camera.cpp and scene/light.cpp (the camera and light models), image/glare.cpp's
// kernel weights, gl_engine/uniforms.cpp (the uniforms), shading/path_table.cpp's loop.
'use strict';
const SunglintHost = (() => {
  // ---- vectors in double
  const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const scale = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
  const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
  const cross = (a, b) => [a[1] * b[2] - b[1] * a[2], a[2] * b[0] - b[2] * a[0], a[0] * b[1] - b[0] * a[1]];
  const length = (a) => Math.sqrt(dot(a, a));
  const normalize = (a) => scale(a, 1 / Math.sqrt(dot(a, a)));  // glm: v * inversesqrt(dot(v, v))
  const radians = (deg) => deg * 0.017453292519943295;
  const kTwoPi = 6.283185307179586;

  // x - n 2 pi for the integer n nearest x / (2 pi), as std::remainder: n 2 pi split exactly
  // into p + e (Dekker's product), so the result has one rounding even for x ~ 1e11.
  function reduceAngle(x) {
    const n = Math.round(x / kTwoPi);
    if (n === 0) return x;
    const split = (a) => { const c = 134217729 * a; const hi = c - (c - a); return [hi, a - hi]; };
    const p = n * kTwoPi;
    const [nh, nl] = split(n), [th, tl] = split(kTwoPi);
    const e = ((nh * th - p) + nh * tl + nl * th) + nl * tl;
    return (x - p) - e;
  }

  // The camera (scene/camera.cpp) and the light (scene/light.cpp).
  function cameraModel(c, width, height) {
    const forward = normalize(sub(c.look_at, c.position));
    const right = normalize(cross(forward, normalize(c.up)));
    const up = cross(right, forward);
    const halfH = Math.tan(radians(c.vfov_deg) / 2);
    return { position: c.position, forward, right, up, halfH, halfW: halfH * width / height };
  }
  function lightModel(l) {
    const L = normalize(l.direction);
    const h = cross([0, 1, 0], L);
    const e1 = length(h) > 1e-9 ? normalize(h) : [1, 0, 0];
    const radius = radians(l.angular_radius_deg);
    return { L, e1, e2: cross(L, e1), radius, visible: l.visible };
  }

  // Frame f integrates [t_f - shutter / fps, t_f], t_f = t0 + f / fps (scene/scene.h).
  function frameTime(a, frame) {
    const end = a.t0 + frame / a.fps;
    return { start: end - a.shutter / a.fps, end };
  }

  // The kernel's inputs for frame `frame` of `scene` at width x height with `variant` (the
  // GL engine's settings of a method, from the page's data): the uniforms by name and the
  // wave buffer's texels (kernel/waves.glsl gives the layout).
  function frameInputs(scene, width, height, frame, variant) {
    const cam = cameraModel(scene.camera, width, height);
    const light = lightModel(scene.light);
    const ft = frameTime(scene.animation, frame);
    const duration = ft.end - ft.start;
    const K = variant.segments;
    const stride = 2 + Math.floor((K + 1) / 2);
    const waves = scene.surface.waves;
    const n = waves.length;
    let amplitudeBound = 0, slopeBound = 0;
    for (const w of waves) {
      amplitudeBound += Math.abs(w.amplitude);
      slopeBound += Math.abs(w.amplitude) * Math.sqrt(w.wave_vector[0] ** 2 + w.wave_vector[1] ** 2);
    }
    const u = {
      'frame.camera.position': [0, cam.position[1], 0], 'frame.camera.forward': cam.forward,
      'frame.camera.right': cam.right, 'frame.camera.up': cam.up, 'frame.camera.half_w': cam.halfW,
      'frame.camera.half_h': cam.halfH, 'frame.camera.width': width, 'frame.camera.height': height,
      'frame.camera_keys.count': 0, 'frame.camera_keys.up': cam.up, // a fixed camera: no keys
      'frame.light.L': light.L, 'frame.light.e1': light.e1, 'frame.light.e2': light.e2,
      'frame.light.radius': light.radius, 'frame.light.cos_radius': Math.cos(light.radius),
      'frame.light.sin_radius': Math.sin(light.radius), 'frame.light.tan_radius': Math.tan(light.radius),
      'frame.light.chord2': 4 * Math.sin(0.5 * light.radius) ** 2, 'frame.light.visible': light.visible,
      'frame.fresnel': scene.surface.fresnel === 'none' ? 0 : 1,
      'frame.displaced': scene.surface.geometry === 'displaced',
      'frame.sky_gradient': scene.sky.gradient, 'frame.sky_exponent': scene.sky.exponent,
      'frame.wave_count': n, 'frame.wave_stride': stride, 'frame.amplitude_bound': amplitudeBound,
      'frame.slope_bound': slopeBound, 'frame.intersect_tolerance': variant.intersect_tolerance,
      'frame.duration': duration, 'frame.segments': K, 'frame.windows': 1, 'frame.frame': frame,
      'frame.cascade_count': 0, 'frame.cascade_base': 0, // the page refuses cascades
      'frame.seed': variant.seed,
    };
    for (let q = 0; q < 8; ++q) { // kMaxCameraKeys (kernel/interface.glsl), unused with count 0
      u[`frame.camera_keys.time[${q}]`] = 0;
      u[`frame.camera_keys.position[${q}]`] = [0, 0, 0];
      u[`frame.camera_keys.look_at[${q}]`] = [0, 0, 0];
    }
    // The waves sorted by |k| (ties in file order), then the sums from each position on.
    const k = waves.map((w) => Math.hypot(w.wave_vector[0], w.wave_vector[1]));
    const order = waves.map((_, i) => i).sort((p, q) => k[p] - k[q] || p - q);
    const texels = new Float32Array(4 * (n * stride + 2 * (n + 1)));
    const xc = scene.camera.position[0], zc = scene.camera.position[2], t = ft.end;
    order.forEach((i, q) => {
      const w = waves[i];
      const a = w.wave_vector[0], b = w.wave_vector[1], c = w.angular_frequency;
      const theta0 = reduceAngle(a * xc + b * zc + reduceAngle(c * t) + reduceAngle(w.phase));
      texels.set([w.amplitude, a, b, theta0, c, k[i], w.amplitude * k[i], 0], 4 * q * stride);
      for (let s = 0; s < K; s++) {
        const delta = reduceAngle(c * (duration * (K - s) / K));
        texels.set([Math.cos(delta), Math.sin(delta)], 4 * (q * stride + 2 + (s >> 1)) + 2 * (s & 1));
      }
    });
    const base = n * stride;
    const preA = [0], preAk = [0];
    order.forEach((i, q) => {
      preA.push(preA[q] + waves[i].amplitude);
      preAk.push(preAk[q] + waves[i].amplitude * k[i]);
    });
    let sxx = 0, sxz = 0, szz = 0, sA2 = 0, sA = 0;
    for (let q = n; q >= 0; q--) {
      if (q < n) {
        const w = waves[order[q]], a = w.wave_vector[0], b = w.wave_vector[1];
        const e = 0.5 * w.amplitude * w.amplitude;
        sxx += e * a * a;
        sxz += e * a * b;
        szz += e * b * b;
        sA2 += w.amplitude * w.amplitude;
        sA += w.amplitude;
      }
      texels.set([sxx, sxz, szz, sA2, sA, preA[q], preAk[q], 0], 4 * (base + 2 * q));
    }
    for (const [group, values] of Object.entries(variant.uniforms)) {
      for (const [field, v] of Object.entries(values)) u[group + '.' + field] = v;
    }
    return { uniforms: u, texels };
  }

  // The weights of the scene's radiances per channel (scene/model.h, Radiances).
  function radiances(scene) {
    const r = [scene.light.radiance, scene.sky.zenith, scene.sky.horizon, scene.surface.sea_radiance];
    return [0, 1, 2].map((c) => r.map((v) => v[c]));
  }

  // The glare's kernels at `height` rows (image/glare.cpp: gaussian_kernel, streak_kernel).
  function glareKernels(g, height) {
    const kernel = (r, f) => {
      const k = [];
      for (let t = -r; t <= r; t++) k.push(f(t));
      const sum = k.reduce((s, v) => s + v, 0);
      return k.map((v) => v / sum);
    };
    const gaussian = (s) => (s > 0 ? kernel(Math.ceil(3 * s), (t) => Math.exp(-0.5 * t * t / (s * s))) : [1]);
    const streak = (l) => (l > 0 ? kernel(Math.ceil(4 * l), (t) => Math.exp(-Math.abs(t) / l)) : [1]);
    const taps = [], passes = [];
    let total = 0;
    const add = (k) => { const offset = taps.length; taps.push(...k); return { offset, radius: (k.length - 1) / 2 }; };
    for (const [sigma, weight] of g.blurs) {
      passes.push({ kind: 'blur', weight, ...add(gaussian(sigma * height)) });
      total += weight;
    }
    if (g.star_points > 0 && g.star_weight > 0) {
      const streaks = g.star_points / 2, s = add(streak(g.star_length * height));
      for (let i = 0; i < streaks; i++) {
        const a = (g.star_angle_deg + 180.0 * i / streaks) * Math.PI / 180.0;
        passes.push({ kind: 'streak', weight: g.star_weight / streaks, dir: [Math.cos(a), Math.sin(a)], ...s });
        total += g.star_weight / streaks;
      }
    }
    return { taps: new Float32Array(taps), passes, total };
  }

  // ---- WebGL 2
  function base64Floats(text) {
    const bin = atob(text);
    const bytes = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
    return new Float32Array(bytes.buffer);
  }

  // The text of shader `name` with its #include lines replaced by those files.
  function expand(sources, name) {
    if (!(name in sources)) throw new Error('shader source ' + name + ' is not in the page');
    return sources[name].replace(/^#include "(.*)"$/gm, (_, f) => expand(sources, f));
  }

  class Renderer {
    constructor(canvas, data, sources) {
      const gl = canvas.getContext('webgl2', { antialias: false, preserveDrawingBuffer: true, alpha: false });
      if (!gl) throw new Error('this browser gives no WebGL 2 context');
      if (!gl.getExtension('EXT_color_buffer_float')) {
        throw new Error('this browser cannot render to float textures (EXT_color_buffer_float)');
      }
      this.gl = gl;
      this.data = data;
      this.sources = sources;
      this.timer = gl.getExtension('EXT_disjoint_timer_query_webgl2');
      this.pending = [];
      this.programs = new Map();
      this.vao = gl.createVertexArray();
      this.size = [0, 0];
      this.tablesReady = false;
      const t = data.tables;
      this.tableF = this.texture(gl.R32F, t.info.n_distance, t.info.n_sigma, base64Floats(t.f));
      this.fits = this.texture(gl.R32F, 15, t.fits_rows, base64Floats(t.fits));
      this.wavesTexture = null;
    }

    // A program from fragment shader sources (joined after "#version 300 es" and `header`).
    program(key, header, names) {
      if (this.programs.has(key)) return this.programs.get(key);
      const gl = this.gl;
      const shader = (type, text) => {
        const s = gl.createShader(type);
        gl.shaderSource(s, text);
        gl.compileShader(s);
        if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) {
          throw new Error('shader ' + key + ' does not compile: ' + gl.getShaderInfoLog(s));
        }
        return s;
      };
      const p = gl.createProgram();
      gl.attachShader(p, shader(gl.VERTEX_SHADER, '#version 300 es\n' + expand(this.sources, 'web/shaders/fullscreen.glsl')));
      const text = '#version 300 es\n' + header + names.map((n) => expand(this.sources, n)).join('\n');
      gl.attachShader(p, shader(gl.FRAGMENT_SHADER, text));
      gl.linkProgram(p);
      if (!gl.getProgramParameter(p, gl.LINK_STATUS)) throw new Error('program ' + key + ' does not link: ' + gl.getProgramInfoLog(p));
      this.programs.set(key, p);
      return p;
    }

    // Every active uniform of `p` from `values` by name (gl_engine/uniforms.cpp): a uniform
    // the host does not write is an error, not a silent zero. Samplers take texture units.
    use(p, values, textures = {}) {
      const gl = this.gl;
      gl.useProgram(p);
      let unit = 0;
      const n = gl.getProgramParameter(p, gl.ACTIVE_UNIFORMS);
      for (let i = 0; i < n; i++) {
        const { name, type } = gl.getActiveUniform(p, i);
        const at = gl.getUniformLocation(p, name);
        if (type === gl.SAMPLER_2D || type === gl.SAMPLER_2D_ARRAY) {
          if (!(name in textures)) throw new Error('texture ' + name + ' not bound');
          gl.activeTexture(gl.TEXTURE0 + unit);
          gl.bindTexture(type === gl.SAMPLER_2D ? gl.TEXTURE_2D : gl.TEXTURE_2D_ARRAY, textures[name]);
          gl.uniform1i(at, unit++);
          continue;
        }
        if (!(name in values)) throw new Error('uniform ' + name + ' not set');
        const v = values[name];
        switch (type) {
          case gl.FLOAT: gl.uniform1f(at, v); break;
          case gl.FLOAT_VEC2: gl.uniform2fv(at, v); break;
          case gl.FLOAT_VEC3: gl.uniform3fv(at, v); break;
          case gl.FLOAT_VEC4: gl.uniform4fv(at, v); break;
          case gl.INT: gl.uniform1i(at, v); break;
          case gl.INT_VEC2: gl.uniform2iv(at, v); break;
          case gl.BOOL: gl.uniform1i(at, v ? 1 : 0); break;
          case gl.UNSIGNED_INT_VEC2: gl.uniform2uiv(at, v); break;
          default: throw new Error('uniform ' + name + ': type ' + type + ' not handled');
        }
      }
    }

    texture(internal, w, h, data = null, layers = 0) {
      const gl = this.gl;
      const target = layers > 0 ? gl.TEXTURE_2D_ARRAY : gl.TEXTURE_2D;
      const t = gl.createTexture();
      gl.bindTexture(target, t);
      const [format, type] = internal === gl.R32F ? [gl.RED, gl.FLOAT]
        : internal === gl.RGBA8 ? [gl.RGBA, gl.UNSIGNED_BYTE] : [gl.RGBA, gl.FLOAT];
      if (layers > 0) gl.texImage3D(target, 0, internal, w, h, layers, 0, format, type, data);
      else gl.texImage2D(target, 0, internal, w, h, 0, format, type, data);
      gl.texParameteri(target, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
      gl.texParameteri(target, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
      gl.texParameteri(target, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
      gl.texParameteri(target, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
      return t;
    }

    // Draws `p` over w x h texels into `targets` (textures, or [texture, layer] pairs).
    draw(targets, w, h) {
      const gl = this.gl;
      if (!this.fbo) this.fbo = gl.createFramebuffer();
      gl.bindFramebuffer(gl.FRAMEBUFFER, targets.length > 0 ? this.fbo : null);
      targets.forEach((t, i) => {
        if (Array.isArray(t)) gl.framebufferTextureLayer(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0 + i, t[0], 0, t[1]);
        else gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0 + i, gl.TEXTURE_2D, t, 0);
      });
      if (targets.length > 0) {
        for (let i = targets.length; i < 2; i++) gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0 + i, gl.TEXTURE_2D, null, 0);
        gl.drawBuffers(targets.map((_, i) => gl.COLOR_ATTACHMENT0 + i));
      }
      gl.viewport(0, 0, w, h);
      gl.bindVertexArray(this.vao);
      gl.drawArrays(gl.TRIANGLES, 0, 3);
    }

    // The path table S (kernel/path_table_gen.glsl, web/shaders/tables.glsl), made once.
    makeTables() {
      if (this.tablesReady) return;
      const start = performance.now();
      const gl = this.gl, t = this.data.tables, info = t.info;
      const cellsN = info.n_u - 1;  // the u cells of [-R, 0]
      const fine = base64Floats(t.fine);
      const width = 1024, rows = Math.ceil(fine.length / width);  // as glsl_es_prelude.glsl reads it
      const padded = new Float32Array(width * rows);
      padded.set(fine);
      const fineTexture = this.texture(gl.R32F, width, rows, padded);
      const a = this.texture(gl.R32F, cellsN, info.n_v, null, info.n_sigma);
      const b = this.texture(gl.R32F, cellsN, info.n_v, null, info.n_sigma);
      this.tableS = this.texture(gl.R32F, info.n_u, info.n_v, null, info.n_sigma);
      const sources = ['kernel/glsl_es_prelude.glsl', 'kernel/path_table_gen.glsl', 'kernel/path_table_grid.glsl', 'web/shaders/tables.glsl'];
      const cells = this.program('cells', '#define SG_PASS_CELLS\n', sources);
      const scan = this.program('scan', '#define SG_PASS_SCAN\n', sources);
      const assemble = this.program('assemble', '#define SG_PASS_ASSEMBLE\n', sources);
      t.slices.forEach((s, k) => {
        if (k === 0) return;  // sigma = 0: the chord, in the assembly
        this.use(cells, { fine_offset: s.offset, fine_count: s.count, fine_step: s.step, extent: s.extent,
          n_u: info.n_u, n_v: info.n_v, panels: s.panels }, { fine: fineTexture });
        this.draw([[a, k]], cellsN, info.n_v);
      });
      let from = a, to = b;
      for (let shift = 1; shift < cellsN; shift *= 2) {
        for (let k = 1; k < info.n_sigma; k++) {
          this.use(scan, { layer: k, shift }, { src: from });
          this.draw([[to, k]], cellsN, info.n_v);
        }
        [from, to] = [to, from];
      }
      t.slices.forEach((s, k) => {
        this.use(assemble, { layer: k, n_u: info.n_u, n_v: info.n_v, extent: s.extent, chord: k === 0 }, { prefix: from });
        this.draw([[this.tableS, k]], info.n_u, info.n_v);
      });
      for (const x of [a, b, fineTexture]) gl.deleteTexture(x);
      // Wait for the GPU (one texel read back), so that the time is the making's.
      gl.bindFramebuffer(gl.FRAMEBUFFER, this.fbo);
      gl.framebufferTextureLayer(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, this.tableS, 0, info.n_sigma - 1);
      gl.readBuffer(gl.COLOR_ATTACHMENT0);
      gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.FLOAT, new Float32Array(4));
      this.tablesMs = performance.now() - start;
      this.tablesReady = true;
    }

    resize(w, h) {
      if (this.size[0] === w && this.size[1] === h) return;
      const gl = this.gl;
      for (const x of this.images || []) gl.deleteTexture(x);
      const f = () => this.texture(gl.RGBA32F, w, h);
      this.weights = f();
      this.x = f();
      this.b = f();
      this.tmp = f();
      this.acc = [f(), f()];
      this.bytes = [this.texture(gl.RGBA8, w, h), this.texture(gl.RGBA8, w, h)];
      this.images = [this.weights, this.x, this.b, this.tmp, ...this.acc, ...this.bytes];
      this.size = [w, h];
      gl.canvas.width = w;
      gl.canvas.height = h;
    }

    // The kernel pass of `variant` for frame `frame` of `scene` into this.weights; its GPU
    // time lands in `timing[variant.id]` a few frames later (timer queries), where present.
    kernel(scene, frame, variant, timing) {
      const gl = this.gl, [w, h] = this.size;
      if (variant.define === 'SG_METHOD_STAA') this.makeTables();
      const { uniforms, texels } = frameInputs(scene, w, h, frame, variant);
      const width = 1024, rows = Math.max(1, Math.ceil(texels.length / 4 / width));  // glsl_es_prelude.glsl
      const padded = new Float32Array(4 * width * rows);
      padded.set(texels);
      if (this.wavesTexture) gl.deleteTexture(this.wavesTexture);
      this.wavesTexture = this.texture(gl.RGBA32F, width, rows, padded);
      const p = this.program(variant.id, variant.header,
        ['kernel/glsl_es_prelude.glsl', 'kernel/interface.glsl', 'kernel/kernel.glsl', 'web/shaders/kernel.glsl']);
      this.use(p, uniforms, { waves: this.wavesTexture, table_f: this.tableF, table_s: this.tableS || this.tableF, fits: this.fits });
      const query = this.timer ? gl.createQuery() : null;
      if (query) gl.beginQuery(this.timer.TIME_ELAPSED_EXT, query);
      this.draw([this.weights], w, h);
      if (query) {
        gl.endQuery(this.timer.TIME_ELAPSED_EXT);
        this.pending.push({ query, id: variant.id, timing });
      }
    }

    // The finished timer queries' GPU times, in ms, into their `timing`s (none when the GPU
    // was disjoint meanwhile: a clock change, another context).
    pollTimer() {
      const gl = this.gl;
      const disjoint = this.timer && gl.getParameter(this.timer.GPU_DISJOINT_EXT);
      this.pending = this.pending.filter((q) => {
        if (!gl.getQueryParameter(q.query, gl.QUERY_RESULT_AVAILABLE)) return true;
        if (!disjoint) q.timing[q.id] = gl.getQueryParameter(q.query, gl.QUERY_RESULT) / 1e6;
        gl.deleteQuery(q.query);
        return false;
      });
    }

    // this.weights through the display pipeline (image/tonemap.h) into this.bytes[side].
    display(scene, side, exposure, glare) {
      const gl = this.gl, [w, h] = this.size;
      const g = this.data.display.glare;
      const src = ['kernel/glsl_es_prelude.glsl', 'image/display.glsl', 'web/shaders/display.glsl'];
      const pass = (name) => this.program('display-' + name, '#define SG_PASS_' + name.toUpperCase() + '\n', src);
      const [r, gr, b] = radiances(scene);
      this.use(pass('expose'), { radiance_r: r, radiance_g: gr, radiance_b: b, scale: 2 ** exposure,
        threshold: g.threshold }, { src: this.weights });
      this.draw([this.x, this.b], w, h);
      let total = 0;
      if (glare) {
        const kernels = this.glareKernels(g, h);
        total = kernels.total;
        gl.bindFramebuffer(gl.FRAMEBUFFER, this.fbo);
        gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, this.acc[0], 0);
        gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT1, gl.TEXTURE_2D, null, 0);
        gl.drawBuffers([gl.COLOR_ATTACHMENT0]);
        gl.clearBufferfv(gl.COLOR, 0, [0, 0, 0, 0]);
        let acc = 0;
        for (const k of kernels.passes) {
          const common = { size: [w, h], offset: k.offset, radius: k.radius, weight: k.weight };
          if (k.kind === 'blur') {
            this.use(pass('blur'), { ...common, axis: [1, 0], accumulate: false }, { src: this.b, acc_in: this.acc[acc], taps: kernels.texture });
            this.draw([this.tmp], w, h);
            this.use(pass('blur'), { ...common, axis: [0, 1], accumulate: true }, { src: this.tmp, acc_in: this.acc[acc], taps: kernels.texture });
          } else {
            this.use(pass('streak'), { ...common, dir: k.dir }, { src: this.b, acc_in: this.acc[acc], taps: kernels.texture });
          }
          this.draw([this.acc[1 - acc]], w, h);
          acc = 1 - acc;
        }
        this.accIndex = acc;
      }
      this.use(pass('finish'), { total_weight: total, glare }, { x_in: this.x, b_in: this.b, acc_in: this.acc[this.accIndex || 0] });
      this.draw([this.bytes[side]], w, h);
    }

    glareKernels(g, h) {
      if (this.kernels && this.kernels.height === h) return this.kernels;
      const k = glareKernels(g, h);
      if (this.kernels) this.gl.deleteTexture(this.kernels.texture);
      k.texture = this.texture(this.gl.R32F, k.taps.length, 1, k.taps);
      k.height = h;
      this.kernels = k;
      return k;
    }

    // The last side's exposed linear image (the display's input: radiances applied, times
    // 2^exposure), RGB floats, row 0 on top: for tests against `render -o x.pfm`.
    readLinear() {
      const gl = this.gl, [w, h] = this.size;
      gl.bindFramebuffer(gl.FRAMEBUFFER, this.fbo);
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, this.x, 0);
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT1, gl.TEXTURE_2D, null, 0);
      gl.readBuffer(gl.COLOR_ATTACHMENT0);
      const rgba = new Float32Array(4 * w * h);
      gl.readPixels(0, 0, w, h, gl.RGBA, gl.FLOAT, rgba);
      const rgb = new Float32Array(3 * w * h);
      for (let i = 0; i < w * h; i++) rgb.set(rgba.subarray(4 * i, 4 * i + 3), 3 * i);
      return rgb;
    }

    // The canvas: columns [0, divider) from side 0's picture, the rest from side 1's.
    compose(divider) {
      const [w, h] = this.size;
      const src = ['kernel/glsl_es_prelude.glsl', 'image/display.glsl', 'web/shaders/display.glsl'];
      this.use(this.program('display-compose', '#define SG_PASS_COMPOSE\n', src), { size: [w, h], divider },
        { left: this.bytes[0], right: this.bytes[1] });
      this.draw([], w, h);
    }
  }

  return { Renderer, frameInputs, cameraModel, lightModel, frameTime, reduceAngle, glareKernels };
})();
