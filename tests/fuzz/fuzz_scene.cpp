#include "fuzz_scene.hpp"

#include <cmath>
#include <cstring>

namespace b2b_fuzz {
namespace {

constexpr double kPi = 3.14159265358979323846;

double dot(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const double* a) { return std::sqrt(dot(a, a)); }
void cross(const double* a, const double* b, double* c) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}
// v / |v|, or fallback if v has no length.
void unit_or(const double* v, const double* fallback, double* out) {
  const double n = norm(v);
  for (int i = 0; i < 3; ++i) out[i] = n > 0 && std::isfinite(n) ? v[i] / n : fallback[i];
}
// A unit vector perpendicular to the unit vector a.
void perpendicular(const double* a, double* out) {
  const double e[3] = {std::fabs(a[0]) < 0.6 ? 1.0 : 0.0, std::fabs(a[0]) < 0.6 ? 0.0 : 1.0, 0.0};
  double c[3];
  cross(a, e, c);
  const double fb[3] = {0, 0, 1};
  unit_or(c, fb, out);
}
// Rotation by angle about the unit axis (Rodrigues), column-major.
void axis_angle(const double* k, double angle, double R[9]) {
  const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
  R[0] = c + t * k[0] * k[0];
  R[1] = t * k[0] * k[1] + s * k[2];
  R[2] = t * k[0] * k[2] - s * k[1];
  R[3] = t * k[0] * k[1] - s * k[2];
  R[4] = c + t * k[1] * k[1];
  R[5] = t * k[1] * k[2] + s * k[0];
  R[6] = t * k[0] * k[2] + s * k[1];
  R[7] = t * k[1] * k[2] - s * k[0];
  R[8] = c + t * k[2] * k[2];
}
void matmul(const double A[9], const double B[9], double C[9]) {
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r)
      C[r + 3 * c] = A[r] * B[3 * c] + A[r + 3] * B[1 + 3 * c] + A[r + 6] * B[2 + 3 * c];
}
// The rotation taking unit a onto unit b.
void align(const double* a, const double* b, double R[9]) {
  double k[3];
  cross(a, b, k);
  const double s = norm(k), c = dot(a, b);
  if (s < 1e-300) {
    if (c > 0) {
      const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
      std::memcpy(R, I, sizeof I);
    } else {
      double p[3];
      perpendicular(a, p);
      axis_angle(p, kPi, R);
    }
    return;
  }
  for (double& v : k) v /= s;
  axis_angle(k, std::atan2(s, c), R);
}

// Point and unit tangent of a segment at t in local coordinates, by the
// library itself; the chord x2 -> x3 where the segment is refused.
void point_and_tangent(const SegmentSpec& s, const double patch[12], const double tangents[6],
                       double t, double p[3], double d[3]) {
  double x[9];
  const double chord[3] = {patch[6] - patch[3], patch[7] - patch[4], patch[8] - patch[5]};
  const double ex[3] = {1, 0, 0};
  if (b2b_segment_eval(s.kind, s.start_rule, s.end_rule, patch, tangents, t, x, nullptr, nullptr,
                       nullptr, 0) == B2B_OK) {
    std::memcpy(p, x, 3 * sizeof(double));
    unit_or(x + 3, ex, d);
    return;
  }
  for (int i = 0; i < 3; ++i) p[i] = 0.5 * (patch[3 + i] + patch[6 + i]);
  unit_or(chord, ex, d);
}

// A closest-point parameter: inside, on a joint, a rounding error off a
// joint (the ownership tolerance is 1e-13), just outside, well outside.
double decode_parameter(FuzzInput& in) {
  switch (in.pick(10)) {
    case 0: return in.sign();
    case 1: return in.sign() * (1 - in.log_uniform(-16, -10));
    case 2: return in.sign() * (1 + in.log_uniform(-16, -10));
    case 3: return in.sign() * in.uniform(1, 2.5);
    default: return in.uniform(-1, 1);
  }
}

}  // namespace

SegmentSpec decode_segment(FuzzInput& in) {
  SegmentSpec s;
  s.kind = in.pick(4);
  const int end_rule = in.flag() ? B2B_END_TANGENT : B2B_END_REFLECT;
  s.start_rule = s.end_rule = B2B_END_NEIGHBOUR;
  switch (in.pick(6)) {
    case 0: s.start_rule = end_rule; break;
    case 1: s.end_rule = end_rule; break;
    case 2:  // both ends: a one-element beam (refused for the midpoint kind)
      s.start_rule = end_rule;
      s.end_rule = in.flag() ? B2B_END_TANGENT : B2B_END_REFLECT;
      break;
    default: break;
  }
  if (in.chance(6)) {
    const int which = in.pick(3);
    const int v = in.flag() ? in.raw_int() : (in.flag() ? 3 + in.pick(2) : -1 - in.pick(2));
    (which == 0 ? s.kind : which == 1 ? s.start_rule : s.end_rule) = v;
  }
  return s;
}

