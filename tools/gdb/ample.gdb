#--------------------------------------------------------------------------
# ample.gdb — gdb settings and the `point` command for ample-cpp
#--------------------------------------------------------------------------
# Loaded by tools/debug.sh after eigen.py (or: source tools/gdb/ample.gdb).
#   point   from any stop inside the point loop (VMconst, Hooke3d, symLog, ...):
#           select detMPs' frame, say which point it is and print it whole, its
#           basis too (nIN, Svp, dSvp: its nn entries of the basis arena, by the
#           printers of eigen.py) and a CPDI point's domain (cpdi)
# Tests:   tests/debug_recipe.sh (CTest debug.readme)
#--------------------------------------------------------------------------
set print pretty on
set pagination off

define point
  frame function detMPs
  printf "point %d of %d in mpData\n", &mp - mpData._M_impl._M_start, mpData._M_impl._M_finish - mpData._M_impl._M_start
  print mp
end
document point
Select the frame of detMPs (the point loop), print the index of the point being
worked on and the point's whole state (mp), with its basis (nn nodes nIN, values
Svp, gradients dSvp 2 x nn) from the basis arena. Use it at any stop inside the loop.
end
