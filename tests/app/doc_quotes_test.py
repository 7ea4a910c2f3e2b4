#!/usr/bin/env python3
"""Quotes in the docs stay what the program prints.

- README.md quotes the paper scene's answer: it must be `summary.answer` of
  `vibro simulate --preset paper`, word for word (the event-time error included).
- docs/ACCURACY.md is written by scripts/accuracy_report.py: the script's fixed passages
  (TRUST_TEXT, DIFFERENTIAL_TEXT) must appear in the page as they are, so that an edit of one
  is made in the other.

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


def printed_answer(vibro):
    out = subprocess.run([vibro, "simulate", "--preset", "paper"], capture_output=True, text=True,
                         timeout=120, check=True)
    return words(json.loads(out.stdout)["summary"]["answer"])


def report_passages():
    src = open(os.path.join(ROOT, "scripts", "accuracy_report.py"), encoding="utf-8").read()
    return {name: re.search(name + r' = """\\\n(.*?)"""', src, re.S).group(1)
            for name in ("TRUST_TEXT", "DIFFERENTIAL_TEXT")}


def main():
    failures = 0
    quoted, printed = readme_answer(), printed_answer(sys.argv[1])
    if quoted == printed:
        print("PASS README quotes the paper scene's answer")
    else:
        print(f"FAIL README quotes the paper scene's answer\n  README: {quoted}\n  vibro:  {printed}")
        failures += 1
    page = open(os.path.join(ROOT, "docs", "ACCURACY.md"), encoding="utf-8").read()
    for name, passage in report_passages().items():
        if passage in page:
            print(f"PASS docs/ACCURACY.md holds accuracy_report.py's {name}")
        else:
            print(f"FAIL docs/ACCURACY.md differs from accuracy_report.py's {name}")
            failures += 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
