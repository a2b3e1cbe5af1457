#--------------------------------------------------------------------------
# eigen.py — gdb pretty printers for the Eigen types of ample-cpp (our own)
#--------------------------------------------------------------------------
# Without them gdb prints an Eigen matrix as pages of template nesting and a
# VectorXd as the address of its storage. With them:
#   p mp.F      [3x3] {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}
#   p mp.sig    [6] {0, -400, 0, 0, 0, 0}
#   p uvw       [130] {0, -1.2e-05, ...}   (the first 10 entries, then how many more)
#   p Kt        SparseMatrix 130x130, 1156 stored entries
#   p mp.nIN    {0, 1, 5, 6, 0 <repeats 12 times>}   (the first nn = 4 are the point's nodes)
#   p mp.Svp    {0.5625, 0.1875, 0.1875, 0.0625, 0 <repeats 12 times>}
#   p mp.dSvp   [2x16] {{-0.75, 0.75, -0.25, 0.25, 0, 0, 0, 0, ...}, ...}
#   p mp.eIN    {0, 1, 0 <repeats 7 times>}
#   p mp.cpdi   none (MPM, GIMP), or the CPDI domain {st0 = [2x2] ..., st = ..., xc = [2x4] ...}
#   pmat mp.D   the whole matrix, one row a line, aligned (the command below; mp.dSvp too)
# Covers Eigen::Matrix and Eigen::Array of any scalar, fixed or dynamic size,
# column- or row-major (Eigen 3.4's DenseStorage layout), SparseMatrix, std::array
# (libstdc++'s printers have none: eIN shows as {0, 1, 0 <repeats 7 times>}), and
# Indirect<T> (ample/mpData.h: the CPDI domain).
# Load: gdb -x tools/gdb/eigen.py (tools/debug.sh does), or `source tools/gdb/eigen.py`.
# Tests: tests/debug_recipe.sh (CTest debug.*)
#--------------------------------------------------------------------------
import re
import gdb
import gdb.printing

VECTOR_SHOWN = 10           # entries of a long vector printed by `p`
ROWS_SHOWN, COLS_SHOWN = 6, 8   # rows and columns of a large matrix printed by `p`


def number(v):
    """one scalar as short text: integers as they are, doubles to 6 digits"""
    if v.type.strip_typedefs().code == gdb.TYPE_CODE_FLT:
        return "%.6g" % float(v)
    return str(v)


class Dense:
    """the size, storage order and data pointer of one Eigen::Matrix or Eigen::Array"""

    def __init__(self, val):
        t = val.type.strip_typedefs()
        rows, cols, options = (int(t.template_argument(i)) for i in (1, 2, 3))
        st = val["m_storage"]
        self.rows = rows if rows >= 0 else int(st["m_rows"])   # -1 is Eigen::Dynamic
        self.cols = cols if cols >= 0 else int(st["m_cols"])
        data = st["m_data"]
        if data.type.strip_typedefs().code != gdb.TYPE_CODE_PTR:  # fixed capacity: plain_array,
            data = data["array"]                               # indexed as it is (a value that
        self.data = data                                       # `finish` returns has no address)
        self.row_major = bool(options & 1)                     # Eigen::RowMajor = 1

    def at(self, i, j):
        k = i * self.cols + j if self.row_major else j * self.rows + i
        return self.data[k]

    def is_vector(self):
        return self.rows == 1 or self.cols == 1


class DensePrinter:
    """`p` of a matrix or vector: one line, the size first, long ones cut"""

    def __init__(self, val):
        self.m = Dense(val)

    def to_string(self):
        m = self.m
        if m.rows * m.cols == 0:
            return "[%dx%d] {}" % (m.rows, m.cols)
        if m.is_vector():
            n = m.rows * m.cols
            shown = [number(m.at(k, 0) if m.cols == 1 else m.at(0, k))
                     for k in range(min(n, VECTOR_SHOWN))]
            more = ", ... (%d more)" % (n - VECTOR_SHOWN) if n > VECTOR_SHOWN else ""
            return "[%d] {%s%s}" % (n, ", ".join(shown), more)
        lines = []
        for i in range(min(m.rows, ROWS_SHOWN)):
            row = [number(m.at(i, j)) for j in range(min(m.cols, COLS_SHOWN))]
            lines.append("{" + ", ".join(row) + (", ..." if m.cols > COLS_SHOWN else "") + "}")
        if m.rows > ROWS_SHOWN:
            lines.append("... (%d more rows)" % (m.rows - ROWS_SHOWN))
        return "[%dx%d] {%s}" % (m.rows, m.cols, ", ".join(lines))


