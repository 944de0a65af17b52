!> The end contact through module b2b: b2b_pair_eval_ends.
!>
!> The geometry: beam A a straight LINEAR segment standing on end along z,
!> its start node x2 = (0, 0, 0.05) above the middle of beam B, a straight
!> LINEAR segment along x from (-1, 0, 0) to (1, 0, 0). With radii 0.03 and
!> 0.03 the node penetrates: gap 0.05 - 0.06 = -0.01, and with penalty 100
!> f_N = 100 * 0.01 = 1, the normal +z (from B to A). The free pair
!> (b2b_pair_eval) cannot see this contact: the two axes meet below A's
!> start (no force).
!>
!>  * ends = [-1, 0]: ACTIVE, the gap and f_N in closed form, xi = -1, eta = 0,
!>    info(B2B_IX_INFO_END_A) = -1, info(B2B_IX_INFO_END_B) = 0; the residual
!>    (-f_N dg/dX) is -f_N along z on A's node x2 and +f_N/2 on each of B's
!>    nodes x2, x3, zero elsewhere; the tangent is symmetric;
!>  * ends = [0, 0] is b2b_pair_eval bit for bit (no force here);
!>  * ends out of range (2, -2) is B2B_ERR_RANGE through ierr, with a message
!>    naming ends and the outputs untouched; ends of size 1 or 3 is
!>    B2B_ERR_SIZE.
program ftest_pair_ends
  use, intrinsic :: iso_c_binding, only: c_double
  use b2b
  use ftest_check
  implicit none

  real(c_double), parameter :: eps_n = 100.0_c_double, sentinel = -7.0_c_double
  real(c_double), parameter :: radii(2) = [0.03_c_double, 0.03_c_double]
  integer, parameter :: seg(3, 2) = reshape([B2B_CURVE_LINEAR, B2B_END_NEIGHBOUR, &
                                             B2B_END_NEIGHBOUR, B2B_CURVE_LINEAR, &
                                             B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR], [3, 2])
  real(c_double) :: X(3, 8)
  type(b2b_params) :: p
  integer :: nh, ierr

  X(:, 1) = [0.0_c_double, 0.0_c_double, -0.95_c_double]  ! A: x1 .. x4 along z
  X(:, 2) = [0.0_c_double, 0.0_c_double, 0.05_c_double]
  X(:, 3) = [0.0_c_double, 0.0_c_double, 1.05_c_double]
  X(:, 4) = [0.0_c_double, 0.0_c_double, 2.05_c_double]
  X(:, 5) = [-3.0_c_double, 0.0_c_double, 0.0_c_double]   ! B: x1 .. x4 along x
  X(:, 6) = [-1.0_c_double, 0.0_c_double, 0.0_c_double]
  X(:, 7) = [1.0_c_double, 0.0_c_double, 0.0_c_double]
  X(:, 8) = [3.0_c_double, 0.0_c_double, 0.0_c_double]

  call b2b_params_create(p, ierr)
  call check(ierr == B2B_OK, 'params_create')
  call b2b_params_set_real(p, 'penalty', eps_n, ierr)
  call b2b_params_finalize(p, ierr)
  call check(ierr == B2B_OK, 'finalize')
  call b2b_params_history_size(p, nh)

  call test_node_to_segment()
  call test_free_is_pair_eval()
  call test_bad_ends()

  call b2b_params_destroy(p)
  call check_summary('ftest_pair_ends')

