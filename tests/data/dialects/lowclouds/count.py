# Independent count of drawn segments (F, G) for simple L-system Explorer
# files: D0L and parametric productions without context; written for the
# corpus of lsolid, without lsolid's code.
import math, re, sys

def modules(s):
    out, i = [], 0
    while i < len(s):
        c = s[i]; i += 1
        if c == '@':
            c += s[i]; i += 1
        if i < len(s) and s[i] == '(':
            d, j = 1, i + 1
            while d:
                d += {'(': 1, ')': -1}.get(s[j], 0); j += 1
            out.append((c, s[i+1:j-1])); i = j
        else:
            out.append((c, None))
    return out

def split_args(a):
    out, d, cur = [], 0, ''
    for ch in a:
        if ch == ',' and d == 0: out.append(cur); cur = ''; continue
        d += ch == '('; d -= ch == ')'; cur += ch
    return out + [cur]

def py(e):
    e = e.replace('^', '**').replace('&&', ' and ').replace('||', ' or ')
    return e

def run(consts, axiom, rules, n):
    env = dict(consts); env.update(math=math)
    s = [(m, [eval(py(x), env) for x in split_args(a)] if a else None) for m, a in modules(axiom)]
    for _ in range(n):
        out = []
        for m, p in s:
            for pm, names, cond, succ in rules:
                if pm != m or (names is None) != (p is None): continue
                if names and len(names) != len(p): continue
                loc = dict(env); loc.update(zip(names or [], p or []))
                if cond and not eval(py(cond), loc): continue
                for sm, sa in modules(succ):
                    out.append((sm, [eval(py(x), loc) for x in split_args(sa)] if sa else None))
                break
            else:
                out.append((m, p))
        s = out
    return s

def read(path):
    consts, rules, axiom, n = {}, [], None, None
    text = re.sub(r'/\*.*?\*/', '', open(path).read(), flags=re.S)
    for line in text.splitlines():
        line = line.strip()
        if not line: continue
        m = re.match(r'#define\s+(\w+)\s+(.*)', line)
        if m: consts[m.group(1)] = eval(m.group(2)); continue
        m = re.match(r'(?:derivation length|dlength)\s*:\s*(\d+)', line)
        if m: n = int(m.group(1)); continue
        m = re.match(r'axiom\s*:\s*(.*)', line)
        if m: axiom = m.group(1).replace(' ', ''); continue
        if '->' in line:
            line = re.sub(r'^[pP]\d+\s*:', '', line)
            lhs, succ = re.split(r'--?>', line, 1)
            cond = None
            if ':' in lhs: lhs, cond = lhs.split(':', 1)
            (pm, pa), = modules(lhs.replace(' ', ''))
            rules.append((pm, [x.strip() for x in pa.split(',')] if pa else None, cond, succ.replace(' ', '')))
            continue
        for piece in re.split(r'[;,]', line):
            m = re.match(r'(\w+)\s*[=:]\s*([-\d.]+)\s*$', piece.strip())
            if m: consts[m.group(1)] = float(m.group(2))
    if n is None: n = int(consts.get('n', 1))
    return consts, axiom, rules, n

consts, axiom, rules, n = read(sys.argv[1])
s = run(consts, axiom, rules, n)
print(sys.argv[1], 'n =', n, 'segments', sum(1 for m, _ in s if m in 'FG'), 'polygons', sum(1 for m, _ in s if m == '{'), 'spheres', sum(1 for m, _ in s if m == '@O'))
