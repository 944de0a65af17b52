// Layout of the per-pair history (host-owned doubles). Private: hosts only
// know its length (b2b_params_history_size), so it may grow in later
// versions. A zero-filled array is a fresh history.
#pragma once

namespace b2b {
namespace pair {

enum HistorySlot {
  kHistTag = 0,        // 0: fresh (never written), 1: written by this layout
  kHistHasNormal = 1,  // 1 if kHistNormal holds the last normal
  kHistNormal = 2,     // 3 entries: unit normal from B to A (sign-tracked)
  kHistXi = 5,         // closest-point parameters of the last evaluation
  kHistEta = 6,
  kHistReserved = 7,
  kHistoryLength = 8
};

constexpr double kHistTagFresh = 0.0;
constexpr double kHistTagV1 = 1.0;

}  // namespace pair
}  // namespace b2b
