c     crossed.f -- scene 1 of the legacy example: two crossed beams.
c
c     Two simply supported beams cross at 90 degrees at their midspans,
c     the upper (along x, length el1, radius r1) a gap g above the lower
c     (along y, el2, r2). A force P at the upper one's midspan, ramped
c     over four steps, closes the gap and presses it onto the lower one.
c     With the linear penalty law (f_N = pen * penetration) the two
c     midspan springs 48 EI/L^3 and the penalty act in series:
c       N = max(0, (P c1 - g) / (c1 + c2 + 1/pen)),  ci = eli^3/(48 E Ii)
c     and the midspans deflect w1 = (P - N) c1, w2 = N c2; the supports
c     of the lower beam carry N, those of the upper one P - N. The frame
c     element is exact at the nodes for nodal loads, and the contact
c     sits on the midspan nodes of both beams with a vertical normal (by
c     symmetry), so the model reproduces these up to Newton's tolerance
c     (1e-10 of the step's largest residual, about P): the check allows
c     1e-8 of P for the forces and of P c1 for the deflections; exactly
c     one contact once the gap is closed (none before), none crossed.
c     Exit code 0 if every step passes, 1 otherwise.
      program cross
      implicit double precision (a-h, o-z)
      include 'lgcom.h'
      common /cscn/ pld, c1, c2, pen, gap, errmax, mid1, mid2, nbad
      integer nod(mxnp)
      pi = 4.d0*atan(1.d0)
      emod = 1.d7
      gmod = emod/2.6d0
      el1 = 1.0d0
      el2 = 1.2d0
      r1 = 0.02d0
      r2 = 0.025d0
      pld = 2.d0
      gap = 0.5d0*r1
      pen = 1.d3
      ne = 8
c     mesh: beam 1 nodes 1 .. ne+1, beam 2 nodes ne+2 .. 2 ne+2
      numnp = 2*(ne + 1)
      numel = 2*ne
      do 20 k = 1, ne + 1
        s = dble(k - 1)/dble(ne) - 0.5d0
        x(1,k) = s*el1
        x(2,k) = 0.d0
        x(3,k) = r1 + r2 + gap
        x(1,ne+1+k) = 0.d0
        x(2,ne+1+k) = s*el2
        x(3,ne+1+k) = 0.d0
        do 10 i = 1, ndf
          kbc(i,k) = 0
          kbc(i,ne+1+k) = 0
          iprf(i,k) = 1
          iprf(i,ne+1+k) = 1
          f(i,k) = 0.d0
          f(i,ne+1+k) = 0.d0
          u(i,k) = 0.d0
          u(i,ne+1+k) = 0.d0
   10   continue
   20 continue
      do 30 ie = 1, ne
        ix(1,ie) = ie
        ix(2,ie) = ie + 1
        ix(1,ne+ie) = ne + 1 + ie
        ix(2,ne+ie) = ne + 2 + ie
        rad(ie) = r1
        rad(ne+ie) = r2
   30 continue
c     supports: pinned (u, v, w and the torsion) at the first node of
c     each beam, a roller (the two transverse displacements) at the last
      call setbc(1, 1, 1, 1, 1, 0, 0)
      call setbc(ne + 1, 0, 1, 1, 0, 0, 0)
      call setbc(ne + 2, 1, 1, 1, 0, 1, 0)
      call setbc(2*ne + 2, 1, 0, 1, 0, 0, 0)
      mid1 = ne/2 + 1
      mid2 = ne + 1 + ne/2 + 1
      f(3,mid1) = -pld
      c1 = el1**3/(48.d0*emod*pi*r1**4/4.d0)
      c2 = el2**3/(48.d0*emod*pi*r2**4/4.d0)
      call numeq
      call elprof
c     contact: linear law, no friction; the beams in groups 1 and 2
      call cbinit(0, pen, 0.d0, 0.d0, 0.d0)
      do 40 k = 1, ne + 1
        nod(k) = k
   40 continue
      call cbbeam(nod, ne + 1, r1, 1)
      do 50 k = 1, ne + 1
        nod(k) = ne + 1 + k
   50 continue
      call cbbeam(nod, ne + 1, r2, 2)
      call cbfin(1, 2, numnp)
c     steps: a quarter of the load each
      tend = 1.d0
      dt = 0.25d0
      dtmin = 1.d-3
      rtol = 1.d-10
      fref = pld
      maxit = 8
      iprt = 1
      nbad = 0
      errmax = 0.d0
      write (*, '(a)')
     &  ' crossed beams: N = (P c1 - g)/(c1 + c2 + 1/pen)'
      write (*, '(a,f6.3,a,f8.3,a,f8.3,a,f8.1,a,f7.4)') '   P =', pld,
     &  ', 1/c1 =', 1.d0/c1, ', 1/c2 =', 1.d0/c2, ', pen =', pen,
     &  ', g =', gap
      call solve
      call cbend
      write (*, '(a,i3,a,i3,a,i3,a,1pe9.2)') ' steps', nstep,
     &  ', Newton iterations', ntot, ', cut-backs', ncut,
     &  '; largest error/P', errmax
      if (nbad .gt. 0 .or. nstep .lt. 1) then
        write (*, '(a)') ' crossed beams: FAILED'
        stop 1
      endif
      write (*, '(a)') ' crossed beams: all checks passed'
      end
c
c     uchk: the checks of a converged step (called by solve)
      subroutine uchk(nit)
      implicit double precision (a-h, o-z)
      include 'lgcom.h'
      common /cscn/ pld, c1, c2, pen, gap, errmax, mid1, mid2, nbad
      double precision r(ndf,mxnp)
      p = pld*t
      fnx = max(0.d0, (p*c1 - gap)/(c1 + c2 + 1.d0/pen))
      nactx = 0
      if (fnx .gt. 0.d0) nactx = 1
      call cbstat(nact, nslip, nhop, nlost, ncrs, fn)
      call preac(r)
c     the lower beam's supports carry N, the upper one's P - N
      rlow = r(3,numnp/2 + 1) + r(3,numnp)
      rupp = r(3,1) + r(3,numnp/2)
      w1 = -u(3,mid1)
      w2 = -u(3,mid2)
      err = max(abs(fn - fnx), abs(rlow - fnx),
     &          abs(rupp - (p - fnx)))/pld
      err = max(err, abs(w1 - (p - fnx)*c1)/(pld*c1),
     &          abs(w2 - fnx*c2)/(pld*c1))
      errmax = max(errmax, err)
      write (*, '(a,i3,a,f6.3,a,i2,a,f9.6,a,f9.6,a,1pe8.1)') ' step',
     &  nstep, ' t =', t, ' (', nit, ' it): N =', fn,
     &  ', closed form', fnx, ', error/P', err
      write (*, '(a,f9.6,a,f9.6,a,f9.6,a,f9.6)') '   supports: lower',
     &  rlow, ', upper', rupp, '; w1 =', w1, ', w2 =', w2
      if (err .gt. 1.d-8 .or. nact .ne. nactx .or. ncrs .ne. 0) then
        write (*, '(a,i2,a,i2)') '   FAILED: active', nact,
     &    ', crossed', ncrs
        nbad = nbad + 1
      endif
      end
