!> The element tangent against central finite differences of the internal
!> force, along the same multiplicative update the Newton loop uses
!> (x <- x + h e, R <- exp(S(h e)) R), on deformed, rotated elements away from
!> equilibrium (where the non-symmetric spin term matters).
!> Asserts: max |K - K_fd| / max |K| <= 1e-6 for every case; and, as a check
!> of the check, that dropping the spin correction -S(m)/2 is detected
!> (error >= 1e-4) in the three loaded cases (case 4 carries no moment, so
!> the term vanishes there).
program test_beam_tangent
  use demo_kinds, only: dp
  use demo_rotation, only: rotvec_to_matrix
  use demo_beam_element, only: beam_element
  implicit none
  real(dp) :: xa(3), xb(3), ra(3, 3), rb(3, 3), r0(3, 3), stiff(4), l0
  real(dp) :: f(12), k(12, 12), kfd(12, 12), fp(12), fm(12), kno(12, 12), err, err_no, worst
  integer :: icase, j
  logical :: ok

  ok = .true.
  worst = 0.0_dp
  do icase = 1, 4
    call make_case(icase)
    call beam_element(xa, xb, matmul(ra, r0), matmul(rb, r0), stiff, l0, f, k)
    call beam_element(xa, xb, matmul(ra, r0), matmul(rb, r0), stiff, l0, f, kno, spin_correction=.false.)
    do j = 1, 12
      call perturbed_force(j, +1.0_dp, fp)
      call perturbed_force(j, -1.0_dp, fm)
      kfd(:, j) = (fp - fm) / (2.0_dp * step(j))
    end do
    err = maxval(abs(k - kfd)) / maxval(abs(k))
    err_no = maxval(abs(kno - kfd)) / maxval(abs(k))
    worst = max(worst, err)
    write (*, '(a,i0,a,es10.3,a,es10.3,a,es10.3)') 'case ', icase, ': relative error ', err, &
      ';  without the spin term ', err_no, ';  asymmetry ', maxval(abs(k - transpose(k))) / maxval(abs(k))
    if (err > 1.0e-6_dp) then
      write (*, '(a)') '  FAIL: tangent differs from the finite differences'
      ok = .false.
    end if
    if (icase <= 3 .and. err_no < 1.0e-4_dp) then
      write (*, '(a)') '  FAIL: the check does not detect a missing spin term'
      ok = .false.
    end if
  end do
  write (*, '(a,es10.3,a)') 'worst relative error ', worst, ' (tolerance 1e-6)'
  if (.not. ok) error stop 'test_beam_tangent: FAILED'

