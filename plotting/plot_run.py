#!/usr/bin/env python3
"""plot_run.py — a picture of one run of ample, from its output folder alone.

Left:        the points of the last converged step (mp_final.csv), or of load step N
             (--step N: mpData_N.vtk), each its domain
             (GIMP: 2 lp x 2 lp; otherwise a square of area V), coloured by FIELD
             (default vonMises), over the background grid (mesh_<last>.vtk, or
             mesh.vtk: a grid that does not move is written once, see ample's
             --vtk-grid; none if the run wrote no VTK, --vtk 0).
Right, top:  the convergence history (residuals.csv): fErr against the Newton-Raphson
             pass, one line per load step (colour = load step), log scale, the tolerance dashed.
Right, low:  the setup's history.csv if it writes one (e.g. load against displacement);
             the columns drawn are chosen in HISTORY below or by --history. Columns of
             different units (UNITS below, docs/output.md) get their own y axes: the first
             unit on the left axis, the second on a right axis; at most two units in the
             panel (the columns of a third are left out, said on stderr).

usage: plot_run.py OUTDIR [--field NAME] [--original] [--deformed-grid] [--out PNG]
                   [--history X Y[,Y...]] [--step N] [--window X0 X1 Y0 Y1]
       plot_run.py --animate OUTDIR [--field NAME] [--out HTML]
  --field         one of: vonMises sxx syy szz sxy p ux uy u J  (default vonMises)
  --original      points at their original positions X0 (and the first grid written, mesh.vtk)
  --deformed-grid the grid of the last converged step moved by that step's nodal displacement
                  increment (mesh_<lstp>.vtk: written with --vtk N when N divides that step and
                  the grid moves (fem=1, stretch, doughnut) or the run had --vtk-grid every)
  --out           the PNG to write (default OUTDIR/run.png)
  --history       history.csv columns: X against Y (several: Y1,Y2)
  --step          draw the points of load step N (mpData_N.vtk, written with --vtk) instead of
                  the last converged step's; a step with no mpData_N.vtk is an error that names
                  the steps there are
  --window        only the points in [X0, X1] x [Y0, Y1] (m), e.g. the mechanism under a footing
  --animate       instead of the PNG, one self-contained HTML page of every load step written
                  (mpData_<lstp>.vtk): the viewer of the browser tab (plotting/viewer/) with the
                  run's files inside it, a slider, play/pause, zoom and pan (animate_run.py,
                  default OUTDIR/run.html; needs no matplotlib)
e.g.   build/release/ample collapse --out output/collapse && plotting/plot_run.py output/collapse
Tests: tests/plot_run_test.sh (CTest plot.run)
"""
import argparse
import glob
import math
import os
import re
import sys
import textwrap
if __name__ == "__main__" and "--animate" in sys.argv[1:]:   # the page needs no matplotlib
    import animate_run
    sys.exit(animate_run.main([a for a in sys.argv[1:] if a != "--animate"]))
try:
    import matplotlib
except ImportError:
    system = "/usr/bin/python3"                               # Debian's, where python3-matplotlib goes
    if (__name__ == "__main__" and os.path.exists(system) and os.path.realpath(sys.executable) !=
            os.path.realpath(system) and not os.environ.get("AMPLE_PLOT_SYSTEM_PYTHON")):
        os.environ["AMPLE_PLOT_SYSTEM_PYTHON"] = "1"          # once: no loop if it lacks it too
        os.execv(system, [system, os.path.abspath(__file__)] + sys.argv[1:])
    sys.exit(f"plot_run.py: matplotlib is not installed for {sys.executable} (Debian: apt-get install "
             "python3-matplotlib, then run /usr/bin/python3 plotting/plot_run.py ...); "
             "--animate writes the page without it")
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import LineCollection, PolyCollection
from matplotlib.ticker import MaxNLocator
from run_output import FIELDS, point_field, read_csv, read_legacy_vtk, read_mesh, read_summary

# history.csv columns to draw per setup, where "second column against the rest" reads badly
HISTORY = {
    "beam": ("tip_v_over_l", ["load_factor"]),      # load against tip deflection
    "footing": ("settlement", ["load_kN"]),
    "funnel": ("push", ["load_kN"]),
    "shear": ("gamma", ["sxy_mean", "sxy_reference"]),
    "stretch": ("lstp", ["reaction", "reference"]),
    "ibcantilever": ("load_factor", ["tip_v", "tip_v_beam"]),
    "doughnut": ("alpha", ["fNorm"]),
    "prandtl": ("settlement_m", ["q_over_cu"]),
}

