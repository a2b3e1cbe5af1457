#!/usr/bin/env python3
"""animate_check.py — the page of plotting/animate_run.py, loaded in headless Chromium, checked.

For each run's output folder given: writes the page (plot_run.py --animate), loads it in
headless Chromium and checks
  - no script error: none in the page's own record (#status, #errors) and no uncaught
    error on Chromium's console log;
  - every frame drawn: one frame per mpData_<lstp>.vtk, and the points each frame drew
    (the page draws every frame once at load and writes the counts into #status) equal the
    POINTS of that VTK file;
  - the frame a fragment asks for is shown (#frame=last: the last load step written);
  - a screenshot of the first frame and one of the last differ inside the drawing's frame:
    at least 1 % of its pixels, and at least 0.5 % coloured by a point in one frame and
    blank or grid in the other (the body moved); both have coloured points there;
  - a run that stopped says "stopped" and its whole message in the page's title and heading.
Two controls show that the checks can fail: two screenshots of the same frame must not
differ, and a copy of a page with a script error must be caught.
PNG files are read with zlib (standard library only).
usage: animate_check.py --chromium BIN --plot-run plotting/plot_run.py --work DIR
                        OUTDIR[:FIELD] ...
"""
import argparse
import glob
import html
import json
import os
import re
import struct
import subprocess
import sys
import zlib

WINDOW = "1040,820"


def chromium(opt, args, log=None):
    cmd = [opt.chromium, "--headless", "--disable-gpu", "--no-sandbox", "--disable-dev-shm-usage",
           "--hide-scrollbars", "--no-first-run", "--force-device-scale-factor=1", "--user-data-dir=" + os.path.join(opt.work, "profile"),
           "--window-size=" + WINDOW] + args
    if log:
        cmd[1:1] = ["--enable-logging=stderr", "--v=0"]
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=120)
    if log:
        with open(log, "wb") as f:
            f.write(r.stderr)
    return r


def dump_dom(opt, url, log):
    return chromium(opt, ["--dump-dom", url], log).stdout.decode("utf-8", "replace")


def screenshot(opt, url, path):
    if os.path.exists(path):
        os.remove(path)
    chromium(opt, ["--screenshot=" + path, url])
    if not os.path.exists(path):
        raise RuntimeError("chromium wrote no screenshot %s" % path)
    return read_png(path)


def read_png(path):
    """(width, height, rows of RGB tuples) of an 8-bit RGB or RGBA PNG"""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("%s: not a PNG" % path)
    pos, idat = 8, b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            w, h, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    if depth != 8 or colour not in (2, 6) or interlace:
        raise ValueError("%s: PNG not 8-bit RGB(A) without interlace" % path)
    bpp = 3 if colour == 2 else 4
    raw, stride = zlib.decompress(idat), w * bpp
    rows, prev = [], bytearray(stride)
    for y in range(h):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * bpp:x * bpp + 3]) for x in range(w)])
        prev = line
    return w, h, rows


def region(img, box):
    """the pixels inside box (CSS pixels = screenshot pixels at a device scale of 1)"""
    w, h, rows = img
    return [rows[y][max(0, box["left"]):min(w, box["right"])]
            for y in range(max(0, box["top"]), min(h, box["bottom"]))]


def coloured(pixels):
    flat = [p for r in pixels for p in r]
    return sum(max(p) - min(p) > 40 for p in flat) / max(1, len(flat))


def moved_pixels(a, b):
    """the fraction of pixels coloured (a point there) in one picture and not in the other"""
    n = sum((max(pa) - min(pa) > 40) != (max(pb) - min(pb) > 40)
            for ra, rb in zip(a, b) for pa, pb in zip(ra, rb))
    return n / max(1, sum(len(r) for r in a))


def differing(a, b):
    n = sum(pa != pb for ra, rb in zip(a, b) for pa, pb in zip(ra, rb))
    return n / max(1, sum(len(r) for r in a))


def vtk_points(path):
    """the POINTS count of a legacy VTK file (ASCII or BINARY), from its header line"""
    with open(path, "rb") as f:
        m = re.search(rb"^POINTS (\d+) ", f.read(), re.M)
    return int(m.group(1))


def status_of(dom):
    m = re.search(r'<pre id="status">(.*?)</pre>', dom, re.S)
    if not m:
        return None
    try:
        return json.loads(html.unescape(m.group(1)))
    except ValueError:
        return None


def console_errors(log):
    with open(log, "rb") as f:
        text = f.read().decode("utf-8", "replace")
    return [l for l in text.splitlines() if "CONSOLE" in l and re.search(r"Uncaught|Error", l)]


