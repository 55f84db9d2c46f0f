#!/usr/bin/env python3
"""`gt shaders`: compiles every stage of every keyword variant and checks the results.

For each variant of shader_variants.txt and each stage of STAGES (plus CACHE_STAGES, the vertex
cache's compute kernels, for GT_VERTEX_CACHE variants):
  1. glslangValidator, HLSL front end -> SPIR-V (Vulkan), registers mapped to the bindings of
     Tools~/rig/README.md ("Descriptor bindings"),
  2. spirv-val,
  3. the bindings, read back with spirv-cross --reflect, compared with EXPECTED_BINDINGS,
  4. spirv-cross -> GLSL 4.50, GLSL ES 3.20 and MSL 2.1,
  5. the two GLSL outputs compiled again by glslangValidator,
  6. Microsoft's DXC (../shared/dxc) on the same source, stage and keywords at HLSL 2018 (FXC's
     language), front end and SPIR-V code generation only (-fcgl -Vd: the language errors FXC and
     DXC share; the module is neither legalised nor kept). Target "dxc".
Step 1 is skipped when this build's shader cache (SHADER_CACHE) holds the SPIR-V of the same
glslang, options, stage, entry point and preprocessed text (every file the stage includes, as
glslang reads it): the many runs of one `gt test` (the full check, each GPU fixture's variants, the
bench's plan) compile each distinct stage once. Steps 2 to 6 run on every stage, cached or not.
Prints one line per variant and stage, then the counts. Exit status 1 on any error, and on any
diagnostic line that ALLOWED_OUTPUT does not explain.

Usage: shaders.py OUT_DIR [-j JOBS] [-I DIR]... [--only VARIANT]... [--dxc PATH] [--clean]
"""
import argparse, hashlib, json, os, re, shutil, subprocess, sys, tempfile, threading
from concurrent.futures import ThreadPoolExecutor

RIG_DIR = os.path.dirname(os.path.abspath(__file__))
PKG_DIR = os.path.dirname(os.path.dirname(RIG_DIR))
ENTRY_FILE = os.path.join(RIG_DIR, "TerrainRig.hlsl")
VARIANTS_FILE = os.path.join(RIG_DIR, "shader_variants.txt")
DXC = os.path.join(PKG_DIR, "..", "shared", "dxc", "bin", "dxc")
# The package's own .build, not GT_BUILD_DIR: fixtures compile into folders of their own and share it.
SHADER_CACHE = os.environ.get("GT_SHADER_CACHE") or os.path.join(PKG_DIR, ".build", "shader-cache")
import options  # noqa: E402  (the rig's range check, beside this file)

DXC_PROFILES = {"vert": "vs_6_0", "tesc": "hs_6_0", "tese": "ds_6_0", "frag": "ps_6_0", "comp": "cs_6_0"}

# (name, glslang stage, HLSL entry point). "fallback" is the no-tessellator vertex stage.
STAGES = [
    ("vert", "vert", "vert"),
    ("tesc", "tesc", "hull_shader"),
    ("tese", "tese", "domain_shader"),
    ("frag", "frag", "frag"),
    ("fallback", "vert", "vert_fallback"),
]
# The vertex cache's compute kernels (VertexCacheKernels.hlsl), compiled for GT_VERTEX_CACHE variants only.
CACHE_STAGES = [
    ("cache_factors", "comp", "CacheTileFactors"),
    ("cache_vertices", "comp", "CacheTileVertices"),
]


# Defines a stage gets whatever the variant, as GregoryTerrain.shader's passes have them: the
# no-tessellator pass defines GT_FALLBACK (it keeps the range origin's run-time branch, TerrainInputs.hlsl).
STAGE_DEFINES = {"fallback": ["-DGT_FALLBACK"]}
# The Horizon levels' factor kernels (LevelFactorKernels.hlsl) and vertex cache kernels
# (LevelVertexCacheKernels.hlsl), compiled for GT_LOD variants only.
LOD_STAGES = [
    ("lod_pieces", "comp", "LodFactorPieces"),
    ("lod_seams", "comp", "LodFactorSeams"),
    ("lod_slots", "comp", "LodVertexSlots"),
    ("lod_vertices", "comp", "LodCacheVertices"),
]


