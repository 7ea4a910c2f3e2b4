"""Runs the ```python code blocks of a markdown file in order, in one namespace, as a notebook
runs its cells, in the directory OUT (where the figures the blocks save land).

Usage: /usr/bin/python3 python/tests/doc_snippets.py DOC.md [OUT]
scripts/figures.sh runs docs/PYTHON.md so into docs/images; test_docs.py into a scratch folder.
"""

import os
import pathlib
import re
import sys

BLOCK = re.compile(r"^```python\n(.*?)^```", re.S | re.M)


def blocks(markdown):
    """The code of each ```python block, in order."""
    return BLOCK.findall(markdown)


def run(doc, out):
    doc = pathlib.Path(doc).resolve()
    namespace = {"__name__": "__main__"}
    os.chdir(out)
    for k, code in enumerate(blocks(doc.read_text()), start=1):
        exec(compile(code, f"{doc.name}, block {k}", "exec"), namespace)


if __name__ == "__main__":
    os.environ.setdefault("MPLBACKEND", "Agg")
    run(sys.argv[1], sys.argv[2] if len(sys.argv) > 2 else ".")
