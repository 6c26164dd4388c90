#!/usr/bin/python3
# A test adapter (toy.py): world (protocol version 2, a float implementation given world points: `input toy-world world SOURCE`).
import sys

sys.dont_write_bytecode = True  # nothing written beside the sources
import toy  # noqa: E402

toy.main("world")
