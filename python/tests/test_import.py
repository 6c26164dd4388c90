"""The package imports from the build tree (PYTHONPATH=<build>/python, set by CTest)."""

import gjk2d


def test_the_package_imports_with_its_extension():
    assert gjk2d._gjk2d.__name__ == "gjk2d._gjk2d"
    assert callable(gjk2d.validate) and callable(gjk2d.load_report)
