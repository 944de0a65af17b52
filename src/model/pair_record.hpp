// What the contact model's update keeps of one evaluated pair beyond its
// status (update.cpp). Of the pairs a bundle evaluates, more than 99% carry
// no force (PARALLEL, OUTSIDE, OPEN): keeping the element's whole output for
// each (info, residual, history: ~550 bytes) made the update's memory grow
// with the pairs looked at, not with the contacts. A record holds only what
// a later stage of the update reads, in doubles:
//   ACTIVE,  the gap and the new history (the trial state keeps it: the
//   OPEN     normal's sign is tracked), then, for a pair that the crossing
//            check reads (crossing.hpp: no committed history, and it moved
//            far enough since the commit), the difference of its closest
//            points (A - B); an active contact's outputs (info, residual,
//            tangent) go straight to the model's next set (contact_result.hpp)
//   OUTSIDE  of a pair with a committed history: xi, eta (where the
//            handover of its committed contact starts)
//   others   no record
// The gap and the difference are read by the crossing check and the
// smallest gap; they are copied from the info, so every output made from a
// record is bit for bit the element's. (The difference is kept only where
// it is read: 24 bytes of every open pair, 7 a segment on a bundle.)
#pragma once

#include <cstddef>

#include "../pair/contact_element.hpp"

namespace b2b {
namespace model {

enum RecordSlot : int {
  kRecGap = 0,      // ACTIVE, OPEN
  kRecHistory = 1,  // the new history (hist_len), then (with_diff) POINT_A - POINT_B
  kRecXi = 0,       // OUTSIDE
  kRecEta = 1
};

// Doubles of the record of a pair of this status (0: none); committed: it
// was evaluated with a committed history; hist_len: of its new history;
// with_diff: the difference of the closest points is kept.
size_t record_length(int status, bool committed, int hist_len, bool with_diff);

// Writes the record of res (record_length doubles) to rec; hist: the new
// history (res.history, or a line pair's histories).
void write_record(const pair::PairResult& res, bool committed, const double* hist, int hist_len,
                  bool with_diff, double* rec);

// The difference of the closest points of a record written with_diff.
inline const double* record_diff(const double* rec, int hist_len) {
  return rec + kRecHistory + hist_len;
}

}  // namespace model
}  // namespace b2b
