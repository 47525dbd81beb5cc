#!/usr/bin/env python3
"""Checks that every #include in src/ points down the layers (docs/architecture.md).

Each folder of src/ (and each module of src/analysis/) has a rank; a file may include headers of
its own folder and of folders of lower rank only. Prints every include that points up or sideways
and the count; exit status 1 when there is one.
"""
import pathlib
import re
import sys

# Folder -> rank. Readers and codecs at the bottom, the command line at the top.
RANKS = {
    "util": 0,
    "spectral": 1,
    "io": 2,
    "color": 3,
    "fresnel": 4,
    "brdf": 4,
    "fit": 5,
    # analysis/, module by module (its CMake libraries' link order)
    "analysis/pipeline": 6,
    "analysis/study": 7,
    "analysis/lut": 8,
    "analysis/basis": 9,
    "analysis/presets": 8,
    "analysis/ltc": 9,
    "analysis/shader": 9,
    "analysis/render": 9,
    "analysis/speed": 9,
    "analysis/consensus": 9,
    "analysis/plan": 10,
    "analysis/library": 10,
    "analysis/tables": 11,
    "draw": 12,
    "documents": 12,
    "jobs": 13,
    "cli": 14,
}


def folder_of(path):
    parts = pathlib.PurePosixPath(path).parts
    if not parts:
        return None
    if parts[0] == "analysis" and len(parts) > 2:
        return "analysis/" + parts[1]
    return parts[0] if len(parts) > 1 else None


def main():
    root = pathlib.Path(__file__).resolve().parent.parent / "src"
    include = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
    bad, checked, unknown = [], 0, set()
    for f in sorted(root.rglob("*")):
        if f.suffix not in (".h", ".cpp"):
            continue
        rel = f.relative_to(root).as_posix()
        mine = folder_of(rel)
        if mine is None:
            continue
        if mine not in RANKS:
            unknown.add(mine)
            continue
        for n, line in enumerate(f.read_text().splitlines(), 1):
            m = include.match(line)
            if not m:
                continue
            target = folder_of(m.group(1))
            if target is None or target == mine or not (root / m.group(1)).exists():
                continue  # the same folder, or a third-party header
            if target not in RANKS:
                unknown.add(target)
                continue
            checked += 1
            if RANKS[target] >= RANKS[mine]:
                bad.append(f"src/{rel}:{n}: {mine} (rank {RANKS[mine]}) includes {m.group(1)} "
                           f"({target}, rank {RANKS[target]})")
    for b in bad:
        print(b)
    for u in sorted(unknown):
        print(f"check-layers: folder {u} has no rank (add it to RANKS)")
    print(f"check-layers: {len(bad)} include(s) against the layers, of {checked} across folders")
    return 1 if bad or unknown else 0


if __name__ == "__main__":
    sys.exit(main())
