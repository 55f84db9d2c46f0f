#!/usr/bin/env python3
"""FXC's rules that neither glslang nor DXC enforces, as a lint (run by `gt shaderlab`).

Unity 2022.3 compiles every platform's shaders with Microsoft's FXC (d3dcompiler_47), which cannot run
here. glslang and DXC accept code FXC refuses; each rule below is one such FXC error, taken from
Microsoft's HLSL documentation (learn.microsoft.com, direct3dhlsl):

  barrier-in-varying-flow  A group barrier (GroupMemoryBarrier[WithGroupSync], DeviceMemoryBarrier
                           [WithGroupSync], AllMemoryBarrier[WithGroupSync]) that not every thread of
                           the group reaches: under a branch or loop whose condition is non-uniform,
                           or after a return / break / continue taken under one. Microsoft: "The
                           behavior of calls to this function that are within diverging branches of
                           a thread group are undefined"; FXC refuses them, error X3663 ("thread sync
                           operation found in varying flow control"). Non-uniform: the thread IDs
                           (SV_GroupThreadID, SV_GroupIndex, SV_DispatchThreadID), any value read from
                           a buffer, texture or groupshared variable, and what is computed from them
                           (data or control dependence); uniform: literals, cbuffer and global
                           constants, SV_GroupID.
  uav-loop-condition       A compute-shader loop whose termination condition depends on a value read
                           from a RW resource (a UAV) without [allow_uav_condition] ("for"/"while"
                           Statement: "allow_uav_condition: Allows a compute shader loop termination
                           condition to be based off of a UAV read. The loop must not contain
                           synchronization intrinsics"); also such a loop that does contain a barrier.
  reserved-name            A declaration (variable, parameter, member, function) named with an HLSL
                           keyword ("Keywords": "You can't use them as identifiers"; with the scalar,
                           vector and matrix expansions of the numeric types), a reserved word
                           ("Reserved Words": "Do not use them to name variables or functions"), or a
                           lowercase type name that Unity's shader headers #define (half, real, fixed,
                           min16float, ...: Built-in's HLSLSupport.cginc makes `int half` read
                           `int float`). Checked on the package's own source files.
  groupshared-limit        More than 32 KB of groupshared variables in one kernel ("Variable
                           Syntax", groupshared: "in D3D11 the maximum size is 32kb"); DXC checks it
                           for DXIL only, glslang not at all.

Looked at and left out, because glslang or DXC already refuses them: [numthreads] outside cs_5_0's
limits (DXC), [unroll] with [loop] (DXC; spirv-val after glslang), a conditional operator on
structs and `int float` (DXC at HLSL 2018).

Findings are (rule, file, line, message); `gt shaderlab` reports those in the package's own files,
never in Unity's headers. The flow rules analyse a kernel's entry function and every function it
calls, on the preprocessed text of the case (#line directives give file and line).

Command line (the rule tests use it):  fxc_lint.py FILE [--entry NAME] [--source] [--shaderlib DIR]
  FILE preprocessed HLSL (or plain HLSL without #include); --entry: a compute kernel for the flow
  and groupshared rules; --source: the reserved-name rule on FILE itself (with the names Unity's
  headers in --shaderlib #define).
  Prints "lint <rule>: <file>:<line>: <message>" per finding and "lint: N findings"; exit 1 on any.
"""
import argparse
import glob
import os
import re
import sys

# ---------------------------------------------------------------------------------------------
# Word lists

# Microsoft, "Keywords" (HLSL appendix).
KEYWORDS = set("""
AppendStructuredBuffer asm asm_fragment BlendState bool break Buffer ByteAddressBuffer case cbuffer
centroid class column_major compile compile_fragment CompileShader const continue ComputeShader
ConsumeStructuredBuffer default DepthStencilState DepthStencilView discard do double DomainShader dword
else export extern false float for fxgroup GeometryShader groupshared half Hullshader if in inline inout
InputPatch int interface line lineadj linear LineStream matrix min16float min10float min16int min12int
min16uint namespace nointerpolation noperspective NULL out OutputPatch packoffset pass pixelfragment
PixelShader point PointStream precise RasterizerState RenderTargetView return register row_major RWBuffer
RWByteAddressBuffer RWStructuredBuffer RWTexture1D RWTexture1DArray RWTexture2D RWTexture2DArray
RWTexture3D sample sampler SamplerState SamplerComparisonState shared snorm stateblock stateblock_state
static string struct switch StructuredBuffer tbuffer technique technique10 technique11 texture Texture1D
Texture1DArray Texture2D Texture2DArray Texture2DMS Texture2DMSArray Texture3D TextureCube
TextureCubeArray true typedef triangle triangleadj TriangleStream uint uniform unorm unsigned vector
vertexfragment VertexShader void volatile while
""".split())
# "These numeric types have scalar, vector, and matrix keyword expansions" (same page); half and
# double expand the same way in both compilers.
NUMERIC = ["float", "int", "uint", "bool", "min10float", "min16float", "min12int", "min16int", "min16uint",
           "half", "double"]
