#!/usr/bin/env python3
"""Turns a GT_READBACK capture into the buffers of the fair static mesh (gt bench, vert_static).

    bench_static_mesh.py CAPTURE.f32 JOB_DIR OUT_DIR

CAPTURE: the terrain's vertices as GT_READBACK wrote them (3 float4 a vertex: (position, 1),
(normal, 0), (q, u, v); Tools~/rig/README.md "Rig-only readback"), for M*M tiles at the uniform factor F.
OUT_DIR gets what vert_static reads, 2 float4 a vertex (position, normal: 32 bytes, the size of a
baked mesh's vertex) in the _ControlPoints file, padded to whole 320-byte "patches", regions.f32
of zeros to match (the harness checks the pair), and the job's params, camera and grid lines.
Only bash, python3 and the harness run on the GPU machine, so no numpy: bytes are sliced.
"""
import math, os, shutil, struct, sys

capture, job, out = sys.argv[1:4]
data = open(capture, "rb").read()
if len(data) % 48:
    sys.exit(f"bench_static_mesh: {capture} holds {len(data)} bytes, not a multiple of 48")
n = len(data) // 48
for i in (0, n // 2, n - 1):   # never-written vertices stay NaN
    x = struct.unpack_from("<f", data, 48 * i)[0]
    if math.isnan(x):
        sys.exit(f"bench_static_mesh: vertex {i} of {capture} was never written")
mv = memoryview(data)
packed = b"".join(mv[48 * i: 48 * i + 32] for i in range(n))
pad = (-len(packed)) % 320
os.makedirs(out, exist_ok=True)
with open(os.path.join(out, "control_points.f32"), "wb") as f:
    f.write(packed)
    f.write(b"\0" * pad)
with open(os.path.join(out, "regions.f32"), "wb") as f:
    f.write(b"\0" * (16 * ((len(packed) + pad) // 320)))
for name in ("params.f32", "camera.f32", "grid_lines.f32"):
    shutil.copyfile(os.path.join(job, name), os.path.join(out, name))
print(f"static mesh vertices {n} bytes {len(packed)}")
