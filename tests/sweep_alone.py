#!/usr/bin/env python3
"""sweep_alone.py: the cases of tests/scenarios/sweep/tiny-sweep.yaml as
scenarios of their own, written here independently of wallload's sweep
code (for tests/cli_sweep_*.sh to run with `wallload assess` and `check`).

usage: sweep_alone.py SWEEP.yaml OUTDIR
Writes OUTDIR/case_<i>.yaml for every case, first swept key slowest, and
prints one line per case: "<i> <energy> <standoff>". Each case is the
scenario up to its `sweep:` line, with the explosion's `charge: ...`
replaced by `energy: <E>` and its `at:` by wall.x - standoff (in m, rounded
to 12 significant digits, as sweep.h documents)."""
import itertools
import re
import sys

src, out = sys.argv[1], sys.argv[2]
text = open(src).read()
base, sweep = text.split("\nsweep:\n", 1)
energies = [v.strip() for v in re.search(r"energy: \[([^]]*)\]", sweep).group(1).split(",")]
standoffs = [v.strip() for v in re.search(r"standoff: \[([^]]*)\]", sweep).group(1).split(",")]
wall_x = float(re.search(r"wall: \{x: ([0-9.]+) m", base).group(1))
for i, (e, s) in enumerate(itertools.product(energies, standoffs)):
    at = float("%.12g" % (wall_x - float(s.split()[0])))
    case = re.sub(r"(explosion: \{)charge: [^,]*, at: [^}]*\}",
                  lambda m: "%senergy: %s, at: %r m}" % (m.group(1), e, at), base)
    assert case != base
    with open("%s/case_%d.yaml" % (out, i), "w") as f:
        f.write(case + "\n")
    print(i, e, s)
