#!/usr/bin/env python3
"""Writes the committed seed corpus of the fuzz targets (docs/fuzzing.md, "Seed corpus").

    python3 fuzz/make_corpus.py            (from the repository root; rewrites fuzz/corpus/)

fuzz/corpus/fuzz_case_file/: the case files under validation/cases/ and tests/validation/data/,
the reproducers of the hardening against hostile inputs (among them an overflowed certified
interval and warm and cold answers that differed, below) and hand-made bad files.
fuzz/corpus/fuzz_truth/: six pseudo-random inputs of fuzz_truth's layout, one per kind of points.
fuzz/corpus/fuzz_distance/: every case of validation/cases/, those two reproducers and
shapes near 1e265 (they once left the simplex uninitialised), encoded in fuzz_distance's byte layout (fuzz_distance.cpp,
`decode`) for a few option sets. Inputs the fuzzer found (reproducers of fixed bugs) are added by hand as
fuzz/corpus/<target>/finding-*: this script leaves files of that name alone.
"""
import json
import os
import struct

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CORPUS = os.path.join(ROOT, "fuzz", "corpus")

# Two points near the largest double (1.5e308) under the same 45-degree rotation: the certified
# interval's products overflow.
ROTATED_POINTS_NEAR_MAX = (
    '{"format":"gjk-cases/1","cases":[{"name":"r1","a":{"points":[[1.5e308,-1.4e308]],'
    '"radius":1,"transform":{"q":[0.7071067811865476,0.7071067811865476]}},"b":{"points":'
    '[[1.5e308,-1.5e308]],"transform":{"q":[0.7071067811865476,0.7071067811865476]}}}]}'
)
# A rotated point against five points, one of them a vertex 3.6e18 away: warm and cold starts
# walk different simplices.
POINT_FAR_VERTEX = (
    '{"format":"gjk-cases/1","cases":[{"name":"s6","a":{"points":[[0.0099668502807617188,'
    '-0.7109375]],"transform":{"p":[-4.7393143177032471e-05,-1.862645149230957e-07],"q":'
    '[0.54540534970280896,0.83817241932406528]}},"b":{"points":[[-0.7109375,'
    "6.7949295043945312e-06],[-5.5511151231257827e-15,-3.5809246537129656e+18],[0,"
    "-1.0103029524088925e-14],[1.6200374375330284e-12,1.4551471139157002e-11],"
    "[1.9775847626135601e-16,-8.6736173798840355e-19]]}}]}"
)

GOOD_CASE = '{"name":"c","a":{"points":[[0,0],[1,0]]},"b":{"points":[[0,2]],"radius":0.5}}'


