#!/usr/bin/python3
# A test adapter (toy.py): prepared (protocol version 2: `prepared toy-prepared case`, two figures per `timed`).
import sys

sys.dont_write_bytecode = True  # nothing written beside the sources
import toy  # noqa: E402

toy.main("prepared")
