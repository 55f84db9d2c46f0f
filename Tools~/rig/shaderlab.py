#!/usr/bin/env python3
"""gt shaderlab: compile the package's shaders against Unity's REAL shader libraries, off Unity.

Every SubShader/Pass of Shaders/GregoryTerrain.shader (and every kernel of every Shaders/**/*.compute)
is compiled with glslang's HLSL front end and with Microsoft's DXC, and linted for FXC's rules that
neither enforces (fxc_lint.py), once per stage its #pragma lines name (vertex -> vert,
hull -> tesc, domain -> tese, fragment -> frag, kernel -> comp) and keyword combination (none, each
keyword alone, all effects together, the effects with the first keyword of every other set), then
validated with spirv-val. Includes resolve as in a Unity project: "Packages/<name>/..." to the
libraries in ../shared/unity-shaderlib (SRP Core/URP 14.0.9, HDRP 14.0.12) and to the package
itself; the Built-in CGIncludes are on the include path (Unity always puts them there).

Unity 2022.3 compiles Vulkan with FXC + HLSLcc, not glslang, so three things the libraries rely on
are emulated after preprocessing (see the shaderlib README), each reported per case on its own
"emulated:" line, apart from real failures:
  half-twins         of two definitions whose parameter types differ only in half vs float (FXC
                     overloads on half, glslang folds it into float), the second is removed;
  texture-types      Texture2D_half / Texture2D_float (HLSLcc types) and their kin -> plain types;
  hdrp-matrix-swizzle  "m._m03_m13_m23 -= v;" and "+= v;" (HDRP ShaderVariables.hlsl lines 345, 375: glslang
                     rejects compound assignment to a matrix swizzle) -> "m.s = m.s - (v);".
  hdrp-shadow-context-buffer  HDRP HDShadowContext.hlsl keeps StructuredBuffer<HDShadowData> as a
                     struct member, always set from the global _HDShadowDatas; glslang cannot hold a
                     buffer in a struct, so the member is dropped and "<ctx>.shadowDatas" reads the
                     global it was set from.
A case that fails only for a known glslang limit is printed "glslang-limit: <case>: <limit>", never
skipped; any other failure in it still fails.

DXC, the second compiler (../shared/dxc): Unity 2022.3 compiles every platform with FXC, which
cannot run here; DXC is the closest compiler that does and the one Unity uses with `#pragma use_dxc`.
Each case is compiled with `-HV 2018` (FXC's HLSL), its own platform defines and keywords (the
Vulkan ones glslang gets) plus UNITY_COMPILER_DXC, so that Unity's headers take their DXC paths, and
Unity's DXC mapping of the HLSLcc precision types emulated by -D (DXC_EMULATED). Target: SPIR-V,
stopping after code generation (-fcgl, unvalidated: -Vd). Why: the language errors FXC refuses and glslang accepts
(`int float`, `cond ? structA : structB`) are DXC front-end errors, caught the same on any target;
DXIL with D3D defines would test the D3D header path, which holds no package code, at 15x the cost
(a URP hull stage: 31 CPU s against 2); SPIR-V legalisation and optimisation find no such error and
would double DXC's share of the check. The SPIR-V, on the platform defines the harness uses, is the
module a later check can run once DXC_OPTIONS legalises it (-O0). DXC's failures are failures;
a known DXC/FXC difference would be a named DXC_LIMITS entry, printed "dxc-limit: <case>: <name>".

Checks (--check, default all):
  pipelines  every SubShader with every library visible; per-pipeline summaries
             "shaderlab <pipeline>: N compiled, N failed, N glslang-limit, N emulated",
             "shaderlab dxc <pipeline>: N compiled, N failed, N dxc-limit" and
             "shaderlab lint <pipeline>: N findings" (each "lint <rule>: <file>:<line>: <message>").
  projects   the .shader as a Built-in-only, a URP-only and an HDRP-only project imports it: a
             SubShader or Pass whose PackageRequirements name an absent package (or a version or
             Unity version outside its ranges) is skipped, every other one compiles with only that
             project's packages visible; "project <kind>: subshaders used ..., compile errors N".
             Project runs reuse the pipelines check's result for a case whose included files all lie
             in the project's packages (same preprocessed text); the rest are compiled again.
             --selection-only: print the SubShaders each project kind uses, compile nothing.
--counts [VARIANTS]  SPIR-V instruction counts per pass, variant and stage ("cost ..." lines; see
             count_instructions), of every variant or of those whose package keywords are one of the
             comma-separated VARIANTS (e.g. base,noise: what the tests compare; a pass's own keywords
             come along; spirv-opt -O is a quarter of a full run's compile time).
--package DIR  check another copy of the package (default: the one holding this script); the
             libraries default to DIR/../shared/unity-shaderlib (--shaderlib DIR to override).
--variants base  only the no-keyword variant (KEYWORD: only the variants with it); --pipeline URP,HDRP,Builtin,Compute  only those.
--dxc PATH   DXC (default ../shared/dxc/bin/dxc beside this package); --no-dxc: glslang only.
Exit 1 on any failure (a project's compile errors, a DXC failure and a lint finding included), 2 on
bad input (missing libraries or DXC, a PackageRequirements block Unity would reject).
"""
import argparse
import concurrent.futures
import functools
import glob
import hashlib
import os
import re
import subprocess
import sys
import tempfile
import threading
import time

import fxc_lint
import options

RIG_DIR = os.path.dirname(os.path.abspath(__file__))
DEFAULT_PKG = os.path.dirname(os.path.dirname(RIG_DIR))
PACKAGE_NAME = "com.gregoryterrain.tessellation"

PRAGMA_STAGES = {"vertex": "vert", "hull": "tesc", "domain": "tese", "fragment": "frag"}
STAGE_DEFINES = {"vert": "SHADER_STAGE_VERTEX", "tesc": "SHADER_STAGE_HULL", "tese": "SHADER_STAGE_DOMAIN",
                 "frag": "SHADER_STAGE_FRAGMENT", "comp": "SHADER_STAGE_COMPUTE"}
EFFECTS = ["GT_NOISE", "GT_HEIGHT_COLOR", "GT_SNOW"]
UNITY_VERSION = "2022.3.62"        # the Built-in CGIncludes' release; UNITY_VERSION define: 202230
COMPUTE_TARGET = 50                # Unity compiles compute shaders as cs_5_0

# Library folders of ../shared/unity-shaderlib, by package name.
LIBRARIES = {
    "com.unity.render-pipelines.core": "srp-14.0.9/com.unity.render-pipelines.core",
    "com.unity.render-pipelines.universal": "srp-14.0.9/com.unity.render-pipelines.universal",
    "com.unity.render-pipelines.universal-config": "srp-14.0.9/com.unity.render-pipelines.universal-config",
    "com.unity.render-pipelines.high-definition": "hdrp-14.0.12/com.unity.render-pipelines.high-definition",
    "com.unity.render-pipelines.high-definition-config": "hdrp-14.0.12/com.unity.render-pipelines.high-definition-config",
}
CGINCLUDES = "builtin-2022.3.62f1/CGIncludes"

