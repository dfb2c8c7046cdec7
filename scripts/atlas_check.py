"""The atlas against `solve` at held-out points: reads an `arch-enum atlas --json` document
of the default rectangle (continuous arches, centreline weight), draws random (alpha, mu), half
of them in the band's neighbourhood alpha in [0.55, 1], a seventh below mu_ms, classifies each
by point-in-polygon on the regions and, where the same single kind holds at half a column
either side and at d x 0.7 and d x 1.3 (d = mu/mu_ms - 1), runs `arch-enum solve` there and
compares. Prints the counts; every disagreement on a line of its own.

    target/release/arch-enum atlas --json > atlas.json
    python3 scripts/atlas_check.py atlas.json target/release/arch-enum 1000
"""
import json, random, subprocess, sys
path, BIN, WANT = sys.argv[1], sys.argv[2], int(sys.argv[3])
d = json.load(open(path))
regions = [(r['kind'], r['polygon']) for r in d['regions']]
def inside(poly, a, m):
    c = False
    n = len(poly)
    for i in range(n):
        p, q = poly[i], poly[(i+1) % n]
        if (p[1] > m) != (q[1] > m):
            x = p[0] + (m - p[1]) * (q[0] - p[0]) / (q[1] - p[1])
            if a < x: c = not c
    return c
def kinds(a, m): return [k for k, p in regions if inside(p, a, m)]
def ms(a):
    o = json.loads(subprocess.run([BIN,'solve','--alpha',repr(a),'--mu','ms','--json'],capture_output=True,text=True).stdout)
    return o['mu']
def solve_kind(a, mu):
    o = json.loads(subprocess.run([BIN,'solve','--alpha',repr(a),'--mu',repr(mu),'--json'],capture_output=True,text=True).stdout)
    if o['status'] == 'no_equilibrium': return 'no_equilibrium'
    if o.get('unique') is None: return None
    if not o.get('mechanism_at_eta') or o.get('attained') is False: return 'no_mechanism_at_eta'
    return 'unique' if o['unique'] else 'non_unique'
random.seed(7)
half = 0.5 * 2.6 / 52
stats = dict(compared=0, near=0, undecided=0, bad=0)
seen = {}
while stats['compared'] < WANT:
    a = -1.4 + 2.6 * random.random()
    if random.random() < 0.5:  # half the points in the band's neighbourhood
        a = 0.55 + 0.45 * random.random()
    m0 = ms(a)
    dd = -0.5 + 0.45 * random.random() if random.random() < 0.15 else 1e-4 * (9 / 1e-4) ** random.random()
    mu = m0 * (1 + dd)
    here = kinds(a, mu)
    around = []
    for da in (-half, half):
        aa = min(max(a + da, -1.4), 1.2); mm = ms(aa)
        for f in (0.7, 1.3): around.append(kinds(aa, mm * (1 + dd * f)))
    if len(here) != 1 or any(k != here for k in around):
        stats['near'] += 1; continue
    k = solve_kind(a, mu)
    if k is None: stats['undecided'] += 1; continue
    stats['compared'] += 1; seen[k] = seen.get(k, 0) + 1
    if k != here[0]:
        stats['bad'] += 1; print('DISAGREE', a, mu, m0, k, here)
print(stats, seen)
