#!/usr/bin/env python3
"""Clipped-pixel fraction of 8-bit RGB PNGs (what render writes): the share of pixels with any
channel at 255, over the whole image and over the pixels that differ from the top-left (background)
pixel. Standard library only.   scripts/clipped_fraction.py FILE.png..."""
import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and colour == 2 and interlace == 0, f"{path}: not 8-bit RGB"
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw, stride, rows, prev = zlib.decompress(idat), 3 * width, [], bytearray(3 * width)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - 3] if i >= 3 else 0
            b, c = prev[i], prev[i - 3] if i >= 3 else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return width, height, rows


for path in sys.argv[1:]:
    w, h, rows = read_png(path)
    bg = tuple(rows[0][0:3])
    total = clipped = fg = fg_clipped = 0
    for line in rows:
        for x in range(w):
            px = tuple(line[3 * x:3 * x + 3])
            hit = 255 in px
            total += 1
            clipped += hit
            if px != bg:
                fg += 1
                fg_clipped += hit
    print(f"{path}: {clipped}/{total} = {clipped / total:.4f} of all pixels clipped; "
          f"{fg_clipped}/{fg} = {fg_clipped / max(fg, 1):.4f} of non-background pixels")