KEYWORDS |= {t + s for t in NUMERIC for s in [str(n) for n in range(1, 5)] + [f"{r}x{c}" for r in range(1, 5) for c in range(1, 5)]}
# Microsoft, "Reserved Words" (HLSL appendix).
RESERVED = set("""
auto case catch char class const_cast default delete dynamic_cast enum explicit friend goto long mutable
new operator private protected public reinterpret_cast short signed sizeof static_cast template this
throw try typename union unsigned using virtual
""".split())

TYPEISH = re.compile(r"^(?:bool|int|uint|half|float|double|min16float|min10float|min16int|min12int|min16uint|fixed|real"
                     r"|[biu]?vec)(?:[1-4](?:x[1-4])?)?$")
OBJECT_DEFINE = re.compile(r"^\s*#\s*define\s+([a-z][a-z0-9_]*)\s+([A-Za-z_]\w*)\s*(?://.*)?$", re.M)


def unity_defined_types(shaderlib):
    """{name: 'as float (HLSLSupport.cginc), min16float (...)'} for the object-like #defines in Unity's
    headers whose name is lowercase and whose replacement is a scalar, vector or matrix type name."""
    found = {}
    if not shaderlib or not os.path.isdir(shaderlib):
        return {}
    for path in sorted(glob.glob(os.path.join(shaderlib, "**", "*.*"), recursive=True)):
        if not path.endswith((".hlsl", ".cginc")):
            continue
        with open(path, encoding="utf-8", errors="replace") as f:
            for m in OBJECT_DEFINE.finditer(f.read()):
                name, repl = m.group(1), m.group(2)
                if TYPEISH.match(repl):
                    files = found.setdefault(name, {}).setdefault(repl, [])
                    if os.path.basename(path) not in files:
                        files.append(os.path.basename(path))
    return {name: ", ".join(f"{repl} ({', '.join(files)})" for repl, files in sorted(repls.items()))
            for name, repls in found.items()}


# ---------------------------------------------------------------------------------------------
# Tokens

class Tok:
    __slots__ = ("text", "file", "line")

    def __init__(self, text, file, line):
        self.text, self.file, self.line = text, file, line

    def __repr__(self):
        return f"{self.text}@{os.path.basename(self.file)}:{self.line}"


TOKEN = re.compile(r"""[A-Za-z_]\w*|(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?[A-Za-z]*|"(?:\\.|[^"\\])*"|
                       <<=|>>=|\+\+|--|&&|\|\||==|!=|<=|>=|<<|>>|::|[-+*/%&|^]=|[^\s\w]""", re.X)
LINE_DIRECTIVE = re.compile(r'^\s*#\s*line\s+(\d+)(?:\s+"([^"]*)")?')


def strip_comments(text):
    """Comments blanked, newlines kept (line numbers stay)."""
    def blank(m):
        return re.sub(r"[^\n]", " ", m.group(0))
    return re.sub(r'/\*.*?\*/|//[^\n]*|"(?:\\.|[^"\\\n])*"', lambda m: m.group(0) if m.group(0).startswith('"') else blank(m),
                  text, flags=re.S)


def tokenize(text, file):
    """Tokens of preprocessed (or plain) HLSL; #line sets file and line, other directives (and
    their continuation lines) are skipped."""
    out, line, continued = [], 1, False
    for raw in text.split("\n"):
        this = line
        line += 1
        if continued:
            continued = raw.rstrip().endswith("\\")
            continue
        s = raw.lstrip()
        if s.startswith("#"):
            m = LINE_DIRECTIVE.match(s)
            if m:
                line = int(m.group(1))
                if m.group(2) is not None:
                    file = m.group(2)
            continued = raw.rstrip().endswith("\\")
            continue
        for t in TOKEN.findall(raw):
            out.append(Tok(t, file, this))
    return out


def matching(toks, i):
    """Index of the bracket closing toks[i] ('(', '[', '{')."""
    pairs = {"(": ")", "[": "]", "{": "}"}
    open_, close = toks[i].text, pairs[toks[i].text]
    depth = 0
    for j in range(i, len(toks)):
        t = toks[j].text
        if t == open_:
            depth += 1
        elif t == close:
            depth -= 1
            if depth == 0:
                return j
    raise ValueError(f"unbalanced '{open_}' at {toks[i]!r}")


def split_top(toks, sep):
    """toks split at top-level (outside brackets) separators."""
    parts, cur, depth = [], [], 0
    for t in toks:
        if t.text in "([{":
            depth += 1
        elif t.text in ")]}":
            depth -= 1
        if depth == 0 and t.text == sep:
            parts.append(cur)
            cur = []
        else:
            cur.append(t)
    parts.append(cur)
    return parts