# the unit of each history.csv column of the setups (docs/output.md); "1": a pure number. A
# column not listed here is a unit of its own (drawn on an axis of its own)
UNITS = {
    "lstp": "load step", "load_factor": "1", "error": "1",
    "settlement": "m", "load_kN": "kN/m", "imbalance": "N/m",                       # footing
    "tip_u": "m", "tip_v": "m", "tip_v_beam": "m", "tip_u_over_l": "1", "tip_v_over_l": "1",
    "v_top": "m", "force": "N/m", "force_a": "N/m",                                  # squeeze
    "gamma": "1", "sxy_mean": "Pa", "sxy_reference": "Pa",                          # shear
    "reaction": "N/m", "reference": "N/m",                                           # stretch
    "push": "m", "outside": "points", "worst": "m",                                  # funnel
    "alpha": "degrees", "f": "N/m", "fNorm": "1", "torque": "N m/m", "torqueNorm": "1",  # doughnut
    "b": "N/m3", "F_y": "N/m", "R_x": "N/m", "R_y": "N/m",                          # ibcantilever
    "settlement_m": "m", "q_over_cu": "1",                                           # prandtl
}


def unit_of(column):
    return UNITS.get(column, "%s: unit unknown" % column)


def axis_label(columns, unit):
    return "%s (%s)" % (", ".join(columns), unit) if unit != "1" else ", ".join(columns)


def grid_file(outdir, step, want_first):
    """the mesh VTK to draw: the grid of the last converged step (mesh_<step>.vtk), else the
    first one written (mesh.vtk: a grid that does not move is written only once), else the
    latest mesh_<lstp>.vtk; want_first: mesh.vtk before mesh_<step>.vtk"""
    last = os.path.join(outdir, "mesh_%d.vtk" % step)
    first = os.path.join(outdir, "mesh.vtk")
    if not want_first and os.path.exists(last):
        return last
    if os.path.exists(first):
        return first
    steps = sorted(glob.glob(os.path.join(outdir, "mesh_*.vtk")),
                   key=lambda p: int(re.findall(r"(\d+)\.vtk$", p)[0]))
    return steps[-1] if steps else None


def vtk_steps(outdir):
    """the load steps whose points were written (mpData_<lstp>.vtk), in order"""
    names = glob.glob(os.path.join(outdir, "mpData_*.vtk"))
    return sorted(int(m.group(1)) for m in (re.search(r"mpData_(\d+)\.vtk$", n) for n in names) if m)


def step_rows(outdir, step, final_rows):
    """the points of load step `step` (mpData_<step>.vtk) as rows of mp_final.csv's columns; V0
    (for --field J) from mp_final.csv when the run has as many points there (none split), else NaN"""
    v = read_legacy_vtk(os.path.join(outdir, "mpData_%d.vtk" % step))
    d = v["data"]
    same = len(final_rows) == len(v["points"])
    rows = []
    for p, (x, y) in enumerate(v["points"]):
        ux, uy = d["displacement"][p][:2]
        rows.append({"x": x, "y": y, "X0": x - ux, "Y0": y - uy, "sxx": d["sigma_xx"][p],
                     "syy": d["sigma_yy"][p], "szz": d["sigma_zz"][p], "sxy": d["sigma_xy"][p],
                     "syz": 0.0, "szx": 0.0, "V": d["volume"][p], "lpx": d["lpx"][p],
                     "lpy": d["lpy"][p], "V0": final_rows[p]["V0"] if same else math.nan})
    return rows


