!> The convergence rate of a step (demo_solver's convergence_rate), which
!> the step line prints as "rate 2.00" or, when it cannot be measured,
!> "rate —": fewer than three usable residual norms after r_0, where the
!> final norms at the round-off floor (within 3 times it) and zero norms
!> are not usable. Asserted case by case; exit code 1 on any mismatch.
program test_rate
  use demo_kinds, only: dp
  use demo_solver, only: convergence_rate
  use, intrinsic :: iso_fortran_env, only: int64
  implicit none
  logical :: ok
  ok = .true.
  ! r_0 and two iterates: not measurable
  call expect('three norms', [1.0_dp, 1.0e-1_dp, 1.0e-3_dp], 0.0_dp, -1.0_dp)
  ! r_0 and three iterates: p = log(1e-4/1e-2) / log(1e-2/1e-1) = 2
  call expect('four norms', [1.0_dp, 1.0e-1_dp, 1.0e-2_dp, 1.0e-4_dp], 0.0_dp, 2.0_dp)
  ! a zero final norm is not usable: three left, not measurable (was 0.00)
  call expect('zero final norm', [1.0_dp, 1.0e-1_dp, 1.0e-3_dp, 0.0_dp], 0.0_dp, -1.0_dp)
  ! ... and with one more norm before it, the rate of the three before
  call expect('zero after four', [1.0_dp, 1.0e-1_dp, 1.0e-2_dp, 1.0e-4_dp, 0.0_dp], 0.0_dp, 2.0_dp)
  ! two final norms at the round-off floor (1e-12): both dropped
  call expect('two at the floor', [1.0_dp, 1.0e-1_dp, 1.0e-3_dp, 2.0e-12_dp, 1.0e-12_dp], 1.0e-12_dp, -1.0_dp)
  ! no decrease: measured, order 0
  call expect('no decrease', [1.0_dp, 1.0e-1_dp, 1.0e-1_dp, 1.0e-2_dp], 0.0_dp, 0.0_dp)
  ! no norm at all
  call expect('no norm', [real(dp) ::], 0.0_dp, -1.0_dp)
  if (.not. ok) error stop 1
  write (*, '(a)') 'test_rate: all cases as expected'
contains
  subroutine expect(what, norms, floor, want)
    character(len=*), intent(in) :: what
    real(dp), intent(in) :: norms(:), floor, want
    integer(int64) :: sigs(size(norms))
    real(dp) :: rate
    logical :: stable
    sigs = 7_int64
    call convergence_rate(norms, sigs, floor, rate, stable)
    write (*, '(a,f8.4,a,f8.4)') what // ': rate ', rate, ', expected ', want
    if (abs(rate - want) > 1.0e-12_dp) then
      write (*, '(a)') '  MISMATCH'
      ok = .false.
    end if
  end subroutine expect
end program test_rate
