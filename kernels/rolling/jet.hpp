// Second-order forward-mode jet: value, gradient and Hessian with respect to N
// variables. Used for the exact (machine-precision) linearisation of the beam strain
// energy and of the rotary inertia terms; the contact tangent is derived by hand
// (README Eq. R-20..R-27) and both are checked against central differences in tests.
#pragma once

#include <array>

namespace rollspec::rolling {

template <int N>
struct Jet2 {
  double v = 0.0;
  std::array<double, N> g{};
  std::array<double, N * N> h{};

  Jet2() = default;
  Jet2(double c) : v(c) {}  // NOLINT: implicit constant promotion is intended

  static Jet2 variable(double value, int i) {
    Jet2 j(value);
    j.g[static_cast<std::size_t>(i)] = 1.0;
    return j;
  }

  Jet2& operator+=(const Jet2& b) {
    v += b.v;
    for (int i = 0; i < N; ++i) g[i] += b.g[i];
    for (int i = 0; i < N * N; ++i) h[i] += b.h[i];
    return *this;
  }
  Jet2& operator-=(const Jet2& b) {
    v -= b.v;
    for (int i = 0; i < N; ++i) g[i] -= b.g[i];
    for (int i = 0; i < N * N; ++i) h[i] -= b.h[i];
    return *this;
  }
  Jet2& operator*=(double c) {
    v *= c;
    for (auto& x : g) x *= c;
    for (auto& x : h) x *= c;
    return *this;
  }
};

template <int N>
inline Jet2<N> operator+(Jet2<N> a, const Jet2<N>& b) {
  return a += b;
}
template <int N>
inline Jet2<N> operator-(Jet2<N> a, const Jet2<N>& b) {
  return a -= b;
}
template <int N>
inline Jet2<N> operator-(Jet2<N> a) {
  a *= -1.0;
  return a;
}
template <int N>
inline Jet2<N> operator+(Jet2<N> a, double c) {
  a.v += c;
  return a;
}
template <int N>
inline Jet2<N> operator+(double c, Jet2<N> a) {
  a.v += c;
  return a;
}
template <int N>
inline Jet2<N> operator-(Jet2<N> a, double c) {
  a.v -= c;
  return a;
}
template <int N>
inline Jet2<N> operator-(double c, Jet2<N> a) {
  a *= -1.0;
  a.v += c;
  return a;
}
template <int N>
inline Jet2<N> operator*(Jet2<N> a, double c) {
  a *= c;
  return a;
}
template <int N>
inline Jet2<N> operator*(double c, Jet2<N> a) {
  a *= c;
  return a;
}

template <int N>
inline Jet2<N> operator*(const Jet2<N>& a, const Jet2<N>& b) {
  Jet2<N> r;
  r.v = a.v * b.v;
  for (int i = 0; i < N; ++i) r.g[i] = a.v * b.g[i] + b.v * a.g[i];
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j)
      r.h[i * N + j] = a.v * b.h[i * N + j] + b.v * a.h[i * N + j] + a.g[i] * b.g[j] + b.g[i] * a.g[j];
  return r;
}

template <int N>
inline Jet2<N> reciprocal(const Jet2<N>& b) {
  Jet2<N> r;
  const double iv = 1.0 / b.v;
  r.v = iv;
  for (int i = 0; i < N; ++i) r.g[i] = -b.g[i] * iv * iv;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) r.h[i * N + j] = -b.h[i * N + j] * iv * iv + 2.0 * b.g[i] * b.g[j] * iv * iv * iv;
  return r;
}

template <int N>
inline Jet2<N> operator/(const Jet2<N>& a, const Jet2<N>& b) {
  return a * reciprocal(b);
}
template <int N>
inline Jet2<N> operator/(double c, const Jet2<N>& b) {
  return c * reciprocal(b);
}
template <int N>
inline Jet2<N> operator/(Jet2<N> a, double c) {
  a *= 1.0 / c;
  return a;
}

inline double value_of(double x) { return x; }
template <int N>
inline double value_of(const Jet2<N>& x) {
  return x.v;
}

}  // namespace rollspec::rolling
