!> The line-contact element through module b2b: b2b_pair_eval_line and
!> b2b_pair_line_points.
!>
!> The geometry: two straight LINEAR segments along x, A from (0, 0, d) to
!> (L, 0, d) above B from (-1, 0, 0) to (3, 0, 0), radii 0.05 each, d = 0.1 -
!> pen: A lies on B along its whole length, penetrating by pen. With
!> line_penalty eps_L the line load is eps_L * pen and the integrated force
!> eps_L * pen * L for every number of points (the point element calls this
!> pair PARALLEL: it carries nothing).
!>
!>  * ACTIVE, line_info: the force, all points active and owned, the length
!>    L, the smallest gap -pen; the residual -F/2 along z on A's two nodes
!>    and F in all on B's two (shared by where A lies over B), and the
!>    potential's axial term eps_L pen^2 / 2 on A's first node along x;
!>    point_info(XI) the Gauss points, symmetric about 0; the tangent
!>    symmetric;
!>  * the module equals a direct call of the C function bit for bit;
!>  * b2b_pair_line_points: the default rule 3 + ceil(L / (r_A + r_B));
!>  * n_points 0 is B2B_ERR_RANGE, a hist_old of the wrong size B2B_ERR_SIZE,
!>    hist_new sharing hist_old B2B_ERR_RANGE, line_info of size 15
!>    B2B_ERR_SIZE, point_info of the wrong shape B2B_ERR_SIZE; outputs
!>    untouched.
program ftest_pair_line
  use, intrinsic :: iso_c_binding, only: c_double, c_int, c_ptr, c_null_ptr, c_loc, c_char, &
                                         c_null_char
  use b2b
  use ftest_check
  implicit none

  interface
    function c_eval_line(params, segments, X, end_tangents, radii, n_points, hist_old, &
                         hist_new, hist_len, contact_status, line_info, point_info, residual, &
                         tangent, ldk, errmsg, errmsg_len) &
        bind(C, name='b2b_pair_eval_line') result(st)
      import :: c_int, c_double, c_ptr, c_char
      type(c_ptr), value :: params
      integer(c_int), intent(in) :: segments(6)
      real(c_double), intent(in) :: X(*)
      type(c_ptr), value :: end_tangents
      real(c_double), intent(in) :: radii(*)
      integer(c_int), value :: n_points
      real(c_double), intent(in) :: hist_old(*)
      real(c_double), intent(inout) :: hist_new(*)
      integer(c_int), value :: hist_len
      integer(c_int), intent(inout) :: contact_status
      real(c_double), intent(inout) :: line_info(*)
      type(c_ptr), value :: point_info
      real(c_double), intent(inout) :: residual(*)
      type(c_ptr), value :: tangent
      integer(c_int), value :: ldk
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function
    function c_params_create(params, errmsg, errmsg_len) bind(C, name='b2b_params_create') &
        result(st)
      import :: c_int, c_ptr, c_char
      type(c_ptr), intent(inout) :: params
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function
  end interface

  real(c_double), parameter :: eps_l = 2.0e3_c_double, pen = 0.004_c_double, len = 1.3_c_double
  real(c_double), parameter :: radii(2) = [0.05_c_double, 0.05_c_double]
  integer, parameter :: seg(3, 2) = reshape([B2B_CURVE_LINEAR, B2B_END_NEIGHBOUR, &
                                             B2B_END_NEIGHBOUR, B2B_CURVE_LINEAR, &
                                             B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR], [3, 2])
  integer, parameter :: np = 5
  real(c_double) :: X(3, 8)
  type(b2b_params) :: p
  integer :: nh, ierr

  X = 0
  X(:, 2) = [0.0_c_double, 0.0_c_double, 0.1_c_double - pen]  ! A's x2, x3 (slots 1, 4 unused)
  X(:, 3) = [len, 0.0_c_double, 0.1_c_double - pen]
  X(:, 6) = [-1.0_c_double, 0.0_c_double, 0.0_c_double]         ! B's x2, x3
  X(:, 7) = [3.0_c_double, 0.0_c_double, 0.0_c_double]

  call b2b_params_create(p, ierr)
  call b2b_params_set_real(p, 'penalty', 1.0_c_double, ierr)
  call b2b_params_set_int(p, 'contact_type', B2B_CONTACT_TYPE_LINE, ierr)
  call check(ierr == B2B_OK, 'set contact_type')
  call b2b_params_set_real(p, 'line_penalty', eps_l, ierr)
  call b2b_params_finalize(p, ierr)
  call check(ierr == B2B_OK, 'finalize')
  call b2b_params_history_size(p, nh)

  call test_closed_form()
  call test_module_equals_c()
  call test_line_points()
  call test_bad_input()

  call b2b_params_destroy(p)
  call check_summary('ftest_pair_line')

