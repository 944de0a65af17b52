!> Second-order forward differentiation with respect to the 12 element
!> variables (two nodes x (3 translations + 3 spins)).
!>
!> Why: the corotational element's energy is a composition of a dozen small
!> maps (chord, triads, corotated frame, local rotation logarithm). Its exact
!> gradient (the internal force) and Hessian (the tangent) follow from the
!> chain rule applied operation by operation; carrying value, gradient and
!> Hessian through the same code path that defines the energy makes the
!> tangent consistent by construction (no separately derived geometric
!> stiffness that could drift from the force). Each number is
!> v + g.d + d.H.d/2 truncated at second order.
!>
!> Nine tenths of a scene's time is spent here (perf), so: H is symmetric
!> and only its upper triangle is kept, packed by columns (entry (i, j),
!> i <= j, at i + j (j - 1) / 2; hd_hessian unpacks it), 78 numbers instead
!> of 144, which also makes the element's tangent symmetric to the bit; no
!> operation clears its result before writing all of it; hd_dot and
!> hd_cross make each result in one pass, rounded as the operators would;
!> and the triangle is written a column section at a time (whole-section
!> expressions, which gfortran vectorises and, under -fcheck=bounds in the
!> sanitize build, checks once a section, not once an entry).
!> tunnel_bar_linear.nml took 3.64 s before these, 1.9 s after (Release;
!> 10.4 and 3.9 s in the sanitize build; one run each on the 2-core
!> development machine).
module demo_hyperdual
  use demo_kinds, only: dp
  implicit none
  private

  integer, parameter, public :: nvar = 12
  integer, parameter :: npacked = nvar * (nvar + 1) / 2

  ! No default initialisation: every operation writes all of its result,
  ! and a default would make each one clear it first (a fifth of a scene's
  ! time went to that).
  type, public :: hdual
    real(dp) :: v
    real(dp) :: g(nvar)
    real(dp) :: h(npacked)   ! the upper triangle of H, by columns
  end type hdual

  public :: hd_const, hd_var, hd_hessian, operator(+), operator(-), operator(*), operator(/)
  public :: sqrt, atan2, hd_dot, hd_cross, hd_norm

  interface operator(+)
    module procedure add_hh, add_hr, add_rh
  end interface
  interface operator(-)
    module procedure sub_hh, sub_hr, sub_rh, neg_h
  end interface
  interface operator(*)
    module procedure mul_hh, mul_hr, mul_rh
  end interface
  interface operator(/)
    module procedure div_hh, div_hr
  end interface
  interface sqrt
    module procedure sqrt_h
  end interface
  interface atan2
    module procedure atan2_h
  end interface

