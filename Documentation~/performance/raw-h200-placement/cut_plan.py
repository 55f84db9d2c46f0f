#!/usr/bin/env python3
"""Cuts this folder's plan from a `gt bench --prepare` plan.tsv (commit 100a68a): the goal's jobs,
each behind 8 placement pads (harness --placement-pad, 0 to 7 x 160 KiB), one pad after the other.
The cached jobs that dispatch every frame get --no-compute-timestamp (the static mesh has no
timestamp between a pre-pass and its draw either).
usage: cut_plan.py PLAN.tsv OUT.tsv"""
import sys, re
bakes = ['fs_m32_f17:bake', 'fs_m32_f31:bake', 'fs_m32_f63:bake']
jobs = ['fs_m32_f17:static', 'fs_m32_f17:static-orbit', 'vc_m16_s32x17:orbit', 'vc_m16_s32x17:still',
        'vc_m16_s32x17:pan', 'vc_m16_s32x17:pan-still', 'vc_m16_s32x17:terrain',
        'vc_m32_s32x17:orbit', 'vc_m32_s32x17:still', 'vc_m32_s32x17:pan',
        'fs_m32_f31:static', 'fs_m32_f31:static-orbit', 'vc_m32_s32x31:orbit', 'vc_m32_s32x31:still', 'vc_m32_s32x31:pan',
        'fs_m32_f63:static', 'fs_m32_f63:static-orbit', 'vc_m32_s32x63:orbit', 'vc_m32_s32x63:still', 'vc_m32_s32x63:pan']
def behind_pads(rows, bakes, jobs, pads):
    """The bakes once, then every job behind each pad in turn (job ids get @padN). Also used by
    ../raw-h200-tile-count/cut_plan.py."""
    out = ['\t'.join(rows[b]) for b in bakes]
    for pad in pads:
        for j in jobs:
            p = rows[j]
            a = re.sub(r'--dump-storage-prefix \S+', '', p[3])
            if j.startswith('vc_') and '--compute-once' not in a: a += ' --no-compute-timestamp'
            if pad: a += ' --placement-pad %d' % pad
            out.append('\t'.join([p[0] + '@pad%d' % pad, p[1], p[2], a]))
    return out

if __name__ == '__main__':
    rows = {l.split('\t')[0]: l.rstrip('\n').split('\t') for l in open(sys.argv[1]) if l.strip()}
    out = behind_pads(rows, bakes, jobs, [k * 163840 for k in range(8)])
    open(sys.argv[2], 'w').write('\n'.join(out) + '\n')
    print(len(out), 'jobs')
