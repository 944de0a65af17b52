// Layout of the per-pair history (host-owned doubles). Private: hosts only
// know its length (b2b_params_history_size), so it may grow in later
// versions. A zero-filled array is a fresh history. A frictionless parameter
// set keeps the first kHistoryLength entries; with friction the friction
// slots follow.
#pragma once

#include "params.hpp"

namespace b2b {
namespace pair {

enum HistorySlot {
  kHistTag = 0,        // 0: fresh (never written), 1: written by this layout
  kHistHasNormal = 1,  // 1 if kHistNormal holds the last normal
  kHistNormal = 2,     // 3 entries: unit normal from B to A (sign-tracked)
  kHistXi = 5,         // closest-point parameters of the last evaluation
  kHistEta = 6,
  kHistReserved = 7,
  kHistoryLength = 8,
  // friction (Params::friction > 0)
  kHistInContact = 8,      // 1 if the pair was active: xi, eta are the slip anchors
  kHistForceE1 = 9,        // committed tangential force in the frame e1, e2
  kHistForceE2 = 10,       //   (e1 = unit x_A,xi, e2 = n x e1)
  kHistFrictionState = 11, // B2B_FRICTION_* of the committed step
  kHistoryLengthFriction = 12,
  kHistoryLengthMax = 12
};

inline int history_length(const Params& p) {
  return p.friction > 0.0 ? kHistoryLengthFriction : kHistoryLength;
}

// The closest-point parameters a history may hold: b2b writes |xi|, |eta| <= 3
// (the search's box) and a handover maps them by the ratio of two segments'
// speeds; beyond this bound a history was not written by b2b.
constexpr double kHistParamMax = 1e3;

constexpr double kHistTagFresh = 0.0;
constexpr double kHistTagV1 = 1.0;

}  // namespace pair
}  // namespace b2b
