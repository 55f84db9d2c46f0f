#!/usr/bin/env python3
"""Rewrites an 8-bit RGB, RGBA or indexed PNG as an indexed PNG of at most N colours (default 64:
renders and plots show no banding at 64, and the pictures are a quarter smaller than at 256),
to keep the manual's pictures small: the palette by median cut over the picture's colours (weighted
by how often each occurs), each pixel mapped to the nearest palette colour, no dithering (renders and
plots have smooth shading or flat areas, which dithering only makes noisier), zlib level 9, then optipng. An
indexed picture of at most N colours comes back with the same pixels (re-encoding it is lossless).
Transparent pixels are composed over white. --half first averages each 2 x 2 block (a thumbnail at
half the width and height). The palette in median-cut order or by brightness (neighbouring pixels of a
smooth shade then have neighbouring indices), the rows with no filter or with each row's best
filter: whichever of the four compresses smallest. Standard library only.

Usage: png_palette.py IN.png OUT.png [COLOURS] [--half]
"""
import shutil, struct, subprocess, sys, zlib
from collections import Counter


def read_rgb(path):
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", f"{path}: not a PNG"
    i, idat, w, h, colour, plte = 8, b"", 0, 0, 0, b""
    while i < len(data):
        n, kind = struct.unpack(">I4s", data[i:i + 8])
        body = data[i + 8:i + 8 + n]
        if kind == b"IHDR":
            w, h, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and colour in (2, 3, 6) and interlace == 0, f"{path}: expected 8-bit RGB, RGBA or indexed, not interlaced"
        elif kind == b"PLTE":
            plte = body
        elif kind == b"IDAT":
            idat += body
        i += 12 + n
    bpp = {2: 3, 3: 1, 6: 4}[colour]
    raw, stride = zlib.decompress(idat), 1 + bpp * w
    prev, pixels = bytearray(bpp * w), []
    for y in range(h):
        kind, row = raw[y * stride], bytearray(raw[y * stride + 1:(y + 1) * stride])
        for k in range(len(row)):
            a = row[k - bpp] if k >= bpp else 0
            b, c = prev[k], (prev[k - bpp] if k >= bpp else 0)
            if kind == 1: row[k] = (row[k] + a) & 255
            elif kind == 2: row[k] = (row[k] + b) & 255
            elif kind == 3: row[k] = (row[k] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                row[k] = (row[k] + (a if pa <= pb and pa <= pc else (b if pb <= pc else c))) & 255
            else: assert kind == 0, f"{path}: unknown filter {kind}"
        prev = row
        for x in range(w):
            px = row[bpp * x:bpp * x + bpp]
            if bpp == 1:
                px = plte[3 * px[0]:3 * px[0] + 3]
            elif bpp == 4:  # over white
                al = px[3]
                px = bytes((v * al + 255 * (255 - al) + 127) // 255 for v in px[:3])
            pixels.append(bytes(px[:3]))
    return w, h, pixels


def half(w, h, pixels):
    """Each 2 x 2 block averaged (rounded); an odd last row or column is dropped."""
    w2, h2, out = w // 2, h // 2, []
    for y in range(h2):
        for x in range(w2):
            q = (pixels[2 * y * w + 2 * x], pixels[2 * y * w + 2 * x + 1], pixels[(2 * y + 1) * w + 2 * x], pixels[(2 * y + 1) * w + 2 * x + 1])
            out.append(bytes((sum(p[ch] for p in q) + 2) // 4 for ch in range(3)))
    return w2, h2, out


def median_cut(counts, n):
    boxes = [list(counts.items())]
    while len(boxes) < n:
        # split the box with the widest channel range, weighted by its pixel count
        best, key = None, -1
        for bi, box in enumerate(boxes):
            if len(box) < 2: continue
            spread = max(max(c[ch] for c, _ in box) - min(c[ch] for c, _ in box) for ch in range(3))
            score = spread * sum(k for _, k in box)
            if score > key: best, key = bi, score
        if best is None: break
        box = boxes.pop(best)
        ch = max(range(3), key=lambda ch: max(c[ch] for c, _ in box) - min(c[ch] for c, _ in box))
        box.sort(key=lambda e: e[0][ch])
        total, acc, cut = sum(k for _, k in box), 0, 1
        for j, (_, k) in enumerate(box):
            acc += k
            if acc >= total / 2: cut = max(1, min(len(box) - 1, j + 1)); break
        boxes += [box[:cut], box[cut:]]
    palette = []
    for box in boxes:
        t = sum(k for _, k in box)
        palette.append(bytes(round(sum(c[ch] * k for c, k in box) / t) for ch in range(3)))
    return palette


def write_indexed(path, w, h, pixels, palette):
    """The smallest of: the palette in median-cut order or by brightness, each with no filter or each row's best."""
    by_brightness = sorted(palette, key=lambda c: (c[0] * 3 + c[1] * 4 + c[2] * 2, c))
    png = min((encode_indexed(w, h, pixels, p) for p in (palette, by_brightness)), key=len)
    open(path, "wb").write(png)


def encode_indexed(w, h, pixels, palette):
    index, cache = bytearray(), {}
    for px in pixels:
        j = cache.get(px)
        if j is None:
            j = min(range(len(palette)), key=lambda i: (palette[i][0] - px[0]) ** 2 * 3 + (palette[i][1] - px[1]) ** 2 * 4 + (palette[i][2] - px[2]) ** 2 * 2)
            cache[px] = j
        index.append(j)
    def filtered(row, prev, kind):  # PNG filter types 0-4 for one byte a pixel
        out = bytearray(w)
        for k in range(w):
            a, b, c = (row[k - 1] if k else 0), prev[k], (prev[k - 1] if k else 0)
            if kind == 0: p = 0
            elif kind == 1: p = a
            elif kind == 2: p = b
            elif kind == 3: p = (a + b) // 2
            else:
                e = a + b - c
                p = a if abs(e - a) <= abs(e - b) and abs(e - a) <= abs(e - c) else (b if abs(e - b) <= abs(e - c) else c)
            out[k] = (row[k] - p) & 255
        return out
    plain, adaptive, prev = bytearray(), bytearray(), bytearray(w)
    for y in range(h):
        row = index[y * w:(y + 1) * w]
        plain += b"\0" + row
        # each row's filter by the usual heuristic: the smallest sum of the bytes read as signed
        kind, best = min(((k, filtered(row, prev, k)) for k in range(5)), key=lambda kb: sum(min(v, 256 - v) for v in kb[1]))
        adaptive += bytes([kind]) + best
        prev = row
    idat = min((zlib.compress(bytes(plain), 9), zlib.compress(bytes(adaptive), 9)), key=len)
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 3, 0, 0, 0))
    png += chunk(b"PLTE", b"".join(palette)) + chunk(b"IDAT", idat) + chunk(b"IEND", b"")
    return png


def recompress(path):
    """optipng's lossless search (gt setup installs it) takes another 5% off the manual's pictures,
    which count against the package's size limit (PackageSizeTests)."""
    if shutil.which("optipng") is None:
        sys.exit("optipng is missing: run gt setup")
    subprocess.run(["optipng", "-quiet", "-o5", "-strip", "all", path], check=True)


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if a != "--half"]
    if len(args) not in (2, 3):
        sys.exit(__doc__)
    colours = int(args[2]) if len(args) == 3 else 64
    if not 2 <= colours <= 256:
        sys.exit(f"COLOURS ({colours}) must lie in [2, 256]")
    w, h, pixels = read_rgb(args[0])
    if "--half" in sys.argv[1:]:
        w, h, pixels = half(w, h, pixels)
    write_indexed(args[1], w, h, pixels, median_cut(Counter(pixels), colours))
    recompress(args[1])