class SparsePrinter:
    """`p` of a SparseMatrix: its size and number of stored entries"""

    def __init__(self, val):
        self.val = val

    def to_string(self):
        v = self.val
        row_major = bool(int(v.type.strip_typedefs().template_argument(1)) & 1)
        outer, inner = int(v["m_outerSize"]), int(v["m_innerSize"])
        rows, cols = (outer, inner) if row_major else (inner, outer)
        nnz = int(v["m_data"]["m_size"])
        if v["m_innerNonZeros"] != 0:                           # not compressed: count per outer
            nnz = sum(int(v["m_innerNonZeros"][k]) for k in range(outer))
        return "SparseMatrix %dx%d, %d stored entries" % (rows, cols, nnz)


class IndirectPrinter:
    """`p mp.cpdi`: the value held (the CPDI domain), or none"""

    def __init__(self, val):
        self.val = val

    def to_string(self):
        target = self.val.type.strip_typedefs().template_argument(0)
        if self.val.address is None:
            return "(a CPDI domain, not shown)"
        ptr = self.val.address.reinterpret_cast(target.pointer().pointer()).dereference()
        if int(ptr) == 0:
            return "none"
        return ptr.dereference()


class StdArrayPrinter:
    """`p` of a std::array (nIN, eIN, Svp of a point): its elements, without _M_elems"""

    def __init__(self, val):
        self.val = val

    def to_string(self):
        return self.val["_M_elems"]


DENSE = re.compile(r"^Eigen::(Matrix|Array)<.*>$")
SPARSE = re.compile(r"^Eigen::SparseMatrix<.*>$")
STDARRAY = re.compile(r"^std::(__1::)?array<.*>$")
INDIRECT = re.compile(r"^ample::Indirect<.*>$")


def lookup(val):
    t = val.type
    if t.code == gdb.TYPE_CODE_REF or t.code == gdb.TYPE_CODE_RVALUE_REF:
        t = t.target()
    name = t.strip_typedefs().unqualified().tag
    if not name:
        return None
    if DENSE.match(name):
        return DensePrinter(val)
    if SPARSE.match(name):
        return SparsePrinter(val)
    if STDARRAY.match(name) and "_M_elems" in [f.name for f in t.strip_typedefs().fields()]:
        return StdArrayPrinter(val)
    if INDIRECT.match(name):
        return IndirectPrinter(val)
    return None


class PrintMatrix(gdb.Command):
    """pmat EXPR — print an Eigen matrix or vector whole, one row a line, aligned."""

    def __init__(self):
        super().__init__("pmat", gdb.COMMAND_DATA, gdb.COMPLETE_EXPRESSION)

    def invoke(self, arg, from_tty):
        val = gdb.parse_and_eval(arg)
        if val.type.code == gdb.TYPE_CODE_REF:
            val = val.referenced_value()
        m = Dense(val)
        cells = [[number(m.at(i, j)) for j in range(m.cols)] for i in range(m.rows)]
        width = max((len(c) for row in cells for c in row), default=1)
        print("%s = [%dx%d]" % (arg, m.rows, m.cols))
        for row in cells:
            print("  " + "  ".join(c.rjust(width) for c in row))


class Collection(gdb.printing.PrettyPrinter):
    """the printers as one named collection (`info pretty-printer` lists it as ample-eigen)"""

    def __init__(self):
        super().__init__("ample-eigen")

    def __call__(self, val):
        return lookup(val)


if not getattr(gdb, "_ample_eigen_loaded", False):  # sourcing twice adds nothing twice
    gdb._ample_eigen_loaded = True
    gdb.printing.register_pretty_printer(None, Collection())
    PrintMatrix()
