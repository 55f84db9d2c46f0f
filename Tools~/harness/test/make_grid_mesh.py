#!/usr/bin/env python3
"""Writes a flat N x N-cell grid mesh over [0,1]^2 (object x, z; y = 0) for --static-mesh:
POSITIONS.f32 ((N+1)^2 float3) and INDICES.u32 (2 N^2 triangles). The benchmark's "static
pre-tessellated mesh of the same triangle count": tiles M at factor F give N = M * F.
Usage: make_grid_mesh.py N POSITIONS INDICES  (standard library only)"""
import array, sys

n = int(sys.argv[1])
pos = array.array("f")
for j in range(n + 1):
    z = j / n
    for i in range(n + 1):
        pos.extend((i / n, 0.0, z))
idx = array.array("I")
row = n + 1
for j in range(n):
    base = j * row
    for i in range(n):
        v = base + i
        # The renderer's fallback triangles: clockwise seen from above (Unity's front face).
        idx.extend((v, v + row, v + 1, v + 1, v + row, v + row + 1))
if sys.byteorder != "little":
    pos.byteswap(); idx.byteswap()
with open(sys.argv[2], "wb") as f:
    pos.tofile(f)
with open(sys.argv[3], "wb") as f:
    idx.tofile(f)
print("mesh %d cells, %d vertices, %d triangles" % (n * n, len(pos) // 3, len(idx) // 3))