# The three project kinds: installed packages and their versions (what the Package Manager
# resolves for URP 14.0.9 / HDRP 14.0.12 on 2022.3). The package under test is in every one.
PROJECTS = {
    "builtin": {},
    "urp": {"com.unity.render-pipelines.core": "14.0.9",
            "com.unity.render-pipelines.universal": "14.0.9",
            "com.unity.render-pipelines.universal-config": "14.0.9"},
    "hdrp": {"com.unity.render-pipelines.core": "14.0.12",
             "com.unity.render-pipelines.high-definition": "14.0.12",
             "com.unity.render-pipelines.high-definition-config": "14.0.12"},
}

# Defines Unity's compiler sets per platform rather than per keyword, compiled together with the
# keyword whose code path they change (Built-in: mobile shadows read the shadow map directly).
PLATFORM_DEFINES = {"SHADOWS_SCREEN": ["UNITY_NO_SCREENSPACE_SHADOWS"]}
# Keywords that only change another keyword's path: alone they compile to the base variant, so
# each is also compiled with the keyword whose path it changes.
MODIFIERS = {"GT_NOISE_TABLE": "GT_NOISE"}

# DXC: Microsoft's DirectX Shader Compiler (../shared/dxc), HLSL 2018 (FXC's language), SPIR-V.
DXC_PROFILES = {"vert": "vs_6_0", "tesc": "hs_6_0", "tese": "ds_6_0", "frag": "ps_6_0", "comp": "cs_6_0"}
# What Unity defines for a `#pragma use_dxc` compile: UNITY_COMPILER_DXC, which the headers test to take
# their DXC paths (Built-in HLSLSupport.cginc and SRP Core Common.hlsl: "DXC no longer supports DX9-style
# HLSL syntax for sampler2D, tex2D and the like", emulated there with sampler2D_f/_h structs; SRP Core
# API/Vulkan.hlsl: the pre-transform constant; Common.hlsl: wave intrinsics left alone). On the platform
# defines glslang uses (SHADER_API_VULKAN, ...), as Unity's own Vulkan compile with use_dxc.
DXC_DEFINES = ["UNITY_COMPILER_DXC=1"]
# Unity's shader compiler front end, not the headers, maps the HLSLcc precision types on GLES3, Vulkan,
# Metal and Switch (HLSLSupport.cginc: on the other DXC platforms "we want the emulated types to work
# directly e.g without needing to redefine 'sampler2D' to 'sampler2D_f'"): emulated by -D, on every case.
DXC_EMULATED = ([f"sampler{t}=sampler{t}_f" for t in ("1D", "2D", "3D", "CUBE")]
                + [f"sampler{t}_float=sampler{t}_f" for t in ("1D", "2D", "3D", "CUBE")]
                + [f"sampler{t}_half=sampler{t}_h" for t in ("1D", "2D", "3D", "CUBE")]
                + [f"Texture{t}_{p}=Texture{t}" for t in ("2D", "2DArray", "Cube", "CubeArray", "3D", "2DMS")
                   for p in ("half", "float")])

KEYWORD_PRAGMA = re.compile(r"^(shader_feature|multi_compile)(_local)?(_vertex|_fragment|_hull|_domain)?$")
PRAGMA_SUFFIX_STAGES = {"_vertex": "vert", "_fragment": "frag", "_hull": "tesc", "_domain": "tese"}


def stage_keywords(program):
    """{keyword: the one stage it is defined in} for multi_compile_fragment and kin: Unity defines
    such a keyword only when compiling that stage."""
    out = {}
    for p in pragmas(program):
        m = KEYWORD_PRAGMA.match(p[0]) if p else None
        if m and m.group(3):
            for k in p[1:]:
                if not is_placeholder(k):
                    out[k] = PRAGMA_SUFFIX_STAGES[m.group(3)]
    return out


# ---------------------------------------------------------------------------------------------
# ShaderLab parsing

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
    raise ValueError("unbalanced braces")


def blocks(text, keyword):
    """(start, end, body) of each 'keyword { ... }' at any depth of text."""
    out = []
    for m in re.finditer(r"\b%s\s*\{" % keyword, text):
        end = block_end(text, m.end() - 1)
        out.append((m.start(), end, text[m.end():end - 1]))
    return out


def outer_part(body, inner_keyword):
    """The part of a block before its first inner block (its own Tags, PackageRequirements)."""
    m = re.search(r"\b%s\s*\{" % inner_keyword, body)
    return body[:m.start()] if m else body


class Pass:
    # shaderlab: the pass's ShaderLab text with its programs removed (tags, render state; render_state.py).
    def __init__(self, name, program, requirements, shaderlab=""):
        self.name, self.program, self.requirements, self.shaderlab = name, program, requirements, shaderlab


class SubShader:
    # outer: the SubShader's text before its first pass (tags, PackageRequirements, shared render state).
    def __init__(self, index, pipeline, requirements, passes, outer=""):
        self.index, self.pipeline, self.requirements, self.passes, self.outer = index, pipeline, requirements, passes, outer


HLSL_INCLUDE = re.compile(r"\bHLSLINCLUDE\b(.*?)\bENDHLSL\b", flags=re.S)


def shared_hlsl(shaderlab):
    """The HLSLINCLUDE blocks of a Shader's or SubShader's own text, joined: Unity pastes them at the top
    of every HLSLPROGRAM in that scope, so their #pragma lines count as the pass's own."""
    return "".join(HLSL_INCLUDE.findall(shaderlab))


INCLUDE_WITH_PRAGMAS = re.compile(r'^[ \t]*#[ \t]*include_with_pragmas[ \t]+"([^"]+)"[^\n]*', flags=re.M)


def with_included_pragmas(program, pkg, seen=()):
    """Unity's #include_with_pragmas (Caching Shader Preprocessor, the only one in 2022.3): the file is
    included and its #pragma lines count as the program's own (its own #include_with_pragmas too).
    Each such line becomes those pragmas and a plain #include, which is all glslang needs; a plain
    #include keeps Unity's behaviour, its file's pragmas ignored."""
    def expand(m):
        name = m.group(1)
        prefix = f"Packages/{PACKAGE_NAME}/"
        if not name.startswith(prefix):
            raise ValueError(f'#include_with_pragmas "{name}": only the package\'s own files ({prefix}...) are read here')
        if name in seen:
            raise ValueError(f'#include_with_pragmas "{name}": includes itself')
        path = os.path.join(pkg, *name[len(prefix):].split("/"))
        if not os.path.isfile(path):
            raise ValueError(f'#include_with_pragmas "{name}": no such file {path}')
        inner = with_included_pragmas(strip_comments(open(path, encoding="utf-8").read()), pkg, seen + (name,))
        lines = [l.strip() for l in inner.splitlines() if l.strip().startswith("#pragma")]
        return "\n".join(lines + [f'#include "{name}"'])
    return INCLUDE_WITH_PRAGMAS.sub(expand, program)


