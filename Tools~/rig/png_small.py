#!/usr/bin/env python3
"""Rewrites a harness PNG (RGBA, stored deflate) as a small RGB PNG: alpha dropped (the harness
writes it opaque), rows filtered with PNG's Up/Sub/Paeth (the best per row by the usual sum of
absolute values), zlib level 9. Standard library only.

Usage: png_small.py IN.png OUT.png
"""
import struct, sys, zlib


def read_rgba(path):
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", f"{path}: not a PNG"
    i, idat, w, h = 8, b"", 0, 0
    while i < len(data):
        n, kind = struct.unpack(">I4s", data[i:i + 8])
        body = data[i + 8:i + 8 + n]
        if kind == b"IHDR":
            w, h, depth, colour = struct.unpack(">IIBB", body[:10])
            assert (depth, colour) == (8, 6), f"{path}: expected 8-bit RGBA"
        elif kind == b"IDAT":
            idat += body
        i += 12 + n
    raw = zlib.decompress(idat)
    stride = 1 + 4 * w
    rows = []
    for y in range(h):
        row = raw[y * stride:(y + 1) * stride]
        assert row[0] == 0, f"{path}: expected filter type None"
        rgba = row[1:]
        rows.append(bytes(b for k, b in enumerate(rgba) if k % 4 != 3))
    return w, h, rows


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    return a if pa <= pb and pa <= pc else (b if pb <= pc else c)


def filtered(row, prev, bpp=3):
    n = len(row)
    sub = bytes((row[k] - (row[k - bpp] if k >= bpp else 0)) & 255 for k in range(n))
    up = bytes((row[k] - prev[k]) & 255 for k in range(n))
    pa = bytes((row[k] - paeth(row[k - bpp] if k >= bpp else 0, prev[k], prev[k - bpp] if k >= bpp else 0)) & 255
               for k in range(n))
    cost = lambda f: sum(b if b < 128 else 256 - b for b in f)
    return min(((1, sub), (2, up), (4, pa)), key=lambda c: cost(c[1]))


def write_rgb(path, w, h, rows):
    out, prev = bytearray(), bytes(3 * w)
    for row in rows:
        kind, f = filtered(row, prev)
        out.append(kind)
        out += f
        prev = row
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(bytes(out), 9)) + chunk(b"IEND", b"")
    open(path, "wb").write(png)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    write_rgb(sys.argv[2], *read_rgba(sys.argv[1]))
