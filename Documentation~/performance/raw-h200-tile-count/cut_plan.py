#!/usr/bin/env python3
"""Cuts a one-off plan from a `gt bench --prepare` plan.tsv whose AdaptiveVsStatic (and, for a
static size the full plan lacks, FairSizes) was widened for the run: per static size, the fair
static mesh (still and on the camera path) and the cached terrain at each tile count with the camera
moving, still, panning over anchored tiles and with the range moving (the last at 0.6M/0.5M only),
each behind 6 placement pads (harness --placement-pad, 0 to 5 x 160 KiB). Cached jobs that dispatch
every frame get --no-compute-timestamp (the static mesh has none).
usage: cut_plan.py PLAN.tsv OUT.tsv [F:M,M,...[;F:M,...]]
  default 17:16,14,12,10;31:24,20,16 (this folder); ../raw-h200-tile-count-0.5m/: 16:16,12,10,9"""
import sys, os, importlib.util
# The pad loop of ../raw-h200-placement/cut_plan.py (behind_pads), loaded from its file.
_spec = importlib.util.spec_from_file_location('placement', os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'raw-h200-placement', 'cut_plan.py'))
placement = importlib.util.module_from_spec(_spec); _spec.loader.exec_module(placement)
rows = {l.split('\t')[0]: l.rstrip('\n').split('\t') for l in open(sys.argv[1]) if l.strip()}
spec = sys.argv[3] if len(sys.argv) > 3 else '17:16,14,12,10;31:24,20,16'
bakes, jobs = [], []
for group in spec.split(';'):
    f, tiles = group.split(':')
    bakes.append('fs_m32_f%s:bake' % f)
    jobs += ['fs_m32_f%s:static' % f, 'fs_m32_f%s:static-orbit' % f]
    kinds = ('orbit', 'still', 'pan', 'terrain') if int(f) < 20 else ('orbit', 'still', 'pan')
    for m in tiles.split(','):
        jobs += ['vc_m%s_s32x%s:%s' % (m, f, k) for k in kinds]
out = placement.behind_pads(rows, bakes, jobs, [k * 163840 for k in range(6)])
open(sys.argv[2], 'w').write('\n'.join(out) + '\n')
print(len(out), 'jobs')
