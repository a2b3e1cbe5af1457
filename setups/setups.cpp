//--------------------------------------------------------------------------
// setups.cpp — the explicit table of setups and the parameter helpers
//--------------------------------------------------------------------------
// To add a problem: write setups/<name>.cpp with its struct of parameters,
// params(), setupGrid(), results() and calls() in namespace ample::<name>,
// declare calls() in one line below and add one line to the table. Only this
// file knows every setup, so a change to one setup file recompiles that file alone.
//--------------------------------------------------------------------------
#include "setups.h"
#include "ample/errors.h"
#include "ample/solver/solverChoice.h"
#include <cmath>
#include <iterator>
#include <sstream>

namespace ample {

// the calls of each setup file: its params, setupGrid and results (a mismatch is a link error)
namespace compaction { SetupCalls calls(); }
namespace beam       { SetupCalls calls(); }
namespace collapse   { SetupCalls calls(); }
namespace shear      { SetupCalls calls(); }
namespace stretch    { SetupCalls calls(); }
namespace ibblock    { SetupCalls calls(); }
namespace deepbeam   { SetupCalls calls(); }
namespace ibshear    { SetupCalls calls(); }
namespace ibcantilever { SetupCalls calls(); }
namespace funnel     { SetupCalls calls(); }
namespace annulus    { SetupCalls calls(); }
namespace doughnut   { SetupCalls calls(); }
namespace footing    { SetupCalls calls(); }
namespace squeeze    { SetupCalls calls(); }
namespace prandtl    { SetupCalls calls(); }
namespace lame       { SetupCalls calls(); }
namespace layer      { SetupCalls calls(); }

const std::vector<Setup>& setupsTable() {
  static const std::vector<Setup> table = {
      {"compaction", "elastic column compacting under self weight ([AMPLE] sec 5.1)",
       compaction::calls()},
      {"beam", "large-deflection elastic cantilever with a tip load ([AMPLE] sec 5.2)",
       beam::calls()},
      {"collapse", "von Mises block collapsing under self weight ([AMPLE] sec 5.3)",
       collapse::calls()},
      {"shear", "simple shear of a unit square, elastic or von Mises ([Lagrangian] sec 7.2)",
       shear::calls()},
      {"stretch", "plane-strain stretch of a von Mises block on a moving grid ([CPDI] sec 3.1)",
       stretch::calls()},
      {"ibblock", "contained block compressed through implicit rollers at an angle ([Boundaries] sec 5.1)",
       ibblock::calls()},
      {"deepbeam", "deep cantilever under self weight, fixed by an implicit boundary ([Boundaries] sec 5.2)",
       deepbeam::calls()},
      {"ibshear", "simple shear held by a fixed implicit boundary anywhere in a cell ([Boundaries] sec 5.3)",
       ibshear::calls()},
      {"ibcantilever", "slender cantilever under body force, fixed by an implicit boundary, at 0/45/90 degrees ([Boundaries] sec 5.4)",
       ibcantilever::calls()},
      {"footing", "rough rigid footing pushed 1 m into an elastic domain by an implicit boundary ([Boundaries] sec 5.5)",
       footing::calls()},
      {"annulus", "elastic annulus twisted by a manufactured body force on triangles ([Lagrangian] sec 7.4)",
       annulus::calls()},
      {"funnel", "elastic body forced through a curved funnel of implicit rollers ([Boundaries] sec 5.6)",
       funnel::calls()},
      {"doughnut", "twist of a confined annulus on an annular quad mesh: MPM, CPDI1, CPDI2, FE mode ([CPDI] sec 3.2)",
       doughnut::calls()},
      {"squeeze", "elastic block squeezed from above, sides free: the worked setup of docs/new-setup.md",
       squeeze::calls()},
      {"prandtl", "rigid strip footing on weightless von Mises soil, q_u = (2 + pi) c_u: a volumetric locking benchmark",
       prandtl::calls()},
      {"lame", "thick-walled elastic cylinder under internal pressure (Lame): a volumetric locking benchmark",
       lame::calls()},
      {"layer", "elastic layer under self weight, nu = 0.49: the mean-stress checkerboard of locking",
       layer::calls()},
  };
  return table;
}

const Setup* findSetup(const std::string& name) {
  for (const Setup& s : setupsTable())
    if (name == s.name) return &s;
  return nullptr;
}

const Param& Params::named(const std::string& name) const {
  for (const Param& p : *this)
    if (p.name == name) return p;
  throw InputError("internal: no parameter '" + name + "'");
}

Param& Params::named(const std::string& name) {
  return const_cast<Param&>(static_cast<const Params&>(*this).named(name));
}

void setParam(Params& P, const std::string& name, double value) { P.named(name).set(value); }

std::string rangeText(const Param& p) {
  auto num = [](double v) {
    if (std::isinf(v)) return std::string(v > 0 ? "inf" : "-inf");
    std::ostringstream s;
    s << v;
    return s.str();
  };
  std::string text = std::string(p.isInteger ? "integer in " : "") + (p.loOpen ? "(" : "[") +
                     num(p.lo) + ", " + num(p.hi) + (p.hiOpen ? ")" : "]");
  for (size_t k = 0; k < p.names.size(); ++k)
    text += (k ? ", " : " or by name: ") + num(p.lo + k) + " " + p.names[k];
  return text;
}

// the names, ranges and help of Common's members, in the order --help and summary.json give them
Params commonParams(Common& p) {
  Params P;
  param(P, "lstps", p.lstps).integer(1, 1e6).help("number of equal load steps");
  param(P, "tol", p.tol).above(0).below(1).help("Newton-Raphson tolerance on fErr (eq 35)");
  param(P, "NRitMax", p.NRitMax).integer(2, 1000).help("most Newton-Raphson passes per load step");
  param(P, "solver", p.solver).choice(0, {std::begin(solverNameList), std::end(solverNameList)})
      .help("sparse solver of Kt(fd,fd): LU = Eigen's SparseLU (COLAMD); LDLT = Eigen's "
            "SimplicialLDLT (AMD) in every pass where Kt(fd,fd) is symmetric, else LU; MUMPS = "
            "MUMPS's LDL^T when symmetric, else its LU (-DAMPLE_MUMPS=ON); PETSC = the same over "
            "the MPI ranks of mpirun (-DAMPLE_PETSC=ON); the ones this build has: below the list");
  param(P, "substeps", p.substeps).integer(0, 30)
      .help("remedy: halvings of a load step allowed when Newton fails (0 = the paper's algorithm)");
  param(P, "ghost", p.ghost).range(0, 1e3)
      .help("remedy: ghost-penalty factor gamma on the faces of the edge cells, on from the "
            "first load step that fails without it (0 = off, the paper's)");
  param(P, "split", p.split).range(0, 10)
      .help("remedy: after each converged load step, split a GIMP point in two along x or y where "
            "its domain half length lp exceeds split times the cell size h (0 = off, the paper's; "
            "0.5 keeps every domain within one cell's length)");
  param(P, "lone", p.lone).integer(0, 2)
      .help("remedy: leave out of the free set the dofs of nodes that one point alone reaches and "
            "that are redundant (a zero-energy mode whose pivot is round-off): 0 = never (the "
            "paper's free set, every node linked to a point), 1 = in every load step, 2 = from the "
            "first load step that fails without it, if it leaves a dof out there");
  param(P, "mpType", p.mpType).choice(1, {"MPM", "GIMP", "CPDI1", "CPDI2"}).help("material point type");
  param(P, "mp", p.mp).integer(1, 20).help("material points per cell in each direction");
  param(P, "cmType", p.cmType).choice(1, {"elastic", "VM"}).help("constitutive model");
  param(P, "formulation", p.formulation).choice(1, {"UL", "PC", "SS"})
      .help("equilibrium frame: updated or previously converged Lagrangian ([Lagrangian]), or "
            "small strain with linear kinematics ([Boundaries] sec 2)");
  param(P, "locking", p.locking).choice(0, {"none", "Fbar"})
      .help("anti-locking (docs/locking.md): none = the papers' point loop; Fbar = each point's J "
            "replaced by the volume average over the points of its cell (F-bar for UL and PC, its "
            "small-strain B-bar for SS), for nearly incompressible or von Mises (undrained) soil");
  param(P, "domainUpdate", p.domainUpdate)
      .choice(0, {"none", "detF", "Fii", "Uii", "corner", "FiiVol", "FiiVolInc"})
      .help("GIMP domain update ([Lagrangian] eqs 32-39)");
  param(P, "E", p.E).above(0).help("Young's modulus (Pa)");
  param(P, "nu", p.nu).above(-1).below(0.5).help("Poisson's ratio");
  param(P, "rhoY", p.rhoY).above(0)
      .help("von Mises strength rho_y = sqrt(2 J2) at yield (Pa); uniaxial yield stress sigma_y = "
            "sqrt(3/2) rho_y; plane-strain undrained shear strength c_u = rho_y / sqrt(2) (Tresca-matched), "
            "so rhoY = sqrt(2) c_u, e.g. c_u = 10 kPa: rhoY=14142.1356");
  param(P, "geostatic", p.geostatic).choice(0, {"off", "on"})
      .help("initial stress (ample/initial/geostatic.h): on = every point starts from sigma_yy = -rho g d "
            "(d its depth below the top of the points of its column of cells), sigma_xx = sigma_zz = K0 "
            "sigma_yy, with its elastic strain, and the weight acts in full from load step 1 (setups with "
            "gravity, regular grid; a von Mises point beyond yield is refused); off = the papers' start "
            "from zero stress, the weight ramped with the load steps");
  param(P, "K0", p.K0).range(0, 10)
      .help("geostatic=on: the ratio sigma_xx / sigma_yy = sigma_zz / sigma_yy of the initial stress "
            "(1 = isotropic)");
  return P;
}

}  // namespace ample
