"""run_output.py — read what one run of ample writes to its output folder.

Used by plot_run.py, plot_points.py and plot_history.py (no plotting here).
  read_csv(path)            rows of a CSV file as dicts of floats (steps, residuals, history, mp_final)
  read_summary(outdir)      summary.json as a dict
  read_vtk(path, field)     points (x, y) and one named scalar of an mpData_<lstp>.vtk file
  read_mesh(path)           nodes (x, y), cells (lists of node numbers) and the nodal
                            displacement (or None) of a mesh.vtk / mesh_<lstp>.vtk file
  point_field(row, name)    one field of a point of mp_final.csv (FIELDS lists them)
"""
import csv
import json
import math


def read_csv(path):
    with open(path) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def read_summary(outdir):
    with open(outdir + "/summary.json") as f:
        return json.load(f)


def _lines(path):
    with open(path) as f:
        return f.read().split("\n")


def read_vtk(path, field):
    """points (x, y) and the named scalar of a legacy ASCII VTK file of ample"""
    lines = _lines(path)
    i = next(k for k, l in enumerate(lines) if l.startswith("POINTS"))
    n = int(lines[i].split()[1])
    xy = [tuple(map(float, lines[i + 1 + p].split()[:2])) for p in range(n)]
    j = next(k for k, l in enumerate(lines) if l.startswith("SCALARS " + field + " "))
    start = j + 2 if lines[j + 1].startswith("LOOKUP_TABLE") else j + 1
    values = [float(lines[start + p]) for p in range(n)]
    return xy, values


def read_mesh(path):
    """nodes, cells and nodal displacement (None if the file has none) of a mesh VTK file"""
    lines = _lines(path)
    i = next(k for k, l in enumerate(lines) if l.startswith("POINTS"))
    n = int(lines[i].split()[1])
    nodes = [tuple(map(float, lines[i + 1 + p].split()[:2])) for p in range(n)]
    j = next(k for k, l in enumerate(lines) if l.startswith("CELLS"))
    cells = [[int(t) for t in lines[j + 1 + e].split()[1:]] for e in range(int(lines[j].split()[1]))]
    disp = None
    if any(l.startswith("VECTORS displacement") for l in lines):
        d = next(k for k, l in enumerate(lines) if l.startswith("VECTORS displacement"))
        disp = [tuple(map(float, lines[d + 1 + p].split()[:2])) for p in range(n)]
    return nodes, cells, disp


def von_mises(r):
    """rho = sqrt(2 J2) of a point's stress, as rho_vonMises of the VTK files"""
    p = (r["sxx"] + r["syy"] + r["szz"]) / 3
    s = [r["sxx"] - p, r["syy"] - p, r["szz"] - p]
    return math.sqrt(sum(x * x for x in s) + 2 * (r["sxy"] ** 2 + r["syz"] ** 2 + r["szx"] ** 2))


FIELDS = {  # name: (value of one row of mp_final.csv, label with unit)
    "vonMises": (von_mises, "von Mises stress rho = sqrt(2 J2) (Pa)"),
    "sxx": (lambda r: r["sxx"], "sigma_xx (Pa)"),
    "syy": (lambda r: r["syy"], "sigma_yy (Pa)"),
    "szz": (lambda r: r["szz"], "sigma_zz (Pa)"),
    "sxy": (lambda r: r["sxy"], "sigma_xy (Pa)"),
    "p": (lambda r: (r["sxx"] + r["syy"] + r["szz"]) / 3, "mean stress p (Pa)"),
    "ux": (lambda r: r["x"] - r["X0"], "u_x (m)"),
    "uy": (lambda r: r["y"] - r["Y0"], "u_y (m)"),
    "u": (lambda r: math.hypot(r["x"] - r["X0"], r["y"] - r["Y0"]), "|u| (m)"),
    "J": (lambda r: r["V"] / r["V0"], "volume ratio V / V0"),
}


def point_field(row, name):
    return FIELDS[name][0](row)
