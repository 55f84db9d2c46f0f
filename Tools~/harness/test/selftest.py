#!/usr/bin/env python3
"""Harness self-test on lavapipe (or any device given with --device).

Runs gt-harness with the test shaders of this folder and checks what it must produce:
  - a non-blank image whose covered area matches the drawn range (camera matrix layout);
  - readback: every vertex of every tile written exactly where Tools~/rig/README.md says, with the tess
    coordinate, the tile index (from SV_VertexID / 4), q and the bindings 2..4 read right, for a
    4x4-tile draw at factor 8 (one draw) and 6x6 tiles at factor 63 (147,456 vertices: split);
  - pipeline statistics equal to the counts an integer-partitioned quad draw must give;
  - the fallback (instanced grid) and static-mesh modes draw;
  - the compute pre-pass (--storage/--compute/--dump-storage): a kernel's pattern dumped byte for
    byte, two chained kernels whose output the domain (or fallback vertex) stage reads, in order,
    with split draws, and its own timestamps;
  - sampled images and separate samplers (--image/--sampler): sampling.hlsl's probes of a texel
    fetch, a bilinear midpoint, a repeat wrap, an array layer and a comparison sampler, exactly;
  - bad input fails with a non-zero exit code and a message (exit code 1 and the option and value
    named for the compute options).
Prints one "PASS name" / "FAIL name: why" line per check; exit 1 if any failed.
Only the standard library is used (the harness machine may have no numpy).
"""
import math, os, struct, subprocess, sys

HARNESS, SPV, WORK = sys.argv[1], sys.argv[2], sys.argv[3]
EXTRA = sys.argv[4:]  # e.g. --device llvmpipe
failures = 0
# Tess coordinates are not exact: lavapipe's tessellator works in fixed point (s = 0.41259765625
# for 26/63, off by 1e-4), so s, t are checked to a quarter of the spacing 1/F.


def check(name, ok, why=""):
    global failures
    print(("PASS " + name) if ok else ("FAIL %s: %s" % (name, why)), flush=True)
    failures += 0 if ok else 1


def write_f32(path, values):
    with open(path, "wb") as f:
        f.write(struct.pack("<%df" % len(values), *values))


def make_inputs(d, tiles, factor, rng=(0.0, 0.0, 1.0, 1.0)):
    """Params (_Tess = (M, maxFactor, 0, F)), an orthographic top-down camera, and buffers whose
    element i holds i + 0.25 / 0.5 / 0.75 so the shader's reads can be checked."""
    os.makedirs(d, exist_ok=True)
    patches = 64
    params = list(rng) + [0] * 4 + [8, 8, 0, 0] + [tiles, factor, 1, factor] + [0] * 24
    write_f32(os.path.join(d, "params.f32"), params)
    # clip = (2x - 1, 2z - 1, 0.5, 1) for object (x, y, z); column-major: column c at [4c..4c+3].
    rows = [[2, 0, 0, -1], [0, 0, 2, -1], [0, 0, 0, 0.5], [0, 0, 0, 1]]
    to_clip = [rows[r][c] for c in range(4) for r in range(4)]
    identity = [1.0 if r == c else 0.0 for c in range(4) for r in range(4)]
    write_f32(os.path.join(d, "camera.f32"), to_clip + identity + [0.5, 2, 0.5, 1, 256, 256, 1 / 256, 1 / 256, 0, 1, 0, 0])
    write_f32(os.path.join(d, "control_points.f32"), [v for i in range(20 * patches) for v in (i + 0.25, 0, 0, 1)])
    write_f32(os.path.join(d, "regions.f32"), [v for i in range(patches) for v in (0, i + 0.5, 0, 0)])
    write_f32(os.path.join(d, "grid_lines.f32"), [i + 0.75 for i in range(65)])
    return d


def run(args, env=None):
    p = subprocess.run([HARNESS] + EXTRA + args, capture_output=True, text=True, env=env)
    lines = {}
    for line in p.stdout.splitlines():
        parts = line.split()
        if len(parts) >= 2:
            lines.setdefault(parts[0], []).append(parts[1:])
    return p, lines


