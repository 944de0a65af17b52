/* The MPI example host's own elements on translational dofs (no b2b here):
 * an axial spring per segment, a bending term per interior node, anchor
 * springs per node. Each returns its energy and adds its exact gradient and
 * Hessian (either may be NULL). Checked by beam_element_fd.c. */
#ifndef MPI_BEAM_ELEMENT_H
#define MPI_BEAM_ELEMENT_H

/* Axial spring between nodes a and b of rest length L0 and axial stiffness
 * EA: E = EA / (2 L0) (l - L0)^2, l = |x_b - x_a|. Geometrically exact.
 * g[6] = dE/d(x_a, x_b), H[36] (row-major 6 x 6). */
double axial_element(const double xa[3], const double xb[3], double L0, double EA, double g[6],
                     double H[36]);

/* Bending at the interior node 1 of the chain 0 - 1 - 2: E = kb (1 - t1.t2),
 * t1 and t2 the unit vectors of the two edges (about kb theta^2 / 2 for the
 * turning angle theta; exact in theta, invariant under rigid motions).
 * g[9] = dE/d(x0, x1, x2), H[81] (row-major 9 x 9). */
double bending_element(const double x0[3], const double x1[3], const double x2[3], double kb,
                       double g[9], double H[81]);

#endif
