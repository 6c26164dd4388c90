"""gjk2d's build backend (PEP 517; pyproject.toml names it; docs/python.md, "Install").

It drives the project's own CMake build of the extension _gjk2d and packs a wheel, with Debian's
packages alone (no scikit-build-core there): CMake, pybind11-dev, python3-wheel (WheelFile writes
RECORD) and mypy (stubgen writes the type stubs). Nothing is written beside the sources: the CMake
build goes to a temporary directory, or to the one the config setting build-dir names.

  build-dir=DIR  (pip --config-settings build-dir=DIR, python3 -m build -C build-dir=DIR): the
                 CMake build goes to DIR and is kept: configured as below when DIR has no
                 CMakeCache.txt, else reused as it is (the test suite packs its own build tree
                 this way); only _gjk2d is brought up to date there.
  jobs=N         the build's parallel jobs (default: CMAKE_BUILD_PARALLEL_LEVEL, else all CPUs).

A new build is the release preset's (its cache variables, -ffp-contract=off among the project's
flags: the module answers bit for bit as gjk-validate does), for the Python that runs this
backend, without the tests, benchmarks and examples. CMAKE_CXX_COMPILER_LAUNCHER=ccache in the
environment is honoured by CMake.

The wheel: the package's .py files (python/gjk2d/), the extension, its stub _gjk2d.pyi and py.typed,
and the default campaign's case files (validation/cases/) in gjk2d/cases/, where the package tells
the runner to look (python/gjk2d/__init__.py). It is a platform wheel (linux_x86_64, not
manylinux): the extension links Debian 12's shared libraries (docs/python.md lists them).
"""

import os
import re
import shutil
import subprocess
import sys
import sysconfig
import tempfile
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]  # python/build_backend/ -> the repository
EXTENSION = "_gjk2d" + sysconfig.get_config_var("EXT_SUFFIX")


def _version():
    """The project's one version: CMakeLists.txt's project(gjk2d VERSION ...)."""
    text = (ROOT / "CMakeLists.txt").read_text()
    m = re.search(r"^project\(gjk2d VERSION ([0-9][0-9.]*)", text, re.M)
    if not m:
        raise RuntimeError("CMakeLists.txt: no `project(gjk2d VERSION x.y.z` line")
    return m.group(1)


def _project():
    with open(ROOT / "pyproject.toml", "rb") as f:
        project = tomllib.load(f)["project"]
    if project.get("dynamic") != ["version"] or "version" in project:
        raise RuntimeError(
            "pyproject.toml: [project] must leave the version dynamic " "(it is CMakeLists.txt's)"
        )
    return project


def _tag():
    """cp311-cp311-linux_x86_64: this interpreter and platform (the extension is built for them)."""
    python = "cp{}{}".format(*sys.version_info[:2])
    return "{0}-{0}-{1}".format(python, re.sub(r"[-.]", "_", sysconfig.get_platform()))


def _dist_info():
    return "gjk2d-{}.dist-info".format(_version())


def _metadata():
    """METADATA (core metadata 2.1) from pyproject.toml's [project] and the version."""
    p = _project()
    lines = [
        "Metadata-Version: 2.1",
        "Name: " + p["name"],
        "Version: " + _version(),
        "Summary: " + p["description"],
        "License: " + p["license"]["text"],
        "Requires-Python: " + p["requires-python"],
    ]
    lines += ["Requires-Dist: " + d for d in p.get("dependencies", [])]
    lines += ["Project-URL: {}, {}".format(k, v) for k, v in p.get("urls", {}).items()]
    return "\n".join(lines) + "\n"


def _wheel_file():
    return (
        "Wheel-Version: 1.0\nGenerator: gjk2d_build\nRoot-Is-Purelib: false\n"
        "Tag: {}\n".format(_tag())
    )


def _run(cmd, **kw):
    print("gjk2d_build: " + " ".join(str(c) for c in cmd), flush=True)
    subprocess.run([str(c) for c in cmd], check=True, **kw)


