!> A failing call without ierr must stop the program (module b2b's documented
!> behaviour) with a non-zero exit status and the message on stderr.
!>
!> Registered with WILL_FAIL: the non-zero exit is the expected outcome. If
!> the call wrongly returns, the program prints "ERROR: returned" and exits
!> with status 0, so that ctest reports the test as failed.
!>
!> Without arguments the call has neither ierr nor errmsg; with the argument
!> "errmsg" it has errmsg but still no ierr (which must stop all the same).
!> With the argument "handover" the failing call is b2b_pair_history_handover
!> with beam 3 (a check of the module itself, before the C call). With the
!> argument "model" it is b2b_model_finalize on a model without beams.
program ftest_stop_without_ierr
  use, intrinsic :: iso_c_binding, only: c_double
  use, intrinsic :: iso_fortran_env, only: output_unit
  use b2b
  implicit none

  real(c_double) :: patch(3, 4), x(3, 3), hist(12), hist_to(12)
  type(b2b_params) :: p
  type(b2b_model) :: m
  character(len=B2B_ERRMSG_LEN) :: msg
  character(len=16) :: arg
  integer :: i

  do i = 1, 4
    patch(:, i) = [real(i, c_double), 0.5_c_double * i**2, 0.0_c_double]
  end do
  x = -7.0_c_double
  msg = ''
  arg = ''
  if (command_argument_count() >= 1) call get_command_argument(1, arg)

  if (arg == 'handover') then
    call b2b_params_create(p)
    call b2b_params_set_real(p, 'penalty', 100.0_c_double)
    call b2b_params_set_real(p, 'friction', 0.3_c_double)
    call b2b_params_set_real(p, 'tangential_penalty', 50.0_c_double)
    call b2b_params_finalize(p)
    hist = 0
    hist_to = -7.0_c_double
    write (output_unit, '(a)') 'calling b2b_pair_history_handover with beam 3 and no ierr'
    flush (output_unit)
    call b2b_pair_history_handover(p, 3, +1, [B2B_CURVE_LINEAR, 0, 0], patch, &
                                   [B2B_CURVE_LINEAR, 0, 0], patch, hist, hist_to)
    write (output_unit, '(a)') 'ERROR: returned from a failing b2b_pair_history_handover ' // &
      'without ierr'
    flush (output_unit)
    stop
  else if (arg == 'model') then
    call b2b_model_create(m)
    write (output_unit, '(a)') 'calling b2b_model_finalize on a model without beams and no ierr'
    flush (output_unit)
    call b2b_model_finalize(m, 4)
    write (output_unit, '(a)') 'ERROR: returned from a failing b2b_model_finalize without ierr'
    flush (output_unit)
    stop
  else if (arg == 'errmsg') then
    write (output_unit, '(a)') 'calling b2b_segment_eval with kind 17, errmsg and no ierr'
    flush (output_unit)
    call b2b_segment_eval(17, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, patch, 0.3_c_double, x=x, &
                          errmsg=msg)
  else
    write (output_unit, '(a)') 'calling b2b_segment_eval with kind 17 and no ierr'
    flush (output_unit)
    call b2b_segment_eval(17, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, patch, 0.3_c_double, x=x)
  end if
  write (output_unit, '(a)') 'ERROR: returned from a failing b2b_segment_eval without ierr ' // &
    '(errmsg: "' // trim(msg) // '")'
  flush (output_unit)
  stop
end program ftest_stop_without_ierr
