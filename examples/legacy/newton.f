c     newton.f -- the solution procedure of the legacy code: step
c     control with cut-back, Newton's iterations of a step, the
c     assembly of F_ext - F_int and its tangent, prescribed
c     displacements by right-hand-side correction, and reactions.
c     Contact enters only through the glue's subroutines cb*
c     (b2b_glue.f90): cbupd, cbprof, cbasm, cbcpr, cbstat, cbaud, cbcmt,
c     cbrvt and cbreac.
c
c     prop: proportional function k at pseudo-time tt
c       k = 0: 1 (a dead load), k = 1: tt (a ramp),
c       k = 2: tt up to 1, then 2 - tt (out and back)
      double precision function prop(k, tt)
      integer k
      double precision tt
      if (k .eq. 0) then
        prop = 1.d0
      else if (k .eq. 1 .or. tt .le. 1.d0) then
        prop = tt
      else
        prop = 2.d0 - tt
      endif
      end
c
c     solve: steps from t = 0 to tend. A step whose Newton fails, or
c     whose converged update has crossed contacts (beams passed through
c     each other), lost contacts (committed ones not found again: they
c     slid further than b2b hands a contact on in one step) or overlaps
c     the audit finds, is reverted in b2b, u goes back to un, and the
c     step is halved and tried again.
c     Converged: b2b commits, and the scene's uchk checks the step.
      subroutine solve
      implicit double precision (a-h, o-z)
      include 'lgcom.h'
      logical conv
      t = 0.d0
      nstep = 0
      ncut = 0
      ntot = 0
c     the initial configuration is committed first, so that the first
c     step has a configuration to check crossings against
      call cbupd(x, u, ndm, ndf, numnp, ierr)
      if (ierr .ne. 0) stop 'solve: initial update failed'
      call cbcmt
   10 if (t .ge. tend*(1.d0 - 1.d-12)) return
      t1 = min(t + dt, tend)
      do 30 n = 1, numnp
        do 20 i = 1, ndf
          un(i,n) = u(i,n)
   20   continue
   30 continue
      call newtn(t1, conv, nit)
      if (conv) then
        call cbstat(nact, nslip, nhop, nlost, ncrs, fn)
        if (ncrs .gt. 0) then
          write (*, '(a,i3,a)') '   crossed contacts:', ncrs,
     &      ' (beams passed through each other)'
          conv = .false.
        endif
        if (nlost .gt. 0) then
          write (*, '(a,i3,a)') '   lost contacts:', nlost,
     &      ' (not found again: a step too large)'
          conv = .false.
        endif
      endif
      if (conv) then
        call cbaud(nfnd)
        if (nfnd .gt. 0) then
          write (*, '(a,i3,a)') '   audit:', nfnd,
     &      ' overlapping pairs without force'
          conv = .false.
        endif
      endif
      if (.not. conv) then
        call cbrvt
        do 50 n = 1, numnp
          do 40 i = 1, ndf
            u(i,n) = un(i,n)
   40     continue
   50   continue
        dt = 0.5d0*dt
        ncut = ncut + 1
        write (*, '(a,f10.6,a,1pe10.3)') '   cut back at t =', t,
     &    ': dt =', dt
        if (dt .lt. dtmin) stop 'solve: step below dtmin'
        goto 10
      endif
      call cbcmt
      t = t1
      nstep = nstep + 1
      ntot = ntot + nit
      call uchk(nit)
      goto 10
      end
c
c     newtn: Newton's iterations from the last converged state to t1.
c     Iteration 1 is linearized about that state: the prescribed dofs
c     still hold their old values, and their increments dup enter as
c     the right-hand-side correction -K(free, prescribed) dup (frame
c     elements in pform, contact by cbcpr); after its solve u takes
c     both the free increments and dup. conv: converged, with nit
c     iterations (solves). A failed update, a zero pivot, a residual
c     that is not finite or maxit iterations: not converged.
      subroutine newtn(t1, conv, nit)
      implicit double precision (a-h, o-z)
      include 'lgcom.h'
      logical conv
      conv = .false.
      nit = 0
      do 20 n = 1, numnp
        do 10 i = 1, ndf
          dup(i,n) = 0.d0
          if (id(i,n) .eq. 0) dup(i,n) = f(i,n)*
     &      (prop(iprf(i,n), t1) - prop(iprf(i,n), t))
   10   continue
   20 continue
      rmax = fref
      do 100 it = 1, maxit + 1
        call cbupd(x, u, ndm, ndf, numnp, ierr)
        if (ierr .ne. 0) return
        call cbprof(id, ndf, numnp, neq, ihc)
        call pprof
        call pform(it, t1)
        rn = 0.d0
        do 30 j = 1, neq
          rn = rn + b(j)**2
   30   continue
        rn = sqrt(rn)
        if (.not. (rn .le. 1.d300)) return
        rmax = max(rmax, rn)
        if (iprt .ne. 0) write (*, '(a,i3,a,1pe10.3)') '     it', it,
     &    '  |F_ext - F_int| =', rn
        if (it .gt. 1 .and. rn .le. rtol*rmax) then
          conv = .true.
          return
        endif
        if (it .gt. maxit) return
        call dfact(ierr)
        if (ierr .ne. 0) return
        call dsolve
        nit = it
        do 50 n = 1, numnp
          do 40 i = 1, ndf
            if (id(i,n) .gt. 0) then
              u(i,n) = u(i,n) + b(id(i,n))
            else if (it .eq. 1) then
              u(i,n) = u(i,n) + dup(i,n)
            endif
   40     continue
   50   continue
  100 continue
      end
