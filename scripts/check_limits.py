#!/usr/bin/env python3
"""The size limits of issue 19: no file in src/ or include/ over 350 lines, no
function over 80 lines. Functions are found by brace matching (Google style):
a body is a '{' at brace depth 0, or directly inside a namespace, class or
struct, whose opening line looks like a function head (a ')' before the '{',
not a control statement, not an initialiser or lambda assignment); its length
is from the head's first line to the closing '}'. Comments and string
literals are blanked first. Usage: check_limits.py [ROOT] [--allow FILE] | --self-test
(FILE: lines 'path:function  # why', each a justified exception).
Also issue 19's "no numeric threshold literal outside the tolerance
definitions" (threshold_literals). In the library's code (src/ but src/cli and
src/apps, whose 1e3 are units and whose defaults are options), outside the
tolerance headers src/numerics/tolerances*.hpp, it reports (1) every literal
in exponent form (1e-9, 2e3) and (2) every decimal literal with a '.' (0.5,
not 0.0 or 1.0) and every integer literal >= 10 (an iteration cap it < 100,
an option range n > 64) that is compared: a side of a binary <, >, <= or >=
(clang-format puts spaces around it; a template's brackets touch their
names), alone, as a factor or a term (x < 0.1 * step, a > y + 0.5) or inside
a grouping '(...)'. In the public headers (include/) the same literals are
reported unless their statement defines a named constant (constexpr) with a
comment on its line or above, or gives a data member its default (an
option's default, documented in docs/cli.md). Not thresholds, by rule: 0 and
1 (a sign, the unit circle: the mathematics) and integers below 10 (small
counts: n < 2, k > 3); a literal not compared (0.5 * (a + b), J << 0.0, 1.0,
os << 100 + i, n % 10 == 0, figure geometry); a literal inside a call's
arguments or an index (std::abs(x - 0.5) < t, v[16] < y); a literal
assigned to a variable compared later; comments and strings. --self-test
runs the literal rules on a small tree (SELF_TEST) and exits 1 unless
exactly its marked lines are reported."""
import os
import re
import sys

MAX_FILE, MAX_FUNCTION = 350, 80
LITERAL_FREE, PUBLIC = ('src' + os.sep,), 'include' + os.sep
LITERAL_EXEMPT = (os.path.join('src', 'cli'), os.path.join('src', 'apps'))
# The tolerance definitions: tolerances.hpp and its parts (tolerances_fixed.hpp).
TOLERANCES = re.compile(r'src[/\\]numerics[/\\]tolerances(_\w+)?\.hpp$')
TOKEN = re.compile(r'(?P<num>(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?[fFlLuU]*)|(?P<id>[A-Za-z_]\w*)'
                   r'|(?P<op><<=|>>=|->|::|<<|>>|<=|>=|==|!=|&&|\|\||\+\+|--|[-+*/%&|^]=|\S)')
RELATIONAL = ('<', '>', '<=', '>=')
# Tokens inside one arithmetic operand: a comparison's side is walked across them.
OPERAND = ('*', '/', '%', '+', '-', '.', '->', '::', '!', '~')
OPEN, CLOSE = '([{', ')]}'


def tokens(code):
    """(text, kind, start, end, binary) of each token; binary: a '<', '>', '<=' or
    '>=' with whitespace on both sides (clang-format's binary operator; a
    template's brackets touch their names)."""
    out = []
    for m in TOKEN.finditer(code):
        s, e = m.span()
        binary = (m.group() in RELATIONAL and (s == 0 or code[s - 1].isspace())
                  and (e == len(code) or code[e].isspace()))
        out.append((m.group(), m.lastgroup, s, e, binary))
    return out


def matching(toks):
    """Index of the bracket that matches each bracket (-1: unmatched)."""
    match, stack = [-1] * len(toks), []
    for k, t in enumerate(toks):
        if t[0] in OPEN:
            stack.append(k)
        elif t[0] in CLOSE and stack:
            match[k] = stack.pop()
            match[match[k]] = k
    return match


