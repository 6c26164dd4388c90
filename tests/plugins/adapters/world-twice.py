#!/usr/bin/python3
# A test adapter (toy.py): world-twice (protocol version 2, two input lines for one name: refused).
import sys

sys.dont_write_bytecode = True  # nothing written beside the sources
import toy  # noqa: E402

toy.main("world-twice")
