!> Assertion bookkeeping shared by the Fortran binding tests.
!>
!> check() counts a passed or failed assertion and prints a line naming every
!> failure; check_summary() prints "<program>: N passed, M failed" and ends
!> the program with error stop 1 when any assertion failed.
module ftest_check
  use, intrinsic :: iso_c_binding, only: c_double
  use, intrinsic :: iso_fortran_env, only: int64, output_unit
  implicit none
  private

  public :: check, check_summary, same_bits, rel_diff, all_equal_to, contains_text, int_str

  integer, save :: n_passed = 0, n_failed = 0

contains

  !> Records one assertion; a failure prints "FAILED: <what>".
  subroutine check(condition, what)
    logical, intent(in) :: condition
    character(len=*), intent(in) :: what
    if (condition) then
      n_passed = n_passed + 1
    else
      n_failed = n_failed + 1
      write (output_unit, '(a)') 'FAILED: ' // what
      flush (output_unit)
    end if
  end subroutine

  !> Prints the summary line; error stop 1 if any assertion failed.
  subroutine check_summary(program_name)
    character(len=*), intent(in) :: program_name
    write (output_unit, '(a, ": ", i0, " passed, ", i0, " failed")') program_name, &
      n_passed, n_failed
    flush (output_unit)
    if (n_failed /= 0) error stop 1
    if (n_passed == 0) error stop 2
  end subroutine

  !> True when a and b hold the same doubles bit for bit (so -0 /= +0 and a
  !> NaN equals only the same NaN).
  logical function same_bits(a, b)
    real(c_double), intent(in) :: a(:), b(:)
    same_bits = size(a) == size(b)
    if (same_bits) same_bits = all(transfer(a, 0_int64, size(a)) == transfer(b, 0_int64, size(b)))
  end function

  !> max|a - b| / max(max|a|, max|b|, floor).
  real(c_double) function rel_diff(a, b, floor)
    real(c_double), intent(in) :: a(:), b(:), floor
    rel_diff = maxval(abs(a - b)) / max(maxval(abs(a)), maxval(abs(b)), floor)
  end function

  !> True when every element of a is bit for bit the value v (a sentinel).
  logical function all_equal_to(a, v)
    real(c_double), intent(in) :: a(:), v
    all_equal_to = all(transfer(a, 0_int64, size(a)) == transfer(v, 0_int64))
  end function

  logical function contains_text(haystack, needle)
    character(len=*), intent(in) :: haystack, needle
    contains_text = index(haystack, needle) > 0
  end function

  function int_str(i) result(s)
    integer, intent(in) :: i
    character(len=:), allocatable :: s
    character(len=24) :: t
    write (t, '(i0)') i
    s = trim(t)
  end function

end module ftest_check
