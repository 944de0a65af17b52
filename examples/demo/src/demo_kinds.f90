!> Working precision and a few constants shared by every part of the demo host.
module demo_kinds
  implicit none
  private
  integer, parameter, public :: dp = kind(1.0d0)
  real(dp), parameter, public :: pi = 3.14159265358979323846264338327950288_dp
  !> Degrees of freedom per node: ux uy uz, then the three spin components.
  integer, parameter, public :: ndf = 6
end module demo_kinds