def _cmake_build(build, jobs):
    """Configures DIR when new, then builds _gjk2d there; returns the extension's path."""
    if not (build / "CMakeCache.txt").exists():
        _run(
            [
                "cmake",
                "-S",
                ROOT,
                "-B",
                build,
                "--preset",
                "release",
                "-DGJK2D_BUILD_TESTS=OFF",
                "-DGJK2D_BUILD_BENCHMARKS=OFF",
                "-DGJK2D_BUILD_EXAMPLES=OFF",
                "-DGJK2D_BUILD_PYTHON=ON",
                "-DPython_EXECUTABLE=" + sys.executable,
            ]
        )
    jobs = jobs or os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
    _run(["cmake", "--build", build, "--target", "_gjk2d", "-j", jobs])
    module = build / "python" / "gjk2d" / EXTENSION
    if not module.is_file():
        raise RuntimeError(
            "build-dir {}: no python/gjk2d/{} after the build (is it a build of "
            "this tree, for this Python, {}?)".format(build, EXTENSION, sys.executable)
        )
    return module


def _stage(module, stage):
    """The package as installed: .py files, extension, cases, stub, py.typed."""
    package = stage / "gjk2d"
    package.mkdir(parents=True)
    for source in sorted((ROOT / "python" / "gjk2d").glob("*.py")):
        shutil.copyfile(source, package / source.name)
    shutil.copyfile(module, package / EXTENSION)
    (package / "cases").mkdir()
    for case in sorted((ROOT / "validation" / "cases").glob("*.json")):
        shutil.copyfile(case, package / "cases" / case.name)
    # The stub of the extension, from its pybind11 signatures; the .py files are their own types.
    stubs = stage.parent / "stubs"
    env = dict(os.environ, PYTHONPATH=str(stage), PYTHONDONTWRITEBYTECODE="1")
    # Debian's mypy is compiled (mypyc): `-m mypy.stubgen` finds no code object, main() runs.
    _run(
        [
            sys.executable,
            "-c",
            "from mypy.stubgen import main; main()",
            "-q",
            "-m",
            "gjk2d._gjk2d",
            "-o",
            stubs,
        ],
        env=env,
        cwd=stage.parent,
    )
    shutil.copyfile(stubs / "gjk2d" / "_gjk2d.pyi", package / "_gjk2d.pyi")
    (package / "py.typed").write_text("")  # PEP 561: the package carries its types


def _pack(stage, wheel_directory):
    from wheel.wheelfile import WheelFile

    name = "gjk2d-{}-{}.whl".format(_version(), _tag())
    path = Path(wheel_directory) / name
    with WheelFile(str(path), "w") as wheel:
        for file in sorted(p for p in stage.rglob("*") if p.is_file()):
            wheel.write(str(file), file.relative_to(stage).as_posix())
        wheel.writestr(_dist_info() + "/METADATA", _metadata())
        wheel.writestr(_dist_info() + "/WHEEL", _wheel_file())
    return name


def get_requires_for_build_wheel(config_settings=None):
    return []  # pyproject.toml's build-system.requires say it all


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    info = Path(metadata_directory) / _dist_info()
    info.mkdir(parents=True, exist_ok=True)
    (info / "METADATA").write_text(_metadata())
    (info / "WHEEL").write_text(_wheel_file())
    return info.name


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    settings = config_settings or {}
    unknown = set(settings) - {"build-dir", "jobs"}
    if unknown:
        raise RuntimeError(
            "unknown config settings {}: gjk2d_build takes build-dir and jobs".format(
                sorted(unknown)
            )
        )
    with tempfile.TemporaryDirectory(prefix="gjk2d-wheel-") as tmp:
        given = settings.get("build-dir")
        build = Path(given).resolve() if given else Path(tmp) / "cmake"
        module = _cmake_build(build, settings.get("jobs"))
        _stage(module, Path(tmp) / "stage")
        return _pack(Path(tmp) / "stage", wheel_directory)
