"""The atlas's polygons against `solve` close to the band's boundary: reads one or more
`arch-enum atlas --json` documents of the same rectangle (e.g. the 46-column map, with and
without the traced boundary), draws random (alpha, mu) with alpha in [A0, A1] and
d = mu/mu_ms - 1 log-uniform in [D0, D1], runs `arch-enum solve` at each and counts, per
document, the points whose point-in-polygon kind differs from solve's (no point is skipped
for being near a boundary). Prints each disagreement and the counts.

    target/release/arch-enum atlas --alpha-min 0.55 --alpha-max 1.0 --columns 46 \\
        --mu-max-factor 1.2 --json > band.json
    python3 scripts/atlas_band_check.py target/release/arch-enum 2000 band.json [other.json ...]

`--box A0 A1 D0 D1` draws from another box (alpha in [A0, A1], d in [D0, D1]).
"""
import json, random, subprocess, sys

args = sys.argv[1:]
A0, A1, D0, D1 = 0.6, 0.93, 1e-3, 0.1
if '--box' in args:  # --box A0 A1 D0 D1: another box of alpha and d
    k = args.index('--box')
    A0, A1, D0, D1 = map(float, args[k + 1:k + 5])
    del args[k:k + 5]
BIN, WANT, paths = args[0], int(args[1]), args[2:]
docs = [[(r['kind'], r['polygon']) for r in json.load(open(p))['regions']] for p in paths]


def inside(poly, a, m):
    c = False
    for i in range(len(poly)):
        p, q = poly[i], poly[(i + 1) % len(poly)]
        if (p[1] > m) != (q[1] > m):
            if a < p[0] + (m - p[1]) * (q[0] - p[0]) / (q[1] - p[1]):
                c = not c
    return c


def solve(args):
    return json.loads(subprocess.run([BIN, 'solve', '--json'] + args,
                                     capture_output=True, text=True).stdout)


def solve_kind(a, mu):
    o = solve(['--alpha', repr(a), '--mu', repr(mu)])
    if o['status'] == 'no_equilibrium':
        return 'no_equilibrium'
    if o.get('unique') is None:
        return None
    if not o.get('mechanism_at_eta') or o.get('attained') is False:
        return 'no_mechanism_at_eta'
    return 'unique' if o['unique'] else 'non_unique'


random.seed(11)
bad = [0] * len(docs)
compared = undecided = 0
while compared < WANT:
    a = A0 + (A1 - A0) * random.random()
    mu = solve(['--alpha', repr(a), '--mu', 'ms'])['mu'] * (1 + D0 * (D1 / D0) ** random.random())
    k = solve_kind(a, mu)
    if k is None:
        undecided += 1
        continue
    compared += 1
    for i, regions in enumerate(docs):
        here = [kind for kind, p in regions if inside(p, a, mu)]
        if here != [k]:
            bad[i] += 1
            print(f'{paths[i]}: alpha {a:.6f} mu {mu:.10f} solve {k} polygons {here}')
print(f'compared {compared}, undecided {undecided}; disagreements:',
      ', '.join(f'{p} {b}' for p, b in zip(paths, bad)))
