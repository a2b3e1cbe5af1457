#--------------------------------------------------------------------------
# count_steps.py — how many gdb `step`s from where we stand to a function
#--------------------------------------------------------------------------
# Loading it sets the skips of skips.py and defines one command:
#   count-steps FUNC [LIMIT]   repeat `step` from the current stop until the
#                              selected frame is in FUNC (its name, or the last
#                              part of a qualified name: Hooke3d matches
#                              ample::Hooke3d), or stands at FILE:LINE (FUNC of
#                              that form: the file's name, detMPs.cpp:51), at
#                              most LIMIT steps (5000), then
#                              print the number of steps and the functions
#                              stopped in on the way, in the order first met,
#                              each with the times it was entered (the stops at
#                              its first line) and the steps that stopped in
#                              it; then the backtrace at the end.
# Skipped when stepping: tools/gdb/skips.py (the standard library, Eigen, the C
# library's maths), which this file loads and tools/debug.sh loads too.
# Load: gdb -x tools/gdb/count_steps.py (tools/count_steps.sh does), or
# `source tools/gdb/count_steps.py` in a running gdb.
#--------------------------------------------------------------------------
import os

import gdb

gdb.execute("source %s" % os.path.join(os.path.dirname(os.path.abspath(__file__)), "skips.py"))


def short(name):
    """the function's own name: the last part of the qualified name"""
    return name.split("(")[0].split("::")[-1]


ENTRY = {}                                         # function's first pc -> pc of its first stop


def at_entry(frame):
    """whether the frame stands where `step` stops on entering its function: the
    first line-table address after the function's first (the end of the prologue,
    where gdb's prologue analysis of -O0 code puts it). A new call from the same
    place (a loop on one line: mp.nIN[v] for each v) is told from a return this way,
    which the depth of the stack cannot do."""
    block = frame.block()
    while block is not None and block.function is None:
        block = block.superblock
    symtab = frame.find_sal().symtab
    if block is None or symtab is None:
        return False
    if block.start not in ENTRY:
        after = [e.pc for e in symtab.linetable() if block.start < e.pc < block.end]
        ENTRY[block.start] = min(after) if after else None
    return frame.pc() == ENTRY[block.start]


def at_line(frame, target):
    """whether the frame stands at target, FILE:LINE (FILE: the source file's name)"""
    if ":" not in target:
        return False
    name, line = target.rsplit(":", 1)
    sal = frame.find_sal()
    return (sal.symtab is not None and os.path.basename(sal.symtab.filename) == name
            and str(sal.line) == line)


class CountSteps(gdb.Command):
    """count-steps FUNC [LIMIT]: repeat `step` until the frame is in FUNC (at most
LIMIT steps, 5000), then print the steps and the functions passed through."""

    def __init__(self):
        super().__init__("count-steps", gdb.COMMAND_RUNNING)

    def invoke(self, arg, from_tty):
        args = gdb.string_to_argv(arg)
        if not 1 <= len(args) <= 2:
            raise gdb.GdbError("usage: count-steps FUNC [LIMIT]")
        target, limit = args[0], int(args[1]) if len(args) == 2 else 5000
        start = gdb.selected_frame()
        sal = start.find_sal()
        print("count-steps: from %s (%s:%d) to %s, skipping the files %s and the functions %s"
              % (start.name(), sal.symtab.filename if sal.symtab else "??", sal.line, target,
                 " ".join(SKIP_FILES[:1]) + " (and deeper)", " ".join(SKIP_FUNCTIONS)))
        seen = {}                                  # name -> [times entered, steps stopped in it]
        order = []
        steps, reached = 0, False
        while steps < limit:
            try:
                gdb.execute("step", to_string=True)
            except gdb.error:                      # "The program is not being run."
                pass
            steps += 1
            if gdb.selected_inferior().pid == 0 or not gdb.selected_thread():
                print("count-steps: the program ended after %d steps" % steps)
                break
            frame = gdb.selected_frame()
            name = frame.name() or "??"
            if name not in seen:
                seen[name] = [0, 0]
                order.append(name)
            seen[name][1] += 1
            if at_entry(frame):
                seen[name][0] += 1
            if name == target or short(name) == target or at_line(frame, target):
                reached = True
                break
        sal = gdb.selected_frame().find_sal() if reached else None
        if reached:
            print("steps to %s: %d (stopped at %s:%d)" % (target, steps, sal.symtab.filename, sal.line))
        else:
            print("steps to %s: not reached in %d steps" % (target, steps))
        print("functions stopped in, in the order first met (entered: the stops at its entry;"
              " steps: the steps that stopped there):")
        print("  %7s %6s  %s" % ("entered", "steps", "function"))
        for name in order:
            print("  %7d %6d  %s" % (seen[name][0], seen[name][1], name))
        if reached:
            print("backtrace at the end:")
            gdb.execute("backtrace -frame-arguments none")


CountSteps()
