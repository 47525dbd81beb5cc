#!/usr/bin/env python3
"""Banding in a flip: distinct colours in a smooth region of one frame, against the lossless PNG.

Decodes the flip (FILE.flip.webp or FILE.flip.gif of `render --compare`) into PNG frames with
bench/flip_frames, then counts the distinct colours in a region of frame 0 (the ground truth) and,
with --reference, in the same region of the truth PNG (FILE.truth.png, the lossless picture). A
palette that bands the region has far fewer colours than the PNG; a lossless flip has as many.
A dithered palette has few colours too, but keeps the region's local means: the script also gives
the largest error of a 5 × 5 block's mean colour against the PNG's.

  scripts/flip_banding.py FLIP [--reference FILE.truth.png] [--frame N] [--region X0,Y0,X1,Y1]
                          [--tool build/bench/flip_frames]

The region is given in fractions of the frame's width (the render is the top square of a frame),
so it covers the same part of the sphere at any size; the default, 0.30,0.10,0.70,0.40, is the sky
above the horizon in the sphere's upper middle under scripts/lookdev.sh's sunset.
Standard library only (PNGs decoded by png_rgb.py beside it).
"""
import argparse
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from png_rgb import read_png  # noqa: E402


def box(width, region):
    return tuple(int(round(f * width)) for f in region)


def distinct_colours(rows, b):
    x0, y0, x1, y1 = b
    return len({rows[y][3 * x:3 * x + 3] for y in range(y0, y1) for x in range(x0, x1)})


def local_mean_error(rows, ref, b, n=5):
    """Largest |mean of an n × n block − the reference's| (codes, any channel) over the region:
    banding moves a block's mean, dithering keeps it."""
    x0, y0, x1, y1 = b
    worst = 0.0
    for y in range(y0, y1 - n + 1, n):
        for x in range(x0, x1 - n + 1, n):
            for c in range(3):
                a = sum(rows[y + j][3 * (x + i) + c] for j in range(n) for i in range(n))
                r = sum(ref[y + j][3 * (x + i) + c] for j in range(n) for i in range(n))
                worst = max(worst, abs(a - r) / (n * n))
    return worst


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("flip")
    ap.add_argument("--reference", help="the lossless truth PNG of the same render")
    ap.add_argument("--frame", type=int, default=0)
    ap.add_argument("--region", default="0.30,0.10,0.70,0.40")
    ap.add_argument("--tool", default="build/bench/flip_frames")
    args = ap.parse_args()
    region = [float(v) for v in args.region.split(",")]
    with tempfile.TemporaryDirectory() as tmp:
        listing = subprocess.run([args.tool, args.flip, os.path.join(tmp, "frame")], check=True,
                                 capture_output=True, text=True).stdout.split("\n")
        frames = sum(1 for line in listing if line and not line.startswith("loop"))
        width, _, rows = read_png(os.path.join(tmp, f"frame-{args.frame}.png"))
    b = box(width, region)
    print(f"{args.flip}: {os.path.getsize(args.flip)} bytes, {frames} frames; frame {args.frame}, "
          f"pixels x {b[0]}-{b[2]}, y {b[1]}-{b[3]}: {distinct_colours(rows, b)} distinct colours")
    if args.reference:
        _, _, ref = read_png(args.reference)
        print(f"{args.reference}: same region: {distinct_colours(ref, b)} distinct colours; "
              f"the frame's largest 5 × 5 block mean error there: "
              f"{local_mean_error(rows, ref, b):.2f} codes")


if __name__ == "__main__":
    main()
