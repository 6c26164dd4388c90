#!/usr/bin/python3
# A test adapter (toy.py): contract (protocol version 2, a declared contract: zero, abs 1e-6).
import sys

sys.dont_write_bytecode = True  # nothing written beside the sources
import toy  # noqa: E402

toy.main("contract")