def compared(toks, match, lo, hi):
    """Whether tokens lo..hi (one operand) are a side of a binary <, >, <= or >=,
    directly, as a factor or term of a side, or inside a grouping '(...)'."""
    part = lambda t: t[1] in ('num', 'id') or t[0] in OPERAND or \
        (t[0] in ('<', '>') and not t[4])
    left = lo - 1
    while left >= 0:
        if toks[left][0] in CLOSE and match[left] >= 0:
            left = match[left] - 1
        elif part(toks[left]):
            left -= 1
        else:
            break
    right = hi + 1
    while right < len(toks):
        if toks[right][0] in OPEN and match[right] >= 0:
            right = match[right] + 1
        elif part(toks[right]):
            right += 1
        else:
            break
    stops = [toks[k] for k in (left, right) if 0 <= k < len(toks)]
    if any(t[4] for t in stops):
        return True
    grouping = (0 <= left and toks[left][0] == '(' and match[left] == right and
                (left == 0 or toks[left - 1][0] == 'return' or
                 toks[left - 1][1] != 'id' and toks[left - 1][0] != '>'))
    return grouping and compared(toks, match, left, right)
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


def brace_kind(code, i, stack):
    """The kind of the '{' at i: namespace, class, function or block (stack:
    the kinds of the braces open around it)."""
    head_start = max(code.rfind(';', 0, i), code.rfind('}', 0, i), code.rfind('{', 0, i)) + 1
    head = code[head_start:i]
    if all(k in ('namespace', 'class') for k in stack):
        h = ' '.join(head.split())
        if re.search(r'\bnamespace\b', h) or h.startswith('extern "'):
            return 'namespace', head_start, head
        if re.search(r'\b(class|struct|union|enum)\b[^()]*$', h):
            return 'class', head_start, head
        if ')' in h and not CONTROL.search(h) and not re.search(r'=\s*\[', h) \
                and not h.rstrip().endswith('='):
            return 'function', head_start, head
    return 'block', head_start, head


def functions(text):
    """(name, first line, lines) of every function body at namespace or class level."""
    code = blank(text)
    found, stack, i = [], [], 0  # stack: kinds of open braces
    line_of = lambda pos: code.count('\n', 0, pos) + 1
    while i < len(code):
        c = code[i]
        if c == '{':
            kind, head_start, head = brace_kind(code, i, stack)
            if kind == 'function':
                h = ' '.join(head.split())
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


def class_level(code):
    """Per character of code: whether the innermost open brace there is a class's."""
    flags, stack = bytearray(len(code)), []
    for i, c in enumerate(code):
        if c == '{':
            stack.append(brace_kind(code, i, stack)[0])
        elif c == '}' and stack:
            stack.pop()
        flags[i] = bool(stack) and stack[-1] == 'class'
    return flags


def directives_blank(code):
    """Preprocessor conditions (#if, #elif and their continuation lines) replaced
    by spaces: a compiler version there is no numerical threshold. A #define's
    body is still read."""
    out, directive = [], False
    for line in code.split('\n'):
        directive = directive or re.match(r'\s*#\s*(if|elif)\b', line) is not None
        out.append(' ' * len(line) if directive else line)
        directive = directive and line.rstrip().endswith('\\')
    return '\n'.join(out)


def threshold_literals(text, public):
    """(line, literal) of each threshold literal: every literal in exponent form,
    and every decimal one (a '.', not 0 or 1) that is compared (see compared).
    In a public header (public) a literal is left alone where its statement
    defines a documented constant (constexpr, a comment on its line or above)
    or gives a data member its default (no '(' in the statement, at class level)."""
    code = directives_blank(blank(text))
    toks = tokens(code)
    match, lines = matching(toks), text.split('\n')
    at_class = class_level(code) if public else None
    found = []
    for k, (t, kind, start, _, _) in enumerate(toks):
        if kind != 'num' or t.lower().startswith('0x'):
            continue
        exponent = bool(re.search(r'[eE]', t))
        value = float(t.rstrip('fFlLuU'))
        counted = '.' in t or value >= 10  # a decimal, or an integer >= 10
        if not exponent and (not counted or value in (0.0, 1.0)
                             or not compared(toks, match, k, k)):
            continue
        line = code.count('\n', 0, start) + 1
        if public:
            s = max(code.rfind(';', 0, start), code.rfind('{', 0, start),
                    code.rfind('}', 0, start)) + 1
            statement = code[s:start]
            first = code.count('\n', 0, s + len(statement) - len(statement.lstrip())) + 1
            above = lines[first - 2].strip() if first >= 2 else ''
            documented = '//' in lines[line - 1] or above.startswith('//') or above.endswith('*/')
            if re.search(r'\bconstexpr\b', statement) and documented:
                continue
            if at_class[start] and '(' not in statement:
                continue
        found.append((line, t))
    return found


