#!/usr/bin/python3
# A test adapter (toy.py): depth-zero (protocol version 2, a depth clause; toy.py's docstring).
import sys

sys.dont_write_bytecode = True  # nothing written beside the sources
import toy  # noqa: E402

toy.main("depth-zero")
