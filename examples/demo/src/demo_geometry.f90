!> Node positions of the simple shapes a scene is built from.
module demo_geometry
  use demo_kinds, only: dp, pi
  implicit none
  private
  public :: line_points, arc_points, element_frame

contains

  !> n_el + 1 equally spaced points from p1 to p2.
  pure function line_points(p1, p2, n_el) result(x)
    real(dp), intent(in) :: p1(3), p2(3)
    integer, intent(in) :: n_el
    real(dp) :: x(3, n_el + 1)
    integer :: i
    do i = 0, n_el
      x(:, i + 1) = p1 + (p2 - p1) * (real(i, dp) / real(n_el, dp))
    end do
  end function line_points

  !> Points on a circular arc: from start, turning about axis (through centre,
  !> right-hand rule) by angle_deg in n_el equal elements; n_pts = n_el + 1
  !> points for an arc, n_el for a closed ring (the last element returns to
  !> the first point).
  pure function arc_points(centre, start, axis, angle_deg, n_el, n_pts) result(x)
    real(dp), intent(in) :: centre(3), start(3), axis(3), angle_deg
    integer, intent(in) :: n_el, n_pts
    real(dp) :: x(3, n_pts), a(3), r(3), t(3), phi
    integer :: i
    a = axis / norm2(axis)
    r = start - centre
    r = r - dot_product(r, a) * a        ! radius vector in the plane of the arc
    t = [a(2) * r(3) - a(3) * r(2), a(3) * r(1) - a(1) * r(3), a(1) * r(2) - a(2) * r(1)]
    do i = 0, n_pts - 1
      phi = angle_deg * pi / 180.0_dp * real(i, dp) / real(n_el, dp)
      x(:, i + 1) = centre + dot_product(start - centre, a) * a + cos(phi) * r + sin(phi) * t
    end do
  end function arc_points

  !> Initial frame [e1 e2 e3] of an element from a to b: e1 along the chord,
  !> e3 the part of `up` normal to it, e2 = e3 x e1. ok = .false. when up is
  !> parallel to the chord.
  pure subroutine element_frame(xa, xb, up, frame, ok)
    real(dp), intent(in) :: xa(3), xb(3), up(3)
    real(dp), intent(out) :: frame(3, 3)
    logical, intent(out) :: ok
    real(dp) :: e1(3), e3(3)
    e1 = (xb - xa) / norm2(xb - xa)
    e3 = up - dot_product(up, e1) * e1
    ok = norm2(e3) > 1.0e-8_dp * norm2(up)
    if (.not. ok) then
      frame = 0.0_dp
      return
    end if
    e3 = e3 / norm2(e3)
    frame(:, 1) = e1
    frame(:, 2) = [e3(2) * e1(3) - e3(3) * e1(2), e3(3) * e1(1) - e3(1) * e1(3), e3(1) * e1(2) - e3(2) * e1(1)]
    frame(:, 3) = e3
  end subroutine element_frame

end module demo_geometry
