#!/usr/bin/python3
# A test adapter (toy.py): too-fast (answers `timed ID 1`: below 1 ns a query).
import sys

sys.dont_write_bytecode = True  # nothing written beside the sources
import toy  # noqa: E402

toy.main("too-fast")
