#!/usr/bin/env python3
"""Docs describe the tool as it is; history goes in docs/CHANGELOG.md.

Fails (exit 1) when README.md, docs/*.md other than CHANGELOG.md, or the --help
of any app names an issue number ("issue 20", "issues 19 and 21", "old #20") or
speaks of a round of work ("last round", "the round before", "the old run", "a
reviewer's run"). Each hit is printed as FILE:LINE: TEXT.

Usage: check_doc_words.py [--self-test] [BUILD_DIR]   (BUILD_DIR holds the apps)
"""
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
APPS = ("ss_continue", "ss_chart", "ss_basin", "ss_simulate", "ss_orbit_diagram")
PATTERNS = [
    re.compile(r"\bissues?\s+#?\d+", re.I),
    re.compile(r"\bold\s+#\d+", re.I),
    re.compile(r"\b(last|previous|this|next)\s+round\b", re.I),
    re.compile(r"\bthe\s+round\s+before\b", re.I),
    re.compile(r"\bthe\s+old\s+run\b", re.I),
    re.compile(r"\breviewer'?s?\b", re.I),
]


def hits(name, text):
    out = []
    for number, line in enumerate(text.splitlines(), 1):
        if any(p.search(line) for p in PATTERNS):
            out.append(f"{name}:{number}: {line.strip()}")
    return out


def self_test():
    bad = ["see issue 20", "Issues 19 and 21", "(old #20)", "the LP doubtful last round",
           "the round before (ospeed)", "the old run passed", "a reviewer's run"]
    good = ["the issue of accuracy", "round-off 1e-16", "a round trip", "20 issues"]
    missed = [s for s in bad if not hits("t", s)]
    false = [s for s in good if hits("t", s)]
    for s in missed:
        print(f"self-test: not reported: {s!r}")
    for s in false:
        print(f"self-test: wrongly reported: {s!r}")
    print(f"self-test: {len(bad) - len(missed)} of {len(bad)} reported, {len(false)} false")
    return 1 if missed or false else 0


def main(argv):
    if argv[1:2] == ["--self-test"]:
        return self_test()
    build = pathlib.Path(argv[1]) if len(argv) > 1 else ROOT / "build"
    found = []
    files = [ROOT / "README.md"] + sorted((ROOT / "docs").glob("*.md"))
    for path in files:
        if path.name == "CHANGELOG.md":
            continue
        found += hits(str(path.relative_to(ROOT)), path.read_text(encoding="utf-8"))
    for app in APPS:
        exe = build / app
        if not exe.exists():
            print(f"check_doc_words.py: {exe} not found; build it first", file=sys.stderr)
            return 2
        run = subprocess.run([str(exe), "--help"], capture_output=True, text=True, check=False)
        found += hits(f"{app} --help", run.stdout + run.stderr)
    for line in found:
        print(line)
    print(f"check_doc_words.py: {len(found)} line(s) name an issue number or a round of work")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
