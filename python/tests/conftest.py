"""Shared fixtures: gjk-validate's per-case answers (cases.jsonl) on the default campaign's kinds
of input, which the tests compare gjk2d against. CTest sets GJK2D_VALIDATE (the program) and
GJK2D_BUILD (the build tree, whose validation/cases links the default case files)."""

import glob
import json
import os
import subprocess

import pytest

import gjk2d

# The default campaign is `random:200000`, `hard` (every sub-family at its built-in count), `engine`
# (2000 per engine family) and the default case files. The tests take every family and every file,
# with fewer random and engine cases, so that they run in seconds.
FAMILIES = ["random:4000", "hard", "engine:300"]


def default_case_files():
    return sorted(
        glob.glob(os.path.join(os.environ["GJK2D_BUILD"], "validation", "cases", "*.json"))
    )


@pytest.fixture(scope="session")
def campaign(tmp_path_factory):
    """(cases by name, gjk-validate's cases.jsonl lines by name) for the double and float variants."""
    out = tmp_path_factory.mktemp("campaign") / "report"
    args = [
        os.environ["GJK2D_VALIDATE"],
        "run",
        "--variants",
        "double,float",
        "--per-case",
        "--no-timing",
        "--no-progress",
        "--out",
        str(out),
    ]
    for f in FAMILIES:
        args += ["--family", f]
    for f in default_case_files():
        args += ["--cases", f]
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    cases = {}
    for f in FAMILIES:
        name, count = f.split(":") if ":" in f else (f, None)
        for c in gjk2d.generate(name, seed=1, count=None if count is None else int(count)):
            cases[c["name"]] = c
    for f in default_case_files():
        for c in gjk2d.read_cases(f):
            cases[c["name"]] = c
    with open(out / "cases.jsonl") as lines:
        answers = {a["name"]: a for a in map(json.loads, lines)}
    assert len(answers) == len(cases) > 7500
    return cases, answers