contains

  subroutine test_closed_form()
    real(c_double) :: h0((np + 1) * nh), h1((np + 1) * nh), li(B2B_LINE_INFO_LEN), r(24)
    real(c_double) :: k(24, 24), pinfo(B2B_PAIR_INFO_LEN, np), f
    integer :: status, i
    h0 = 0
    call b2b_pair_eval_line(p, seg, X, radii, np, h0, h1, status, li, r, k, pinfo, ierr=ierr)
    call check(ierr == B2B_OK, 'closed form: ierr')
    call check(status == B2B_CONTACT_ACTIVE, 'closed form: ACTIVE, got ' // int_str(status))
    f = eps_l * pen * len
    call check(abs(li(B2B_IX_LINE_INFO_NORMAL_FORCE) - f) <= 1e-12_c_double * f, &
               'closed form: force eps_L pen L')
    call check(nint(li(B2B_IX_LINE_INFO_ACTIVE_POINTS)) == np, 'closed form: all points active')
    call check(nint(li(B2B_IX_LINE_INFO_OWNED_POINTS)) == np, 'closed form: all points owned')
    call check(abs(li(B2B_IX_LINE_INFO_LENGTH) - len) <= 1e-14_c_double, 'closed form: length')
    call check(abs(li(B2B_IX_LINE_INFO_MIN_GAP) + pen) <= 1e-14_c_double, 'closed form: min gap')
    call check(abs(r(6) + 0.5_c_double * f) <= 1e-12_c_double * f .and. &
               abs(r(9) + 0.5_c_double * f) <= 1e-12_c_double * f, 'closed form: A pushed up')
    call check(abs(r(18) + r(21) - f) <= 1e-12_c_double * f .and. r(18) > 0 .and. r(21) > 0, &
               'closed form: B pushed down by F in all')
    ! the length term: pi = eps_L pen^2 / 2 per unit length, dJ/dX_A = -+1/(2 J) on x
    call check(abs(r(4) + 0.5_c_double * eps_l * pen**2) <= 1e-12_c_double * f, &
               'closed form: axial length term')
    do i = 1, np
      call check(abs(pinfo(B2B_IX_INFO_XI, i) + pinfo(B2B_IX_INFO_XI, np + 1 - i)) <= &
                 1e-15_c_double, 'closed form: Gauss points symmetric')
    end do
    call check(maxval(abs(k - transpose(k))) <= 1e-12_c_double * maxval(abs(k)), &
               'closed form: tangent symmetric')
    call check(li(B2B_IX_LINE_INFO_SYMMETRIC) == 1.0_c_double, 'closed form: reported symmetric')
  end subroutine

  subroutine test_module_equals_c()
    real(c_double), target :: h0((np + 1) * nh), h1((np + 1) * nh), li(B2B_LINE_INFO_LEN)
    real(c_double), target :: r(24), k(24, 24), pinfo(B2B_PAIR_INFO_LEN, np)
    real(c_double), target :: g1((np + 1) * nh), li2(B2B_LINE_INFO_LEN), r2(24), k2(24, 24)
    real(c_double), target :: pinfo2(B2B_PAIR_INFO_LEN, np)
    type(c_ptr) :: cp
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer :: status
    integer(c_int) :: st, cstatus
    h0 = 0
    call b2b_pair_eval_line(p, seg, X, radii, np, h0, h1, status, li, r, k, pinfo, ierr=ierr)
    ! the C function with its own handle: the same parameters set through C
    cp = c_null_ptr
    buf = c_null_char
    st = c_params_create(cp, buf, int(size(buf), c_int))
    call check(st == B2B_OK, 'C params')
    call set_c(cp)
    st = c_eval_line(cp, int(reshape(seg, [6]), c_int), X, c_null_ptr, radii, int(np, c_int), &
                     h0, g1, int(size(h0), c_int), cstatus, li2, c_loc(pinfo2), r2, c_loc(k2), &
                     24_c_int, buf, int(size(buf), c_int))
    call check(st == B2B_OK, 'C call')
    call check(all(li == li2) .and. all(r == r2) .and. all(k == k2) .and. all(h1 == g1) .and. &
               all(pinfo == pinfo2) .and. status == cstatus, 'module = C bit for bit')
    call destroy_c(cp)
  end subroutine

  subroutine set_c(cp)
    type(c_ptr), intent(inout) :: cp
    interface
      function c_set_real(params, key, value, errmsg, errmsg_len) &
          bind(C, name='b2b_params_set_real') result(st)
        import :: c_int, c_double, c_ptr, c_char
        type(c_ptr), value :: params
        character(kind=c_char), intent(in) :: key(*)
        real(c_double), value :: value
        character(kind=c_char), intent(inout) :: errmsg(*)
        integer(c_int), value :: errmsg_len
        integer(c_int) :: st
      end function
      function c_set_int(params, key, value, errmsg, errmsg_len) &
          bind(C, name='b2b_params_set_int') result(st)
        import :: c_int, c_ptr, c_char
        type(c_ptr), value :: params
        character(kind=c_char), intent(in) :: key(*)
        integer(c_int), value :: value
        character(kind=c_char), intent(inout) :: errmsg(*)
        integer(c_int), value :: errmsg_len
        integer(c_int) :: st
      end function
      function c_finalize(params, errmsg, errmsg_len) bind(C, name='b2b_params_finalize') &
          result(st)
        import :: c_int, c_ptr, c_char
        type(c_ptr), value :: params
        character(kind=c_char), intent(inout) :: errmsg(*)
        integer(c_int), value :: errmsg_len
        integer(c_int) :: st
      end function
    end interface
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    st = c_set_real(cp, 'penalty' // c_null_char, 1.0_c_double, buf, int(size(buf), c_int))
    st = c_set_int(cp, 'contact_type' // c_null_char, int(B2B_CONTACT_TYPE_LINE, c_int), buf, &
                   int(size(buf), c_int))
    st = c_set_real(cp, 'line_penalty' // c_null_char, eps_l, buf, int(size(buf), c_int))
    st = c_finalize(cp, buf, int(size(buf), c_int))
    call check(st == B2B_OK, 'C finalize')
  end subroutine

  subroutine destroy_c(cp)
    type(c_ptr), intent(inout) :: cp
    interface
      function c_destroy(params) bind(C, name='b2b_params_destroy') result(st)
        import :: c_int, c_ptr
        type(c_ptr), intent(inout) :: params
        integer(c_int) :: st
      end function
    end interface
    integer(c_int) :: st
    st = c_destroy(cp)
  end subroutine

  subroutine test_line_points()
    integer :: n
    n = -1
    call b2b_pair_line_points(p, 1.0_c_double, 0.05_c_double, 0.05_c_double, n, ierr)
    call check(ierr == B2B_OK .and. n == 13, 'line_points: 3 + ceil(1 / 0.1) = 13, got ' // &
               int_str(n))
    n = -1
    call b2b_pair_line_points(p, -1.0_c_double, 0.05_c_double, 0.05_c_double, n, ierr)
    call check(ierr == B2B_ERR_RANGE .and. n == -1, 'line_points: negative length refused')
  end subroutine

  subroutine test_bad_input()
    real(c_double), target :: h0((np + 1) * nh), h1((np + 1) * nh), li(B2B_LINE_INFO_LEN)
    real(c_double) :: r(24), li15(15), pbad(B2B_PAIR_INFO_LEN, np + 1)
    character(len=256) :: msg
    integer :: status
    h0 = 0
    h1 = -3
    li = -3
    r = -3
    status = -3
    call b2b_pair_eval_line(p, seg, X, radii, 0, h0, h1, status, li, r, ierr=ierr, errmsg=msg)
    call check(ierr == B2B_ERR_RANGE .and. index(msg, 'n_points') > 0, 'n_points 0: ' // trim(msg))
    call b2b_pair_eval_line(p, seg, X, radii, np, h0(1:np * nh), h1(1:np * nh), status, li, r, &
                            ierr=ierr, errmsg=msg)
    call check(ierr == B2B_ERR_SIZE .and. index(msg, 'size(hist_old)') > 0, 'history size: ' // &
               trim(msg))
    call b2b_pair_eval_line(p, seg, X, radii, np, h0, h0, status, li, r, ierr=ierr, errmsg=msg)
    call check(ierr == B2B_ERR_RANGE, 'hist_new = hist_old: ' // trim(msg))
    call b2b_pair_eval_line(p, seg, X, radii, np, h0, h1, status, li15, r, ierr=ierr, &
                            errmsg=msg)
    call check(ierr == B2B_ERR_SIZE .and. index(msg, 'line_info') > 0, 'line_info(15): ' // &
               trim(msg))
    call b2b_pair_eval_line(p, seg, X, radii, np, h0, h1, status, li, r, point_info=pbad, &
                            ierr=ierr, errmsg=msg)
    call check(ierr == B2B_ERR_SIZE .and. index(msg, 'point_info') > 0, 'point_info shape: ' // &
               trim(msg))
    call check(all(h1 == -3) .and. all(li == -3) .and. all(r == -3) .and. status == -3, &
               'bad input: outputs untouched')
  end subroutine

end program
