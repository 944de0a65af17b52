c     profil.f -- equation numbers, the profile (skyline) structure and
c     its non-symmetric solver, in FEAP's storage:
c       ad(j)                    K(j,j)
c       au(jp(j) - j + i + 1)    K(i,j), i < j: column j above the
c                                diagonal, rows j - ih(j) .. j - 1
c       al(jp(j) - j + i + 1)    K(j,i), i < j: row j left of it
c     with jp(1) = 0, jp(j) = jp(j-1) + ih(j), ih(j) the column height.
c     Friction makes the contact tangent non-symmetric, so al is its own
c     array and the factorization is Crout's K = L D U (L, U unit
c     triangular, L in al, D in ad, U in au).
c
c     numeq: id(i,n) from the boundary codes kbc, node by node
      subroutine numeq
      include 'lgcom.h'
      integer i, n
      neq = 0
      do 20 n = 1, numnp
        do 10 i = 1, ndf
          if (kbc(i,n) .eq. 0) then
            neq = neq + 1
            id(i,n) = neq
          else
            id(i,n) = 0
          endif
   10   continue
   20 continue
      if (neq .gt. mxeq) stop 'numeq: more equations than mxeq'
      end
c
c     setbc: the boundary codes of node n (1: constrained)
      subroutine setbc(n, k1, k2, k3, k4, k5, k6)
      include 'lgcom.h'
      integer n, k1, k2, k3, k4, k5, k6
      kbc(1,n) = k1
      kbc(2,n) = k2
      kbc(3,n) = k3
      kbc(4,n) = k4
      kbc(5,n) = k5
      kbc(6,n) = k6
      end
c
c     elprof: the column heights of the frame elements (ihe), the
c     heights in use start as these, and the pointers jp
      subroutine elprof
      include 'lgcom.h'
      integer ld(12), j, k, ie, mn
      do 10 j = 1, neq
        ihe(j) = 0
   10 continue
      do 40 ie = 1, numel
        call eleq(ie, ld)
        mn = neq + 1
        do 20 k = 1, 12
          if (ld(k) .gt. 0) mn = min(mn, ld(k))
   20   continue
        do 30 k = 1, 12
          j = ld(k)
          if (j .gt. 0) ihe(j) = max(ihe(j), j - mn)
   30   continue
   40 continue
      do 50 j = 1, neq
        ih(j) = ihe(j)
   50 continue
      call setjp
      write (*, '(a,i6,a,i4,a)') ' profile of the frame elements:',
     &  jp(neq), ' terms above the diagonal,', neq, ' equations'
      end
c
c     pprof: merge the contact's column heights ihc (from b2b, after the
c     update) into ih. The profile only grows, so that re-pointing is
c     rare: when a column grew, jp is recomputed and the pool checked.
      subroutine pprof
      include 'lgcom.h'
      integer j, nold, ngrow
      nold = jp(neq)
      ngrow = 0
      do 10 j = 1, neq
        if (ihc(j) .gt. ih(j)) then
          ih(j) = ihc(j)
          ngrow = ngrow + 1
        endif
   10 continue
      if (ngrow .gt. 0) then
        call setjp
        write (*, '(a,i6,a,i6,a,i4,a)') '   profile grew with contact:',
     &    nold, ' ->', jp(neq), ' terms (', ngrow, ' columns)'
      endif
      end
c
c     setjp: pointers from the heights; the pool holds mxa words
      subroutine setjp
      include 'lgcom.h'
      integer j
      jp(1) = 0
      do 10 j = 2, neq
        jp(j) = jp(j-1) + ih(j)
   10 continue
      if (jp(neq) .gt. mxa) stop 'setjp: profile larger than mxa'
      end
c
c     eleq: the 12 equation numbers of element ie (0: constrained)
      subroutine eleq(ie, ld)
      include 'lgcom.h'
      integer ie, ld(12), i, k
      do 20 k = 1, 2
        do 10 i = 1, ndf
          ld(ndf*(k-1) + i) = id(i, ix(k,ie))
   10   continue
   20 continue
      end
c
c     passem: the element matrix s into ad, au, al and -p into b
      subroutine passem(s, p, ld)
      include 'lgcom.h'
      double precision s(12,12), p(12)
      integer ld(12), ka, kb, ir, ic
      do 20 ka = 1, 12
        ir = ld(ka)
        if (ir .le. 0) goto 20
        b(ir) = b(ir) - p(ka)
        do 10 kb = 1, 12
          ic = ld(kb)
          if (ic .le. 0) goto 10
          if (ir .eq. ic) then
            ad(ir) = ad(ir) + s(ka,kb)
          else if (ir .lt. ic) then
            au(jp(ic) - ic + ir + 1) = au(jp(ic) - ic + ir + 1)
     &                                 + s(ka,kb)
          else
            al(jp(ir) - ir + ic + 1) = al(jp(ir) - ir + ic + 1)
     &                                 + s(ka,kb)
          endif
   10   continue
   20 continue
      end
c
c     dfact: K = L D U in place (Crout, column by column). For column
c     j, rows i = j - ih(j) .. j - 1 of U and columns of L are reduced
c     by the dot products over the overlap of the two profiles, then
c     divided by the pivots. ierr = 1 for a pivot below 1e-12 of the
c     diagonal it came from (a singular system: the step is cut back).
      subroutine dfact(ierr)
      implicit double precision (a-h, o-z)
      include 'lgcom.h'
      ierr = 0
      do 50 j = 1, neq
        i0 = j - ih(j)
        ja = jp(j) - j + 1
        do 30 i = i0, j - 1
          ia = jp(i) - i + 1
          k0 = max(i0, i - ih(i))
          su = 0.d0
          sl = 0.d0
          do 20 k = k0, i - 1
            su = su + al(ia+k)*au(ja+k)
            sl = sl + al(ja+k)*au(ia+k)
   20     continue
          au(ja+i) = au(ja+i) - su
          al(ja+i) = al(ja+i) - sl
   30   continue
        dj = ad(j)
        do 40 i = i0, j - 1
          xut = au(ja+i)
          xlt = al(ja+i)
          au(ja+i) = xut/ad(i)
          al(ja+i) = xlt/ad(i)
          dj = dj - xlt*au(ja+i)
   40   continue
        if (abs(dj) .le. 1.d-12*abs(ad(j))) then
          write (*, '(a,i5)') '   dfact: zero pivot in equation', j
          ierr = 1
          return
        endif
        ad(j) = dj
   50 continue
      end
c
c     dsolve: b := K^-1 b with the factors of dfact
      subroutine dsolve
      implicit double precision (a-h, o-z)
      include 'lgcom.h'
c     L y = b, by rows of L
      do 20 j = 2, neq
        ja = jp(j) - j + 1
        sum = 0.d0
        do 10 i = j - ih(j), j - 1
          sum = sum + al(ja+i)*b(i)
   10   continue
        b(j) = b(j) - sum
   20 continue
c     D z = y
      do 30 j = 1, neq
        b(j) = b(j)/ad(j)
   30 continue
c     U x = z, by columns of U
      do 50 j = neq, 2, -1
        ja = jp(j) - j + 1
        do 40 i = j - ih(j), j - 1
          b(i) = b(i) - au(ja+i)*b(j)
   40   continue
   50 continue
      end
