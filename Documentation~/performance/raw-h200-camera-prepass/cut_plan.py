#!/usr/bin/env python3
"""Cuts this folder's plans from a `gt bench --prepare` plan.tsv (commit 100a68a).
usage: cut_plan.py PLAN.tsv OUT.tsv FRAMES WARMUP REPS [VARIANT,...]
  JOBS="id id ..." the cached jobs (default: run 1's), TS=0 leaves out the base-ts orbit jobs.
Each cached job runs once per variant and repetition (#a, #b), interleaved; the static meshes once
per repetition. Variants (SPIR-V under @SPV@/exp/, built from experiment-prepass.patch):
  base      the bench's kernels, --no-compute-timestamp (base-ts: with the compute timestamp)
  base2     the bench's factors kernel, a vertex kernel of 128 lanes x 2 passes (G = 18)
  merged4, merged2, m1024x5, m512x9, m512x8, m256x8   CacheTilesMerged, LANESxPASSES (merged4 =
            128x4, merged2 = 128x2), G groups a tile, each on its own copy of the factor state
  compact   hull, domain and kernels with the edge slots after the tile's own grid (GT_EXP_COMPACT)
  pad2, pad3  the bench's shaders, the factor buffer (binding 7) 2x or 3x as large"""
import sys, re, os
src, dst, frames, warmup, reps = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4], int(sys.argv[5])
rows = {}
order = []
for line in open(src):
    p = line.rstrip('\n').split('\t')
    if len(p) < 4: continue
    rows[p[0]] = p; order.append(p[0])
bakes = ['fs_m32_f17:bake', 'fs_m32_f31:bake', 'fs_m32_f63:bake']
statics = ['fs_m32_f17:static', 'fs_m32_f17:static-orbit', 'fs_m32_f31:static', 'fs_m32_f31:static-orbit',
           'fs_m32_f63:static', 'fs_m32_f63:static-orbit']
cached = os.environ.get('JOBS', 'vc_m16_s32x17:orbit vc_m16_s32x17:terrain vc_m16_s32x17:still vc_m16_s32x17:pan '
          'vc_m32_s32x17:orbit vc_m32_s32x17:terrain vc_m64_s32x17:orbit vc_m64_s32x17:terrain '
          'vc_m32_s32x31:orbit vc_m32_s32x31:terrain vc_m32_s32x63:orbit vc_m32_s32x63:terrain').split()
def timing(a):
    a = re.sub(r'--frames \d+', '--frames ' + frames, a)
    return re.sub(r'--warmup \d+', '--warmup ' + warmup, a)
def variant(a, name):
    m = re.search(r'--storage 7:(\d+)', a); size = int(m.group(1))
    fac = re.search(r'--compute (\S+cache_factors\.spv):(\d+),(\d+),1 ', a)
    ver = re.search(r'--compute (\S+cache_vertices\.spv):(\d+),(\d+),(\d+) ', a)
    t = fac.group(2)
    a = re.sub(r'--dump-storage-prefix \S+', '', a)
    if name == 'base': return a + ' --no-compute-timestamp'
    if name == 'base-ts': return a
    if name in ('pad2', 'pad3', 'pad4'):
        return a.replace(m.group(0), '--storage 7:%d' % (size * int(name[-1]))) + ' --no-compute-timestamp'
    if name == 'compact':
        for st in ('tesc', 'tese', 'cache_factors', 'cache_vertices'):
            a = a.replace('@SPV@/noise+height_color+vertex_cache/%s.spv' % st, '@SPV@/exp/compact/%s.spv' % st)
        return a + ' --no-compute-timestamp'
    if name == 'base2':
        a = a.replace(ver.group(0), '--compute @SPV@/exp/base2_vertices.spv:%s,%s,18 ' % (t, t))
        return a + ' --no-compute-timestamp'
    g = {'merged4': 9, 'merged2': 18, 'm1024x5': 1, 'm512x9': 1, 'm512x8': 2, 'm256x8': 3}[name]
    a = a.replace(fac.group(0), '')
    a = a.replace(ver.group(0), '--compute @SPV@/exp/%s.spv:%s,%s,%d ' % (name, t, t, g))
    a = a.replace(m.group(0), '--storage 7:%d' % (size * g))
    return a + ' --no-compute-timestamp'
out = []
for b in bakes: out.append('\t'.join(rows[b]))
variants = sys.argv[6].split(',') if len(sys.argv) > 6 else ['base', 'merged4', 'merged2', 'base2']
for r in range(reps):
    tag = 'ab'[r]
    for s in statics:
        p = rows[s]; out.append('\t'.join([p[0] + '#' + tag, p[1], p[2], timing(p[3])]))
    for c in cached:
        p = rows[c]
        for v in variants + (['base-ts'] if c.endswith(':orbit') and os.environ.get('TS', '1') == '1' else []):
            out.append('\t'.join([p[0] + '@' + v + '#' + tag, p[1], p[2], timing(variant(p[3], v))]))
open(dst, 'w').write('\n'.join(out) + '\n')
print(len(out), 'jobs')
