#!/usr/bin/env python3
"""Holds the shading kernel's sources (src/kernel/*.glsl) to the subset of GLSL that is also
C++20 (the list is in src/kernel/cpp_prelude.h), then compiles the kernel with
glslangValidator, the Khronos reference compiler, twice: as a GLSL 4.50 compute shader (the GL
engine) and as a GLSL ES 3.00 fragment shader (WebGL 2: `sunglint web`), each with a main
that calls every entry point.

glslang does not know WebGL's own restrictions on top of ES 3.00 (the WebGL 2 specification,
"Differences Between WebGL and OpenGL ES 3.0"; ANGLE enforces them in browsers), so those
the kernel could break are checked here by pattern: no ternary operator on structs, no names
beginning with webgl_ or _webgl or holding two consecutive underscores.

Usage: check_subset.py SOURCE_DIR [GLSLANG_VALIDATOR]
       check_subset.py --self-test   (the struct-ternary rule against planted cases)
Exit status 0 when every rule holds and both shaders compile; each violation is printed as
file:line: rule.
"""
import re
import subprocess
import sys
import tempfile
from pathlib import Path

# Tokens of C++ (or of GLSL only) that the subset excludes, with the reason printed.
FORBIDDEN = [
    (r"::", "no scope resolution (std::, namespaces)"),
    (r"\b(template|typename|namespace|using|class|public|private|protected|virtual)\b",
     "no C++ declarations"),
    (r"\b(auto|nullptr|new|delete|throw|try|catch|static|thread_local|constexpr|inline|"
     r"mutable|operator|this|sizeof)\b", "no C++-only keywords"),
    (r"->", "no pointers"),
    (r"\b(float|double|dvec\d|dmat\d)\b", "scalars are `real` (the precision is the prelude's)"),
    (r"\b\d+\.\d*f\b|\b\d+f\b", "no float suffix on literals"),
    # (glm has no swizzles: a multi-component one would not compile in C++ either)
    (r"\.(?:[xyzw]{2,4}|[rgba]{2,4}|[stpq]{2,4})\b(?!\s*\()", "no swizzles beyond one component"),
    # GLSL's qualifiers: never a name (a variable `out` compiles as C++, not as GLSL), and
    # parameters are written IN(T), OUT(T), INOUT(T).
    (r"\b(in|out|inout)\b", "GLSL's in/out/inout (parameters as IN(T), OUT(T), INOUT(T); "
     "never a name)"),
    (r"\b(uniform|buffer|shared|layout|discard|gl_\w+)\b", "no shader-stage GLSL in the kernel"),
    (r"\btexelFetch\s*\(\s*waves\b", "the wave buffer is read with wave_texel (ES has no buffers)"),
    (r"=\s*\{", "constant arrays as SG_ARRAY(T, N, (items)) (ES has no brace initialisers)"),
    (r"\b(webgl_\w*|_webgl\w*|\w*__\w*)", "a name WebGL reserves (webgl_, _webgl, __)"),
    (r"\b(sample|input|output|filter|common|partition|active|flat|smooth|patch|precise|"
     r"subroutine|coherent|volatile|restrict|readonly|writeonly|resource|invariant|"
     r"centroid|noperspective|attribute|varying|lowp|mediump|highp|precision|superp|"
     r"fixed|half|long|short|unsigned|goto|union|enum|typedef|extern|external|interface|"
     r"cast|asm|noinline|hvec\d|fvec\d)\b", "a GLSL reserved word used as a name"),
]

# A function definition at the top level: a return type, a name, a parameter list, "{".
DEFINITION = re.compile(r"^(?P<head>[A-Za-z_][\w ]*?)\b(?P<name>\w+)\s*\([^;]*$")


def strip_comments(line):
    return line.split("//", 1)[0]


def check_file(path, problems):
    lines = path.read_text().splitlines()
    in_cpu_hook = False
    for number, raw in enumerate(lines, 1):
        line = strip_comments(raw)
        where = f"{path}:{number}"
        if line.startswith("#ifdef SG_CPU_WAVE_SUMS"):
            in_cpu_hook = True
        elif line.startswith("#else") or line.startswith("#endif"):
            in_cpu_hook = False
        if line.startswith("#"):
            if not re.match(r"#(include \"kernel/[\w/]+\.glsl\"|ifdef SG_CPU_WAVE_SUMS|ifndef|"
                            r"define|else|endif)", line):
                problems.append(f"{where}: preprocessor line outside the subset: {line.strip()}")
            if line.startswith("#include") and path.name != "kernel.glsl":
                problems.append(f"{where}: only kernel.glsl lists the files")
            continue
        for pattern, rule in FORBIDDEN:
            if re.search(pattern, line):
                problems.append(f"{where}: {rule}: {raw.strip()}")
        m = DEFINITION.match(line)
        if m and not line.startswith(" ") and not in_cpu_hook:
            head = m.group("head").split()
            if head and head[0] not in ("SG_FN", "struct", "const", "return", "else"):
                problems.append(f"{where}: a kernel function is marked SG_FN: {raw.strip()}")


