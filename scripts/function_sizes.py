#!/usr/bin/env python3
"""Lists the functions in C++ files longer than a limit, longest first, and the files' sizes.

A function is a line at column 0 that ends in '{' (or a member function indented two spaces in a
header) and runs to its closing brace at the same indentation: the house format (.clang-format)
puts them there. Usage: scripts/function_sizes.py [--limit 60] DIR...
"""
import argparse
import os
import re

SKIP = ("if ", "for ", "while ", "switch ", "}", "//", "#", "namespace", "struct ", "class ",
        "enum ", "public", "private", "protected", "template", "using ", "return", "case ")


def functions(path):
    lines = open(path, encoding="utf-8").read().split("\n")
    k = 0
    while k < len(lines):
        line = lines[k]
        indent = line[: len(line) - len(line.lstrip())]
        if len(indent) in (0, 2) and line.strip() and not line.lstrip().startswith(SKIP):
            j = k
            while j < min(k + 8, len(lines)) and not lines[j].rstrip().endswith(("{", ";", "}")):
                j += 1
            head = " ".join(x.strip() for x in lines[k : j + 1])
            if j < len(lines) and lines[j].rstrip().endswith("{") and "(" in head and "=" not in head.split("(")[0]:
                end = j + 1
                while end < len(lines) and lines[end] not in (indent + "}", indent + "};"):
                    end += 1
                name = head.split("(")[0].split()[-1] if head.split("(")[0].split() else "?"
                yield name, k + 1, end - k + 1
                k = end
        k += 1


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--limit", type=int, default=60)
    ap.add_argument("dirs", nargs="+")
    a = ap.parse_args()
    long, sizes = [], []
    for d in a.dirs:
        for root, _, files in os.walk(d):
            for f in files:
                if f.endswith((".h", ".cpp")):
                    p = os.path.join(root, f)
                    sizes.append((sum(1 for _ in open(p, encoding="utf-8")), p))
                    long += [(n, p, line, name) for name, line, n in functions(p) if n > a.limit]
    for n, p, line, name in sorted(long, reverse=True):
        print(f"{n:5d}  {p}:{line}  {name}")
    print(f"{len(long)} functions over {a.limit} lines; largest files:")
    for n, p in sorted(sizes, reverse=True)[:8]:
        print(f"{n:5d}  {p}")


if __name__ == "__main__":
    main()
