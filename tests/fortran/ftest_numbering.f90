!> Messages of module b2b's curve and contact-element procedures speak the
!> caller's Fortran numbers (the model's do through its "message_base",
!> tested in ftest_model).
!>  * b2b_beam_segment_patch: a segment outside the beam names the 1-based
!>    range ("segments 1 .. 4"), for open beams and rings, never a 0-based
!>    number;
!>  * b2b_pair_eval: a non-finite history entry is named hist_old(k) with the
!>    Fortran index, and so is the non-zero entry of a "fresh" history (C
!>    writes hist_old[k-1] and "entry k-1");
!>  * b2b_pair_history_handover: the same for hist_from;
!>  * a history of the wrong length is "size(hist_old) is k", not C's
!>    "hist_len is k"; an end tangent the rules need but the caller left out
!>    is "end_tangents is absent", not "NULL" (b2b_segment_eval,
!>    b2b_pair_eval).
!> Each failing call also returns its status and leaves its outputs alone.
program ftest_numbering
  use, intrinsic :: iso_c_binding, only: c_double
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf
  use b2b
  use ftest_check
  implicit none

  real(c_double), parameter :: sentinel = -7.0_c_double
  integer, parameter :: isentinel = -77

  call test_segment_patch()
  call test_pair_history()
  call test_handover_history()
  call test_fortran_terms()
  call check_summary('ftest_numbering')