# ---------------------------------------------------------------------------------------------
# Top level: globals, structs, functions

RESOURCE = re.compile(r"^(?:RW|Rasterizer|Append|Consume)?(?:StructuredBuffer|ByteAddressBuffer|Buffer|Texture\w*|"
                      r"sampler\w*|SamplerState|SamplerComparisonState)$")
UAV = re.compile(r"^(?:RW\w+|AppendStructuredBuffer|ConsumeStructuredBuffer|RasterizerOrdered\w+)$")
MODIFIERS = {"static", "const", "uniform", "extern", "groupshared", "precise", "volatile", "shared", "row_major",
             "column_major", "inline", "export", "nointerpolation", "linear", "centroid", "noperspective", "sample",
             "in", "out", "inout", "snorm", "unorm", "point", "line", "triangle", "lineadj", "triangleadj"}


class Function:
    def __init__(self, name, params, body, attrs, tok):
        self.name, self.params, self.body, self.attrs, self.tok = name, params, body, attrs, tok


class Param:
    def __init__(self, name, type_, mods, semantic):
        self.name, self.type, self.mods, self.semantic = name, type_, mods, semantic


class Global:
    def __init__(self, name, type_, mods, dims):
        self.name, self.type, self.mods, self.dims = name, type_, mods, dims


class Program:
    """Functions (by name, overloads together), globals and struct members of a translation unit."""

    def __init__(self, toks):
        self.functions, self.globals, self.structs = {}, {}, {}
        self._parse(toks)

    def _declarators(self, toks):
        """Globals of one declaration statement (no trailing ';')."""
        toks = [t for t in toks]
        mods = []
        while toks and toks[0].text in MODIFIERS:
            mods.append(toks.pop(0).text)
        if not toks:
            return
        # The type: a name, possibly templated (<...>).
        type_ = toks[0].text
        i = 1
        if i < len(toks) and toks[i].text == "<":
            depth = 0
            while i < len(toks):
                depth += {"<": 1, ">": -1}.get(toks[i].text, 0)
                i += 1
                if depth == 0:
                    break
        for part in split_top(toks[i:], ","):
            if part and re.match(r"^[A-Za-z_]\w*$", part[0].text):
                self.globals[part[0].text] = Global(part[0].text, type_, mods, self._dims(part))

    def _parse(self, toks):
        i, item = 0, []
        while i < len(toks):
            t = toks[i]
            if t.text == ";":
                if item:
                    self._declarators(item)
                item = []
                i += 1
                continue
            if t.text != "{":
                item.append(t)
                i += 1
                continue
            end = matching(toks, i)
            head = [x.text for x in item]
            if head and head[0] in ("struct", "class", "interface") and len(head) >= 2:
                members = []
                for decl in split_top(toks[i + 1:end], ";"):
                    decl = [x for x in decl if x.text not in MODIFIERS]
                    if len(decl) >= 2:
                        members += [(decl[0].text, part[0].text, self._dims(part)) for part in split_top(decl[1:], ",") if part]
                self.structs[head[1]] = members
                item = []
                # Declarators may follow the struct body: skip to ';'.
                j = end + 1
                while j < len(toks) and toks[j].text != ";":
                    j += 1
                i = j + 1
                continue
            if head and head[0] in ("cbuffer", "tbuffer"):
                for decl in split_top(toks[i + 1:end], ";"):
                    if decl:
                        self._declarators(decl)
                item = []
                i = end + 1
                continue
            if head and head[0] == "namespace":
                self._parse(toks[i + 1:end])
                item = []
                i = end + 1
                continue
            if "=" in head:   # an initializer list: part of the declaration
                item.extend(toks[i:end + 1])
                i = end + 1
                continue
            self._function(item, toks[i + 1:end])
            item = []
            i = end + 1

    @staticmethod
    def _dims(part):
        dims, j = [], 1
        while j < len(part) and part[j].text == "[":
            k = matching(part, j)
            dims.append(part[j + 1:k])
            j = k + 1
        return dims

    def _function(self, head, body):
        attrs = []
        while head and head[0].text == "[":
            k = matching(head, 0)
            attrs.append(head[1:k])
            head = head[k + 1:]
        # The parameter list: the last top-level (...) of the head.
        close = max((j for j, t in enumerate(head) if t.text == ")"), default=None)
        if close is None:
            return
        depth, open_ = 0, None
        for j in range(close, -1, -1):
            depth += {")": 1, "(": -1}.get(head[j].text, 0)
            if depth == 0:
                open_ = j
                break
        if open_ is None or open_ == 0:
            return
        name = head[open_ - 1]
        params = []
        for p in split_top(head[open_ + 1:close], ","):
            p = [x for x in p]
            semantic = None
            for j, x in enumerate(p):
                if x.text == ":" and j + 1 < len(p):
                    semantic = p[j + 1].text
                    p = p[:j]
                    break
            p = split_top(p, "=")[0]
            mods = []
            while p and p[0].text in MODIFIERS:
                mods.append(p.pop(0).text)
            while p and p[-1].text == "]":
                depth = 0
                for j in range(len(p) - 1, -1, -1):
                    depth += {"]": 1, "[": -1}.get(p[j].text, 0)
                    if depth == 0:
                        p = p[:j]
                        break
            if len(p) >= 2:
                params.append(Param(p[-1].text, " ".join(x.text for x in p[:-1]), mods, semantic))
        self.functions.setdefault(name.text, []).append(
            Function(name.text, params, body, attrs, name))


