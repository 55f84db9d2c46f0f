#!/usr/bin/env python3
"""The levels' plain path against the precise path alone, side by side in one run (rig only).

  lod_plain_ab.py prepare PLAN BEFORE_SPV [ROUNDS]
      PLAN: a `gt bench --prepare` folder. Keeps the ground views' jobs (lod_t*_{still,walk,fly}: levels,
      levels' floor, floor) and adds per view a `levels-before` job: the same buffers, cameras and levels
      drawn with BEFORE_SPV (the lod+noise+height_color stages of the commit before the plain path, whose
      TerrainParams block is one float4 shorter: the job's params.f32 carries _LodLevels in its last
      float4 and its tails lose their first). ROUNDS (default 2) repeats the jobs, interleaved.
  lod_plain_ab.py report RESULTS
      Per view the medians over rounds: triangles, ms of the route, of the precise path, of the levels'
      floor and the floor, and the ratios.
"""
import os
import re
import shutil
import statistics
import struct
import sys

VIEWS = re.compile(r"^(lod_t\d+_(still|walk|fly)):(levels|levels-floor|floor)$")
OLD_PARAMS = 160   # TerrainParams before _OriginSurface


def view_jobs(plan, views):
    """The plan's jobs whose id `views` matches (group 1 the view, the last group the job's kind):
    {view: {kind: the plan.tsv fields}}, and the views in plan order."""
    rows, order = {}, []
    with open(os.path.join(plan, "plan.tsv")) as f:
        for line in f:
            parts = line.rstrip("\n").split("\t")
            m = views.match(parts[0])
            if not m:
                continue
            view, kind = m.group(1), m.group(m.lastindex)
            if view not in rows:
                rows[view] = {}
                order.append(view)
            rows[view][kind] = parts
    return rows, order


def prepare(plan, before_spv, rounds):
    spv_before = os.path.join(plan, "spirv", "before")
    shutil.rmtree(spv_before, ignore_errors=True)
    shutil.copytree(before_spv, spv_before)
    rows, order = view_jobs(plan, VIEWS)
    out = []
    for r in range(1, rounds + 1):
        for view in order:
            jobs = os.path.join(plan, "jobs")
            before = view + "-before"
            if r == 1:
                old_layout(os.path.join(jobs, view), os.path.join(jobs, before))
            tag = "" if r == 1 else f"-r{r}"
            lv = rows[view]["levels"]
            out.append([f"{view}{tag}:levels"] + lv[1:])
            args = lv[3].replace("@SPV@/lod+noise+height_color/", "@SPV@/before/").replace(f"@JOB@/{view}/", f"@JOB@/{before}/")
            args = args.replace(f"@JOB@/{view} ", f"@JOB@/{before} ")
            out.append([f"{view}{tag}:levels-before", "run", "-", args])
            fl = rows[view]["levels-floor"]
            out.append([f"{view}{tag}:levels-floor"] + fl[1:])
            fm = rows[view]["floor"]
            out.append([f"{view}{tag}:floor", fm[1], f"{view}{tag}:levels", fm[3]])
    with open(os.path.join(plan, "plan.tsv"), "w") as f:
        for o in out:
            f.write("\t".join(o) + "\n")
    # Only the jobs kept travel.
    keep = set(order) | {v + "-before" for v in order} | {"levels_floor"}
    for d in os.listdir(os.path.join(plan, "jobs")):
        if d not in keep and os.path.isdir(os.path.join(plan, "jobs", d)):
            shutil.rmtree(os.path.join(plan, "jobs", d))
    print(f"lod_plain_ab: {len(out)} jobs, {len(order)} views x {rounds} rounds")


def old_layout(src, dst):
    """A copy of job src for the stages before _OriginSurface: _LodLevels moved into params.f32's last float4."""
    shutil.rmtree(dst, ignore_errors=True)
    os.makedirs(dst)
    for name in os.listdir(src):
        if name not in ("params.f32", "lod_tail.f32", "lod_tail_path.f32"):
            os.symlink(os.path.join("..", os.path.basename(src), name), os.path.join(dst, name))
    params = open(os.path.join(src, "params.f32"), "rb").read()
    tail = open(os.path.join(src, "lod_tail.f32"), "rb").read()
    assert len(params) == OLD_PARAMS + 16, len(params)
    with open(os.path.join(dst, "params.f32"), "wb") as f:
        f.write(params[:OLD_PARAMS] + tail[:16])
    with open(os.path.join(dst, "lod_tail.f32"), "wb") as f:
        f.write(tail[16:])
    path = os.path.join(src, "lod_tail_path.f32")
    if os.path.exists(path):
        data = open(path, "rb").read()
        n = len(tail)
        with open(os.path.join(dst, "lod_tail_path.f32"), "wb") as f:
            for k in range(0, len(data), n):
                rec = data[k:k + n]
                assert rec[:16] == tail[:16], "the level count changed along the path"
                f.write(rec[16:])


def report(results):
    cur = None
    vals = {}
    for line in open(results):
        if line.startswith("== "):
            cur = line.split()[1]
            continue
        w = line.split()
        if cur and len(w) == 3 and w[0] == "time" and w[1] == "frame_ms_median":
            vals.setdefault(cur, {})["ms"] = float(w[2])
        if cur and len(w) == 3 and w[0] == "stat" and w[1] == "clipping_invocations":
            vals.setdefault(cur, {})["tris"] = int(w[2])
    views = []
    for k in vals:
        m = re.match(r"^(lod_t\d+_\w+?)(-r\d+)?:(.*)$", k)
        if m and m.group(1) not in views:
            views.append(m.group(1))
    print("| ground view | triangles | plain path ms | precise only ms | levels' floor ms | floor ms | plain / floor | precise / floor | plain / precise |")
    print("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
    for v in views:
        def med(kind, key="ms"):
            xs = [d[key] for k, d in vals.items() if re.match(rf"^{re.escape(v)}(-r\d+)?:{kind}$", k) and key in d]
            return statistics.median(xs) if xs else float("nan")
        lv, bf, lf, fl = med("levels"), med("levels-before"), med("levels-floor"), med("floor")
        t, tb = med("levels", "tris"), med("levels-before", "tris")
        print(f"| {v} | {t:,.0f} ({tb:,.0f}) | {lv:.2f} | {bf:.2f} | {lf:.2f} | {fl:.2f} | {lv / fl:.2f}x | {bf / fl:.2f}x | {lv / bf:.3f}x |")


if __name__ == "__main__":
    if len(sys.argv) >= 4 and sys.argv[1] == "prepare":
        prepare(sys.argv[2], sys.argv[3], int(sys.argv[4]) if len(sys.argv) > 4 else 2)
    elif len(sys.argv) == 3 and sys.argv[1] == "report":
        report(sys.argv[2])
    else:
        sys.exit(__doc__)