def parse_shader(path):
    text = strip_comments(open(path, encoding="utf-8").read())
    text = with_included_pragmas(text, os.path.dirname(os.path.dirname(os.path.abspath(path))))
    subs = []
    found = blocks(text, "SubShader")
    shader_shared = shared_hlsl(text[:found[0][0]] if found else text)
    for k, (_, _, sub) in enumerate(found):
        outer = outer_part(sub, "Pass")
        shared = shader_shared + shared_hlsl(outer)
        outer = HLSL_INCLUDE.sub("", outer)
        tag = re.search(r'"RenderPipeline"\s*=\s*"(\w+)"', outer)
        pipeline = {"UniversalPipeline": "URP", "HDRenderPipeline": "HDRP"}.get(tag.group(1), tag.group(1)) if tag else "Builtin"
        where = f"{os.path.basename(path)} SubShader {k}"
        passes = []
        for _, _, body in blocks(sub, "Pass"):
            name = re.search(r'\bName\s+"([^"]+)"', body)
            name = name.group(1) if name else "?"
            progs = re.findall(r"HLSLPROGRAM(.*?)ENDHLSL", body, flags=re.S)
            passes.append(Pass(name, shared + progs[0] if progs else None,
                               parse_requirements(body.split("HLSLPROGRAM")[0], f"{where} Pass {name}"),
                               re.sub(r"HLSLPROGRAM.*?ENDHLSL", "", body, flags=re.S)))
        subs.append(SubShader(k, pipeline, parse_requirements(outer, where), passes, outer))
    return subs


# ---------------------------------------------------------------------------------------------
# PackageRequirements (Unity manual, "ShaderLab: specifying package requirements"):
#   "name"                  any version of the package
#   "name": "ranges"        the package, in one of the version ranges
#   "name": "unity=ranges"  the package, and a Unity version in the ranges
#   "unity": "ranges"       a Unity version in the ranges
# ranges: ';'-separated; each "v" (v and later), "[v]" (exactly v) or "[v1,v2]" with '[' / ']'
# inclusive and '(' / ')' exclusive; v is major.minor[.patch][-preview[.n]]. Whitespace-sensitive.

VERSION = re.compile(r"^(\d+)\.(\d+)(?:\.(\d+))?(?:-preview(?:\.(\d+))?)?$")


def parse_version(text, where):
    m = VERSION.match(text)
    if not m:
        raise ValueError(f"{where}: version '{text}' is not major.minor[.patch][-preview[.n]]")
    preview = "-preview" in text
    # A preview comes before the release of the same number.
    return (int(m.group(1)), int(m.group(2)), int(m.group(3) or 0), 0 if preview else 1, int(m.group(4) or 0))


def parse_ranges(text, where):
    """[(low, low_inclusive, high or None, high_inclusive)]"""
    out = []
    for part in text.split(";"):
        if part.startswith("[") or part.startswith("("):
            if not (part.endswith("]") or part.endswith(")")):
                raise ValueError(f"{where}: version range '{part}' has no closing bracket")
            inner = part[1:-1].split(",")
            if len(inner) == 1:
                if part[0] != "[" or part[-1] != "]":
                    raise ValueError(f"{where}: exact version '{part}' must be written [v]")
                v = parse_version(inner[0], where)
                out.append((v, True, v, True))
            elif len(inner) == 2:
                lo, hi = parse_version(inner[0], where), parse_version(inner[1], where)
                if lo > hi:
                    raise ValueError(f"{where}: version range '{part}' is empty")
                out.append((lo, part[0] == "[", hi, part[-1] == "]"))
            else:
                raise ValueError(f"{where}: version range '{part}' has more than two versions")
        else:
            out.append((parse_version(part, where), True, None, False))
    return out


def in_ranges(version, ranges):
    for lo, lo_in, hi, hi_in in ranges:
        if (version > lo or (lo_in and version == lo)) and (hi is None or version < hi or (hi_in and version == hi)):
            return True
    return False


def parse_requirements(outer, where):
    """[(package or 'unity', package ranges or None, unity ranges or None)] of the block's
    PackageRequirements, [] without one."""
    found = list(re.finditer(r"\bPackageRequirements\s*\{([^{}]*)\}", outer))
    if not found:
        return []
    if len(found) > 1:
        raise ValueError(f"{where}: more than one PackageRequirements block")
    if outer[:found[0].start()].strip():
        raise ValueError(f"{where}: PackageRequirements must come before all other declarations")
    body = found[0].group(1)
    reqs, pos = [], 0
    item = re.compile(r'\s*"([^"]+)"(?:\s*:\s*"([^"]*)")?\s*,?')
    while body[pos:].strip():
        m = item.match(body, pos)
        if not m:
            raise ValueError(f"{where}: PackageRequirements entry not understood at '{body[pos:].strip()[:40]}'")
        name, value = m.group(1), m.group(2)
        label = f"{where}: PackageRequirements \"{name}\""
        if name == "unity":
            if value is None:
                raise ValueError(f"{label} needs a version range")
            reqs.append(("unity", None, parse_ranges(value, label)))
        elif value is None:
            reqs.append((name, None, None))
        elif value.startswith("unity="):
            reqs.append((name, None, parse_ranges(value[len("unity="):], label)))
        else:
            reqs.append((name, parse_ranges(value, label), None))
        pos = m.end()
    return reqs


def requirements_met(reqs, installed):
    """None when met, else the first unmet requirement in words."""
    unity = parse_version(UNITY_VERSION, "UNITY_VERSION")
    for name, pkg_ranges, unity_ranges in reqs:
        if name != "unity":
            if name not in installed:
                return f"{name} not installed"
            if pkg_ranges and not in_ranges(parse_version(installed[name], name), pkg_ranges):
                return f"{name} {installed[name]} outside the required versions"
        if unity_ranges and not in_ranges(unity, unity_ranges):
            return f"Unity {UNITY_VERSION} outside the required versions"
    return None


# ---------------------------------------------------------------------------------------------
# Cases

def pragmas(program):
    return [l.strip()[len("#pragma"):].split() for l in program.splitlines() if l.strip().startswith("#pragma")]


def is_placeholder(k):
    return re.fullmatch(r"_+", k) is not None


FOG_KEYWORDS = ["FOG_LINEAR", "FOG_EXP", "FOG_EXP2"]   # what Unity's multi_compile_fog declares
# Built-in's shortcut pragmas and the keyword sets Unity declares for them (a set without "_": one keyword is always
# on). multi_compile_shadowcaster: SHADOWS_DEPTH for directional and spot maps, SHADOWS_CUBE for a point light's.
SHORTCUTS = {"multi_compile_fog": ["_"] + FOG_KEYWORDS, "multi_compile_shadowcaster": ["SHADOWS_DEPTH", "SHADOWS_CUBE"]}


