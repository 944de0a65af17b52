c     lgcom.h -- the common blocks of the legacy frame code (included
c     by every routine; FORTRAN 77 with the INCLUDE line every compiler
c     of that era accepted). Fixed sizes: F77 has no ALLOCATE, so the
c     profile lives in a pool of mxa words and "re-sizing" it is
c     re-pointing jp inside that pool (see pprof in profil.f).
c
c     mxnp, mxel, mxeq  most nodes, elements, equations
c     mxa               words for au and for al (the profile pool)
c     ndm = 3, ndf = 6  coordinates per node, dofs per node
c                       (u, v, w, then the rotations about x, y, z)
      integer mxnp, mxel, mxeq, mxa, ndm, ndf
      parameter (mxnp = 64, mxel = 64, mxeq = 6*64, mxa = 40000)
      parameter (ndm = 3, ndf = 6)
c
c     /cdim/   numnp nodes, numel elements, neq equations
c     /cmesh/  ix(1:2,e) the nodes of element e, id(i,n) the equation
c              of dof i of node n (0: constrained), kbc(i,n) 1 where
c              dof i of node n is constrained (the input), iprf(i,n)
c              the proportional function of its load or motion
      integer numnp, numel, neq
      common /cdim/ numnp, numel, neq
      integer ix, id, kbc, iprf
      common /cmesh/ ix(2,mxel), id(ndf,mxnp), kbc(ndf,mxnp),
     &               iprf(ndf,mxnp)
c
c     /cxu/    x reference coordinates, u displacements (kept apart:
c              the current position is x + u), un u at the last
c              converged step, dup the prescribed increments of the
c              step on the constrained dofs, f the load pattern: a
c              force on a free dof, a displacement on a constrained one
      double precision x, u, un, dup, f
      common /cxu/ x(ndm,mxnp), u(ndf,mxnp), un(ndf,mxnp),
     &             dup(ndf,mxnp), f(ndf,mxnp)
c
c     /cmat/   emod, gmod Young's and shear moduli, rad(e) the radius
c              of element e's solid circular section
      double precision emod, gmod, rad
      common /cmat/ emod, gmod, rad(mxel)
c
c     /cprof/  the profile (skyline) system, FEAP's layout: jp(j) the
c              pointer of column j (jp(1) = 0, jp(j) = jp(j-1) + its
c              height), ihe the heights of the frame elements alone,
c              ih the heights in use (elements and contact, grown only),
c              ad the diagonal, au the upper triangle by columns, al the
c              lower by rows, b the right-hand side F_ext - F_int
      integer jp, ihe, ih, ihc
      common /cprof/ jp(mxeq), ihe(mxeq), ih(mxeq), ihc(mxeq)
      double precision ad, au, al, b
      common /cprfa/ ad(mxeq), au(mxa), al(mxa), b(mxeq)
c
c     /cstep/  t pseudo-time of the last converged step, tend the end,
c              dt the step, dtmin the smallest before giving up, rtol
c              the Newton tolerance relative to fref (a force of the
c              scene) or the step's largest residual, maxit iterations,
c              ncut cut-backs so far, nstep steps converged, ntot
c              Newton iterations, iprt 1: print every iteration
      double precision t, tend, dt, dtmin, rtol, fref
      integer maxit, ncut, nstep, ntot, iprt
      common /cstep/ t, tend, dt, dtmin, rtol, fref, maxit, ncut,
     &               nstep, ntot, iprt
