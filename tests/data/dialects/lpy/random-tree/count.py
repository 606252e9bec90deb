# Independent derivation (written without lsolid) of L-Py's tutorial
# random tree, share/tutorial/04 - simple-plant-archi/02 - random-tree.lpy,
# with lsolid's random numbers: cpfg's erand48 from its first state 0x330E,
# one draw per A rewritten (its body runs once per module), modules in
# string order. Prints what the turtle draws after 250 steps: the F and C
# modules (C draws as F in the homomorphism) and the ~l and k leaves (k
# draws as ~l), each ~l PlantGL's hexagon of 6 triangles.
#
#   python3 count.py
MASK = (1 << 48) - 1
state = 0x330E


def rand():
    global state
    state = (0x5DEECE66D * state + 0xB) & MASK
    return state / 2.0**48


PHI, ALPHA, BETA, STEP, STEPLEAF = 90, 32, 20, 0.1, 0.02


def step(s):
    out = []
    for m in s:
        n = m[0]
        if n == 'A':
            k = m[1]
            p1 = min(1, (2 * k + 1) / k**2)
            if rand() <= p1:
                out += [['/', PHI], ['['], ['+', ALPHA], ['C', 0.1, k], [']'],
                        ['-', BETA], ['C', STEP, k]]
            else:
                out += [['/', PHI], ['['], ['+', ALPHA], ['/', 90], [';'],
                        ['k', STEP], [']'], ['-', BETA], ['C', 0.1, k]]
        elif n == 'C':
            x, k = m[1], m[2]
            if x >= 1:
                out.append(['F', 1, 0.05 + 0.25 / k])
                if k < 19:
                    out.append(['A', k + 1])
            else:
                out.append(['C', x + STEP, k])
        elif n == 'k':
            s_ = m[1]
            out.append(['~l', s_] if s_ >= 1.2 else ['k', s_ + STEPLEAF])
        else:
            out.append(m)
    return out


s = [['_', 0.3], ['@Gs'], ['G', 1], ['A', 1.0]]
for _ in range(250):
    s = step(s)
segments = sum(1 for m in s if m[0] in ('F', 'C'))
leaves = sum(1 for m in s if m[0] in ('~l', 'k'))
print(f'segments {segments}, polygons 0, surfaces {leaves} of '
      f'{6 * leaves} triangles')
