//--------------------------------------------------------------------------
// basisArena.h — where a point's basis and its CPDI domain are kept
//--------------------------------------------------------------------------
// [AMPLE] table 3 gives every point its nodes nIN, basis values Svp and
// gradients dSvp. A point links 4-9 nodes (at most MAXN = 16), so arrays of 16
// in every point would be mostly empty: the basis of all points lives instead
// in one BasisArena, point after point, each point's nn entries one slice.
// elemMPinfo rebuilds it at the start of each load step (roomForBasis,
// mpData.h); a point reads its slice through three small views that read
// as the arrays of the paper: mp.nIN[v], mp.Svp[v], mp.dSvp(j, v),
// mp.dSvp.col(v), mp.dSvp.leftCols(mp.nn) (an Eigen::Map, 2 x nn).
// The points that view an arena share its ownership (MaterialPoint::basis),
// so a copy of a point or of mpData stays valid wherever it goes.
// Indirect<T>: a value kept on the heap that copies as a value; a CPDI
// point's domain (CpdiDomain, mpData.h) is one, empty for MPM and GIMP points.
// Debugger: tools/gdb/eigen.py prints a view as the point's nn entries.
// Inputs:  (types only)
// Outputs: BasisView<T>, GradientView, BasisArena, Indirect<T>
// Tests:   tests/test_basisArena.cpp
//--------------------------------------------------------------------------
#pragma once
#include <Eigen/Dense>
#include <memory>
#include <vector>

namespace ample {

// nIN or Svp of one point: its nn entries in the arena, read and written as an array
template <class T>
class BasisView {
 public:
  T& operator[](int v) { return first_[v]; }
  const T& operator[](int v) const { return first_[v]; }
  T* data() { return first_; }
  const T* data() const { return first_; }
  const T* begin() const { return first_; }  // with begin() + mp.nn: the point's entries
  void viewAt(T* first) { first_ = first; }  // roomForBasis: the point's slice
 private:
  T* first_ = nullptr;                       // the point's first entry (none: nullptr)
};

// dSvp of one point: 2 x nn, column v the gradient (dS/dX, dS/dY) of node v, its
// columns one after another in the arena (column-major, as an Eigen matrix)
class GradientView {
 public:
  using Cols = Eigen::Map<Eigen::Matrix<double, 2, Eigen::Dynamic>>;
  using ConstCols = Eigen::Map<const Eigen::Matrix<double, 2, Eigen::Dynamic>>;
  double& operator()(int j, int v) { return first_[2 * v + j]; }
  double operator()(int j, int v) const { return first_[2 * v + j]; }
  Eigen::Map<Eigen::Vector2d> col(int v) { return Eigen::Map<Eigen::Vector2d>(first_ + 2 * v); }
  Eigen::Map<const Eigen::Vector2d> col(int v) const {
    return Eigen::Map<const Eigen::Vector2d>(first_ + 2 * v);
  }
  Cols leftCols(int n) { return Cols(first_, 2, n); }
  ConstCols leftCols(int n) const { return ConstCols(first_, 2, n); }
  double* data() { return first_; }
  const double* data() const { return first_; }
  void viewAt(double* first) { first_ = first; }
 private:
  double* first_ = nullptr;
};

// the basis of many points, point after point (slice of point p: its nn entries)
struct BasisArena {
  std::vector<int> nIN;      // nodes linked to each point
  std::vector<double> Svp;   // basis values S_vp
  std::vector<double> dSvp;  // gradients dS_vp/dX~, two per node (x, y)
};

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

}  // namespace ample
