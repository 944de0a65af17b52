c     slider.f -- scene 2 of the legacy example: large sliding.
c
c     A long beam (along x, nel elements of length h, radius r1) lies on
c     supports at every node (v and w fixed) and is anchored in x at
c     node 1; its axial and rotational dofs are free. A short beam, the
c     slider (one element along y, radius r2), is pressed onto it by a
c     dead load P (P/2 at each end node, its w free, its rotations
c     fixed) and pulled along it by a prescribed displacement of both
c     end nodes in x: 20 segments out (t = 0 .. 1) and back (t = 1 ..
c     2), across a joint of the long beam every h, with Coulomb friction
c     mu. The slider's x is prescribed: each step enters as the
c     right-hand-side correction -K(free, prescribed) dup. The first
c     step tries the whole way out at once: more segments than b2b
c     hands a contact on in one update ("max_handover_hops", 16), so
c     the contact is lost and the step control cuts the step back.
c     Closed form while slipping (the long beam's axis stays a straight
c     line on its supports, so the contact normal is vertical), with
c     s = +1 out, -1 back:
c       N = P (slider's equilibrium in z; b2b's sum of f_N)
c       R = s mu P (the pulling force: the reaction at the slider's x)
c       A = -s mu P (the anchor's reaction at node 1)
c     The check allows 1e-8 of P (Newton's tolerance is 1e-10 of the
c     step's largest residual, about P); at every converged step
c     exactly one contact, slipping, none lost (B2B_COUNT_LOST), none
c     crossed; the contact handed over at least once per joint passed.
c     Exit code 0 if every step passes, 1 otherwise.
      program slider
      implicit double precision (a-h, o-z)
      include 'lgcom.h'
      common /cscn/ pld, fmu, xs0, hel, errmax, nbad, nhops, ns1
      integer nod(mxnp)
      emod = 1.d7
      gmod = emod/2.6d0
      nel = 24
      hel = 0.5d0
      r1 = 0.05d0
      r2 = 0.05d0
      els = 1.d0
      pld = 1.d0
      fmu = 0.3d0
      pen = 1.d4
      g0 = 1.d-4
      pent = 1.d4
c     the slider starts over the middle of segment 3 and travels 20
c     segments out and back; it is placed at the gap where the quadratic law carries
c     P (f_N = pen (g0/2 - g) for g <= 0), so the start is in equilibrium
      xs0 = 2.5d0*hel
      trav = 20.d0*hel
      gap = 0.5d0*g0 - pld/pen
      numnp = nel + 3
      numel = nel + 1
      ns1 = nel + 2
      do 20 n = 1, numnp
        do 10 i = 1, ndf
          kbc(i,n) = 0
          iprf(i,n) = 0
          f(i,n) = 0.d0
          u(i,n) = 0.d0
   10   continue
   20 continue
      do 30 k = 1, nel + 1
        x(1,k) = dble(k - 1)*hel
        x(2,k) = 0.d0
        x(3,k) = 0.d0
        call setbc(k, 0, 1, 1, 0, 0, 0)
   30 continue
      call setbc(1, 1, 1, 1, 1, 0, 0)
      do 40 k = 1, nel
        ix(1,k) = k
        ix(2,k) = k + 1
        rad(k) = r1
   40 continue
      do 50 k = 0, 1
        n = ns1 + k
        x(1,n) = xs0
        x(2,n) = (dble(k) - 0.5d0)*els
        x(3,n) = r1 + r2 + gap
        call setbc(n, 1, 1, 0, 1, 1, 1)
        f(1,n) = trav
        iprf(1,n) = 2
        f(3,n) = -0.5d0*pld
   50 continue
      ix(1,numel) = ns1
      ix(2,numel) = ns1 + 1
      rad(numel) = r2
      call numeq
      call elprof
c     contact: quadratic law, Coulomb friction; groups 1 and 2
      call cbinit(1, pen, g0, fmu, pent)
      do 60 k = 1, nel + 1
        nod(k) = k
   60 continue
      call cbbeam(nod, nel + 1, r1, 1)
      nod(1) = ns1
      nod(2) = ns1 + 1
      call cbbeam(nod, 2, r2, 2)
      call cbfin(1, 2, numnp)
c     steps: the whole way out at once first
      tend = 2.d0
      dt = 1.d0
      dtmin = 1.d-3
      rtol = 1.d-10
      fref = pld
      maxit = 12
      iprt = 0
      nbad = 0
      nhops = 0
      errmax = 0.d0
      write (*, '(a)') ' slider: N = P, R = s mu P, A = -s mu P'
      write (*, '(a,f5.2,a,f5.2,a,f6.2,a,i3,a)') '   P =', pld,
     &  ', mu =', fmu, ', travel', trav, ' (', nint(trav/hel),
     &  ' segments) out and back'
      call solve
      call cbend
      njnt = 2*(int((xs0 + trav)/hel) - int(xs0/hel))
      write (*, '(a,i3,a,i4,a,i3,a,1pe9.2)') ' steps', nstep,
     &  ', Newton iterations', ntot, ', cut-backs', ncut,
     &  '; largest error / P', errmax
      write (*, '(a,i3,a,i3,a)') ' the contact was handed over',
     &  nhops, ' times, across', njnt, ' joints'
      if (nbad .gt. 0 .or. nhops .lt. njnt .or. nstep .lt. 1) then
        write (*, '(a)') ' slider: FAILED'
        stop 1
      endif
      write (*, '(a)') ' slider: all checks passed'
      end
c
c     uchk: the checks of a converged step (called by solve)
      subroutine uchk(nit)
      implicit double precision (a-h, o-z)
      include 'lgcom.h'
      common /cscn/ pld, fmu, xs0, hel, errmax, nbad, nhops, ns1
      double precision r(ndf,mxnp)
      call cbstat(nact, nslip, nhop, nlost, ncrs, fn)
      call preac(r)
      nhops = nhops + nhop
      xs = xs0 + u(1,ns1)
      rpull = r(1,ns1) + r(1,ns1+1)
      ranch = r(1,1)
      sg = 1.d0
      if (t .gt. 1.d0) sg = -1.d0
      err = max(abs(fn - pld), abs(rpull - sg*fmu*pld),
     &          abs(ranch + sg*fmu*pld))/pld
      errmax = max(errmax, err)
      write (*, '(a,i3,a,f6.3,a,i2,a,f6.3,a,i2,a,f9.6,a,f9.6,a,f9.6)')
     &  ' step', nstep, ' t =', t, ' (', nit, ' it): x =', xs,
     &  ' seg', int(xs/hel) + 1, ': N =', fn, ', R =', rpull,
     &  ', A =', ranch
      if (err .gt. 1.d-8 .or. nact .ne. 1 .or. nslip .ne. 1 .or.
     &    nlost .ne. 0 .or. ncrs .ne. 0) then
        write (*, '(a,1pe9.2,a,i2,a,i2,a,i2,a,i2)') '   FAILED: error',
     &    err, ', active', nact, ', slipping', nslip, ', lost', nlost,
     &    ', crossed', ncrs
        nbad = nbad + 1
      endif
      end
