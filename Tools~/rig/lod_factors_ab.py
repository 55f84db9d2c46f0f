#!/usr/bin/env python3
"""Where the Horizon levels' vert + hull time goes, side by side in one run (rig only, issue 38).

  lod_factors_ab.py prepare PLAN [ROUNDS]
      PLAN: a `gt bench --prepare` folder whose spirv/lodf holds Tools~/rig/bench_lod_factors.hlsl's
      stages (lod_pieces, lod_seams, vert_light, vert_buffered, hull_buffered; see that file). Keeps
      the ground views (lod_t*_{still,walk,fly}, and the still views without a range origin) and per
      view runs, ROUNDS times interleaved (default 2):
        levels              today: factors in the hull stage, every vertex through the domain stage
        levels-cf           the factors from two compute kernels every frame, the hull reads them
                            (vert_light: the domain stage reads no corner)
        levels-cf-vert      the same with today's vert (each corner evaluated, walking to the origin)
        levels-floor        today's hull with bench_floor.hlsl's flat domain stage
        levels-floor-cf     the kernels every frame, the hull reads the factors, the flat domain
        levels-floor-const  the same, the kernels in the first frame only (--compute-once): the
                            hull and vert reading constants, what the L x M^2 patches cost alone
        floor               the tessellator's floor at the levels' triangles (bench_run.sh floor-match)
      The stages, from the repository's root (F = the glslang options of bench.sh's floor_lod.spv):
        glslangValidator $F -S comp -e lod_pieces -DLOD_KERNELS -o PLAN/spirv/lodf/lod_pieces.spv Tools~/rig/bench_lod_factors.hlsl
        (lod_seams likewise; vert_light, vert_buffered: -S vert; hull_buffered: -S tesc; no -DLOD_KERNELS)
      Run: bash PLAN/bench_run.sh PLAN PLAN/gt-harness PLAN/spirv OUT --device NVIDIA
  lod_factors_ab.py report RESULTS
      Per view the medians over rounds: triangles and hull invocations, ms of each job, the kernels'
      ms, and the ratios to the floor.
"""
import os
import re
import shutil
import statistics
import sys

VIEWS = re.compile(r"^(lod_t\d+_(still|walk|fly)(-no_origin)?):(levels|levels-floor|floor)$")
LODF = "@SPV@/lodf/"


def patches_of(args):
    return int(re.search(r"--patches (\d+)", args).group(1))


def with_kernels(args, vert, tese, once):
    p = patches_of(args)
    a = args if vert is None else re.sub(r"--vert \S+", f"--vert {LODF}{vert}.spv", args)
    a = re.sub(r"--tesc \S+", f"--tesc {LODF}hull_buffered.spv", a)
    a = re.sub(r"--tese \S+", f"--tese {tese}", a)
    a += (f" --storage 7:{32 * p} --storage 8:{32 * p} --storage 9:{64 * p}"
          f" --compute {LODF}lod_pieces.spv:{p} --compute {LODF}lod_seams.spv:{(p + 63) // 64}")
    return a + (" --compute-once" if once else "")


def prepare(plan, rounds):
    from lod_plain_ab import view_jobs   # beside this script; `report` runs without it
    rows, order = view_jobs(plan, VIEWS)
    out = []
    for r in range(1, rounds + 1):
        tag = "" if r == 1 else f"-r{r}"
        for view in order:
            lv = rows[view]["levels"]
            lod_tese = re.search(r"--tese (\S+)", lv[3]).group(1)
            floor_tese = "@SPV@/floor_lod.spv"
            floor_args = lv[3].replace(f"--tese {lod_tese}", f"--tese {floor_tese}")
            jobs = [("levels", lv[3]),
                    ("levels-cf", with_kernels(lv[3], "vert_light", lod_tese, False)),
                    ("levels-cf-vert", with_kernels(lv[3], None, lod_tese, False)),
                    ("levels-floor", floor_args),
                    ("levels-floor-cf", with_kernels(lv[3], "vert_buffered", floor_tese, False)),
                    ("levels-floor-const", with_kernels(lv[3], "vert_buffered", floor_tese, True))]
            for kind, args in jobs:
                out.append([f"{view}{tag}:{kind}", "run", "-", args])
            if "floor" in rows[view]:
                fm = rows[view]["floor"]
                out.append([f"{view}{tag}:floor", fm[1], f"{view}{tag}:levels", fm[3]])
    with open(os.path.join(plan, "plan.tsv"), "w") as f:
        for o in out:
            f.write("\t".join(o) + "\n")
    keep = set(order) | {"levels_floor"}
    for d in os.listdir(os.path.join(plan, "jobs")):
        if d not in keep and os.path.isdir(os.path.join(plan, "jobs", d)):
            shutil.rmtree(os.path.join(plan, "jobs", d))
    print(f"lod_factors_ab: {len(out)} jobs, {len(order)} views x {rounds} rounds")


KINDS = ["levels", "levels-cf", "levels-cf-vert", "levels-floor", "levels-floor-cf", "levels-floor-const", "floor"]


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


def report(results):
    vals = parse_results(results)
    views = views_of(vals)

    def med(v, kind, key="ms"):
        xs = [d[key] for k, d in vals.items() if re.match(rf"^{re.escape(v)}(-r\d+)?:{kind}$", k) and key in d]
        return statistics.median(xs) if xs else float("nan")

    print("| ground view | triangles today / cf | domain invocations today / cf | hull invocations | levels ms | levels-cf ms (kernels) | levels-cf-vert ms | levels' floor ms | floor-cf ms | floor-const ms | floor ms | levels / floor | levels-cf / floor | cf / today |")
    print("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
    for v in views:
        ms = {k: med(v, k) for k in KINDS}
        fl = ms["floor"]
        print(f"| {v} | {med(v, 'levels', 'tris'):,.0f} / {med(v, 'levels-cf', 'tris'):,.0f}"
              f" | {med(v, 'levels', 'tese'):,.0f} / {med(v, 'levels-cf', 'tese'):,.0f} | {med(v, 'levels', 'hull'):,.0f}"
              f" | {ms['levels']:.2f} | {ms['levels-cf']:.2f} ({med(v, 'levels-cf', 'cms'):.2f}) | {ms['levels-cf-vert']:.2f} | {ms['levels-floor']:.2f}"
              f" | {ms['levels-floor-cf']:.2f} | {ms['levels-floor-const']:.2f} | {fl:.2f}"
              f" | {ms['levels'] / fl:.2f}x | {ms['levels-cf'] / fl:.2f}x | {ms['levels-cf'] / ms['levels']:.3f}x |")


if __name__ == "__main__":
    if len(sys.argv) >= 3 and sys.argv[1] == "prepare":
        prepare(sys.argv[2], int(sys.argv[3]) if len(sys.argv) > 3 else 2)
    elif len(sys.argv) == 3 and sys.argv[1] == "report":
        report(sys.argv[2])
    else:
        sys.exit(__doc__)
