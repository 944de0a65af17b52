!> The interpenetration audit through module b2b (b2b_model_audit): two
!> parallel beams of straight segments (radius 0.1) pressed 0.05 into each
!> other carry no force (below parallel_angle); the audit lists every
!> overlapping pair with reason B2B_AUDIT_PARALLEL, 1-based beam and segment
!> numbers and overlap 0.05, and the size query gives the same count. Then
!> crossed beams in contact (Hermite): an empty audit. Error paths with ierr
!> and errmsg (state before an update, tolerance, capacity, shape, missing
!> arrays) leave the outputs untouched.
program ftest_model_audit
  use, intrinsic :: iso_c_binding, only: c_double
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  use b2b
  use ftest_check
  implicit none

  real(c_double), parameter :: r = 0.1_c_double
  integer, parameter :: isentinel = -77
  type(b2b_params) :: p
  type(b2b_model) :: m
  real(c_double) :: x(3, 12), overlap(32), small_overlap(2)
  integer :: pairs(4, 32), reasons(32), bad_pairs(3, 32), small_pairs(4, 2), small_reasons(2)
  integer :: n, n_query, ierr, beam, k
  character(len=B2B_ERRMSG_LEN) :: msg
  logical :: found_middle

  call b2b_params_create(p)
  call b2b_params_set_real(p, 'penalty', 1000.0_c_double)
  call b2b_params_finalize(p)

  ! --- parallel beams: beam 1 nodes 1..6 along x, beam 2 nodes 7..12 at z = 0.15
  call b2b_model_create(m)
  call b2b_model_add_beam(m, [1, 2, 3, 4, 5, 6], .false., r, B2B_CURVE_LINEAR, 0, beam)
  call b2b_model_add_beam(m, [7, 8, 9, 10, 11, 12], .false., r, B2B_CURVE_LINEAR, 1, beam)
  call b2b_model_set_group_pair(m, 0, 1, p)
  call b2b_model_finalize(m, 12)
  do k = 1, 6
    x(:, k) = [0.5_c_double * (k - 1), 0.0_c_double, 0.0_c_double]
    x(:, 6 + k) = [0.5_c_double * (k - 1) + 0.2_c_double, 0.0_c_double, 0.15_c_double]
  end do

  ! before any update: B2B_ERR_STATE, n untouched
  n = isentinel
  call b2b_model_audit(m, 0.0_c_double, n, ierr=ierr, errmsg=msg)
  call check(ierr == B2B_ERR_STATE, 'audit before an update: B2B_ERR_STATE')
  call check(contains_text(msg, 'b2b_model_update'), 'state message names the update: ' // trim(msg))
  call check(n == isentinel, 'n untouched before an update')

  call b2b_model_update(m, x)
  n_query = isentinel
  call b2b_model_audit(m, 0.01_c_double, n_query, ierr=ierr, errmsg=msg)
  call check(ierr == B2B_OK .and. msg == '', 'size query succeeds')
  pairs = isentinel
  reasons = isentinel
  overlap = -7.0_c_double
  call b2b_model_audit(m, 0.01_c_double, n, pairs, overlap, reasons, ierr)
  call check(ierr == B2B_OK, 'audit succeeds')
  call check(n == n_query .and. n == 9, 'parallel: 9 overlapping pairs, got ' // int_str(n))
  found_middle = .false.
  do k = 1, n
    call check(reasons(k) == B2B_AUDIT_PARALLEL, 'reason PARALLEL')
    call check(abs(overlap(k) - 0.05_c_double) < 1.0e-9_c_double, 'overlap 0.05')
    call check(pairs(1, k) == 1 .and. pairs(3, k) == 2, 'beams 1 and 2 (1-based)')
    call check(all(pairs([2, 4], k) >= 1) .and. all(pairs([2, 4], k) <= 5), 'segments 1..5')
    if (pairs(2, k) == 3 .and. pairs(4, k) == 3) found_middle = .true.
  end do
  call check(found_middle, 'the middle segments (3, 3) are listed')
  call check(all(reasons(n + 1:) == isentinel), 'nothing written beyond n')

  ! a tolerance above the overlap hides them
  call b2b_model_audit(m, 0.51_c_double, n, pairs, overlap, reasons)
  call check(n == 0, 'tolerance 0.51 r: no finding')

  ! error paths: outputs untouched
  n = isentinel
  small_pairs = isentinel
  small_reasons = isentinel
  small_overlap = -7.0_c_double
  call b2b_model_audit(m, 0.01_c_double, n, small_pairs, small_overlap, small_reasons, ierr, msg)
  call check(ierr == B2B_ERR_SIZE, 'capacity 2 < 9: B2B_ERR_SIZE')
  call check(contains_text(msg, '9 findings'), 'message gives the count: ' // trim(msg))
  call check(n == isentinel .and. all(small_pairs == isentinel) .and. &
             all(small_reasons == isentinel) .and. all(small_overlap == -7.0_c_double), &
             'capacity: outputs untouched')
  call b2b_model_audit(m, 0.01_c_double, n, bad_pairs, overlap, reasons, ierr, msg)
  call check(ierr == B2B_ERR_SIZE .and. contains_text(msg, '(4,n)'), 'pairs (3, n): ' // trim(msg))
  call b2b_model_audit(m, 0.01_c_double, n, pairs, overlap, ierr=ierr, errmsg=msg)
  call check(ierr == B2B_ERR_NULL .and. contains_text(msg, 'reasons'), 'reasons missing: ' // &
             trim(msg))
  call b2b_model_audit(m, -1.0_c_double, n, ierr=ierr, errmsg=msg)
  call check(ierr == B2B_ERR_RANGE .and. contains_text(msg, 'tolerance'), 'negative tolerance')
  call b2b_model_audit(m, ieee_value(0.0_c_double, ieee_quiet_nan), n, ierr=ierr, errmsg=msg)
  call check(ierr == B2B_ERR_NONFINITE .and. contains_text(msg, 'tolerance'), 'NaN tolerance')
  call check(n == isentinel, 'n untouched by the errors')
  call b2b_model_destroy(m)

  ! --- crossed beams in contact (Hermite nodal): the force is carried, audit empty
  call b2b_model_create(m)
  call b2b_model_add_beam(m, [1, 2, 3, 4, 5], .false., r, B2B_CURVE_HERMITE_NODAL, 0, beam)
  call b2b_model_add_beam(m, [6, 7, 8, 9, 10], .false., r, B2B_CURVE_HERMITE_NODAL, 1, beam)
  call b2b_model_set_group_pair(m, 0, 1, p)
  call b2b_model_finalize(m, 10)
  do k = 1, 5
    x(:, k) = [-1.0_c_double + 0.55_c_double * (k - 1), 0.0_c_double, 0.0_c_double]
    x(:, 5 + k) = [0.05_c_double, -1.0_c_double + 0.55_c_double * (k - 1), 0.19_c_double]
  end do
  call b2b_model_update(m, x(:, 1:10))
  call b2b_model_contact_count(m, k)
  call check(k == 1, 'crossed beams: one contact')
  call b2b_model_audit(m, 0.0_c_double, n)
  call check(n == 0, 'crossed beams in contact: empty audit, got ' // int_str(n))
  call b2b_model_destroy(m)
  call b2b_params_destroy(p)
  call check_summary('ftest_model_audit')
end program
