#!/usr/bin/env python3
"""Quotes in the docs stay what the program prints.

- README.md quotes the paper scene's answer: it must be `summary.answer` of
  `vibro simulate --preset paper`, word for word (the event-time error included); and the
  preset's impacts per limiter and pellet where it states how far it is from the paper's run.
- Preset descriptions say what the preset's run does: high-frequency never sticks or releases
  (no such event in its run), impact-oscillator is a pendulum forced along its circle, not at its
  pivot.
- docs/ACCURACY.md is written by scripts/accuracy_report.py: the script's fixed passages
  (TRUST_TEXT, DIFFERENTIAL_TEXT) must appear in the page as they are, so that an edit of one
  is made in the other; and the tables of the long forced run and of the extremes, remade by the
  script's own functions, must be the page's but for their wall times.

Usage: doc_quotes_test.py path/to/vibro
"""
import json
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def words(text):
    return " ".join(text.split())


def readme_answer():
    text = open(os.path.join(ROOT, "README.md"), encoding="utf-8").read()
    after = text.split("The paper scene's answer", 1)[1]
    quote = re.search(r"((?:^> .*\n)+)", after, re.M).group(1)
    return words(re.sub(r"^> ", "", quote, flags=re.M))


def paper_summary(vibro):
    out = subprocess.run([vibro, "simulate", "--preset", "paper"], capture_output=True, text=True,
                         timeout=120, check=True)
    return json.loads(out.stdout)["summary"]


def printed_answer(vibro):
    return words(paper_summary(vibro)["answer"])


def readme_gap(vibro):
    """The README's `impacts_by_limiter` of the paper preset, and the program's."""
    text = open(os.path.join(ROOT, "README.md"), encoding="utf-8").read()
    quoted = re.search(r"`summary\.impacts_by_limiter`, per limiter and pellet: `([^`]*)`", text)
    return (json.loads(quoted.group(1)) if quoted else None,
            paper_summary(vibro)["impacts_by_limiter"])


def descriptions_true(vibro):
    """Why a preset's description is not what its run does; empty when all are."""
    wrong = []
    def preset(name):
        return json.loads(subprocess.run([vibro, "preset", name], capture_output=True, text=True,
                                         timeout=60, check=True).stdout)
    high = preset("high-frequency")
    run = json.loads(subprocess.run([vibro, "simulate", "--preset", "high-frequency", "--no-check"],
                                    capture_output=True, text=True, timeout=120, check=True).stdout)
    kinds = {e["kind"] for e in run["events"]}
    if kinds & {"stick", "release"} or "never sticks" not in high["description"]:
        wrong.append(f"high-frequency: events {sorted(kinds)}, described: {high['description']}")
    oscillator = preset("impact-oscillator")["description"]
    if "pivot" in oscillator or "forced pendulum" not in oscillator:
        wrong.append(f"impact-oscillator: {oscillator}")
    return wrong


def report_passages():
    src = open(os.path.join(ROOT, "scripts", "accuracy_report.py"), encoding="utf-8").read()
    return {name: re.search(name + r' = """\\\n(.*?)"""', src, re.S).group(1)
            for name in ("TRUST_TEXT", "DIFFERENTIAL_TEXT")}


def rows(table):
    return [[c.strip() for c in line.strip().strip("|").split("|")] for line in table.strip().splitlines()]


def same_but_wall_times(made, quoted):
    """Whether two markdown tables agree but for their wall-time column, the only one a machine
    moves. A row the fresh run ended at its deadline, or whose trust check it cut short (no error
    estimate where the quoted row has one), is not compared: a loaded machine."""
    made, quoted = rows(made), rows(quoted)
    if len(made) != len(quoted) or made[0] != quoted[0]:
        return False
    wall = made[0].index("wall ms")
    for a, b in zip(made[2:], quoted[2:]):
        if a[1].startswith("deadline") or (a[-1] == "—" and b[-1] != "—"):
            print(f"  skipped (its run or its check reached the deadline here): {a[0]}")
            continue
        if a[:wall] + a[wall + 1:] != b[:wall] + b[wall + 1:]:
            print(f"  made:   {a}\n  quoted: {b}")
            return False
    return True


def page_table(page, header):
    start = page.index(header)
    end = page.find("\n\n", start)
    return page[start:end if end >= 0 else len(page)]


def report_tables(vibro):
    """The long-run and extremes tables as scripts/accuracy_report.py makes them with `vibro`."""
    sys.dont_write_bytecode = True  # nothing written into the source tree
    sys.path.insert(0, os.path.join(ROOT, "scripts"))
    argv, sys.argv = sys.argv, ["accuracy_report.py", "--vibro", vibro]
    try:
        import accuracy_report
    finally:
        sys.argv = argv
    return {"long forced run": accuracy_report.long_runs()[1], "extremes": accuracy_report.extremes()}


def main():
    failures = 0
    quoted, printed = readme_answer(), printed_answer(sys.argv[1])
    if quoted == printed:
        print("PASS README quotes the paper scene's answer")
    else:
        print(f"FAIL README quotes the paper scene's answer\n  README: {quoted}\n  vibro:  {printed}")
        failures += 1
    quoted, counted = readme_gap(sys.argv[1])
    if quoted == counted:
        print("PASS README states the paper preset's impacts per limiter and pellet")
    else:
        print(f"FAIL README states the paper preset's impacts per limiter\n  README: {quoted}\n"
              f"  vibro:  {counted}")
        failures += 1
    wrong = descriptions_true(sys.argv[1])
    if not wrong:
        print("PASS preset descriptions say what their runs do")
    else:
        print("FAIL preset descriptions:\n  " + "\n  ".join(wrong))
        failures += 1
    page = open(os.path.join(ROOT, "docs", "ACCURACY.md"), encoding="utf-8").read()
    for name, passage in report_passages().items():
        if passage in page:
            print(f"PASS docs/ACCURACY.md holds accuracy_report.py's {name}")
        else:
            print(f"FAIL docs/ACCURACY.md differs from accuracy_report.py's {name}")
            failures += 1
    for name, table in report_tables(sys.argv[1]).items():
        header = table.splitlines()[0]
        if same_but_wall_times(table, page_table(page, header)):
            print(f"PASS docs/ACCURACY.md's {name} table is what accuracy_report.py makes")
        else:
            print(f"FAIL docs/ACCURACY.md's {name} table differs from accuracy_report.py's:\n{table}")
            failures += 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
