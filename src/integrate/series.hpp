// Private to src/: coefficient k of products of Taylor series, the inner loop
// of the Taylor recurrences (Jorba & Zou 2005, section 2).
#pragma once

namespace stickslip {

// A Taylor series stored with kPad zeros before coefficient 0 and kPad
// entries after the last, so that Cauchy() runs in whole blocks of four.
constexpr int kPad = 4;
template <int N>
struct Series {
  double buf[N + 1 + 2 * kPad] = {};
  double* c() { return buf + kPad; }
  const double* c() const { return buf + kPad; }
};

// Coefficient k of the Cauchy product of p and q: sum_{j <= k} p_j q_{k-j}.
// q must be padded (q[-3..-1] = 0) and p[k+1..k+3] finite: the blocks of four
// run past j = k with zero terms, in four partial sums (a single sum is one
// chain of dependent multiply-adds).
inline double Cauchy(const double* p, const double* q, int k) {
  double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
  for (int j = 0; j <= k; j += 4) {
    s0 += p[j] * q[k - j];
    s1 += p[j + 1] * q[k - j - 1];
    s2 += p[j + 2] * q[k - j - 2];
    s3 += p[j + 3] * q[k - j - 3];
  }
  return (s0 + s1) + (s2 + s3);
}

// sum_{i < n} a_i b_i for two ascending arrays (a product of series with one
// factor stored reversed): two-lane vectors (GCC/Clang vector extensions;
// SSE2 on x86-64, VEX in an x86-64-v3 kernel clone), two accumulators.
inline double Dot(const double* a, const double* b, int n) {
  typedef double V2 __attribute__((vector_size(16)));
  V2 s0 = {0, 0}, s1 = {0, 0};
  int i = 0;
  for (; i + 4 <= n; i += 4) {
    V2 a0, a1, b0, b1;
    __builtin_memcpy(&a0, a + i, sizeof a0);
    __builtin_memcpy(&a1, a + i + 2, sizeof a1);
    __builtin_memcpy(&b0, b + i, sizeof b0);
    __builtin_memcpy(&b1, b + i + 2, sizeof b1);
    s0 += a0 * b0;
    s1 += a1 * b1;
  }
  if (i + 2 <= n) {
    V2 a0, b0;
    __builtin_memcpy(&a0, a + i, sizeof a0);
    __builtin_memcpy(&b0, b + i, sizeof b0);
    s0 += a0 * b0;
    i += 2;
  }
  const V2 s = s0 + s1;
  double r = s[0] + s[1];
  if (i < n) r += a[i] * b[i];
  return r;
}

// sum_{i < n} |a_i| in two-lane vectors (n < 0: 0).
inline double AbsSum(const double* a, int n) {
  typedef double V2 __attribute__((vector_size(16)));
  typedef long long M2 __attribute__((vector_size(16)));
  const M2 mask = {0x7fffffffffffffffLL, 0x7fffffffffffffffLL};  // clears the sign bit
  V2 s = {0, 0};
  int i = 0;
  for (; i + 2 <= n; i += 2) {
    V2 v;
    __builtin_memcpy(&v, a + i, sizeof v);
    s += (V2)((M2)v & mask);
  }
  double r = s[0] + s[1];
  if (i < n) r += a[i] < 0 ? -a[i] : a[i];
  return r;
}

// sum_{lo <= j <= hi} p_j q_{k-j} in four partial sums (no padding read).
inline double CauchyRange(const double* p, const double* q, int lo, int hi, int k) {
  double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
  int j = lo;
  for (; j + 3 <= hi; j += 4) {
    s0 += p[j] * q[k - j];
    s1 += p[j + 1] * q[k - j - 1];
    s2 += p[j + 2] * q[k - j - 2];
    s3 += p[j + 3] * q[k - j - 3];
  }
  for (; j <= hi; ++j) s0 += p[j] * q[k - j];
  return (s0 + s1) + (s2 + s3);
}
// Coefficient k of p q with p_0 = 0, the newest terms (j = 1 and j = k - 1,
// holding q_{k-1} and p_{k-1}) added last: the sum of the older ones does not
// wait for them, so a recurrence through p q waits one multiply-add per order,
// not a chain of k / 4.
inline double CauchyNewestLast(const double* p, const double* q, int k) {
  if (k < 2) return 0.0;
  if (k == 2) return p[1] * q[1];
  return CauchyRange(p, q, 2, k - 2, k) + (p[1] * q[k - 1] + p[k - 1] * q[1]);
}
// Coefficient k of p q and of r q in one pass over q (the variational
// equations' two columns against one coefficient series).
inline void Cauchy2(const double* p, const double* r, const double* q, int k, double* pq,
                    double* rq) {
  double s0 = 0, s1 = 0, s2 = 0, s3 = 0, t0 = 0, t1 = 0, t2 = 0, t3 = 0;
  for (int j = 0; j <= k; j += 4) {
    const double q0 = q[k - j], q1 = q[k - j - 1], q2 = q[k - j - 2], q3 = q[k - j - 3];
    s0 += p[j] * q0, t0 += r[j] * q0;
    s1 += p[j + 1] * q1, t1 += r[j + 1] * q1;
    s2 += p[j + 2] * q2, t2 += r[j + 2] * q2;
    s3 += p[j + 3] * q3, t3 += r[j + 3] * q3;
  }
  *pq = (s0 + s1) + (s2 + s3);
  *rq = (t0 + t1) + (t2 + t3);
}
// Cauchy2 with the newest terms (j = 0 with q_k, j = k with p_k and r_k) added
// last, so that the sums of the older terms do not wait for them.
inline void Cauchy2NewestLast(const double* p, const double* r, const double* q, int k, double* pq,
                              double* rq) {
  if (k == 0) {
    *pq = p[0] * q[0], *rq = r[0] * q[0];
    return;
  }
  double s0 = 0, s1 = 0, s2 = 0, s3 = 0, t0 = 0, t1 = 0, t2 = 0, t3 = 0;
  int j = 1;
  for (; j + 3 <= k - 1; j += 4) {
    const double q0 = q[k - j], q1 = q[k - j - 1], q2 = q[k - j - 2], q3 = q[k - j - 3];
    s0 += p[j] * q0, t0 += r[j] * q0;
    s1 += p[j + 1] * q1, t1 += r[j + 1] * q1;
    s2 += p[j + 2] * q2, t2 += r[j + 2] * q2;
    s3 += p[j + 3] * q3, t3 += r[j + 3] * q3;
  }
  for (; j <= k - 1; ++j) s0 += p[j] * q[k - j], t0 += r[j] * q[k - j];
  *pq = ((s0 + s1) + (s2 + s3)) + (p[0] * q[k] + p[k] * q[0]);
  *rq = ((t0 + t1) + (t2 + t3)) + (r[0] * q[k] + r[k] * q[0]);
}

// Phi' = J Phi, J = [0 1; -1 cc] (the variational equations of both models'
// slip fields): order k + 1 of Phi's two columns (rows p0, q0 and p1, q1),
// cc set to order k, both columns' sums with cc in one pass.
inline void PhiColumnsNext(double* p0, double* q0, double* p1, double* q1, const double* cc, int k,
                           double inv) {
  double cq0, cq1;
  Cauchy2NewestLast(q0, q1, cc, k, &cq0, &cq1);
  p0[k + 1] = q0[k] * inv;
  q0[k + 1] = (-p0[k] + cq0) * inv;
  p1[k + 1] = q1[k] * inv;
  q1[k + 1] = (-p1[k] + cq1) * inv;
}

// k as a double for k < kMax.
template <int kMax>
struct Ordinals {
  double k[kMax];
  constexpr Ordinals() : k() {
    for (int i = 0; i < kMax; ++i) k[i] = i;
  }
};

// 1 / (k + 1) for k < kMax.
template <int kMax>
struct Reciprocals {
  double r[kMax];
  constexpr Reciprocals() : r() {
    for (int k = 0; k < kMax; ++k) r[k] = 1.0 / (k + 1);
  }
};

}  // namespace stickslip