def struct_names(texts):
    """The kernel's struct types, and the functions that return one."""
    structs = set()
    for text in texts.values():
        structs.update(re.findall(r"^struct\s+(\w+)", text, flags=re.M))
    returning = set()
    for text in texts.values():
        for kind, name in re.findall(r"^SG_FN\s+(\w+)\s+(\w+)\s*\(", text, flags=re.M):
            if kind in structs:
                returning.add(name)
    return structs, returning


def functions(code):
    """Each top-level SG_FN function of `code`: its return type, and the offsets of its
    parameter list's start and of its body's end (the brace that closes it)."""
    for m in re.finditer(r"^SG_FN\s+(\w+)\s+\w+\s*\(", code, flags=re.M):
        body = code.find("{", m.end())
        if body < 0:
            continue
        depth, end = 0, len(code)
        for i in range(body, len(code)):
            if code[i] == "{":
                depth += 1
            elif code[i] == "}":
                depth -= 1
                if depth == 0:
                    end = i + 1
                    break
        yield m.group(1), m.end(), end


def check_struct_ternaries(files, problems):
    """WebGL forbids the ternary operator on structs (ANGLE: "ternary operator is not allowed
    for structures"). Reported, within each function (its parameters and declarations tell
    which names hold structs): a struct declared or assigned from a ternary, a ternary one
    of whose operands is a struct variable or a call of a function returning a struct, and
    a function returning a struct that returns a ternary."""
    texts = {path: path.read_text() for path in files}
    structs, returning = struct_names(texts)
    if not structs:
        return
    names = "|".join(sorted(structs))
    calls = "|".join(sorted(returning)) or r"(?!)"
    for path, text in texts.items():
        code = "\n".join(strip_comments(line) for line in text.splitlines())
        scopes = [(kind, begin, end) for kind, begin, end in functions(code)]
        # The file's top level: the functions blanked out (their lines kept).
        top = code
        for _, begin, end in scopes:
            top = top[:begin] + re.sub(r"[^\n]", " ", top[begin:end]) + top[end:]
        reported = set()
        for kind, begin, end in scopes + [(None, 0, len(code))]:
            scope = code[begin:end] if kind is not None else top
            held = set(re.findall(rf"\b(?:IN|OUT|INOUT)\(\s*(?:{names})\s*\)\s*(\w+)", scope))
            held |= set(re.findall(rf"\b(?:{names})\s+(\w+)\s*[=;,)\[]", scope))
            held -= structs
            variables = "|".join(sorted(held)) or r"(?!)"
            start = begin
            for statement in re.split(r"(?<=[;{}])", scope):
                offset = start + len(statement) - len(statement.lstrip())
                start += len(statement)
                if "?" not in statement:
                    continue
                rule = None
                if re.search(rf"\b({names})\s+\w+\s*=[^;]*\?", statement):
                    rule = "a struct declared from a ternary"
                elif re.search(rf"^\s*({variables})\s*=(?!=)[^;]*\?", statement):
                    rule = "a struct assigned from a ternary"
                elif re.search(rf"[?:]\s*({calls})\s*\(", statement):
                    rule = "a ternary yields a struct returned by a call"
                elif re.search(rf"[?:]\s*({variables})\s*(?=[;:)]|$)", statement):
                    rule = "a ternary yields a struct variable"
                elif kind in structs and re.search(r"^\s*return\b[^;]*\?", statement):
                    rule = "a function returning a struct returns a ternary"
                line = code.count("\n", 0, offset) + 1
                if rule and line not in reported:
                    reported.add(line)
                    problems.append(f"{path}:{line}: no ternary operator on structs (WebGL), "
                                    f"{rule}: {' '.join(statement.split())[:100]}")


# Each case the struct-ternary rule must report (True) or let pass (False): the rule's own
# test (`check_subset.py --self-test`), so that a rule that no longer catches what WebGL
# refuses fails a test.
TERNARY_CASES = [
    (True, "S f(bool c, S a, S b) { S r = c ? a : b; return r; }"),
    (True, "S f(bool c, S a, S b) { S r = a; r = c ? a : b; return r; }"),
    (True, "S f(bool c, IN(S) a, IN(S) b) { return c ? a : b; }"),
    (True, "S g() { S s; s.x = 0.0; return s; }\nSG_FN real f(bool c) { real y = (c ? g() : g()).x; return y; }"),
    (True, "real f(bool c, IN(S) a, IN(S) b) { S t; t = a; t = c ? b : t; return t.x; }"),
    (False, "real f(bool c, IN(S) a) { real y = c ? a.x : 0.0; return y; }"),
    (False, "S f(bool c, S a) { S r = a; r.x = c ? 1.0 : a.x; return r; }"),
    (False, "real f(bool c, real a, real b) { real r = c ? a : b; return r; }"),
]


