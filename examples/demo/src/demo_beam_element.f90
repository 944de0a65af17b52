!> Two-node corotational Euler-Bernoulli beam for large displacements and
!> rotations, after Battini & Pacoste (2002), "Co-rotational beam elements
!> with warping effects in instability problems", CMAME 191, 1755-1789
!> (their element without warping), in the line of Crisfield (1990),
!> "A consistent co-rotational formulation for non-linear, three-dimensional,
!> beam-elements", CMAME 81, 131-150.
!>
!> Kinematics (Battini & Pacoste, section 3):
!>  * corotated frame Rr = [r1 r2 r3]: r1 along the current chord; r3 normal
!>    to r1 and to q = (q_a + q_b)/2, the mean of the second axes of the two
!>    nodal triads, r2 = r3 x r1. Using both nodes' triads keeps the frame
!>    independent of the node order and free of the drift of a single node.
!>  * local rotations theta_i = log(Rr^T T_i), T_i = R_i R0 the triad of node
!>    i (R_i the node's total rotation, R0 the element's initial frame);
!>    local elongation u = l - l0.
!>  * local law: the small-strain Euler-Bernoulli element in the corotated
!>    frame (axial, torsion, two cubic bending modes), energy
!>      U = EA u^2/(2 l0) + GJ (th_bx - th_ax)^2/(2 l0)
!>          + sum over y,z of 2 EI/l0 (th_a^2 + th_a th_b + th_b^2).
!>
!> The variables are the translations and the spatial spins of both nodes,
!> d = (du_a, dw_a, du_b, dw_b), with R_i <- exp(S(dw_i)) R_i: the internal
!> force is dU/dd and the tangent its derivative along the same multiplicative
!> update. Both are obtained by carrying value, gradient and Hessian through
!> the energy (module demo_hyperdual): the Hessian H of U(exp(S(d)) R) is
!> symmetric, and the derivative of the force along a second spin adds, by the
!> Baker-Campbell-Hausdorff formula exp(S(a))exp(S(b)) = exp(S(a + b + a x b/2 + ...)),
!> the term -S(m_i)/2 on each node's spin-spin block (m_i the node's moment):
!>   K = H - diag(0, S(m_a)/2, 0, S(m_b)/2).
!> So K is the exact Newton matrix of the multiplicative update, non-symmetric
!> away from equilibrium: the derivative that Battini & Pacoste write out in
!> closed form, here obtained without transcribing it by hand.
!>
!> Why this element: Euler-Bernoulli is locking-free with two nodes, its local
!> cubic is exact for end loads, and with the frame eliminating rigid motion
!> the large rotations are carried by the kinematics alone, so the published
!> benchmarks (roll-up, Mattiasson, 45-degree bend) converge with 8-20
!> elements. Shear deformation is irrelevant for the slender ropes and cables
!> b2b targets.
module demo_beam_element
  use demo_kinds, only: dp
  use demo_hyperdual
  implicit none
  private
  public :: beam_element

