"""Cases from Python: gjk2d.generate gives the cases `gjk-validate generate` writes, read_cases
and write_cases round-trip gjk-cases/1 files bit for bit, and a bad file or case raises
gjk2d.InputError (a ValueError) with the runner's one-line message naming file, case and field."""

import os
import subprocess

import numpy as np
import pytest

import gjk2d


def same_case(x, y):
    assert x["name"] == y["name"]
    for side in ("a", "b"):
        assert np.array_equal(x[side]["points"], y[side]["points"]), x["name"]
        for key in ("radius", "position", "rotation"):
            assert x[side][key] == y[side][key], (x["name"], side, key)


@pytest.mark.parametrize("family", ["random:50", "hard/sliver:7", "engine/pyramid-toi:20"])
def test_generate_gives_the_cases_of_gjk_validate_generate(tmp_path, family):
    path = tmp_path / "cases.json"
    subprocess.run([os.environ["GJK2D_VALIDATE"], "generate", "--family", family, "--seed", "9",
                    "--out", str(path)], check=True, stderr=subprocess.DEVNULL)
    name, count = family.split(":")
    mine = gjk2d.generate(name, seed=9, count=int(count))
    theirs = gjk2d.read_cases(str(path))
    assert len(mine) == len(theirs) == int(count)
    for x, y in zip(mine, theirs):
        same_case(x, y)


def test_families_lists_every_group():
    names = gjk2d.families()
    assert names[0] == "random"
    assert any(n.startswith("hard/") for n in names) and any(n.startswith("engine/") for n in names)
    for n in names:
        assert len(gjk2d.generate(n, count=1)) == 1


def test_write_then_read_round_trips(tmp_path):
    cases = gjk2d.generate("hard", count=1, seed=3)
    cases[0]["comment"] = "from Python"
    path = str(tmp_path / "out.json")
    gjk2d.write_cases(path, cases, comments=["a test"])
    back = gjk2d.read_cases(path)
    assert len(back) == len(cases)
    for x, y in zip(cases, back):
        same_case(x, y)
    assert back[0]["comment"] == "from Python"
    # The file is what gjk-validate runs: it reads it without a rejection.
    subprocess.run([os.environ["GJK2D_VALIDATE"], "run", "--cases", path, "--variants", "double",
                    "--no-timing", "--no-progress", "--out", str(tmp_path / "r")], check=True,
                   stdout=subprocess.DEVNULL)


def test_a_case_given_by_hand_is_written(tmp_path):
    path = str(tmp_path / "hand.json")
    case = {"name": "hand", "a": {"points": [[0, 0], [1, 0]]},
            "b": {"points": [[0, 2]], "radius": 0.5, "position": (1, 1), "rotation": (0, 1)}}
    gjk2d.write_cases(path, [case])
    (back,) = gjk2d.read_cases(path)
    assert back["b"]["radius"] == 0.5 and back["b"]["rotation"] == (0.0, 1.0)
    assert back["a"]["position"] == (0.0, 0.0)


def write(tmp_path, text):
    path = tmp_path / "bad.json"
    path.write_text(text)
    return str(path)


def test_a_rejected_case_raises_naming_file_case_and_field(tmp_path):
    path = write(tmp_path, '{"format": "gjk-cases/1", "cases": ['
                 '{"name": "ok", "a": {"points": [[0, 0]]}, "b": {"points": [[1, 0]]}},'
                 '{"name": "neg", "a": {"points": [[0, 0]], "radius": -1}, "b": {"points": [[1, 0]]}}]}')
    with pytest.raises(gjk2d.InputError, match=r"^bad\.json#1 \(case 'neg'\): a\.radius is negative"):
        gjk2d.read_cases(path)


def test_a_bad_file_raises_the_runners_message(tmp_path):
    path = write(tmp_path, '{"format": "gjk-cases/1", "cases": [')
    run = subprocess.run([os.environ["GJK2D_VALIDATE"], "run", "--cases", path, "--out",
                          str(tmp_path / "r")], capture_output=True, text=True)
    assert run.returncode == 2
    with pytest.raises(ValueError) as raised:
        gjk2d.read_cases(path)
    assert run.stderr.strip() == "gjk-validate: error: " + str(raised.value)
    assert str(raised.value).startswith(path + ":1:37: invalid JSON")
    with pytest.raises(ValueError, match="cannot open"):
        gjk2d.read_cases(str(tmp_path / "missing.json"))


def test_a_bad_case_dict_raises_naming_case_and_field(tmp_path):
    path = str(tmp_path / "w.json")
    good = {"name": "g", "a": {"points": [[0, 0]]}, "b": {"points": [[1, 0]]}}
    bad = {"name": "x", "a": {"points": [[0, 0]]}, "b": {"points": [[float("nan"), 0]]}}
    with pytest.raises(ValueError, match=r"^cases\[1\] \(case 'x'\)\.b\.points: "):
        gjk2d.write_cases(path, [good, bad])
    with pytest.raises(ValueError, match=r"^cases\[0\]\.b: missing"):
        gjk2d.write_cases(path, [{"name": "y", "a": good["a"]}])
    assert not os.path.exists(path)


def test_an_unknown_family_raises_the_runners_message():
    with pytest.raises(gjk2d.InputError, match="no-such"):
        gjk2d.generate("no-such")