def self_test():
    failures = 0
    with tempfile.TemporaryDirectory() as folder:
        for expected, body in TERNARY_CASES:
            path = Path(folder) / "case.glsl"
            path.write_text("struct S {\n  real x;\n};\nSG_FN " + body + "\n")
            problems = []
            check_struct_ternaries([path], problems)
            if bool(problems) != expected:
                failures += 1
                print(f"{'missed' if expected else 'wrongly reported'}: {body}")
    print(f"{len(TERNARY_CASES)} struct-ternary cases, {failures} failure(s)")
    return 1 if failures else 0


def expand(source_dir, name, seen):
    """The file with its #include lines replaced by the files, as the GL engine does."""
    out = []
    for line in (source_dir / name).read_text().splitlines():
        m = re.match(r'\s*#include "(.*)"', line)
        if m:
            out.append(expand(source_dir, m.group(1), seen))
        else:
            out.append(line)
    return "\n".join(out)


# Mains that call every entry point, so that the compiler checks all of the kernel: a GL 4.50
# compute shader, a GLSL ES 3.00 fragment shader.
CALLS = """
  w += stratified_pixel(waves, frame, counts, p.x, p.y);
  w += staa_temporal_pixel(waves, frame, p.x, p.y);
  w += reference_pixel(waves, frame, ref_params, p.x, p.y).weights;
  w.x += path_cell_panel(line, 0, 8, 0.5, w.y, 0.25, 1.0) + path_table_chord(w.z, w.w);
  StaaPath path;
  StaaResult r = staa_pixel(waves, table_f, table_s, tinfo, fits, finfo, frame, params, p.x,
                            p.y, path);
"""
UNIFORMS = """
uniform sampler2D table_f;
uniform sampler2DArray table_s;
uniform sampler2D fits;
uniform Frame frame;
uniform StaaParams params;
uniform SampleCounts counts;
uniform ReferenceParams ref_params;
uniform PathTableInfo tinfo;
uniform KernelFitInfo finfo;
"""
TEST_MAIN = """
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform writeonly image2D out_image;
uniform samplerBuffer waves;
uniform samplerBuffer line;
""" + UNIFORMS + """
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  vec4 w = point_pixel(waves, frame, p.x, p.y);""" + CALLS + """
  imageStore(out_image, p, w + r.weights);
}
"""
TEST_MAIN_ES = """
uniform sampler2D waves;
uniform sampler2D line;
""" + UNIFORMS + """
out vec4 weights_out;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 w = point_pixel(waves, frame, p.x, p.y);""" + CALLS + """
  weights_out = w + r.weights;
}
"""



def compile_shader(validator, text, suffix, what, problems):
    with tempfile.NamedTemporaryFile("w", suffix=suffix, delete=False) as f:
        f.write(text)
        shader_path = f.name
    result = subprocess.run([validator, shader_path], capture_output=True, text=True)
    Path(shader_path).unlink()
    if result.returncode != 0:
        print(f"glslangValidator rejects the kernel as {what}:")
        print(result.stdout + result.stderr)
        problems.append(what)


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    source_dir = Path(sys.argv[1]) / "src"
    validator = sys.argv[2] if len(sys.argv) > 2 else "glslangValidator"
    problems = []
    # The preludes map the subset onto a language (macros, ES's stand-ins): outside it.
    preludes = ("glsl_prelude.glsl", "glsl_es_prelude.glsl")
    files = sorted((source_dir / "kernel").glob("*.glsl"))
    for path in files:
        if path.name not in preludes:
            check_file(path, problems)
    check_struct_ternaries([p for p in files if p.name not in preludes], problems)
    for p in problems:
        print(p)
    kernel = expand(source_dir, "kernel/interface.glsl", set()) + "\n"
    kernel += expand(source_dir, "kernel/kernel.glsl", set()) + "\n"
    gl = "#version 450\n" + (source_dir / "kernel/glsl_prelude.glsl").read_text() + "\n"
    compile_shader(validator, gl + kernel + TEST_MAIN, ".comp", "GLSL 4.50", problems)
    es = "#version 300 es\n" + (source_dir / "kernel/glsl_es_prelude.glsl").read_text() + "\n"
    compile_shader(validator, es + kernel + TEST_MAIN_ES, ".frag", "GLSL ES 3.00", problems)
    print(f"{len(files)} kernel files checked, {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