bool valid_segment(const SegmentSpec& s) {
  return s.kind >= 0 && s.kind <= 3 && s.start_rule >= 0 && s.start_rule <= 2 &&
         s.end_rule >= 0 && s.end_rule <= 2;
}

unsigned used_slots(const SegmentSpec& s) {
  if (!valid_segment(s)) return 0xFu;
  const bool prev = s.start_rule == B2B_END_NEIGHBOUR, next = s.end_rule == B2B_END_NEIGHBOUR;
  if (s.kind == B2B_CURVE_LINEAR) return 0x6u;
  if (s.kind == B2B_CURVE_HERMITE_MIDPOINT) return 0x2u | (prev ? 0x1u : 0u) | (next ? 0x4u : 0u);
  return 0x6u | (prev ? 0x1u : 0u) | (next ? 0x8u : 0u);
}

void poison_unused(FuzzInput& in, const SegmentSpec& s, double patch[12]) {
  const unsigned used = used_slots(s);
  for (int slot = 0; slot < 4; ++slot)
    if (!(used & (1u << slot)))
      for (int i = 0; i < 3; ++i) patch[3 * slot + i] = in.wild();
}

void decode_chain(FuzzInput& in, int n, double* x) {
  static const double kTurn[] = {0.0, 0.05, 0.3, 0.8, 1.5, 2.8, 3.1};
  const double turn = kTurn[in.pick(7)];
  const double uneven = in.flag() ? 0.0 : in.uniform(0, 0.9);
  const int odd = in.chance(24) ? in.pick(n > 1 ? n - 1 : 1) : -1;  // one extreme element
  const double odd_ratio = in.log_uniform(-9, 9);
  double dir[3] = {1, 0, 0};
  std::memset(x, 0, 3 * sizeof(double));
  for (int k = 1; k < n; ++k) {
    if (k > 1 && turn > 0) {
      double axis[3], p[3], R[9], nd[3];
      perpendicular(dir, p);
      double Rroll[9];
      axis_angle(dir, in.uniform(0, 2 * kPi), Rroll);
      rotate(Rroll, p, axis);
      axis_angle(axis, in.uniform(0, turn), R);
      rotate(R, dir, nd);
      std::memcpy(dir, nd, sizeof dir);
    }
    double len = 1 + uneven * in.uniform(-1, 1);
    if (k - 1 == odd) len *= odd_ratio;
    for (int i = 0; i < 3; ++i) x[3 * k + i] = x[3 * (k - 1) + i] + len * dir[i];
  }
}

void decode_degeneracy(FuzzInput& in, double* x, int n) {
  if (n < 2) return;
  const int k = in.pick(n - 1);
  switch (in.pick(4)) {
    case 0:  // neighbours coincide
      std::memcpy(x + 3 * (k + 1), x + 3 * k, 3 * sizeof(double));
      break;
    case 1:  // a fold: both neighbours of node k+1 coincide
      if (k + 2 < n) std::memcpy(x + 3 * (k + 2), x + 3 * k, 3 * sizeof(double));
      break;
    case 2: {  // neighbours a rounding error apart
      const double eps = in.log_uniform(-18, -8);
      for (int i = 0; i < 3; ++i) x[3 * (k + 1) + i] = x[3 * k + i] * (1 + eps) + eps * in.sign();
      break;
    }
    default: {  // a node on top of a non-neighbour (self-crossing chain)
      const int j = in.pick(n);
      std::memcpy(x + 3 * j, x + 3 * in.pick(n), 3 * sizeof(double));
      break;
    }
  }
}

void rotate(const double R[9], const double v[3], double out[3]) {
  const double a = v[0], b = v[1], c = v[2];  // out may be v
  for (int r = 0; r < 3; ++r) out[r] = R[r] * a + R[r + 3] * b + R[r + 6] * c;
}

void random_rotation(FuzzInput& in, double R[9]) {
  // A unit quaternion from four decoded numbers (identity if all vanish).
  double q[4];
  for (double& v : q) v = in.uniform(-1, 1);
  double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (!(n > 1e-6)) {
    q[0] = 1;
    q[1] = q[2] = q[3] = 0;
    n = 1;
  }
  const double w = q[0] / n, a = q[1] / n, b = q[2] / n, c = q[3] / n;
  R[0] = 1 - 2 * (b * b + c * c);
  R[1] = 2 * (a * b + w * c);
  R[2] = 2 * (a * c - w * b);
  R[3] = 2 * (a * b - w * c);
  R[4] = 1 - 2 * (a * a + c * c);
  R[5] = 2 * (b * c + w * a);
  R[6] = 2 * (a * c + w * b);
  R[7] = 2 * (b * c - w * a);
  R[8] = 1 - 2 * (a * a + b * b);
}