def variants(program):
    """Keyword sets to compile: none, each keyword alone (plus the platform defines that change
    its path; a modifier with the keyword it modifies), all effects together, and the effects with
    the first keyword of every other set."""
    keywords, firsts, required_sets = [], [], []
    for p in pragmas(program):
        if p and p[0] in SHORTCUTS:
            p = ["multi_compile"] + SHORTCUTS[p[0]]
        if p and KEYWORD_PRAGMA.match(p[0]):
            declared = [k for k in p[1:] if not is_placeholder(k)]
            if not any(is_placeholder(k) for k in p[1:]) and len(declared) > 1:
                required_sets.append(declared)
            keywords += declared
            # Debug views replace the lighting, so they would hide the other sets' code paths.
            if declared and not set(declared) & set(EFFECTS) and not declared[0].startswith("GT_DEBUG"):
                firsts.append(declared[0])
    out = [[]] + [[k] for k in keywords]
    out += [[k] + PLATFORM_DEFINES[k] for k in keywords if k in PLATFORM_DEFINES]
    out += [[MODIFIERS[k], k] for k in keywords if k in MODIFIERS and MODIFIERS[k] in keywords]
    effects = [k for k in EFFECTS if k in keywords]
    if len(effects) > 1:
        out.append(effects)
    if effects and firsts:
        out.append(effects + firsts)
    # A set without "_" always has one of its keywords on: Unity never compiles the set's absence,
    # so every variant gets the set's first keyword unless it already names one of them.
    for required in required_sets:
        out = [v if set(v) & set(required) else v + [required[0]] for v in out]
    return [v for i, v in enumerate(out) if v not in out[:i]]


def pass_variants(shader_path):
    """[(pipeline, SubShader index, pass name, keywords)]: every pass's variants as this module compiles them
    (variants(); a pass without a program has none), SubShader after SubShader. gt pipeline_pass_all draws these."""
    return [(s.pipeline, s.index, p.name, v) for s in parse_shader(shader_path) for p in s.passes if p.program is not None
            for v in variants(p.program)]


def variant_name(keywords):
    return "+".join(x.lower().replace("gt_", "") for x in keywords) or "base"


class Case:
    """One compile: a program, a stage and entry point, a keyword set."""
    def __init__(self, pipeline, label, source, stage, entry, keywords, target, group, only_in=None):
        self.only_in = only_in or {}   # stage_keywords of the program
        self.pipeline, self.label, self.source = pipeline, label, source
        self.stage, self.entry, self.keywords, self.target = stage, entry, keywords, target
        self.group = group     # (pipeline, "sub<k> <pass>" or "<file>") for counts

    def key(self):
        """Same program, stage, entry and keywords: the same compile in any project."""
        if self.source is None:
            return None
        with open(self.source, "rb") as f:
            program = hashlib.sha256(f.read()).hexdigest()
        return (program, self.stage, self.entry, tuple(self.defines()), self.target)

    def defines(self):
        # =1, not empty: the libraries test them in #if expressions (UnityCG: !(SHADER_API_VULKAN || ...)).
        return (["SHADER_API_VULKAN=1", "SHADER_API_DESKTOP=1", "UNITY_VERSION=202230", f"SHADER_TARGET={self.target}",
                 STAGE_DEFINES[self.stage] + "=1"]
                + [k + "=1" for k in self.keywords if self.only_in.get(k, self.stage) == self.stage])


def shader_target(program, default):
    for p in pragmas(program):
        if len(p) >= 2 and p[0] == "target":
            major, _, minor = p[1].partition(".")
            return int(major) * 10 + int(minor or 0)
    return default


def select(variant_list, which):
    """which: "all", "base" (no keyword) or a keyword (the variants that have it)."""
    if which == "all":
        return variant_list
    return variant_list[:1] if which == "base" else [v for v in variant_list if which in v]


def shader_cases(subs, shader_path, tmp, tag, which="all"):
    """(Case list, list of (subshader, pass) compiled) for the given SubShaders."""
    cases = []
    for s in subs:
        for p in s.passes:
            label0 = f"{s.pipeline} sub{s.index} {p.name}"
            if p.program is None:
                cases.append(Case(s.pipeline, label0 + ": no HLSLPROGRAM block", None, None, None, [], 0, (s.pipeline, label0)))
                continue
            src = os.path.join(tmp, f"{tag}_sub{s.index}_{re.sub(r'[^A-Za-z0-9]', '_', p.name)}.hlsl")
            with open(src, "w", encoding="utf-8") as f:
                # Errors in the pass's own lines point at the .shader.
                f.write(f'#line 1 "{shader_path}"\n' + p.program)
            stages = [(PRAGMA_STAGES[a[0]], a[1]) for a in pragmas(p.program) if len(a) >= 2 and a[0] in PRAGMA_STAGES]
            target = shader_target(p.program, 25)
            only_in = stage_keywords(p.program)
            for keywords in select(variants(p.program), which):
                for stage, entry in stages:
                    label = f"{label0} variant {variant_name(keywords)} stage {stage} ({entry})"
                    cases.append(Case(s.pipeline, label, src, stage, entry, keywords, target, (s.pipeline, label0), only_in))
    return cases


def compute_cases(pkg, which="all"):
    cases = []
    for path in sorted(glob.glob(os.path.join(pkg, "Shaders", "**", "*.compute"), recursive=True)):
        program = strip_comments(open(path, encoding="utf-8").read())
        rel = os.path.relpath(path, pkg)
        # "#pragma kernel NAME DEFINE...": Unity compiles that kernel alone with those defines.
        kernels = [(a[1], a[2:]) for a in pragmas(program) if len(a) >= 2 and a[0] == "kernel"]
        target = shader_target(program, COMPUTE_TARGET)
        for keywords in select(variants(program), which):
            for k, defines in kernels:
                label = f"Compute {rel} variant {variant_name(keywords)} kernel {k}"
                cases.append(Case("Compute", label, path, "comp", k, keywords + defines, target, ("Compute", "Compute " + rel)))
    return cases


# ---------------------------------------------------------------------------------------------
# Emulation of FXC/HLSLcc behaviour glslang lacks (applied to preprocessed text)

TOP_LEVEL_TOKEN = re.compile(r"(?m)^[ \t]*#[^\n]*|[;{]")
BRACE = re.compile(r"[{}]")


def _scan_top_level(text):
    """Top-level function definitions of preprocessed HLSL: [(head_start, body_end, head)].
    Directive lines (#line, #pragma) are skipped; struct/cbuffer bodies are not functions."""
    out, start, pos = [], 0, 0
    while True:
        m = TOP_LEVEL_TOKEN.search(text, pos)
        if not m:
            return out
        tok = m.group(0)
        if tok == ";":
            start = pos = m.end()
            continue
        if tok != "{":   # a directive line
            if text[start:m.start()].strip() == "":
                start = m.end()
            pos = m.end()
            continue
        depth, end = 0, len(text)
        for b in BRACE.finditer(text, m.start()):
            depth += 1 if b.group(0) == "{" else -1
            if depth == 0:
                end = b.end()
                break
        head = re.sub(r"(?m)^[ \t]*#.*$", " ", text[start:m.start()])
        is_type = re.match(r"\s*(struct|cbuffer|tbuffer|namespace|class|interface)\b", head)
        if not is_type and re.search(r"\)\s*(:\s*\w+\s*)?$", head):
            out.append((start, end, head))
            start = end
        elif is_type and re.match(r"\s*(cbuffer|tbuffer|namespace)\b", head):
            start = end
        pos = end


def _split_params(params):
    out, depth, cur = [], 0, ""
    for c in params:
        if c in "(<":
            depth += 1
        elif c in ")>":
            depth -= 1
        if c == "," and depth == 0:
            out.append(cur)
            cur = ""
        else:
            cur += c
    if cur.strip():
        out.append(cur)
    return out


