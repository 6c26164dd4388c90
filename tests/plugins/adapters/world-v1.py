#!/usr/bin/python3
# A test adapter (toy.py): world-v1 (an input line in a version-1 handshake: refused).
import sys

sys.dont_write_bytecode = True  # nothing written beside the sources
import toy  # noqa: E402

toy.main("world-v1")