Placement decode_placement(FuzzInput& in) {
  Placement p;
  if (in.chance(64)) {
    const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    std::memcpy(p.R, I, sizeof I);
  } else {
    random_rotation(in, p.R);
  }
  switch (in.pick(6)) {
    case 0: p.scale = in.log_uniform(-95, 95); break;
    case 1: p.scale = in.log_uniform(-6, 6); break;
    case 2: p.scale = in.flag() ? in.log_uniform(-100, -90) : in.log_uniform(90, 99.5); break;
    default: p.scale = 1.0; break;
  }
  double rel = 0;
  switch (in.pick(5)) {
    case 0: rel = in.log_uniform(0, 18); break;  // far from the origin: digits lost
    case 1: rel = in.uniform(0, 10); break;
    default: break;
  }
  double dir[3];
  const double d0[3] = {in.uniform(-1, 1), in.uniform(-1, 1), in.uniform(-1, 1)};
  const double ex[3] = {1, 0, 0};
  unit_or(d0, ex, dir);
  for (int i = 0; i < 3; ++i) p.offset[i] = rel * p.scale * dir[i];
  return p;
}

void place_points(const Placement& p, const double* local, double* out, int n) {
  for (int k = 0; k < n; ++k) {
    double r[3];
    rotate(p.R, local + 3 * k, r);
    for (int i = 0; i < 3; ++i) out[3 * k + i] = p.scale * r[i] + p.offset[i];
  }
}

void decode_end_tangents(FuzzInput& in, const double patch[12], double t[6]) {
  for (int e = 0; e < 2; ++e) {
    // the end element's chord: x2 -> x3 for both ends of the nodal kinds'
    // segment (x1 -> x2 and x2 -> x3 for the midpoint kind are close enough)
    double d[3];
    for (int i = 0; i < 3; ++i) d[i] = patch[6 + i] - patch[3 + i];
    double* out = t + 3 * e;
    switch (in.pick(10)) {
      case 0: {  // tilted by up to 80 degrees
        double u[3], p[3], R[9];
        const double ex[3] = {1, 0, 0};
        unit_or(d, ex, u);
        perpendicular(u, p);
        axis_angle(p, in.uniform(0, 1.4), R);
        rotate(R, d, out);
        break;
      }
      case 1: for (int i = 0; i < 3; ++i) out[i] = -d[i]; break;
      case 2: {
        const double s = in.flag() ? in.log_uniform(-300, -200) : in.log_uniform(200, 300);
        for (int i = 0; i < 3; ++i) out[i] = d[i] * s;
        break;
      }
      case 3: out[0] = out[1] = out[2] = 0.0; break;
      default: std::memcpy(out, d, sizeof d); break;
    }
  }
  if (in.chance(8)) inject_wild(in, t, 6);
}