@functools.lru_cache(maxsize=None)
def _signature(head):
    """(name, raw parameter types, return type) of a function head, or None. Memoized: every case
    of a run includes the same library functions, so most heads were parsed for an earlier case."""
    head = re.sub(r"\[[^\]]*\]", " ", head)   # attributes: [domain("quad")] ...
    m = re.search(r"([\w:]+)\s*\((.*)\)\s*(:\s*\w+\s*)?$", head, flags=re.S)
    if not m:
        return None
    ret = head[:m.start()].split()
    types = []
    for p in _split_params(m.group(2)):
        p = re.sub(r":\s*\w+", "", p.split("=")[0])
        p = re.sub(r"\[[^\]]*\]", "", p)
        tokens = [t for t in re.findall(r"[\w<>,]+", p) if t != "in"]
        if tokens == ["void"] or not tokens:
            continue
        types.append(" ".join(tokens[:-1]))
    return m.group(1), tuple(types), " ".join(ret)


@functools.lru_cache(maxsize=None)
def _fold_half(t):
    return re.sub(r"\b(?:half|min16float|min10float)(\d(?:x\d)?)?\b", lambda m: "float" + (m.group(1) or ""), t)


def remove_half_twins(text):
    """Blank the second of two definitions whose parameter types differ only in half vs float.
    Returns (text, count). Identical definitions (a real redefinition) are left for glslang to report."""
    seen, cuts = {}, []
    for start, end, head in _scan_top_level(text):
        sig = _signature(head)
        if not sig:
            continue
        name, raw, _ = sig
        key = (name, tuple(_fold_half(t) for t in raw))
        if key in seen and seen[key] != raw:
            cuts.append((start, end))
        else:
            seen.setdefault(key, raw)
    for start, end in reversed(cuts):
        # Keep the newlines so #line numbering and later errors still point at the right lines.
        text = text[:start] + re.sub(r"[^\n]", " ", text[start:end]) + text[end:]
    return text, len(cuts)


TEXTURE_TYPES = re.compile(r"\bTexture(2D|2DArray|Cube|CubeArray|3D|2DMS)_(?:half|float)\b")
MATRIX_SWIZZLE_OP = re.compile(r"(\w+)\s*\.\s*(_m\d\d(?:_m\d\d)+)\s*([-+])=\s*([^;]+);")


def emulate(text):
    applied = []
    text, n = remove_half_twins(text)
    if n:
        applied.append("half-twins")
    text, n = TEXTURE_TYPES.subn(r"Texture\1", text)
    if n:
        applied.append("texture-types")
    n = 0
    if re.search(r"_m\d\d_m\d\d\w*\s*[-+]=", text):
        text, n = MATRIX_SWIZZLE_OP.subn(r"\1.\2 = \1.\2 \3 (\4);", text)
    if n:
        applied.append("hdrp-matrix-swizzle")
    text, n = emulate_shadow_context_buffer(text)
    if n:
        applied.append("hdrp-shadow-context-buffer")
    return text, applied


SHADOW_CONTEXT_MEMBER = re.compile(r"^[ \t]*StructuredBuffer\s*<\s*HDShadowData\s*>\s*shadowDatas\s*;[ \t]*$", re.M)
SHADOW_CONTEXT_SET = re.compile(r"^[ \t]*\w+\s*\.\s*shadowDatas\s*=\s*_HDShadowDatas\s*;[ \t]*$", re.M)
SHADOW_CONTEXT_READ = re.compile(r"\b\w+\s*\.\s*shadowDatas\b")


SHADOW_DATAS_GLOBAL = re.compile(r"^[ \t]*StructuredBuffer\s*<\s*HDShadowData\s*>\s*_HDShadowDatas\s*;[ \t]*$", re.M)
SHADOW_CONTEXT_STRUCT = re.compile(r"^[ \t]*struct\s+HDShadowContext\b", re.M)


def emulate_shadow_context_buffer(text):
    """HDRP's shadow context holds the shadow data buffer as a struct member; only ever the global.
    The global is declared after the shadow algorithms that read the member, so its declaration
    moves up to where the struct is declared."""
    struct = SHADOW_CONTEXT_STRUCT.search(text)
    if not SHADOW_CONTEXT_MEMBER.search(text) or struct is None or not SHADOW_DATAS_GLOBAL.search(text):
        return text, 0
    text, members = SHADOW_CONTEXT_MEMBER.subn("", text)
    text = SHADOW_DATAS_GLOBAL.sub("", text)
    struct = SHADOW_CONTEXT_STRUCT.search(text)
    # On the struct's own line: the line numbers after it stay those of the source.
    text = text[:struct.start()] + "StructuredBuffer<HDShadowData> _HDShadowDatas; " + text[struct.start():]
    text, sets = SHADOW_CONTEXT_SET.subn("", text)
    text, reads = SHADOW_CONTEXT_READ.subn("_HDShadowDatas", text)
    return text, members + sets + reads


# ---------------------------------------------------------------------------------------------
# Known glslang limits: a failure is put down to one only when every error is that one's.

def _builtin_screen_shadow(case, errors):
    """Built-in SHADOWS_SCREEN: AutoLight's tex2Dproj lookup of the screen-space shadow map
    (sampler2D, projective) becomes an image operation spirv-val rejects (shaderlib README)."""
    if "SHADOWS_SCREEN" not in case.keywords or "UNITY_NO_SCREENSPACE_SHADOWS" in case.keywords:
        return False
    return len(errors) == 1 and re.match(
        r"spirv-val: error: .*Expected Sampled Image to be of type OpTypeSampledImage .*= OpImageSampleProj\w*ImplicitLod ",
        errors[0]) is not None


LIMITS = [("builtin-shadows-screen-tex2Dproj", _builtin_screen_shadow)]

# Known differences between DXC and FXC, each a (name, test) like LIMITS: a DXC failure is put down
# to one only when the test says so; none is needed today.
DXC_LIMITS = []
# Front end and code generation only (see the docstring); -Vd: the module is not legalised, so
# spirv-val would refuse what legalisation removes (Built-in's emulated sampler2D_f struct holding a
# texture and a sampler). ["-O0"] would legalise and validate it, at about twice DXC's time.
DXC_OPTIONS = ["-fcgl", "-Vd"]


def hlsl_blocks_only(shader_text):
    """A .shader with everything outside its HLSLPROGRAM and HLSLINCLUDE blocks blanked (line numbers kept)."""
    out, pos = [], 0
    for m in re.finditer(r"HLSL(?:PROGRAM|INCLUDE)(.*?)ENDHLSL", shader_text, flags=re.S):
        out.append(re.sub(r"[^\n]", " ", shader_text[pos:m.start(1)]))
        out.append(m.group(1))
        pos = m.end(1)
    out.append(re.sub(r"[^\n]", " ", shader_text[pos:]))
    return "".join(out)


# ---------------------------------------------------------------------------------------------
# Compilation

