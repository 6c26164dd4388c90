"""gjk2d.validate and gjk2d.load_report (docs/python.md, "Validating your own GJK from Python"):
a Python callable runs through `gjk-validate run`'s campaign in this process, its failures,
errors and timing counted as the runner counts any plugin's, its report the runner's."""

import os
import subprocess

import numpy as np
import pytest

import gjk2d

VALIDATE = os.environ.get("GJK2D_VALIDATE")
NAME = "py-test"  # every test registers its callable under this name again: that must work


def one_percent_off(points_a, points_b, **pose):
    """gjk2d's answer with the distance 1% too large (the witness points as they were)."""
    r = gjk2d.distance(points_a, points_b, **pose)
    return r.distance * 1.01, r.point_a, r.point_b


def separated(family, count):
    """Cases of the family (seed 1, as validate's campaign) whose exact distance is positive."""
    cases = gjk2d.generate(family, seed=1, count=count)
    return sum(gjk2d.exact_distance(**gjk2d.case_args(c))["distance"] > 0 for c in cases)


def test_a_planted_wrong_callable_fails_every_separated_case(tmp_path):
    # A random case apart is about 1 apart at size about 1: 1% is ~1e14 times the bound (~1e-16
    # relative), so every separated case fails (once, though its witness gap is off too); a case
    # in contact (distance 0) stays right. The expected count is the exact side's, case by case.
    expected = separated("random", 600)
    assert 180 < expected < 420  # random's make-up: 30% to 70% of its cases overlap
    report = gjk2d.validate(
        one_percent_off,
        families=["random:600"],
        out=tmp_path / "r",
        name=NAME,
        judge=True,
        timing=False,
    )
    stats = report["families"][0]["variants"][NAME]
    assert stats["cases"] == 600
    assert stats["failures"] == expected
    assert stats["beyond_bound"] == expected
    assert report["families"][0]["variants"]["double"]["failures"] == 0
    assert report["exit_code"] == 1 and report["passed"] is False  # judged on request
    assert [v["judged"] for v in report["variants"]] == [True, True]


def test_a_comparison_variant_is_not_judged_by_default(tmp_path):
    report = gjk2d.validate(
        one_percent_off, families="random:300", out=tmp_path / "r", name=NAME, timing=False
    )
    assert report["families"][0]["variants"][NAME]["failures"] == separated("random", 300)
    assert report["exit_code"] == 0 and report["passed"] is True
    assert [v["judged"] for v in report["variants"]] == [True, False]


def test_exceptions_are_counted_per_case_and_the_campaign_completes(tmp_path):
    def raises(points_a, points_b, **pose):
        raise ZeroDivisionError("planted")

    report = gjk2d.validate(
        raises, families=["random:100", "hard/points", "engine:20"], out=tmp_path / "r", name=NAME
    )
    assert len(report["families"]) == 1 + 1 + 6
    for family in report["families"]:
        stats = family["variants"][NAME]
        assert stats["cases"] == family["variants"]["double"]["cases"] > 0
        assert stats["plugin_errors"] == stats["failures"] == stats["cases"]
        assert stats["ns_per_query"] is None  # no case answered: none is timed
    worst = report["worst"][0]["variants"][NAME]
    assert worst["plugin_status"] == "error"
    assert worst["plugin_detail"] == "ZeroDivisionError: planted"
    assert report["exit_code"] == 0  # a comparison variant's errors are shown, not judged


def test_invalid_answers_are_judged_and_malformed_ones_are_errors(tmp_path):
    answers = {
        0: (-1.0, (0, 0), (0, 0)),  # a negative distance: invalid, a failure
        1: (float("nan"), (0, 0), (0, 0)),  # non-finite: a failure
        2: None,  # not an answer: an error (a failure) with its message
        3: (1.0, (0, 0, 0), (0, 0)),
    }  # a point of three numbers: an error
    calls = []

    def odd(points_a, points_b, **pose):
        calls.append(1)
        return answers[len(calls) % 4]

    report = gjk2d.validate(odd, families="random:400", out=tmp_path / "r", name=NAME, timing=False)
    stats = report["families"][0]["variants"][NAME]
    assert len(calls) == 400
    assert stats["invalid_reasons"]["negative_distance"] == 100
    assert stats["nonfinite"] == 100
    assert stats["plugin_errors"] == 200
    assert stats["failures"] == 400


