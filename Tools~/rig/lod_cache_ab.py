#!/usr/bin/env python3
"""A vertex cache for the Horizon levels, its draw cost measured before it is built (rig only, issue 38).

  lod_cache_ab.py prepare PLAN [ROUNDS]
      PLAN: a `gt bench --prepare` folder whose spirv/lodc holds Tools~/rig/bench_lod_cache.hlsl's
      domain stages (domain_cached.spv, domain_cached_blend.spv). Keeps the ground views
      (lod_t*_{still,walk,fly}) and the single-range cache's jobs at 0.6M and 8.1M triangles whose
      kernels evaluate every tile every frame (vc_*:terrain, the range moving; vc_*:still, drawing
      only) beside the same views through the domain stage and its floor (va_*:terrain, tess-floor),
      and per view runs, ROUNDS times interleaved (default 3):
        levels               today: the factor kernels every frame, every vertex through the domain stage
        levels-floor         the same vert and hull with bench_floor.hlsl's flat domain stage
        levels-cached        the same with a domain stage reading one 16-byte record a vertex
        levels-cached-blend  two records a vertex and the fading octaves blended at the vertex's pixel scale
        levels-cached-switch levels-cached behind a uniform branch beside the full domain stage (one variant, both paths)
        floor                the tessellator's floor at the levels' triangles (bench_run.sh floor-match)
      The stages, from the repository's root (F = the glslang options of bench.sh's floor_lod.spv):
        glslangValidator $F -S tese -e domain_cached -o PLAN/spirv/lodc/domain_cached.spv Tools~/rig/bench_lod_cache.hlsl
        (domain_cached_blend and domain_cached_switch likewise)
      Run: bash PLAN/bench_run.sh PLAN PLAN/gt-harness PLAN/spirv OUT --device NVIDIA
  lod_cache_ab.py report RESULTS
      Per view the medians over rounds: triangles, domain invocations, ms of each job and ratios to
      the floor; per cache job its compute ms and domain invocations.
"""
import os
import re
import shutil
import statistics
import sys

VIEWS = re.compile(r"^(lod_t\d+_(still|walk|fly)):(levels|levels-floor|floor)$")
# The single-range cache with both kernels every frame over every tile (terrain: the range moving) and
# drawing only (still), beside the same views through the domain stage and its floor (va_*).
SINGLE = re.compile(r"^(vc|va)_(m16_s32x17|m32_s32x63):(terrain|still|tess-floor)$")
LODC = "@SPV@/lodc/"
SLOTS_64 = 65 * 65 + 4 * 65   # VertexCacheSlotsPerTile(64)


def patches_of(args):
    return int(re.search(r"--patches (\d+)", args).group(1))


def cached(args, entry, uint4s):
    a = re.sub(r"--tese \S+", f"--tese {LODC}{entry}.spv", args)
    return re.sub(r"--storage 8:\d+", f"--storage 8:{16 * uint4s * SLOTS_64 * patches_of(args)}", a)


def prepare(plan, rounds):
    from lod_plain_ab import view_jobs   # beside this script; `report` runs without it
    rows, order = view_jobs(plan, VIEWS)
    single = []
    with open(os.path.join(plan, "plan.tsv")) as f:
        for line in f:
            parts = line.rstrip("\n").split("\t")
            if SINGLE.match(parts[0]):
                single.append(parts)
    out = []
    for r in range(1, rounds + 1):
        tag = "" if r == 1 else f"-r{r}"
        for view in order:
            lv = rows[view]["levels"]
            jobs = [("levels", lv[3]), ("levels-floor", rows[view]["levels-floor"][3]),
                    ("levels-cached", cached(lv[3], "domain_cached", 1)),
                    ("levels-cached-blend", cached(lv[3], "domain_cached_blend", 2)),
                    ("levels-cached-switch", cached(lv[3], "domain_cached_switch", 1))]
            for kind, args in jobs:
                out.append([f"{view}{tag}:{kind}", "run", "-", args])
            fm = rows[view]["floor"]
            out.append([f"{view}{tag}:floor", fm[1], f"{view}{tag}:levels", fm[3]])
        for s in single:
            out.append([s[0].replace(":", f"{tag}:", 1)] + s[1:])
    with open(os.path.join(plan, "plan.tsv"), "w") as f:
        for o in out:
            f.write("\t".join(o) + "\n")
    keep = set(order) | {"levels_floor"} | {re.search(r"@JOB@/([^/ ]+)", s[3]).group(1) for s in single if "@JOB@/" in s[3]}
    for d in os.listdir(os.path.join(plan, "jobs")):
        if d not in keep and os.path.isdir(os.path.join(plan, "jobs", d)):
            shutil.rmtree(os.path.join(plan, "jobs", d))
    print(f"lod_cache_ab: {len(out)} jobs, {len(order)} views and {len(single)} single-range jobs x {rounds} rounds")