# ---------------------------------------------------------------------------------------------
# Statements

class Stmt:
    def __init__(self, kind, tok, **kw):
        self.kind, self.tok = kind, tok
        self.__dict__.update(kw)


def parse_block(toks):
    out, i = [], 0
    while i < len(toks):
        s, i = parse_stmt(toks, i)
        if s is not None:
            out.append(s)
    return out


def parse_stmt(toks, i):
    attrs = []
    while i < len(toks) and toks[i].text == "[":
        k = matching(toks, i)
        attrs.append(" ".join(x.text for x in toks[i + 1:k]))
        i = k + 1
    if i >= len(toks):
        return None, i
    t = toks[i]
    w = t.text
    if w == ";":
        return None, i + 1
    if w == "{":
        k = matching(toks, i)
        return Stmt("block", t, body=parse_block(toks[i + 1:k])), k + 1
    if w in ("if", "while", "switch"):
        k = matching(toks, i + 1)
        cond = toks[i + 2:k]
        if w == "switch":
            e = matching(toks, k + 1)
            return Stmt("switch", t, cond=cond, body=parse_block(toks[k + 2:e])), e + 1
        body, j = parse_stmt(toks, k + 1)
        if w == "while":
            return Stmt("loop", t, init=[], cond=cond, step=[], body=[body] if body else [], attrs=attrs), j
        other = []
        if j < len(toks) and toks[j].text == "else":
            e, j = parse_stmt(toks, j + 1)
            other = [e] if e else []
        return Stmt("if", t, cond=cond, then=[body] if body else [], other=other), j
    if w == "for":
        k = matching(toks, i + 1)
        parts = split_top(toks[i + 2:k], ";")
        parts += [[]] * (3 - len(parts))
        body, j = parse_stmt(toks, k + 1)
        return Stmt("loop", t, init=parts[0], cond=parts[1], step=parts[2], body=[body] if body else [], attrs=attrs), j
    if w == "do":
        body, j = parse_stmt(toks, i + 1)
        k = matching(toks, j + 1)   # toks[j] is 'while'
        return Stmt("loop", t, init=[], cond=toks[j + 2:k], step=[], body=[body] if body else [], attrs=attrs,
                    do=True), k + 2
    if w in ("case", "default"):
        j = i
        depth = 0
        while toks[j].text != ":" or depth:
            depth += {"(": 1, ")": -1}.get(toks[j].text, 0)
            j += 1
        return Stmt("label", t), j + 1
    j, depth = i, 0
    while j < len(toks) and (toks[j].text != ";" or depth):
        depth += {"(": 1, "[": 1, "{": 1, ")": -1, "]": -1, "}": -1}.get(toks[j].text, 0)
        j += 1
    expr = toks[i:j]
    if w == "return":
        return Stmt("return", t, expr=expr[1:]), j + 1
    if w in ("break", "continue", "discard"):
        return Stmt(w, t), j + 1
    return Stmt("simple", t, expr=expr), j + 1


# ---------------------------------------------------------------------------------------------
# Flow analysis: which values are non-uniform across the group, which come from a UAV

class Taint:
    """Why a value is non-uniform (varying) and why it depends on a UAV read (uav): a reason or None."""
    __slots__ = ("varying", "uav")

    def __init__(self, varying=None, uav=None):
        self.varying, self.uav = varying, uav

    def __or__(self, other):
        return Taint(_direct(self.varying, other.varying), _direct(self.uav, other.uav))

    def key(self):
        return (self.varying is not None, self.uav is not None)

    def __bool__(self):
        return self.varying is not None or self.uav is not None


def _direct(a, b):
    """Of two reasons, the more direct one (fewer steps through conditions)."""
    if a is None or b is None:
        return a or b
    return min(a, b, key=lambda r: (r.count(" whose condition "), len(r)))