def stages_of(keywords):
    return STAGES + (CACHE_STAGES if "GT_VERTEX_CACHE" in keywords else []) + (LOD_STAGES if "GT_LOD" in keywords else [])

# HLSL register -> Vulkan binding (set 0): b0 -> 0, b1 -> 1 (no shift), t0..t2 -> 2..4 (+2),
# u0 -> 5 (+5), t4 -> 6 (+2; GT_SNOW's _SnowDepth), t5/u2 -> 7 and t6/u3 -> 8 (GT_VERTEX_CACHE; GT_LOD's too), t7 -> 9 (GT_NOISE_TABLE's _NoiseCells), u5 -> 10 (the cache kernels' _TileCellsRW). glslang applies the shift of each register class
# with --hlsl-iomap.
REGISTER_SHIFTS = ["--shift-cbuffer-binding", "0", "--shift-texture-binding", "2",
                   "--shift-UAV-binding", "5"]
EXPECTED_BINDINGS = {
    "TerrainParams": 0, "RigCamera": 1,
    "_ControlPoints": 2, "_Regions": 3, "_GridLines": 4, "_Readback": 5,
    "_SnowDepth": 6,
    "_TileFactors": 7, "_TileFactorsRW": 7, "_VertexCache": 8, "_VertexCacheRW": 8,
    "_LodFactors": 7, "_LodFactorsRW": 7,
    "_NoiseCells": 9, "_TileCellsRW": 10,
}
TERRAIN_PARAMS_BYTES = 176   # 11 float4
SNOW_PARAMS_BYTES = 16       # GT_SNOW appends _SnowMapSize to TerrainParams
LOD_PARAMS_BYTES = 16 + 20 * 16   # GT_LOD appends _LodLevels and _Ranges[GT_MAX_LOD_LEVELS = 20]
RIG_CAMERA_BYTES = 176       # 2 float4x4 + 3 float4

# Diagnostics that are known and harmless. Each entry: (regex over one output line, why).
# Anything else a tool prints counts as a warning and fails the variant.
ALLOWED_OUTPUT = [
    # glslangValidator echoes the name of each file it compiles.
    (r"^\S+\.(hlsl|vert|tesc|tese|frag)$", "glslang prints the input file name"),
]

# GLSL ES: tessellation is core in ES 3.20, so no GL_EXT_tessellation_shader is needed there; the
# ES outputs recompile with glslang as they are.
# MSL: all five stages convert (also without options); the version is pinned to 2.1 so the output
# does not change with spirv-cross's default. spirv-cross turns tesc into a compute kernel; the
# vertex stage that feeds it must write its outputs to a buffer (--msl-capture-output), as Metal's
# tessellation pipeline reads them there.
# The Metal output is generated and checked for spirv-cross errors only: no Metal compiler here.
MSL_OPTIONS = ["--msl", "--msl-version", "20100"]
MSL_STAGE_OPTIONS = {"vert": ["--msl-capture-output"]}


def read_variants(path=VARIANTS_FILE):
    variants = []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if not line:
                continue
            keywords = [] if line == "-" else line.split()
            # GT_NOISE GT_READBACK -> "noise+readback": short, and a valid folder name.
            name = "+".join(k[3:].lower() if k.startswith("GT_") else k.lower() for k in keywords)
            variants.append((name or "base", keywords))
    names = [n for n, _ in variants]
    if len(set(names)) != len(names):
        sys.exit(f"shaders: duplicate variant in {path}")
    return variants


def run(cmd, log):
    """Runs cmd; returns (ok, unexplained diagnostic lines). Appends everything to log."""
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    log.append("$ " + " ".join(cmd) + "\n" + p.stdout)
    bad = [l for l in p.stdout.splitlines()
           if l.strip() and not any(re.search(rx, l.strip()) for rx, _ in ALLOWED_OUTPUT)]
    return p.returncode == 0, bad


