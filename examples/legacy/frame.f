c     frame.f -- the frame element of the legacy code.
c
c     A two-node 3D Euler-Bernoulli frame element, LINEAR (small
c     displacements, small rotations): the classical 12 x 12 stiffness
c     of axial force, torsion and bending in two planes, in local axes
c     rotated to the global ones. No geometric stiffness: it is exact
c     for the small deflections of the two scenes, where the only
c     nonlinearity is the contact (and a rigid translation of the
c     slider, which a linear element carries without strain). It is not
c     an element for large rotations. Solid circular section of radius
c     r: A = pi r^2, I = pi r^4 / 4 about both axes, J = 2 I.
c     Dofs per node: u, v, w, then the rotations about x, y, z.
c
      subroutine frmstf(xl, r, s)
      implicit double precision (a-h, o-z)
      include 'lgcom.h'
      double precision xl(3,2), s(12,12)
      double precision sl(12,12), e(3,3), vr(3), tmp(3,3)
      pi = 4.d0*atan(1.d0)
c     local axes: e(1,.) along the element, e(2,.) normal to it in the
c     plane of e(1,.) and global z (global y for a vertical element)
      do 10 i = 1, 3
        e(1,i) = xl(i,2) - xl(i,1)
   10 continue
      el = sqrt(e(1,1)**2 + e(1,2)**2 + e(1,3)**2)
      do 20 i = 1, 3
        e(1,i) = e(1,i)/el
        vr(i) = 0.d0
   20 continue
      if (abs(e(1,3)) .lt. 0.9d0) then
        vr(3) = 1.d0
      else
        vr(2) = 1.d0
      endif
      dot = e(1,1)*vr(1) + e(1,2)*vr(2) + e(1,3)*vr(3)
      do 30 i = 1, 3
        e(2,i) = vr(i) - dot*e(1,i)
   30 continue
      en = sqrt(e(2,1)**2 + e(2,2)**2 + e(2,3)**2)
      do 40 i = 1, 3
        e(2,i) = e(2,i)/en
   40 continue
      e(3,1) = e(1,2)*e(2,3) - e(1,3)*e(2,2)
      e(3,2) = e(1,3)*e(2,1) - e(1,1)*e(2,3)
      e(3,3) = e(1,1)*e(2,2) - e(1,2)*e(2,1)
c     section and local stiffness
      a  = pi*r**2
      ai = pi*r**4/4.d0
      aj = 2.d0*ai
      do 60 j = 1, 12
        do 50 i = 1, 12
          sl(i,j) = 0.d0
   50   continue
   60 continue
      ea = emod*a/el
      gj = gmod*aj/el
      b1 = 12.d0*emod*ai/el**3
      b2 = 6.d0*emod*ai/el**2
      b3 = 4.d0*emod*ai/el
      b4 = 2.d0*emod*ai/el
c     axial (1, 7) and torsion (4, 10)
      call add2(sl, 1, 7, ea)
      call add2(sl, 4, 10, gj)
c     bending in the local 1-2 plane: v (2, 8) with the rotation about
c     the local 3 axis (6, 12)
      call bend4(sl, 2, 6, 8, 12, b1, b2, b3, b4)
c     bending in the local 1-3 plane: w (3, 9) with the rotation about
c     the local 2 axis (5, 11), whose sign is opposite (dw/dx = -th2)
      call bend4(sl, 3, 5, 9, 11, b1, -b2, b3, b4)
c     global stiffness: each 3 x 3 block k_IJ becomes R^T k_IJ R
      do 120 jb = 0, 9, 3
        do 110 ib = 0, 9, 3
          do 80 j = 1, 3
            do 70 i = 1, 3
              tmp(i,j) = 0.d0
              do 65 k = 1, 3
                tmp(i,j) = tmp(i,j) + sl(ib+i,jb+k)*e(k,j)
   65         continue
   70       continue
   80     continue
          do 100 j = 1, 3
            do 90 i = 1, 3
              sum = 0.d0
              do 85 k = 1, 3
                sum = sum + e(k,i)*tmp(k,j)
   85         continue
              s(ib+i,jb+j) = sum
   90       continue
  100     continue
  110   continue
  120 continue
      end
c
c     the 2 x 2 block of a bar: k [1 -1; -1 1] on dofs i, j
      subroutine add2(sl, i, j, ck)
      double precision sl(12,12), ck
      integer i, j
      sl(i,i) = sl(i,i) + ck
      sl(j,j) = sl(j,j) + ck
      sl(i,j) = sl(i,j) - ck
      sl(j,i) = sl(j,i) - ck
      end
c
c     the 4 x 4 bending block on (w1, th1, w2, th2) = dofs (i1, i2, i3,
c     i4): 12EI/l^3 (b1), 6EI/l^2 (b2, signed), 4EI/l (b3), 2EI/l (b4)
      subroutine bend4(sl, i1, i2, i3, i4, b1, b2, b3, b4)
      double precision sl(12,12), b1, b2, b3, b4
      integer i1, i2, i3, i4
      sl(i1,i1) = b1
      sl(i1,i2) = b2
      sl(i1,i3) = -b1
      sl(i1,i4) = b2
      sl(i2,i2) = b3
      sl(i2,i3) = -b2
      sl(i2,i4) = b4
      sl(i3,i3) = b1
      sl(i3,i4) = -b2
      sl(i4,i4) = b3
      sl(i2,i1) = b2
      sl(i3,i1) = -b1
      sl(i4,i1) = b2
      sl(i3,i2) = -b2
      sl(i4,i2) = b4
      sl(i4,i3) = -b2
      end