CLEAN = Taint()
BARRIERS = {"GroupMemoryBarrierWithGroupSync", "DeviceMemoryBarrierWithGroupSync", "AllMemoryBarrierWithGroupSync",
            "GroupMemoryBarrier", "DeviceMemoryBarrier", "AllMemoryBarrier"}
VARYING_SEMANTICS = {"SV_DISPATCHTHREADID", "SV_GROUPTHREADID", "SV_GROUPINDEX"}
ASSIGN = {"=", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "<<=", ">>="}


def where(tok):
    return f"{os.path.basename(tok.file)}:{tok.line}"


class Exits:
    """How a statement may leave its flow early, under which non-uniform condition."""
    __slots__ = ("ret", "brk")

    def __init__(self, ret=None, brk=None):
        self.ret, self.brk = ret, brk   # Taint (with a varying reason) or None

    def __or__(self, other):
        return Exits(self.ret or other.ret, self.brk or other.brk)


class FlowLint:
    """Taint analysis of a kernel: data dependence (assignments, calls, out arguments) and control
    dependence where control flow merges (a variable assigned under a condition takes the
    condition's taint after the branch or loop; a function's result takes its returns'
    conditions). `ctx` is the flow taint inside the current function; `self.outer` the flow
    taint of the call site (both decide whether a barrier is in varying flow)."""

    def __init__(self, program, report):
        self.p, self.report = program, report
        self.memo = {}
        self.outer = [CLEAN]
        self.written = []   # stack of sets: variables assigned inside the branch or loop being analysed
        self.groupshared_used = set()

    # -- expressions

    def expr(self, toks, env, ctx):
        """Taint of an expression; analyses the calls in it (their effects on out arguments included)."""
        taint = CLEAN
        i = 0
        while i < len(toks):
            t = toks[i]
            w = t.text
            nxt = toks[i + 1].text if i + 1 < len(toks) else None
            prev = toks[i - 1].text if i > 0 else None
            if not re.match(r"^[A-Za-z_]\w*$", w) or prev == ".":
                i += 1
                continue
            if nxt == "(":
                k = matching(toks, i + 1)
                args = split_top(toks[i + 2:k], ",") if k > i + 2 else []
                taint = taint | self.call(t, args, env, ctx)
                i = k + 1
                continue
            taint = taint | self.read(t, env)
            i += 1
        return taint

    def read(self, tok, env):
        w = tok.text
        if w in env:
            return env[w]
        g = self.p.globals.get(w)
        if g is None:
            return CLEAN
        if "groupshared" in g.mods:
            self.groupshared_used.add(w)
            return Taint(varying=f"a read of groupshared {w} at {where(tok)}")
        if RESOURCE.match(g.type):
            if UAV.match(g.type):
                why = f"a read of RW resource {w} at {where(tok)}"
                return Taint(varying=why, uav=why)
            return Taint(varying=f"a read of resource {w} at {where(tok)}")
        if "static" in g.mods and "const" not in g.mods:
            return Taint(varying=f"static variable {w} at {where(tok)}")
        return CLEAN

    def call(self, tok, args, env, ctx):
        name = tok.text
        arg_taints = [self.expr(a, env, ctx) for a in args]
        flow = ctx | self.outer[-1]
        if name in BARRIERS:
            if flow.varying:
                self.report("barrier-in-varying-flow", tok,
                            f"{name}() in varying flow control, under {flow.varying}: not every thread of the "
                            "group reaches it (FXC error X3663)")
            return CLEAN
        funcs = self.p.functions.get(name)
        if not funcs:
            # An intrinsic, a constructor or a method: its value follows its arguments (a method on
            # a resource reads it: expr read the base).
            out = CLEAN
            for a in arg_taints:
                out = out | a
            return out
        result = CLEAN
        for f in funcs:
            if len(f.params) < len(args):
                continue
            ret, outs = self.function(f, arg_taints, flow)
            result = result | ret
            for p, a in zip(f.params, args):
                if ("out" in p.mods or "inout" in p.mods) and a:
                    self.assign(a, outs.get(p.name, CLEAN), env)
        return result

    def function(self, f, arg_taints, outer):
        """(taint of the result, {out parameter: taint}) of f called with these argument taints
        from flow `outer`."""
        key = (id(f), tuple(a.key() for a in arg_taints), outer.key())
        if key in self.memo:
            return self.memo[key]
        self.memo[key] = (CLEAN, {})   # HLSL has no recursion; this guards a malformed input
        env = {}
        for p, a in zip(f.params, arg_taints + [CLEAN] * (len(f.params) - len(arg_taints))):
            if (p.semantic or "").upper() in VARYING_SEMANTICS:
                env[p.name] = Taint(varying=f"thread ID {p.name} ({p.semantic})")
            elif "out" in p.mods:
                env[p.name] = CLEAN
            else:
                env[p.name] = a
        state = {"ret": CLEAN}
        self.outer.append(outer)
        try:
            self.block(parse_block(f.body), env, CLEAN, state)
        finally:
            self.outer.pop()
        outs = {p.name: env.get(p.name, CLEAN) for p in f.params if "out" in p.mods or "inout" in p.mods}
        self.memo[key] = (state["ret"], outs)
        return self.memo[key]

    # -- assignments

    def assign(self, lhs, value, env):
        """lhs = value: the local written takes the value's taint (joined with what it held when only
        a part of it is written); a write into a resource or a groupshared variable changes no local."""
        root = next((t for t in lhs if re.match(r"^[A-Za-z_]\w*$", t.text)), None)
        if root is None:
            return
        w = root.text
        g = self.p.globals.get(w)
        if w not in env:
            if g is not None and "groupshared" in g.mods:
                self.groupshared_used.add(w)
            return
        partial = any(t.text in ("[", ".") for t in lhs[1:])
        env[w] = (env[w] | value) if partial else value
        for written in self.written:
            written.add(w)

    def simple(self, toks, env, ctx):
        """A declaration or an expression statement."""
        j = 0
        while j < len(toks) and toks[j].text in MODIFIERS:
            j += 1
        if (j + 1 < len(toks) and re.match(r"^[A-Za-z_]\w*$", toks[j].text) and toks[j].text not in self.p.functions
                and (re.match(r"^[A-Za-z_]\w*$", toks[j + 1].text) or toks[j + 1].text == "<")):
            # Declaration: [modifiers] Type name [dims] [= init] {, name [dims] [= init]}
            k = j + 1
            if toks[k].text == "<":
                depth = 0
                while k < len(toks):
                    depth += {"<": 1, ">": -1}.get(toks[k].text, 0)
                    k += 1
                    if depth == 0:
                        break
            for part in split_top(toks[k:], ","):
                if not part:
                    continue
                init = split_top(part, "=")
                value = self.expr(init[1], env, ctx) if len(init) > 1 else CLEAN
                env[part[0].text] = value | self.expr(init[0][1:], env, ctx)
            return
        depth, top = 0, []
        for k, t in enumerate(toks):
            if t.text in "([{":
                depth += 1
            elif t.text in ")]}":
                depth -= 1
            elif depth == 0 and t.text in ASSIGN:
                top.append(k)
        if not top:
            # Calls, increments.
            taint = self.expr(toks, env, ctx)
            for k, t in enumerate(toks):
                if t.text in ("++", "--"):
                    after = k + 1 < len(toks) and re.match(r"^[A-Za-z_]", toks[k + 1].text)
                    self.assign(toks[k + 1:k + 2] if after else toks[k - 1:k], taint, env)
            return
        # Assignments, right to left: a = b += c.
        value = self.expr(toks[top[-1] + 1:], env, ctx)
        bounds = [-1] + top
        for a, b in reversed(list(zip(bounds[:-1], bounds[1:]))):
            lhs = toks[a + 1:b]
            if toks[b].text != "=":
                value = value | self.expr(lhs, env, ctx)
            self.assign(lhs, value | self.index_taint(lhs, env, ctx), env)

    def index_taint(self, lhs, env, ctx):
        """Taint of the index expressions inside an assigned place (x[i].y: i)."""
        taint, k = CLEAN, 1
        while k < len(lhs):
            if lhs[k].text == "[":
                e = matching(lhs, k)
                taint = taint | self.expr(lhs[k + 1:e], env, ctx)
                k = e + 1
            else:
                k += 1
        return taint

    def merge(self, env, written, cond):
        """After a branch or loop: the variables it assigned that live on take its condition's taint."""
        for w in written:
            if w in env:
                env[w] = env[w] | cond
        if self.written:
            self.written[-1].update(written)

    # -- statements

    def block(self, stmts, env, ctx, state):
        """Analyses a statement list; returns the early exits it may take under varying flow."""
        exits = Exits()
        for s in stmts:
            # After an early exit taken by some threads only, the rest runs in varying flow.
            flow = ctx
            if exits.ret:
                flow = flow | exits.ret
            if exits.brk:
                flow = flow | exits.brk
            exits = exits | self.stmt(s, env, flow, state)
        return exits

    def stmt(self, s, env, ctx, state):
        k = s.kind
        if k == "block":
            return self.block(s.body, env, ctx, state)
        if k == "simple":
            self.simple(s.expr, env, ctx)
            return Exits()
        if k == "return":
            state["ret"] = state["ret"] | self.expr(s.expr, env, ctx) | ctx
            return Exits(ret=self.exit(s, ctx))
        if k in ("break", "continue", "discard"):
            e = self.exit(s, ctx)
            return Exits(ret=e) if k == "discard" else Exits(brk=e)
        if k == "label":
            return Exits()
        if k == "if":
            cond = self.condition(self.expr(s.cond, env, ctx), s.tok, "branch")
            env_then, env_else = dict(env), dict(env)
            self.written.append(set())
            e1 = self.block(s.then, env_then, ctx | cond, state)
            e2 = self.block(s.other, env_else, ctx | cond, state)
            written = self.written.pop()
            for name in env:
                env[name] = env_then.get(name, CLEAN) | env_else.get(name, CLEAN)
            self.merge(env, written, cond)
            return e1 | e2
        if k == "switch":
            cond = self.condition(self.expr(s.cond, env, ctx), s.tok, "switch")
            before = dict(env)
            self.written.append(set())
            e = self.block(s.body, env, ctx | cond, state)
            written = self.written.pop()
            for name in before:
                env[name] = env[name] | before[name]
            self.merge(env, written, cond)
            return Exits(ret=e.ret)   # a break leaves the switch only
        if k == "loop":
            return self.loop(s, env, ctx, state)
        return Exits()

    @staticmethod
    def exit(s, ctx):
        """The flow taint after an early exit taken under ctx (None when every thread takes it)."""
        if not ctx.varying:
            return None
        return Taint(varying=f"the {s.kind} at {where(s.tok)}, taken under {ctx.varying}",
                     uav=ctx.uav and f"the {s.kind} at {where(s.tok)}, taken under {ctx.uav}")

    @staticmethod
    def condition(cond, tok, what):
        """The flow taint a condition puts on what it controls."""
        if not cond:
            return CLEAN
        return Taint(varying=cond.varying and f"the {what} at {where(tok)}, whose condition depends on {cond.varying}",
                     uav=cond.uav and f"the {what} at {where(tok)}, whose condition depends on {cond.uav}")

    def loop(self, s, env, ctx, state):
        if s.init:
            self.simple(s.init, env, ctx)
        exits, flow, written = Exits(), ctx, set()
        for _ in range(6):   # until the taints stop growing
            before = ({n: t.key() for n, t in env.items()}, flow.key())
            cond = self.condition(self.expr(s.cond, env, flow) if s.cond else CLEAN, s.tok, "loop")
            self.written.append(written)
            e = self.block(s.body, env, flow | cond, state)
            if s.step:
                self.simple(s.step, env, flow | cond)
            self.written.pop()
            exits = exits | e
            if e.brk:
                # Some threads left the loop or skipped an iteration: every iteration diverges.
                flow = flow | e.brk
            self.merge(env, set(written), cond | (e.brk or CLEAN))
            if ({n: t.key() for n, t in env.items()}, flow.key()) == before:
                break
        # What ends the loop: its condition and the breaks taken under a condition.
        data = (self.expr(s.cond, env, flow) if s.cond else CLEAN) | Taint(uav=exits.brk.uav if exits.brk else None)
        allowed = any(a.split("(")[0].strip() == "allow_uav_condition" for a in s.attrs if a)
        if data.uav and not allowed:
            self.report("uav-loop-condition", s.tok,
                        f"loop whose end depends on {data.uav}, without [allow_uav_condition] "
                        "(FXC refuses such a loop in a compute shader)")
        if allowed and self.contains_barrier(s.body):
            self.report("uav-loop-condition", s.tok,
                        "[allow_uav_condition] loop contains a barrier (the attribute forbids synchronization intrinsics)")
        return Exits(ret=exits.ret)

    def contains_barrier(self, stmts, seen=None):
        seen = seen if seen is not None else set()
        toks = []

        def collect(ss):
            for s in ss:
                for attr in ("cond", "expr", "init", "step"):
                    toks.extend(getattr(s, attr, None) or [])
                for attr in ("body", "then", "other"):
                    collect(getattr(s, attr, None) or [])
        collect(stmts)
        for i, t in enumerate(toks):
            if t.text in BARRIERS:
                return True
            if i + 1 < len(toks) and toks[i + 1].text == "(" and t.text in self.p.functions and t.text not in seen:
                seen.add(t.text)
                if any(self.contains_barrier(parse_block(f.body), seen) for f in self.p.functions[t.text]):
                    return True
        return False