contains

  subroutine test_node_to_segment()
    real(c_double) :: h0(nh), h1(nh), info(B2B_PAIR_INFO_LEN), r(24), k(24, 24), f, want(24)
    integer :: status
    h0 = 0
    call b2b_pair_eval_ends(p, seg, X, radii, [-1, 0], h0, h1, status, info, r, k, ierr=ierr)
    call check(ierr == B2B_OK, 'node to segment: ierr')
    call check(status == B2B_CONTACT_ACTIVE, 'node to segment: ACTIVE, got ' // int_str(status))
    f = eps_n * 0.01_c_double
    call check(abs(info(B2B_IX_INFO_GAP) + 0.01_c_double) <= 1e-15_c_double, &
               'node to segment: gap -0.01')
    call check(abs(info(B2B_IX_INFO_NORMAL_FORCE) - f) <= 1e-13_c_double * f, &
               'node to segment: f_N = penalty * 0.01')
    call check(info(B2B_IX_INFO_XI) == -1.0_c_double, 'node to segment: xi = -1')
    call check(abs(info(B2B_IX_INFO_ETA)) <= 1e-15_c_double, 'node to segment: eta = 0')
    call check(info(B2B_IX_INFO_END_A) == -1.0_c_double, 'info(B2B_IX_INFO_END_A) = -1')
    call check(info(B2B_IX_INFO_END_B) == 0.0_c_double, 'info(B2B_IX_INFO_END_B) = 0')
    call check(abs(info(B2B_IX_INFO_NORMAL + 2) - 1.0_c_double) <= 1e-15_c_double, &
               'node to segment: normal +z')
    want = 0
    want(6) = -f            ! A's x2, z
    want(18) = 0.5_c_double * f  ! B's x2, z
    want(21) = 0.5_c_double * f  ! B's x3, z
    call check(maxval(abs(r - want)) <= 1e-13_c_double * f, 'node to segment: residual')
    call check(maxval(abs(k - transpose(k))) <= 1e-13_c_double * maxval(abs(k)), &
               'node to segment: symmetric tangent')
    call check(maxval(abs(k)) > 0, 'node to segment: a tangent')
  end subroutine

  subroutine test_free_is_pair_eval()
    real(c_double) :: h0(nh), h1(nh), h2(nh), i1(B2B_PAIR_INFO_LEN), i2(B2B_PAIR_INFO_LEN)
    real(c_double) :: r1(24), r2(24), k1(24, 24), k2(24, 24)
    integer :: s1, s2
    logical :: same
    h0 = 0
    call b2b_pair_eval(p, seg, X, radii, h0, h1, s1, i1, r1, k1, ierr=ierr)
    call check(ierr == B2B_OK, 'free: b2b_pair_eval')
    call b2b_pair_eval_ends(p, seg, X, radii, [0, 0], h0, h2, s2, i2, r2, k2, ierr=ierr)
    call check(ierr == B2B_OK, 'free: b2b_pair_eval_ends')
    ! the axes meet below A's start: the free pair carries no force
    call check(s1 /= B2B_CONTACT_ACTIVE .and. s2 == s1, 'free: no contact, the same status')
    same = same_bits(i1(1:B2B_IX_INFO_END_A - 1), i2(1:B2B_IX_INFO_END_A - 1)) .and. &
           same_bits(r1, r2) .and. same_bits(reshape(k1, [576]), reshape(k2, [576])) .and. &
           same_bits(h1, h2)
    ! the END entries echo ends (0 here, as b2b_pair_eval writes them)
    same = same .and. same_bits(i1, i2)
    call check(same, 'ends = [0, 0] is b2b_pair_eval bit for bit')
  end subroutine

  subroutine test_bad_ends()
    real(c_double) :: h0(nh), h1(nh), info(B2B_PAIR_INFO_LEN), r(24)
    integer :: status
    character(len=B2B_ERRMSG_LEN) :: msg
    h0 = 0
    h1 = sentinel
    info = sentinel
    r = sentinel
    status = -77
    call b2b_pair_eval_ends(p, seg, X, radii, [2, 0], h0, h1, status, info, r, ierr=ierr, &
                            errmsg=msg)
    call check(ierr == B2B_ERR_RANGE, 'ends(1) = 2: B2B_ERR_RANGE, got ' // int_str(ierr))
    call check(contains_text(msg, 'ends'), 'ends(1) = 2: message names ends: ' // trim(msg))
    call check(status == -77 .and. all_equal_to(h1, sentinel) .and. &
               all_equal_to(info, sentinel) .and. all_equal_to(r, sentinel), &
               'ends(1) = 2: outputs untouched')
    call b2b_pair_eval_ends(p, seg, X, radii, [0, -2], h0, h1, status, info, r, ierr=ierr)
    call check(ierr == B2B_ERR_RANGE, 'ends(2) = -2: B2B_ERR_RANGE')
    call b2b_pair_eval_ends(p, seg, X, radii, [-1, 0, 0], h0, h1, status, info, r, ierr=ierr, &
                            errmsg=msg)
    call check(ierr == B2B_ERR_SIZE, 'size(ends) = 3: B2B_ERR_SIZE, got ' // int_str(ierr))
    call check(contains_text(msg, 'ends'), 'size(ends) = 3: message names ends: ' // trim(msg))
    call b2b_pair_eval_ends(p, seg, X, radii, [1], h0, h1, status, info, r, ierr=ierr)
    call check(ierr == B2B_ERR_SIZE, 'size(ends) = 1: B2B_ERR_SIZE')
    call check(status == -77 .and. all_equal_to(h1, sentinel), 'bad sizes: outputs untouched')
  end subroutine

end program