def draw_points(ax, fig, outdir, summary, opt):
    rows = read_csv(os.path.join(outdir, "mp_final.csv"))
    step = summary["last_converged_step"]
    if opt.step is not None:                            # checked in main: its file is there
        step = opt.step
        rows = step_rows(outdir, step, rows)
        if any(math.isnan(r["V0"]) for r in rows) and (opt.field == "J" or opt.original):
            sys.exit("plot_run.py: --step %d: the points were split after it (%d there, %d at the end), so "
                     "their V0 is unknown: --field J and --original need it" % (step, len(rows),
                                                                                 summary["nmp"]))
    path = grid_file(outdir, step, opt.original and not opt.deformed_grid)
    if path:
        nodes, cells, disp = read_mesh(path)
        if opt.deformed_grid and not disp:
            print("plot_run.py: %s has no nodal displacement (the grid did not move); rerun "
                  "ample with --vtk-grid every to draw the deformed grid" % path, file=sys.stderr)
        if opt.deformed_grid and disp:
            nodes = [(x + u, y + v) for (x, y), (u, v) in zip(nodes, disp)]
        edges = [[nodes[c[k]], nodes[c[(k + 1) % len(c)]]] for c in cells for k in range(len(c))]
        ax.add_collection(LineCollection(edges, colors="0.75", linewidths=0.5, zorder=1))
        ax.update_datalim(nodes)
    else:
        ax.text(0.01, 0.01, "no mesh VTK (run with --vtk N to draw the grid)",
                transform=ax.transAxes, fontsize=8)
    boxes, values = [], []
    for r in rows:
        x, y = (r["X0"], r["Y0"]) if opt.original else (r["x"], r["y"])
        if opt.window and not (opt.window[0] <= x <= opt.window[1] and opt.window[2] <= y <= opt.window[3]):
            continue
        if r["lpx"] > 0 and r["lpy"] > 0 and not opt.original:
            hx, hy = r["lpx"], r["lpy"]
        else:
            hx = hy = 0.5 * math.sqrt(r["V0"] if opt.original else r["V"])
        boxes.append([(x - hx, y - hy), (x + hx, y - hy), (x + hx, y + hy), (x - hx, y + hy)])
        values.append(point_field(r, opt.field))
    lo, hi = min(values), max(values)
    if hi - lo <= 1e-9 * max(abs(lo), abs(hi), 1e-300):  # a uniform field: a visible range around it
        lo, hi = lo - 0.01 * abs(lo) - 1e-12, hi + 0.01 * abs(hi) + 1e-12
    pc = PolyCollection(boxes, array=values, cmap="viridis", edgecolors="none", zorder=2)
    pc.set_clim(lo, hi)
    ax.add_collection(pc)
    ax.update_datalim([p for b in boxes for p in b])
    ax.autoscale_view()
    if opt.window:
        ax.set_xlim(opt.window[0], opt.window[1])
        ax.set_ylim(opt.window[2], opt.window[3])
    ax.set_aspect("equal", adjustable="datalim")      # to scale: a point's square stays square
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    where = "original positions" if opt.original else "load step %d" % step
    ax.set_title("%d points, %s" % (len(rows), where), fontsize=10)
    bar = fig.colorbar(pc, ax=ax, label=FIELDS[opt.field][1], shrink=0.8)
    bar.formatter.set_useOffset(False)                 # values as they are, not 1e-8 + offset


def draw_convergence(ax, fig, outdir, summary):
    rows = [r for r in read_csv(os.path.join(outdir, "residuals.csv")) if r["fErr"] > 0]
    steps = sorted({int(r["lstp"]) for r in rows})
    cmap = plt.get_cmap("plasma")
    for s in steps:
        mine = [r for r in rows if int(r["lstp"]) == s]
        c = cmap((s - steps[0]) / max(1, steps[-1] - steps[0]) * 0.9)
        ax.semilogy([r["NRit"] for r in mine], [r["fErr"] for r in mine], "o-", ms=2.5, lw=0.8, color=c)
    ax.axhline(summary["parameters"]["tol"], color="k", ls="--", lw=0.8, label="tol")
    ax.xaxis.set_major_locator(MaxNLocator(integer=True))
    ax.set_xlabel("Newton-Raphson pass NRit")
    ax.set_ylabel("fErr (eq 35)")
    ax.set_title("convergence, load steps %d-%d (dark to light)" % (steps[0], steps[-1])
                 if steps else "convergence: no residuals", fontsize=10)
    ax.grid(True, which="major", alpha=0.3)
    ax.legend(fontsize=8)


def draw_setup_history(ax, outdir, summary, opt):
    path = os.path.join(outdir, "history.csv")
    rows = read_csv(path)
    cols = list(rows[0].keys())
    if opt.history:
        x, ys = opt.history[0], opt.history[1].split(",")
    elif summary["setup"] in HISTORY:
        x, ys = HISTORY[summary["setup"]]
    else:
        x, ys = cols[1], cols[2:]                      # lstp, x, then the y columns
    missing = [c for c in [x] + ys if c not in cols]
    if missing:
        sys.exit("plot_run.py: history.csv has no column %s; its columns: %s"
                 % (", ".join(missing), ", ".join(cols)))
    draw_grouped_history(ax, rows, x, ys)


