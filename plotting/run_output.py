"""run_output.py — read what one run of ample writes to its output folder.

Used by plot_run.py, plot_points.py and plot_history.py (no plotting here).
  read_csv(path)            rows of a CSV file as dicts of floats (steps, residuals, history, mp_final;
                            an empty field, a number that is not finite: NaN)
  read_summary(outdir)      summary.json as a dict
  read_legacy_vtk(path)     everything of a legacy VTK file of ample, ASCII or BINARY: points
                            (x, y), cells (lists of node numbers), point data (name: values)
  read_vtk(path, field)     points (x, y) and one named scalar of an mpData_<lstp>.vtk file
  read_mesh(path)           nodes (x, y), cells (lists of node numbers) and the nodal
                            displacement (or None) of a mesh.vtk / mesh_<lstp>.vtk file
  point_field(row, name)    one field of a point of mp_final.csv (FIELDS lists them)
"""
import csv
import json
import math
import struct


def read_csv(path):
    """every field a float; an empty one (ample's number that is not finite, e.g. the
    residual of a pass that went NaN) is NaN"""
    with open(path) as f:
        return [{k: float(v) if v != "" else math.nan for k, v in r.items()} for r in csv.DictReader(f)]


def read_summary(outdir):
    with open(outdir + "/summary.json") as f:
        return json.load(f)


class _VtkReader:
    """the sections of a legacy VTK file as ample writes them (plotting/makeVtkWriter.cpp):
    keyword lines in text; data in text (ASCII) or big-endian 4-byte float / int32 (BINARY)"""

    SIZE = {"float": (4, "f"), "double": (8, "d"), "int": (4, "i"), "vtkIdType": (4, "i")}

    def __init__(self, path):
        with open(path, "rb") as f:
            self.data = f.read()
        self.pos = 0
        if not self.line().startswith("# vtk DataFile"):
            raise ValueError("%s: not a legacy VTK file" % path)
        self.title = self.line()
        self.binary = self.line().strip().upper() == "BINARY"

    def line(self):
        """the next non-empty text line, or None at the end"""
        while self.pos < len(self.data):
            end = self.data.find(b"\n", self.pos)
            end = len(self.data) if end < 0 else end
            text = self.data[self.pos:end].decode("ascii", "replace").strip()
            self.pos = end + 1
            if text:
                return text
        return None

    def values(self, count, kind):
        if self.binary:
            size, code = self.SIZE[kind]
            chunk = self.data[self.pos:self.pos + size * count]
            self.pos += size * count
            if self.data[self.pos:self.pos + 1] == b"\n":
                self.pos += 1
            return list(struct.unpack(">%d%s" % (count, code), chunk))
        out = []
        convert = int if kind in ("int", "vtkIdType") else float
        while len(out) < count:
            out += [convert(t) for t in self.line().split()]
        return out


def read_legacy_vtk(path):
    """{"points": [(x, y)], "cells": [[node, ...]], "data": {name: [value] or [(x, y, z)]}}"""
    r = _VtkReader(path)
    out = {"points": [], "cells": [], "data": {}}
    n = 0
    while True:
        head = r.line()
        if head is None:
            return out
        w = head.split()
        if w[0] == "POINTS":
            n = int(w[1])
            v = r.values(3 * n, w[2])
            out["points"] = [(v[3 * p], v[3 * p + 1]) for p in range(n)]
        elif w[0] == "CELLS":
            v = r.values(int(w[2]), "int")
            k = 0
            for _ in range(int(w[1])):
                out["cells"].append(v[k + 1:k + 1 + v[k]])
                k += 1 + v[k]
        elif w[0] == "CELL_TYPES":
            r.values(int(w[1]), "int")
        elif w[0] == "VECTORS":
            v = r.values(3 * n, w[2])
            out["data"][w[1]] = [tuple(v[3 * p:3 * p + 3]) for p in range(n)]
        elif w[0] == "SCALARS":
            components = int(w[3]) if len(w) > 3 else 1
            pos = r.pos
            if not (r.line() or "").startswith("LOOKUP_TABLE"):
                r.pos = pos
            v = r.values(components * n, w[2])
            out["data"][w[1]] = v if components == 1 else \
                [tuple(v[components * p:components * (p + 1)]) for p in range(n)]
        # DATASET, POINT_DATA, CELL_DATA: nothing to read after the keyword line


def read_vtk(path, field):
    """points (x, y) and the named scalar of a legacy VTK file of ample (ASCII or BINARY)"""
    v = read_legacy_vtk(path)
    if field not in v["data"]:
        raise KeyError("%s has no field %s" % (path, field))
    return v["points"], v["data"][field]


def read_mesh(path):
    """nodes, cells and nodal displacement (None if the file has none) of a mesh VTK file"""
    v = read_legacy_vtk(path)
    disp = v["data"].get("displacement")
    return v["points"], v["cells"], [d[:2] for d in disp] if disp else None


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
