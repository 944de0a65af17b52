!> Error paths of module b2b's contact procedures with ierr and errmsg
!> present: the status, a message naming the problem, and outputs left
!> untouched on failure (pre-filled with a sentinel); on success ierr == 0 and
!> errmsg == ''. Also the life cycle of a handle: destroy is idempotent, a
!> null handle is reported, not dereferenced.
program ftest_pair_errors
  use, intrinsic :: iso_c_binding, only: c_double
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf
  use b2b
  use ftest_check
  implicit none

  real(c_double), parameter :: sentinel = -7.0_c_double
  integer, parameter :: isentinel = -77
  real(c_double), parameter :: radii0(2) = [0.2_c_double, 0.15_c_double]
  integer, parameter :: segs0(3, 2) = reshape([ &
    B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, &
    B2B_CURVE_LINEAR, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR], [3, 2])

  ! A finalized handle, its history length, a valid crossing.
  type(b2b_params) :: p
  integer :: n
  real(c_double) :: X0(3, 8)
  real(c_double), allocatable :: hist0(:)
  ! Outputs of b2b_pair_eval, reset to the sentinel before every call.
  real(c_double), allocatable :: hist_new(:)
  real(c_double) :: info(32), residual(24), tangent(24, 24)
  integer :: status, ierr
  character(len=B2B_ERRMSG_LEN) :: msg

  call setup()
  call test_handle_life_cycle()
  call test_state()
  call test_keys_and_values()
  call test_shapes()
  call test_bad_values()
  call test_success_clears()
  call b2b_params_destroy(p)
  deallocate (hist0, hist_new)
  call check_summary('ftest_pair_errors')