c
c     pform: b = F_ext(t1) - F_int(u), its tangent in ad, au, al; in
c     iteration 1 also b = b - K(free, prescribed) dup
      subroutine pform(it, t1)
      implicit double precision (a-h, o-z)
      include 'lgcom.h'
      double precision xl(3,2), ul(12), dul(12), s(12,12), p(12)
      integer ld(12)
      do 10 j = 1, neq
        ad(j) = 0.d0
        b(j) = 0.d0
   10 continue
      do 20 j = 1, jp(neq)
        au(j) = 0.d0
        al(j) = 0.d0
   20 continue
      do 40 n = 1, numnp
        do 30 i = 1, ndf
          if (id(i,n) .gt. 0) b(id(i,n)) = b(id(i,n))
     &      + f(i,n)*prop(iprf(i,n), t1)
   30   continue
   40 continue
      do 90 ie = 1, numel
        call elget(ie, xl, ul, dul, ld)
        call frmstf(xl, rad(ie), s)
        do 60 ka = 1, 12
          p(ka) = 0.d0
          do 50 kb = 1, 12
            p(ka) = p(ka) + s(ka,kb)*ul(kb)
            if (it .eq. 1 .and. ld(ka) .gt. 0 .and. ld(kb) .eq. 0)
     &        b(ld(ka)) = b(ld(ka)) - s(ka,kb)*dul(kb)
   50     continue
   60   continue
        call passem(s, p, ld)
   90 continue
c     contact: -(its residual) into b, its tangent into the profile,
c     and in iteration 1 its share of -K(free, prescribed) dup
      call cbasm(id, ndf, numnp, neq, jp, ad, au, al, b)
      if (it .eq. 1) call cbcpr(id, ndf, numnp, neq, dup, b)
      end
c
c     elget: element ie's coordinates, displacements, prescribed
c     increments and equation numbers
      subroutine elget(ie, xl, ul, dul, ld)
      include 'lgcom.h'
      integer ie, ld(12), i, k, n
      double precision xl(3,2), ul(12), dul(12)
      call eleq(ie, ld)
      do 20 k = 1, 2
        n = ix(k,ie)
        do 10 i = 1, ndf
          if (i .le. ndm) xl(i,k) = x(i,n)
          ul(ndf*(k-1) + i) = u(i,n)
          dul(ndf*(k-1) + i) = dup(i,n)
   10   continue
   20 continue
      end
c
c     preac: r = F_int - F_ext at every dof of every node (frame
c     elements, contact by cbreac, loads of time t): at a constrained
c     dof the reaction, at a free one the residual (about 0)
      subroutine preac(r)
      implicit double precision (a-h, o-z)
      include 'lgcom.h'
      double precision r(ndf,numnp)
      double precision xl(3,2), ul(12), dul(12), s(12,12)
      integer ld(12)
      do 20 n = 1, numnp
        do 10 i = 1, ndf
          r(i,n) = 0.d0
          if (id(i,n) .gt. 0) r(i,n) = -f(i,n)*prop(iprf(i,n), t)
   10   continue
   20 continue
      do 50 ie = 1, numel
        call elget(ie, xl, ul, dul, ld)
        call frmstf(xl, rad(ie), s)
        do 40 k = 1, 2
          n = ix(k,ie)
          do 35 i = 1, ndf
            ka = ndf*(k - 1) + i
            do 30 kb = 1, 12
              r(i,n) = r(i,n) + s(ka,kb)*ul(kb)
   30       continue
   35     continue
   40   continue
   50 continue
      call cbreac(ndf, numnp, r)
      end
