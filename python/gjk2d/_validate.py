"""gjk2d.validate and gjk2d.load_report (docs/python.md, "Validating your own GJK from Python").

validate() registers a Python callable as an in-process variant of gjk-validate and runs
`gjk-validate run` in this process with the arguments its keywords make (python/src/py_validate.cpp):
the same inputs, exact truth, judgement, statistics, timing and report as the command line.
"""

import json
import os
import platform
import re
import shutil
import sys
import tempfile

import numpy

from . import _gjk2d

REPORT_SCHEMA = "gjk-report/1"


def _variant_name(fn):
    """The default variant name: the callable's __name__, in the characters a variant name takes."""
    name = re.sub(r"[^A-Za-z0-9._+-]+", "-", getattr(fn, "__name__", "") or "").strip("-")
    return name[:64] or "python"


def _source(fn):
    """What answers, for the report: python:module.qualname."""
    module = getattr(fn, "__module__", None) or "?"
    qualname = getattr(fn, "__qualname__", None) or type(fn).__qualname__
    if qualname.startswith("PyCapsule."):  # a function of an extension module (pybind11)
        qualname = getattr(fn, "__name__", qualname)
    return f"python:{module}.{qualname}"


def _specs(value, name):
    """None, one string, or strings: a list of strings."""
    if value is None:
        return []
    if isinstance(value, (str, os.PathLike)):
        return [os.fspath(value)]
    items = [os.fspath(v) for v in value]
    if not all(isinstance(v, str) for v in items):
        raise ValueError(f"{name}: expected a string or a list of strings")
    return items


def _run_arguments(name, families, cases, out, options):
    """The argument vector of `gjk-validate run` (docs/cli.md, "`run`") for validate()."""
    args = ["run", "--out", out, "--no-default-plugins" if not options["default_plugins"] else None]
    for f in _specs(families, "families"):
        args += ["--family", f]
    for f in _specs(cases, "cases"):
        args += ["--cases", f]
    if options["default_cases"]:
        args.append("--default-cases")
    variants = _specs(options["variants"], "variants")
    if name in variants:
        raise ValueError(f"variants: name only gjk2d's variants; {name!r} is the callable")
    args += ["--variants", ",".join(variants + [name])]
    if options["judge"]:
        args += ["--judge", name]
    for option, key in (
        ("--seed", "seed"),
        ("--threads", "threads"),
        ("--passes", "passes"),
        ("--worst", "worst"),
        ("--chunk", "chunk"),
        ("--exact-route", "exact_route"),
    ):
        if options[key] is not None:
            args += [option, str(options[key])]
    for flag, key, wanted in (
        ("--no-timing", "timing", False),
        ("--per-case", "per_case", True),
        ("--verbose", "verbose", True),
        ("--no-progress", "progress", False),
    ):
        if bool(options[key]) == wanted:
            args.append(flag)
    return [a for a in args if a is not None]


