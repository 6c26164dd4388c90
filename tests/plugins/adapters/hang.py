#!/usr/bin/python3
# A test adapter (toy.py): hang.
import sys

sys.dont_write_bytecode = True  # nothing written beside the sources
import toy  # noqa: E402

toy.main("hang")