contains

  !> Internal force f (12) and tangent k (12,12) of one element.
  !> xa, xb current node positions; ta, tb current element triads at the
  !> nodes (columns = local axes); stiff = [EA, GJ, EIy, EIz]; l0 initial length.
  !> spin_correction (default .true.) may be switched off by a test to show
  !> that the finite-difference check detects the missing term.
  subroutine beam_element(xa, xb, ta, tb, stiff, l0, f, k, spin_correction)
    real(dp), intent(in) :: xa(3), xb(3), ta(3, 3), tb(3, 3), stiff(4), l0
    real(dp), intent(out) :: f(12), k(12, 12)
    logical, intent(in), optional :: spin_correction
    type(hdual) :: pa(3), pb(3), wa(3), wb(3), d(3), l, r(3, 3), q(3), n3
    type(hdual) :: tta(3, 3), ttb(3, 3), tha(3), thb(3), u, energy
    real(dp) :: ea, gj, eiy, eiz
    integer :: i
    logical :: corr

    corr = .true.
    if (present(spin_correction)) corr = spin_correction
    ea = stiff(1); gj = stiff(2); eiy = stiff(3); eiz = stiff(4)

    do i = 1, 3
      pa(i) = hd_var(xa(i), i)
      wa(i) = hd_var(0.0_dp, 3 + i)
      pb(i) = hd_var(xb(i), 6 + i)
      wb(i) = hd_var(0.0_dp, 9 + i)
    end do
    do i = 1, 3
      tta(:, i) = spun(wa, ta(:, i))
      ttb(:, i) = spun(wb, tb(:, i))
    end do

    d = pb - pa
    l = hd_norm(d)
    r(:, 1) = d / l
    q = 0.5_dp * (tta(:, 2) + ttb(:, 2))
    r(:, 3) = hd_cross(r(:, 1), q)
    n3 = hd_norm(r(:, 3))
    r(:, 3) = r(:, 3) / n3
    r(:, 2) = hd_cross(r(:, 3), r(:, 1))

    tha = local_rotation(r, tta)
    thb = local_rotation(r, ttb)
    u = l - l0

    energy = (0.5_dp * ea / l0) * (u * u) &
           + (0.5_dp * gj / l0) * ((thb(1) - tha(1)) * (thb(1) - tha(1))) &
           + (2.0_dp * eiy / l0) * (tha(2) * tha(2) + tha(2) * thb(2) + thb(2) * thb(2)) &
           + (2.0_dp * eiz / l0) * (tha(3) * tha(3) + tha(3) * thb(3) + thb(3) * thb(3))

    f = energy%g
    k = hd_hessian(energy)
    if (corr) then
      k(4:6, 4:6) = k(4:6, 4:6) - 0.5_dp * skew3(f(4:6))
      k(10:12, 10:12) = k(10:12, 10:12) - 0.5_dp * skew3(f(10:12))
    end if
  end subroutine beam_element

  !> exp(S(w)) t to second order in w: exact value, gradient and Hessian at w = 0.
  pure function spun(w, t) result(r)
    type(hdual), intent(in) :: w(3)
    real(dp), intent(in) :: t(3)
    type(hdual) :: r(3), tt(3), wt(3)
    tt = hd_const(t)
    wt = hd_cross(w, tt)
    r = tt + wt + 0.5_dp * hd_cross(w, wt)
  end function spun

  !> log(Rr^T T) as a rotation vector in the corotated frame.
  !> With s the axial vector of the skew part (sin(theta) n) and
  !> c = cos(theta), theta n = (theta/sin(theta)) s; near theta = 0 the
  !> factor is asin(x)/x by its series in x^2 = s.s (a square root would
  !> have an infinite derivative there).
  pure function local_rotation(r, t) result(th)
    type(hdual), intent(in) :: r(3, 3), t(3, 3)
    type(hdual) :: th(3), rb(3, 3), s(3), c, x2, sn, factor
    integer :: i, j
    do j = 1, 3
      do i = 1, 3
        rb(i, j) = hd_dot(r(:, i), t(:, j))
      end do
    end do
    s(1) = 0.5_dp * (rb(3, 2) - rb(2, 3))
    s(2) = 0.5_dp * (rb(1, 3) - rb(3, 1))
    s(3) = 0.5_dp * (rb(2, 1) - rb(1, 2))
    c = 0.5_dp * (rb(1, 1) + rb(2, 2) + rb(3, 3) - 1.0_dp)
    x2 = hd_dot(s, s)
    if (x2%v < 1.0e-6_dp .and. c%v > 0.0_dp) then
      ! truncation error below 35/1152 x^8 < 1e-25
      factor = 1.0_dp + x2 * (1.0_dp / 6.0_dp + x2 * (3.0_dp / 40.0_dp + x2 * (5.0_dp / 112.0_dp)))
    else
      sn = sqrt(x2)
      factor = atan2(sn, c) / sn
    end if
    th = factor * s
  end function local_rotation

  pure function skew3(a) result(s)
    real(dp), intent(in) :: a(3)
    real(dp) :: s(3, 3)
    s(1, :) = [0.0_dp, -a(3), a(2)]
    s(2, :) = [a(3), 0.0_dp, -a(1)]
    s(3, :) = [-a(2), a(1), 0.0_dp]
  end function skew3

end module demo_beam_element
