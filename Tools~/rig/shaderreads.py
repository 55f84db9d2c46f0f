#!/usr/bin/env python3
"""Which constants and resources a shader entry point reads, compiled as Unity compiles it for a
pass of a pipeline: what a rig test can check of a pass that no harness draws (Unity's shadow and
HDRP passes).

The program is either a pass of Shaders/GregoryTerrain.shader (--pass "sub<k> <Name>", its real
HLSL block) or a probe: HLSL text that includes a pipeline adapter and the package's files
(--probe FILE, "#include"s resolved as in a Unity project). It is preprocessed and compiled with
glslang exactly as `gt shaderlab` does (shaderlab.py: the desktop Vulkan defines, Unity's real
libraries in ../shared/unity-shaderlib, the FXC emulation), optimised with spirv-opt -O (so only
what the entry's result depends on is left), and every global it reads is printed by name: a
cbuffer's member, or a resource (StructuredBuffer, texture) by its variable name.

  shaderreads.py (--pass "sub<k> <Name>" | --probe FILE) --stage vert|tesc|tese|frag|comp
                 --entry NAME [--define KEY[=VALUE]]... [--constants]
prints   reads: NAME NAME ...   (sorted, unique) and exits 0; 1 when the program does not compile.
--constants also prints   constants: X X ...   the module's float constants as spirv-dis writes them.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import shaderlab  # noqa: E402  (the emulation and library layout shared with gt shaderlab)


def include_roots(pkg, shaderlib, tmp):
    """A folder whose Packages/ holds the package and every library, and the Built-in CGIncludes."""
    root = os.path.join(tmp, "root")
    os.makedirs(os.path.join(root, "Packages"))
    os.symlink(pkg, os.path.join(root, "Packages", shaderlab.PACKAGE_NAME))
    for name, folder in shaderlab.LIBRARIES.items():
        os.symlink(os.path.join(shaderlib, folder), os.path.join(root, "Packages", name))
    return [root, os.path.join(shaderlib, shaderlab.CGINCLUDES)]


def pass_source(pkg, which, tmp):
    """The HLSL block of pass "sub<k> <Name>" of GregoryTerrain.shader, written to a file."""
    m = re.fullmatch(r"sub(\d+) (.+)", which)
    if not m:
        raise ValueError(f"--pass '{which}': expected \"sub<k> <Name>\"")
    subs = shaderlab.parse_shader(os.path.join(pkg, "Shaders", "GregoryTerrain.shader"))
    k = int(m.group(1))
    found = [p for p in subs[k].passes if p.name == m.group(2)] if k < len(subs) else []
    if not found or found[0].program is None:
        raise ValueError(f"--pass '{which}': no such pass with an HLSLPROGRAM block")
    path = os.path.join(tmp, "pass.hlsl")
    with open(path, "w", encoding="utf-8") as f:
        f.write(found[0].program)
    return path, shaderlab.shader_target(found[0].program, 25)


def compile_spirv(source, stage, entry, defines, includes, tmp):
    """Preprocess, emulate and compile as shaderlab.Rig does, then spirv-opt -O. -> (path, errors)"""
    cmd = (["glslangValidator", "-D", "-E", "-S", stage, "-e", entry]
           + [f"-I{d}" for d in includes] + [f"-D{d}" for d in defines] + [source])
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        return None, [l for l in (p.stdout + p.stderr).splitlines() if "rror" in l] or ["preprocessing failed"]
    text, _ = shaderlab.emulate(p.stdout)
    src, spv, opt = (os.path.join(tmp, n) for n in ("pre.hlsl", "out.spv", "opt.spv"))
    with open(src, "w", encoding="utf-8") as f:
        f.write(text)
    c = subprocess.run(["glslangValidator", "-D", "-V", "-S", stage, "-e", entry, "--auto-map-bindings",
                        "--hlsl-iomap", "-o", spv, src], capture_output=True, text=True)
    if c.returncode != 0:
        return None, [l for l in (c.stdout + c.stderr).splitlines() if "ERROR" in l] or [f"glslang exit {c.returncode}"]
    o = subprocess.run(["spirv-opt", "-O", spv, "-o", opt], capture_output=True, text=True)
    if o.returncode != 0:
        return None, ["spirv-opt: " + " ".join((o.stdout + o.stderr).split())]
    return opt, []


def reads(spv):
    """Names of the globals the module's code reads: the member of a block (cbuffer) an access
    chain selects by a constant index, or the variable itself (a StructuredBuffer, whose block's
    only member is glslang's "@data", a texture, a sampler)."""
    d = subprocess.run(["spirv-dis", "--raw-id", "--no-header", spv], capture_output=True, text=True, check=True)
    names, members, pointee, constants, variables = {}, {}, {}, {}, set()
    lines = d.stdout.splitlines()
    for line in lines:
        if m := re.match(r'\s*OpName (%\d+) "([^"]*)"', line):
            names[m.group(1)] = m.group(2)
        elif m := re.match(r'\s*OpMemberName (%\d+) (\d+) "([^"]*)"', line):
            members[(m.group(1), int(m.group(2)))] = m.group(3)
        elif m := re.match(r"\s*(%\d+) = OpTypePointer \w+ (%\d+)", line):
            pointee[m.group(1)] = m.group(2)
        elif m := re.match(r"\s*(%\d+) = OpConstant %\d+ (-?\d+)$", line):
            constants[m.group(1)] = int(m.group(2))
        elif m := re.match(r"\s*(%\d+) = OpVariable (%\d+) (Uniform|StorageBuffer|UniformConstant|PushConstant)\b", line):
            variables.add(m.group(1))
            pointee[m.group(1)] = pointee.get(m.group(2))
    found = set()
    for line in lines:
        if m := re.match(r"\s*%\d+ = Op(?:InBounds)?AccessChain %\d+ (%\d+) (%\d+)", line):
            var, index = m.group(1), m.group(2)
            if var not in variables:
                continue
            member = members.get((pointee[var], constants.get(index, -1)))
            found.add(names.get(var, var) if member in (None, "@data") else member)
        elif m := re.match(r"\s*%\d+ = OpLoad %\d+ (%\d+)", line):
            if m.group(1) in variables:
                found.add(names.get(m.group(1), m.group(1)))
    return sorted(found)


def float_constants(spv):
    d = subprocess.run(["spirv-dis", "--raw-id", "--no-header", spv], capture_output=True, text=True, check=True)
    floats = set(re.findall(r"(%\d+) = OpTypeFloat 32", d.stdout))
    return sorted({m.group(2) for m in re.finditer(r"= OpConstant (%\d+) (\S+)", d.stdout) if m.group(1) in floats})


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    src = ap.add_mutually_exclusive_group(required=True)
    src.add_argument("--pass", dest="pass_name", help='a pass of GregoryTerrain.shader: "sub<k> <Name>"')
    src.add_argument("--probe", help="an HLSL file")
    ap.add_argument("--stage", required=True, choices=sorted(shaderlab.STAGE_DEFINES))
    ap.add_argument("--entry", required=True)
    ap.add_argument("--define", action="append", default=[], help="a keyword or KEY=VALUE (repeatable)")
    ap.add_argument("--package", default=shaderlab.DEFAULT_PKG)
    ap.add_argument("--shaderlib", default=None)
    ap.add_argument("--constants", action="store_true", help="also print the float constants")
    args = ap.parse_args(argv)
    pkg = os.path.abspath(args.package)
    shaderlib = os.path.abspath(args.shaderlib or os.path.join(pkg, "..", "shared", "unity-shaderlib"))
    with tempfile.TemporaryDirectory(prefix="gt-shaderreads-") as tmp:
        try:
            source, target = pass_source(pkg, args.pass_name, tmp) if args.pass_name else (os.path.abspath(args.probe), 46)
        except ValueError as e:
            print(f"shaderreads: error: {e}", file=sys.stderr)
            return 2
        defines = (["SHADER_API_VULKAN=1", "SHADER_API_DESKTOP=1", "UNITY_VERSION=202230", f"SHADER_TARGET={target}",
                    shaderlab.STAGE_DEFINES[args.stage] + "=1"]
                   + [d if "=" in d else d + "=1" for d in args.define])
        spv, errors = compile_spirv(source, args.stage, args.entry, defines, include_roots(pkg, shaderlib, tmp), tmp)
        if spv is None:
            print("shaderreads: does not compile:\n  " + "\n  ".join(errors[:12]))
            return 1
        print("reads: " + " ".join(reads(spv)))
        if args.constants:
            print("constants: " + " ".join(float_constants(spv)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
