#include "pair_record.hpp"

#include <cstring>

#include <b2b/b2b.h>

namespace b2b {
namespace model {

size_t record_length(int status, bool committed, int hist_len, bool with_diff) {
  switch (status) {
    case B2B_CONTACT_ACTIVE:
    case B2B_CONTACT_OPEN: return kRecHistory + hist_len + (with_diff ? 3 : 0);
    case B2B_CONTACT_OUTSIDE: return committed ? 2 : 0;
    default: return 0;
  }
}

void write_record(const pair::PairResult& res, bool committed, const double* hist, int hist_len,
                  bool with_diff, double* rec) {
  const int st = res.contact_status;
  if (st == B2B_CONTACT_OUTSIDE) {
    if (committed) {
      rec[kRecXi] = res.info[B2B_INFO_XI];
      rec[kRecEta] = res.info[B2B_INFO_ETA];
    }
    return;
  }
  if (st != B2B_CONTACT_ACTIVE && st != B2B_CONTACT_OPEN) return;
  rec[kRecGap] = res.info[B2B_INFO_GAP];
  std::memcpy(rec + kRecHistory, hist, sizeof(double) * hist_len);
  if (!with_diff) return;
  double* d = rec + kRecHistory + hist_len;
  for (int i = 0; i < 3; ++i) d[i] = res.info[B2B_INFO_POINT_A + i] - res.info[B2B_INFO_POINT_B + i];
}

}  // namespace model
}  // namespace b2b
