#!/usr/bin/python3
# A test adapter (toy.py): world-bad-form (protocol version 2, `input NAME local`: refused at the handshake).
import sys

sys.dont_write_bytecode = True  # nothing written beside the sources
import toy  # noqa: E402

toy.main("world-bad-form")
