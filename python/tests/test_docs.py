"""docs/PYTHON.md and README.md: every ```python block runs, in order as a notebook's cells, and
PYTHON.md's make the figures the page shows."""

import os
import re
import subprocess
import sys

import pytest

from conftest import BUILD, HANG, ROOT
from doc_snippets import blocks

DOC = ROOT / "docs" / "PYTHON.md"


def run_snippets(doc, out):
    env = dict(os.environ, MPLBACKEND="Agg", PYTHONPATH=str(BUILD / "python"))
    done = subprocess.run(
        [sys.executable, str(ROOT / "python" / "tests" / "doc_snippets.py"), str(doc), str(out)],
        env=env,
        capture_output=True,
        text=True,
        timeout=HANG,
    )
    assert done.returncode == 0, done.stdout + done.stderr


def test_the_readmes_snippet_runs(tmp_path):
    assert len(blocks((ROOT / "README.md").read_text())) == 1
    run_snippets(ROOT / "README.md", tmp_path)


def test_the_snippets_run_and_draw_the_pages_figures(tmp_path):
    pytest.importorskip("matplotlib", reason="python3-matplotlib (scripts/setup.sh --test)")
    pytest.importorskip("pandas", reason="python3-pandas (scripts/setup.sh --test)")
    text = DOC.read_text()
    assert len(blocks(text)) >= 5
    run_snippets(DOC, tmp_path)
    shown = re.findall(r"\]\(images/(python-[^)]+)\)", text)
    assert shown, "the page shows no figure of its own"
    for name in shown:
        made = tmp_path / name
        assert made.exists() and made.stat().st_size > 1000, name
        assert (ROOT / "docs" / "images" / name).exists(), f"docs/images/{name}: scripts/figures.sh"
