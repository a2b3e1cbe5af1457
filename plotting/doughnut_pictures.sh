#!/bin/bash
# The pictures of docs/doughnut.md: deformed points coloured by rho_vonMises ([CPDI] figs 9-10).
# usage (from the top folder, after a Release build): plotting/doughnut_pictures.sh
cd "$(dirname "$0")/.."
B=build/release/ample
# ellipse: 5x18, uniform, 1 degree steps, to 60 (fig 10's angles and 45)
$B doughnut hole=1 nr=5 nc=18 dalpha=1 lstps=60 fem=1 --vtk 1 --quiet --out /tmp/pE_FE >/dev/null 2>&1
for t in 1 3 4; do $B doughnut hole=1 nr=5 nc=18 dalpha=1 lstps=60 mpType=$t --vtk 1 --quiet --out /tmp/pE_$t >/dev/null 2>&1; done
VMAX=1.2e6 /usr/bin/python3 plotting/doughnut_points.py docs/results/doughnut_ellipse_points.png rho_vonMises 20,30,45,60 1 FE=/tmp/pE_FE MPM=/tmp/pE_1 CPDI1=/tmp/pE_3 CPDI2=/tmp/pE_4
# circle 5x18, 5 degree steps: fig 9's angles
$B doughnut nr=5 nc=18 lstps=12 fem=1 --vtk 1 --quiet --out /tmp/pC_FE >/dev/null 2>&1
for t in 1 3 4; do $B doughnut nr=5 nc=18 lstps=12 mpType=$t --vtk 1 --quiet --out /tmp/pC_$t >/dev/null 2>&1; done
VMAX=1.2e6 /usr/bin/python3 plotting/doughnut_points.py docs/results/doughnut_5x18_points.png rho_vonMises 30,45,60 5 FE=/tmp/pC_FE MPM=/tmp/pC_1 CPDI1=/tmp/pC_3 CPDI2=/tmp/pC_4
