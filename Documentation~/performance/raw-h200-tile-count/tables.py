#!/usr/bin/env python3
"""The tables of README.md from results.txt: frame ms per pad, mean and range; ratios of the means
(and the range of the per-pad ratios). usage: tables.py results.txt"""
import sys, re, collections, statistics
med = collections.defaultdict(dict); tris = {}
for block in open(sys.argv[1]).read().split('\n== '):
    lines = block.strip().split('\n')
    job, _, pad = lines[0].replace('== ', '').split()[0].partition('@pad')
    for l in lines:
        if l.startswith('time frame_ms_median'): med[job][int(pad)] = float(l.split()[-1])
        if l.startswith('stat clipping_invocations'): tris[job] = int(l.split()[-1])
pads = sorted({p for v in med.values() for p in v})
print('| job | triangles | ' + ' | '.join('%d KiB' % (p // 1024) for p in pads) + ' | mean | min-max |')
print('| --- | ---: |' + ' ---: |' * (len(pads) + 2))
for job, v in med.items():
    xs = [v[p] for p in pads]
    print('| `%s` | %s | %s | **%.4f** | %.4f-%.4f |' % (job, format(tris.get(job, 0), ','), ' | '.join('%.4f' % x for x in xs), statistics.mean(xs), min(xs), max(xs)))
def ratio(a, b):
    A = [med[a][p] for p in pads]; B = [med[b][p] for p in pads]
    per = [x / y for x, y in zip(A, B)]
    return statistics.mean(A) / statistics.mean(B), min(per), max(per)
print()
print('| tiles | triangles (static) | camera moving / static | still / static | panning / static | range moving (tiles on the range) / static |')
print('| ---: | ---: | ---: | ---: | ---: | ---: |')
groups = {}   # static size -> tile counts, in the order the results list them
for job in med:
    m = re.match(r'vc_m(\d+)_(s32x\d+):', job)
    if m and int(m.group(1)) not in groups.setdefault(m.group(2), []): groups[m.group(2)].append(int(m.group(1)))
for size, ms in groups.items():
    static = 'fs_m32_f%s' % size.split('x')[1]
    for m in ms:
        cells = []
        for k in ('orbit', 'still', 'pan', 'terrain'):
            if 'vc_m%d_%s:%s' % (m, size, k) not in med: cells.append(''); continue
            r, lo, hi = ratio('vc_m%d_%s:%s' % (m, size, k), static + (':static-orbit' if k == 'orbit' else ':static'))
            cells.append('**%.4fx** (%.4f-%.4f)' % (r, lo, hi))
        print('| %d | %s | %s |' % (m, format(tris[static + ':static'], ','), ' | '.join(cells)))
