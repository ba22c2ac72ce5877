#!/usr/bin/env python3
"""Runs the walk-through of docs/own-system.md as a user would.

In a fresh temporary folder it writes the page's ```ini block under the name the
first command's --model gives, runs every command of its ```sh blocks (the apps
from BUILD_DIR), requires exit 0, and requires every line of the ```text block
that follows a command in its standard output. Exits 1 naming the first
command or line that fails.

Usage: check_walkthrough.py BUILD_DIR
"""
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PAGE = os.path.join(ROOT, "docs", "own-system.md")
BLOCK = re.compile(r"^```(\w+)\n(.*?)^```", re.S | re.M)


def main():
    if len(sys.argv) != 2:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    build = os.path.abspath(sys.argv[1])
    blocks = [(m.group(1), m.group(2)) for m in BLOCK.finditer(open(PAGE).read())]
    model = [text for kind, text in blocks if kind == "ini"]
    steps = []  # (command, expected lines)
    for kind, text in blocks:
        if kind == "sh":
            steps += [[line.strip(), []] for line in text.splitlines() if line.strip()]
        elif kind == "text" and steps:
            steps[-1][1] += [line for line in text.splitlines() if line.strip()]
    if len(model) != 1 or not steps:
        print("own-system.md: expected one ini block and sh blocks", file=sys.stderr)
        return 1
    name = re.search(r"--model (\S+)", steps[0][0]).group(1)
    with tempfile.TemporaryDirectory() as work:
        with open(os.path.join(work, name), "w") as f:
            f.write(model[0])
        for command, expected in steps:
            words = command.split()
            words[0] = os.path.join(build, words[0])
            run = subprocess.run(words, cwd=work, capture_output=True, text=True, timeout=600)
            if run.returncode != 0:
                print(f"own-system.md: '{command}' exited {run.returncode}: {run.stderr.strip()}",
                      file=sys.stderr)
                return 1
            for line in expected:
                if line not in run.stdout:
                    print(f"own-system.md: '{command}' did not print '{line}':\n{run.stdout}",
                          file=sys.stderr)
                    return 1
            print(f"ok  {command}  ({len(expected)} lines checked)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