# ---------------------------------------------------------------------------------------------
# Rules on a kernel

SCALAR_BYTES = {"bool": 4, "int": 4, "uint": 4, "dword": 4, "float": 4, "half": 4, "min16float": 4, "min10float": 4,
                "min16int": 4, "min12int": 4, "min16uint": 4, "double": 8}


def eval_int(toks):
    expr = " ".join(t.text for t in toks)
    expr = re.sub(r"\b(\d+)[uUlL]+\b", r"\1", expr)
    if not re.fullmatch(r"[\d\s()+\-*/%<>&|^~]*", expr):
        return None
    try:
        return int(eval(expr.replace("/", "//"), {"__builtins__": {}}))
    except Exception:
        return None


def type_bytes(program, type_):
    if type_ in SCALAR_BYTES:
        return SCALAR_BYTES[type_]
    m = re.fullmatch(r"(bool|int|uint|float|half|double|min16float|min10float|min16int|min12int|min16uint)([1-4])(?:x([1-4]))?", type_)
    if m:
        return SCALAR_BYTES[m.group(1)] * int(m.group(2)) * int(m.group(3) or 1)
    if type_ in program.structs:
        total = 0
        for t, _, dims in program.structs[type_]:
            n = type_bytes(program, t)
            if n is None:
                return None
            for d in dims:
                v = eval_int(d)
                if v is None:
                    return None
                n *= v
            total += n
        return total
    return None