def case_file_seeds():
    """name -> bytes for the parser target."""
    seeds = {}
    for folder in ("validation/cases", "tests/validation/data"):
        for name in sorted(os.listdir(os.path.join(ROOT, folder))):
            with open(os.path.join(ROOT, folder, name), "rb") as f:
                seeds[folder.replace("/", "-") + "-" + name] = f.read()
    seeds["rotated-points-near-max.json"] = ROTATED_POINTS_NEAR_MAX.encode()
    seeds["point-far-vertex.json"] = POINT_FAR_VERTEX.encode()
    # A deeply nested "format" value (2,000 levels), and deep nesting inside a case.
    depth = 2000
    seeds["deep-format.json"] = ('{"format":' + "[" * depth + "]" * depth + ',"cases":[]}').encode()
    seeds["deep-points.json"] = (
        '{"format":"gjk-cases/1","cases":[{"name":"d","a":{"points":'
        + "[" * depth
        + "]" * depth
        + '},"b":{"points":[[0,0]]}}]}'
    ).encode()
    seeds["deep-unclosed.json"] = ('{"format":"gjk-cases/1","cases":' + "[{" * 1000).encode()
    seeds["long-format-string.json"] = ('{"format":"' + "x" * 5000 + '","cases":[]}').encode()
    # Duplicate keys; numbers that overflow, underflow or are subnormal.
    seeds[
        "duplicate-format-key.json"
    ] = b'{"format":"gjk-cases/1","format":"gjk-cases/1","cases":[]}'
    seeds["duplicate-cases-key.json"] = (
        '{"format":"gjk-cases/1","cases":[],"cases":[' + GOOD_CASE + "]}"
    ).encode()
    seeds["duplicate-radius-key.json"] = (
        b'{"format":"gjk-cases/1","cases":[{"name":"c","a":{"points":'
        b'[[0,0]],"radius":1,"radius":-1},"b":{"points":[[3,0]]}}]}'
    )
    seeds["duplicate-name.json"] = (
        '{"format":"gjk-cases/1","cases":[' + GOOD_CASE + "," + GOOD_CASE + "]}"
    ).encode()
    for label, text in (
        ("underflow-1e-999", "1e-999"),
        ("underflow-minus-1e-999", "-1e-999"),
        ("overflow-1e999", "1e999"),
        ("subnormal-4.9e-324", "4.9e-324"),
        ("underflow-2e-324", "2e-324"),
        ("max-1.7976931348623157e308", "1.7976931348623157e308"),
        ("long-mantissa", "0." + "1" * 800 + "e-300"),
    ):
        seeds["number-" + label + ".json"] = (
            '{"format":"gjk-cases/1","cases":[{"name":"n","a":{"points":[['
            + text
            + ',0]],"radius":'
            + text.lstrip("-")
            + '},"b":{"points":[[0,'
            + text
            + ']],"transform":{"p":['
            + text
            + ',0],"q":[1,'
            + text
            + "]}}}]}"
        ).encode()
    seeds["strings-nan-inf.json"] = (
        b'{"format":"gjk-cases/1","cases":[{"name":"s","a":{"points":'
        b'[["nan","inf"]],"radius":"-inf"},"b":{"points":[[0,0]]}}]}'
    )
    # Non-UTF-8 bytes in names, comments and the format, a lone surrogate escape, a BOM.
    seeds["non-utf8-name.json"] = (
        b'{"format":"gjk-cases/1","cases":[{"name":"x\xff","a":{"points":'
        b'[[0,0]]},"b":{"points":[[1,0]]}}]}'
    )
    seeds["non-utf8-comment.json"] = (
        b'{"format":"gjk-cases/1","comments":["\xc0\x80 overlong",'
        b'"\xed\xa0\x80 surrogate"],"cases":[]}'
    )
    seeds["non-utf8-format.json"] = b'{"format":"gjk-cases/1\xfe","cases":[]}'
    seeds["escaped-surrogate-name.json"] = (
        b'{"format":"gjk-cases/1","cases":[{"name":"\\ud800",'
        b'"a":{"points":[[0,0]]},"b":{"points":[[1,0]]}}]}'
    )
    seeds["utf8-bom.json"] = (
        b"\xef\xbb\xbf" + ('{"format":"gjk-cases/1","cases":[' + GOOD_CASE + "]}").encode()
    )
    seeds["nul-bytes.json"] = b'{"format":"gjk-cases/1",\x00"cases":[]}'
    seeds["empty.json"] = b""
    return seeds


# --- fuzz_distance's byte layout (fuzz_distance.cpp, `decode`) -------------------------------------
DIRECTION, STOPPING, FRAME, SUPPORT, CERTIFY, NO_RADII, DOUBLE, TRACE = (1 << i for i in range(8))


def raw(v):
    """A number as tag 5 (raw bit pattern)."""
    return bytes([5]) + struct.pack("<d", v)


def shape_bytes(s):
    pts = s["points"]
    assert 1 <= len(pts) <= 20
    out = bytes([len(pts) - 1])
    for x, y in pts:
        out += raw(x) + raw(y)
    radius = s.get("radius", 0)
    out += (bytes([1]) + raw(radius)) if radius else bytes([0])
    t = s.get("transform", {})
    c, sn = t.get("q", [1, 0])
    px, py = t.get("p", [0, 0])
    out += (bytes([2]) + raw(c) + raw(sn)) if (c, sn) != (1, 0) else bytes([0])
    return out + raw(px) + raw(py)


def query_bytes(case, bits, limit=0):
    return bytes([bits, limit]) + shape_bytes(case["a"]) + shape_bytes(case["b"])


def scaled(case, factor):
    """The case with every point and translation multiplied by factor (a power of two: exact)."""
    out = json.loads(json.dumps(case))
    for key in ("a", "b"):
        s = out[key]
        s["points"] = [[x * factor, y * factor] for x, y in s["points"]]
        if "radius" in s:
            s["radius"] *= factor
        if "transform" in s and "p" in s["transform"]:
            s["transform"]["p"] = [v * factor for v in s["transform"]["p"]]
    return out


