!> The 1-based index parameters B2B_IX_* of module b2b.
!>
!> The C index constants (B2B_INFO_*, B2B_COUNT_*, B2B_TOTAL_*) keep their
!> 0-based C values; B2B_IX_<name> is the Fortran index of the same entry,
!> the C value + 1. Checked:
!>  * every B2B_IX_* equals its C constant + 1 and lies inside its array,
!>    and the C constants still have their C values;
!>  * read with B2B_IX_*, the info of a pair whose answer is known by hand
!>    gives that answer: two straight LINEAR segments crossing at right
!>    angles, A along x at z = 0, B along y through x = 0.2 at z = -0.15,
!>    radii 0.1 each, penalty 1000: xi = 0.2, eta = 0, gap -0.05, f_N = 50,
!>    energy eps_N g^2 / 2 = 1.25, angle 90, normal (0, 0, 1); and
!>    info(B2B_INFO_GAP), the misreading the parameters exist to prevent, is
!>    the normal's z;
!>  * counts and totals of the contact model read with B2B_IX_COUNT_* and
!>    B2B_IX_TOTAL_* agree with the contacts the model lists (the same two
!>    beams as a model with 1-based host nodes 1..3 and 4..6).
program ftest_index
  use, intrinsic :: iso_c_binding, only: c_double
  use b2b
  use ftest_check
  implicit none

  real(c_double), parameter :: tol = 1.0e-13_c_double
  real(c_double), parameter :: penalty = 1000.0_c_double, r = 0.1_c_double, &
                               depth = 0.15_c_double, x_cross = 0.2_c_double

  call test_values()
  call test_pair_info()
  call test_model_stats()
  call check_summary('ftest_index')