def check_bindings(spv, log, keywords=()):
    """Every resource must sit in set 0 at the binding of Tools~/rig/README.md, "Descriptor bindings (Vulkan rig) and registers"."""
    params_bytes = TERRAIN_PARAMS_BYTES + (SNOW_PARAMS_BYTES if "GT_SNOW" in keywords else 0) + (LOD_PARAMS_BYTES if "GT_LOD" in keywords else 0)
    p = subprocess.run(["spirv-cross", spv, "--reflect"], stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, text=True)
    if p.returncode != 0:
        return [f"spirv-cross --reflect failed: {p.stderr.strip()}"]
    refl = json.loads(p.stdout)
    errors = []
    for kind in ("ubos", "ssbos", "textures", "separate_images", "separate_samplers", "images"):
        for r in refl.get(kind, []):
            name, binding, dset = r.get("name"), r.get("binding"), r.get("set")
            want = EXPECTED_BINDINGS.get(name)
            if want is None:
                errors.append(f"{kind} '{name}' is not in the binding table")
            elif binding != want or dset != 0:
                errors.append(f"'{name}' at set {dset} binding {binding}, expected set 0 binding {want}")
            size = r.get("block_size")
            if name == "TerrainParams" and size != params_bytes:
                errors.append(f"TerrainParams is {size} bytes, expected {params_bytes}")
            if name == "RigCamera" and size != RIG_CAMERA_BYTES:
                errors.append(f"RigCamera is {size} bytes, expected {RIG_CAMERA_BYTES}")
    log.append("bindings: " + json.dumps({k: [(r["name"], r.get("binding")) for r in v]
                                          for k, v in refl.items() if k in ("ubos", "ssbos")}))
    return errors


class SpirvCache:
    """glslang's SPIR-V by sha256 of (glslang's version, the command without its output path, the
    stage's preprocessed text). A changed include, define or option is another key: a miss."""
    def __init__(self, folder):
        self.folder, self.lock, self.hits, self.misses = folder, threading.Lock(), 0, 0
        self.version = subprocess.run(["glslangValidator", "--version"], capture_output=True, text=True).stdout

    def key(self, cmd):
        """None when glslang cannot preprocess the stage (the compile itself reports why)."""
        i = cmd.index("-o")
        options = cmd[:i] + cmd[i + 2:]
        stage, entry = cmd[cmd.index("-S") + 1], cmd[cmd.index("-e") + 1]
        pre = (["glslangValidator", "-D", "-E", "-S", stage, "-e", entry]
               + [a for a in options if a.startswith(("-I", "-D")) and len(a) > 2] + [options[-1]])
        p = subprocess.run(pre, capture_output=True, text=True)
        if p.returncode != 0:
            return None
        return hashlib.sha256("\0".join([self.version] + options + [p.stdout]).encode()).hexdigest()

    def fetch(self, key, spv):
        path = os.path.join(self.folder, key + ".spv")
        found = key is not None and os.path.isfile(path)
        if found:
            shutil.copyfile(path, spv)
        with self.lock:
            self.hits += found
            self.misses += not found
        return found

    def store(self, key, spv):
        if key is None:
            return
        os.makedirs(self.folder, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=self.folder, suffix=".tmp")
        os.close(fd)
        shutil.copyfile(spv, tmp)
        os.replace(tmp, os.path.join(self.folder, key + ".spv"))   # atomic: parallel runs share the folder


