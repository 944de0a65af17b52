// C entry points of the AD reference (b2b_ad.h): input checks, the options
// through the public b2b_params getters, the double instantiation for the
// residual and the Dual<24> instantiation for the tangent.
#include "b2b_ad.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <exception>

#include "ad_line.hpp"
#include "ad_pair.hpp"

namespace {

using b2bad::kNdof;

int fail(char* errmsg, int errmsg_len, int status, const char* fmt, ...) {
  if (errmsg && errmsg_len > 0) {
    char buf[512];
    va_list ap;
    va_start(ap, fmt);
    std::vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    std::snprintf(errmsg, static_cast<size_t>(errmsg_len), "b2b_ad_pair_eval: %s", buf);
  }
  return status;
}

int read_settings(const b2b_params* p, b2bad::Settings& st, char* errmsg, int errmsg_len) {
  double angle = 0.0;
  int ok = b2b_params_get_real(p, "penalty", &st.penalty, nullptr, 0) == B2B_OK &&
           b2b_params_get_int(p, "law", &st.law, nullptr, 0) == B2B_OK &&
           b2b_params_get_real(p, "regularization_gap", &st.g0, nullptr, 0) == B2B_OK &&
           b2b_params_get_real(p, "parallel_angle", &angle, nullptr, 0) == B2B_OK &&
           b2b_params_get_int(p, "warm_start", &st.warm_start, nullptr, 0) == B2B_OK &&
           b2b_params_get_int(p, "max_iterations", &st.max_iterations, nullptr, 0) == B2B_OK &&
           b2b_params_get_real(p, "friction", &st.mu, nullptr, 0) == B2B_OK &&
           b2b_params_get_real(p, "tangential_penalty", &st.eps_t, nullptr, 0) == B2B_OK &&
           b2b_params_get_int(p, "tangent", &st.tangent, nullptr, 0) == B2B_OK &&
           b2b_params_history_size(p, &st.hist_len, nullptr, 0) == B2B_OK;
  if (!ok) return fail(errmsg, errmsg_len, B2B_ERR_STATE, "cannot read the parameter set");
  st.sin_parallel = std::sin(angle * 3.14159265358979323846 / 180.0);
  return B2B_OK;
}

int check_and_spec(const int* segments, const double* X, const double* end_tangents,
                   const double* radii, b2bad::SegmentSpec spec[2], char* errmsg,
                   int errmsg_len) {
  static const char* const beam[2] = {"A", "B"};
  for (int b = 0; b < 2; ++b) {
    const int kind = segments[3 * b], sr = segments[3 * b + 1], er = segments[3 * b + 2];
    double dirs[6] = {1, 0, 0, 1, 0, 0};
    const bool linear = kind == B2B_CURVE_LINEAR;
    for (int e = 0; e < 2; ++e) {
      const int rule = e ? er : sr;
      if (linear || rule != B2B_END_TANGENT) continue;
      if (!end_tangents)
        return fail(errmsg, errmsg_len, B2B_ERR_NULL, "beam %s: end_tangents is NULL",
                    beam[b]);
      const double* t = end_tangents + 6 * b + 3 * e;
      if (!(std::isfinite(t[0]) && std::isfinite(t[1]) && std::isfinite(t[2])))
        return fail(errmsg, errmsg_len, B2B_ERR_NONFINITE, "beam %s: end tangent %d not finite",
                    beam[b], e);
      const double len = std::hypot(t[0], t[1], t[2]);
      if (!(len > 0.0))
        return fail(errmsg, errmsg_len, B2B_ERR_RANGE, "beam %s: end tangent %d is zero",
                    beam[b], e);
      for (int i = 0; i < 3; ++i) dirs[3 * e + i] = t[i] / len;
    }
    const int st = b2bad::make_spec(kind, sr, er, dirs, spec[b]);
    if (st != B2B_OK)
      return fail(errmsg, errmsg_len, st, "beam %s: kind %d with rules %d, %d is not known here",
                  beam[b], kind, sr, er);
    for (int s = 0; s < 4; ++s)
      if (spec[b].used & (1u << s))
        for (int i = 0; i < 3; ++i)
          if (!std::isfinite(X[12 * b + 3 * s + i]))
            return fail(errmsg, errmsg_len, B2B_ERR_NONFINITE,
                        "beam %s: patch node x%d is not finite", beam[b], s + 1);
    if (!std::isfinite(radii[b]))
      return fail(errmsg, errmsg_len, B2B_ERR_NONFINITE, "beam %s: radius not finite", beam[b]);
  }
  return B2B_OK;
}

// The reference in the real type R (double, or long double as a more
// precise diagnostic): the residual from the R instantiation, the tangent
// and the energy gradient from Dual<24, R>.
template <class R>
int eval_in(const b2bad::Settings& st, const b2bad::SegmentSpec* spec, const double* X,
            const double* radii, const double* hist_old, double* hist_new, int hist_len,
            int flags, int* contact_status, double* info, double* residual, double* tangent,
            int ldk, double* energy_gradient, double* value_mismatch, const double* at,
            const int* held, char* errmsg, int errmsg_len) {
  using DR = b2bad::Dual<kNdof, R>;
  static thread_local b2bad::Result<R> rd;  // large: kept off the stack
  static thread_local b2bad::Result<DR> rr;
  if (int e = b2bad::evaluate(st, spec, X, radii, hist_old, flags, at, rd, held))
    return fail(errmsg, errmsg_len, e, "a patch has a zero element length or direction");
  const bool need_dual = (tangent && rd.active && st.tangent != B2B_TANGENT_MAIN) ||
                         energy_gradient || value_mismatch;
  if (need_dual) {
    if (int e = b2bad::evaluate(st, spec, X, radii, hist_old, flags, at, rr, held))
      return fail(errmsg, errmsg_len, e, "a patch has a zero element length or direction");
  }

  *contact_status = rd.status;
  std::memcpy(info, rd.info, sizeof rd.info);
  std::memcpy(hist_new, rd.hist, hist_len * sizeof(double));
  for (int r = 0; r < kNdof; ++r) residual[r] = static_cast<double>(rd.R[r]);
  if (energy_gradient)
    for (int a = 0; a < kNdof; ++a)
      energy_gradient[a] = static_cast<double>(rr.energy.d[a] / rr.scale);
  if (value_mismatch) {
    double m = 0.0;
    for (int r = 0; r < kNdof; ++r)
      m = std::fmax(m, static_cast<double>(std::fabs(rr.R[r].v - rd.R[r])));
    if (rr.status != rd.status) m = INFINITY;
    *value_mismatch = m;
  }
  if (!tangent) return B2B_OK;
  for (int c = 0; c < kNdof; ++c)
    for (int r = 0; r < kNdof; ++r) tangent[r + static_cast<size_t>(ldk) * c] = 0.0;
  if (!rd.active) return B2B_OK;
  if (st.tangent == B2B_TANGENT_MAIN) {
    for (int c = 0; c < kNdof; ++c)
      for (int r = 0; r < kNdof; ++r)
        tangent[r + static_cast<size_t>(ldk) * c] = -rd.slope * rd.G[r] * rd.G[c];
    info[B2B_INFO_SYMMETRIC] = 1.0;
    return B2B_OK;
  }
  for (int c = 0; c < kNdof; ++c)
    for (int r = 0; r < kNdof; ++r)
      tangent[r + static_cast<size_t>(ldk) * c] = static_cast<double>(rr.R[r].d[c] / rr.scale);
  if (st.tangent == B2B_TANGENT_SYMMETRIC && info[B2B_INFO_SYMMETRIC] == 0.0) {
    for (int c = 0; c < kNdof; ++c)
      for (int r = 0; r < c; ++r) {
        double& u = tangent[r + static_cast<size_t>(ldk) * c];
        double& l = tangent[c + static_cast<size_t>(ldk) * r];
        u = l = 0.5 * (u + l);
      }
    info[B2B_INFO_SYMMETRIC] = 1.0;
  }
  if (st.tangent == B2B_TANGENT_FD) info[B2B_INFO_SYMMETRIC] = 0.0;
  return B2B_OK;
}

int eval(const b2b_params* params, const int* segments, const double* X,
         const double* end_tangents, const double* radii, const double* hist_old,
         double* hist_new, int hist_len, int flags, int* contact_status, double* info,
         double* residual, double* tangent, int ldk, double* energy_gradient,
         double* value_mismatch, const double* at, const int* held, char* errmsg,
         int errmsg_len) {
  if (!params || !segments || !X || !radii || !hist_old || !hist_new || !contact_status ||
      !info || !residual)
    return fail(errmsg, errmsg_len, B2B_ERR_NULL, "a required argument is NULL");
  b2bad::Settings st;
  if (int e = read_settings(params, st, errmsg, errmsg_len)) return e;
  if (hist_len != st.hist_len)
    return fail(errmsg, errmsg_len, B2B_ERR_SIZE, "hist_len is %d, the parameter set needs %d",
                hist_len, st.hist_len);
  if (tangent && ldk < kNdof)
    return fail(errmsg, errmsg_len, B2B_ERR_SIZE, "ldk is %d, at least 24 needed", ldk);
  for (int i = 0; i < hist_len; ++i)
    if (!std::isfinite(hist_old[i]))
      return fail(errmsg, errmsg_len, B2B_ERR_NONFINITE, "hist_old[%d] is not finite", i);
  if (held)
    for (int b = 0; b < 2; ++b)
      if (held[b] < -1 || held[b] > 1)
        return fail(errmsg, errmsg_len, B2B_ERR_RANGE, "ends[%d] is %d", b, held[b]);
  b2bad::SegmentSpec spec[2];
  if (int e = check_and_spec(segments, X, end_tangents, radii, spec, errmsg, errmsg_len))
    return e;
  if (flags & b2bad::kLongDouble)
    return eval_in<long double>(st, spec, X, radii, hist_old, hist_new, hist_len, flags,
                                contact_status, info, residual, tangent, ldk, energy_gradient,
                                value_mismatch, at, held, errmsg, errmsg_len);
  return eval_in<double>(st, spec, X, radii, hist_old, hist_new, hist_len, flags,
                         contact_status, info, residual, tangent, ldk, energy_gradient,
                         value_mismatch, at, held, errmsg, errmsg_len);
}

// ------------------------------------------------------------- line contact

int read_line_settings(const b2b_params* p, const b2bad::Settings& st, b2bad::Settings& lst,
                       b2bad::LineSettings& ls, char* errmsg, int errmsg_len) {
  double la = 0.0, pa = 0.0;
  const int ok =
      b2b_params_get_int(p, "contact_type", &ls.type, nullptr, 0) == B2B_OK &&
      b2b_params_get_real(p, "line_penalty", &ls.line_penalty, nullptr, 0) == B2B_OK &&
      b2b_params_get_real(p, "line_tangential_penalty", &ls.line_eps_t, nullptr, 0) ==
          B2B_OK &&
      b2b_params_get_real(p, "line_angle", &la, nullptr, 0) == B2B_OK &&
      b2b_params_get_real(p, "point_angle", &pa, nullptr, 0) == B2B_OK;
  if (!ok) return fail(errmsg, errmsg_len, B2B_ERR_STATE, "cannot read the line options");
  const double deg = 3.14159265358979323846 / 180.0;
  ls.s1 = std::sin(la * deg) * std::sin(la * deg);
  ls.s2 = std::sin(pa * deg) * std::sin(pa * deg);
  lst = st;
  lst.penalty = ls.line_penalty;
  lst.eps_t = ls.line_eps_t;
  return B2B_OK;
}

template <class R>
int eval_line_in(const b2bad::Settings& st, const b2bad::Settings& lst,
                 const b2bad::LineSettings& ls, const b2bad::SegmentSpec* spec, const double* X,
                 const double* radii, int n, const double* hist_old, double* hist_new,
                 int hist_len, int flags, int* contact_status, double* line_info,
                 double* point_info, double* residual, double* tangent, int ldk,
                 double* energy_gradient, double* value_mismatch, char* errmsg,
                 int errmsg_len) {
  using DR = b2bad::Dual<kNdof, R>;
  static thread_local b2bad::LineResult<R> rd;  // large: kept off the stack
  static thread_local b2bad::LineResult<DR> rr;
  if (int e = b2bad::evaluate_line(st, lst, ls, spec, X, radii, n, hist_old, flags, rd))
    return fail(errmsg, errmsg_len, e, "a patch has a zero element length or direction");
  const bool need_dual = (tangent && rd.active && st.tangent != B2B_TANGENT_MAIN) ||
                         energy_gradient || value_mismatch;
  if (need_dual)
    if (int e = b2bad::evaluate_line(st, lst, ls, spec, X, radii, n, hist_old, flags, rr))
      return fail(errmsg, errmsg_len, e, "a patch has a zero element length or direction");
  *contact_status = rd.status;
  std::memcpy(line_info, rd.line_info, sizeof rd.line_info);
  if (point_info)
    std::memcpy(point_info, rd.point_info, sizeof(double) * B2B_PAIR_INFO_LEN * n);
  std::memcpy(hist_new, rd.hist, hist_len * sizeof(double));
  for (int r = 0; r < kNdof; ++r) residual[r] = static_cast<double>(rd.R[r]);
  if (energy_gradient)
    for (int a = 0; a < kNdof; ++a)
      energy_gradient[a] = static_cast<double>(rr.potential.d[a] / rr.scale);
  if (value_mismatch) {
    double m = 0.0;
    for (int r = 0; r < kNdof; ++r)
      m = std::fmax(m, static_cast<double>(std::fabs(rr.R[r].v - rd.R[r])));
    if (rr.status != rd.status) m = INFINITY;
    *value_mismatch = m;
  }
  if (!tangent) return B2B_OK;
  for (int c = 0; c < kNdof; ++c)
    for (int r = 0; r < kNdof; ++r) tangent[r + static_cast<size_t>(ldk) * c] = 0.0;
  if (!rd.active) return B2B_OK;
  if (st.tangent == B2B_TANGENT_MAIN) {
    for (int c = 0; c < kNdof; ++c)
      for (int r = 0; r < kNdof; ++r)
        tangent[r + static_cast<size_t>(ldk) * c] = rd.K_main[r + kNdof * c];
    line_info[B2B_LINE_INFO_SYMMETRIC] = 1.0;
    return B2B_OK;
  }
  for (int c = 0; c < kNdof; ++c)
    for (int r = 0; r < kNdof; ++r)
      tangent[r + static_cast<size_t>(ldk) * c] = static_cast<double>(rr.R[r].d[c] / rr.scale);
  if (st.tangent == B2B_TANGENT_SYMMETRIC && line_info[B2B_LINE_INFO_SYMMETRIC] == 0.0) {
    for (int c = 0; c < kNdof; ++c)
      for (int r = 0; r < c; ++r) {
        double& u = tangent[r + static_cast<size_t>(ldk) * c];
        double& l = tangent[c + static_cast<size_t>(ldk) * r];
        u = l = 0.5 * (u + l);
      }
    line_info[B2B_LINE_INFO_SYMMETRIC] = 1.0;
  }
  if (st.tangent == B2B_TANGENT_FD) line_info[B2B_LINE_INFO_SYMMETRIC] = 0.0;
  return B2B_OK;
}

int eval_line(const b2b_params* params, const int* segments, const double* X,
              const double* end_tangents, const double* radii, int n, const double* hist_old,
              double* hist_new, int hist_len, int flags, int* contact_status,
              double* line_info, double* point_info, double* residual, double* tangent,
              int ldk, double* energy_gradient, double* value_mismatch, char* errmsg,
              int errmsg_len) {
  if (!params || !segments || !X || !radii || !hist_old || !hist_new || !contact_status ||
      !line_info || !residual)
    return fail(errmsg, errmsg_len, B2B_ERR_NULL, "a required argument is NULL");
  b2bad::Settings st, lst;
  b2bad::LineSettings ls;
  if (int e = read_settings(params, st, errmsg, errmsg_len)) return e;
  if (int e = read_line_settings(params, st, lst, ls, errmsg, errmsg_len)) return e;
  if (n < 1 || n > b2bad::kLinePointsMax)
    return fail(errmsg, errmsg_len, B2B_ERR_RANGE, "n_points is %d, 1 .. %d allowed", n,
                b2bad::kLinePointsMax);
  if (hist_len != (n + 1) * st.hist_len)
    return fail(errmsg, errmsg_len, B2B_ERR_SIZE, "hist_len is %d, the parameter set needs %d",
                hist_len, (n + 1) * st.hist_len);
  if (tangent && ldk < kNdof)
    return fail(errmsg, errmsg_len, B2B_ERR_SIZE, "ldk is %d, at least 24 needed", ldk);
  for (int i = 0; i < hist_len; ++i)
    if (!std::isfinite(hist_old[i]))
      return fail(errmsg, errmsg_len, B2B_ERR_NONFINITE, "hist_old[%d] is not finite", i);
  b2bad::SegmentSpec spec[2];
  if (int e = check_and_spec(segments, X, end_tangents, radii, spec, errmsg, errmsg_len))
    return e;
  if (flags & b2bad::kLongDouble)
    return eval_line_in<long double>(st, lst, ls, spec, X, radii, n, hist_old, hist_new,
                                     hist_len, flags, contact_status, line_info, point_info,
                                     residual, tangent, ldk, energy_gradient, value_mismatch,
                                     errmsg, errmsg_len);
  return eval_line_in<double>(st, lst, ls, spec, X, radii, n, hist_old, hist_new, hist_len,
                              flags, contact_status, line_info, point_info, residual, tangent,
                              ldk, energy_gradient, value_mismatch, errmsg, errmsg_len);
}

}  // namespace