class Rig:
    def __init__(self, pkg, shaderlib, tmp, jobs, counts, dxc=None):
        self.pkg, self.shaderlib, self.tmp, self.jobs, self.counts, self.dxc = pkg, shaderlib, tmp, jobs, counts, dxc
        self.cache, self.lock, self.serial = {}, threading.Lock(), 0
        self.preprocessed = 0
        self.resolved = {}   # Case.key() -> (result, logical paths of the files it included), all libraries visible
        self.dxc_cache = {}  # Case.key() -> DXC's result
        self.count_cache = {}  # compiled program (.spv path) -> count_instructions
        self.lint_cache = {}  # (text hash, kernel) or package file -> findings
        self.banned = fxc_lint.banned_words(shaderlib)

    def include_root(self, name, packages):
        """A folder whose Packages/ holds the package under test and the given libraries."""
        root = os.path.join(self.tmp, "root-" + name)
        os.makedirs(os.path.join(root, "Packages"))
        os.symlink(self.pkg, os.path.join(root, "Packages", PACKAGE_NAME))
        for p in packages:
            os.symlink(os.path.join(self.shaderlib, LIBRARIES[p]), os.path.join(root, "Packages", p))
        return [root, os.path.join(self.shaderlib, CGINCLUDES)]

    def next_path(self, suffix):
        with self.lock:
            self.serial += 1
            return os.path.join(self.tmp, f"c{self.serial}{suffix}")

    def run_case(self, case, includes, visible=None, lint=None):
        """-> (status 'ok' | 'fail' | 'limit', lines, emulated list, instruction count or None).
        visible: the packages a project has (None: all). A case whose files, with every library
        visible, all lie in visible packages preprocesses to the same text: its result is reused.
        lint: a list that takes the case's lint findings (the pipelines check)."""
        if case.source is None:
            return "fail", [], [], None
        key = case.key()
        if visible is not None and key in self.resolved:
            result, used = self.resolved[key]
            if all(not u.startswith("Packages/") or u.split("/")[1] in visible for u in used):
                return result
        result, used = self.preprocess_and_compile(case, includes, lint)
        if visible is None:
            self.resolved[key] = (result, used)
        return result

    def preprocess_and_compile(self, case, includes, lint=None):
        with self.lock:
            self.preprocessed += 1
        cmd = (["glslangValidator", "-D", "-E", "-S", case.stage, "-e", case.entry]
               + [f"-I{d}" for d in includes] + [f"-D{d}" for d in case.defines()] + [case.source])
        p = subprocess.run(cmd, capture_output=True, text=True)
        if p.returncode != 0:
            lines = [l for l in (p.stdout + p.stderr).splitlines() if "ERROR" in l or "error" in l]
            for d in includes:
                lines = [l.replace(d + "/", "") for l in lines]
            return ("fail", lines or ["preprocessing failed"], [], None), None
        text = p.stdout
        # Logical paths in #line, so the same code gives the same text whatever the root.
        for d in includes:
            text = text.replace(d + "/", "")
        used = set(re.findall(r'(?m)^#line \d+ "([^"]+)"', text))
        if lint is not None:
            lint.extend(self.lint(case, text, used))
        text, applied = emulate(text)
        key = hashlib.sha256(f"{case.stage}\0{case.entry}\0{text}".encode()).hexdigest()
        with self.lock:
            hit = self.cache.get(key)
        if hit is None:
            hit = self.compile(case, text)
            with self.lock:
                self.cache[key] = hit
        ok, errors, spv = hit
        if ok:
            return ("ok", [], applied, self.count(spv) if self.counted(case) else None), used
        for name, test in LIMITS:
            if test(case, errors):
                return ("limit", [name] + errors, applied, None), used
        return ("fail", errors, applied, None), used

    def compile(self, case, text):
        src, spv = self.next_path(".hlsl"), self.next_path(".spv")
        with open(src, "w", encoding="utf-8") as f:
            f.write(text)
        p = subprocess.run(["glslangValidator", "-D", "-V", "-S", case.stage, "-e", case.entry,
                            "--auto-map-bindings", "--hlsl-iomap", "-o", spv, src], capture_output=True, text=True)
        # glslang echoes the input file name; anything else it prints is a diagnostic.
        lines = [l for l in (p.stdout + p.stderr).splitlines()
                 if l.strip() and l.strip() != src and "SPIR-V is not generated" not in l]
        if p.returncode != 0 or any("ERROR" in l for l in lines):
            return False, lines or [f"glslang exit {p.returncode}"], None
        v = subprocess.run(["spirv-val", spv], capture_output=True, text=True)
        if v.returncode != 0:
            return False, ["spirv-val: " + " ".join((v.stdout + v.stderr).split())], None
        return True, [], spv

    def counted(self, case):
        """--counts VARIANTS name the package's keywords: a pass's own that come along (HDRP's
        SHADOW_LOW in every ForwardOnly variant) do not change which variants are counted."""
        if self.counts is None or self.counts == "all":
            return self.counts == "all"
        return variant_name([k for k in case.keywords if k.startswith("GT_")]) in self.counts

    def count(self, spv):
        """count_instructions of a compiled program, once per program."""
        with self.lock:
            hit = self.count_cache.get(spv)
        if hit is None:
            hit = count_instructions(spv)
            with self.lock:
                self.count_cache[spv] = hit
        return hit

    def run(self, cases, includes, visible=None):
        with concurrent.futures.ThreadPoolExecutor(self.jobs) as pool:
            return list(pool.map(lambda c: self.run_case(c, includes, visible), cases))

    def run_pipelines(self, cases, includes):
        """[(glslang result, DXC result or None, lint findings)] per case, every compile in one pool."""
        def one(case):
            found = []
            result = self.run_case(case, includes, None, found)
            return result, (self.run_dxc(case, includes) if self.dxc else None), found
        with concurrent.futures.ThreadPoolExecutor(self.jobs) as pool:
            return list(pool.map(one, cases))

    # -- DXC

    def run_dxc(self, case, includes):
        """-> (status 'ok' | 'fail' | 'limit', lines). DXC preprocesses the pass itself (its own
        preprocessor, with Unity's DXC defines); the same compile in two cases runs once."""
        if case.source is None:
            return "fail", ["no HLSLPROGRAM block"]
        key = case.key()
        with self.lock:
            hit = self.dxc_cache.get(key)
        if hit is None:
            hit = self.dxc_compile(case, includes)
            with self.lock:
                self.dxc_cache[key] = hit
        ok, errors = hit
        if ok:
            return "ok", []
        for name, test in DXC_LIMITS:
            if test(case, errors):
                return "limit", [name] + errors
        return "fail", errors

    def dxc_compile(self, case, includes):
        spv = self.next_path(".dxc.spv")
        cmd = ([self.dxc, "-HV", "2018", "-spirv", "-T", DXC_PROFILES[case.stage], "-E", case.entry] + DXC_OPTIONS
               + ["-Fo", spv] + [f"-I{d}" for d in includes]
               + [f"-D{d}" for d in case.defines() + DXC_DEFINES + DXC_EMULATED] + [case.source])
        p = subprocess.run(cmd, capture_output=True, text=True)
        out = p.stdout + p.stderr
        for d in includes:
            out = out.replace(d + "/", "")
        errors = [l.strip() for l in out.splitlines() if re.search(r"\berror\b", l)]
        if p.returncode != 0:
            return False, errors or [l.strip() for l in out.splitlines() if l.strip()][:12] or [f"dxc exit {p.returncode}"]
        return True, []

    # -- lint (fxc_lint.py)

    def package_file(self, path):
        """The package-relative path of a file the case included, or None (Unity's headers)."""
        prefix = f"Packages/{PACKAGE_NAME}/"
        if path.startswith(prefix):
            return os.path.normpath(path[len(prefix):])
        full = os.path.normpath(path)
        return os.path.relpath(full, self.pkg) if full.startswith(self.pkg + os.sep) else None

    def lint(self, case, text, used):
        """FXC's rules on the case (fxc_lint.py): a kernel's flow and groupshared size on its
        preprocessed text, reserved-name on the package's files the case includes."""
        found = []
        if case.stage == "comp":
            key = (hashlib.sha256(text.encode()).hexdigest(), case.entry)
            with self.lock:
                kernel = self.lint_cache.get(key)
            if kernel is None:
                raw = []
                fxc_lint.lint_text(text, case.source, case.entry,
                                   lambda rule, tok, msg: raw.append((rule, tok.file, tok.line, msg)))
                kernel = [(rule, self.package_file(f), line, msg) for rule, f, line, msg in raw if self.package_file(f)]
                with self.lock:
                    self.lint_cache[key] = kernel
            found += kernel
        for path in sorted(used):
            rel = self.package_file(path)
            if rel is None or not os.path.isfile(os.path.join(self.pkg, rel)):
                continue
            with self.lock:
                names = self.lint_cache.get(rel)
            if names is None:
                with open(os.path.join(self.pkg, rel), encoding="utf-8") as f:
                    source = f.read()
                if rel.endswith(".shader"):
                    source = hlsl_blocks_only(source)
                names = []
                fxc_lint.lint_source_names(source, rel, self.banned,
                                           lambda rule, tok, msg: names.append((rule, tok.file, tok.line, msg)))
                with self.lock:
                    self.lint_cache[rel] = names
            found += names
        return found


