#!/usr/bin/python3
# A test adapter (toy.py): world-unknown (protocol version 2, an input line for no implementation: refused).
import sys

sys.dont_write_bytecode = True  # nothing written beside the sources
import toy  # noqa: E402

toy.main("world-unknown")
