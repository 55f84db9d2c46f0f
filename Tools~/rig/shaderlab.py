#!/usr/bin/env python3
"""gt shaderlab: compile every pass of Shaders/GregoryTerrain.shader off Unity, as far as possible.

For each SubShader and Pass, the HLSLPROGRAM block is cut out as it is and compiled with glslang's
HLSL front end, once per stage its #pragma lines name (vertex -> vert, hull -> tesc, domain -> tese,
fragment -> frag), for the keyword combinations its shader_feature / multi_compile lines allow
(none, each keyword alone, all effect keywords together, the effects with one keyword of every
other set). Then spirv-val.

Includes: "Packages/com.gregoryterrain.tessellation/..." resolves to this package (a link in a
temporary include root); Unity's own shader libraries (Built-in .cginc, URP, HDRP) resolve to the
MOCK in Tools~/rig/unity-mock (see its README: the few names the adapters use, not Unity's code).
So this catches syntax and type errors in the pass code, the adapters and the stages; it says
nothing about Unity's real headers or Unity's shader compiler.

Prints one line per (subshader, pass, variant, stage): "PASS ..." or "FAIL ..." with the errors,
then a summary line "shaderlab: N compiled, N failed". Exit 1 on any failure.
"""
import os
import re
import subprocess
import sys
import tempfile

RIG_DIR = os.path.dirname(os.path.abspath(__file__))
PKG_DIR = os.path.dirname(os.path.dirname(RIG_DIR))
SHADER = os.path.join(PKG_DIR, "Shaders", "GregoryTerrain.shader")
MOCK_DIR = os.path.join(RIG_DIR, "unity-mock")
PACKAGE_NAME = "com.gregoryterrain.tessellation"

PRAGMA_STAGES = {"vertex": "vert", "hull": "tesc", "domain": "tese", "fragment": "frag"}
EFFECTS = ["GT_NOISE", "GT_HEIGHT_COLOR", "GT_SNOW"]


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def block_end(text, open_index):
    """Index just past the brace matching text[open_index] == '{' (HLSL blocks skipped)."""
    depth, i = 0, open_index
    while i < len(text):
        if text.startswith("HLSLPROGRAM", i):
            i = text.index("ENDHLSL", i) + len("ENDHLSL")
            continue
        c = text[i]
        if c == "{":
            depth += 1
        elif c == "}":
            depth -= 1
            if depth == 0:
                return i + 1
        i += 1
    raise ValueError("unbalanced braces in GregoryTerrain.shader")


def blocks(text, keyword):
    """(start, end, body) of each 'keyword { ... }' at any depth of text."""
    out = []
    for m in re.finditer(r"\b%s\s*\{" % keyword, text):
        open_index = m.end() - 1
        end = block_end(text, open_index)
        out.append((m.start(), end, text[open_index + 1:end - 1]))
    return out


def parse(path=SHADER):
    """[(subshader index, subshader tags text, [(pass name, pass text, hlsl program)])]."""
    raw = open(path, encoding="utf-8").read()
    text = strip_comments(raw)
    result = []
    for k, (_, _, sub) in enumerate(blocks(text, "SubShader")):
        passes = []
        for _, _, body in blocks(sub, "Pass"):
            name = re.search(r'\bName\s+"([^"]+)"', body)
            progs = re.findall(r"HLSLPROGRAM(.*?)ENDHLSL", body, flags=re.S)
            passes.append((name.group(1) if name else "?", body, progs[0] if progs else None))
        result.append((k, sub, passes))
    return result


def pragmas(program):
    return [l.strip()[len("#pragma"):].split() for l in program.splitlines() if l.strip().startswith("#pragma")]


# Defines Unity's compiler sets per platform rather than per keyword, compiled together with the
# keyword whose code path they change (Built-in: mobile shadows read the shadow map directly).
PLATFORM_DEFINES = {"SHADOWS_SCREEN": ["UNITY_NO_SCREENSPACE_SHADOWS"]}

