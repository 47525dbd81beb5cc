#!/usr/bin/env python3
"""Clipped-pixel fraction of 8-bit RGB PNGs (what render writes): the share of pixels with any
channel at 255, over the whole image and over the pixels that differ from the top-left (background)
pixel. Standard library only.   scripts/clipped_fraction.py FILE.png..."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from png_rgb import read_png  # noqa: E402


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
