#!/usr/bin/env python3
"""Cuts a one-off plan from a `gt bench --prepare` plan.tsv whose AdaptiveVsStatic was widened to
(16, 14, 12, 10 tiles at 0.6M) and (24, 20, 16 tiles at 2M): the cached terrain at each tile count
beside the fair static mesh, each behind 6 placement pads (harness --placement-pad, 0 to 5 x 160 KiB).
Cached jobs that dispatch every frame get --no-compute-timestamp (the static mesh has none).
usage: cut_plan.py PLAN.tsv OUT.tsv"""
import sys, re
rows = {l.split('\t')[0]: l.rstrip('\n').split('\t') for l in open(sys.argv[1]) if l.strip()}
bakes = ['fs_m32_f17:bake', 'fs_m32_f31:bake']
jobs = ['fs_m32_f17:static', 'fs_m32_f17:static-orbit']
for m in (16, 14, 12, 10):
    jobs += ['vc_m%d_s32x17:%s' % (m, k) for k in ('orbit', 'still', 'pan', 'terrain')]
jobs += ['fs_m32_f31:static', 'fs_m32_f31:static-orbit']
for m in (24, 20, 16):
    jobs += ['vc_m%d_s32x31:%s' % (m, k) for k in ('orbit', 'still', 'pan')]
pads = [k * 163840 for k in range(6)]
out = ['\t'.join(rows[b]) for b in bakes]
for pad in pads:
    for j in jobs:
        p = rows[j]
        a = re.sub(r'--dump-storage-prefix \S+', '', p[3])
        if j.startswith('vc_') and '--compute-once' not in a: a += ' --no-compute-timestamp'
        if pad: a += ' --placement-pad %d' % pad
        out.append('\t'.join([p[0] + '@pad%d' % pad, p[1], p[2], a]))
open(sys.argv[2], 'w').write('\n'.join(out) + '\n')
print(len(out), 'jobs')
