#!/usr/bin/env python3
"""No hand-written source file in src/ over 400 lines without its reason, and at most three such.

A file over the limit says why in its opening comment, in a line starting "Over 400 lines:".
Generated files (one of their first three lines says "generated") are not counted. Exit status 1 otherwise.
"""
import pathlib
import sys

LIMIT = 400
MAX_EXCEPTIONS = 3


def main():
    root = pathlib.Path(__file__).resolve().parent.parent / "src"
    long_files, missing = [], []
    for f in sorted(root.rglob("*")):
        if f.suffix not in (".h", ".cpp"):
            continue
        lines = f.read_text().splitlines()
        if len(lines) <= LIMIT or any("generated" in line.lower() for line in lines[:3]):
            continue
        opening = []
        for line in lines:
            if not line.startswith("//"):
                break
            opening.append(line)
        rel = f.relative_to(root.parent).as_posix()
        long_files.append(f"{rel} ({len(lines)} lines)")
        if not any("Over 400 lines:" in line for line in opening):
            missing.append(rel)
    for rel in missing:
        print(f"{rel}: over {LIMIT} lines with no 'Over 400 lines:' reason in its opening comment")
    if len(long_files) > MAX_EXCEPTIONS:
        print(f"check-file-length: {len(long_files)} files over {LIMIT} lines (at most "
              f"{MAX_EXCEPTIONS}): " + ", ".join(long_files))
    if not missing:
        print(f"check-file-length: {len(long_files)} hand-written file(s) over {LIMIT} lines, each "
              f"with its reason")
    return 1 if missing or len(long_files) > MAX_EXCEPTIONS else 0


if __name__ == "__main__":
    sys.exit(main())