contains

  subroutine ix(fortran_index, c_value, length, what)
    integer, intent(in) :: fortran_index, c_value, length
    character(len=*), intent(in) :: what
    call check(fortran_index == c_value + 1, what // ': B2B_IX_ == C value + 1')
    call check(fortran_index >= 1 .and. fortran_index <= length, what // ': inside its array')
  end subroutine

  subroutine test_values()
    ! The C values, unchanged (b2b_pair.h, b2b_model.h).
    call check(B2B_INFO_GAP == 11 .and. B2B_INFO_NORMAL == 8 .and. B2B_COUNT_ACTIVE == 2 .and. &
               B2B_TOTAL_MIN_GAP == 4, 'C index constants keep their C values')

    call ix(B2B_IX_INFO_XI, B2B_INFO_XI, B2B_PAIR_INFO_LEN, 'INFO_XI')
    call ix(B2B_IX_INFO_ETA, B2B_INFO_ETA, B2B_PAIR_INFO_LEN, 'INFO_ETA')
    call ix(B2B_IX_INFO_POINT_A, B2B_INFO_POINT_A, B2B_PAIR_INFO_LEN, 'INFO_POINT_A')
    call ix(B2B_IX_INFO_POINT_B, B2B_INFO_POINT_B, B2B_PAIR_INFO_LEN, 'INFO_POINT_B')
    call ix(B2B_IX_INFO_NORMAL, B2B_INFO_NORMAL, B2B_PAIR_INFO_LEN, 'INFO_NORMAL')
    call ix(B2B_IX_INFO_GAP, B2B_INFO_GAP, B2B_PAIR_INFO_LEN, 'INFO_GAP')
    call ix(B2B_IX_INFO_NORMAL_FORCE, B2B_INFO_NORMAL_FORCE, B2B_PAIR_INFO_LEN, &
            'INFO_NORMAL_FORCE')
    call ix(B2B_IX_INFO_ENERGY, B2B_INFO_ENERGY, B2B_PAIR_INFO_LEN, 'INFO_ENERGY')
    call ix(B2B_IX_INFO_ANGLE, B2B_INFO_ANGLE, B2B_PAIR_INFO_LEN, 'INFO_ANGLE')
    call ix(B2B_IX_INFO_ITERATIONS, B2B_INFO_ITERATIONS, B2B_PAIR_INFO_LEN, 'INFO_ITERATIONS')
    call ix(B2B_IX_INFO_SYMMETRIC, B2B_INFO_SYMMETRIC, B2B_PAIR_INFO_LEN, 'INFO_SYMMETRIC')
    call ix(B2B_IX_INFO_TANGENTIAL_FORCE, B2B_INFO_TANGENTIAL_FORCE, B2B_PAIR_INFO_LEN, &
            'INFO_TANGENTIAL_FORCE')
    call ix(B2B_IX_INFO_SLIP, B2B_INFO_SLIP, B2B_PAIR_INFO_LEN, 'INFO_SLIP')
    call ix(B2B_IX_INFO_FRICTION_STATE, B2B_INFO_FRICTION_STATE, B2B_PAIR_INFO_LEN, &
            'INFO_FRICTION_STATE')
    call ix(B2B_IX_INFO_DISSIPATION, B2B_INFO_DISSIPATION, B2B_PAIR_INFO_LEN, 'INFO_DISSIPATION')
    ! The 3-vectors end inside info too.
    call check(B2B_IX_INFO_SLIP + 2 <= B2B_PAIR_INFO_LEN, 'INFO_SLIP: 3 entries inside info')

    call ix(B2B_IX_COUNT_CANDIDATES, B2B_COUNT_CANDIDATES, B2B_MODEL_COUNTS_LEN, 'COUNT_CANDIDATES')
    call ix(B2B_IX_COUNT_EVALUATED, B2B_COUNT_EVALUATED, B2B_MODEL_COUNTS_LEN, 'COUNT_EVALUATED')
    call ix(B2B_IX_COUNT_ACTIVE, B2B_COUNT_ACTIVE, B2B_MODEL_COUNTS_LEN, 'COUNT_ACTIVE')
    call ix(B2B_IX_COUNT_OPEN, B2B_COUNT_OPEN, B2B_MODEL_COUNTS_LEN, 'COUNT_OPEN')
    call ix(B2B_IX_COUNT_OUTSIDE, B2B_COUNT_OUTSIDE, B2B_MODEL_COUNTS_LEN, 'COUNT_OUTSIDE')
    call ix(B2B_IX_COUNT_PARALLEL, B2B_COUNT_PARALLEL, B2B_MODEL_COUNTS_LEN, 'COUNT_PARALLEL')
    call ix(B2B_IX_COUNT_NOT_CONVERGED, B2B_COUNT_NOT_CONVERGED, B2B_MODEL_COUNTS_LEN, &
            'COUNT_NOT_CONVERGED')
    call ix(B2B_IX_COUNT_NO_NORMAL, B2B_COUNT_NO_NORMAL, B2B_MODEL_COUNTS_LEN, 'COUNT_NO_NORMAL')
    call ix(B2B_IX_COUNT_FAR, B2B_COUNT_FAR, B2B_MODEL_COUNTS_LEN, 'COUNT_FAR')
    call ix(B2B_IX_COUNT_SEARCH_BUILDS, B2B_COUNT_SEARCH_BUILDS, B2B_MODEL_COUNTS_LEN, &
            'COUNT_SEARCH_BUILDS')
    call ix(B2B_IX_COUNT_HANDOVERS, B2B_COUNT_HANDOVERS, B2B_MODEL_COUNTS_LEN, 'COUNT_HANDOVERS')
    call ix(B2B_IX_COUNT_LOST, B2B_COUNT_LOST, B2B_MODEL_COUNTS_LEN, 'COUNT_LOST')
    call ix(B2B_IX_COUNT_STICK, B2B_COUNT_STICK, B2B_MODEL_COUNTS_LEN, 'COUNT_STICK')
    call ix(B2B_IX_COUNT_SLIP, B2B_COUNT_SLIP, B2B_MODEL_COUNTS_LEN, 'COUNT_SLIP')

    call ix(B2B_IX_TOTAL_ENERGY, B2B_TOTAL_ENERGY, B2B_MODEL_TOTALS_LEN, 'TOTAL_ENERGY')
    call ix(B2B_IX_TOTAL_DISSIPATION_STEP, B2B_TOTAL_DISSIPATION_STEP, B2B_MODEL_TOTALS_LEN, &
            'TOTAL_DISSIPATION_STEP')
    call ix(B2B_IX_TOTAL_DISSIPATION, B2B_TOTAL_DISSIPATION, B2B_MODEL_TOTALS_LEN, &
            'TOTAL_DISSIPATION')
    call ix(B2B_IX_TOTAL_NORMAL_FORCE, B2B_TOTAL_NORMAL_FORCE, B2B_MODEL_TOTALS_LEN, &
            'TOTAL_NORMAL_FORCE')
    call ix(B2B_IX_TOTAL_MIN_GAP, B2B_TOTAL_MIN_GAP, B2B_MODEL_TOTALS_LEN, 'TOTAL_MIN_GAP')

    ! The constants are default integers, like the procedures' integer
    ! arguments (so a host with a wider default integer can pass them).
    call check(kind(B2B_IX_INFO_GAP) == kind(0) .and. kind(B2B_OK) == kind(0), &
               'integer constants are default integers')
  end subroutine

  !> A finalized parameter set with the linear law.
  subroutine make_params(p)
    type(b2b_params), intent(inout) :: p
    integer :: ierr
    character(len=B2B_ERRMSG_LEN) :: msg
    call b2b_params_create(p, ierr, msg)
    call b2b_params_set_real(p, 'penalty', penalty, ierr, msg)
    call b2b_params_finalize(p, ierr, msg)
    call check(ierr == B2B_OK, 'params [' // trim(msg) // ']')
  end subroutine

  subroutine test_pair_info()
    type(b2b_params) :: p
    integer :: segs(3, 2), status, ierr, n
    real(c_double) :: X(3, 8), info(B2B_PAIR_INFO_LEN), residual(B2B_PAIR_NDOF)
    real(c_double), allocatable :: h0(:), h1(:)
    character(len=B2B_ERRMSG_LEN) :: msg

    call make_params(p)
    n = 0
    call b2b_params_history_size(p, n, ierr, msg)
    allocate (h0(n), h1(n))
    h0 = 0
    ! LINEAR reads only slots x2, x3; the others get plausible neighbours.
    segs = B2B_END_NEIGHBOUR
    segs(1, :) = B2B_CURVE_LINEAR
    X(:, 1:4) = reshape([-2.0_c_double, 0.0_c_double, 0.0_c_double, -1.0_c_double, 0.0_c_double, &
                         0.0_c_double, 1.0_c_double, 0.0_c_double, 0.0_c_double, 2.0_c_double, &
                         0.0_c_double, 0.0_c_double], [3, 4])
    X(:, 5:8) = reshape([x_cross, -2.0_c_double, -depth, x_cross, -1.0_c_double, -depth, &
                         x_cross, 1.0_c_double, -depth, x_cross, 2.0_c_double, -depth], [3, 4])
    status = -1
    info = -7
    call b2b_pair_eval(p, segs, X, [r, r], h0, h1, status, info, residual, ierr=ierr, errmsg=msg)
    call check(ierr == B2B_OK .and. status == B2B_CONTACT_ACTIVE, 'crossing: active [' // &
               trim(msg) // ']')

    call check(abs(info(B2B_IX_INFO_XI) - x_cross) <= tol, 'info(B2B_IX_INFO_XI) == 0.2')
    call check(abs(info(B2B_IX_INFO_ETA)) <= tol, 'info(B2B_IX_INFO_ETA) == 0')
    call check(all(abs(info(B2B_IX_INFO_POINT_A:B2B_IX_INFO_POINT_A + 2) - &
                       [x_cross, 0.0_c_double, 0.0_c_double]) <= tol), &
               'info(B2B_IX_INFO_POINT_A:+2) == (0.2, 0, 0)')
    call check(all(abs(info(B2B_IX_INFO_POINT_B:B2B_IX_INFO_POINT_B + 2) - &
                       [x_cross, 0.0_c_double, -depth]) <= tol), &
               'info(B2B_IX_INFO_POINT_B:+2) == (0.2, 0, -0.15)')
    call check(all(abs(info(B2B_IX_INFO_NORMAL:B2B_IX_INFO_NORMAL + 2) - &
                       [0.0_c_double, 0.0_c_double, 1.0_c_double]) <= tol), &
               'info(B2B_IX_INFO_NORMAL:+2) == (0, 0, 1)')
    call check(abs(info(B2B_IX_INFO_GAP) - (depth - 2 * r)) <= tol, &
               'info(B2B_IX_INFO_GAP) == -0.05, got ' // real_str(info(B2B_IX_INFO_GAP)))
    call check(abs(info(B2B_IX_INFO_NORMAL_FORCE) - penalty * (2 * r - depth)) <= &
               1.0e-9_c_double, 'info(B2B_IX_INFO_NORMAL_FORCE) == 50')
    call check(abs(info(B2B_IX_INFO_ENERGY) - penalty * (2 * r - depth)**2 / 2) <= &
               1.0e-9_c_double, 'info(B2B_IX_INFO_ENERGY) == 1.25')
    call check(abs(info(B2B_IX_INFO_ANGLE) - 90) <= 1.0e-9_c_double, &
               'info(B2B_IX_INFO_ANGLE) == 90')
    call check(info(B2B_IX_INFO_SYMMETRIC) == 1, 'info(B2B_IX_INFO_SYMMETRIC) == 1')
    call check(info(B2B_IX_INFO_FRICTION_STATE) == B2B_FRICTION_NONE, &
               'info(B2B_IX_INFO_FRICTION_STATE) == B2B_FRICTION_NONE')
    ! The misreading: the C constant as a Fortran index is the entry before,
    ! here the normal's z.
    call check(info(B2B_INFO_GAP) == info(B2B_IX_INFO_NORMAL + 2), &
               'info(B2B_INFO_GAP) is the normal''s z, not the gap')
    call b2b_params_destroy(p)
  end subroutine

  subroutine test_model_stats()
    type(b2b_params) :: p
    type(b2b_model) :: m
    integer :: beam, n, k, ierr, counts(B2B_MODEL_COUNTS_LEN)
    real(c_double) :: x(3, 6), info(B2B_PAIR_INFO_LEN), totals(B2B_MODEL_TOTALS_LEN), &
                      min_gap, sum_fn
    character(len=B2B_ERRMSG_LEN) :: msg

    call make_params(p)
    call b2b_model_create(m, ierr, msg)
    call b2b_model_add_beam(m, [1, 2, 3], .false., r, B2B_CURVE_LINEAR, 0, beam, ierr, msg)
    call b2b_model_add_beam(m, [4, 5, 6], .false., r, B2B_CURVE_LINEAR, 0, beam, ierr, msg)
    call b2b_model_set_group_pair(m, 0, 0, p, ierr, msg)
    call b2b_model_finalize(m, 6, ierr, msg)
    call check(ierr == B2B_OK, 'model finalize [' // trim(msg) // ']')
    ! The crossing lies inside segment 2 of beam 1 and segment 1 of beam 2.
    x = reshape([-1.0_c_double, 0.0_c_double, 0.0_c_double, 0.0_c_double, 0.0_c_double, &
                 0.0_c_double, 1.0_c_double, 0.0_c_double, 0.0_c_double, &
                 x_cross, -1.0_c_double, -depth, x_cross, 0.3_c_double, -depth, &
                 x_cross, 1.3_c_double, -depth], [3, 6])
    call b2b_model_update(m, x, ierr=ierr, errmsg=msg)
    call check(ierr == B2B_OK, 'model update [' // trim(msg) // ']')
    n = -1
    call b2b_model_contact_count(m, n, ierr, msg)
    call check(n == 1, 'one contact, got ' // int_str(n))
    min_gap = huge(min_gap)
    sum_fn = 0
    do k = 1, n
      call b2b_model_get_contact(m, k, info=info, ierr=ierr, errmsg=msg)
      min_gap = min(min_gap, info(B2B_IX_INFO_GAP))
      sum_fn = sum_fn + info(B2B_IX_INFO_NORMAL_FORCE)
    end do
    call check(abs(min_gap - (depth - 2 * r)) <= tol, 'model contact gap == -0.05')

    counts = -1
    totals = -1
    call b2b_model_stats(m, counts, totals, ierr, msg)
    call check(ierr == B2B_OK, 'stats [' // trim(msg) // ']')
    call check(counts(B2B_IX_COUNT_ACTIVE) == n, 'counts(B2B_IX_COUNT_ACTIVE) == contact count')
    call check(counts(B2B_IX_COUNT_EVALUATED) >= n, 'counts(B2B_IX_COUNT_EVALUATED) >= count')
    call check(counts(B2B_IX_COUNT_SEARCH_BUILDS) == 1, 'counts(B2B_IX_COUNT_SEARCH_BUILDS) == 1')
    call check(totals(B2B_IX_TOTAL_MIN_GAP) == min_gap, 'totals(B2B_IX_TOTAL_MIN_GAP) == min gap')
    call check(totals(B2B_IX_TOTAL_NORMAL_FORCE) == sum_fn, &
               'totals(B2B_IX_TOTAL_NORMAL_FORCE) == sum of f_N')
    call check(abs(totals(B2B_IX_TOTAL_ENERGY) - penalty * (2 * r - depth)**2 / 2) <= &
               1.0e-9_c_double, 'totals(B2B_IX_TOTAL_ENERGY) == 1.25')
    call b2b_model_destroy(m)
    call b2b_params_destroy(p)
  end subroutine

  function real_str(v) result(s)
    real(c_double), intent(in) :: v
    character(len=:), allocatable :: s
    character(len=32) :: t
    write (t, '(es23.15)') v
    s = trim(adjustl(t))
  end function

end program ftest_index
