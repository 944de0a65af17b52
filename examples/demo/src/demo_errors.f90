!> Fatal errors: one message on standard error naming what is wrong and what
!> to change, then a non-zero exit (2). Nothing is written after it, so a
!> failed run never leaves a result that looks complete.
module demo_errors
  use demo_kinds, only: dp
  use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
  implicit none
  private
  public :: fatal, str

  interface str
    module procedure str_int, str_real
  end interface

contains

  subroutine fatal(msg)
    character(len=*), intent(in) :: msg
    flush (output_unit)
    write (error_unit, '(a)') 'b2b_demo: error: ' // msg
    flush (error_unit)
    error stop 2
  end subroutine fatal

  pure function str_int(i) result(s)
    integer, intent(in) :: i
    character(len=:), allocatable :: s
    character(len=24) :: buf
    write (buf, '(i0)') i
    s = trim(buf)
  end function str_int

  pure function str_real(x) result(s)
    real(dp), intent(in) :: x
    character(len=:), allocatable :: s
    character(len=32) :: buf
    ! fixed notation where it reads naturally (0.050000, -100.000000), else scientific
    if (abs(x) < 1.0e6_dp .and. (abs(x) >= 1.0e-3_dp .or. .not. abs(x) > 0.0_dp)) then
      write (buf, '(f20.6)') x
    else
      write (buf, '(es14.6)') x
    end if
    s = trim(adjustl(buf))
  end function str_real

end module demo_errors