b2b_params* decode_params(FuzzInput& in, double scale, ParamsInfo* info, int max_iterations_cap) {
  b2b_params* p = nullptr;
  if (b2b_params_create(&p, nullptr, 0) != B2B_OK) return nullptr;
  ParamsInfo pi;
  // Penalties: plausible ones (force ~ 1 for a gap of a tenth of the
  // scale), any over 600 decades (overflow of force and energy), zero.
  switch (in.pick(6)) {
    case 0: pi.penalty = in.log_uniform(-300, 300); break;
    case 1: pi.penalty = 0.0; break;
    case 2: pi.penalty = in.wild(); break;
    default: pi.penalty = in.log_uniform(-2, 6) / scale; break;
  }
  b2b_params_set_real(p, "penalty", pi.penalty, nullptr, 0);
  pi.law = in.pick(2);
  if (in.chance(4)) pi.law = in.raw_int();
  b2b_params_set_int(p, "law", pi.law, nullptr, 0);
  if (pi.law == B2B_LAW_QUADRATIC || in.chance(16)) {
    switch (in.pick(4)) {
      case 0: pi.regularization_gap = in.log_uniform(-300, 308); break;
      case 1: pi.regularization_gap = in.wild(); break;
      default: pi.regularization_gap = scale * in.log_uniform(-4, 0.5); break;
    }
    b2b_params_set_real(p, "regularization_gap", pi.regularization_gap, nullptr, 0);
  }
  if (in.chance(48))
    b2b_params_set_real(p, "parallel_angle", in.flag() ? in.uniform(0, 90) : in.special(),
                        nullptr, 0);
  pi.warm_start = in.chance(64) ? 1 : 0;
  if (in.chance(4)) pi.warm_start = in.raw_int();
  b2b_params_set_int(p, "warm_start", pi.warm_start, nullptr, 0);
  static const int kIter[] = {50, 50, 50, 50, 1, 2, 3, 5, 8, 20, 100, 1000, 100000};
  int mi = kIter[in.pick(13)];
  if (in.chance(4)) mi = in.raw_int();
  if (mi > max_iterations_cap) mi = max_iterations_cap;
  b2b_params_set_int(p, "max_iterations", mi, nullptr, 0);
  if (in.flag()) {
    switch (in.pick(4)) {
      case 0: pi.friction = in.log_uniform(-12, 4); break;
      case 1: pi.friction = in.wild(); break;
      default: pi.friction = in.uniform(0, 1); break;
    }
    b2b_params_set_real(p, "friction", pi.friction, nullptr, 0);
    if (!in.chance(4)) {
      switch (in.pick(4)) {
        case 0: pi.tangential_penalty = in.log_uniform(-300, 300); break;
        case 1: pi.tangential_penalty = in.wild(); break;
        default: pi.tangential_penalty = in.log_uniform(-2, 6) / scale; break;
      }
      b2b_params_set_real(p, "tangential_penalty", pi.tangential_penalty, nullptr, 0);
    }
  }
  pi.tangent = in.chance(192) ? B2B_TANGENT_EXACT : in.pick(4);
  if (in.chance(2)) pi.tangent = in.raw_int();
  b2b_params_set_int(p, "tangent", pi.tangent, nullptr, 0);
  if (b2b_params_finalize(p, nullptr, 0) != B2B_OK) {
    b2b_params_destroy(&p);
    return nullptr;
  }
  // What the handle holds is what counts (a refused set_* kept the default).
  b2b_params_get_int(p, "max_iterations", &pi.max_iterations, nullptr, 0);
  b2b_params_get_int(p, "tangent", &pi.tangent, nullptr, 0);
  b2b_params_get_int(p, "law", &pi.law, nullptr, 0);
  b2b_params_get_int(p, "warm_start", &pi.warm_start, nullptr, 0);
  b2b_params_get_real(p, "penalty", &pi.penalty, nullptr, 0);
  b2b_params_get_real(p, "regularization_gap", &pi.regularization_gap, nullptr, 0);
  b2b_params_get_real(p, "friction", &pi.friction, nullptr, 0);
  b2b_params_get_real(p, "tangential_penalty", &pi.tangential_penalty, nullptr, 0);
  b2b_params_history_size(p, &pi.hist_len, nullptr, 0);
  *info = pi;
  return p;
}