def draw_grouped_history(ax, rows, x, ys):
    """columns ys against x from the unloaded state 0, grouped by unit (UNITS): the first unit
    on ax's left axis, the second on a right axis of its own; further units are left out"""
    groups = {}
    for y in ys:
        groups.setdefault(unit_of(y), []).append(y)
    units = list(groups)
    if len(units) > 2:
        left_out = ["%s (%s)" % (", ".join(groups[u]), u) for u in units[2:]]
        print("plot_run.py: history panel: at most two units, one on each y axis: left out %s "
              "(draw them with --history %s ...)" % ("; ".join(left_out), x), file=sys.stderr)
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    lines, k = [], 0
    for side, unit in enumerate(units[:2]):
        axis = ax if side == 0 else ax.twinx()
        for y in groups[unit]:
            lines += axis.plot([0] + [r[x] for r in rows], [0] + [r[y] for r in rows],
                               "o-" if side == 0 else "s--", ms=3, color=colours[k % len(colours)],
                               label=y)
            k += 1
        axis.set_ylabel(axis_label(groups[unit], unit))
    ax.set_xlabel(axis_label([x], unit_of(x)))
    ax.grid(True, alpha=0.3)
    if len(lines) > 1:
        ax.legend(lines, [ln.get_label() for ln in lines], fontsize=8)
    title = " and ".join(", ".join(groups[u]) for u in units[:2])
    ax.set_title("history.csv: %s against %s" % (title, x), fontsize=10)


def title_of(summary, width=110):
    """the figure's title, its lines at most width characters: a stopped run's whole message"""
    head = "%s — load step %d of %d, " % (summary["setup"], summary["last_converged_step"],
                                         summary["lstps"])
    lines = [head + "converged"] if summary["converged"] else \
        textwrap.wrap(head + "stopped: " + summary["message"], width)
    results = ", ".join("%s = %s" % (k, "null" if v is None else "%.4g" % v)   # null: undefined
                        for k, v in list(summary["results"].items())[:3])
    return "\n".join(lines + ([results] if results else []))


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("outdir")
    ap.add_argument("--field", default="vonMises", choices=sorted(FIELDS))
    ap.add_argument("--original", action="store_true")
    ap.add_argument("--deformed-grid", action="store_true")
    ap.add_argument("--out")
    ap.add_argument("--history", nargs=2, metavar=("X", "Y"))
    ap.add_argument("--animate", action="store_true", help="an HTML page of every load step written")
    ap.add_argument("--step", type=int, help="draw the points of load step N (mpData_N.vtk)")
    ap.add_argument("--window", nargs=4, type=float, metavar=("X0", "X1", "Y0", "Y1"),
                    help="draw only the points in [X0, X1] x [Y0, Y1] (m), the colours scaled to them")
    opt = ap.parse_args(argv)
    if opt.window and not (opt.window[0] < opt.window[1] and opt.window[2] < opt.window[3]):
        sys.exit("plot_run.py: --window X0 X1 Y0 Y1 needs X0 < X1 and Y0 < Y1")
    if opt.animate:
        import animate_run
        return animate_run.main([a for a in argv if a != "--animate"])
    if not os.path.exists(os.path.join(opt.outdir, "summary.json")):
        sys.exit("plot_run.py: %s has no summary.json: not the output folder of a run" % opt.outdir)
    summary = read_summary(opt.outdir)
    if opt.step is not None and not os.path.exists(os.path.join(opt.outdir, "mpData_%d.vtk" % opt.step)):
        steps = vtk_steps(opt.outdir)
        sys.exit("plot_run.py: --step %d: %s has no mpData_%d.vtk; the load steps written there: %s"
                 % (opt.step, opt.outdir, opt.step, ", ".join(map(str, steps)) if steps else
                    "none (the run had --vtk 0; --vtk N writes every Nth load step)"))
    has_history = os.path.exists(os.path.join(opt.outdir, "history.csv"))
    title = title_of(summary)
    extra = 0.2 * max(0, title.count("\n") - 1)      # inches for title lines beyond two
    fig = plt.figure(figsize=(12, 5.2 + extra))
    gs = fig.add_gridspec(2, 2, width_ratios=[1.7, 1])
    draw_points(fig.add_subplot(gs[:, 0]), fig, opt.outdir, summary, opt)
    draw_convergence(fig.add_subplot(gs[0, 1] if has_history else gs[:, 1]), fig, opt.outdir, summary)
    if has_history:
        draw_setup_history(fig.add_subplot(gs[1, 1]), opt.outdir, summary, opt)
    fig.suptitle(title, fontsize=11)
    fig.tight_layout()                                  # (it leaves room for the title)
    out = opt.out or os.path.join(opt.outdir, "run.png")
    fig.savefig(out, dpi=100)
    if opt.step is not None:
        print("plot_run.py: the points of load step %d (mpData_%d.vtk)" % (opt.step, opt.step))
    print(out)


if __name__ == "__main__":
    main(sys.argv[1:])
