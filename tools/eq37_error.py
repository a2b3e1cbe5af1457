#!/usr/bin/env python3
"""eq37_error.py — the compaction error of [AMPLE] eq 37 from a run's mp_final.csv,
written independently of the C++ code: the reference values pinned in
tests/test_setups.cpp ("compaction: eq 37 at E = 10 kPa ...") come from

    ample compaction nelsy=4 lstps=10 --vtk 0 --out /tmp/c4 && tools/eq37_error.py /tmp/c4/mp_final.csv
    ample compaction nelsy=8 lstps=10 --vtk 0 --out /tmp/c8 && tools/eq37_error.py /tmp/c8/mp_final.csv

error = sum_p |syy_p - syy_a(Y0_p)| V0_p / (rho g l0 sum_p V0_p), syy_a = -rho g (l0 - Y0)
(eq 36, Y0 the original height). Defaults rho = 80, g = 10, l0 = 50 (setups/compaction.cpp).
Prints the error and the stress of the lowest point (the pinned base stress)."""
import csv
import sys

path = sys.argv[1]
rho, g, l0 = (float(v) for v in (sys.argv[2:5] if len(sys.argv) >= 5 else (80, 10, 50)))
rows = list(csv.DictReader(open(path)))
num = sum(abs(float(r["syy"]) + rho * g * (l0 - float(r["Y0"]))) * float(r["V0"]) for r in rows)
V0 = sum(float(r["V0"]) for r in rows)
low = min(rows, key=lambda r: float(r["Y0"]))
print("error %.17g" % (num / (rho * g * l0 * V0)))
print("syy_lowest_point %.17g" % float(low["syy"]))