extern "C" {

int b2b_ad_pair_eval_line_ex(const b2b_params* params, const int segments[6],
                             const double X[24], const double end_tangents[12],
                             const double radii[2], int n_points, const double* hist_old,
                             double* hist_new, int hist_len, int flags, int* contact_status,
                             double line_info[16], double* point_info, double residual[24],
                             double* tangent, int ldk, double energy_gradient[24],
                             double* value_mismatch, char* errmsg, int errmsg_len) {
  try {
    return eval_line(params, segments, X, end_tangents, radii, n_points, hist_old, hist_new,
                     hist_len, flags, contact_status, line_info, point_info, residual, tangent,
                     ldk, energy_gradient, value_mismatch, errmsg, errmsg_len);
  } catch (const std::exception& e) {
    return fail(errmsg, errmsg_len, B2B_ERR_INTERNAL, "exception: %s", e.what());
  } catch (...) {
    return fail(errmsg, errmsg_len, B2B_ERR_INTERNAL, "unknown exception");
  }
}

int b2b_ad_pair_eval_line(const b2b_params* params, const int segments[6], const double X[24],
                          const double end_tangents[12], const double radii[2], int n_points,
                          const double* hist_old, double* hist_new, int hist_len,
                          int* contact_status, double line_info[16], double* point_info,
                          double residual[24], double* tangent, int ldk, char* errmsg,
                          int errmsg_len) {
  return b2b_ad_pair_eval_line_ex(params, segments, X, end_tangents, radii, n_points, hist_old,
                                  hist_new, hist_len, 0, contact_status, line_info, point_info,
                                  residual, tangent, ldk, nullptr, nullptr, errmsg, errmsg_len);
}


int b2b_ad_pair_eval_ex(const b2b_params* params, const int segments[6], const double X[24],
                        const double end_tangents[12], const double radii[2],
                        const double* hist_old, double* hist_new, int hist_len, int flags,
                        int* contact_status, double info[32], double residual[24],
                        double* tangent, int ldk, double energy_gradient[24],
                        double* value_mismatch, const double closest_points[2], char* errmsg,
                        int errmsg_len) {
  try {
    return eval(params, segments, X, end_tangents, radii, hist_old, hist_new, hist_len, flags,
                contact_status, info, residual, tangent, ldk, energy_gradient, value_mismatch,
                closest_points, nullptr, errmsg, errmsg_len);
  } catch (const std::exception& e) {
    return fail(errmsg, errmsg_len, B2B_ERR_INTERNAL, "exception: %s", e.what());
  } catch (...) {
    return fail(errmsg, errmsg_len, B2B_ERR_INTERNAL, "unknown exception");
  }
}

int b2b_ad_pair_eval(const b2b_params* params, const int segments[6], const double X[24],
                     const double end_tangents[12], const double radii[2],
                     const double* hist_old, double* hist_new, int hist_len,
                     int* contact_status, double info[32], double residual[24],
                     double* tangent, int ldk, char* errmsg, int errmsg_len) {
  return b2b_ad_pair_eval_ex(params, segments, X, end_tangents, radii, hist_old, hist_new,
                             hist_len, 0, contact_status, info, residual, tangent, ldk, nullptr,
                             nullptr, nullptr, errmsg, errmsg_len);
}

int b2b_ad_pair_eval_ends(const b2b_params* params, const int segments[6], const double X[24],
                          const double end_tangents[12], const double radii[2],
                          const int ends[2], const double* hist_old, double* hist_new,
                          int hist_len, int flags, int* contact_status, double info[32],
                          double residual[24], double* tangent, int ldk,
                          double energy_gradient[24], char* errmsg, int errmsg_len) {
  if (!ends) return fail(errmsg, errmsg_len, B2B_ERR_NULL, "ends is NULL");
  try {
    return eval(params, segments, X, end_tangents, radii, hist_old, hist_new, hist_len, flags,
                contact_status, info, residual, tangent, ldk, energy_gradient, nullptr, nullptr,
                ends, errmsg, errmsg_len);
  } catch (const std::exception& e) {
    return fail(errmsg, errmsg_len, B2B_ERR_INTERNAL, "exception: %s", e.what());
  } catch (...) {
    return fail(errmsg, errmsg_len, B2B_ERR_INTERNAL, "unknown exception");
  }
}

int b2b_ad_curve_kind_count(void) { return B2B_CURVE_HERMITE_NODAL_WEIGHTED + 1; }

}  // extern "C"
