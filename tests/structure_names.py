#!/usr/bin/env python3
"""structure_names.py - every name docs/structure.md gives the code exists in the code (CTest docs.structure)

Reads the call graph of docs/structure.md (the fenced block under "Call graph"): each line names
one or more functions (comma-separated, or `a → b`) and the file that defines them; the file must
exist and each name must appear in it as a word. Then every `code span` of the page that looks
like a path (holds a '/' or ends in .h/.cpp/.py/.sh) must exist, and every one that looks like
an identifier (a C++ name, optionally with ::, a call's () or a member's .) must occur as a word
somewhere in ample/, constitutive/, setups/, plotting/, tests/ or tools/. Names the page gives for
things that are not code (a parameter such as `ghost=`, an option such as `--vtk`) are not
identifiers by this rule. Exit 0 when all are found, 1 with one line per missing name otherwise.
Usage: tests/structure_names.py [ROOT]   (ROOT: the top of the tree, default: this file's ../)
"""
import os
import re
import sys

root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
page = os.path.join(root, "docs", "structure.md")
text = open(page, encoding="utf-8").read()
sources = {}
for top in ("ample", "constitutive", "setups", "plotting", "tests", "tools"):
    for d, _, files in os.walk(os.path.join(root, top)):
        for f in files:
            if f.endswith((".h", ".cpp", ".py", ".sh", ".gdb", ".cmake", ".txt")):
                p = os.path.join(d, f)
                sources[os.path.relpath(p, root)] = open(p, encoding="utf-8", errors="replace").read()
everything = "\n".join(sources.values())
missing = []


def has_word(name, body):
    return re.search(r"(?<![A-Za-z0-9_])" + re.escape(name) + r"(?![A-Za-z0-9_])", body) is not None


# 1. the call graph: "├── name[, name] [→ name]   path [(note)]"
graph = re.search(r"## Call graph\s*```\n(.*?)```", text, re.S)
if not graph:
    missing.append("docs/structure.md: no call graph block under '## Call graph'")
else:
    for line in graph.group(1).splitlines():
        m = re.match(r"^[\s│├└─]*([A-Za-z_][\w, →]*?)\s{2,}((?:ample|constitutive|setups|plotting)/\S+)", line)
        if not m:
            continue
        names = [n.strip() for n in re.split(r"[,→]", m.group(1)) if n.strip()]
        path = m.group(2)
        if "<" in path:  # setups/<name>.cpp: a pattern, not a file
            continue
        if path not in sources:
            missing.append("call graph: %s (for %s) does not exist" % (path, ", ".join(names)))
            continue
        for n in names:
            if n.startswith("for ") or not re.match(r"^[A-Za-z_]\w*$", n):
                continue
            if not has_word(n, sources[path]):
                missing.append("call graph: %s is not in %s" % (n, path))

# 2. code spans of the whole page
for span in set(re.findall(r"`([^`\n]+)`", text)):
    s = span.strip()
    if re.search(r"\.(h|cpp|py|sh|md|gdb)$", s) or ("/" in s and " " not in s and not s.startswith("-")):
        if "*" in s or "<" in s or s.startswith("http") or "=" in s:
            continue
        if s.startswith("/") or s.startswith("."):
            continue  # a folder outside the tree, or an extension alone
        found = os.path.exists(os.path.join(root, s.rstrip("/")))
        if not found and "/" not in s:  # a file named within its folder's context
            found = any(os.path.basename(k) == s for k in sources) or os.path.exists(os.path.join(root, "docs", s))
        if not found:
            missing.append("path `%s` does not exist" % s)
        continue
    m = re.match(r"^([A-Za-z_]\w*(?:::[A-Za-z_]\w*)*)(?:\(.*\))?$", s)
    if not m or "=" in s:
        continue
    name = m.group(1).split("::")[-1]
    if len(name) < 3 or name.isupper() and len(name) < 5:
        continue  # symbols (`fd`, `h`, `LU`) are the equations', not the code's names
    if not has_word(name, everything):
        missing.append("`%s` is named on the page but occurs nowhere in the code" % s)

for m in sorted(set(missing)):
    print("docs/structure.md: " + m)
print("structure_names.py: %s" % ("%d names missing" % len(set(missing)) if missing else "every name found"))
sys.exit(1 if missing else 0)
