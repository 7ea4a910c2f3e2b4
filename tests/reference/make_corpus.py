#!/usr/bin/env python3
"""Writes the reference simulator's answer for every scene of the regression corpus.

Usage: /usr/bin/python3 tests/reference/make_corpus.py
Each tests/reference/corpus/NAME.json (a scene the engine once got wrong, found by this
reference or by the differential tests) gets tests/reference/corpus/expected/NAME.json: the
reference's events and final states at rtol 1e-12, which the engine's test (core_test,
ReferenceCorpus) compares event by event under every method.
"""
import glob
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import vibro_ref  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    out_dir = os.path.join(HERE, "corpus", "expected")
    os.makedirs(out_dir, exist_ok=True)
    for path in sorted(glob.glob(os.path.join(HERE, "corpus", "*.json"))):
        name = os.path.splitext(os.path.basename(path))[0]
        with open(path) as f:
            scene = json.load(f)
        ref = vibro_ref.simulate(scene, rtol=1e-12, atol=1e-14)
        if ref.get("unsupported"):
            sys.exit(f"{name}: the reference cannot run it: {ref['unsupported']}")
        expected = {"events": ref["events"], "final": ref["final"]}
        with open(os.path.join(out_dir, name + ".json"), "w") as f:
            json.dump(expected, f, indent=1)
        print(f"{name}: {len(ref['events'])} events")


if __name__ == "__main__":
    main()
