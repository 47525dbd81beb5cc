#!/usr/bin/env python3
"""Lists every function body in src/ longer than a limit (default 60 lines) and exits 1 if any.

A brace-matching scanner over the .cpp and .h files, run after clang-format: comments, string
and character literals (raw strings included) and preprocessor lines are blanked, then every
top-level `{ ... }` block whose opening brace follows a parameter list `)` (optionally followed by
qualifiers, `-> type`, `noexcept`, `override`, a constructor's initializer list) is a function
body. Namespace, class, struct, enum and initializer braces are descended into, so member
functions and functions in namespaces are found; lambdas count as part of the function that
holds them. A body's length is the number of lines from the line of its opening brace to the
line of its closing brace, inclusive.

    scripts/check-function-length.py [--max N] [PATH...]   (default PATH: src)
"""
import argparse
import os
import re
import sys


def blank(text):
    """Comments, literals and preprocessor lines replaced by spaces (newlines kept)."""
    out = []
    i, n = 0, len(text)
    at_line_start = True
    while i < n:
        c = text[i]
        if at_line_start and c == "#":
            j = i
            while j < n:  # a directive, with its continuation lines
                if text[j] == "\n" and text[j - 1] != "\\":
                    break
                j += 1
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
            continue
        if c == "\n":
            at_line_start = True
            out.append(c)
            i += 1
            continue
        if not c.isspace():
            at_line_start = False
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == "R" and text.startswith('R"', i) and (i == 0 or not text[i - 1].isalnum()):
            open_paren = text.find("(", i + 2)
            delim = text[i + 2:open_paren]
            j = text.find(")" + delim + '"', open_paren)
            j = n if j < 0 else j + len(delim) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            if c == "'" and i > 0 and text[i - 1].isalnum():  # a digit separator: 1'000
                out.append(c)
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(" " * (min(j + 1, n) - i))
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


QUALIFIERS = re.compile(
    r"(\s|const\b|noexcept\b|override\b|final\b|mutable\b|&|->\s*[\w:<>,\s\*&]+|"
    r"requires\b[^{;]*)*$"
)


def is_function_body(before):
    """Whether the code before a `{` ends a function head."""
    s = before.rstrip()
    # A constructor's initializer list: `) : a_(x), b_{y} {` -> look before the ':'.
    m = re.search(r"\)\s*(noexcept\s*)?:\s*[\w:]+\s*[({][^;{}]*$", s)
    if m:
        return True
    m = QUALIFIERS.search(s)
    head = s[: m.start()] if m else s
    if not head.endswith(")"):
        return False
    # Control statements and lambdas are not function heads: find the matching '('.
    depth, k = 0, len(head) - 1
    while k >= 0:
        if head[k] == ")":
            depth += 1
        elif head[k] == "(":
            depth -= 1
            if depth == 0:
                break
        k -= 1
    word = re.search(r"([\w:~<>\]=!+\-*/\[]+)\s*$", head[:k])
    if not word:
        return False
    name = word.group(1)
    if name in ("if", "for", "while", "switch", "catch", "return", "sizeof", "decltype"):
        return False
    if name.endswith("]") or name == "=":  # a lambda's capture list, or `= (...)`
        return False
    return True


def functions(text):
    """(first line, last line) of every function body in `text`."""
    code = blank(text)
    found = []
    stack = []  # per open brace: whether it opened a function body
    line = 1
    start_line = []
    last_stmt = 0  # index just after the last ';', '{' or '}' at the current level
    for i, c in enumerate(code):
        if c == "\n":
            line += 1
        elif c == "{":
            inside_function = any(stack)
            body = not inside_function and is_function_body(code[last_stmt:i])
            stack.append(body)
            start_line.append(line)
            last_stmt = i + 1
        elif c == "}":
            if stack:
                body = stack.pop()
                first = start_line.pop()
                if body:
                    found.append((first, line))
            last_stmt = i + 1
        elif c == ";":
            last_stmt = i + 1
    return found


def name_of(text_lines, first):
    for k in range(first - 1, max(first - 6, -1), -1):
        m = re.search(r"([\w:~]+)\s*\(", text_lines[k])
        if m:
            return m.group(1)
    return "?"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--max", type=int, default=60)
    ap.add_argument("paths", nargs="*", default=["src"])
    args = ap.parse_args()
    files = []
    for p in args.paths:
        if os.path.isfile(p):
            files.append(p)
        for root, _, names in os.walk(p):
            files += [os.path.join(root, f) for f in names if f.endswith((".cpp", ".h"))]
    over = []
    for path in sorted(files):
        with open(path, encoding="utf-8") as f:
            text = f.read()
        lines = text.split("\n")
        for first, last in functions(text):
            length = last - first + 1
            if length > args.max:
                over.append((path, first, length, name_of(lines, first)))
    for path, first, length, name in over:
        print(f"{path}:{first}: {name}: {length} lines (limit {args.max})")
    print(f"check-function-length: {len(over)} function(s) over {args.max} lines in "
          f"{len(files)} files", file=sys.stderr)
    return 1 if over else 0


if __name__ == "__main__":
    sys.exit(main())
