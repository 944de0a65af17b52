!> The aliasing rule of module b2b's histories.
!>
!> C lets hist_new be hist_old (b2b_pair_eval) and hist_to be hist_from
!> (b2b_pair_history_handover). Fortran does not: hist_old is intent(in), and
!> an argument may not change through another one during the call. Compilers
!> let such a call through (gfortran 12 without a word, even with -Wall), so
!> the module checks it:
!>  * the same array for both, or two overlapping sections of one array, is
!>    B2B_ERR_RANGE with a message naming both arguments, and nothing is
!>    written (history, status, info, residual);
!>  * the documented way to update in place, hist_old=(h), hist_new=h (a
!>    parenthesised copy), works and gives bit for bit what two distinct
!>    arrays give;
!>  * distinct arrays, and two disjoint sections of one array, pass.
!> The geometry is a friction pair (so that the history holds a force),
!> pressed, committed and moved, as in ftest_pair_friction.
program ftest_alias
  use, intrinsic :: iso_c_binding, only: c_double
  use b2b
  use ftest_check
  implicit none

  real(c_double), parameter :: sentinel = -7.0_c_double
  real(c_double), parameter :: radii(2) = [0.2_c_double, 0.15_c_double]
  integer, parameter :: segs(3, 2) = reshape([B2B_CURVE_LINEAR, B2B_END_NEIGHBOUR, &
                                              B2B_END_NEIGHBOUR, B2B_CURVE_LINEAR, &
                                              B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR], [3, 2])

  type(b2b_params) :: p
  integer :: n
  real(c_double), allocatable :: committed(:)

  call make_params()
  call make_history()
  call test_pair_eval()
  call test_handover()
  call b2b_params_destroy(p)
  deallocate (committed)  ! a main program's allocatables are not freed at its end (LeakSanitizer)
  call check_summary('ftest_alias')

