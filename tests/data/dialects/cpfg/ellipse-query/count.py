# Independent derivation (written without lsolid) of two forms of one
# model, an apex whose branches are pruned where their query ?P finds them
# outside an ellipse; the query is answered by a turtle walk before each
# step, as cpfg and L-Py do. A turtle in the plane of the branches: height
# z and a lateral coordinate y (the condition is symmetric in y).
#
#   python3 count.py        vlab's Enviro-sensitive/ellipse (cpfg): 360
#                           discs, then 39 steps of the apex; a ?P inside
#                           the ellipse stays
#   python3 count.py lpy    L-Py's share/examples/ex_lsystem2.lpy: 24 steps;
#                           a ?P inside is erased (produce *)
import math
import sys

LPY = len(sys.argv) > 1 and sys.argv[1] == 'lpy'


def interpret(s):
    stack = []
    y = z = a = 0.0
    for m in s:
        n = m[0]
        if n == 'F':
            y -= math.sin(math.radians(a))
            z += math.cos(math.radians(a))
        elif n == '+':
            a += m[1]
        elif n == '-':
            a -= m[1]
        elif n == '[':
            stack.append((y, z, a))
        elif n == ']':
            y, z, a = stack.pop()
        elif n == '?P':
            m[1:] = [y, z]


def step(s):
    out = []
    for m in s:
        n = m[0]
        if n == 'A':
            out += [['['], ['+', 60], ['B'], [']'], ['['], ['-', 60], ['B'],
                    [']'], ['F'], ['?P', 0, 0], ['A']]
        elif n == 'B':
            out += [['F'], ['?P', 0, 0], ['@O'], ['B']]
        elif n == '?P':
            y, z = m[1:]
            if 4 * y * y + (z - 10) ** 2 > 100:
                out += [['['], ['+', 2 * z], ['F'], [']'], ['['],
                        ['-', 2 * z], ['F'], [']'], ['%']]
            elif not LPY:
                out.append(m)
        else:
            out.append(m)
    # % erases itself and the rest of its branch.
    kept = []
    i = 0
    while i < len(out):
        if out[i][0] == '%':
            depth = 0
            i += 1
            while i < len(out):
                if out[i][0] == '[':
                    depth += 1
                elif out[i][0] == ']':
                    if depth == 0:
                        break
                    depth -= 1
                i += 1
            continue
        kept.append(out[i])
        i += 1
    return kept


s = [['A']]
for _ in range(24 if LPY else 39):
    interpret(s)
    s = step(s)
print('segments', sum(1 for m in s if m[0] == 'F'),
      'polygons', 0 if LPY else 360,
      'spheres', sum(1 for m in s if m[0] == '@O'))