def check_dom(dom, log, vtks, name):
    """the load-time checks of one page; returns (problems, status)"""
    bad = []
    st = status_of(dom)
    if st is None:
        return ["%s: no status written: the page's script did not run to its end" % name], None
    if st["errors"]:
        bad.append("%s: script errors %s" % (name, st["errors"]))
    errs = console_errors(log)
    if errs:
        bad.append("%s: console errors %s" % (name, errs[:3]))
    m = re.search(r'<div id="errors">(.*?)</div>', dom, re.S)
    if m and m.group(1).strip():
        bad.append("%s: %s" % (name, html.unescape(m.group(1).strip())))
    want = [vtk_points(p) for p in vtks]
    if st["frames"] != len(vtks) or st["drawn"] != want:
        bad.append("%s: points drawn per frame %s, the VTK files hold %s" % (name, st["drawn"], want))
    return bad, st


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--chromium", required=True)
    ap.add_argument("--plot-run", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("runs", nargs="+")
    opt = ap.parse_args()
    problems = []
    control_done = False
    for spec in opt.runs:
        outdir, _, field = spec.partition(":")
        name = os.path.basename(outdir)
        page = os.path.join(outdir, "run.html")
        cmd = [sys.executable, opt.plot_run, "--animate", outdir, "--out", page]
        subprocess.run(cmd + (["--field", field] if field else []), check=True)
        vtks = sorted(glob.glob(os.path.join(outdir, "mpData_*.vtk")),
                      key=lambda p: int(re.findall(r"_(\d+)\.vtk$", p)[0]))
        url = "file://" + os.path.abspath(page)
        log = os.path.join(opt.work, name + "_console.log")
        dom = dump_dom(opt, url + "#frame=last", log)
        with open(os.path.join(opt.work, name + "_dom.html"), "w") as f:
            f.write(dom)
        bad, st = check_dom(dom, log, vtks, name)
        problems += bad
        if st is None:
            continue
        last = int(re.findall(r"_(\d+)\.vtk$", vtks[-1])[0])
        if st["shown"] != len(vtks) - 1 or st["lstp"] != last:
            problems.append("%s: #frame=last shows frame %s (load step %s), not load step %d"
                            % (name, st["shown"], st["lstp"], last))
        with open(os.path.join(outdir, "summary.json")) as f:
            summary = json.load(f)
        if not summary["converged"]:
            msg = " ".join(summary["message"].split())
            for tag in ("title", "h1"):
                m = re.search(r"<%s[^>]*>(.*?)</%s>" % (tag, tag), dom, re.S)
                text = " ".join(html.unescape(m.group(1)).split()) if m else ""
                if "stopped" not in text or msg not in text:
                    problems.append("%s: the page's %s lacks the stop or its whole message: %r"
                                    % (name, tag, text))
        first = screenshot(opt, url + "#frame=0", os.path.join(opt.work, name + "_first.png"))
        final = screenshot(opt, url + "#frame=last", os.path.join(opt.work, name + "_last.png"))
        a, b = region(first, st["plot"]), region(final, st["plot"])
        changed, moved, ca, cb = differing(a, b), moved_pixels(a, b), coloured(a), coloured(b)
        print("%s: %d frames, points drawn %s; first and last frame: %.1f %% of the drawing's "
              "pixels differ, %.1f %% have a point in one frame only (points on %.1f %% / %.1f %%)"
              % (name, st["frames"], st["drawn"], 100 * changed, 100 * moved, 100 * ca, 100 * cb))
        if changed < 0.01 or moved < 0.005:
            problems.append("%s: first and last frame hardly differ (%.2f %% of the pixels, "
                            "%.2f %% where the body moved)" % (name, 100 * changed, 100 * moved))
        if min(ca, cb) < 0.01:
            problems.append("%s: hardly any coloured points drawn (%.2f %%, %.2f %%)"
                            % (name, 100 * ca, 100 * cb))
        if not control_done:                   # the controls, once: the checks can fail
            control_done = True
            again = screenshot(opt, url, os.path.join(opt.work, name + "_default.png"))
            same = differing(a, region(again, st["plot"]))
            print("control: the first frame twice (#frame=0 and no fragment) differs on %.2f %%" % (100 * same))
            if same != 0:
                problems.append("control: two screenshots of the first frame differ (%.2f %%)" % (100 * same))
            with open(page, encoding="utf-8") as f:
                text = f.read()
            broken = os.path.join(opt.work, name + "_broken.html")
            with open(broken, "w", encoding="utf-8") as f:
                f.write(text.replace("</body>", "<script>noSuchFunction();</script>\n</body>"))
            blog = os.path.join(opt.work, name + "_broken_console.log")
            bad, _ = check_dom(dump_dom(opt, "file://" + os.path.abspath(broken), blog), blog, vtks, "broken")
            print("control: a page with a script error: %s" % ("; ".join(bad) or "NOT CAUGHT"))
            if not bad:
                problems.append("control: a script error in the page was not caught")
    for p in problems:
        print("FAIL " + p)
    print("animate: %d runs, %s" % (len(opt.runs), "all checks passed" if not problems
                                     else "%d problems" % len(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
