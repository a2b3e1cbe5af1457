//--------------------------------------------------------------------------
// mpData.h — the two data structures of the analysis: material points and mesh
//--------------------------------------------------------------------------
// [AMPLE] tables 3 (mpData) and 4 (mesh). One MaterialPoint holds the whole
// state of one point, so a debugger shows it at once (`p mpData[17]`).
// Indices are 0-based: node n owns the degrees of freedom 2n (x) and 2n+1 (y).
// Stress and strain are 6-vectors in the order [xx yy zz xy yz zx]; strains
// store engineering shear components (2 eps_xy, ...).
// A point's basis (nIN, Svp, dSvp) is kept in fixed-size arrays of MAXN
// nodes, of which the first nn are its own. The domain of a CPDI point
// (st0, st, xc) is kept on the heap for CPDI points only (cpdi, empty for MPM
// and GIMP).
// Inputs:  (types only)
// Outputs: MaterialPoint, CpdiDomain, Mesh, BC, Indirect
// Tests:   tests/test_mpData.cpp
//--------------------------------------------------------------------------
#pragma once
#include "constitutive/Hooke3d.h"  // MaterialConstants
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <array>
#include <memory>
#include <vector>

namespace ample {

using SpMat = Eigen::SparseMatrix<double>;  // column-major compressed sparse matrix (Kt)

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Eigen::Matrix3d;
using Eigen::Vector2d;
using Eigen::Vector3d;

constexpr int nD = 2;        // spatial dimensions of the background grid
constexpr int nen = 4;       // most nodes per cell (bi-linear quadrilateral; a triangle has 3)
constexpr int MAXN = 16;     // most nodes one point may influence (4 x 4): its basis arrays
constexpr int MAXE = 9;      // most cells one point domain may overlap (3 x 3)

enum class MpType { MPM = 1, GIMP = 2, CPDI1 = 3, CPDI2 = 4 };  // [AMPLE]: mpType (+ [CPDI])
enum class CmType { Elastic = 1, VonMises = 2 };                 // [AMPLE]: cmType
enum class Formulation { UL = 1, PC = 2, SS = 3 };  // updated / previously converged Lagrangian
                                                    // ([Lagrangian]), small strain ([Boundaries] sec 2)
enum class Locking { None = 0, Fbar = 1 };          // volumetric locking remedy (ample/locking/)
enum class LinearSolver {                   // the sparse solve of Kt(fd,fd) (freeSystem.h)
  LU = 0, LDLT = 1, MUMPS = 2, PETSC = 3
};  // SparseLU (the default) · SimplicialLDLT if symmetric, else SparseLU · MUMPS LDL^T if
    // symmetric, else its LU (-DAMPLE_MUMPS=ON; mumps.h) · the same over the MPI ranks of
    // `mpirun -n N` by PETSc's linear solver server (-DAMPLE_PETSC=ON; petscSolve.h);
    // the choices retired in 2026: docs/solvers.md, "Retired choices"
enum class DomainUpdate {                   // GIMP domain updating, [Lagrangian] sec 6.4, table 2
  None = 0, DetF = 1, Fii = 2, Uii = 3, Corner = 4, FiiVol = 5, FiiVolInc = 6
};  //  -     eq 32     eq 33    eq 34    eqs 35-37   eq 38      eq 39

// [CPDI] sec 2: the domain of a CPDI point, a parallelogram (CPDI1) or a quadrilateral (CPDI2)
// a value kept on the heap: a copy copies the value (unlike std::unique_ptr, like
// C++26 std::indirect); empty until one is given, so an unused one costs one pointer
template <class T>
class Indirect {
 public:
  Indirect() = default;
  Indirect(const T& value) : p_(new T(value)) {}
  Indirect(const Indirect& o) : p_(o.p_ ? new T(*o.p_) : nullptr) {}
  Indirect(Indirect&&) noexcept = default;
  Indirect& operator=(const Indirect& o) {
    if (o.p_ && p_) *p_ = *o.p_;             // both held: copy the value in place
    else p_.reset(o.p_ ? new T(*o.p_) : nullptr);
    return *this;
  }
  Indirect& operator=(Indirect&&) noexcept = default;
  T* operator->() { return p_.get(); }
  const T* operator->() const { return p_.get(); }
  T& operator*() { return *p_; }
  const T& operator*() const { return *p_; }
  explicit operator bool() const { return p_ != nullptr; }
 private:
  std::unique_ptr<T> p_;
};

struct CpdiDomain {
  Eigen::Matrix2d st0 = Eigen::Matrix2d::Zero();  // CPDI1: original domain vectors s, t (columns)
  Eigen::Matrix2d st = Eigen::Matrix2d::Zero();   // CPDI1: current domain vectors s = F s0, t = F t0
  Eigen::Matrix<double, nD, 4> xc = Eigen::Matrix<double, nD, 4>::Zero();  // CPDI2: domain corners
};

struct MaterialPoint {                     // members ordered so that they pack
  MpType mpType = MpType::GIMP;            // material point type
  CmType cmType = CmType::Elastic;         // constitutive model type
  double vp = 0, vp0 = 0;                  // current and original volume (eq 15)
  double mpM = 0;                          // mass
  Vector2d mpC = Vector2d::Zero();         // current coordinates x_p
  Vector2d X0 = Vector2d::Zero();          // original coordinates X_p
  int nn = 0;                              // number of nodes linked to the point
  int ne = 0;                              // number of cells linked to the point
  std::array<int, MAXE> eIN{};             // cells linked to the point
  std::array<int, MAXN> nIN{};             // nodes linked to the point: nIN[v], v < nn
  std::array<double, MAXN> Svp{};          // basis functions S_vp: Svp[v]
  Eigen::Matrix<double, nD, MAXN> dSvp = Eigen::Matrix<double, nD, MAXN>::Zero();  // dS_vp/dX~:
                                           // dSvp(j, v), dSvp.col(v), dSvp.leftCols(nn)
  Matrix3d Fn = Matrix3d::Identity();      // deformation gradient at start of load step
  Matrix3d F = Matrix3d::Identity();       // current deformation gradient (SS: stays I)
  MaterialConstants mCst;                  // material constants E, nu, rhoY
  Vector6d sig = Vector6d::Zero();         // Cauchy stress
  Vector6d epsEn = Vector6d::Zero();       // elastic log strain at start of load step (SS: small)
  Vector6d epsE = Vector6d::Zero();        // current elastic log strain (SS: small strain)
  Vector2d fp = Vector2d::Zero();          // point force carried by the point (total)
  Vector2d u = Vector2d::Zero();           // total displacement
  Vector2d lp = Vector2d::Zero();          // domain half lengths (0 for MPM)
  Vector2d lp0 = Vector2d::Zero();         // original domain half lengths
  Indirect<CpdiDomain> cpdi;               // CPDI points only: st0, st, xc (MPM, GIMP: empty)
};

inline bool isCPDI(const MaterialPoint& mp) {
  return mp.mpType == MpType::CPDI1 || mp.mpType == MpType::CPDI2;
}

// degree of freedom i (0 = x, 1 = y) of node `node` (0-based); written once here
inline int dof(int node, int i) { return nD * node + i; }

struct BC {
  int dof;       // constrained degree of freedom
  double value;  // prescribed displacement increment per load step
};

// the kind of background mesh (docs/meshes.md): the regular grid of formCoord2D (fast
// cell search by the spacing, GIMP) or a general mesh of one cell shape (generalMesh)
enum class MeshType { Grid = 0, Tri3 = 3, Quad4 = 4 };

// bucket grid over a general mesh's bounding box (cellSearch.cpp): bucket (i, j) lists
// the cells whose bounding boxes overlap it, ascending, in cells[start[b] .. start[b+1])
struct CellSearch {
  Vector2d lo = Vector2d::Zero(), size = Vector2d::Zero();  // box corner, bucket size
  int nbx = 0, nby = 0;                                     // buckets in x and y
  std::vector<int> start, cells;
  bool empty() const { return start.empty(); }
};

struct Mesh {
  MeshType type = MeshType::Grid;                      // regular grid or general mesh
  int nelsx = 0, nelsy = 0;                            // cells in x and y (regular grid)
  Vector2d origin = Vector2d::Zero();                  // lower-left corner of the grid
  Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> etpl;  // cell topology:
                                                       // nels x 4 (grid, Quad4) or x 3 (Tri3)
  Eigen::Matrix<double, Eigen::Dynamic, nD, Eigen::RowMajor> coord;  // nodal coordinates
  Vector2d h = Vector2d::Zero();                       // grid spacing (regular grid only)
  std::vector<BC> bc;                                  // Dirichlet conditions
  std::vector<char> eInA;                              // 1 = active cell (holds points)
  CellSearch search;                                   // general mesh: its bucket grid

  int nodes() const { return int(coord.rows()); }
  int nels() const { return int(etpl.rows()); }
  int nDoF() const { return nD * nodes(); }
  int cellNodes() const { return int(etpl.cols()); }   // 4, or 3 for triangles
  bool regular() const { return type == MeshType::Grid; }
};

}  // namespace ample