def lint_kernel(program, entry, report):
    """The flow rules and the groupshared size for compute kernel `entry`."""
    funcs = program.functions.get(entry)
    if not funcs:
        return
    f = funcs[0]
    flow = FlowLint(program, report)
    flow.function(f, [CLEAN] * len(f.params), CLEAN)
    total, parts = 0, []
    for name in sorted(flow.groupshared_used):
        g = program.globals[name]
        n = type_bytes(program, g.type)
        for d in g.dims:
            v = eval_int(d)
            n = None if (n is None or v is None) else n * v
        if n is None:
            continue
        total += n
        parts.append(f"{name} {n} B")
    if total > 32768:
        report("groupshared-limit", f.tok,
               f"{entry} uses {total} bytes of groupshared memory ({', '.join(parts)}); cs_5_0 allows 32768")


def lint_text(text, file, entry=None, report=None):
    """The kernel rules on preprocessed HLSL (nothing without an entry: the other stages have no
    barrier, and FXC's UAV loop rule is a compute shader's)."""
    if entry is not None:
        lint_kernel(Program(tokenize(text, file)), entry, report)


# ---------------------------------------------------------------------------------------------
# reserved-name, on source files

NOT_A_TYPE = {"return", "else", "case", "goto", "new", "delete", "typedef", "sizeof", "do", "throw", "in", "out", "inout",
              "uniform", "static", "const", "extern", "groupshared", "precise", "volatile", "shared", "inline", "export",
              "register", "packoffset", "row_major", "column_major", "nointerpolation", "linear", "centroid",
              "noperspective", "snorm", "unorm", "struct", "cbuffer", "tbuffer", "if", "for", "while", "switch", "break",
              "continue", "discard", "true", "false", "NULL", "define", "undef", "pragma", "include", "line", "point",
              "triangle", "lineadj", "triangleadj", "sample", "class", "interface", "namespace"}