def test_no_fork_and_a_plain_timed_loop_over_the_first_2048_cases(tmp_path):
    # Every call in this process; the accuracy run calls once per case, the timing (one pass
    # asked: its calibration pass, then one pass of one loop, a Python call lasting far more than
    # the 2 ms a pass is calibrated to) calls once per case of the first 2,048.
    pids = []

    def counted(points_a, points_b, **pose):
        pids.append(os.getpid())
        return gjk2d.distance(points_a, points_b, **pose)

    report = gjk2d.validate(
        counted, families="random:3000", out=tmp_path / "r", name=NAME, passes=1
    )
    assert set(pids) == {os.getpid()}
    assert len(pids) == 3000 + 2 * 2048
    stats = report["families"][0]["variants"][NAME]
    assert stats["failures"] == 0
    assert stats["ns_per_query"] > 0 and stats["timing_passes"] == 1


def test_gjk2d_distance_as_the_callable_is_gjk_validate_double(tmp_path):
    # The callable's answers are the double variant's bits: the statistics agree, field by field.
    report = gjk2d.validate(
        gjk2d.distance,
        families=["random:500", "hard:8", "engine:30"],
        out=tmp_path / "r",
        name=NAME,
        timing=False,
    )
    for family in report["families"]:
        ours, double = family["variants"][NAME], family["variants"]["double"]
        for key in ("cases", "failures", "errors", "iterations", "false_overlap"):
            assert ours[key] == double[key], (family["name"], key)
    plugin = report["context"]["plugins"][0]
    assert plugin["kind"] == "in-process" and plugin["variants"] == [NAME]
    assert plugin["file"] == "python:gjk2d._gjk2d.distance"


def test_float32_sees_the_float_rounded_case(tmp_path):
    seen = set()

    def in_float(points_a, points_b, **pose):
        seen.add((points_a.dtype.name, pose["position_a"].dtype.name))
        return gjk2d.distance(points_a, points_b, **pose)

    report = gjk2d.validate(
        in_float,
        families="random:300",
        out=tmp_path / "r",
        name=NAME,
        dtype=np.float32,
        variants=["float"],
        timing=False,
    )
    assert seen == {("float32", "float32")}
    family = report["families"][0]["variants"]
    assert family[NAME]["errors"] == family["float"]["errors"]
    assert report["variants"][1]["type"] == "float"


def test_a_batch_callable_gives_the_per_case_report(tmp_path):
    families = ["random:700", "hard:10", "engine:40"]
    each = gjk2d.validate(
        gjk2d.distance, families=families, out=tmp_path / "each", name=NAME, timing=False
    )
    batches = []

    def batch(points, offsets_a, offsets_b, **poses):
        batches.append(len(offsets_a) - 1)
        return gjk2d.distance_batch(points, offsets_a, offsets_b, **poses)

    together = gjk2d.validate(
        batch,
        families=families,
        out=tmp_path / "batch",
        name=NAME,
        batch=True,
        chunk=500,
        timing=False,
    )
    assert each["families"] == together["families"]
    hard = sum(f["name"].startswith("hard/") for f in each["families"])
    assert hard >= 20
    assert sum(batches) == 700 + 10 * hard + 40 * 6  # every case once, by chunks of at most 500
    assert max(batches) == 500

    def without_iterations(points, offsets_a, offsets_b, **poses):  # a tuple of three arrays
        out = gjk2d.distance_batch(points, offsets_a, offsets_b, **poses)
        return out["distance"], out["point_a"], out["point_b"]

    tuples = gjk2d.validate(
        without_iterations,
        families=families,
        out=tmp_path / "tuples",
        name=NAME,
        batch=True,
        timing=False,
    )
    for ours, theirs in zip(tuples["families"], each["families"]):
        assert ours["variants"][NAME]["errors"] == theirs["variants"][NAME]["errors"]
        assert ours["variants"][NAME]["failures"] == 0
        assert ours["variants"][NAME]["iterations"]["counts"] == []  # not said: not counted


