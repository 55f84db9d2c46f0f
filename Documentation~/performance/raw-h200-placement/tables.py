#!/usr/bin/env python3
"""The tables of README.md from results.txt: frame ms per pad, mean and range; ratios of the means.
usage: tables.py results.txt"""
import sys, collections, statistics
res = open(sys.argv[1]).read().split('\n== ')
med = collections.defaultdict(dict)
for block in res:
    lines = block.strip().split('\n')
    head = lines[0].replace('== ', '').split()[0]
    for l in lines:
        if l.startswith('time frame_ms_median'):
            job, pad = head.split('@pad')
            med[job][int(pad)] = float(l.split()[-1])
pads = sorted({p for v in med.values() for p in v})
print('| job | ' + ' | '.join('%d KiB' % (p // 1024) for p in pads) + ' | mean | min-max |')
print('| --- |' + ' ---: |' * (len(pads) + 2))
for job, v in med.items():
    xs = [v[p] for p in pads]
    print('| `%s` | %s | **%.4f** | %.4f-%.4f |' % (job, ' | '.join('%.4f' % x for x in xs), statistics.mean(xs), min(xs), max(xs)))
def r(a, b):
    A = [med[a][p] for p in pads]; B = [med[b][p] for p in pads]
    per = [x / y for x, y in zip(A, B)]
    return statistics.mean(A) / statistics.mean(B), min(per), max(per)
print()
for a, b in [('vc_m16_s32x17:orbit', 'fs_m32_f17:static-orbit'), ('vc_m16_s32x17:still', 'fs_m32_f17:static'),
             ('vc_m16_s32x17:pan', 'fs_m32_f17:static'), ('vc_m16_s32x17:pan', 'vc_m16_s32x17:pan-still'),
             ('vc_m16_s32x17:terrain', 'fs_m32_f17:static'),
             ('vc_m32_s32x17:orbit', 'fs_m32_f17:static-orbit'), ('vc_m32_s32x17:pan', 'fs_m32_f17:static'),
             ('vc_m32_s32x31:orbit', 'fs_m32_f31:static-orbit'), ('vc_m32_s32x31:still', 'fs_m32_f31:static'),
             ('vc_m32_s32x31:pan', 'fs_m32_f31:static'),
             ('vc_m32_s32x63:orbit', 'fs_m32_f63:static-orbit'), ('vc_m32_s32x63:still', 'fs_m32_f63:static'),
             ('vc_m32_s32x63:pan', 'fs_m32_f63:static')]:
    m, lo, hi = r(a, b)
    print('| `%s` / `%s` | **%.4fx** | %.4fx-%.4fx |' % (a, b, m, lo, hi))
