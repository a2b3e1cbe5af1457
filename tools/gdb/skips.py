#--------------------------------------------------------------------------
# skips.py — what gdb's `step` passes over, so that it walks our code only
#--------------------------------------------------------------------------
# Loaded by tools/debug.sh, tools/gdb/count_steps.py and .vscode/launch.json
# (or `source tools/gdb/skips.py` in a running gdb). `step` passes over, and
# over what they call:
#   - every file under /usr/include: the standard library (/usr/include/c++/...)
#     and Eigen (/usr/include/eigen3/...), as `skip -gfi /usr/include/*/...`
#     for each depth from 1 to 8 (one `*` of gdb's file glob matches one
#     folder or file name, never a '/': /usr/include/* alone skips only the
#     files right in /usr/include);
#   - any function whose name begins with std::, Eigen:: or __ (skip -rfu):
#     instances of their templates in our own files, and the C library's math
#     (exp, log: __GI___exp, __log, ... whose lines gdb shows when the
#     package libc6-dbg is installed; __gnu_cxx:: too);
#   - the program's timers (ample::Stopwatch, ample::ScopedTimer, setups/program/runLog.h),
#     which each of the program's hooks starts before it calls its core function.
# Functions without line information (libc without libc6-dbg, libstdc++.so)
# are passed over as gdb always does. A function of ours called only from
# skipped code (a lambda handed to std::sort or a std::function) is passed
# over too: `break` on it, or `step` at its own call. `info skip` lists them.
# Tests:   tests/debug_recipe.sh (CTest debug.readme: the steps from the point
#          loop to Hooke3d with the README's recipe)
#--------------------------------------------------------------------------
import gdb

SKIP_FILES = ["/usr/include" + "/*" * depth for depth in range(1, 9)]
SKIP_FUNCTIONS = [r"^std::", r"^Eigen::", r"^__", r"^ample::Stopwatch::", r"^ample::ScopedTimer::"]

for pattern in SKIP_FILES:
    gdb.execute("skip -gfile %s" % pattern, to_string=True)
for regex in SKIP_FUNCTIONS:
    gdb.execute("skip -rfunction %s" % regex, to_string=True)
