#!/usr/bin/env python3
"""The code snippets in the docs are regions of the compiled examples, verbatim.

An example marks a region with two comment lines (the region is dedented as a whole):

    // [snippet: one-query]
    ...
    // [end snippet]

(in a Python example, examples/adapter/*.py: `# [snippet: NAME]` ... `# [end snippet]`, shown in
a ```python block).

A doc shows it as a fenced block right after a marker line:

    <!-- snippet: one-query -->
    ```cpp
    ...
    ```

check (the default) exits 1 when a doc block differs from its region, names an unknown snippet,
or a marker has no fenced block after it; and, in the strictly checked docs (docs/gjk.md and
docs/exact.md), when a ```cpp block has no marker, i.e. does not come from an example.
--fix rewrites the doc blocks from the examples (unknown names are still errors).
Exit codes: 0 all good, 1 a mismatch or error in the docs, 2 a malformed example.
"""
import argparse
import difflib
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "examples"
DOCS = ROOT / "docs"
# Docs whose every ```cpp block must come from an example.
STRICT = ["docs/gjk.md", "docs/exact.md"]

BEGIN = re.compile(r"^\s*(?://|#) \[snippet: ([a-z0-9-]+)\]\s*$")
END = re.compile(r"^\s*(?://|#) \[end snippet\]\s*$")
MARKER = re.compile(r"^<!-- snippet: ([a-z0-9-]+) -->\s*$")
FENCE = re.compile(r"^```")


def dedent(lines):
    indents = [len(l) - len(l.lstrip(" ")) for l in lines if l.strip()]
    cut = min(indents, default=0)
    return [l[cut:] if l.strip() else "" for l in lines]


def read_examples():
    """name -> (file, lines); exits 2 on a malformed example."""
    snippets = {}
    errors = []
    # also examples/plugin/, and examples/adapter/'s Python
    for path in sorted(EXAMPLES.rglob("*.cpp")) + sorted(EXAMPLES.rglob("*.py")):
        rel = path.relative_to(ROOT)
        name, start, body = None, 0, []
        for no, line in enumerate(path.read_text().splitlines(), 1):
            b, e = BEGIN.match(line), END.match(line)
            if b:
                if name:
                    errors.append(f"{rel}:{no}: snippet '{b.group(1)}' begins inside '{name}'")
                name, start, body = b.group(1), no, []
            elif e:
                if not name:
                    errors.append(f"{rel}:{no}: [end snippet] without a beginning")
                elif name in snippets:
                    errors.append(f"{rel}:{start}: snippet '{name}' also in {snippets[name][0]}")
                else:
                    fence = "```python" if path.suffix == ".py" else "```cpp"
                    snippets[name] = (rel, dedent(body), fence)
                name = None
            elif name:
                body.append(line.rstrip())
        if name:
            errors.append(f"{rel}:{start}: snippet '{name}' has no [end snippet]")
    if errors:
        print("\n".join(errors), file=sys.stderr)
        sys.exit(2)
    return snippets


def check_doc(path, snippets, strict, fix, used):
    """Returns (errors, new text or None when unchanged)."""
    rel = path.relative_to(ROOT)
    lines = path.read_text().splitlines()
    out, errors, changed = [], [], False
    i = 0
    while i < len(lines):
        line = lines[i]
        m = MARKER.match(line)
        if m:
            name = m.group(1)
            out.append(line)
            fence = snippets[name][2] if name in snippets else "```cpp"
            if i + 1 >= len(lines) or lines[i + 1] != fence:
                errors.append(
                    f"{rel}:{i + 1}: snippet marker '{name}' not followed by a {fence} fence"
                )
                i += 1
                continue
            j = i + 2
            while j < len(lines) and not FENCE.match(lines[j]):
                j += 1
            if j == len(lines):
                errors.append(f"{rel}:{i + 2}: unterminated code block")
                return errors, None
            body = lines[i + 2 : j]
            if name not in snippets:
                errors.append(
                    f"{rel}:{i + 1}: unknown snippet '{name}' (known: {', '.join(sorted(snippets))})"
                )
                new = body
            else:
                used.add(name)
                new = snippets[name][1]
                if body != new:
                    if fix:
                        changed = True
                    else:
                        errors.append(
                            f"{rel}:{i + 3}: block '{name}' differs from {snippets[name][0]}:"
                        )
                        errors.extend(
                            "    " + d
                            for d in difflib.unified_diff(
                                body, new, str(rel), str(snippets[name][0]), lineterm="", n=1
                            )
                        )
            out.append(fence)
            out.extend(new if fix else body)
            out.append(lines[j])
            i = j + 1
            continue
        if strict and line.startswith("```cpp"):
            errors.append(
                f"{rel}:{i + 1}: a ```cpp block without a '<!-- snippet: NAME -->' marker "
                "(doc code must come from examples/)"
            )
        # Skip over any other fenced block so that its contents are not read as markers.
        if FENCE.match(line):
            j = i + 1
            while j < len(lines) and not FENCE.match(lines[j]):
                j += 1
            out.extend(lines[i : j + 1])
            i = j + 1
            continue
        out.append(line)
        i += 1
    text = "\n".join(out) + "\n"
    return errors, (text if changed else None)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument(
        "--fix", action="store_true", help="rewrite the doc blocks from the examples"
    )
    args = parser.parse_args()

    snippets = read_examples()
    used, errors = set(), []
    docs = sorted(DOCS.glob("*.md"))
    for path in docs:
        strict = str(path.relative_to(ROOT)) in STRICT
        errs, new = check_doc(path, snippets, strict, args.fix, used)
        errors += errs
        if new is not None:
            path.write_text(new)
            print(f"rewrote {path.relative_to(ROOT)}")
    for name in sorted(set(snippets) - used):
        print(f"note: snippet '{name}' ({snippets[name][0]}) is shown in no doc")
    if errors:
        print("\n".join(errors), file=sys.stderr)
        print(
            "run scripts/check_snippets.py --fix to copy the examples into the docs",
            file=sys.stderr,
        )
        return 1
    print(f"{len(used)} snippet(s) in the docs match examples/")
    return 0


if __name__ == "__main__":
    sys.exit(main())
