// The scene loader's checks (src/scene/scene_load.cpp, src/scene/scene_limits.h) ported to
// JavaScript, for a scene file dropped on the web page: the same rules in the same order,
// so a malformed file gets the message `sunglint info FILE` prints, word for word (the
// web test runs both on every scene of tests/scenes/bad/ and compares). That takes a JSON
// reader of its own: JSON.parse reports neither nlohmann's words for a syntax error nor its
// byte position, nor the key path of a number out of range, nor duplicate keys, and accepts
// nothing but UTF-16; this one is a port of nlohmann's lexer and parser that reads the
// file's bytes as they do (a UTF-8 BOM skipped, the error at the last byte read).
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
  const kFormat = 'sunglint-scene/1', kFormat2 = 'sunglint-scene/2', kFormat3 = 'sunglint-scene/3';
  const kMaxImageSide = 16384;
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
  //
  // A port of nlohmann/json 3.11.2 (the CLI's JSON library): its lexer
  // (/usr/include/nlohmann/detail/input/lexer.hpp: scan, scan_string, scan_number,
  // scan_literal, get, unget, reset, get_token_string, token_type_name and the lexer's
  // error_message strings) and its parser (detail/input/parser.hpp: sax_parse_internal and
  // exception_message), and of the SAX handler in scene_load.cpp (JsonReader: key paths,
  // duplicate keys). A syntax error's message is the text nlohmann's parse_error carries
  // after " - ", as scene_load.cpp's parse_error keeps it: what the lexer met ("unexpected
  // ','", or the lexer's own error and "last read: '...'") and, mostly, what the parser
  // wanted ("expected '}'"). Its position is the lexer's count of bytes read (EOF reads
  // counted, ungets not), as parse_scene turns it into a line and column.
  const EOF = -1;

  // lexer_base::token_type_name: a token's name in the messages.
  function tokenTypeName(type) {
    switch (type) {
      case 'uninitialized': return '<uninitialized>';
      case 'literal_true': return 'true literal';
      case 'literal_false': return 'false literal';
      case 'literal_null': return 'null literal';
      case 'value_string': return 'string literal';
      case 'value_unsigned': case 'value_integer': case 'value_float': return 'number literal';
      case 'begin_array': return "'['";
      case 'begin_object': return "'{'";
      case 'end_array': return "']'";
      case 'end_object': return "'}'";
      case 'name_separator': return "':'";
      case 'value_separator': return "','";
      case 'parse_error': return '<parse error>';
      case 'end_of_input': return 'end of input';
      case 'literal_or_value': return "'[', '{', or a literal";
      default: return 'unknown token';
    }
  }

  // The names of the control characters U+0000..U+001F in scan_string's messages, and the
  // short escapes some of them have.
  const kControlNames = ['NUL', 'SOH', 'STX', 'ETX', 'EOT', 'ENQ', 'ACK', 'BEL', 'BS', 'HT', 'LF',
    'VT', 'FF', 'CR', 'SO', 'SI', 'DLE', 'DC1', 'DC2', 'DC3', 'DC4', 'NAK', 'SYN', 'ETB', 'CAN',
    'EM', 'SUB', 'ESC', 'FS', 'GS', 'RS', 'US'];
  const kShortEscapes = { 0x08: '\\b', 0x09: '\\t', 0x0a: '\\n', 0x0c: '\\f', 0x0d: '\\r' };
  const hex4 = (c) => c.toString(16).toUpperCase().padStart(4, '0');  // printf's %.4X
  const isDigit = (c) => c >= 0x30 && c <= 0x39;
  const utf8 = new TextDecoder('utf-8', { ignoreBOM: true });  // a BOM kept, bad bytes as U+FFFD

  class Lexer {
    constructor(bytes) {
      this.bytes = bytes;
      this.next = 0;            // the input adapter's next byte
      this.current = EOF;       // the byte last read
      this.nextUnget = false;   // get() gives `current` again
      this.position = 0;        // position.chars_read_total
      // token_string, the bytes read since reset() (what "last read" shows), is always a run
      // of the input: get() appends the byte it reads (not EOF), unget() takes it back,
      // reset() starts it at `current`. So it is kept as where it starts; it ends at the last
      // byte read. Only strings and numbers reset it: after `"a": 1} x` it is "1} x".
      this.tokenStart = 0;
      this.tokenBuffer = [];    // token_buffer: a string's bytes (escapes decoded), a number's text
      this.errorMessage = '';
      this.value = undefined;   // the token's value: a string, a number
    }

    get() {
      this.position++;
      if (this.nextUnget) this.nextUnget = false;
      else this.current = this.next < this.bytes.length ? this.bytes[this.next++] : EOF;
      return this.current;
    }
    unget() {
      this.nextUnget = true;
      this.position--;
    }
    add(c) { this.tokenBuffer.push(c); }
    reset() {
      this.tokenBuffer = [];
      this.tokenStart = this.position - 1;  // `current`, the byte last read
    }

    // The bytes read since reset(), control characters as <U+XXXX>, other bytes as they are
    // (UTF-8 or not: the CLI prints them so, and the terminal or the test reads them as UTF-8).
    getTokenString() {
      const end = Math.min(this.position, this.bytes.length);
      const out = [];
      for (let k = this.tokenStart; k < end; k++) {
        const c = this.bytes[k];
        if (c <= 0x1f) for (const ch of '<U+' + hex4(c) + '>') out.push(ch.charCodeAt(0));
        else out.push(c);
      }
      return utf8.decode(new Uint8Array(out));
    }

    skipBom() {
      if (this.get() === 0xef) return this.get() === 0xbb && this.get() === 0xbf;
      this.unget();
      return true;
    }
    skipWhitespace() {
      do this.get();
      while (this.current === 0x20 || this.current === 0x09 || this.current === 0x0a || this.current === 0x0d);
    }

    scan() {
      if (this.position === 0 && !this.skipBom()) {
        this.errorMessage = 'invalid BOM; must be 0xEF 0xBB 0xBF if given';
        return 'parse_error';
      }
      this.skipWhitespace();
      const c = this.current === EOF ? 'EOF' : String.fromCharCode(this.current);
      switch (c) {
        case '[': return 'begin_array';
        case ']': return 'end_array';
        case '{': return 'begin_object';
        case '}': return 'end_object';
        case ':': return 'name_separator';
        case ',': return 'value_separator';
        case 't': return this.scanLiteral('true', 'literal_true', true);
        case 'f': return this.scanLiteral('false', 'literal_false', false);
        case 'n': return this.scanLiteral('null', 'literal_null', null);
        case '"': return this.scanString();
        case '-': case '0': case '1': case '2': case '3': case '4':
        case '5': case '6': case '7': case '8': case '9':
          return this.scanNumber();
        case '\0': case 'EOF': return 'end_of_input';  // a NUL byte ends the input too
        default:
          this.errorMessage = 'invalid literal';
          return 'parse_error';
      }
    }

    scanLiteral(text, type, value) {
      for (let k = 1; k < text.length; k++) {
        if (this.get() !== text.charCodeAt(k)) {
          this.errorMessage = 'invalid literal';
          return 'parse_error';
        }
      }
      this.value = value;
      return type;
    }

    // After `\u`: the 4 hex digits' value, or -1.
    getCodepoint() {
      let codepoint = 0;
      for (let k = 0; k < 4; k++) {
        const c = this.get();
        if (c >= 0x30 && c <= 0x39) codepoint = codepoint * 16 + (c - 0x30);
        else if (c >= 0x41 && c <= 0x46) codepoint = codepoint * 16 + (c - 0x37);
        else if (c >= 0x61 && c <= 0x66) codepoint = codepoint * 16 + (c - 0x57);
        else return -1;
      }
      return codepoint;
    }

    // A UTF-8 sequence: `current` and, for each [lo, hi], a next byte in that range.
    nextByteInRange(ranges) {
      this.add(this.current);
      for (const [lo, hi] of ranges) {
        const c = this.get();
        if (c >= lo && c <= hi) {
          this.add(c);
        } else {
          this.errorMessage = 'invalid string: ill-formed UTF-8 byte';
          return false;
        }
      }
      return true;
    }

    scanString() {
      this.reset();  // token_string starts at the opening quote
      for (;;) {
        const c = this.get();
        if (c === EOF) {
          this.errorMessage = 'invalid string: missing closing quote';
          return 'parse_error';
        }
        if (c === 0x22) {  // the closing quote
          this.value = utf8.decode(new Uint8Array(this.tokenBuffer));
          return 'value_string';
        }
        if (c === 0x5c) {  // a backslash
          const e = this.get();
          const simple = { 0x22: 0x22, 0x5c: 0x5c, 0x2f: 0x2f, 0x62: 0x08, 0x66: 0x0c, 0x6e: 0x0a, 0x72: 0x0d, 0x74: 0x09 };
          if (e in simple) {
            this.add(simple[e]);
            continue;
          }
          if (e !== 0x75) {  // not u
            this.errorMessage = 'invalid string: forbidden character after backslash';
            return 'parse_error';
          }
          const codepoint1 = this.getCodepoint();
          let codepoint = codepoint1;
          if (codepoint1 === -1) {
            this.errorMessage = "invalid string: '\\u' must be followed by 4 hex digits";
            return 'parse_error';
          }
          if (codepoint1 >= 0xd800 && codepoint1 <= 0xdbff) {
            // a high surrogate: a \u with a low one must follow
            if (this.get() === 0x5c && this.get() === 0x75) {
              const codepoint2 = this.getCodepoint();
              if (codepoint2 === -1) {
                this.errorMessage = "invalid string: '\\u' must be followed by 4 hex digits";
                return 'parse_error';
              }
              if (codepoint2 >= 0xdc00 && codepoint2 <= 0xdfff) {
                codepoint = 0x10000 + ((codepoint1 - 0xd800) << 10) + (codepoint2 - 0xdc00);
              } else {
                this.errorMessage = 'invalid string: surrogate U+D800..U+DBFF must be followed by U+DC00..U+DFFF';
                return 'parse_error';
              }
            } else {
              this.errorMessage = 'invalid string: surrogate U+D800..U+DBFF must be followed by U+DC00..U+DFFF';
              return 'parse_error';
            }
          } else if (codepoint1 >= 0xdc00 && codepoint1 <= 0xdfff) {
            this.errorMessage = 'invalid string: surrogate U+DC00..U+DFFF must follow U+D800..U+DBFF';
            return 'parse_error';
          }
          for (const b of new TextEncoder().encode(String.fromCodePoint(codepoint))) this.add(b);
          continue;
        }
        if (c <= 0x1f) {
          this.errorMessage = 'invalid string: control character U+' + hex4(c) + ' (' + kControlNames[c] +
            ') must be escaped to \\u' + hex4(c) + (c in kShortEscapes ? ' or ' + kShortEscapes[c] : '');
          return 'parse_error';
        }
        if (c <= 0x7f) {
          this.add(c);
          continue;
        }
        // UTF-8 (RFC 3629): the range of each continuation byte after the lead byte.
        const ranges = c >= 0xc2 && c <= 0xdf ? [[0x80, 0xbf]]
          : c === 0xe0 ? [[0xa0, 0xbf], [0x80, 0xbf]]
          : (c >= 0xe1 && c <= 0xec) || c === 0xee || c === 0xef ? [[0x80, 0xbf], [0x80, 0xbf]]
          : c === 0xed ? [[0x80, 0x9f], [0x80, 0xbf]]
          : c === 0xf0 ? [[0x90, 0xbf], [0x80, 0xbf], [0x80, 0xbf]]
          : c >= 0xf1 && c <= 0xf3 ? [[0x80, 0xbf], [0x80, 0xbf], [0x80, 0xbf]]
          : c === 0xf4 ? [[0x80, 0x8f], [0x80, 0xbf], [0x80, 0xbf]] : null;
        if (ranges === null) {  // 80..C1, F5..FF
          this.errorMessage = 'invalid string: ill-formed UTF-8 byte';
          return 'parse_error';
        }
        if (!this.nextByteInRange(ranges)) return 'parse_error';
      }
    }

    // nlohmann's state machine: minus? (0 | 1-9 digits*) (. digit+)? ([eE] [+-]? digit+)?
    scanNumber() {
      this.reset();
      let type = 'value_unsigned';
      let c = this.current;
      this.add(c);
      if (c === 0x2d) {  // minus
        type = 'value_integer';
        c = this.get();
        if (!isDigit(c)) {
          this.errorMessage = "invalid number; expected digit after '-'";
          return 'parse_error';
        }
        this.add(c);
      }
      if (c === 0x30) {  // zero: no digits follow
        c = this.get();
      } else {
        while (isDigit(c = this.get())) this.add(c);
      }
      if (c === 0x2e) {  // .
        type = 'value_float';
        this.add(c);
        c = this.get();
        if (!isDigit(c)) {
          this.errorMessage = "invalid number; expected digit after '.'";
          return 'parse_error';
        }
        this.add(c);
        while (isDigit(c = this.get())) this.add(c);
      }
      if (c === 0x65 || c === 0x45) {  // e E
        type = 'value_float';
        this.add(c);
        c = this.get();
        if (c === 0x2b || c === 0x2d) {  // + -
          this.add(c);
          c = this.get();
          if (!isDigit(c)) {
            this.errorMessage = 'invalid number; expected digit after exponent sign';
            return 'parse_error';
          }
        } else if (!isDigit(c)) {
          this.errorMessage = "invalid number; expected '+', '-', or digit after exponent";
          return 'parse_error';
        }
        this.add(c);
        while (isDigit(c = this.get())) this.add(c);
      }
      this.unget();  // the byte after the number
      const text = String.fromCharCode(...this.tokenBuffer);
      this.value = Number(text);
      // An integer that fits nlohmann's uint64 (or, with a minus, int64) is one (-0 is 0);
      // any other number is a double, which may overflow.
      if (type === 'value_unsigned' && text.length <= 20 && BigInt(text) <= 0xffffffffffffffffn) return type;
      if (type === 'value_integer' && text.length <= 20 && BigInt(text) >= -0x8000000000000000n) {
        this.value += 0;
        return type;
      }
      return 'value_float';
    }
  }

  class JsonError extends Error {}
  // `bytes` as JSON (a value of objects, arrays, strings, numbers, true, false, null), or a
  // JsonError: {position, detail} for a syntax error, {position, path, outOfRange} for a
  // number too large for a double, {duplicate} for a duplicate key (its key path).
  function parseJson(bytes) {
    const lexer = new Lexer(bytes);

    // The SAX handler: JsonReader's frames (key paths) and the values built (nlohmann's
    // json_sax_dom_parser). Objects have no prototype, so that "__proto__" is a key like any.
    const frames = [];  // {array, index, key, keys, value}
    let root;
    const path = () => {
      let p = '';
      for (const f of frames) {
        if (f.array) p += '[' + f.index + ']';
        else if (f.key !== '') p += (p === '' ? '' : '.') + f.key;
      }
      return p;
    };
    const put = (v) => {
      const f = frames[frames.length - 1];
      if (f === undefined) root = v;
      else if (f.array) f.value.push(v);
      else f.value[f.key] = v;
    };
    const counted = () => {  // JsonReader::value
      if (frames.length > 0 && frames[frames.length - 1].array) frames[frames.length - 1].index++;
    };
    const scalar = (v) => { counted(); put(v); };
    const startObject = () => {
      const o = Object.create(null);
      put(o);
      frames.push({ array: false, index: 0, key: '', keys: new Set(), value: o });
    };
    const startArray = () => {
      const a = [];
      put(a);
      frames.push({ array: true, index: 0, key: '', keys: null, value: a });
    };
    const end = () => { frames.pop(); counted(); };
    const key = (k) => {
      const f = frames[frames.length - 1];
      f.key = k;
      if (f.keys.has(k)) {
        const e = new JsonError('duplicate key');
        e.duplicate = path();
        throw e;
      }
      f.keys.add(k);
    };

    // The parser (sax_parse and sax_parse_internal), its states and its gotos as they are.
    let lastToken = 'uninitialized';
    const getToken = () => (lastToken = lexer.scan());
    // parser::exception_message, from after " - " on.
    const syntaxError = (expected) => {
      let detail = lastToken === 'parse_error'
        ? lexer.errorMessage + "; last read: '" + lexer.getTokenString() + "'"
        : 'unexpected ' + tokenTypeName(lastToken);
      if (expected !== 'uninitialized') detail += '; expected ' + tokenTypeName(expected);
      const e = new JsonError('invalid JSON');
      e.position = lexer.position;
      e.detail = detail;
      throw e;
    };
    const states = [];  // true: in an array, false: in an object
    let skipToStateEvaluation = false;
    getToken();
    for (;;) {
      if (!skipToStateEvaluation) {
        switch (lastToken) {
          case 'begin_object':
            startObject();
            if (getToken() === 'end_object') {
              end();
              break;
            }
            if (lastToken !== 'value_string') syntaxError('value_string');
            key(lexer.value);
            if (getToken() !== 'name_separator') syntaxError('name_separator');
            states.push(false);
            getToken();
            continue;
          case 'begin_array':
            startArray();
            if (getToken() === 'end_array') {
              end();
              break;
            }
            states.push(true);
            continue;
          case 'value_float':
            if (!Number.isFinite(lexer.value)) {
              const e = new JsonError('number out of range');
              e.position = lexer.position;
              e.path = path();
              e.outOfRange = true;
              throw e;
            }
            scalar(lexer.value);
            break;
          case 'literal_false': case 'literal_null': case 'literal_true':
          case 'value_integer': case 'value_string': case 'value_unsigned':
            scalar(lexer.value);
            break;
          case 'parse_error':
            syntaxError('uninitialized');  // the lexer's message, nothing expected
            break;
          default:
            syntaxError('literal_or_value');
        }
      } else {
        skipToStateEvaluation = false;
      }

      // a value read
      if (states.length === 0) break;
      if (states[states.length - 1]) {  // in an array
        if (getToken() === 'value_separator') {
          getToken();
          continue;
        }
        if (lastToken === 'end_array') {
          end();
          states.pop();
          skipToStateEvaluation = true;
          continue;
        }
        syntaxError('end_array');
      }
      // in an object
      if (getToken() === 'value_separator') {
        if (getToken() !== 'value_string') syntaxError('value_string');
        key(lexer.value);
        if (getToken() !== 'name_separator') syntaxError('name_separator');
        getToken();
        continue;
      }
      if (lastToken === 'end_object') {
        end();
        states.pop();
        skipToStateEvaluation = true;
        continue;
      }
      syntaxError('end_object');
    }
    // strict: nothing but the end of the input after the value
    if (getToken() !== 'end_of_input') syntaxError('end_of_input');
    return root;
  }

  // scene_load.cpp's line_col: the line and column of byte `at` (bytes, not characters).
  function lineCol(bytes, at) {
    let line = 1, col = 1;
    for (let k = 0; k < at && k < bytes.length; k++) {
      if (bytes[k] === 0x0a) { line++; col = 1; } else col++;
    }
    return 'line ' + line + ', column ' + col;
  }

  // ---- the scene's keys (scene_load.cpp's ObjectReader and read_*)
  // std::string's order: byte by byte (as unsigned), of the keys' UTF-8.
  const encoder = new TextEncoder();
  function byteOrder(a, b) {
    const x = encoder.encode(a), y = encoder.encode(b);
    for (let k = 0; k < x.length && k < y.length; k++) if (x[k] !== y[k]) return x[k] - y[k];
    return x.length - y.length;
  }
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
    // The first unknown key in nlohmann's order: its objects are std::maps, keys in byte order.
    finish() {
      const keys = Object.keys(this.j).sort(byteOrder);
      for (const k of keys) if (!this.seen.has(k)) fail(this.keyPath(k), 'unknown key');
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
  const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  function checkPosition(p, path) {
    if (!(hypot3(p) <= limits.maxCameraDistance)) {
      fail(path, 'must be within ' + num(limits.maxCameraDistance) +
        ' m of the origin (got |position| = ' + num(hypot3(p)) + ' m)');
    }
    if (!(p[1] >= limits.minCameraHeight)) {
      fail(path, 'must be above the water at rest (y >= ' + num(limits.minCameraHeight) + ' m)');
    }
  }
  function checkLookAt(a, path) {
    if (!(hypot3(a) <= limits.maxLookAtDistance)) {
      fail(path, 'must be within ' + num(limits.maxLookAtDistance) +
        ' m of the origin (got |look_at| = ' + num(hypot3(a)) + ' m)');
    }
  }
  // scene_load.cpp's quadratic_min and view_margins.
  function quadraticMin(a, b, c) {
    let at = 0, best = c;
    if (a + b + c < best) { best = a + b + c; at = 1; }
    if (a > 0) {
      const s = -b / (2 * a);
      if (s > 0 && s < 1 && a * s * s + b * s + c < best) { best = a * s * s + b * s + c; at = s; }
    }
    return [best, at];
  }
  function viewMargins(d0, d1, u) {
    const eps = 1e-6, e = sub(d1, d0);
    const [meet, meetAt] = quadraticMin(dot(e, e), 2 * dot(d0, e), dot(d0, d0) - eps * eps);
    const c0 = cross(d0, u), ce = cross(e, u);
    const [parallel, parallelAt] = quadraticMin(dot(ce, ce) - eps * eps * dot(e, e),
      2 * (dot(c0, ce) - eps * eps * dot(d0, e)), dot(c0, c0) - eps * eps * dot(d0, d0));
    return { meet, meetAt, parallel, parallelAt };
  }
  function readKeyframes(o, up) {
    const path = o.keyPath('keyframes');
    const keys = o.get('keyframes');
    require(Array.isArray(keys) && keys.length >= 2, path,
      'must be an array of at least 2 keyframes {time, position, look_at}');
    const u = normalize(up);
    const out = [];
    for (let k = 0; k < keys.length; k++) {
      const kp = path + '[' + k + ']';
      const r = new ObjectReader(keys[k], kp);
      const key = { time: r.number('time') };
      requireIn(key.time, -limits.maxTime, limits.maxTime, r.keyPath('time'), 's');
      if (k > 0 && !(key.time > out[k - 1].time)) {
        fail(r.keyPath('time'), "must be greater than the previous keyframe's (" + num(out[k - 1].time) +
          ' s), got ' + num(key.time) + ' s');
      }
      key.position = r.vector('position', 3);
      checkPosition(key.position, r.keyPath('position'));
      key.look_at = r.vector('look_at', 3);
      checkLookAt(key.look_at, r.keyPath('look_at'));
      r.finish();
      const d = sub(key.look_at, key.position);
      const atKey = viewMargins(d, d, u);
      require(atKey.meet > 0, r.keyPath('look_at'), 'must differ from ' + r.keyPath('position'));
      require(atKey.parallel > 0, kp, "the viewing direction is parallel to camera.up (the camera's basis is undefined)");
      if (k > 0) {
        const a = out[k - 1];
        const m = viewMargins(sub(a.look_at, a.position), d, u);
        const prev = path + '[' + (k - 1) + ']';
        const when = (s) => num(a.time + s * (key.time - a.time));
        require(m.meet > 0, prev, "the camera's position meets its look_at point between this keyframe and the next (at t = " +
          when(m.meetAt) + ' s)');
        require(m.parallel > 0, prev, 'the viewing direction turns parallel to camera.up between this keyframe and the next (at t = ' +
          when(m.parallelAt) + ' s)');
      }
      out.push(key);
    }
    return out;
  }
  function readCamera(o, version) {
    if (o.has('keyframes')) {
      require(version >= 3, o.keyPath('keyframes'), 'needs "format": "' + kFormat3 + '"');
      for (const k of ['position', 'look_at']) {
        require(!o.has(k), o.keyPath(k), 'not allowed with camera.keyframes (a camera is fixed or keyframed)');
      }
      const up = o.vector('up', 3);
      requireDirection(up, o.keyPath('up'));
      const keyframes = readKeyframes(o, up);
      const c = { position: keyframes[0].position, look_at: keyframes[0].look_at, up, keyframes };
      c.vfov_deg = o.number('vfov_deg');
      requireIn(c.vfov_deg, limits.minVfov, limits.maxVfov, o.keyPath('vfov_deg'), 'degrees');
      o.finish();
      return c;
    }
    const c = { position: o.vector('position', 3), look_at: o.vector('look_at', 3), up: o.vector('up', 3) };
    c.vfov_deg = o.number('vfov_deg');
    checkPosition(c.position, o.keyPath('position'));
    checkLookAt(c.look_at, o.keyPath('look_at'));
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
      // As parse_scene tells them apart (a duplicate key by its path, which a duplicate ""
      // at the top level lacks: the CLI calls that one invalid JSON at line 1, column 1).
      if (e.duplicate !== undefined && e.duplicate !== '') {
        throw new Error(name + ': ' + e.duplicate + ': duplicate key (JSON object keys must be unique)');
      }
      const position = e.position || 0, detail = e.detail || '', path = e.path || '';
      const at = lineCol(bytes, position > 0 ? position - 1 : 0);
      if (e.outOfRange) throw new Error(name + ': ' + (path === '' ? '' : path + ': ') + 'number out of range at ' + at);
      // A syntax error: where it is, not a key (the text there may not be the key's at all).
      throw new Error(name + ': ' + at + ': invalid JSON' + (detail === '' ? '' : ' (' + detail + ')'));
    }
    try {
      const top = new ObjectReader(j, '');
      const format = top.string('format');
      require(format === kFormat || format === kFormat2 || format === kFormat3, 'format',
        'must be "' + kFormat + '", "' + kFormat2 + '" or "' + kFormat3 + '" (got "' + format + '")');
      const version = format === kFormat ? 1 : format === kFormat2 ? 2 : 3;
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
      s.camera = readCamera(top.object('camera'), version);
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