def count_instructions(spv):
    """Instructions in the function bodies of the module after spirv-opt -O (dead code of off
    effects removed, helpers inlined into the entry point): every instruction between OpFunction
    and OpFunctionEnd except OpFunctionParameter, OpLabel and debug lines. Falls back to the
    unoptimised module (count prefixed '~') if spirv-opt fails."""
    opt = spv + ".opt"
    o = subprocess.run(["spirv-opt", "-O", spv, "-o", opt], capture_output=True, text=True)
    source, prefix = (opt, "") if o.returncode == 0 else (spv, "~")
    d = subprocess.run(["spirv-dis", "--no-header", "--raw-id", source], capture_output=True, text=True)
    n, inside = 0, False
    for line in d.stdout.splitlines():
        op = re.search(r"\b(Op\w+)", line)
        if not op:
            continue
        op = op.group(1)
        if op == "OpFunction":
            inside = True
        elif op == "OpFunctionEnd":
            inside = False
        elif inside and op not in ("OpFunctionParameter", "OpLabel", "OpLine", "OpNoLine"):
            n += 1
    return f"{prefix}{n}"


# ---------------------------------------------------------------------------------------------

def report(cases, results, prefix, quiet=False):
    """Print per case (quiet: not the passing ones); return {pipeline: [compiled, failed, limit, emulated]}."""
    totals = {}
    for case, (status, lines, applied, _) in zip(cases, results):
        t = totals.setdefault(case.pipeline, [0, 0, 0, 0])
        if status == "ok":
            t[0] += 1
            if not quiet:
                print(f"{prefix}PASS {case.label}")
        elif status == "limit":
            t[2] += 1
            print(f"{prefix}glslang-limit: {case.label}: {lines[0]}")
            for l in lines[1:]:
                print("     " + l)
        else:
            t[1] += 1
            print(f"{prefix}FAIL {case.label}")
            for l in lines[:12]:
                print("     " + l)
        if applied:
            t[3] += 1
            if not quiet or status != "ok":
                print(f"{prefix}emulated: {case.label}: {', '.join(applied)}")
    return totals


def report_dxc(cases, results, quiet=False):
    """DXC's failures and known differences per case; {pipeline: [compiled, failed, limit]}."""
    totals = {}
    for case, (status, lines) in zip(cases, results):
        t = totals.setdefault(case.pipeline, [0, 0, 0])
        if status == "ok":
            t[0] += 1
        elif status == "limit":
            t[2] += 1
            print(f"dxc-limit: {case.label}: {lines[0]}")
            for l in lines[1:]:
                print("     " + l)
        else:
            t[1] += 1
            print(f"dxc FAIL {case.label}")
            for l in lines[:12]:
                print("     " + l)
    return totals


def report_lint(cases, found):
    """Each distinct finding once ("lint <rule>: <file>:<line>: <message>"); {pipeline: count}."""
    first, per_pipeline = {}, {}
    for case, findings in zip(cases, found):
        for rule, file, line, message in findings:
            first.setdefault((rule, file, line), message)
            per_pipeline.setdefault(case.pipeline, set()).add((rule, file, line))
    for (rule, file, line), message in sorted(first.items()):
        print(f"lint {rule}: {file}:{line}: {message}")
    return {p: len(per_pipeline.get(p, ())) for p in dict.fromkeys(c.pipeline for c in cases)}, len(first)