def check(root, allow):
    """The problems found under root (allow: the justified exceptions)."""
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
                public = rel.startswith(PUBLIC)
                if public or (rel.startswith(LITERAL_FREE) and not rel.startswith(LITERAL_EXEMPT)
                              and not TOLERANCES.match(rel)):
                    for k, literal in threshold_literals(text, public):
                        if f'{rel}:{k}' not in allow:
                            problems.append(f'{rel}:{k}: threshold literal {literal} ' + (
                                'neither a documented constant nor a member default'
                                if public else 'outside src/numerics/tolerances*.hpp'))
                for name, first, length in functions(text):
                    if length > MAX_FUNCTION and f'{rel}:{name}' not in allow:
                        problems.append(f'{rel}:{first}: {name} is {length} lines '
                                        f'(limit {MAX_FUNCTION})')
    return problems


SELF_TEST = {  # path: text; the lines marked /* bad */ must be reported, no other
    'src/orbits/orbit.cpp': """#if defined(__GNUC__) && __GNUC__ >= 11 && \\
    __GNUC_MINOR__ > 12
#define K 1
#define TOL 1e-9 /* bad */
#endif
void F(double x, double y, double a, double b, int n) {
  if (x < 0.3 * y) return; /* bad */
  if ((0.25 * a) >= b) return; /* bad */
  const bool up = x > -0.7; /* bad */
  const double tiny = 2e-3; /* bad */
  const double mid = 0.5 * (a + b);
  J << 0.0, 1.0, -1.0, 2.5;
  const bool stable = std::abs(a) < 1.0;
  os << 5.5 + static_cast<double>(n) << std::array<double, 2>{0.25, 0.75}[0];
  if (2 * (x - a) > b && n < 9) return;
  for (int it = 0; it < 100; ++it) x *= 0.5; /* bad */
  if (n >= 16 * k) return; /* bad */
  os << "set label " << 100 + n << " n < 150";  // n < 150
  if (v[16] < y || Pow(x, 12) > y || n % 10 == 0 || (1 << 20) == n) return;
  std::array<double, 16> w{};
}
""",
    'src/cli/cli.cpp': 'const double ms = 1e3 * s;\n',
    'src/numerics/tolerances.hpp': 'static constexpr double kA = 1e-9, kB = 0.5;\n',
    'include/stickslip/o.hpp': """struct O {
  double rtol = 1e-10;
  double w = 0.5, atol = 1e-13;
  // documented
  static constexpr double kMax = 1e6;
  void Set(double t = 1e-6); /* bad */
};

/// documented
constexpr double kMin = 1e-6;

constexpr double kBare = 1e-3; /* bad */

double G(double t = 1e-6); /* bad */

inline bool H(double a, double b) { return a < 0.25 * b; } /* bad */

struct P {
  // documented
  static constexpr int kMaxN = 1000;
  int n = 200;
  bool Big() const { return n > 64; } /* bad */
};
""",
}


def self_test():
    """Runs the literal rules on SELF_TEST's tree; 0 if exactly the marked lines are reported."""
    import tempfile
    with tempfile.TemporaryDirectory() as root:
        want = set()
        for rel, text in SELF_TEST.items():
            os.makedirs(os.path.dirname(os.path.join(root, rel)), exist_ok=True)
            open(os.path.join(root, rel), 'w').write(text)
            want |= {f'{rel}:{k}' for k, l in enumerate(text.split('\n'), 1) if '/* bad */' in l}
        got = {p.split(': ')[0] for p in check(root, set())}
    for p in sorted(want ^ got):
        print(f'self-test: {p} ' + ('missed' if p in want else 'reported in error'))
    print(f'check_limits self-test: {len(want & got)} of {len(want)} found, '
          f'{len(got - want)} false')
    return 0 if want == got else 1


def main(argv):
    root, allow = '.', set()
    args = argv[1:]
    if '--self-test' in args:
        return self_test()
    if '--allow' in args:
        k = args.index('--allow')
        for line in open(args[k + 1]):
            entry = line.split('#')[0].strip()
            if entry:
                allow.add(entry)
        del args[k:k + 2]
    if args:
        root = args[0]
    problems = check(root, allow)
    for p in problems:
        print(p)
    print(f'check_limits: {len(problems)} over the limits')
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