def test_the_report_is_one_gjk_validate_compare_accepts(tmp_path):
    good = gjk2d.validate(
        gjk2d.distance,
        families="random:300",
        out=tmp_path / "good",
        name=NAME,
        judge=True,
        timing=False,
    )
    bad = gjk2d.validate(
        one_percent_off,
        families="random:300",
        out=tmp_path / "bad",
        name=NAME,
        judge=True,
        timing=False,
    )
    same = subprocess.run(
        [VALIDATE, "compare", good.path, good.path], capture_output=True, text=True
    )
    assert same.returncode == 0, same.stderr
    worse = subprocess.run(
        [VALIDATE, "compare", good.path, bad.path], capture_output=True, text=True
    )
    assert worse.returncode == 1, worse.stderr  # the judged callable regressed
    assert any(
        line.split()[1:3] == [NAME, "failures"] and line.endswith("REGRESSED")
        for line in worse.stdout.splitlines()
    )


def test_errors_are_the_command_lines_one_line_messages(tmp_path):
    cli = subprocess.run(
        [VALIDATE, "run", "--family", "no-such-family", "--out", str(tmp_path / "cli")],
        capture_output=True,
        text=True,
    )
    assert cli.returncode == 2
    message = cli.stderr.strip().removeprefix("gjk-validate: error: ")
    with pytest.raises(gjk2d.InputError) as error:
        gjk2d.validate(gjk2d.distance, families="no-such-family", out=tmp_path / "py", name=NAME)
    assert str(error.value) == message and isinstance(error.value, ValueError)
    with pytest.raises(ValueError, match="'double': the name is taken by a gjk2d variant"):
        gjk2d.validate(
            gjk2d.distance, families="random:2", out=tmp_path / "py", name="double", variants=[]
        )
    with pytest.raises(ValueError, match=r"^--passes 0: expected 1\.\.1000$"):
        gjk2d.validate(
            gjk2d.distance, families="random:2", out=tmp_path / "py", name=NAME, passes=0
        )
    assert not (tmp_path / "py").exists()


def test_one_campaign_at_a_time(tmp_path):
    def nested(points_a, points_b, **pose):
        gjk2d.validate(gjk2d.distance, families="random:1", out=tmp_path / "inner", name="inner")

    report = gjk2d.validate(
        nested, families="random:5", out=tmp_path / "r", name=NAME, timing=False
    )
    worst = report["worst"][0]["variants"][NAME]
    assert worst["plugin_detail"] == (
        "RuntimeError: gjk2d.validate: another campaign runs in " "this process (one at a time)"
    )
    assert report["families"][0]["variants"][NAME]["plugin_errors"] == 5


def test_keyboard_interrupt_ends_the_campaign_without_a_report(tmp_path):
    def interrupted(points_a, points_b, **pose):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        gjk2d.validate(interrupted, families="random:50", out=tmp_path / "r", name=NAME)
    assert not (tmp_path / "r").exists()
    # and the next campaign of the same name runs
    report = gjk2d.validate(
        gjk2d.distance, families="random:50", out=tmp_path / "r", name=NAME, timing=False
    )
    assert report["families"][0]["variants"][NAME]["failures"] == 0


def test_load_report_rows_and_frame(tmp_path):
    report = gjk2d.validate(
        gjk2d.distance,
        families=["random:50", "hard/points"],
        out=tmp_path / "r",
        name=NAME,
        timing=False,
    )
    again = gjk2d.load_report(tmp_path / "r")
    assert again == report and type(again) is gjk2d.Report and again.path == str(tmp_path / "r")
    rows = again.rows()
    assert [(r["family"], r["variant"]) for r in rows] == [
        ("random", "double"),
        ("random", NAME),
        ("hard/points", "double"),
        ("hard/points", NAME),
    ]
    assert rows[1]["cases"] == 50 and rows[1]["judged"] is False and rows[1]["abs_max"] >= 0
    try:
        import pandas  # noqa: F401  (optional)
    except ImportError:
        with pytest.raises(ImportError, match="rows()"):
            again.frame()
    else:
        assert again.frame().shape[0] == 4
    with pytest.raises(FileNotFoundError):
        gjk2d.load_report(tmp_path / "nothing")
    (tmp_path / "other").mkdir()
    (tmp_path / "other" / "report.json").write_text('{"schema": "gjk-shard/1"}')
    with pytest.raises(ValueError, match="not a gjk-report/1 report"):
        gjk2d.load_report(tmp_path / "other")