contains

  !> Step h relative to the variable's scale: lengths ~ l0, rotations ~ 1.
  !> Central differences have truncation error ~ h^2 and round-off ~ eps/h:
  !> h = 1e-5 balances them near 1e-10.
  pure function step(j) result(h)
    integer, intent(in) :: j
    real(dp) :: h
    if (mod((j - 1) / 3, 2) == 0) then
      h = 1.0e-5_dp * l0
    else
      h = 1.0e-5_dp
    end if
  end function step

  subroutine perturbed_force(j, sgn, fo)
    integer, intent(in) :: j
    real(dp), intent(in) :: sgn
    real(dp), intent(out) :: fo(12)
    real(dp) :: pa(3), pb(3), qa(3, 3), qb(3, 3), e(3), kk(12, 12)
    integer :: blk, c
    pa = xa; pb = xb; qa = ra; qb = rb
    blk = (j - 1) / 3
    c = j - 3 * blk
    e = 0.0_dp
    e(c) = sgn * step(j)
    select case (blk)
    case (0); pa = pa + e
    case (1); qa = matmul(rotvec_to_matrix(e), qa)
    case (2); pb = pb + e
    case (3); qb = matmul(rotvec_to_matrix(e), qb)
    end select
    call beam_element(pa, pb, matmul(qa, r0), matmul(qb, r0), stiff, l0, fo, kk)
  end subroutine perturbed_force

  !> Four elements: mildly and strongly deformed, arbitrary orientations,
  !> different section stiffnesses (so no term can hide behind symmetry).
  subroutine make_case(icase)
    integer, intent(in) :: icase
    real(dp) :: x0a(3), x0b(3), e1(3), e2(3), e3(3), g(3)
    select case (icase)
    case (1)
      x0a = [0.0_dp, 0.0_dp, 0.0_dp]; x0b = [1.0_dp, 0.0_dp, 0.0_dp]
      g = [0.0_dp, 0.0_dp, 1.0_dp]
      ra = rotvec_to_matrix([0.01_dp, -0.02_dp, 0.03_dp])
      rb = rotvec_to_matrix([-0.02_dp, 0.015_dp, 0.01_dp])
      xa = x0a + [0.001_dp, 0.002_dp, -0.001_dp]; xb = x0b + [-0.002_dp, 0.01_dp, 0.02_dp]
      stiff = [100.0_dp, 3.0_dp, 2.0_dp, 5.0_dp]
    case (2)
      x0a = [0.3_dp, -1.0_dp, 2.0_dp]; x0b = [1.1_dp, 0.5_dp, 1.2_dp]
      g = [0.2_dp, 0.1_dp, 1.0_dp]
      ra = rotvec_to_matrix([0.7_dp, -0.4_dp, 1.1_dp])
      rb = matmul(rotvec_to_matrix([0.2_dp, 0.3_dp, -0.25_dp]), ra)
      xa = x0a + [0.1_dp, 0.2_dp, -0.3_dp]
      xb = xa + matmul(ra, x0b - x0a) * 1.01_dp + [0.05_dp, -0.04_dp, 0.03_dp]
      stiff = [1.0e3_dp, 7.0_dp, 11.0_dp, 13.0_dp]
    case (3)
      ! large rigid rotation (2.5 rad) plus local rotations of 0.3 rad
      x0a = [1.0_dp, 2.0_dp, 3.0_dp]; x0b = [1.0_dp, 2.5_dp, 3.1_dp]
      g = [1.0_dp, 0.0_dp, 0.0_dp]
      ra = matmul(rotvec_to_matrix([0.3_dp, 0.0_dp, 0.1_dp]), rotvec_to_matrix([1.5_dp, 1.5_dp, -1.2_dp]))
      rb = matmul(rotvec_to_matrix([-0.1_dp, 0.25_dp, 0.2_dp]), rotvec_to_matrix([1.5_dp, 1.5_dp, -1.2_dp]))
      xa = x0a
      xb = xa + matmul(rotvec_to_matrix([1.5_dp, 1.5_dp, -1.2_dp]), x0b - x0a) * 0.98_dp
      stiff = [5.0e4_dp, 40.0_dp, 20.0_dp, 60.0_dp]
    case default
      ! undeformed but rotated: the force vanishes, K must still match
      x0a = [0.0_dp, 0.0_dp, 0.0_dp]; x0b = [0.0_dp, 0.0_dp, 2.0_dp]
      g = [0.0_dp, 1.0_dp, 0.0_dp]
      ra = rotvec_to_matrix([0.4_dp, 0.2_dp, 0.1_dp]); rb = ra
      xa = [0.5_dp, 0.5_dp, 0.5_dp]; xb = xa + matmul(ra, x0b - x0a)
      stiff = [1.0e6_dp, 0.5_dp, 1.0_dp, 1.0_dp]
    end select
    l0 = norm2(x0b - x0a)
    e1 = (x0b - x0a) / l0
    e3 = g - dot_product(g, e1) * e1
    e3 = e3 / norm2(e3)
    e2 = [e3(2) * e1(3) - e3(3) * e1(2), e3(3) * e1(1) - e3(1) * e1(3), e3(1) * e1(2) - e3(2) * e1(1)]
    r0(:, 1) = e1; r0(:, 2) = e2; r0(:, 3) = e3
  end subroutine make_case

end program test_beam_tangent