contains

  subroutine setup()
    real(c_double), parameter :: xa(4) = [-1.5_c_double, -0.5_c_double, 0.6_c_double, &
                                          1.4_c_double]
    real(c_double), parameter :: yb(4) = [-1.4_c_double, -0.5_c_double, 0.5_c_double, &
                                          1.6_c_double]
    integer :: k
    do k = 1, 4
      X0(:, k) = [xa(k), 0.1_c_double * xa(k), 0.05_c_double * xa(k)**2]
      X0(:, 4 + k) = [0.1_c_double + 0.05_c_double * yb(k), yb(k), &
                      -0.3_c_double - 0.03_c_double * yb(k)**2]
    end do
    call b2b_params_create(p, ierr, msg)
    call check(ierr == B2B_OK, 'setup: create [' // trim(msg) // ']')
    call b2b_params_set_real(p, 'penalty', 1.0e3_c_double, ierr, msg)
    call check(ierr == B2B_OK, 'setup: set penalty [' // trim(msg) // ']')
    call b2b_params_finalize(p, ierr, msg)
    call check(ierr == B2B_OK, 'setup: finalize [' // trim(msg) // ']')
    n = 0
    call b2b_params_history_size(p, n, ierr, msg)
    call check(ierr == B2B_OK .and. n > 0, 'setup: history_size > 0 [' // trim(msg) // ']')
    if (n <= 0) call check_summary('ftest_pair_errors')
    allocate (hist0(n), hist_new(n))
    hist0 = 0
    ! The valid configuration succeeds and is an active contact.
    call reset()
    call b2b_pair_eval(p, segs0, X0, radii0, hist0, hist_new, status, info, residual, tangent, &
                       ierr=ierr, errmsg=msg)
    call check(ierr == B2B_OK .and. status == B2B_CONTACT_ACTIVE, &
               'setup: the reference crossing is active [' // trim(msg) // ']')
  end subroutine

  subroutine reset()
    hist_new = sentinel
    info = sentinel
    residual = sentinel
    tangent = sentinel
    status = isentinel
    ierr = isentinel
    msg = 'garbage'
  end subroutine

  logical function outputs_untouched()
    outputs_untouched = all_equal_to(hist_new, sentinel) .and. all_equal_to(info, sentinel) &
                        .and. all_equal_to(residual, sentinel) .and. &
                        all_equal_to(reshape(tangent, [576]), sentinel) .and. &
                        status == isentinel
  end function

  !> ierr == expected and a non-empty errmsg that contains `needle`.
  subroutine expect_status(label, expected, needle)
    character(len=*), intent(in) :: label, needle
    integer, intent(in) :: expected
    call check(ierr == expected, label // ': ierr ' // int_str(ierr) // ' == ' // &
               int_str(expected) // ' [' // trim(msg) // ']')
    call check(len_trim(msg) > 0, label // ': errmsg is not empty')
    call check(contains_text(msg, needle), label // ': errmsg "' // trim(msg) // &
               '" contains "' // needle // '"')
  end subroutine

  !> The same, and every output of b2b_pair_eval untouched.
  subroutine expect_failure(label, expected, needle)
    character(len=*), intent(in) :: label, needle
    integer, intent(in) :: expected
    call expect_status(label, expected, needle)
    call check(outputs_untouched(), label // ': outputs untouched')
  end subroutine

  ! -------------------------------------------------------- handle life cycle

  subroutine test_handle_life_cycle()
    type(b2b_params) :: q, never
    real(c_double) :: v
    integer :: iv, m

    ! Destroying a never-created handle, and destroying twice, is safe.
    call b2b_params_destroy(never)
    call b2b_params_destroy(never)
    call b2b_params_create(q, ierr, msg)
    call check(ierr == B2B_OK, 'create q [' // trim(msg) // ']')
    call b2b_params_destroy(q)
    call b2b_params_destroy(q)
    call b2b_params_destroy(q, ierr, msg)
    call check(ierr == B2B_OK .and. msg == '', 'destroy a third time: ierr == 0, errmsg == ''''')

    ! A null handle (never created, or destroyed) is reported as NULL.
    call reset()
    call b2b_pair_eval(never, segs0, X0, radii0, hist0, hist_new, status, info, residual, &
                       tangent, ierr=ierr, errmsg=msg)
    call expect_failure('eval with a never-created handle', B2B_ERR_NULL, 'params')
    call reset()
    call b2b_pair_eval(q, segs0, X0, radii0, hist0, hist_new, status, info, residual, &
                       tangent, ierr=ierr, errmsg=msg)
    call expect_failure('eval with a destroyed handle', B2B_ERR_NULL, 'params')
    call reset()
    call b2b_params_set_real(q, 'penalty', 1.0_c_double, ierr, msg)
    call expect_status('set_real on a destroyed handle', B2B_ERR_NULL, 'params')
    call reset()
    call b2b_params_set_int(never, 'law', B2B_LAW_LINEAR, ierr, msg)
    call expect_status('set_int on a never-created handle', B2B_ERR_NULL, 'params')
    v = sentinel
    call reset()
    call b2b_params_get_real(never, 'penalty', v, ierr, msg)
    call expect_status('get_real on a never-created handle', B2B_ERR_NULL, 'params')
    call check(v == sentinel, 'get_real on a never-created handle: value untouched')
    iv = isentinel
    call reset()
    call b2b_params_get_int(never, 'law', iv, ierr, msg)
    call expect_status('get_int on a never-created handle', B2B_ERR_NULL, 'params')
    call check(iv == isentinel, 'get_int on a never-created handle: value untouched')
    call reset()
    call b2b_params_finalize(never, ierr, msg)
    call expect_status('finalize a never-created handle', B2B_ERR_NULL, 'params')
    m = isentinel
    call reset()
    call b2b_params_history_size(never, m, ierr, msg)
    call expect_status('history_size of a never-created handle', B2B_ERR_NULL, 'params')
    call check(m == isentinel, 'history_size of a never-created handle: n untouched')

    ! Creating over a live handle would lose it: B2B_ERR_STATE, and the
    ! handle keeps working.
    call b2b_params_create(q, ierr, msg)
    call check(ierr == B2B_OK, 'create q again [' // trim(msg) // ']')
    call b2b_params_set_real(q, 'penalty', 5.0_c_double, ierr, msg)
    call reset()
    call b2b_params_create(q, ierr, msg)
    call expect_status('create over a live handle', B2B_ERR_STATE, 'destroy')
    v = sentinel
    call b2b_params_get_real(q, 'penalty', v, ierr, msg)
    call check(ierr == B2B_OK .and. v == 5.0_c_double, &
               'create over a live handle: the handle is unchanged')
    call b2b_params_destroy(q)
    call b2b_params_create(q, ierr, msg)
    call check(ierr == B2B_OK, 'create after destroy succeeds [' // trim(msg) // ']')
    call b2b_params_destroy(q)
  end subroutine

  ! -------------------------------------------------------------------- state

  subroutine test_state()
    type(b2b_params) :: q
    integer :: m

    call b2b_params_create(q, ierr, msg)
    call b2b_params_set_real(q, 'penalty', 1.0e3_c_double, ierr, msg)
    call check(ierr == B2B_OK, 'unfinalized q: set penalty [' // trim(msg) // ']')

    ! Evaluating with a handle that is not finalized.
    call reset()
    call b2b_pair_eval(q, segs0, X0, radii0, hist0, hist_new, status, info, residual, &
                       tangent, ierr=ierr, errmsg=msg)
    call expect_failure('eval with unfinalized params', B2B_ERR_STATE, 'finalize')
    call reset()
    call b2b_pair_eval(q, segs0, X0, radii0, hist0, hist_new, status, info, residual, &
                       ierr=ierr, errmsg=msg)
    call expect_failure('eval with unfinalized params, no tangent', B2B_ERR_STATE, 'finalize')
    m = isentinel
    call reset()
    call b2b_params_history_size(q, m, ierr, msg)
    call expect_status('history_size of unfinalized params', B2B_ERR_STATE, 'finalize')
    call check(m == isentinel, 'history_size of unfinalized params: n untouched')

    ! Setting an option after finalize.
    call b2b_params_finalize(q, ierr, msg)
    call check(ierr == B2B_OK, 'finalize q [' // trim(msg) // ']')
    call reset()
    call b2b_params_set_real(q, 'penalty', 2.0e3_c_double, ierr, msg)
    call expect_status('set_real after finalize', B2B_ERR_STATE, 'penalty')
    call reset()
    call b2b_params_set_int(q, 'max_iterations', 10, ierr, msg)
    call expect_status('set_int after finalize', B2B_ERR_STATE, 'max_iterations')
    call b2b_params_destroy(q)

    ! Finalize checks the options together.
    call b2b_params_create(q, ierr, msg)
    call reset()
    call b2b_params_finalize(q, ierr, msg)
    call expect_status('finalize without penalty', B2B_ERR_STATE, 'penalty')
    call b2b_params_set_real(q, 'penalty', 1.0_c_double, ierr, msg)
    call b2b_params_set_int(q, 'law', B2B_LAW_QUADRATIC, ierr, msg)
    call reset()
    call b2b_params_finalize(q, ierr, msg)
    call expect_status('finalize QUADRATIC without regularization_gap', B2B_ERR_STATE, &
                       'regularization_gap')
    call b2b_params_destroy(q)
  end subroutine

  ! ----------------------------------------------------------- keys and values

  subroutine test_keys_and_values()
    type(b2b_params) :: q
    real(c_double) :: v, nan
    integer :: iv

    nan = ieee_value(0.0_c_double, ieee_quiet_nan)
    call b2b_params_create(q, ierr, msg)

    ! Unknown keys name the key.
    call reset()
    call b2b_params_set_real(q, 'stiffness', 1.0_c_double, ierr, msg)
    call expect_status('set_real "stiffness"', B2B_ERR_UNKNOWN_KEY, 'stiffness')
    call reset()
    call b2b_params_set_int(q, 'max_iter', 3, ierr, msg)
    call expect_status('set_int "max_iter"', B2B_ERR_UNKNOWN_KEY, 'max_iter')
    ! A real key is not an integer key, and the other way round.
    call reset()
    call b2b_params_set_int(q, 'penalty', 1, ierr, msg)
    call expect_status('set_int "penalty" (a real key)', B2B_ERR_UNKNOWN_KEY, 'penalty')
    call reset()
    call b2b_params_set_real(q, 'law', 1.0_c_double, ierr, msg)
    call expect_status('set_real "law" (an integer key)', B2B_ERR_UNKNOWN_KEY, 'law')
    ! Keys are case-sensitive; leading blanks are part of the key.
    call reset()
    call b2b_params_set_real(q, 'Penalty', 1.0_c_double, ierr, msg)
    call expect_status('set_real "Penalty"', B2B_ERR_UNKNOWN_KEY, 'Penalty')
    call reset()
    call b2b_params_set_real(q, ' penalty', 1.0_c_double, ierr, msg)
    call expect_status('set_real " penalty"', B2B_ERR_UNKNOWN_KEY, ' penalty')
    v = sentinel
    call reset()
    call b2b_params_get_real(p, 'gap', v, ierr, msg)
    call expect_status('get_real "gap"', B2B_ERR_UNKNOWN_KEY, 'gap')
    call check(v == sentinel, 'get_real "gap": value untouched')
    iv = isentinel
    call reset()
    call b2b_params_get_int(p, 'iterations', iv, ierr, msg)
    call expect_status('get_int "iterations"', B2B_ERR_UNKNOWN_KEY, 'iterations')
    call check(iv == isentinel, 'get_int "iterations": value untouched')

    ! Values out of range.
    call reset()
    call b2b_params_set_real(q, 'penalty', -1.0_c_double, ierr, msg)
    call expect_status('negative penalty', B2B_ERR_RANGE, 'penalty')
    call reset()
    call b2b_params_set_real(q, 'penalty', nan, ierr, msg)
    call expect_status('NaN penalty', B2B_ERR_NONFINITE, 'penalty')
    call reset()
    call b2b_params_set_real(q, 'regularization_gap', 0.0_c_double, ierr, msg)
    call expect_status('regularization_gap 0', B2B_ERR_RANGE, 'regularization_gap')
    call reset()
    call b2b_params_set_real(q, 'parallel_angle', 90.0_c_double, ierr, msg)
    call expect_status('parallel_angle 90', B2B_ERR_RANGE, 'parallel_angle')
    call reset()
    call b2b_params_set_int(q, 'law', B2B_LAW_COUNT, ierr, msg)
    call expect_status('law B2B_LAW_COUNT', B2B_ERR_UNKNOWN_KIND, 'law')
    call reset()
    call b2b_params_set_int(q, 'warm_start', 2, ierr, msg)
    call expect_status('warm_start 2', B2B_ERR_RANGE, 'warm_start')
    call reset()
    call b2b_params_set_int(q, 'max_iterations', 0, ierr, msg)
    call expect_status('max_iterations 0', B2B_ERR_RANGE, 'max_iterations')
    ! A rejected value leaves the option as it was.
    v = sentinel
    call b2b_params_get_real(q, 'parallel_angle', v, ierr, msg)
    call check(ierr == B2B_OK .and. v == 0.5_c_double, 'rejected values change nothing')
    call b2b_params_destroy(q)
  end subroutine

  ! ------------------------------------------------------------- wrong shapes

  subroutine test_shapes()
    integer :: segs33(3, 3), segs23(2, 3)
    real(c_double) :: X37(3, 7), X38(3, 9), X83(8, 3), radii3(3), info31(31), res23(23)
    real(c_double) :: tan2024(20, 24), tan2423(24, 23), tan2425(24, 25), et32(3, 2)
    real(c_double), allocatable :: h_long(:), h_short(:), h_long2(:), h_empty(:), h_empty2(:)

    segs33 = B2B_END_NEIGHBOUR
    segs33(:, 1:2) = segs0
    call reset()
    call b2b_pair_eval(p, segs33, X0, radii0, hist0, hist_new, status, info, residual, &
                       tangent, ierr=ierr, errmsg=msg)
    call expect_failure('segments(3,3)', B2B_ERR_SIZE, ' segments ')
    call check(contains_text(msg, '(3,3)') .and. contains_text(msg, '(3,2)'), &
               'segments(3,3): errmsg gives the shapes')
    segs23 = 0
    call reset()
    call b2b_pair_eval(p, segs23, X0, radii0, hist0, hist_new, status, info, residual, &
                       tangent, ierr=ierr, errmsg=msg)
    call expect_failure('segments(2,3)', B2B_ERR_SIZE, ' segments ')

    X37 = X0(:, 1:7)
    call reset()
    call b2b_pair_eval(p, segs0, X37, radii0, hist0, hist_new, status, info, residual, &
                       tangent, ierr=ierr, errmsg=msg)
    call expect_failure('X(3,7)', B2B_ERR_SIZE, ' X ')
    call check(contains_text(msg, '(3,7)') .and. contains_text(msg, '(3,8)'), &
               'X(3,7): errmsg gives the shapes')
    X38 = 0
    call reset()
    call b2b_pair_eval(p, segs0, X38, radii0, hist0, hist_new, status, info, residual, &
                       tangent, ierr=ierr, errmsg=msg)
    call expect_failure('X(3,9)', B2B_ERR_SIZE, ' X ')
    X83 = 0
    call reset()
    call b2b_pair_eval(p, segs0, X83, radii0, hist0, hist_new, status, info, residual, &
                       tangent, ierr=ierr, errmsg=msg)
    call expect_failure('X(8,3)', B2B_ERR_SIZE, ' X ')

    radii3 = 0.1_c_double
    call reset()
    call b2b_pair_eval(p, segs0, X0, radii3, hist0, hist_new, status, info, residual, &
                       tangent, ierr=ierr, errmsg=msg)
    call expect_failure('radii(3)', B2B_ERR_SIZE, ' radii ')

    info31 = sentinel
    call reset()
    call b2b_pair_eval(p, segs0, X0, radii0, hist0, hist_new, status, info31, residual, &
                       tangent, ierr=ierr, errmsg=msg)
    call expect_failure('info(31)', B2B_ERR_SIZE, ' info ')
    call check(all_equal_to(info31, sentinel), 'info(31): info untouched')

    res23 = sentinel
    call reset()
    call b2b_pair_eval(p, segs0, X0, radii0, hist0, hist_new, status, info, res23, &
                       tangent, ierr=ierr, errmsg=msg)
    call expect_failure('residual(23)', B2B_ERR_SIZE, ' residual ')
    call check(all_equal_to(res23, sentinel), 'residual(23): residual untouched')

    tan2024 = sentinel
    call reset()
    call b2b_pair_eval(p, segs0, X0, radii0, hist0, hist_new, status, info, residual, &
                       tan2024, ierr=ierr, errmsg=msg)
    call expect_failure('tangent(20,24)', B2B_ERR_SIZE, ' tangent ')
    call check(contains_text(msg, '(20,24)') .and. contains_text(msg, '>= 24'), &
               'tangent(20,24): errmsg gives the shape and the rule')
    call check(all_equal_to(reshape(tan2024, [480]), sentinel), 'tangent(20,24): untouched')
    tan2423 = sentinel
    call reset()
    call b2b_pair_eval(p, segs0, X0, radii0, hist0, hist_new, status, info, residual, &
                       tan2423, ierr=ierr, errmsg=msg)
    call expect_failure('tangent(24,23)', B2B_ERR_SIZE, ' tangent ')
    call check(all_equal_to(reshape(tan2423, [552]), sentinel), 'tangent(24,23): untouched')
    tan2425 = sentinel
    call reset()
    call b2b_pair_eval(p, segs0, X0, radii0, hist0, hist_new, status, info, residual, &
                       tan2425, ierr=ierr, errmsg=msg)
    call expect_failure('tangent(24,25)', B2B_ERR_SIZE, ' tangent ')
    call check(all_equal_to(reshape(tan2425, [600]), sentinel), 'tangent(24,25): untouched')

    et32 = 1.0_c_double
    call reset()
    call b2b_pair_eval(p, segs0, X0, radii0, hist0, hist_new, status, info, residual, &
                       tangent, end_tangents=et32, ierr=ierr, errmsg=msg)
    call expect_failure('end_tangents(3,2)', B2B_ERR_SIZE, ' end_tangents ')

    ! History of the wrong length (both arrays): the library's check.
    allocate (h_long(n + 1), h_long2(n + 1), h_short(n - 1), h_empty(0), h_empty2(0))
    h_long = 0
    h_long2 = sentinel
    call reset()
    call b2b_pair_eval(p, segs0, X0, radii0, h_long, h_long2, status, info, residual, &
                       tangent, ierr=ierr, errmsg=msg)
    call expect_failure('history of length n + 1', B2B_ERR_SIZE, &
                        'size(hist_old) is ' // int_str(n + 1))
    call check(all_equal_to(h_long2, sentinel), 'history of length n + 1: hist_new untouched')
    h_short = 0
    h_long2 = sentinel
    call reset()
    call b2b_pair_eval(p, segs0, X0, radii0, h_short, h_long2(1:n - 1), status, info, &
                       residual, tangent, ierr=ierr, errmsg=msg)
    call expect_failure('history of length n - 1', B2B_ERR_SIZE, &
                        'size(hist_old) is ' // int_str(n - 1))
    call check(all_equal_to(h_long2, sentinel), 'history of length n - 1: hist_new untouched')
    call reset()
    call b2b_pair_eval(p, segs0, X0, radii0, h_empty, h_empty2, status, info, residual, &
                       tangent, ierr=ierr, errmsg=msg)
    call expect_failure('history of length 0', B2B_ERR_SIZE, 'size(hist_old) is 0')

    ! hist_old and hist_new of different sizes: the module's check.
    h_long2 = sentinel
    call reset()
    call b2b_pair_eval(p, segs0, X0, radii0, hist0, h_long2, status, info, residual, &
                       tangent, ierr=ierr, errmsg=msg)
    call expect_failure('hist_old(n), hist_new(n+1)', B2B_ERR_SIZE, 'hist_new')
    call check(contains_text(msg, 'hist_old'), 'hist_old(n), hist_new(n+1): errmsg names ' // &
               'hist_old [' // trim(msg) // ']')
    call check(all_equal_to(h_long2, sentinel), 'hist_old(n), hist_new(n+1): hist_new untouched')
    call reset()
    call b2b_pair_eval(p, segs0, X0, radii0, h_long, hist_new, status, info, residual, &
                       tangent, ierr=ierr, errmsg=msg)
    call expect_failure('hist_old(n+1), hist_new(n)', B2B_ERR_SIZE, 'hist_new')

    ! The whole shape message.
    call reset()
    call b2b_pair_eval(p, segs0, X37, radii0, hist0, hist_new, status, info, residual, &
                       ierr=ierr, errmsg=msg)
    call check(trim(msg) == 'b2b_pair_eval: X has shape (3,7), expected (3,8)', &
               'shape message: "' // trim(msg) // '"')

    ! ierr without errmsg.
    call reset()
    call b2b_pair_eval(p, segs0, X37, radii0, hist0, hist_new, status, info, residual, &
                       tangent, ierr=ierr)
    call check(ierr == B2B_ERR_SIZE .and. outputs_untouched(), &
               'X(3,7), ierr without errmsg: B2B_ERR_SIZE, outputs untouched')
  end subroutine

  ! --------------------------------------------------------------- bad values

  subroutine test_bad_values()
    real(c_double) :: X(3, 8), radii(2), h(n), et(3, 4), nan, inf
    integer :: segs(3, 2), i

    nan = ieee_value(0.0_c_double, ieee_quiet_nan)
    inf = ieee_value(0.0_c_double, ieee_positive_inf)

    ! A NaN coordinate of beam B: every coordinate of B's used nodes x2, x3
    ! (columns 6 and 7).
    do i = 1, 3
      X = X0
      X(i, 6) = nan
      call reset()
      call b2b_pair_eval(p, segs0, X, radii0, hist0, hist_new, status, info, residual, &
                         tangent, ierr=ierr, errmsg=msg)
      call expect_failure('NaN in X(' // int_str(i) // ',6)', B2B_ERR_NONFINITE, 'beam B')
      call check(contains_text(msg, 'x2'), 'NaN in X(' // int_str(i) // &
                 ',6): errmsg names node x2')
    end do
    X = X0
    X(3, 7) = inf
    call reset()
    call b2b_pair_eval(p, segs0, X, radii0, hist0, hist_new, status, info, residual, &
                       ierr=ierr, errmsg=msg)
    call expect_failure('Inf in X(3,7), no tangent', B2B_ERR_NONFINITE, 'beam B')
    ! And of beam A.
    X = X0
    X(1, 1) = nan
    call reset()
    call b2b_pair_eval(p, segs0, X, radii0, hist0, hist_new, status, info, residual, &
                       tangent, ierr=ierr, errmsg=msg)
    call expect_failure('NaN in X(1,1)', B2B_ERR_NONFINITE, 'beam A')
    ! B is LINEAR: its slots x1, x4 (columns 5 and 8) are never read.
    X = X0
    X(:, 5) = nan
    X(:, 8) = nan
    call reset()
    call b2b_pair_eval(p, segs0, X, radii0, hist0, hist_new, status, info, residual, &
                       tangent, ierr=ierr, errmsg=msg)
    call check(ierr == B2B_OK .and. status == B2B_CONTACT_ACTIVE, &
               'LINEAR beam B ignores NaN in its unused slots [' // trim(msg) // ']')

    ! Radii.
    radii = [0.2_c_double, -0.15_c_double]
    call reset()
    call b2b_pair_eval(p, segs0, X0, radii, hist0, hist_new, status, info, residual, &
                       tangent, ierr=ierr, errmsg=msg)
    call expect_failure('negative radius of B', B2B_ERR_RANGE, 'radius')
    call check(contains_text(msg, 'beam B'), 'negative radius of B: errmsg names beam B')
    radii = [-0.2_c_double, 0.15_c_double]
    call reset()
    call b2b_pair_eval(p, segs0, X0, radii, hist0, hist_new, status, info, residual, &
                       tangent, ierr=ierr, errmsg=msg)
    call expect_failure('negative radius of A', B2B_ERR_RANGE, 'beam A')
    radii = [0.2_c_double, nan]
    call reset()
    call b2b_pair_eval(p, segs0, X0, radii, hist0, hist_new, status, info, residual, &
                       tangent, ierr=ierr, errmsg=msg)
    call expect_failure('NaN radius', B2B_ERR_NONFINITE, 'radius')

    ! Unknown kind and rule, per beam.
    segs = segs0
    segs(1, 2) = 17
    call reset()
    call b2b_pair_eval(p, segs, X0, radii0, hist0, hist_new, status, info, residual, &
                       tangent, ierr=ierr, errmsg=msg)
    call expect_failure('kind 17 for B', B2B_ERR_UNKNOWN_KIND, 'beam B')
    call check(contains_text(msg, '17'), 'kind 17 for B: errmsg names 17')
    segs = segs0
    segs(3, 1) = 9
    call reset()
    call b2b_pair_eval(p, segs, X0, radii0, hist0, hist_new, status, info, residual, &
                       tangent, ierr=ierr, errmsg=msg)
    call expect_failure('end_rule 9 for A', B2B_ERR_UNKNOWN_KIND, 'end_rule')

    ! B2B_END_TANGENT without end_tangents; with a NaN end tangent.
    segs = segs0
    segs(2, 1) = B2B_END_TANGENT
    call reset()
    call b2b_pair_eval(p, segs, X0, radii0, hist0, hist_new, status, info, residual, &
                       tangent, ierr=ierr, errmsg=msg)
    call expect_failure('A start TANGENT without end_tangents', B2B_ERR_NULL, 'end_tangents')
    et = 1.0_c_double
    et(2, 1) = nan
    call reset()
    call b2b_pair_eval(p, segs, X0, radii0, hist0, hist_new, status, info, residual, &
                       tangent, end_tangents=et, ierr=ierr, errmsg=msg)
    call expect_failure('A start TANGENT NaN', B2B_ERR_NONFINITE, 'beam A')

    ! Coincident nodes of B.
    X = X0
    X(:, 7) = X(:, 6)
    call reset()
    call b2b_pair_eval(p, segs0, X, radii0, hist0, hist_new, status, info, residual, &
                       tangent, ierr=ierr, errmsg=msg)
    call expect_failure('B x2 == x3', B2B_ERR_COINCIDENT, 'beam B')

    ! A history that b2b did not write, or with a NaN.
    h = 5.0_c_double
    call reset()
    call b2b_pair_eval(p, segs0, X0, radii0, h, hist_new, status, info, residual, &
                       tangent, ierr=ierr, errmsg=msg)
    call expect_failure('history filled with 5', B2B_ERR_RANGE, 'hist_old')
    h = 0
    h(n) = nan
    call reset()
    call b2b_pair_eval(p, segs0, X0, radii0, h, hist_new, status, info, residual, &
                       tangent, ierr=ierr, errmsg=msg)
    call expect_failure('history with a NaN', B2B_ERR_NONFINITE, 'hist_old')
  end subroutine

  ! ----------------------------------------------------------- success clears

  subroutine test_success_clears()
    type(b2b_params) :: q
    real(c_double) :: v
    integer :: iv, m

    call reset()
    call b2b_params_create(q, ierr, msg)
    call check(ierr == 0 .and. msg == '', 'create: success clears')
    call reset()
    call b2b_params_set_real(q, 'penalty', 10.0_c_double, ierr, msg)
    call check(ierr == 0 .and. msg == '', 'set_real: success clears')
    call reset()
    call b2b_params_set_int(q, 'law', B2B_LAW_LINEAR, ierr, msg)
    call check(ierr == 0 .and. msg == '', 'set_int: success clears')
    call reset()
    call b2b_params_get_real(q, 'penalty', v, ierr, msg)
    call check(ierr == 0 .and. msg == '', 'get_real: success clears')
    call reset()
    call b2b_params_get_int(q, 'law', iv, ierr, msg)
    call check(ierr == 0 .and. msg == '', 'get_int: success clears')
    call reset()
    call b2b_params_finalize(q, ierr, msg)
    call check(ierr == 0 .and. msg == '', 'finalize: success clears')
    call reset()
    call b2b_params_history_size(q, m, ierr, msg)
    call check(ierr == 0 .and. msg == '' .and. m == n, 'history_size: success clears')
    call reset()
    call b2b_pair_eval(q, segs0, X0, radii0, hist0, hist_new, status, info, residual, &
                       tangent, ierr=ierr, errmsg=msg)
    call check(ierr == 0 .and. msg == '', 'pair_eval: success clears')
    call check(status == B2B_CONTACT_ACTIVE .and. .not. all_equal_to(hist_new, sentinel) .and. &
               .not. all_equal_to(info, sentinel) .and. .not. all_equal_to(residual, sentinel) &
               .and. .not. any(tangent == sentinel), 'pair_eval: success writes every output')
    call reset()
    call b2b_params_destroy(q, ierr, msg)
    call check(ierr == 0 .and. msg == '', 'destroy: success clears')
  end subroutine

end program ftest_pair_errors