def parse_results(results):
    """bench_run.sh's results.txt: {job id: {ms, cms, tris, hull, tese}} (those the job printed)."""
    keys = {("time", "frame_ms_median"): "ms", ("time", "compute_ms_median"): "cms",
            ("stat", "clipping_invocations"): "tris", ("stat", "tessellation_control_shader_patches"): "hull",
            ("stat", "tessellation_evaluation_shader_invocations"): "tese"}
    cur, vals = None, {}
    for line in open(results):
        if line.startswith("== "):
            cur = line.split()[1]
            continue
        w = line.split()
        key = keys.get((w[0], w[1])) if cur and len(w) == 3 else None
        if key:
            vals.setdefault(cur, {})[key] = float(w[2]) if key in ("ms", "cms") else int(w[2])
    return vals


def views_of(vals):
    """The ground views of parsed results (lod_t{metres}_{path}[-no_origin]), in run order; rounds (-rN) folded."""
    views = []
    for k in vals:
        m = re.match(r"^(lod_t\d+_[a-z]+(?:-no_origin)?)(-r\d+)?:(.*)$", k)
        if m and m.group(1) not in views:
            views.append(m.group(1))
    return views


KINDS = ["levels", "levels-floor", "levels-cached", "levels-cached-blend", "levels-cached-switch", "floor"]


def report(results):
    vals = parse_results(results)

    def med(pattern, key="ms"):
        xs = [d[key] for k, d in vals.items() if re.match(pattern, k) and key in d]
        return statistics.median(xs) if xs else float("nan")

    print("| ground view | triangles | domain invocations | levels ms | levels' floor ms | cached ms | cached-blend ms | cached-switch ms | floor ms | levels / floor | cached / floor | cached-blend / floor | cached-switch / floor | domain ns a vertex (levels - levels' floor) |")
    print("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
    for v in views_of(vals):
        p = lambda kind: rf"^{re.escape(v)}(-r\d+)?:{re.escape(kind)}$"
        ms = {k: med(p(k)) for k in KINDS}
        fl, tese = ms["floor"], med(p("levels"), "tese")
        print(f"| {v} | {med(p('levels'), 'tris'):,.0f} | {tese:,.0f} | {ms['levels']:.3f} | {ms['levels-floor']:.3f}"
              f" | {ms['levels-cached']:.3f} | {ms['levels-cached-blend']:.3f} | {ms['levels-cached-switch']:.3f} | {fl:.3f}"
              f" | {ms['levels'] / fl:.2f}x | {ms['levels-cached'] / fl:.2f}x | {ms['levels-cached-blend'] / fl:.2f}x"
              f" | {ms['levels-cached-switch'] / fl:.2f}x"
              f" | {(ms['levels'] - ms['levels-floor']) * 1e6 / tese:.2f} |")
    print()
    print("| single-range job | frame ms | compute ms | domain invocations | compute ns a drawn vertex |")
    print("| --- | ---: | ---: | ---: | ---: |")
    jobs = []
    for k in vals:
        j = re.sub(r"-r\d+:", ":", k)
        if re.match(r"^(vc_|fair_)", j) and j not in jobs:
            jobs.append(j)
    for j in jobs:
        p = rf"^{re.escape(j.split(':')[0])}(-r\d+)?:{re.escape(j.split(':')[1])}$"
        cms, tese = med(p, "cms"), med(p, "tese")
        print(f"| {j} | {med(p):.3f} | {cms:.4f} | {tese:,.0f} | {cms * 1e6 / tese:.3f} |")


if __name__ == "__main__":
    if len(sys.argv) >= 3 and sys.argv[1] == "prepare":
        prepare(sys.argv[2], int(sys.argv[3]) if len(sys.argv) > 3 else 3)
    elif len(sys.argv) == 3 and sys.argv[1] == "report":
        report(sys.argv[2])
    else:
        sys.exit(__doc__)
