"""Every ```python block of docs/python.md runs, in document order, in one namespace (as a reader
would paste them into one session), in a temporary directory, with python/examples on sys.path; and every line of the form
`expression   # value` shows what the expression gives: the comment is the repr of its value, or
of each element of a top-level tuple joined by spaces (`r.iterations, r.stop  # 2 'repeated-support'`).
A ```text block (a signature) is not run. The working directory is a fresh one, with the build's
gjk-validate on PATH."""

import ast
import os
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
DOC = ROOT / "docs" / "python.md"
FENCE = re.compile(r"^```python\n(.*?)^```", re.S | re.M)


def blocks():
    return [m.group(1) for m in FENCE.finditer(DOC.read_text())]


def shown(value, expr_node):
    if isinstance(expr_node, ast.Tuple):
        return " ".join(repr(v) for v in value)
    return repr(value)


def expectations(source):
    """(line number, expression source, the comment) of every `expression  # value` line."""
    tree = ast.parse(source)
    lines = source.splitlines()
    out = []
    for node in tree.body:
        if isinstance(node, ast.Expr) and node.lineno == node.end_lineno:
            line = lines[node.lineno - 1]
            if "#" in line[node.end_col_offset :]:
                comment = line[node.end_col_offset :].split("#", 1)[1].strip()
                out.append((node.lineno, ast.get_source_segment(source, node), node.value, comment))
    return out


def test_the_doc_has_python_blocks():
    assert len(blocks()) >= 3


def test_every_block_runs_and_shows_what_it_says(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv(
        "PATH",
        os.path.dirname(os.environ["GJK2D_VALIDATE"]) + os.pathsep + os.environ.get("PATH", ""),
    )
    monkeypatch.syspath_prepend(str(ROOT / "python" / "examples"))  # the page's `import numpy_gjk`
    namespace = {"__name__": "__docs__"}
    checked = 0
    for i, source in enumerate(blocks()):
        exec(compile(source, f"{DOC.name} python block {i + 1}", "exec"), namespace)
        for lineno, expr, node, comment in expectations(source):
            value = eval(
                compile(expr, f"{DOC.name} block {i + 1} line {lineno}", "eval"), namespace
            )
            assert shown(value, node) == comment, f"block {i + 1} line {lineno}: {expr}"
            checked += 1
    assert checked >= 3