void decode_crossing(FuzzInput& in, Crossing& c) {
  double local[2][12], tan_local[2][6];
  for (int b = 0; b < 2; ++b) {
    c.seg[b] = decode_segment(in);
    decode_chain(in, 4, local[b]);
    decode_end_tangents(in, local[b], tan_local[b]);
  }
  const double xi = decode_parameter(in), eta = decode_parameter(in);
  double pa[3], ta[3], pb[3], tb[3];
  point_and_tangent(c.seg[0], local[0], tan_local[0], xi, pa, ta);
  point_and_tangent(c.seg[1], local[1], tan_local[1], eta, pb, tb);

  // Crossing angle in degrees.
  double angle;
  switch (in.pick(8)) {
    case 0: angle = in.log_uniform(-12, 0); break;  // near-parallel
    case 1: angle = 0.0; break;
    case 2: angle = 0.5 * (1 + in.uniform(-1e-3, 1e-3)); break;  // the default threshold
    case 3: angle = 90.0; break;
    default: angle = in.uniform(0, 90); break;
  }
  double u[3];  // direction perpendicular to A's tangent, rolled
  {
    double p[3], R[9];
    perpendicular(ta, p);
    axis_angle(ta, in.uniform(0, 2 * kPi), R);
    rotate(R, p, u);
  }
  const double th = angle * kPi / 180.0 * (in.flag() ? 1 : -1);
  double tb_new[3];
  for (int i = 0; i < 3; ++i) tb_new[i] = std::cos(th) * ta[i] + std::sin(th) * u[i];
  if (in.chance(48))
    for (double& v : tb_new) v = -v;  // anti-parallel
  double n[3], nn[3];
  cross(ta, tb_new, nn);
  double fb[3];
  cross(ta, u, fb);  // parallel tangents: any normal
  unit_or(nn, fb, n);
  if (norm(nn) < 1e-12) std::memcpy(n, fb, sizeof n);

  // Radii in element lengths, and the axes' distance along n.
  for (int b = 0; b < 2; ++b) {
    switch (in.pick(6)) {
      case 0: c.radii[b] = 0.0; break;
      case 1: c.radii[b] = in.log_uniform(-12, 1); break;
      default: c.radii[b] = in.uniform(0.01, 0.3); break;
    }
  }
  const double rsum = c.radii[0] + c.radii[1];
  double dist;
  switch (in.pick(9)) {
    case 0: dist = 0.0; break;  // axes intersect: no normal
    case 1: dist = in.sign() * in.log_uniform(-16, -8); break;
    case 2: dist = in.uniform(-2, 2); break;
    case 3: dist = rsum * (1 + in.sign() * in.log_uniform(-16, -6)); break;  // touching
    default: dist = rsum * in.uniform(0.2, 1.6); break;
  }

  // B rotated so that its tangent at eta is tb_new (and rolled about it),
  // then moved so that its point at eta lies dist along n from A's.
  double R1[9], R2[9], RB[9];
  align(tb, tb_new, R1);
  axis_angle(tb_new, in.flag() ? 0.0 : in.uniform(0, 2 * kPi), R2);
  matmul(R2, R1, RB);
  double target[3];
  for (int i = 0; i < 3; ++i) target[i] = pa[i] + dist * n[i];
  double lb[12];
  for (int k = 0; k < 4; ++k) {
    double d[3], r[3];
    for (int i = 0; i < 3; ++i) d[i] = local[1][3 * k + i] - pb[i];
    rotate(RB, d, r);
    for (int i = 0; i < 3; ++i) lb[3 * k + i] = target[i] + r[i];
  }
  std::memcpy(local[1], lb, sizeof lb);
  for (int e = 0; e < 2; ++e) rotate(RB, tan_local[1] + 3 * e, tan_local[1] + 3 * e);

  if (in.chance(20)) decode_degeneracy(in, local[in.pick(2)], 4);
  if (in.chance(6)) {  // the two segments share nodes
    const int ka = in.pick(4), kb = in.pick(4);
    std::memcpy(local[1] + 3 * kb, local[0] + 3 * ka, 3 * sizeof(double));
  }

  const Placement pl = decode_placement(in);
  c.scale = pl.scale;
  place_points(pl, local[0], c.X, 4);
  place_points(pl, local[1], c.X + 12, 4);
  for (int b = 0; b < 2; ++b)
    for (int e = 0; e < 2; ++e) rotate(pl.R, tan_local[b] + 3 * e, c.tangents + 6 * b + 3 * e);
  rotate(pl.R, n, c.normal);
  for (double& r : c.radii) r *= pl.scale;
  if (in.chance(192))
    for (int b = 0; b < 2; ++b) poison_unused(in, c.seg[b], c.X + 12 * b);
}

void decode_motion(FuzzInput& in, const Crossing& c, double X[24]) {
  std::memcpy(X, c.X, 24 * sizeof(double));
  const double h = c.scale;
  switch (in.pick(6)) {
    case 0: {  // B slides along A's first chord, possibly across joints
      double d[3];
      for (int i = 0; i < 3; ++i) d[i] = c.X[6 + i] - c.X[3 + i];
      const double s = in.uniform(-1.5, 1.5);
      for (int k = 4; k < 8; ++k)
        for (int i = 0; i < 3; ++i) X[3 * k + i] += s * d[i];
      break;
    }
    case 1: {  // B pushed along the normal, possibly through A's axis
      const double s = h * in.uniform(-1.2, 1.2);
      for (int k = 4; k < 8; ++k)
        for (int i = 0; i < 3; ++i) X[3 * k + i] += s * c.normal[i];
      break;
    }
    case 2: {  // both turned rigidly about A's node x2 (read by every kind)
      double R[9];
      random_rotation(in, R);
      for (int k = 0; k < 8; ++k) {
        double d[3], r[3];
        for (int i = 0; i < 3; ++i) d[i] = c.X[3 * k + i] - c.X[3 + i];
        rotate(R, d, r);
        for (int i = 0; i < 3; ++i) X[3 * k + i] = c.X[3 + i] + r[i];
      }
      break;
    }
    default: {  // every node moves a little
      const double s = h * in.log_uniform(-8, -0.5);
      for (int k = 0; k < 24; ++k) X[k] += s * in.uniform(-1, 1);
      break;
    }
  }
}

}  // namespace b2b_fuzz
