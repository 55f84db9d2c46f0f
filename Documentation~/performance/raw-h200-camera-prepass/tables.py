#!/usr/bin/env python3
"""Tables of a run of this folder: frame ms, mean of the two medians (#a, #b) of each job x variant.
usage: tables.py results-N.txt"""
import sys, collections, statistics
med = collections.defaultdict(list)
for block in open(sys.argv[1]).read().split('\n== '):
    lines = block.strip().split('\n')
    head = lines[0].replace('== ', '').split()[0]
    for l in lines:
        if l.startswith('time frame_ms_median') and '#' in head:
            med[head.split('#')[0]].append(float(l.split()[-1]))
jobs, variants = [], []
for k in med:
    j, _, v = k.partition('@')
    if j not in jobs: jobs.append(j)
    if v and v not in variants: variants.append(v)
print('| job | ' + ' | '.join(variants or ['ms']) + ' |')
print('| --- |' + ' ---: |' * max(1, len(variants)))
for j in jobs:
    if j + '@' + (variants[0] if variants else '') not in med and j in med:
        print('| `%s` | %.4f |' % (j, statistics.mean(med[j])) + ' |' * (len(variants) - 1)); continue
    cells = ['%.4f' % statistics.mean(med[j + '@' + v]) if j + '@' + v in med else '' for v in variants]
    print('| `%s` | %s |' % (j, ' | '.join(cells)))