def distance_seeds():
    cases = []
    for name in sorted(os.listdir(os.path.join(ROOT, "validation/cases"))):
        with open(os.path.join(ROOT, "validation/cases", name)) as f:
            cases += [
                ("cases-" + name[:-5] + "-" + c["name"].split("/")[-1], c)
                for c in json.load(f)["cases"]
            ]
    cases.append(("rotated-points-near-max", json.loads(ROTATED_POINTS_NEAR_MAX)["cases"][0]))
    cases.append(("point-far-vertex", json.loads(POINT_FAR_VERTEX)["cases"][0]))
    # solve3's fallback with all three edge lengths overflowing. Identity rotations and
    # coordinates near 1e265: an axis-aligned triangle around the origin and a point, and the
    # shapes of `gjk-validate generate --family hard/range --seed 1`'s case 10-gap-x1e+160 scaled
    # by 2^350 (about 2.3e105).
    big = 1e265
    cases.append(
        (
            "overflowing-edges-triangle-1e265",
            {
                "a": {"points": [[-big, -big], [big, -0.5 * big], [0.25 * big, big]]},
                "b": {"points": [[3.0, 1.0]]},
            },
        )
    )
    cases.append(
        (
            "overflowing-edges-squares-1e265",
            {
                "a": {"points": [[big, big], [-big, big], [-big, -big], [big, -big]]},
                "b": {
                    "points": [[0.5 * big, 0.5 * big], [-0.75 * big, 0.5 * big], [0, -0.9 * big]],
                    "transform": {"p": [1e250, -1e250]},
                },
            },
        )
    )
    hard10 = {
        "a": {
            "points": [
                [-3.873984342514763e159, 1.484236684695396e160],
                [-4.38800837429091e159, 1.469860506350043e160],
                [-1.451376158707704e160, -4.965312970910757e159],
                [8.545183476337879e158, -1.5315789457261573e160],
                [1.8510129429001323e159, -1.52275198043156e160],
                [1.088016406187104e160, -1.0813215908894885e160],
                [1.0886712624049262e160, -1.0806622809507786e160],
                [1.3750513734224804e160, -6.7990426054336975e159],
            ],
            "transform": {"p": [3.688833903958622e160, -3.646168361901023e160]},
        },
        "b": {
            "points": [
                [1.0963860429206643e160, 1.5583605640721312e158],
                [7.322469882929395e159, 8.161614742267107e159],
                [-9.12043817460672e159, -6.086717332912399e159],
                [9.314315278233425e159, -5.7856763896079775e159],
                [1.0482245765313196e160, -3.2176146604547495e159],
            ],
            "transform": {"p": [5.652346655961531e160, -2.4083775049934223e160]},
        },
    }
    cases.append(("overflowing-edges-hard-range-10-x2p350", scaled(hard10, 2.0**350)))

    seeds = {}
    for name, case in cases:
        seeds[name + "-double"] = query_bytes(case, DOUBLE)
        seeds[name + "-double-certify"] = query_bytes(case, DOUBLE | CERTIFY)
        seeds[name + "-float-certify"] = query_bytes(case, CERTIFY)
        seeds[name + "-double-world-closest-gap"] = query_bytes(
            case, DOUBLE | FRAME | DIRECTION | STOPPING | CERTIFY
        )
    return seeds


def truth_seeds():
    """fuzz_truth's byte layout (fuzz/fuzz_truth.cpp): per shape a head byte (count, transform
    kind) and a kind byte (point kind, radius), then numbers (a selector byte and its bytes),
    pseudo-random from a fixed seed: one seed per point kind and transform kind."""
    import random

    rng = random.Random(34)
    kinds = {
        "free-identity": (0x03, 0x00),
        "free-rotated": (0x13, 0x04),
        "collinear-quarter-turn": (0x0C, 0x01),
        "duplicates-any-transform": (0x1D, 0x06),
        "tiny-edges": (0x05, 0x07),
        "free-raw-bits": (0x17, 0x00),
    }
    seeds = {}
    for name, (head, kind) in kinds.items():
        out = bytearray()
        for _ in range(2):
            out += bytes([head, kind])
            for _ in range(40):
                out += bytes([rng.randrange(5)]) + bytes(rng.randrange(256) for _ in range(9))
        seeds[name] = bytes(out[:500])
    return seeds


def write(target, seeds):
    folder = os.path.join(CORPUS, target)
    if os.path.isdir(folder):
        for name in os.listdir(folder):
            if not name.startswith("finding-"):
                os.remove(os.path.join(folder, name))
    os.makedirs(folder, exist_ok=True)
    for name, data in seeds.items():
        with open(os.path.join(folder, name), "wb") as f:
            f.write(data)


if __name__ == "__main__":
    write("fuzz_case_file", case_file_seeds())
    write("fuzz_distance", distance_seeds())
    write("fuzz_truth", truth_seeds())
