#!/usr/bin/python3
# A test adapter (toy.py): prepared-v1 (a `prepared` line in a version-1 handshake).
import sys

sys.dont_write_bytecode = True  # nothing written beside the sources
import toy  # noqa: E402

toy.main("prepared-v1")
