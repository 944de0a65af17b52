// The contacts' coupling pattern in the host's equations, for a host that
// sizes its own sparse structure (a profile / skyline, a band) before it
// assembles, and the assembly into FEAP's profile storage. Contact couples
// dofs that no element of the host connects, also across beams, and the
// pattern changes from update to update as contacts open and close.
#pragma once

#include "contact_dofs.hpp"
#include "model.hpp"

namespace b2b {
namespace model {

// The pattern of the contacts' tangent, as a profile and as a band:
// heights[j] = j - (the smallest equation i <= j with K(i, j) or K(j, i)
// coupled), 0 where no contact couples column j to an earlier equation
// (FEAP's column heights, the input of its pointer sums); *kl, *ku: the
// largest r - c and c - r of a coupled entry (r, c), 0 without contacts.
// Any output may be nullptr. The pattern holds every pair of unconstrained
// dofs of a contact, zero values too, as tangent_coo lists them.
void tangent_profile(const Model& m, const EqMap& map, int* heights, int* kl, int* ku);

// FEAP's profile storage with its pointer array jp (0-based here: equation
// j's pointer is jp[j]; the values are FEAP's, jp[0] = 0 and jp[j] the sum
// of the column heights of equations 0 .. j). The first problem, if any:
// jp not a pointer array (ProfilePointer: jp[0] != 0, a height < 0 or > j),
// else an entry of a contact outside the profile (Profile: row, col with
// the host's eq base added).
Problem check_profile(const Model& m, const EqMap& map, const int* jp);

// Adds scale * K: K(j, j) to ad[j]; K(i, j), i < j, to au[jp[j] - j + i]
// (column j of the upper triangle, rows top down, its last entry the one
// above the diagonal); K(j, i), i < j, to al[jp[j] - j + i] (row j of the
// lower triangle, in the same place as its transpose in au) unless al is
// nullptr. check_profile must have passed.
void add_tangent_profile(const Model& m, const EqMap& map, double scale, const int* jp,
                         double* ad, double* au, double* al);

}  // namespace model
}  // namespace b2b
