!> A Fortran program built against an installed b2b, as a host code would be:
!> use b2b, link libb2b_fortran. Stops with a non-zero code on any mismatch.
!> Built by tests/consumer/run_consumer_test.sh through CMake (find_package)
!> and through pkg-config.
program b2b_consumer_fortran
  use, intrinsic :: iso_c_binding, only: c_double
  use b2b
  implicit none
  integer :: major, minor, patch, abi, ierr, failures, i
  real(c_double) :: nodes(3, 4), x(3, 3)
  character(len=B2B_ERRMSG_LEN) :: msg

  failures = 0

  ! The run-time library matches the headers the module was generated from.
  call b2b_version(major, minor, patch, ierr=ierr)
  call check(ierr == B2B_OK, 'b2b_version failed')
  call check(major == B2B_VERSION_MAJOR .and. minor == B2B_VERSION_MINOR .and. &
             patch == B2B_VERSION_PATCH, 'b2b_version does not match B2B_VERSION_*')
  call b2b_abi_version(abi, ierr=ierr)
  call check(ierr == B2B_OK .and. abi == B2B_SOVERSION, 'b2b_abi_version does not match B2B_SOVERSION')

  ! The node-preserving curve starts at x2.
  nodes = reshape([0, 0, 0, 1, 0, 0, 2, 1, 0, 3, 1, 1], [3, 4]) * 1.0_c_double
  x = -999.0_c_double
  call b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, nodes, &
                        -1.0_c_double, x=x, ierr=ierr, errmsg=msg)
  call check(ierr == B2B_OK, 'b2b_segment_eval(HERMITE_NODAL, xi = -1) failed: ' // trim(msg))
  if (ierr == B2B_OK) then
    do i = 1, 3
      call check(abs(x(i, 1) - nodes(i, 2)) <= 1.0e-14_c_double, 'x(-1) is not node x2')
    end do
  end if

  ! An unknown curve kind is reported, with a message.
  call b2b_segment_eval(42, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, nodes, -1.0_c_double, &
                        x=x, ierr=ierr, errmsg=msg)
  call check(ierr == B2B_ERR_UNKNOWN_KIND, 'b2b_segment_eval(kind 42) did not give B2B_ERR_UNKNOWN_KIND')
  call check(len_trim(msg) > 0, 'b2b_segment_eval(kind 42) gave no message')

  if (failures /= 0) then
    write (*, '(a, i0, a)') 'b2b Fortran consumer: ', failures, ' failure(s)'
    error stop 1
  end if
  write (*, '(a, i0, ".", i0, ".", i0, a, i0, a)') 'b2b Fortran consumer: library ', major, &
    minor, patch, ' (ABI ', abi, '): OK'
  write (*, '(a)') '  kind 42 -> ' // b2b_strerror(B2B_ERR_UNKNOWN_KIND) // ': ' // trim(msg)

contains

  subroutine check(ok, what)
    logical, intent(in) :: ok
    character(len=*), intent(in) :: what
    if (.not. ok) then
      write (*, '(a)') 'FAIL: ' // what
      failures = failures + 1
    end if
  end subroutine

end program