def print_counts(cases, results):
    print("instruction counts (SPIR-V after spirv-opt -O, function bodies; see shaderlab.py count_instructions)")
    rows = {}
    for case, (status, _, _, count) in zip(cases, results):
        if status == "ok" and count is not None:
            rows.setdefault((case.group, variant_name(case.keywords)), []).append((case.stage, case.entry, count))
    for (group, variant), stages in rows.items():
        total = sum(int(c.lstrip("~")) for _, _, c in stages)
        cells = "  ".join(f"{s} {c}" if s != "comp" else f"{e} {c}" for s, e, c in stages)
        print(f"cost {group[1]} variant {variant}: {cells}  total {total}")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--package", default=DEFAULT_PKG, help="package root to check (default: this package)")
    ap.add_argument("--shaderlib", default=None, help="Unity's shader libraries (default: PACKAGE/../shared/unity-shaderlib)")
    ap.add_argument("--check", choices=["all", "pipelines", "projects"], default="all")
    ap.add_argument("--counts", nargs="?", const="all", default=None, metavar="VARIANTS",
                    help="print SPIR-V instruction counts per pass, variant and stage (all variants, or the comma-separated VARIANTS)")
    options.add_number(ap, "--jobs", range="jobs", default=2, help="parallel compiles (default 2)")
    ap.add_argument("--pipeline", default=None, help="comma-separated pipelines to check (URP,HDRP,Builtin,Compute; default all)")
    ap.add_argument("--variants", default="all", metavar="all|base|KEYWORD",
                    help="all: none, each keyword alone, the effects together, the effects with the other sets' first keywords; "
                         "base: no keyword; KEYWORD: those of all that have it")
    ap.add_argument("--selection-only", action="store_true",
                    help="projects check: print which SubShaders and passes each project kind uses, compile nothing")
    ap.add_argument("--quiet", action="store_true", help="print failures, limits and summaries only")
    ap.add_argument("--dxc", default=os.path.join(DEFAULT_PKG, "..", "shared", "dxc", "bin", "dxc"),
                    help="Microsoft's DXC (default: ../shared/dxc/bin/dxc beside this package)")
    ap.add_argument("--no-dxc", action="store_true", help="glslang only, for a quick look (the tests run both)")
    ap.add_argument("--list-variants", action="store_true",
                    help="print each pass's variants (pipeline, SubShader, pass, keywords; tab-separated), compile nothing")
    args = ap.parse_args(argv)
    if args.list_variants:
        for pipeline, sub, name, keywords in pass_variants(os.path.join(os.path.abspath(args.package), "Shaders", "GregoryTerrain.shader")):
            print(f"{pipeline}\t{sub}\t{name}\t{' '.join(keywords) or '-'}")
        return 0

    pkg = os.path.abspath(args.package)
    shader = os.path.join(pkg, "Shaders", "GregoryTerrain.shader")
    if not os.path.isfile(shader):
        print(f"shaderlab: error: --package {pkg}: no Shaders/GregoryTerrain.shader there", file=sys.stderr)
        return 2
    shaderlib = os.path.abspath(args.shaderlib or os.path.join(pkg, "..", "shared", "unity-shaderlib"))
    missing = [d for d in list(LIBRARIES.values()) + [CGINCLUDES] if not os.path.isdir(os.path.join(shaderlib, d))]
    if missing:
        print(f"shaderlab: error: Unity's shader libraries not found: {shaderlib} lacks {', '.join(missing)}. "
              "They sit beside the package as ../shared/unity-shaderlib (see its README); "
              "pass --shaderlib DIR to use another copy.", file=sys.stderr)
        return 2
    for tool in ("glslangValidator", "spirv-val", "spirv-opt", "spirv-dis"):
        if subprocess.run(["which", tool], capture_output=True).returncode != 0:
            print(f"shaderlab: error: {tool} not found (run Tools~/gt setup)", file=sys.stderr)
            return 2
    dxc = None if args.no_dxc else os.path.abspath(args.dxc)
    if dxc and not os.access(dxc, os.X_OK):
        print(f"shaderlab: error: --dxc {dxc}: no DXC there. Microsoft's DXC sits beside the package as "
              "../shared/dxc (see its README); pass --dxc PATH to use another copy.", file=sys.stderr)
        return 2
    try:
        subs = parse_shader(shader)
    except ValueError as e:
        print(f"shaderlab: error: {e}", file=sys.stderr)
        return 2

    failed, started = False, time.time()
    with tempfile.TemporaryDirectory(prefix="gt-shaderlab-") as tmp:
        counted = None if args.counts is None else "all" if args.counts == "all" else set(args.counts.split(","))
        rig = Rig(pkg, shaderlib, tmp, args.jobs, counted, dxc)
        if args.check in ("all", "pipelines"):
            cases = shader_cases(subs, shader, tmp, "all", args.variants) + compute_cases(pkg, args.variants)
            if args.pipeline:
                cases = [c for c in cases if c.pipeline in args.pipeline.split(",")]
            outcome = rig.run_pipelines(cases, rig.include_root("all", LIBRARIES))
            results = [o[0] for o in outcome]
            totals = report(cases, results, "", args.quiet)
            dxc_totals = report_dxc(cases, [o[1] for o in outcome]) if dxc else {}
            lint_totals, lint_all = report_lint(cases, [o[2] for o in outcome])
            if args.counts:
                print_counts(cases, results)
            all_t = [0, 0, 0, 0]
            for pipeline, t in totals.items():
                print(f"shaderlab {pipeline}: {t[0]} compiled, {t[1]} failed, {t[2]} glslang-limit, {t[3]} emulated")
                all_t = [a + b for a, b in zip(all_t, t)]
            print(f"shaderlab: {all_t[0]} compiled, {all_t[1]} failed, {all_t[2]} glslang-limit, {all_t[3]} emulated")
            failed |= all_t[1] > 0 or all_t[0] == 0
            if dxc:
                print("dxc emulated (every case): unity-dxc-precision-types (" + ", ".join(DXC_EMULATED[:3]) + ", ...)")
                all_d = [0, 0, 0]
                for pipeline, t in dxc_totals.items():
                    print(f"shaderlab dxc {pipeline}: {t[0]} compiled, {t[1]} failed, {t[2]} dxc-limit")
                    all_d = [a + b for a, b in zip(all_d, t)]
                print(f"shaderlab dxc: {all_d[0]} compiled, {all_d[1]} failed, {all_d[2]} dxc-limit "
                      f"({len(rig.dxc_cache)} distinct programs)")
                failed |= all_d[1] > 0 or all_d[0] == 0
            for pipeline, n in lint_totals.items():
                print(f"shaderlab lint {pipeline}: {n} findings")
            print(f"shaderlab lint: {lint_all} findings")
            failed |= lint_all > 0
        if args.check in ("all", "projects"):
            for kind, installed in PROJECTS.items():
                used, skipped, kept = [], [], []
                for s in subs:
                    why = requirements_met(s.requirements, installed)
                    if why:
                        skipped.append(f"{s.index} {s.pipeline} ({why})")
                        continue
                    passes = []
                    for p in s.passes:
                        pwhy = requirements_met(p.requirements, installed)
                        if pwhy:
                            skipped.append(f"{s.index} {s.pipeline} pass {p.name} ({pwhy})")
                        else:
                            passes.append(p)
                    used.append(f"{s.index} {s.pipeline}")
                    kept.append(SubShader(s.index, s.pipeline, s.requirements, passes))
                if args.selection_only:
                    print(f"project {kind}: subshaders used {len(used)} ({', '.join(used) or 'none'}), skipped "
                          f"{', '.join(skipped) or 'none'}; passes {sum(len(s.passes) for s in kept)}")
                    continue
                cases = shader_cases(kept, shader, tmp, kind, args.variants)
                results = rig.run(cases, rig.include_root(kind, installed), set(installed) | {PACKAGE_NAME})
                errors = [(c, r) for c, r in zip(cases, results) if r[0] == "fail"]
                limits = sum(1 for r in results if r[0] == "limit")
                for c, r in errors:
                    print(f"project {kind}: FAIL {c.label}")
                    for l in r[1][:6]:
                        print("     " + l)
                for c, r in zip(cases, results):
                    if r[0] == "limit":
                        print(f"project {kind}: glslang-limit: {c.label}: {r[1][0]}")
                failing_passes = sorted({c.group[1] for c, _ in errors})
                print(f"project {kind}: subshaders used {len(used)} ({', '.join(used) or 'none'}), skipped "
                      f"{', '.join(skipped) or 'none'}; passes compiled {sum(len(s.passes) for s in kept)}, "
                      f"cases {len(cases)}, compile errors {len(errors)} (in {len(failing_passes)} passes"
                      f"{': ' + ', '.join(failing_passes) if failing_passes else ''}), glslang-limit {limits}")
                failed |= bool(errors)
        print(f"shaderlab: {rig.preprocessed} cases preprocessed, {len(rig.cache)} distinct programs compiled, "
              f"{time.time() - started:.0f} s with {args.jobs} jobs")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