NAME_FOLLOWERS = {";", "=", ",", ")", "[", ":", "("}


def lint_source_names(text, file, banned, report):
    """Declarations named with a banned word: `Type name` followed by ; = , ) [ : or ( (a function)."""
    toks = tokenize(strip_comments(text), file)
    for i in range(1, len(toks) - 1):
        name, prev, nxt = toks[i], toks[i - 1].text, toks[i + 1].text
        if name.text not in banned or nxt not in NAME_FOLLOWERS:
            continue
        if prev == ">":
            # A templated type (StructuredBuffer<float4> x): not a comparison.
            if nxt == "(":
                continue
        elif not re.match(r"^[A-Za-z_]\w*$", prev) or prev in NOT_A_TYPE:
            continue
        report("reserved-name", name, f"'{name.text}' names a declaration: {banned[name.text]}")


def banned_words(shaderlib):
    words = {w: "an HLSL keyword (Microsoft, HLSL Keywords)" for w in KEYWORDS}
    words.update({w: "an HLSL reserved word (Microsoft, HLSL Reserved Words)" for w in RESERVED})
    for name, why in unity_defined_types(shaderlib).items():
        words[name] = (words[name] + "; " if name in words else "") + "Unity's headers #define it as " + why
    return words


# ---------------------------------------------------------------------------------------------

def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("file")
    ap.add_argument("--entry", help="compute kernel: the flow and groupshared rules")
    ap.add_argument("--source", action="store_true", help="also the reserved-name rule on FILE itself")
    ap.add_argument("--shaderlib", default=None, help="Unity's shader libraries (for the names they #define)")
    args = ap.parse_args(argv)
    with open(args.file, encoding="utf-8") as f:
        text = f.read()
    findings = []

    def report(rule, tok, message):
        findings.append((rule, tok.file, tok.line, message))
    lint_text(text, args.file, args.entry, report)
    if args.source:
        lint_source_names(text, args.file, banned_words(args.shaderlib), report)
    for rule, file, line, message in sorted(set(findings)):
        print(f"lint {rule}: {file}:{line}: {message}")
    print(f"lint: {len(set(findings))} findings")
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