contains

  subroutine make_params()
    integer :: ierr
    character(len=B2B_ERRMSG_LEN) :: msg
    call b2b_params_create(p, ierr, msg)
    call b2b_params_set_real(p, 'penalty', 100.0_c_double, ierr, msg)
    call b2b_params_set_real(p, 'friction', 0.3_c_double, ierr, msg)
    call b2b_params_set_real(p, 'tangential_penalty', 50.0_c_double, ierr, msg)
    call b2b_params_finalize(p, ierr, msg)
    call check(ierr == B2B_OK, 'params [' // trim(msg) // ']')
    n = 0
    call b2b_params_history_size(p, n, ierr, msg)
    call check(ierr == B2B_OK .and. n > 0, 'history size [' // trim(msg) // ']')
  end subroutine

  !> A along x at z = 0 moved by shift along y, B along y at x = 0.1, z = -0.3:
  !> the contact point lies inside both segments, with gap -0.05.
  function pair_x(shift) result(X)
    real(c_double), intent(in) :: shift
    real(c_double) :: X(3, 8)
    integer :: k
    do k = 1, 4
      X(:, k) = [-2.5_c_double + k, shift, 0.0_c_double]
      X(:, 4 + k) = [0.1_c_double, -2.5_c_double + k, -0.3_c_double]
    end do
  end function

  !> The committed history of the pressed pair (in contact, stick).
  subroutine make_history()
    real(c_double), allocatable :: h0(:)
    real(c_double) :: info(B2B_PAIR_INFO_LEN), residual(B2B_PAIR_NDOF)
    integer :: status, ierr
    character(len=B2B_ERRMSG_LEN) :: msg
    allocate (h0(n), committed(n))
    h0 = 0
    committed = sentinel
    call b2b_pair_eval(p, segs, pair_x(0.0_c_double), radii, h0, committed, status, info, &
                       residual, ierr=ierr, errmsg=msg)
    call check(ierr == B2B_OK .and. status == B2B_CONTACT_ACTIVE, 'press: active [' // &
               trim(msg) // ']')
  end subroutine

  subroutine test_pair_eval()
    real(c_double), allocatable :: h(:), ref(:), w(:), before(:)
    real(c_double) :: X(3, 8), info(B2B_PAIR_INFO_LEN), residual(B2B_PAIR_NDOF), &
                      info_ref(B2B_PAIR_INFO_LEN), res_ref(B2B_PAIR_NDOF)
    integer :: status, status_ref, ierr
    character(len=B2B_ERRMSG_LEN) :: msg

    X = pair_x(0.01_c_double)
    ! The reference: two distinct arrays.
    allocate (ref(n))
    ref = sentinel
    call b2b_pair_eval(p, segs, X, radii, committed, ref, status_ref, info_ref, res_ref, &
                       ierr=ierr, errmsg=msg)
    call check(ierr == B2B_OK .and. msg == '', 'distinct arrays: ierr == 0 [' // trim(msg) // ']')

    ! One array for both: rejected, nothing written.
    h = committed
    status = -77
    info = sentinel
    residual = sentinel
    call b2b_pair_eval(p, segs, X, radii, h, h, status, info, residual, ierr=ierr, errmsg=msg)
    call check(ierr == B2B_ERR_RANGE, 'hist_old = hist_new: B2B_ERR_RANGE, got ' // &
               int_str(ierr) // ' [' // trim(msg) // ']')
    call check(contains_text(msg, 'b2b_pair_eval: hist_new shares memory with hist_old'), &
               'hist_old = hist_new: message names both [' // trim(msg) // ']')
    call check(same_bits(h, committed), 'hist_old = hist_new: history untouched')
    call check(status == -77 .and. all_equal_to(info, sentinel) .and. &
               all_equal_to(residual, sentinel), 'hist_old = hist_new: outputs untouched')

    ! Overlapping sections of one array (shifted by one entry): rejected.
    allocate (w(n + 1))
    w(1:n) = committed
    w(n + 1) = 0
    before = w
    call b2b_pair_eval(p, segs, X, radii, w(1:n), w(2:n + 1), status, info, residual, &
                       ierr=ierr, errmsg=msg)
    call check(ierr == B2B_ERR_RANGE .and. contains_text(msg, 'shares memory'), &
               'overlapping sections: B2B_ERR_RANGE [' // trim(msg) // ']')
    call check(same_bits(w, before), 'overlapping sections: array untouched')

    ! Disjoint sections of one array: fine.
    deallocate (w)
    allocate (w(2 * n))
    w(1:n) = committed
    w(n + 1:) = sentinel
    call b2b_pair_eval(p, segs, X, radii, w(1:n), w(n + 1:2 * n), status, info, residual, &
                       ierr=ierr, errmsg=msg)
    call check(ierr == B2B_OK, 'disjoint sections: ierr == 0 [' // trim(msg) // ']')
    call check(same_bits(w(n + 1:2 * n), ref) .and. same_bits(w(1:n), committed), &
               'disjoint sections: the reference history, hist_old untouched')

    ! In place through a parenthesised copy: the reference result.
    h = committed
    call b2b_pair_eval(p, segs, X, radii, (h), h, status, info, residual, ierr=ierr, errmsg=msg)
    call check(ierr == B2B_OK, 'hist_old=(h), hist_new=h: ierr == 0 [' // trim(msg) // ']')
    call check(same_bits(h, ref), 'hist_old=(h), hist_new=h: h is the new history')
    call check(status == status_ref .and. same_bits(info, info_ref) .and. &
               same_bits(residual, res_ref), 'hist_old=(h), hist_new=h: outputs as distinct')
  end subroutine

  subroutine test_handover()
    real(c_double), allocatable :: h(:), ref(:)
    real(c_double) :: from_X(3, 4), to_X(3, 4)
    integer :: ierr, k
    character(len=B2B_ERRMSG_LEN) :: msg
    integer, parameter :: seg(3) = [B2B_CURVE_LINEAR, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR]

    ! Beam A: segment from x = -0.5 to 0.5, the next one from 0.5 to 1.5.
    do k = 1, 4
      from_X(:, k) = [-2.5_c_double + k, 0.0_c_double, 0.0_c_double]
      to_X(:, k) = [-1.5_c_double + k, 0.0_c_double, 0.0_c_double]
    end do
    allocate (ref(n))
    ref = sentinel
    call b2b_pair_history_handover(p, 1, +1, seg, from_X, seg, to_X, committed, ref, &
                                   ierr=ierr, errmsg=msg)
    call check(ierr == B2B_OK, 'handover, distinct arrays: ierr == 0 [' // trim(msg) // ']')

    h = committed
    call b2b_pair_history_handover(p, 1, +1, seg, from_X, seg, to_X, h, h, ierr=ierr, errmsg=msg)
    call check(ierr == B2B_ERR_RANGE .and. contains_text(msg, &
               'b2b_pair_history_handover: hist_to shares memory with hist_from'), &
               'handover, hist_from = hist_to: B2B_ERR_RANGE, message [' // trim(msg) // ']')
    call check(same_bits(h, committed), 'handover, hist_from = hist_to: untouched')

    h = committed
    call b2b_pair_history_handover(p, 1, +1, seg, from_X, seg, to_X, (h), h, ierr=ierr, &
                                   errmsg=msg)
    call check(ierr == B2B_OK .and. same_bits(h, ref), &
               'handover, hist_from=(h), hist_to=h: the reference result [' // trim(msg) // ']')
  end subroutine

end program ftest_alias
