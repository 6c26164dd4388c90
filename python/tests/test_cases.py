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
    subprocess.run(
        [
            os.environ["GJK2D_VALIDATE"],
            "generate",
            "--family",
            family,
            "--seed",
            "9",
            "--out",
            str(path),
        ],
        check=True,
        stderr=subprocess.DEVNULL,
    )
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
    subprocess.run(
        [
            os.environ["GJK2D_VALIDATE"],
            "run",
            "--cases",
            path,
            "--variants",
            "double",
            "--no-timing",
            "--no-progress",
            "--out",
            str(tmp_path / "r"),
        ],
        check=True,
        stdout=subprocess.DEVNULL,
    )


def test_a_case_given_by_hand_is_written(tmp_path):
    path = str(tmp_path / "hand.json")
    case = {
        "name": "hand",
        "a": {"points": [[0, 0], [1, 0]]},
        "b": {"points": [[0, 2]], "radius": 0.5, "position": (1, 1), "rotation": (0, 1)},
    }
    gjk2d.write_cases(path, [case])
    (back,) = gjk2d.read_cases(path)
    assert back["b"]["radius"] == 0.5 and back["b"]["rotation"] == (0.0, 1.0)
    assert back["a"]["position"] == (0.0, 0.0)


def write(tmp_path, text):
    path = tmp_path / "bad.json"
    path.write_text(text)
    return str(path)


def test_a_rejected_case_raises_naming_file_case_and_field(tmp_path):
    path = write(
        tmp_path,
        '{"format": "gjk-cases/1", "cases": ['
        '{"name": "ok", "a": {"points": [[0, 0]]}, "b": {"points": [[1, 0]]}},'
        '{"name": "neg", "a": {"points": [[0, 0]], "radius": -1}, "b": {"points": [[1, 0]]}}]}',
    )
    with pytest.raises(
        gjk2d.InputError, match=r"^bad\.json#1 \(case 'neg'\): a\.radius is negative"
    ):
        gjk2d.read_cases(path)


def test_a_bad_file_raises_the_runners_message(tmp_path):
    path = write(tmp_path, '{"format": "gjk-cases/1", "cases": [')
    run = subprocess.run(
        [os.environ["GJK2D_VALIDATE"], "run", "--cases", path, "--out", str(tmp_path / "r")],
        capture_output=True,
        text=True,
    )
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


def bits(v):
    return np.asarray(v, dtype=np.float64).view(np.uint64)


def columns_of(cases):
    """The array form of write_cases, built from case dicts (as a user's NumPy arrays would be)."""

    def shape(side):
        return {
            "points": np.concatenate([c[side]["points"] for c in cases]),
            "counts": np.array([len(c[side]["points"]) for c in cases]),
            "radius": np.array([c[side]["radius"] for c in cases]),
            "position": np.array([c[side]["position"] for c in cases]),
            "rotation": np.array([c[side]["rotation"] for c in cases]),
        }

    return {
        "names": [c["name"] for c in cases],
        "a": shape("a"),
        "b": shape("b"),
        "source": [c["source"] for c in cases],
        "comment": [c["comment"] for c in cases],
    }


@pytest.mark.parametrize("fmt", ["json", "msgpack"])
def test_numpy_columns_write_the_same_cases_as_dicts(tmp_path, fmt):
    # Float values (the engine families record floats) and doubles; radius, rotations, provenance.
    cases = gjk2d.generate("engine/container-proximity", count=40, seed=4) + gjk2d.generate(
        "random", count=40, seed=4
    )
    cases[3]["source"], cases[5]["comment"] = "https://example.org/3", "\u00e9 five"
    by_dicts, by_columns = str(tmp_path / "d"), str(tmp_path / ("c." + fmt))
    gjk2d.write_cases(by_dicts, cases, comments=["x"], format="json")
    gjk2d.write_cases(by_columns, columns_of(cases), comments=["x"], format=fmt)
    x, y = gjk2d.read_cases(by_dicts), gjk2d.read_cases(by_columns)
    assert len(x) == len(y) == len(cases)
    for p, q in zip(x, y):
        same_case(p, q)
        assert (p["source"], p["comment"]) == (q["source"], q["comment"])
        for side in ("a", "b"):
            assert np.array_equal(bits(p[side]["points"]), bits(q[side]["points"]))
            assert bits(p[side]["radius"]) == bits(q[side]["radius"])
            assert np.array_equal(bits(p[side]["rotation"]), bits(q[side]["rotation"]))


def test_binary_file_layout_read_independently(tmp_path):
    """The documented layout (docs/case-files.md, "Binary case files"), decoded by python3-msgpack
    and NumPy alone, gives the cases of the JSON file that gjk-validate writes for the same seed."""
    msgpack = pytest.importorskip("msgpack")
    js, mp = tmp_path / "r.json", tmp_path / "r.bin"
    for path, fmt in ((js, "json"), (mp, "msgpack")):
        subprocess.run(
            [
                os.environ["GJK2D_VALIDATE"],
                "generate",
                "--family",
                "engine/bullets-toi:30",
                "--family",
                "random:20",
                "--seed",
                "2",
                "--format",
                fmt,
                "--out",
                str(path),
            ],
            check=True,
            stderr=subprocess.DEVNULL,
        )
    want = gjk2d.read_cases(str(js))
    with open(mp, "rb") as f:
        u = msgpack.Unpacker(f, raw=False)
        header = next(u)
        assert header["format"] == "gjk-cases-msgpack/1" and len(header["comments"]) == 3
        got = []
        for block in u:
            shapes = {}
            for side in ("a", "b"):
                s = block[side]
                counts = np.frombuffer(s["counts"], "<u4")
                points = np.split(
                    np.frombuffer(s["points"], "<f8").reshape(-1, 2), np.cumsum(counts)[:-1]
                )
                p, q = (np.frombuffer(s[k], "<f8").reshape(-1, 2) for k in ("p", "q"))
                shapes[side] = [
                    {
                        "points": points[i],
                        "radius": np.frombuffer(s["radius"], "<f8")[i],
                        "position": tuple(p[i]),
                        "rotation": tuple(q[i]),
                    }
                    for i in range(len(counts))
                ]
            got += [
                {"name": n, "a": shapes["a"][i], "b": shapes["b"][i]}
                for i, n in enumerate(block["names"])
            ]
    assert len(got) == len(want) == 50
    for x, y in zip(want, got):
        same_case(x, y)
    assert gjk2d.read_cases(str(mp))[7]["b"]["rotation"] == want[7]["b"]["rotation"]


def test_bad_numpy_columns_raise_value_error(tmp_path):
    cols = columns_of(gjk2d.generate("random", count=3, seed=1))
    cols["a"]["counts"] = cols["a"]["counts"] + 1
    path = str(tmp_path / "bad.bin")
    with pytest.raises(ValueError, match=r"^cases\.a\.points: \d+ rows, but the counts add up to"):
        gjk2d.write_cases(path, cols, format="msgpack")
    with pytest.raises(ValueError, match=r"format: unknown format 'npz'"):
        gjk2d.write_cases(path, [], format="npz")
    assert not os.path.exists(path)
