#!/usr/bin/env python3
"""The size limits of issue 19: no file in src/ or include/ over 350 lines, no
function over 80 lines. Functions are found by brace matching (Google style):
a body is a '{' at brace depth 0, or directly inside a namespace, class or
struct, whose opening line looks like a function head (a ')' before the '{',
not a control statement, not an initialiser or lambda assignment); its length
is from the head's first line to the closing '}'. Comments and string
literals are blanked first. Usage: check_limits.py [ROOT] [--allow FILE]
(FILE: lines 'path:function  # why', each a justified exception).
Also issue 19's "no numeric threshold literal outside the tolerance
definitions": a literal in exponent form (1e-9, 2e3) in the library's code
(src/ but src/cli and src/apps, whose 1e3 are units and whose defaults are
options) outside src/numerics/tolerances.hpp is reported. Not checked: the
public headers (include/: option defaults, and three public constants
documented where declared: params.hpp's kMinScale/kMaxScale,
continuation.hpp's kLoosestTrustedRtol, plane.hpp's kMinRelativeWidth), and
literals in decimal form (0.5, 1000000)."""
import os
import re
import sys

MAX_FILE, MAX_FUNCTION = 350, 80
EXPONENT = re.compile(r'(?<![\w.])(\d+\.?\d*|\.\d+)[eE][-+]?\d+')
LITERAL_FREE = ('src' + os.sep,)
LITERAL_EXEMPT = (os.path.join('src', 'cli'), os.path.join('src', 'apps'),
                  os.path.join('src', 'numerics', 'tolerances.hpp'))
CONTROL = re.compile(r'\b(if|for|while|switch|catch|do|else)\b\s*(\(|$)')


def blank(text):
    """Comments and string/char literals replaced by spaces (newlines kept)."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith('//', i):
            j = text.find('\n', i)
            j = n if j < 0 else j
            out.append(' ' * (j - i)); i = j
        elif text.startswith('/*', i):
            j = text.find('*/', i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r'[^\n]', ' ', text[i:j])); i = j
        elif text.startswith('R"', i):
            m = re.match(r'R"([^(]*)\(', text[i:])
            end = text.find(')' + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(re.sub(r'[^\n]', ' ', text[i:j])); i = j
        elif c in '"\'':
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == '\\' else 1
            out.append(c + ' ' * (j - i - 1) + c); i = j + 1
        else:
            out.append(c); i += 1
    return ''.join(out)


def functions(text):
    """(name, first line, lines) of every function body at namespace or class level."""
    code = blank(text)
    found, stack, i = [], [], 0  # stack: kinds of open braces
    line_of = lambda pos: code.count('\n', 0, pos) + 1
    while i < len(code):
        c = code[i]
        if c == '{':
            head_start = max(code.rfind(';', 0, i), code.rfind('}', 0, i), code.rfind('{', 0, i)) + 1
            head = code[head_start:i]
            kind = 'block'
            if all(k in ('namespace', 'class') for k in stack):
                h = ' '.join(head.split())
                if re.search(r'\bnamespace\b', h) or h.startswith('extern "'):
                    kind = 'namespace'
                elif re.search(r'\b(class|struct|union|enum)\b[^()]*$', h):
                    kind = 'class'
                elif ')' in h and not CONTROL.search(h) and not re.search(r'=\s*\[', h) \
                        and not h.rstrip().endswith('='):
                    kind = 'function'
                    name = re.findall(r'([~\w:]+(?:operator\s*\S+)?)\s*\(', h)
                    first = line_of(head_start + len(head) - len(head.lstrip()))
                    found.append([name[0] if name else '?', first, i])
            stack.append(kind)
        elif c == '}' and stack:
            kind = stack.pop()
            if kind == 'function':
                for f in reversed(found):
                    if isinstance(f[2], int) and f[2] >= 0 and len(f) == 3:
                        f.append(line_of(i) - f[1] + 1)
                        break
        i += 1
    return [(f[0], f[1], f[3]) for f in found if len(f) == 4]


def main(argv):
    root, allow = '.', set()
    args = argv[1:]
    if '--allow' in args:
        k = args.index('--allow')
        for line in open(args[k + 1]):
            entry = line.split('#')[0].strip()
            if entry:
                allow.add(entry)
        del args[k:k + 2]
    if args:
        root = args[0]
    problems = []
    for top in ('src', 'include'):
        for d, _, files in os.walk(os.path.join(root, top)):
            for f in sorted(files):
                if not f.endswith(('.cpp', '.hpp', '.h', '.cc')):
                    continue
                path = os.path.join(d, f)
                rel = os.path.relpath(path, root)
                text = open(path, encoding='utf-8').read()
                n = text.count('\n')
                if n > MAX_FILE and rel not in allow:
                    problems.append(f'{rel}: {n} lines (limit {MAX_FILE})')
                if rel.startswith(LITERAL_FREE) and not rel.startswith(LITERAL_EXEMPT):
                    for k, line in enumerate(blank(text).split('\n'), 1):
                        m = EXPONENT.search(line)
                        if m and f'{rel}:{k}' not in allow:
                            problems.append(f'{rel}:{k}: threshold literal {m.group(0)} '
                                            'outside src/numerics/tolerances.hpp')
                for name, first, length in functions(text):
                    if length > MAX_FUNCTION and f'{rel}:{name}' not in allow:
                        problems.append(f'{rel}:{first}: {name} is {length} lines '
                                        f'(limit {MAX_FUNCTION})')
    for p in problems:
        print(p)
    print(f'check_limits: {len(problems)} over the limits')
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
