// The interpenetration audit (b2b_model_audit): for the configuration of the
// model's last update, every pair of segments that may touch (a group pair,
// no shared host node, self-contact only where it is on) whose surfaces
// overlap by more than tolerance * min(r_A, r_B) and that carries no force,
// with the reason why (B2B_AUDIT_*). Detection is independent of the update:
// its own search (audit_grid.hpp) on boxes grown by the radius and its own
// distances (segment_distance.hpp). Only to name the reason, and to know
// which pairs carry force, does it read what the update recorded (its
// contacts and its candidate list). doc/audit.md gives the guarantees.
#pragma once

#include <vector>

#include "model.hpp"

namespace b2b {
namespace model {

struct AuditFinding {
  int a, b;        // segments, a < b
  double overlap;  // r_A + r_B - centreline distance
  int reason;      // B2B_AUDIT_*
};

// The findings in the order of (a, b). The model must have results (an
// update since finalize, revert or restore); tolerance >= 0 (checked by the
// caller).
std::vector<AuditFinding> audit(const Model& m, double tolerance);

}  // namespace model
}  // namespace b2b
