// The web page's scene checks (src/web/assets/scene_check.js, a port of the scene loader's)
// against the CLI's: for every scene of tests/scenes/bad/ and a list of malformed JSON texts
// (syntax errors at every kind of token, bad UTF-8 and escapes, numbers out of range,
// duplicate keys), the message the page shows equals what `sunglint info FILE` prints after
// "sunglint: ", run from the file's folder so that both name it alike; and every valid scene
// (scenes/, tests/scenes/edge/) loads in both. Node's standard library only.
//
// Usage: node check_scenes.mjs SUNGLINT SOURCE_DIR WORK_DIR [SCENE_CHECK_JS]
import { execFile } from 'node:child_process';
import { mkdirSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { join, resolve } from 'node:path';

const [bin, src, work, checker] = process.argv.slice(2);
const require = createRequire(import.meta.url);
const SunglintScene = require(resolve(checker || join(src, 'src/web/assets/scene_check.js')));

// What the CLI says of `file` in `dir`: its message after "sunglint: ", or null when it loads.
function cli(dir, file) {
  return new Promise((ok) => {
    execFile(resolve(bin), ['info', file], { cwd: dir, maxBuffer: 1 << 24 }, (error, stdout, stderr) => {
      if (!error) return ok(null);
      const text = stderr.toString().trim();
      ok(text.startsWith('sunglint: ') ? text.slice('sunglint: '.length) : text);
    });
  });
}
function page(dir, file) {
  try {
    SunglintScene.parse(new Uint8Array(readFileSync(join(dir, file))), file);
    return null;
  } catch (e) {
    return e.message;
  }
}

// Malformed texts beyond tests/scenes/bad/: the JSON reader's corners.
const valid = readFileSync(join(src, 'scenes/simple.json'), 'utf8');
const extra = {
  'colon_missing.json': '{"a" 1}', 'value_missing.json': '{"a": }', 'trailing_comma.json': '{"a": 1,}',
  'newline_in_string.json': '{"a": "x\n"}', 'empty.json': '', 'after_value.json': '{"a": 1} x',
  'array_open.json': '[1, 2', 'literal_short.json': '{"a": tru}', 'leading_zero.json': '{"a": 01}',
  'minus_alone.json': '{"a": -}', 'array_no_comma.json': '{"a": [1 2]}', 'bad_escape_u.json': '{"a": "\\u12"}',
  'dot_alone.json': '{"a": 1.}', 'control_in_key.json': '{"a\u0001": 1}', 'spaces.json': '  \n\n  ',
  'nested_duplicate.json': '{"camera": {"x": 1, "x": 2}}', 'exponent_alone.json': '{"a": 1e}',
  'plus.json': '{"a": +1}', 'nan.json': '{"a": NaN}', 'string_open.json': '{"a": "abc',
  'number_then_eof.json': '{"a": 1', 'key_then_eof.json': '{"a"', 'brace.json': '{', 'bracket.json': '{"a": [',
  'whitespace_lines.json': '{"a": \t\r\n 1 x}', 'escape_x.json': '{"a": "\\x"}',
  'lone_high.json': '{"a": "\\ud800"}', 'bad_low.json': '{"a": "\\ud800\\u0041"}', 'lone_low.json': '{"a": "\\udc00"}',
  'null_short.json': '{"a": nul', 'comment.json': '{"a": 1 /* c */}', 'single_quotes.json': "{'a': 1}",
  'bom_format_number.json': '\ufeff{"format": 1}', 'top_level_number.json': '42',
  'deep_range.json': '{"format": "sunglint-scene/1", "surface": {"waves": [{"a": [1, {"b": 1e400}]}]}}',
  'minus_zero_vfov.json': valid.replace(/"vfov_deg": [^,\n]*/, '"vfov_deg": -0'),
  'utf8_path.json': '{"\u00e9": tru}', 'utf8_value.json': '{"a": "\u00e9x", "b": tru}',
  'truncated.json': valid.slice(0, 400), 'second_object.json': valid + valid,
  'big_integer.json': valid.replace(/"frames": \d+/, '"frames": 123456789012345678901234567890'),
  // nlohmann's lexer paths: each message, and what its "last read" shows.
  'tab_in_string.json': '{"a": "x\ty"}', 'nul_in_key.json': '{"a\u0000": 1}', 'escape_eof.json': '{"a": "\\',
  'high_then_x.json': '{"a": "\\ud800x"}', 'high_then_short.json': '{"a": "\\ud800\\u12"}',
  'exponent_sign_alone.json': '{"a": 1e+}', 'minus_eof.json': '-', 'dot_dot.json': '[1.5.3]', 'false_short.json': '[fals]',
  'array_trailing_comma.json': '[1,]', 'two_values.json': '{} {}', 'object_no_comma.json': '{"a": 1 "b": 2}',
  'key_number.json': '{1: 2}', 'bom_literal.json': '\ufeff tru', 'nul_after_scene.json': valid + '\u0000 x',
  'empty_key_duplicate.json': '{"": 1, "": 2}', 'proto_key.json': valid.replace('{', '{"__proto__": 1, '),
  'deep_array.json': '['.repeat(100000) + ']'.repeat(100000),
  // Two unknown keys: the first in byte order is named (nlohmann's objects are std::maps).
  'unknown_keys_order.json': valid.replace('{', '{"zz": 1, "\ue000": 2, "\u{1f600}": 3, "aa": 4, "10": 5, "9": 6, '),
  'unknown_keys_utf8.json': valid.replace('{', '{"\u{1f600}": 3, "\ue000": 2, '),
};
const bytes = { 'bad_utf8.json': Buffer.from([0x7b, 0x22, 0x61, 0x22, 0x3a, 0x20, 0x22, 0xff, 0x22, 0x7d]),
  'overlong_utf8.json': Buffer.from([0x7b, 0x22, 0xc0, 0x80, 0x22, 0x3a, 0x31, 0x7d]),
  'surrogate_utf8.json': Buffer.from([0x7b, 0x22, 0xed, 0xa0, 0x80, 0x22, 0x3a, 0x31, 0x7d]),
  'four_byte_utf8.json': Buffer.from([0x7b, 0x22, 0xf0, 0x9f, 0x41, 0x22, 0x3a, 0x31, 0x7d]),
  'bom_bad.json': Buffer.from([0xef, 0x7b, 0x7d]), 'bom_cut.json': Buffer.from([0xef, 0xbb]) };
const dir = join(work, 'malformed');
mkdirSync(dir, { recursive: true });
for (const [name, text] of Object.entries(extra)) writeFileSync(join(dir, name), text);
for (const [name, b] of Object.entries(bytes)) writeFileSync(join(dir, name), b);

// Every file, the CLI run on four at a time.
const files = [];
const badDir = join(src, 'tests/scenes/bad');
for (const f of readdirSync(badDir).filter((f) => f.endsWith('.json')).sort()) files.push([badDir, f, true]);
for (const f of [...Object.keys(extra), ...Object.keys(bytes)].sort()) files.push([dir, f, false]);
for (const d of [join(src, 'scenes'), join(src, 'tests/scenes/edge')]) {
  for (const f of readdirSync(d).filter((f) => f.endsWith('.json')).sort()) files.push([d, f, false]);
}
const results = new Array(files.length);
let next = 0;
await Promise.all([0, 1, 2, 3].map(async () => {
  while (next < files.length) {
    const k = next++;
    results[k] = await cli(files[k][0], files[k][1]);
  }
}));
let fails = 0, compared = 0;
files.forEach(([d, file, wantError], k) => {
  const a = results[k], b = page(d, file);
  compared++;
  if (a !== b) {
    fails++;
    console.log(`FAIL ${file}:\n  cli:  ${a}\n  page: ${b}`);
  } else if (wantError && a === null) {
    fails++;
    console.log(`FAIL ${file}: loads, but is meant to be malformed`);
  }
});
console.log(`check_scenes: ${compared} files, ${fails} differ`);
process.exit(fails === 0 ? 0 : 1);