KEYWORD_PRAGMA = re.compile(r"^(shader_feature|multi_compile)(_local)?(_vertex|_fragment|_hull|_domain)?$")


def variants(program):
    """Keyword sets to compile: none, each keyword alone (plus the platform defines that change
    its path), all effects together, and the effects with the first keyword of every other set."""
    keywords, firsts = [], []
    for p in pragmas(program):
        if p and KEYWORD_PRAGMA.match(p[0]):
            declared = [k for k in p[1:] if k != "_"]
            keywords += declared
            # Debug views replace the lighting, so they would hide the other sets' code paths.
            if declared and not set(declared) & set(EFFECTS) and not declared[0].startswith("GT_DEBUG"):
                firsts.append(declared[0])
    out = [[]] + [[k] for k in keywords]
    out += [[k] + PLATFORM_DEFINES[k] for k in keywords if k in PLATFORM_DEFINES]
    effects = [k for k in EFFECTS if k in keywords]
    if len(effects) > 1:
        out.append(effects)
    if effects and firsts:
        out.append(effects + firsts)
    return out


def include_root(tmp):
    root = os.path.join(tmp, "root")
    os.makedirs(os.path.join(root, "Packages"))
    os.symlink(PKG_DIR, os.path.join(root, "Packages", PACKAGE_NAME))
    for name in os.listdir(os.path.join(MOCK_DIR, "Packages")):
        os.symlink(os.path.join(MOCK_DIR, "Packages", name), os.path.join(root, "Packages", name))
    return root


def compile_stage(src, stage, entry, keywords, includes, spv):
    cmd = (["glslangValidator", "-D", "-V", "-S", stage, "-e", entry, "--auto-map-bindings",
            "--hlsl-iomap"] + [f"-I{d}" for d in includes] + [f"-D{k}" for k in keywords]
           + ["-o", spv, src])
    p = subprocess.run(cmd, capture_output=True, text=True)
    # glslang echoes the input file name; anything else it prints is a diagnostic.
    lines = [l for l in (p.stdout + p.stderr).splitlines()
             if l.strip() and not re.match(r"^\S+\.hlsl$", l.strip())]
    if p.returncode == 0:
        v = subprocess.run(["spirv-val", spv], capture_output=True, text=True)
        if v.returncode != 0:
            lines.append("spirv-val: " + (v.stdout + v.stderr).strip())
            return False, lines
    return p.returncode == 0 and not lines, lines


def main():
    subshaders = parse()
    ok_count = fail_count = 0
    with tempfile.TemporaryDirectory(prefix="gt-shaderlab-") as tmp:
        root = include_root(tmp)
        includes = [root, os.path.join(MOCK_DIR, "builtin")]
        for k, _, passes in subshaders:
            for name, _, program in passes:
                if program is None:
                    print(f"FAIL subshader {k} pass {name}: no HLSLPROGRAM block")
                    fail_count += 1
                    continue
                src = os.path.join(tmp, f"sub{k}_{name}.hlsl")
                with open(src, "w", encoding="utf-8") as f:
                    f.write(program)
                stages = [(PRAGMA_STAGES[p[0]], p[1]) for p in pragmas(program)
                          if len(p) >= 2 and p[0] in PRAGMA_STAGES]
                for keywords in variants(program):
                    vname = "+".join(x.lower().replace("gt_", "") for x in keywords) or "base"
                    for stage, entry in stages:
                        spv = os.path.join(tmp, f"sub{k}_{name}_{vname}_{stage}.spv")
                        ok, lines = compile_stage(src, stage, entry, keywords, includes, spv)
                        label = f"subshader {k} pass {name} variant {vname} stage {stage} ({entry})"
                        if ok:
                            ok_count += 1
                            print("PASS " + label)
                        else:
                            fail_count += 1
                            print("FAIL " + label)
                            for l in lines[:20]:
                                print("     " + l)
    print(f"shaderlab: {ok_count} compiled, {fail_count} failed")
    return 1 if fail_count or ok_count == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