def validate(
    fn,
    families=None,
    cases=None,
    out=None,
    *,
    name=None,
    batch=False,
    dtype="float64",
    judge=False,
    variants=("double",),
    default_cases=False,
    seed=None,
    threads=None,
    timing=True,
    passes=None,
    per_case=False,
    worst=None,
    chunk=None,
    exact_route=None,
    default_plugins=False,
    accepts_radius=True,
    max_vertices=0,
    library=None,
    progress=True,
    verbose=False,
):
    """Runs fn as a variant of `gjk-validate run` and returns the report (a Report: report.json's
    dict, with .path the report directory).

    fn answers one pair, called as gjk2d.distance is:
        fn(points_a, points_b, radius_a=, radius_b=, position_a=, rotation_a=, position_b=,
           rotation_b=)
    with (n, 2) arrays of dtype, radii as floats, positions and rotations (c, s) as (2,) arrays;
    it returns (distance, point_a, point_b[, iterations]), or a dict or an object with those
    names (gjk2d.distance's result is one). With batch=True it answers many pairs, called as
    gjk2d.distance_batch is:
        fn(points, offsets_a, offsets_b, radius_a=, radius_b=, position_a=, rotation_a=,
           position_b=, rotation_b=)
    (every A shape, then every B shape, packed in one (N, 2) array; radii (n,), positions and
    rotations (n, 2)), returning distance (n,), point_a and point_b (n, 2) and optionally
    iterations (n,) the same ways.

    families, cases: as `run --family`, `--cases` (a string or a list); both None: the default
    campaign. out: the report directory (None: a new temporary directory). An exception raised by
    fn is that case's error (a batch call's: every case of the call), counted, never the end of
    the campaign; KeyboardInterrupt and SystemExit end it. The rest: docs/python.md.
    """
    if batch not in (True, False):
        raise ValueError("batch: expected True or False")
    name = _variant_name(fn) if name is None else name
    dtype = numpy.dtype(dtype).name
    options = dict(
        default_plugins=default_plugins,
        default_cases=default_cases,
        variants=variants,
        judge=judge,
        seed=seed,
        threads=threads,
        passes=passes,
        worst=worst,
        chunk=chunk,
        exact_route=exact_route,
        timing=timing,
        per_case=per_case,
        verbose=verbose,
        progress=progress,
    )
    if library is None:
        library = f"Python {platform.python_version()}, NumPy {numpy.__version__}"
    made = tempfile.mkdtemp(prefix="gjk2d-validate-") if out is None else None
    out = os.path.abspath(os.path.join(made, "report") if made else os.fspath(out))
    try:
        args = _run_arguments(name, families, cases, out, options)
        sys.stdout.flush()  # before the runner's summary, which C's stdout prints
        sys.stderr.flush()
        _gjk2d._validate(
            fn,
            name,
            batch,
            dtype,
            _source(fn),
            library,
            bool(accepts_radius),
            int(max_vertices),
            args,
        )
    except BaseException:
        if made:
            shutil.rmtree(made, ignore_errors=True)
        raise
    return load_report(out)


class Report(dict):
    """report.json (docs/report-schema.md) as plain dicts and lists; .path is its directory."""

    path = None

    def rows(self):
        """One flat dict per family x variant: family, variant, judged, every number of its
        Stats (cases, failures, plugin_errors, ns_per_query, ...) and each error histogram's max
        and p99 (abs_max, bound_ratio_p99, ...)."""
        judged = {v["name"]: v["judged"] for v in self["variants"]}
        rows = []
        for family in self["families"]:
            for variant, stats in family["variants"].items():
                row = {"family": family["name"], "variant": variant, "judged": judged[variant]}
                for key, value in stats.items():
                    if value is None or isinstance(value, (bool, int, float, str)):
                        row[key] = value
                for key, hist in stats.get("errors", {}).items():
                    row[key + "_max"] = hist.get("max")
                    row[key + "_p99"] = hist.get("p99")
                rows.append(row)
        return rows

    def frame(self):
        """rows() as a pandas DataFrame (ImportError without pandas: rows() needs nothing)."""
        try:
            import pandas
        except ImportError as e:
            raise ImportError(
                "Report.frame() needs pandas (apt-get install python3-pandas); "
                "Report.rows() gives the same rows as dicts"
            ) from e
        return pandas.DataFrame(self.rows())


def load_report(directory):
    """A report directory's report.json (written by gjk-validate run, merge or gjk2d.validate) as
    a Report: plain dicts, .rows() per family x variant, .frame() for pandas. A missing file
    raises FileNotFoundError; a file that is not a gjk-report/1 report, ValueError."""
    directory = os.path.abspath(os.fspath(directory))
    path = os.path.join(directory, "report.json")
    with open(path, encoding="utf-8") as f:
        try:
            data = json.load(f)
        except ValueError as e:
            raise ValueError(f"{path}: not JSON: {e}") from None
    schema = data.get("schema") if isinstance(data, dict) else None
    if schema != REPORT_SCHEMA:
        raise ValueError(f"{path}: not a {REPORT_SCHEMA} report (its schema: {schema!r})")
    report = Report(data)
    report.path = directory
    return report
