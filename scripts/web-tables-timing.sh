#!/usr/bin/env bash
# How the web page should get its path table S (docs/web.md): made in the browser from the
# fine grids of F it carries (what `sunglint web` does), or the host's table shipped
# compressed beside the page. Writes both variants of a page for scenes/simple.json and
# times, in headless Chromium (SwiftShader; tests/web/check_web.mjs), from navigation start
# to the table's being on the GPU:
#   generated: host.js's makeTables (the kernel's path_table_gen.glsl, three passes);
#   file:      the host's tables (path_tables.bin: F and S, 64 MiB of floats) gzipped (-9)
#              into a script as base64 (file:// pages cannot fetch), decoded, inflated
#              (DecompressionStream) and uploaded.
# Prints the sizes and the times. Usage: scripts/web-tables-timing.sh [BUILD_DIR] [WORK_DIR]
set -eu
build=${1:-build}
work=${2:-/tmp/sunglint-web-tables}
src=$(cd "$(dirname "$0")/.." && pwd)
rm -rf "$work" && mkdir -p "$work"
"$build/sunglint" web "$src/scenes/simple.json" -o "$work/page" >/dev/null
cache=${SUNGLINT_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/sunglint}/path_tables.bin
[ -s "$cache" ] || { echo "no $cache: run a staa render first"; exit 1; }
python3 - "$cache" "$work/page/tables_file.js" <<'EOF'
import base64, gzip, sys
data = open(sys.argv[1], 'rb').read()[64:-4]  # the floats: F, then S (path_table.cpp)
packed = gzip.compress(data, compresslevel=9)
with open(sys.argv[2], 'w') as f:
    f.write('window.SG_TABLES_GZ = "' + base64.b64encode(packed).decode() + '";\n')
print(f"tables: {len(data)} bytes of floats, {len(packed)} gzipped, "
      f"{(len(packed) + 2) // 3 * 4} as base64")
EOF
cat >"$work/page/tables_file.html" <<'EOF'
<!DOCTYPE html><html><head><meta charset="utf-8"><title>file</title></head><body>
<canvas id="canvas"></canvas><div id="error"></div>
<script src="data.js"></script><script src="tables_file.js"></script><script>
(async () => {
  const t = { script_ms: performance.now() };
  const bin = atob(window.SG_TABLES_GZ);
  const bytes = new Uint8Array(bin.length);
  for (let i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
  const raw = await new Response(new Blob([bytes]).stream().pipeThrough(new DecompressionStream('gzip'))).arrayBuffer();
  t.inflated_ms = performance.now();
  const info = SUNGLINT_DATA.tables.info, f = info.n_distance * info.n_sigma;
  const floats = new Float32Array(raw);
  const gl = document.getElementById('canvas').getContext('webgl2');
  const tex = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D_ARRAY, tex);
  gl.texImage3D(gl.TEXTURE_2D_ARRAY, 0, gl.R32F, info.n_u, info.n_v, info.n_sigma, 0, gl.RED, gl.FLOAT, floats.subarray(f));
  gl.getExtension('EXT_color_buffer_float');
  const fb = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
  gl.framebufferTextureLayer(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, tex, 0, info.n_sigma - 1);
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.FLOAT, new Float32Array(4));
  t.total_ms = performance.now();
  window.T = t;
  document.title = 'ready';
})().catch((e) => { document.getElementById('error').textContent = e.message; });
</script></body></html>
EOF
cat >"$work/page/tables_generated.html" <<'EOF'
<!DOCTYPE html><html><head><meta charset="utf-8"><title>generated</title></head><body>
<canvas id="canvas"></canvas><div id="error"></div>
<script src="data.js"></script><script src="shaders.js"></script><script src="host.js"></script><script>
try {
  const t = { script_ms: performance.now() };
  const r = new SunglintHost.Renderer(document.getElementById('canvas'), SUNGLINT_DATA, SUNGLINT_SHADERS);
  r.makeTables();
  t.making_ms = r.tablesMs;
  t.total_ms = performance.now();
  window.T = t;
  document.title = 'ready';
} catch (e) { document.getElementById('error').textContent = e.message; }
</script></body></html>
EOF
ls -l "$work/page"
cat >"$work/jobs.json" <<EOF
[{"name": "generated", "page": "$work/page/tables_generated.html", "width": 1, "height": 1, "steps": [{"eval": "window.T"}]},
 {"name": "file", "page": "$work/page/tables_file.html", "width": 1, "height": 1, "steps": [{"eval": "window.T"}]},
 {"name": "generated", "page": "$work/page/tables_generated.html", "width": 1, "height": 1, "steps": [{"eval": "window.T"}]},
 {"name": "file", "page": "$work/page/tables_file.html", "width": 1, "height": 1, "steps": [{"eval": "window.T"}]}]
EOF
node "$src/tests/web/check_web.mjs" "$work/jobs.json" --timeout 600
