!> Finite rotations of the nodes, stored as unit quaternions (w, x, y, z).
!>
!> Why quaternions: four numbers without singularity for any angle, and the
!> multiplicative update R <- exp(S(dw)) R of a spatial spin dw is one
!> quaternion product; renormalising after it keeps round-off from
!> accumulating over thousands of Newton updates.
module demo_rotation
  use demo_kinds, only: dp
  implicit none
  private
  public :: quat_identity, quat_from_rotvec, quat_mul, quat_to_matrix, quat_to_rotvec
  public :: quat_spin_update, skew, rotvec_to_matrix

contains

  pure function quat_identity() result(q)
    real(dp) :: q(4)
    q = [1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp]
  end function quat_identity

  !> exp of a rotation vector (angle times unit axis).
  pure function quat_from_rotvec(w) result(q)
    real(dp), intent(in) :: w(3)
    real(dp) :: q(4), a, s
    a = norm2(w)
    if (a < 1.0e-8_dp) then
      ! sin(a/2)/a by its series: exact to round-off below 1e-8
      s = 0.5_dp - a**2 / 48.0_dp
    else
      s = sin(0.5_dp * a) / a
    end if
    q = [cos(0.5_dp * a), s * w(1), s * w(2), s * w(3)]
  end function quat_from_rotvec

  !> Hamilton product p*q: the rotation q followed by p.
  pure function quat_mul(p, q) result(r)
    real(dp), intent(in) :: p(4), q(4)
    real(dp) :: r(4)
    r(1) = p(1) * q(1) - p(2) * q(2) - p(3) * q(3) - p(4) * q(4)
    r(2) = p(1) * q(2) + p(2) * q(1) + p(3) * q(4) - p(4) * q(3)
    r(3) = p(1) * q(3) - p(2) * q(4) + p(3) * q(1) + p(4) * q(2)
    r(4) = p(1) * q(4) + p(2) * q(3) - p(3) * q(2) + p(4) * q(1)
  end function quat_mul

  !> R <- exp(S(dw)) R for a spatial spin dw (global components), renormalised.
  pure function quat_spin_update(q, dw) result(r)
    real(dp), intent(in) :: q(4), dw(3)
    real(dp) :: r(4)
    r = quat_mul(quat_from_rotvec(dw), q)
    r = r / norm2(r)
  end function quat_spin_update

  pure function quat_to_matrix(q) result(r)
    real(dp), intent(in) :: q(4)
    real(dp) :: r(3, 3), w, x, y, z
    w = q(1); x = q(2); y = q(3); z = q(4)
    r(1, :) = [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)]
    r(2, :) = [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)]
    r(3, :) = [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]
  end function quat_to_matrix

  !> log: the rotation vector with angle in [0, pi].
  pure function quat_to_rotvec(q) result(w)
    real(dp), intent(in) :: q(4)
    real(dp) :: w(3), qq(4), s, a
    qq = q
    if (qq(1) < 0.0_dp) qq = -qq   ! q and -q are the same rotation
    s = norm2(qq(2:4))
    a = 2.0_dp * atan2(s, qq(1))
    if (s < 1.0e-12_dp) then
      w = 2.0_dp * qq(2:4)
    else
      w = (a / s) * qq(2:4)
    end if
  end function quat_to_rotvec

  pure function rotvec_to_matrix(w) result(r)
    real(dp), intent(in) :: w(3)
    real(dp) :: r(3, 3)
    r = quat_to_matrix(quat_from_rotvec(w))
  end function rotvec_to_matrix

  !> S(a) b = a x b.
  pure function skew(a) result(s)
    real(dp), intent(in) :: a(3)
    real(dp) :: s(3, 3)
    s(1, :) = [0.0_dp, -a(3), a(2)]
    s(2, :) = [a(3), 0.0_dp, -a(1)]
    s(3, :) = [-a(2), a(1), 0.0_dp]
  end function skew

end module demo_rotation
