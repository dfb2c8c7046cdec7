"""`solve` near the ends of branches of limit states: reads an `arch-enum atlas --json`
document, takes its solved `non_unique`/`unique` boundary points (`exact: true`, mu = where the
branch ends), runs `arch-enum solve` at mu (1 - r) for r = 3e-2, 1e-2, ..., 1e-9 and at
mu (1 + 1e-8), and prints a row per point (F: unique false, T: unique true, ?: undecided, here
below mu_ms) and the counts. Inside an end the answer must be F, beyond it T.

    target/release/arch-enum atlas --alpha-min 0.55 --alpha-max 1.0 --columns 46 \\
        --mu-max-factor 1.2 --json > band.json
    python3 scripts/branch_end_check.py band.json target/release/arch-enum

With `--traced` the points traced between the columns (`traced` in the JSON) are checked
instead of the columns' own.
"""
import json
import subprocess
import sys

path, BIN = sys.argv[1], sys.argv[2]
doc = json.load(open(path))
ends = [(p['alpha'], p['mu']) for b in doc['boundaries']
        if b['between'] == ['non_unique', 'unique'] for p in b['points'] if p.get('exact')]
if '--traced' in sys.argv:
    # the points traced between the columns instead
    ends = [(p['alpha'], p['mu']) for t in doc.get('traced', []) for p in t['points']]
RS = [3e-2, 1e-2, 3e-3, 1e-3, 3e-4, 1e-4, 3e-5, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9]


def unique(alpha, mu):
    out = subprocess.run([BIN, 'solve', '--alpha', repr(alpha), '--mu', repr(mu), '--json'],
                         capture_output=True, text=True).stdout
    return json.loads(out).get('unique')


wrong_inside = inside = wrong_beyond = 0
for alpha, mu in ends:
    row = ''
    for r in RS:
        u = unique(alpha, mu * (1 - r))
        row += {False: 'F', True: 'T'}.get(u, '?')
        inside += u is not None
        wrong_inside += u is True
    beyond = unique(alpha, mu * (1 + 1e-8))
    wrong_beyond += beyond is not True
    print(f'{alpha:.4f} {mu:.10f} {row} beyond: {beyond}')
print(f'{len(ends)} ends; inside: {wrong_inside} of {inside} decided points called unique; '
      f'beyond: {wrong_beyond} of {len(ends)} not unique')
