#!/usr/bin/env python3
"""The README's map of the library is true: its subsystems (the folders of src/
and include/stickslip/ in the code block under "## How it works", top first,
folders on one line one level) each include only their own headers and those
of folders above them. Every folder of src/ (but cli/ and apps/, the command
line, which may use all) must be on the map. A back-arrow is allowed only as a
line 'path -> folder  # why' of scripts/layers_allow.txt, each used. A public
header (include/) includes only public ones (stickslip/...), and no include is
relative (../).
Usage: check_layers.py [ROOT] | --self-test. Exit 1 on a violation."""
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+[<"]((?:stickslip/)?)([a-z_.]+)/', re.M)
COMMAND_LINE = {'cli', 'apps'}


def read_map(readme_text):
    """{folder: level} from the code block after '## How it works'."""
    at = readme_text.find('## How it works')
    if at < 0:
        raise ValueError("README.md has no '## How it works' section")
    start = readme_text.find('```', at)
    end = readme_text.find('```', start + 3)
    levels = {}
    for level, line in enumerate(readme_text[start + 3:end].strip('\n').splitlines()):
        for word in line.split():
            if not word.endswith('/'):
                break
            levels[word.rstrip('/')] = level
    return levels


def read_allowed(text):
    """{(path, folder)} from 'path -> folder  # why' lines."""
    allowed = set()
    for line in text.splitlines():
        line = line.split('#', 1)[0].strip()
        if not line:
            continue
        if line.count('->') != 1:
            raise ValueError("layers_allow.txt: '%s' is no 'path -> folder' line" % line)
        path, folder = (x.strip() for x in line.split('->'))
        allowed.add((path, folder))
    return allowed


def sources(root):
    """(path relative to root, its subsystem) of every library file."""
    for base in ('src', os.path.join('include', 'stickslip')):
        top = os.path.join(root, base)
        for sub in sorted(os.listdir(top)):
            folder = os.path.join(top, sub)
            if not os.path.isdir(folder) or sub in COMMAND_LINE:
                continue
            for d, _, files in os.walk(folder):
                for f in sorted(files):
                    if f.endswith(('.hpp', '.cpp', '.h')):
                        yield os.path.relpath(os.path.join(d, f), root), sub


def check(root, levels, allowed, read=lambda p: open(p, encoding='utf-8').read()):
    problems, used = [], set()
    for path, sub in sources(root):
        if sub not in levels:
            problems.append('%s: folder %s/ is not on the README\'s map' % (path, sub))
            continue
        public = path.startswith('include' + os.sep)
        for prefix, target in INCLUDE.findall(read(os.path.join(root, path))):
            if target == '..':
                problems.append('%s: a relative include (../): name the folder' % path)
                continue
            if public and not prefix and target in levels:
                problems.append('%s: a public header includes the private %s/' % (path, target))
            if target == sub or target not in levels or levels[target] <= levels[sub]:
                continue
            if (path, target) in allowed:
                used.add((path, target))
                continue
            problems.append('%s: %s/ includes %s/, which is below it on the README\'s map'
                            % (path, sub, target))
    for path, target in sorted(allowed - used):
        problems.append('layers_allow.txt: %s -> %s is no longer needed' % (path, target))
    return problems


def self_test():
    import tempfile
    with tempfile.TemporaryDirectory() as root:
        for rel, text in {'src/a/x.cpp': '#include "b/y.hpp"\n',
                          'src/b/y.hpp': '#include "stickslip/a/x.hpp"\n',
                          'include/stickslip/a/z.hpp': '#include "stickslip/c/w.hpp"\n',
                          'src/cli/q.cpp': '#include "c/w.hpp"\n',
                          'include/stickslip/b/v.hpp': '#include <stickslip/a/x.hpp>\n'
                                                       '#include "b/private.hpp"\n'}.items():
            os.makedirs(os.path.dirname(os.path.join(root, rel)), exist_ok=True)
            open(os.path.join(root, rel), 'w').write(text)
        levels = read_map('## How it works\n```\na/    A\nb/  c/   B and C\n```\n')
        assert levels == {'a': 0, 'b': 1, 'c': 1}, levels
        got = check(root, levels, set())
        assert len(got) == 3 and 'src/a/x.cpp' in got[0] and 'z.hpp' in got[1], got
        assert 'private b/' in got[2], got
        got = check(root, levels, {('src/a/x.cpp', 'b'), ('src/a/x.cpp', 'c')})
        assert len(got) == 3 and 'no longer needed' in got[2], got
        try:
            read_allowed('src/a/x.cpp b\n')
            raise AssertionError('a line without -> was taken')
        except ValueError:
            pass
    print('check_layers self-test passed')


def main(argv):
    if argv[1:] == ['--self-test']:
        self_test()
        return 0
    root = argv[1] if len(argv) > 1 else os.path.join(os.path.dirname(__file__), '..')
    levels = read_map(open(os.path.join(root, 'README.md'), encoding='utf-8').read())
    allow = os.path.join(root, 'scripts', 'layers_allow.txt')
    allowed = read_allowed(open(allow, encoding='utf-8').read()) if os.path.exists(allow) else set()
    problems = check(root, levels, allowed)
    for p in problems:
        print(p)
    print('%d folders on the map, %d back-arrows allowed, %d problems'
          % (len(levels), len(allowed), len(problems)))
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