def value(lines, key, sub):
    for parts in lines.get(key, []):
        if parts[0] == sub:
            return parts[1:]
    return None


def tess_args(d, tiles, readback=None, floats=0, stats=False, extra=()):
    a = ["--vert", SPV + "/tiles.vert.spv", "--tesc", SPV + "/tiles.tesc.spv",
         "--tese", SPV + ("/tiles_readback.tese.spv" if readback else "/tiles.tese.spv"),
         "--frag", SPV + "/tiles.frag.spv", "--buffers", d, "--patches", str(tiles * tiles), "--width", "128", "--height", "128"]
    if readback:
        a += ["--readback", readback, "--readback-floats", str(floats)]
    if stats:
        a += ["--stats"]
    return a + list(extra)


def check_readback(name, path, m, f, rng, per_draw):
    """Every slot holds the vertex the contract's index formula puts there; the hull stage's
    SV_PrimitiveID is tile % per_draw (it restarts in each draw of per_draw patches)."""
    n = m * m * (f + 1) ** 2
    data = open(path, "rb").read()
    vals = struct.unpack("<%df" % (len(data) // 4), data)
    if len(vals) != 12 * n:
        return check(name, False, "readback has %d floats, expected %d" % (len(vals), 12 * n))
    bad, prim_bad, worst = [], [], 0.0
    c, d, g, h = rng
    for k in range(n):
        tile, r = divmod(k, (f + 1) ** 2)
        row, col = divmod(r, f + 1)
        s, t = col / f, row / f
        ti, tj = tile % m, tile // m
        qx, qy = c + (ti + s) / m * (g - c), d + (tj + t) / m * (h - d)
        v = vals[12 * k:12 * k + 12]
        # s, t: within a quarter spacing of col/F, row/F (they are not exact, see TOL); q from
        # the s, t actually read back, with the contract's formula, to float accuracy.
        sv, tv = v[4], v[5]
        qx = c + (ti + sv) / m * (g - c)
        qy = d + (tj + tv) / m * (h - d)
        expect = [(4, s, 0.25 / f), (5, t, 0.25 / f), (0, qx, 1e-6), (1, 0.0, 0), (2, qy, 1e-6), (3, 1.0, 0),
                  (6, tile, 0), (8, tile + 0.25, 0), (9, tile + 0.5, 0), (10, tile + 0.75, 0), (11, m, 0)]
        for i, e, tol in expect:
            if not (abs(v[i] - e) <= tol):
                bad.append("vertex %d float %d = %r, expected %r" % (k, i, v[i], e))
                break
        worst = max(worst, abs(sv - s), abs(tv - t))
        if v[7] != tile % per_draw:
            prim_bad.append("vertex %d: SV_PrimitiveID %r, expected %d" % (k, v[7], tile % per_draw))
        if len(bad) > 3:
            break
    check(name, not bad, "; ".join(bad[:4]))
    print("  %s: largest |s - col/F| = %.3g" % (name, worst))
    check(name + " primitive_id restarts per draw", not prim_bad, "; ".join(prim_bad[:3]))


PATTERN_RECORDS = 4 * 2 * 3 * 64  # storage_pattern.hlsl dispatched over (4, 2, 3) groups of 64


def expected_pattern(tiles):
    """storage_pattern.hlsl's records: (i, i * 2654435761 mod 2^32, bits of _Tess.x, bits of
    _ControlPoints[i % 1280].x), the control point x being its index + 0.25 (make_inputs)."""
    bits = lambda f: struct.unpack("<I", struct.pack("<f", f))[0]
    out = []
    for i in range(PATTERN_RECORDS):
        out += [i, (i * 2654435761) % 2 ** 32, bits(float(tiles)), bits(i % 1280 + 0.25)]
    return struct.pack("<%dI" % len(out), *out)


def kept_tiles(m):
    """tile_scale.hlsl keeps every third tile."""
    return sum(1 for t in range(m * m) if t % 3 == 0)


def compute_tile_args(m, order=("tile_flags", "tile_scale")):
    groups = str((m * m + 63) // 64)
    a = ["--storage", "7:%d" % (16 * m * m), "--storage", "8:%d" % (16 * m * m)]
    for k in order:
        a += ["--compute", "%s/%s.comp.spv:%s" % (SPV, k, groups)]
    return a


def check_tile_dumps(name, path7, path8, m):
    """Binding 7: (kept, tile, M, 0) from tile_flags; binding 8: (kept, tile + 0.5, 0, 0) from
    tile_scale, which read binding 7 after the compute->compute barrier."""
    f7 = struct.unpack("<%df" % (4 * m * m), open(path7, "rb").read())
    f8 = struct.unpack("<%df" % (4 * m * m), open(path8, "rb").read())
    bad = []
    for t in range(m * m):
        kept = 1.0 if t % 3 == 0 else 0.0
        if f7[4 * t:4 * t + 4] != (kept, t, m, 0.0):
            bad.append("binding 7 tile %d = %r" % (t, f7[4 * t:4 * t + 4]))
        if f8[4 * t:4 * t + 4] != (kept, t + 0.5, 0.0, 0.0):
            bad.append("binding 8 tile %d = %r" % (t, f8[4 * t:4 * t + 4]))
    check(name, not bad, "; ".join(bad[:4]))


def compute_checks(lavapipe):
    """9. The compute pre-pass."""
    d = make_inputs(WORK + "/in_4x4_f8", 4, 8)
    mesh = WORK + "/mesh"
    pattern_bytes = 16 * PATTERN_RECORDS
    # a. A kernel's pattern at binding 8, dumped; 256 bytes more than it writes stay zero (zero
    #    fill), binding 7 given but unwritten is all zeros. Static-mesh mode, timed, 3 frames.
    d7, d8 = WORK + "/pattern_7.bin", WORK + "/pattern_8.bin"
    p, l = run(["--static-mesh", "--mesh", mesh + "/positions.f32", mesh + "/indices.u32", "--vert", SPV + "/mesh.vert.spv",
                "--frag", SPV + "/mesh.frag.spv", "--buffers", d, "--width", "128", "--height", "128",
                "--storage", "7:64", "--storage", "8:%d" % (pattern_bytes + 256),
                "--compute", SPV + "/pattern.comp.spv:4,2,3", "--dump-storage", "8:" + d8, "--dump-storage", "7:" + d7,
                "--frames", "3", "--timestamps"])
    check("compute pattern (static mesh) runs", p.returncode == 0, p.stderr.strip())
    if p.returncode == 0:
        check("compute pattern storage line", value(l, "storage", "8") == [d8, "bytes", str(pattern_bytes + 256)],
              str(l.get("storage")))
        got = open(d8, "rb").read()
        want = expected_pattern(4) + bytes(256)
        first = next((i for i in range(min(len(got), len(want))) if got[i] != want[i]), None)
        check("compute pattern dump equals the pattern", got == want,
              "%d bytes, expected %d; first difference at byte %s" % (len(got), len(want), first))
        check("compute unwritten storage dumps zeros", open(d7, "rb").read() == bytes(64), "binding 7 not zero")
        check("compute static mesh still covers a quarter", int(value(l, "image", "nonsky_pixels")[0]) == 64 * 64,
              str(l.get("image")))
        frame = [float(v[1]) for v in l.get("time", []) if v[0] == "frame_ms"]
        comp = [float(v[1]) for v in l.get("time", []) if v[0] == "compute_ms"]
        check("compute_ms per frame", len(comp) == 3 and len(frame) == 3, str(l.get("time")))
        check("compute_ms within the frame time", all(0 <= c <= f for c, f in zip(comp, frame)),
              "compute %r frame %r" % (comp, frame))
        check("compute_ms median/min/mean", all(value(l, "time", "compute_ms_" + k) for k in ("median", "min", "mean")),
              str(l.get("time")))

    # b. Two chained kernels feed the domain stage: only the kept tiles cover pixels (one draw at
    #    4x4 tiles, factor 8; split into 2 draws at 8x8 tiles, factor 32 = 69,696 vertices).
    for m, f, draws in ((4, 8, "1"), (8, 32, "2")):
        name = "compute tiles %dx%d f%d" % (m, m, f)
        dm = make_inputs(WORK + "/in_%dx%d_f%d" % (m, m, f), m, f)
        d7, d8 = WORK + "/tiles_%d_7.bin" % m, WORK + "/tiles_%d_8.bin" % m
        a = tess_args(dm, m, extra=["--max-factor", str(f), "--max-vertices-per-draw", "65536",
                                    "--png", WORK + "/compute_tiles_%d.png" % m])
        a[a.index(SPV + "/tiles.tese.spv")] = SPV + "/tiles_storage.tese.spv"
        p, l = run(a + compute_tile_args(m) + ["--dump-storage", "7:" + d7, "--dump-storage", "8:" + d8])
        check(name + " runs", p.returncode == 0, p.stderr.strip())
        if p.returncode == 0:
            check(name + " draws", l["draws"][0][0] == draws, str(l.get("draws")))
            nonsky = int(value(l, "image", "nonsky_pixels")[0])
            want = kept_tiles(m) * (128 // m) ** 2
            check(name + " domain stage sees the kernels' scales", nonsky == want, "nonsky %d, expected %d" % (nonsky, want))
            check_tile_dumps(name + " dumps", d7, d8, m)

    # c. The same kernels in the wrong order: tile_scale reads binding 7 before tile_flags wrote it,
    #    so every scale is 0 and nothing is drawn (the order given is the order run).
    a = tess_args(d, 4, extra=["--max-factor", "8"])
    a[a.index(SPV + "/tiles.tese.spv")] = SPV + "/tiles_storage.tese.spv"
    p, l = run(a + compute_tile_args(4, ("tile_scale", "tile_flags")))
    check("compute reversed order runs", p.returncode == 0, p.stderr.strip())
    if p.returncode == 0:
        check("compute reversed order draws nothing", int(value(l, "image", "nonsky_pixels")[0]) == 0, str(l.get("image")))

    # d. Fallback mode: the vertex stage reads the kernels' output.
    p, l = run(["--vert", SPV + "/fallback_storage.vert.spv", "--frag", SPV + "/tiles.frag.spv", "--buffers", d,
                "--grid-factor", "8", "--instances", "16", "--width", "128", "--height", "128"] + compute_tile_args(4))
    check("compute fallback runs", p.returncode == 0, p.stderr.strip())
    if p.returncode == 0:
        nonsky = int(value(l, "image", "nonsky_pixels")[0])
        check("compute fallback vertex stage sees the kernels' scales", nonsky == kept_tiles(4) * 32 * 32, "nonsky %d" % nonsky)

    # e. The barriers: lavapipe runs a command buffer in order, so a missing one changes no result
    #    there; the Khronos layer's synchronization validation sees it at the API (checked: without
    #    the kernel->kernel or kernel->draw barrier it reports SYNC-HAZARD-READ-AFTER-WRITE).
    layer = "/usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json"
    if os.path.exists(layer):
        env = dict(os.environ, VK_INSTANCE_LAYERS="VK_LAYER_KHRONOS_validation",
                   VK_LAYER_ENABLES="VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT")
        a = tess_args(d, 4, extra=["--max-factor", "8", "--frames", "2", "--timestamps", "--resend-bytes", "4096",
                                   "--dump-storage", "8:" + WORK + "/sync_8.bin"])
        a[a.index(SPV + "/tiles.tese.spv")] = SPV + "/tiles_storage.tese.spv"
        p, l = run(a + compute_tile_args(4), env)
        messages = [x for x in (p.stdout + p.stderr).splitlines() if "Validation" in x or "VUID" in x]
        check("compute pre-pass under synchronization validation", p.returncode == 0 and not messages,
              "exit %d; %s" % (p.returncode, " / ".join(m[:300] for m in messages[:3]) or p.stderr.strip()))
    else:
        print("INFO barriers not checked: no Khronos validation layer (apt package vulkan-validationlayers)")

    # f. Bad compute options: exit code 1, the option and the offending value named.
    pattern = SPV + "/pattern.comp.spv"
    cases = [
        (["--storage", "7"], ["--storage", "'7'"]),
        (["--storage", "7:abc"], ["--storage", "7:abc"]),
        (["--storage", "3:64"], ["--storage", "3:64", "_Regions"]),
        (["--storage", "7:6"], ["--storage", "7:6", "multiple of 4"]),
        (["--storage", "8:64", "--storage", "8:128"], ["--storage", "8:128"]),
        (["--compute", "pattern.spv"], ["--compute", "pattern.spv"]),
        (["--compute", pattern + ":0"], ["--compute", pattern + ":0"]),
        (["--compute", pattern + ":1,1,1,1"], ["--compute", pattern + ":1,1,1,1"]),
        # GY: 65,535 is the limit on lavapipe and NVIDIA alike (GX goes to 2^31 - 1 on NVIDIA).
        (["--storage", "8:64", "--compute", pattern + ":1,70000"], ["--compute", pattern + ":1,70000", "maxComputeWorkGroupCount[1]"]),
        (["--storage", "8:64", "--compute", SPV + "/tiles.vert.spv:1"], ["--compute", "tiles.vert.spv:1", "no compute entry point"]),
        (["--compute", pattern + ":4,2,3"], ["--compute", "pattern.comp.spv", "binding 8", "--storage 8:BYTES"]),
        (["--dump-storage", "8:" + WORK + "/x.bin"], ["--dump-storage", "8:" + WORK + "/x.bin"]),
    ]
    if lavapipe:  # 128 MiB there; NVIDIA's limit is 2^32 - 1, which no BYTES that parses exceeds
        cases.append((["--storage", "8:4294967292"], ["--storage", "8:4294967292", "maxStorageBufferRange"]))
    for extra, words in cases:
        p, l = run(tess_args(d, 4, extra=["--max-factor", "8"] + extra))
        missing = [w for w in words if w not in p.stderr]
        check("bad compute option %s" % " ".join(extra).replace(SPV + "/", ""), p.returncode == 1 and not missing,
              "exit %d, stderr lacks %r: %s" % (p.returncode, missing, p.stderr.strip()))
    # A graphics stage that reads a storage binding the run does not bind.
    a = tess_args(d, 4, extra=["--max-factor", "8"])
    a[a.index(SPV + "/tiles.tese.spv")] = SPV + "/tiles_storage.tese.spv"
    p, l = run(a)
    check("unbound storage binding fails", p.returncode == 1 and "--tese" in p.stderr and "binding 8" in p.stderr, p.stderr)


def image_checks():
    """10. --image / --sampler: sampling.hlsl's probes (HarnessImageTests checks the same)."""
    d = make_inputs(WORK + "/in_4x4_f8", 4, 8)
    mesh = WORK + "/mesh"
    values, depth, layers, dump = (WORK + "/" + n for n in ("values.f32", "depth.f32", "layers.u8", "probes.bin"))
    write_f32(values, [v for i in range(16) for v in (i % 4 + 4 * (i // 4), 1000 - (i % 4) * (i // 4))])
    write_f32(depth, [0.25, 0.75, 0.25, 0.75])
    with open(layers, "wb") as f:
        f.write(bytes([0, 0, 0, 0, 255, 0, 51, 102]))

    def probes(op):
        p, l = run(["--static-mesh", "--mesh", mesh + "/positions.f32", mesh + "/indices.u32", "--vert", SPV + "/mesh.vert.spv",
                    "--frag", SPV + "/mesh.frag.spv", "--buffers", d, "--storage", "8:80",
                    "--compute", SPV + "/sampling.comp.spv:1", "--dump-storage", "8:" + dump,
                    "--image", "10:%s:R32G32_SFLOAT:4:4" % values, "--image", "11:%s:D32:2:2" % depth,
                    "--image", "15:%s:R8G8B8A8_UNORM:1:1:2" % layers, "--sampler", "12:linear:clamp",
                    "--sampler", "13:point:repeat", "--sampler", "14:point:clamp:" + op])
        check("images and samplers run (%s)" % op, p.returncode == 0, p.stderr.strip())
        if p.returncode != 0:
            return None
        with open(dump, "rb") as f:
            return struct.unpack("<20f", f.read())

    got = probes("compare-gequal")
    if got:
        check("texel fetch (3, 1)", got[0:2] == (7.0, 997.0), str(got[0:2]))
        check("bilinear midpoint", got[4:6] == (7.5, 997.75), str(got[4:6]))
        check("point repeat wraps to texel (1, 2)", got[8:10] == (9.0, 998.0), str(got[8:10]))
        check("array layer 1", all(abs(a - b) < 1e-6 for a, b in zip(got[16:20], (1, 0, 51 / 255, 102 / 255))), str(got[16:20]))
        check("compare-gequal (Unity's reversed depth)", got[12:16] == (1.0, 0.0, 1.0, 1.0), str(got[12:16]))
    got = probes("compare-less")
    if got:
        check("compare-less inverts the probes", got[12:16] == (0.0, 1.0, 0.0, 0.0), str(got[12:16]))
    p, _ = run(["--static-mesh", "--mesh", mesh + "/positions.f32", mesh + "/indices.u32", "--vert", SPV + "/mesh.vert.spv",
                "--frag", SPV + "/mesh.frag.spv", "--buffers", d, "--sampler", "12:cubic"])
    check("bad --sampler fails naming it", p.returncode == 1 and "--sampler" in p.stderr and "'cubic'" in p.stderr, p.stderr)


def main():
    os.makedirs(WORK, exist_ok=True)
    p, l = run(["--list-devices"])
    check("list_devices", p.returncode == 0 and "device" in l, p.stderr)

    # 1. 4x4 tiles at factor 8: one draw, readback, image, stats.
    d = make_inputs(WORK + "/in_4x4_f8", 4, 8)
    rb = WORK + "/rb_4x4_f8.f32"
    n = 16 * 81
    p, l = run(tess_args(d, 4, rb, 12 * n, stats=True, extra=["--max-factor", "8", "--png", WORK + "/tiles_4x4_f8.png"]))
    check("tess_4x4_f8 runs", p.returncode == 0, p.stderr.strip())
    lavapipe = value(l, "device", "lavapipe") == ["1"]  # for the checks of lavapipe's own limits
    if p.returncode == 0:
        check("tess_4x4_f8 one draw", l["draws"][0][0] == "1", str(l.get("draws")))
        nonsky = int(value(l, "image", "nonsky_pixels")[0])
        check("tess_4x4_f8 image covers the target", nonsky == 128 * 128, "nonsky %d of %d" % (nonsky, 128 * 128))
        check("tess_4x4_f8 readback complete", value(l, "readback", rb)[3] == "0", str(value(l, "readback", rb)))
        check_readback("tess_4x4_f8 readback values", rb, 4, 8, (0, 0, 1, 1), 16)
        stats = {k: int(v) for k, v in l.get("stat", [])}
        print("  stats 4x4 f8: " + " ".join("%s=%d" % kv for kv in stats.items()))
        check("stat input_assembly_vertices", stats.get("input_assembly_vertices") == 64, str(stats))
        check("stat vertex_shader_invocations", stats.get("vertex_shader_invocations") == 64, str(stats))
        check("stat tessellation_control_shader_patches", stats.get("tessellation_control_shader_patches") == 16, str(stats))
        check("stat tessellation_evaluation_shader_invocations = (F+1)^2 * patches",
              stats.get("tessellation_evaluation_shader_invocations") == 16 * 81, str(stats))
        check("stat input_assembly_primitives = patches", stats.get("input_assembly_primitives") == 16, str(stats))
        check("stat clipping_primitives = 2 F^2 patches", stats.get("clipping_primitives") == 2 * 64 * 16, str(stats))
        check("stat fragment_shader_invocations >= pixels", stats.get("fragment_shader_invocations", 0) >= 128 * 128, str(stats))

    # The same draw behind a placement pad: the same picture and readback (only the memory moved).
    rb_pad = WORK + "/rb_4x4_f8_pad.f32"
    p, l = run(tess_args(d, 4, rb_pad, 12 * n, extra=["--max-factor", "8", "--placement-pad", "1048580"]))
    check("placement pad runs and says so", p.returncode == 0 and value(l, "inputs", "placement_pad") == ["1048580"],
          p.stderr.strip() or str(l.get("inputs")))
    if p.returncode == 0:
        with open(rb, "rb") as a, open(rb_pad, "rb") as b:
            check("placement pad changes no output", a.read() == b.read()
                  and int(value(l, "image", "nonsky_pixels")[0]) == 128 * 128, "readback or image differs")

    # 2. 6x6 tiles at factor 63 = 147,456 vertices: must split on lavapipe (16 patches per draw).
    d = make_inputs(WORK + "/in_6x6_f63", 6, 63, (0.25, 0.25, 0.75, 0.75))
    rb = WORK + "/rb_6x6_f63.f32"
    n = 36 * 64 * 64
    p, l = run(tess_args(d, 6, rb, 12 * n, stats=True, extra=["--max-factor", "63", "--max-vertices-per-draw", "65536",
                                                                  "--png", WORK + "/tiles_6x6_f63.png"]))
    check("tess_6x6_f63 runs", p.returncode == 0, p.stderr.strip())
    if p.returncode == 0:
        draws = l["draws"][0][0]
        check("tess_6x6_f63 split into 3 draws", draws == "3", "draws %s" % draws)
        check("tess_6x6_f63 readback complete", value(l, "readback", rb)[3] == "0", str(value(l, "readback", rb)))
        check_readback("tess_6x6_f63 readback values", rb, 6, 63, (0.25, 0.25, 0.75, 0.75), 16)
        nonsky = int(value(l, "image", "nonsky_pixels")[0])
        # Range [0.25,0.75]^2 of the unit square: a quarter of the target.
        check("tess_6x6_f63 image covers a quarter", abs(nonsky - 128 * 128 / 4) <= 2 * 128, "nonsky %d" % nonsky)
        stats = {k: int(v) for k, v in l.get("stat", [])}
        print("  stats 6x6 f63 split: " + " ".join("%s=%d" % kv for kv in stats.items()))
        check("stat split tessellation_control_shader_patches", stats.get("tessellation_control_shader_patches") == 36, str(stats))
        check("stat split clipping_primitives", stats.get("clipping_primitives") == 2 * 63 * 63 * 36, str(stats))
        check("stat split tessellation_evaluation_shader_invocations",
              stats.get("tessellation_evaluation_shader_invocations") == 36 * 64 * 64, str(stats))
        check("stat split input_assembly_vertices", stats.get("input_assembly_vertices") == 4 * 36, str(stats))

    # 3. The same draw without the split: on lavapipe the tessellation evaluation output is right
    #    (readback) but only the first 65,536 vertices' triangles are drawn. Reported, not required.
    rb = WORK + "/rb_6x6_f63_unsplit.f32"
    p, l = run(tess_args(d, 6, rb, 12 * n, extra=["--max-factor", "63", "--max-vertices-per-draw", "0",
                                                  "--png", WORK + "/tiles_6x6_f63_unsplit.png"]))
    if p.returncode == 0:
        nonsky = int(value(l, "image", "nonsky_pixels")[0])
        check_readback("unsplit 6x6 f63 readback values (domain output is right)", rb, 6, 63,
                       (0.25, 0.25, 0.75, 0.75), 10 ** 9)
        print("INFO unsplit 6x6 f63 (one draw of 147,456 vertices): nonsky %d of %d expected -> %s"
              % (nonsky, 128 * 128 // 4, "lavapipe 65,536-vertex bug reproduced" if nonsky < 128 * 128 // 4 - 256
                 else "complete (no bug on this device)"))

    # 4. --range overrides params.f32's _Range.
    d = make_inputs(WORK + "/in_4x4_f8", 4, 8)
    rb = WORK + "/rb_range.f32"
    p, l = run(tess_args(d, 4, rb, 12 * 16 * 81, extra=["--max-factor", "8", "--range", "0.5,0.5,1,1"]))
    check("range override runs", p.returncode == 0, p.stderr.strip())
    if p.returncode == 0:
        check_readback("range override readback values", rb, 4, 8, (0.5, 0.5, 1, 1), 16)

    # 5. Fallback: instanced (F+1)^2 grid, 4x4 instances at F = 8.
    rb = WORK + "/rb_fallback.f32"
    p, l = run(["--vert", SPV + "/fallback_readback.vert.spv", "--frag", SPV + "/tiles.frag.spv", "--buffers", d,
                "--grid-factor", "8", "--instances", "16", "--width", "128", "--height", "128",
                "--readback", rb, "--readback-floats", str(12 * 16 * 81), "--stats", "--png", WORK + "/fallback.png"])
    check("fallback runs", p.returncode == 0, p.stderr.strip())
    if p.returncode == 0:
        check("fallback image covers the target", int(value(l, "image", "nonsky_pixels")[0]) == 128 * 128, str(l.get("image")))
        check_readback("fallback readback values", rb, 4, 8, (0, 0, 1, 1), 1)  # slot holds 0
        stats = {k: int(v) for k, v in l.get("stat", [])}
        check("fallback stat input_assembly_primitives", stats.get("input_assembly_primitives") == 2 * 64 * 16, str(stats))

    # 6. Static mesh: one quad over [0.25, 0.75]^2 (object x, z).
    mesh = WORK + "/mesh"
    os.makedirs(mesh, exist_ok=True)
    write_f32(mesh + "/positions.f32", [0.25, 0, 0.25, 0.75, 0, 0.25, 0.75, 0, 0.75, 0.25, 0, 0.75])
    with open(mesh + "/indices.u32", "wb") as f:
        f.write(struct.pack("<6I", 0, 2, 1, 0, 3, 2))  # clockwise from above: Unity's front face
    p, l = run(["--static-mesh", "--mesh", mesh + "/positions.f32", mesh + "/indices.u32", "--vert", SPV + "/mesh.vert.spv",
                "--frag", SPV + "/mesh.frag.spv", "--buffers", d, "--width", "128", "--height", "128",
                "--frames", "3", "--timestamps"])
    check("static mesh runs", p.returncode == 0, p.stderr.strip())
    if p.returncode == 0:
        check("static mesh covers a quarter", int(value(l, "image", "nonsky_pixels")[0]) == 64 * 64, str(l.get("image")))
        check("static mesh prints times", value(l, "time", "frame_ms_median") is not None, str(l.get("time")))

    # 7. Wireframe draws lines only: something drawn, less than the filled image.
    p, l = run(tess_args(d, 4, extra=["--max-factor", "8", "--wireframe", "--png", WORK + "/wireframe.png"]))
    check("wireframe runs", p.returncode == 0, p.stderr.strip())
    if p.returncode == 0:
        nonsky = int(value(l, "image", "nonsky_pixels")[0])
        check("wireframe draws lines only", 0 < nonsky < 128 * 128, "nonsky %d" % nonsky)

    # 8. Errors: bad file size, missing split possibility, unknown device.
    bad = make_inputs(WORK + "/in_bad", 4, 8)
    write_f32(bad + "/params.f32", [0] * 39)
    p, l = run(tess_args(bad, 4))
    check("bad params size fails", p.returncode != 0 and "params.f32" in p.stderr and "176" in p.stderr, p.stderr)
    p, l = run(tess_args(d, 4, extra=["--device", "no-such-gpu-anywhere"]))
    check("unknown device fails", p.returncode != 0 and "no-such-gpu-anywhere" in p.stderr, p.stderr)
    p, l = run(tess_args(d, 4, extra=["--max-vertices-per-draw", "100", "--max-factor", "63"]))
    check("unsplittable patch fails", p.returncode != 0 and "per-draw limit" in p.stderr, p.stderr)

    compute_checks(lavapipe)
    image_checks()

    print("selftest %s (%d failed)" % ("PASSED" if failures == 0 else "FAILED", failures))
    sys.exit(1 if failures else 0)


main()