contains

  elemental function hd_const(x) result(r)
    real(dp), intent(in) :: x
    type(hdual) :: r
    r%v = x
    r%g = 0.0_dp
    r%h = 0.0_dp
  end function hd_const

  !> The independent variable number k, at value x.
  elemental function hd_var(x, k) result(r)
    real(dp), intent(in) :: x
    integer, intent(in) :: k
    type(hdual) :: r
    r%v = x
    r%g = 0.0_dp
    r%g(k) = 1.0_dp
    r%h = 0.0_dp
  end function hd_var

  elemental function add_hh(a, b) result(r)
    type(hdual), intent(in) :: a, b
    type(hdual) :: r
    r%v = a%v + b%v
    r%g = a%g + b%g
    r%h = a%h + b%h
  end function add_hh

  elemental function add_hr(a, b) result(r)
    type(hdual), intent(in) :: a
    real(dp), intent(in) :: b
    type(hdual) :: r
    r = a
    r%v = a%v + b
  end function add_hr

  elemental function add_rh(a, b) result(r)
    real(dp), intent(in) :: a
    type(hdual), intent(in) :: b
    type(hdual) :: r
    r = b
    r%v = a + b%v
  end function add_rh

  elemental function sub_hh(a, b) result(r)
    type(hdual), intent(in) :: a, b
    type(hdual) :: r
    r%v = a%v - b%v
    r%g = a%g - b%g
    r%h = a%h - b%h
  end function sub_hh

  elemental function sub_hr(a, b) result(r)
    type(hdual), intent(in) :: a
    real(dp), intent(in) :: b
    type(hdual) :: r
    r = a
    r%v = a%v - b
  end function sub_hr

  elemental function sub_rh(a, b) result(r)
    real(dp), intent(in) :: a
    type(hdual), intent(in) :: b
    type(hdual) :: r
    r%v = a - b%v
    r%g = -b%g
    r%h = -b%h
  end function sub_rh

  elemental function neg_h(a) result(r)
    type(hdual), intent(in) :: a
    type(hdual) :: r
    r%v = -a%v
    r%g = -a%g
    r%h = -a%h
  end function neg_h

  elemental function mul_hh(a, b) result(r)
    type(hdual), intent(in) :: a, b
    type(hdual) :: r
    integer :: j, k
    r%v = a%v * b%v
    r%g = a%v * b%g + b%v * a%g
    do j = 1, nvar
      k = j * (j - 1) / 2   ! column j of the triangle is h(k + 1 : k + j)
      r%h(k + 1:k + j) = a%v * b%h(k + 1:k + j) + b%v * a%h(k + 1:k + j) + a%g(1:j) * b%g(j) &
                         + b%g(1:j) * a%g(j)
    end do
  end function mul_hh

  elemental function mul_hr(a, b) result(r)
    type(hdual), intent(in) :: a
    real(dp), intent(in) :: b
    type(hdual) :: r
    r%v = a%v * b
    r%g = a%g * b
    r%h = a%h * b
  end function mul_hr

  elemental function mul_rh(a, b) result(r)
    real(dp), intent(in) :: a
    type(hdual), intent(in) :: b
    type(hdual) :: r
    r = mul_hr(b, a)
  end function mul_rh

  !> f(a) for a scalar function with derivatives f1 = f'(a%v), f2 = f''(a%v).
  elemental function chain1(a, f0, f1, f2) result(r)
    type(hdual), intent(in) :: a
    real(dp), intent(in) :: f0, f1, f2
    type(hdual) :: r
    integer :: j, k
    r%v = f0
    r%g = f1 * a%g
    do j = 1, nvar
      k = j * (j - 1) / 2
      r%h(k + 1:k + j) = f1 * a%h(k + 1:k + j) + f2 * a%g(1:j) * a%g(j)
    end do
  end function chain1

  elemental function div_hh(a, b) result(r)
    type(hdual), intent(in) :: a, b
    type(hdual) :: r
    r = mul_hh(a, chain1(b, 1.0_dp / b%v, -1.0_dp / b%v**2, 2.0_dp / b%v**3))
  end function div_hh

  elemental function div_hr(a, b) result(r)
    type(hdual), intent(in) :: a
    real(dp), intent(in) :: b
    type(hdual) :: r
    r = mul_hr(a, 1.0_dp / b)
  end function div_hr

  elemental function sqrt_h(a) result(r)
    type(hdual), intent(in) :: a
    type(hdual) :: r
    real(dp) :: s
    s = sqrt(a%v)
    r = chain1(a, s, 0.5_dp / s, -0.25_dp / (s * a%v))
  end function sqrt_h

  !> atan2(y, x): the angle of the point (x, y); partial derivatives in closed form.
  elemental function atan2_h(y, x) result(r)
    type(hdual), intent(in) :: y, x
    type(hdual) :: r
    real(dp) :: rho, fy, fx, fyy, fxx, fxy
    integer :: j, k
    rho = x%v**2 + y%v**2
    fy = x%v / rho
    fx = -y%v / rho
    fyy = -2.0_dp * x%v * y%v / rho**2
    fxx = -fyy
    fxy = (y%v**2 - x%v**2) / rho**2
    r%v = atan2(y%v, x%v)
    r%g = fy * y%g + fx * x%g
    do j = 1, nvar
      k = j * (j - 1) / 2
      r%h(k + 1:k + j) = fy * y%h(k + 1:k + j) + fx * x%h(k + 1:k + j) + fyy * y%g(1:j) * y%g(j) &
                         + fxx * x%g(1:j) * x%g(j) + fxy * (y%g(1:j) * x%g(j) + x%g(1:j) * y%g(j))
    end do
  end function atan2_h

  !> The Hessian of a as a full symmetric matrix.
  pure function hd_hessian(a) result(h)
    type(hdual), intent(in) :: a
    real(dp) :: h(nvar, nvar)
    integer :: i, j, p
    p = 0
    do j = 1, nvar
      do i = 1, j
        p = p + 1
        h(i, j) = a%h(p)
        h(j, i) = a%h(p)
      end do
    end do
  end function hd_hessian

  !> a . b for 3-vectors, in one pass: each entry as
  !> (a(1) * b(1) + a(2) * b(2)) + a(3) * b(3) by the operators would round it,
  !> without the four intermediate numbers (each written and copied whole).
  pure function hd_dot(a, b) result(r)
    type(hdual), intent(in) :: a(3), b(3)
    type(hdual) :: r
    integer :: j, k
    r%v = (a(1)%v * b(1)%v + a(2)%v * b(2)%v) + a(3)%v * b(3)%v
    r%g = ((a(1)%v * b(1)%g + b(1)%v * a(1)%g) + (a(2)%v * b(2)%g + b(2)%v * a(2)%g)) &
          + (a(3)%v * b(3)%g + b(3)%v * a(3)%g)
    do j = 1, nvar
      k = j * (j - 1) / 2
      r%h(k + 1:k + j) = ((a(1)%v * b(1)%h(k + 1:k + j) + b(1)%v * a(1)%h(k + 1:k + j) &
                           + a(1)%g(1:j) * b(1)%g(j) + b(1)%g(1:j) * a(1)%g(j)) &
                          + (a(2)%v * b(2)%h(k + 1:k + j) + b(2)%v * a(2)%h(k + 1:k + j) &
                             + a(2)%g(1:j) * b(2)%g(j) + b(2)%g(1:j) * a(2)%g(j))) &
                         + (a(3)%v * b(3)%h(k + 1:k + j) + b(3)%v * a(3)%h(k + 1:k + j) &
                            + a(3)%g(1:j) * b(3)%g(j) + b(3)%g(1:j) * a(3)%g(j))
    end do
  end function hd_dot

  !> a x b for 3-vectors, each component in one pass (as the operators
  !> would round it).
  pure function hd_cross(a, b) result(r)
    type(hdual), intent(in) :: a(3), b(3)
    type(hdual) :: r(3)
    r(1) = mul_sub(a(2), b(3), a(3), b(2))
    r(2) = mul_sub(a(3), b(1), a(1), b(3))
    r(3) = mul_sub(a(1), b(2), a(2), b(1))
  end function hd_cross

  !> a * b - c * d in one pass, rounded as mul_hh(a, b) - mul_hh(c, d).
  elemental function mul_sub(a, b, c, d) result(r)
    type(hdual), intent(in) :: a, b, c, d
    type(hdual) :: r
    integer :: j, k
    r%v = a%v * b%v - c%v * d%v
    r%g = (a%v * b%g + b%v * a%g) - (c%v * d%g + d%v * c%g)
    do j = 1, nvar
      k = j * (j - 1) / 2
      r%h(k + 1:k + j) = (a%v * b%h(k + 1:k + j) + b%v * a%h(k + 1:k + j) + a%g(1:j) * b%g(j) &
                          + b%g(1:j) * a%g(j)) &
                         - (c%v * d%h(k + 1:k + j) + d%v * c%h(k + 1:k + j) + c%g(1:j) * d%g(j) &
                            + d%g(1:j) * c%g(j))
    end do
  end function mul_sub

  pure function hd_norm(a) result(r)
    type(hdual), intent(in) :: a(3)
    type(hdual) :: r
    r = sqrt(hd_dot(a, a))
  end function hd_norm

end module demo_hyperdual