def compile_one(out_dir, variant, stage, includes, dxc=DXC, spirv_only=False, cache=None):
    name, keywords = variant
    sname, gstage, entry = stage
    vdir = os.path.join(out_dir, name)
    spv = os.path.join(vdir, sname + ".spv")
    log, problems, targets = [], [], []

    def step(label, cmd):
        ok, bad = run(cmd, log)
        if not ok:
            problems.append(f"{label} failed")
        problems.extend(f"{label}: {l}" for l in bad)
        return ok and not bad

    def step_cached(label, cmd, spv):
        key = cache.key(cmd) if cache else None
        if cache and cache.fetch(key, spv):
            log.append(f"{label}: {spv} from the shader cache ({key})")
            return True
        ok = step(label, cmd)
        if ok and cache:
            cache.store(key, spv)
        return ok

    cmd = (["glslangValidator", "-D", "-V", "-S", gstage, "-e", entry, "--hlsl-iomap"]
           + REGISTER_SHIFTS + [f"-I{d}" for d in includes]
           + [f"-D{k}" for k in keywords] + STAGE_DEFINES.get(sname, []) + ["-o", spv, ENTRY_FILE])
    if step_cached("glslang", cmd, spv) and step("spirv-val", ["spirv-val", spv]):
        targets.append("spirv")
        problems.extend(check_bindings(spv, log, keywords))
    if "spirv" in targets and not spirv_only:
        glsl = os.path.join(vdir, f"{sname}.450.{gstage}")
        essl = os.path.join(vdir, f"{sname}.es320.{gstage}")
        msl = os.path.join(vdir, f"{sname}.metal")
        if (step("spirv-cross glsl450", ["spirv-cross", spv, "--entry", entry, "--no-es",
                                         "--version", "450", "--output", glsl])
                and step("glslang glsl450", ["glslangValidator", "-S", gstage, glsl])):
            targets.append("glsl450")
        if (step("spirv-cross essl320", ["spirv-cross", spv, "--entry", entry, "--es",
                                         "--version", "320", "--output", essl])
                and step("glslang essl320", ["glslangValidator", "-S", gstage, essl])):
            targets.append("essl320")
        if step("spirv-cross msl", ["spirv-cross", spv, "--entry", entry] + MSL_OPTIONS
                + MSL_STAGE_OPTIONS.get(sname, []) + ["--output", msl]):
            targets.append("msl21")
    if not spirv_only and step("dxc", [dxc, "-HV", "2018", "-spirv", "-fcgl", "-Vd", "-T", DXC_PROFILES[gstage], "-E", entry, "-Fo", os.devnull]
            + [f"-I{d}" for d in includes] + [f"-D{k}" for k in keywords] + STAGE_DEFINES.get(sname, []) + [ENTRY_FILE]):
        targets.append("dxc")
    with open(os.path.join(vdir, sname + ".log"), "w") as f:
        f.write("\n".join(log))
    return name, sname, problems, targets


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out_dir")
    options.add_number(ap, "-j", "--jobs", range="jobs", default=min(os.cpu_count() or 1, 256))
    ap.add_argument("-I", dest="includes", action="append", default=[],
                    help="extra include directory (searched after the includer's own folder)")
    ap.add_argument("--only", action="append", default=[], help="compile only this variant")
    ap.add_argument("--dxc", default=DXC, help="Microsoft's DXC (default: ../shared/dxc/bin/dxc beside the package)")
    ap.add_argument("--clean", action="store_true", help="empty OUT_DIR first (once the options are checked)")
    ap.add_argument("--no-cache", action="store_true", help="compile every stage with glslang, ignoring the shader cache")
    ap.add_argument("--spirv-only", action="store_true",
                    help="SPIR-V, spirv-val and the binding check only (what a GPU test draws); no cross-compiles, no DXC")
    args = ap.parse_args()
    if args.clean:
        shutil.rmtree(args.out_dir, ignore_errors=True)
    if not os.access(args.dxc, os.X_OK):
        sys.exit(f"shaders: --dxc {args.dxc}: no DXC there (it sits beside the package as ../shared/dxc, see its README)")

    variants = read_variants()
    if args.only:
        unknown = set(args.only) - {n for n, _ in variants}
        if unknown:
            sys.exit(f"shaders: unknown variant(s) {sorted(unknown)}")
        variants = [v for v in variants if v[0] in args.only]
    for name, _ in variants:
        os.makedirs(os.path.join(args.out_dir, name), exist_ok=True)

    jobs = [(v, s) for v in variants for s in stages_of(v[1])]
    cache = None if args.no_cache else SpirvCache(SHADER_CACHE)
    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        results = list(pool.map(lambda j: compile_one(args.out_dir, j[0], j[1], args.includes, args.dxc, args.spirv_only, cache), jobs))

    failed = 0
    for name, sname, problems, targets in results:
        status = "FAIL" if problems else "PASS"
        failed += bool(problems)
        print(f"{status} {name:<38} {sname:<8} {' '.join(targets)}")
        for p in problems:
            print(f"     {p}")
        if problems:
            print(f"     log: {os.path.join(args.out_dir, name, sname + '.log')}")
    print(f"variants: {len(variants)}, stages: {len(STAGES)} (+{len(CACHE_STAGES)} with GT_VERTEX_CACHE), "
          f"compiled: {len(results)}, passed: {len(results) - failed}, failed: {failed}")
    if cache:
        print(f"shader cache: {cache.hits} stages reused, {cache.misses} compiled by glslang ({SHADER_CACHE})")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
