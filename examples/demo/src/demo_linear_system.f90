!> The Newton matrix and its solution with LAPACK: general banded (dgbsv)
!> or dense (dgesv). Both are LU with partial pivoting, so a non-symmetric
!> matrix (friction) is fine.
!>
!> Entries outside the band are not dropped: sys_add records the width they
!> need (overflow), and the caller widens the band (sys_setup again) and
!> reassembles. Contacts between distant nodes therefore widen the band, or
!> switch to the dense solver when the band would cost more than the full
!> matrix, without the contact code knowing the storage.
module demo_linear_system
  use demo_kinds, only: dp
  implicit none
  private
  public :: sys_setup, sys_zero, sys_add, sys_solve

  type, public :: linear_system
    logical :: dense = .true.
    integer :: n = 0, kl = 0, ku = 0
    real(dp), allocatable :: a(:, :)       !< dense n x n, or LAPACK band storage (2kl+ku+1, n)
    integer, allocatable :: ipiv(:)
    logical :: overflow = .false.          !< an entry fell outside the band
    integer :: need = 0                    !< half bandwidth the overflowing entries need
  end type linear_system

  interface
    subroutine dgbsv(n, kl, ku, nrhs, ab, ldab, ipiv, b, ldb, info)
      import :: dp
      integer, intent(in) :: n, kl, ku, nrhs, ldab, ldb
      real(dp), intent(inout) :: ab(ldab, *), b(ldb, *)
      integer, intent(out) :: ipiv(*), info
    end subroutine dgbsv
    subroutine dgesv(n, nrhs, a, lda, ipiv, b, ldb, info)
      import :: dp
      integer, intent(in) :: n, nrhs, lda, ldb
      real(dp), intent(inout) :: a(lda, *), b(ldb, *)
      integer, intent(out) :: ipiv(*), info
    end subroutine dgesv
  end interface

contains

  !> Storage for n equations of half bandwidth hb. choice: 'dense', 'banded'
  !> or 'auto' (dense when the band storage, (3 hb + 1) n, is not clearly
  !> smaller than n^2, which also covers tiny problems).
  subroutine sys_setup(sys, n, hb, choice)
    type(linear_system), intent(inout) :: sys
    integer, intent(in) :: n, hb
    character(len=*), intent(in) :: choice
    sys%n = n
    sys%kl = min(hb, max(n - 1, 0))
    sys%ku = sys%kl
    select case (choice)
    case ('dense'); sys%dense = .true.
    case ('banded'); sys%dense = .false.
    case default; sys%dense = 2 * (3 * sys%kl + 1) >= n
    end select
    if (allocated(sys%a)) deallocate (sys%a)
    if (allocated(sys%ipiv)) deallocate (sys%ipiv)
    if (sys%dense) then
      allocate (sys%a(n, n))
    else
      allocate (sys%a(2 * sys%kl + sys%ku + 1, n))
    end if
    allocate (sys%ipiv(n))
    call sys_zero(sys)
  end subroutine sys_setup

  subroutine sys_zero(sys)
    type(linear_system), intent(inout) :: sys
    sys%a = 0.0_dp
    sys%overflow = .false.
    sys%need = 0
  end subroutine sys_zero

  !> A(i, j) += v.
  subroutine sys_add(sys, i, j, v)
    type(linear_system), intent(inout) :: sys
    integer, intent(in) :: i, j
    real(dp), intent(in) :: v
    if (sys%dense) then
      sys%a(i, j) = sys%a(i, j) + v
    else if (i - j > sys%kl .or. j - i > sys%ku) then
      sys%overflow = .true.
      sys%need = max(sys%need, abs(i - j))
    else
      sys%a(sys%kl + sys%ku + 1 + i - j, j) = sys%a(sys%kl + sys%ku + 1 + i - j, j) + v
    end if
  end subroutine sys_add

  !> Solves A x = b in place (b becomes x); A is overwritten by its factors.
  !> info > 0: the matrix is singular (LAPACK's zero pivot).
  subroutine sys_solve(sys, b, info)
    type(linear_system), intent(inout) :: sys
    real(dp), intent(inout) :: b(:)
    integer, intent(out) :: info
    if (sys%n == 0) then
      info = 0
      return
    end if
    if (sys%dense) then
      call dgesv(sys%n, 1, sys%a, sys%n, sys%ipiv, b, sys%n, info)
    else
      call dgbsv(sys%n, sys%kl, sys%ku, 1, sys%a, size(sys%a, 1), sys%ipiv, b, sys%n, info)
    end if
  end subroutine sys_solve

end module demo_linear_system