contains

  !> msg holds needle and no "[" (a C index) nor "segments 0".
  subroutine expect_text(label, msg, needle)
    character(len=*), intent(in) :: label, msg, needle
    call check(contains_text(msg, needle), label // ': "' // trim(msg) // '" contains "' // &
               needle // '"')
    call check(index(msg, '[') == 0 .and. .not. contains_text(msg, 'segments 0'), &
               label // ': no C numbering in "' // trim(msg) // '"')
  end subroutine

  subroutine test_segment_patch()
    integer :: nodes(4), sr, er, ierr, kind, n_seg
    character(len=B2B_ERRMSG_LEN) :: msg
    character(len=8) :: tag

    do kind = B2B_CURVE_LINEAR, B2B_CURVE_HERMITE_NODAL_WEIGHTED
      tag = 'kind ' // int_str(kind)
      ! Open beam of 5 nodes.
      call b2b_beam_segment_count(kind, 5, .false., n_seg, ierr, msg)
      call check(ierr == B2B_OK, trim(tag) // ': count [' // trim(msg) // ']')
      nodes = isentinel
      sr = isentinel
      er = isentinel
      call b2b_beam_segment_patch(kind, 5, .false., 0, nodes, sr, er, ierr, msg)
      call check(ierr == B2B_ERR_RANGE, trim(tag) // ', segment 0: B2B_ERR_RANGE')
      call expect_text(trim(tag) // ', segment 0', msg, 'b2b_beam_segment_patch: segment 0 is ' &
                       // 'out of range: this beam has segments 1 .. ' // int_str(n_seg))
      call check(all(nodes == isentinel) .and. sr == isentinel .and. er == isentinel, &
                 trim(tag) // ', segment 0: outputs untouched')
      call b2b_beam_segment_patch(kind, 5, .false., n_seg + 1, nodes, sr, er, ierr, msg)
      call check(ierr == B2B_ERR_RANGE, trim(tag) // ', segment n + 1: B2B_ERR_RANGE')
      call expect_text(trim(tag) // ', segment n + 1', msg, 'segment ' // int_str(n_seg + 1) // &
                       ' is out of range: this beam has segments 1 .. ' // int_str(n_seg))
      ! A ring of 6 nodes.
      call b2b_beam_segment_count(kind, 6, .true., n_seg, ierr, msg)
      call b2b_beam_segment_patch(kind, 6, .true., -3, nodes, sr, er, ierr, msg)
      call check(ierr == B2B_ERR_RANGE, trim(tag) // ', ring, segment -3: B2B_ERR_RANGE')
      call expect_text(trim(tag) // ', ring, segment -3', msg, 'segment -3 is out of range: ' // &
                       'this beam has segments 1 .. ' // int_str(n_seg))
      ! Both ends of the range are segments.
      call b2b_beam_segment_patch(kind, 6, .true., 1, nodes, sr, er, ierr, msg)
      call check(ierr == B2B_OK, trim(tag) // ', ring, segment 1 [' // trim(msg) // ']')
      call b2b_beam_segment_patch(kind, 6, .true., n_seg, nodes, sr, er, ierr, msg)
      call check(ierr == B2B_OK, trim(tag) // ', ring, last segment [' // trim(msg) // ']')
    end do

    ! A beam the library rejects is still reported by the library, under
    ! the procedure's own name.
    call b2b_beam_segment_patch(B2B_CURVE_LINEAR, 1, .false., 1, nodes, sr, er, ierr, msg)
    call check(ierr == B2B_ERR_RANGE .and. contains_text(msg, 'b2b_beam_segment_patch: ') .and. &
               contains_text(msg, 'at least 2 nodes'), 'one-node beam: the library''s message [' &
               // trim(msg) // ']')
  end subroutine

  !> A finalized parameter set; with friction the history holds a force.
  subroutine make_params(p, friction)
    type(b2b_params), intent(inout) :: p
    logical, intent(in) :: friction
    integer :: ierr
    character(len=B2B_ERRMSG_LEN) :: msg
    call b2b_params_create(p, ierr, msg)
    call b2b_params_set_real(p, 'penalty', 100.0_c_double, ierr, msg)
    if (friction) then
      call b2b_params_set_real(p, 'friction', 0.3_c_double, ierr, msg)
      call b2b_params_set_real(p, 'tangential_penalty', 50.0_c_double, ierr, msg)
    end if
    call b2b_params_finalize(p, ierr, msg)
    call check(ierr == B2B_OK, 'params [' // trim(msg) // ']')
  end subroutine

  !> Two straight segments crossing: A along x, B along y, 0.3 below.
  function pair_x() result(X)
    real(c_double) :: X(3, 8)
    integer :: k
    do k = 1, 4
      X(:, k) = [-2.5_c_double + k, 0.0_c_double, 0.0_c_double]
      X(:, 4 + k) = [0.1_c_double, -2.5_c_double + k, -0.3_c_double]
    end do
  end function

  subroutine test_pair_history()
    type(b2b_params) :: p
    real(c_double), allocatable :: h(:), hnew(:)
    real(c_double) :: info(B2B_PAIR_INFO_LEN), residual(B2B_PAIR_NDOF)
    integer :: segs(3, 2), status, ierr, n, k
    character(len=B2B_ERRMSG_LEN) :: msg

    call make_params(p, .true.)
    call b2b_params_history_size(p, n, ierr, msg)
    allocate (h(n), hnew(n))
    segs = B2B_END_NEIGHBOUR
    segs(1, :) = B2B_CURVE_LINEAR

    ! A NaN or Inf at Fortran index k: the message says hist_old(k).
    do k = 1, n
      h = 0
      if (mod(k, 2) == 1) then
        h(k) = ieee_value(0.0_c_double, ieee_quiet_nan)
      else
        h(k) = ieee_value(0.0_c_double, ieee_positive_inf)
      end if
      hnew = sentinel
      status = isentinel
      call b2b_pair_eval(p, segs, pair_x(), [0.2_c_double, 0.15_c_double], h, hnew, status, &
                         info, residual, ierr=ierr, errmsg=msg)
      call check(ierr == B2B_ERR_NONFINITE, 'hist_old(' // int_str(k) // ') not finite: ' // &
                 'B2B_ERR_NONFINITE')
      call expect_text('hist_old(' // int_str(k) // ') not finite', msg, &
                       'b2b_pair_eval: hist_old(' // int_str(k) // ') is not finite')
      call check(all_equal_to(hnew, sentinel) .and. status == isentinel, &
                 'hist_old(' // int_str(k) // ') not finite: outputs untouched')
    end do

    ! A "fresh" history (format tag hist_old(1) = 0) that is not all zeros.
    do k = 2, n
      h = 0
      h(k) = 1.5_c_double
      call b2b_pair_eval(p, segs, pair_x(), [0.2_c_double, 0.15_c_double], h, hnew, status, &
                         info, residual, ierr=ierr, errmsg=msg)
      call check(ierr == B2B_ERR_RANGE, 'fresh history, hist_old(' // int_str(k) // &
                 ') = 1.5: B2B_ERR_RANGE')
      call expect_text('fresh history, hist_old(' // int_str(k) // ') = 1.5', msg, &
                       'but hist_old(' // int_str(k) // ') is 1.5')
    end do
    call b2b_params_destroy(p)
  end subroutine

  subroutine test_handover_history()
    type(b2b_params) :: p
    real(c_double), allocatable :: h(:), hto(:)
    real(c_double) :: from_X(3, 4), to_X(3, 4)
    integer :: ierr, n, k
    character(len=B2B_ERRMSG_LEN) :: msg
    integer, parameter :: seg(3) = [B2B_CURVE_LINEAR, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR]

    call make_params(p, .true.)
    call b2b_params_history_size(p, n, ierr, msg)
    allocate (h(n), hto(n))
    do k = 1, 4
      from_X(:, k) = [-2.5_c_double + k, 0.0_c_double, 0.0_c_double]
      to_X(:, k) = [-1.5_c_double + k, 0.0_c_double, 0.0_c_double]
    end do
    h = 0
    h(n) = ieee_value(0.0_c_double, ieee_quiet_nan)
    hto = sentinel
    call b2b_pair_history_handover(p, 1, +1, seg, from_X, seg, to_X, h, hto, ierr=ierr, &
                                   errmsg=msg)
    call check(ierr == B2B_ERR_NONFINITE, 'handover, hist_from(n) NaN: B2B_ERR_NONFINITE')
    call expect_text('handover, hist_from(n) NaN', msg, 'b2b_pair_history_handover: ' // &
                     'hist_from(' // int_str(n) // ') is not finite')
    call check(all_equal_to(hto, sentinel), 'handover, hist_from(n) NaN: hist_to untouched')
    h = 0
    h(3) = -2.0_c_double
    call b2b_pair_history_handover(p, 1, +1, seg, from_X, seg, to_X, h, hto, ierr=ierr, &
                                   errmsg=msg)
    call check(ierr == B2B_ERR_RANGE, 'handover, fresh hist_from(3) = -2: B2B_ERR_RANGE')
    call expect_text('handover, fresh hist_from(3) = -2', msg, 'but hist_from(3) is -2')
    call b2b_params_destroy(p)
  end subroutine

  subroutine test_fortran_terms()
    type(b2b_params) :: p
    real(c_double), allocatable :: h(:), hnew(:)
    real(c_double) :: info(B2B_PAIR_INFO_LEN), residual(B2B_PAIR_NDOF), patch(3, 4), x(3, 3)
    integer :: segs(3, 2), status, ierr, n, k
    character(len=B2B_ERRMSG_LEN) :: msg

    call make_params(p, .false.)
    call b2b_params_history_size(p, n, ierr, msg)
    allocate (h(n + 1), hnew(n + 1))
    h = 0
    segs = B2B_END_NEIGHBOUR
    segs(1, :) = B2B_CURVE_LINEAR
    call b2b_pair_eval(p, segs, pair_x(), [0.2_c_double, 0.15_c_double], h, hnew, status, &
                       info, residual, ierr=ierr, errmsg=msg)
    call check(ierr == B2B_ERR_SIZE, 'history of n + 1: B2B_ERR_SIZE')
    call expect_text('history of n + 1', msg, 'b2b_pair_eval: size(hist_old) is ' // &
                     int_str(n + 1) // ' but this parameter set keeps ' // int_str(n))
    call check(.not. contains_text(msg, 'hist_len'), 'history of n + 1: no C argument name')

    ! Beam B's end rule is TANGENT, and no end_tangents are given.
    segs(:, 2) = [B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_TANGENT]
    call b2b_pair_eval(p, segs, pair_x(), [0.2_c_double, 0.15_c_double], h(1:n), hnew(1:n), &
                       status, info, residual, ierr=ierr, errmsg=msg)
    call check(ierr == B2B_ERR_NULL, 'pair, TANGENT rule without end_tangents: B2B_ERR_NULL')
    call expect_text('pair, TANGENT rule without end_tangents', msg, &
                     'beam B: end_tangents is absent')
    call check(.not. contains_text(msg, 'NULL'), 'pair, TANGENT rule: no "NULL" [' // &
               trim(msg) // ']')

    do k = 1, 4
      patch(:, k) = [real(k, c_double), 0.1_c_double * k**2, 0.0_c_double]
    end do
    call b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_TANGENT, B2B_END_NEIGHBOUR, patch, &
                          0.0_c_double, x=x, ierr=ierr, errmsg=msg)
    call check(ierr == B2B_ERR_NULL, 'segment, TANGENT rule without end_tangents: B2B_ERR_NULL')
    call expect_text('segment, TANGENT rule without end_tangents', msg, &
                     'b2b_segment_eval: end_tangents is absent')
    call b2b_params_destroy(p)
  end subroutine

end program ftest_numbering
