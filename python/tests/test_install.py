"""`cmake --install` puts the package under the prefix's lib/python3/dist-packages (relative to the
prefix, so it follows --prefix), and it imports from there with the build tree out of the path."""

import os
import subprocess
import sys


def test_the_installed_package_imports_from_the_prefix(tmp_path):
    prefix = tmp_path / "prefix"
    subprocess.run(
        ["cmake", "--install", os.environ["GJK2D_BUILD"], "--prefix", str(prefix)],
        check=True,
        stdout=subprocess.DEVNULL,
    )
    site = prefix / "lib" / "python3" / "dist-packages"
    env = dict(os.environ, PYTHONPATH=str(site))
    probe = (
        "import gjk2d; print(gjk2d.__file__); " "print(gjk2d.distance([[0, 0]], [[3, 4]]).distance)"
    )
    run = subprocess.run(
        [sys.executable, "-c", probe],
        env=env,
        cwd=str(tmp_path),
        capture_output=True,
        text=True,
        check=True,
    )
    where, answer = run.stdout.split()
    assert where == str(site / "gjk2d" / "__init__.py")
    assert answer == "5.0"
