// Forward-mode dual number with a fixed number of directions; nests (Dual<Dual<double,N>,N>) for second derivatives.
#pragma once
#include <array>
#include <cmath>

namespace strandfem {

// Why a hand-written dual type: Eigen's AutoDiffScalar nests poorly with fixed-size derivative vectors,
// and the beam element needs exact first and mixed second derivatives of its strains with respect to
// multiplicative (spin) perturbations of the nodal rotations. Only the operations the element uses exist.
template <class T, int N>
struct Dual {
  T value{};
  std::array<T, N> grad{};

  Dual() = default;
  Dual(double v) : value(v) {}  // NOLINT: implicit from constants is intended
  Dual(const T& v, int) : value(v) {}

  // A variable: value v, derivative 1 in direction k.
  static Dual variable(const T& v, int k) {
    Dual d(v, 0);
    d.grad[k] = T(1.0);
    return d;
  }
};

template <class T>
struct is_dual : std::false_type {};
template <class T, int N>
struct is_dual<Dual<T, N>> : std::true_type {};

inline double value_of(double x) { return x; }
template <class T, int N>
double value_of(const Dual<T, N>& x) { return value_of(x.value); }

// A real-valued function f with derivative df lifted through the dual: chain rule.
template <class T, int N, class F, class DF>
Dual<T, N> lift(const Dual<T, N>& a, F f, DF df) {
  Dual<T, N> r(f(a.value), 0);
  const T d = df(a.value);
  for (int k = 0; k < N; ++k) r.grad[k] = d * a.grad[k];
  return r;
}

template <class T, int N>
Dual<T, N> operator+(const Dual<T, N>& a, const Dual<T, N>& b) {
  Dual<T, N> r(a.value + b.value, 0);
  for (int k = 0; k < N; ++k) r.grad[k] = a.grad[k] + b.grad[k];
  return r;
}
template <class T, int N>
Dual<T, N> operator-(const Dual<T, N>& a, const Dual<T, N>& b) {
  Dual<T, N> r(a.value - b.value, 0);
  for (int k = 0; k < N; ++k) r.grad[k] = a.grad[k] - b.grad[k];
  return r;
}
template <class T, int N>
Dual<T, N> operator-(const Dual<T, N>& a) {
  Dual<T, N> r(-a.value, 0);
  for (int k = 0; k < N; ++k) r.grad[k] = -a.grad[k];
  return r;
}
template <class T, int N>
Dual<T, N> operator*(const Dual<T, N>& a, const Dual<T, N>& b) {
  Dual<T, N> r(a.value * b.value, 0);
  for (int k = 0; k < N; ++k) r.grad[k] = a.grad[k] * b.value + a.value * b.grad[k];
  return r;
}
template <class T, int N>
Dual<T, N> operator/(const Dual<T, N>& a, const Dual<T, N>& b) {
  const T inv = T(1.0) / b.value;
  Dual<T, N> r(a.value * inv, 0);
  for (int k = 0; k < N; ++k) r.grad[k] = (a.grad[k] - r.value * b.grad[k]) * inv;
  return r;
}
template <class T, int N>
Dual<T, N> operator*(double s, const Dual<T, N>& a) {
  Dual<T, N> r(s * a.value, 0);
  for (int k = 0; k < N; ++k) r.grad[k] = s * a.grad[k];
  return r;
}
template <class T, int N>
Dual<T, N> operator*(const Dual<T, N>& a, double s) { return s * a; }
template <class T, int N>
Dual<T, N> operator/(const Dual<T, N>& a, double s) { return (1.0 / s) * a; }
template <class T, int N>
Dual<T, N> operator+(const Dual<T, N>& a, double s) { Dual<T, N> r = a; r.value = r.value + s; return r; }
template <class T, int N>
Dual<T, N> operator+(double s, const Dual<T, N>& a) { return a + s; }
template <class T, int N>
Dual<T, N> operator-(const Dual<T, N>& a, double s) { Dual<T, N> r = a; r.value = r.value - s; return r; }
template <class T, int N>
Dual<T, N> operator-(double s, const Dual<T, N>& a) { return (-a) + s; }
template <class T, int N>
Dual<T, N> operator/(double s, const Dual<T, N>& a) { return Dual<T, N>(s) / a; }
template <class T, int N>
Dual<T, N>& operator+=(Dual<T, N>& a, const Dual<T, N>& b) { a = a + b; return a; }
template <class T, int N>
Dual<T, N>& operator-=(Dual<T, N>& a, const Dual<T, N>& b) { a = a - b; return a; }
template <class T, int N>
Dual<T, N>& operator*=(Dual<T, N>& a, const Dual<T, N>& b) { a = a * b; return a; }

template <class T, int N>
bool operator<(const Dual<T, N>& a, double s) { return value_of(a) < s; }
template <class T, int N>
bool operator>(const Dual<T, N>& a, double s) { return value_of(a) > s; }

using std::atan2;
using std::cos;
using std::sin;
using std::sqrt;

template <class T, int N>
Dual<T, N> sqrt(const Dual<T, N>& a) {
  const T s = sqrt(a.value);
  Dual<T, N> r(s, 0);
  const T d = T(0.5) / s;
  for (int k = 0; k < N; ++k) r.grad[k] = d * a.grad[k];
  return r;
}
template <class T, int N>
Dual<T, N> sin(const Dual<T, N>& a) {
  Dual<T, N> r(sin(a.value), 0);
  const T c = cos(a.value);
  for (int k = 0; k < N; ++k) r.grad[k] = c * a.grad[k];
  return r;
}
template <class T, int N>
Dual<T, N> cos(const Dual<T, N>& a) {
  Dual<T, N> r(cos(a.value), 0);
  const T s = -sin(a.value);
  for (int k = 0; k < N; ++k) r.grad[k] = s * a.grad[k];
  return r;
}
// atan2(y, x), derivative (x dy - y dx) / (x^2 + y^2).
template <class T, int N>
Dual<T, N> atan2(const Dual<T, N>& y, const Dual<T, N>& x) {
  Dual<T, N> r(atan2(y.value, x.value), 0);
  const T inv = T(1.0) / (x.value * x.value + y.value * y.value);
  for (int k = 0; k < N; ++k) r.grad[k] = (x.value * y.grad[k] - y.value * x.grad[k]) * inv;
  return r;
}

}  // namespace strandfem
