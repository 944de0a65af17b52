!> Coulomb friction through module b2b: the friction options of type
!> b2b_params, b2b_pair_eval with friction, and b2b_pair_history_handover.
!>
!> The geometry: beam A a straight 6-node HERMITE_NODAL beam along x with
!> non-uniform nodes, beam B a straight HERMITE_NODAL_WEIGHTED patch along y at
!> x = 0.5, 0.3 below A. With radii 0.2 and 0.15 the gap is -0.05 and the
!> contact point lies in A's segment 3 (nodes 3..4, x in [-0.5, 0.6]). With
!> penalty 100, friction 0.3 and tangential_penalty 50: f_N = 5, mu f_N = 1.5,
!> so moving A sideways (along y) by delta sticks for delta <= 0.03.
!>
!>  * parameters: the friction keys read back; history size 12 with friction,
!>    8 without; finalize without tangential_penalty is B2B_ERR_STATE.
!>  * physics: press (fresh history: active, stick, T = 0), commit, move A by
!>    0.01 along y: stick, T = eps_T delta along +y (B is dragged with A),
!>    no slip, no dissipation, and A's nodal residual (internal forces) adds
!>    up to -f_N n + T (A feels +f_N n - T); by 0.2: slip, |T| = mu f_N, slip
!>    increment (eps_T delta - mu f_N) / eps_T, dissipation mu f_N times that;
!>    the tangent is reported, and is, non-symmetric.
!>  * parity: the module's b2b_pair_eval with friction equals a direct call of
!>    the C function bit for bit (status, info, residual, tangent, history).
!>  * handover (segments from the module's b2b_beam_segment_patch): module ==
!>    direct C call bit for bit, beam = 1 / 2 in Fortran is C's 0 / 1, both
!>    directions, host end tangents (TANGENT rule); and the physics of a handover: the contact
!>    point crosses A's joint 3|4, the pair (3, B) reports OUTSIDE, the pair
!>    (4, B) with the handed-over history slips with the friction force,
!>    while a fresh history would restart in stick with T = 0.
!>  * bad input with ierr: status, message, hist_to untouched.
program ftest_pair_friction
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_ptr, c_char, c_loc, c_null_ptr, &
                                         c_null_char, c_associated
  use b2b
  use ftest_check
  use ftest_capi
  implicit none

  real(c_double), parameter :: sentinel = -7.0_c_double, sentinel_c = -9.0_c_double
  integer, parameter :: isentinel = -77
  real(c_double), parameter :: eps_n = 100.0_c_double, mu = 0.3_c_double, &
                               eps_t = 50.0_c_double
  real(c_double), parameter :: radii0(2) = [0.2_c_double, 0.15_c_double]
  integer, parameter :: n_a = 6
  real(c_double), parameter :: xnode_a(n_a) = [-2.6_c_double, -1.5_c_double, -0.5_c_double, &
                                          0.6_c_double, 1.4_c_double, 2.5_c_double]
  real(c_double), parameter :: yb(4) = [-2.5_c_double, -1.0_c_double, 1.2_c_double, &
                                        2.4_c_double]
  integer, parameter :: kind_a = B2B_CURVE_HERMITE_NODAL
  integer, parameter :: seg_b(3) = [B2B_CURVE_HERMITE_NODAL_WEIGHTED, B2B_END_NEIGHBOUR, &
                                    B2B_END_NEIGHBOUR]
  ! Host end tangents of a segment: first node, last node.
  real(c_double), parameter :: tangents0(3, 2) = reshape([ &
    1.0_c_double, 0.05_c_double, -0.02_c_double, &
    1.0_c_double, -0.1_c_double, 0.08_c_double], [3, 2])

  type(b2b_params) :: p
  type(c_ptr) :: cp
  integer :: nh

  call test_constants()
  call test_params()
  call make_params(p)
  cp = make_c_params()
  nh = 0
  call b2b_params_history_size(p, nh)
  if (nh /= 12) then
    call check(.false., 'history size 12, cannot go on')
    call check_summary('ftest_pair_friction')
  end if
  call test_stick_slip()
  call test_handover_parity()
  call test_handover_physics()
  call test_handover_errors()
  call b2b_params_destroy(p)
  call check(c_params_destroy(cp) == B2B_OK .and. .not. c_associated(cp), 'C destroy')
  call check_summary('ftest_pair_friction')

contains

  ! ------------------------------------------------------------- geometry

  !> Beam A's nodes, moved by shift.
  function beam_a(shift) result(XA)
    real(c_double), intent(in) :: shift(3)
    real(c_double) :: XA(3, n_a)
    integer :: k
    do k = 1, n_a
      XA(:, k) = [xnode_a(k), 0.0_c_double, 0.0_c_double] + shift
    end do
  end function

  !> Segment s of beam A: its (kind, start_rule, end_rule) and patch, from the
  !> module's b2b_beam_segment_patch (a missing slot holds zeros).
  subroutine segment_a(s, XA, seg, patch)
    integer, intent(in) :: s
    real(c_double), intent(in) :: XA(3, n_a)
    integer, intent(out) :: seg(3)
    real(c_double), intent(out) :: patch(3, 4)
    integer :: nodes(4), sr, er, k, ierr
    character(len=B2B_ERRMSG_LEN) :: msg
    nodes = isentinel
    sr = isentinel
    er = isentinel
    call b2b_beam_segment_patch(kind_a, n_a, .false., s, nodes, sr, er, ierr, msg)
    call check(ierr == B2B_OK, 'segment_patch ' // int_str(s) // ' [' // trim(msg) // ']')
    seg = [kind_a, sr, er]
    patch = 0
    do k = 1, 4
      if (nodes(k) > 0) patch(:, k) = XA(:, nodes(k))
    end do
  end subroutine

  !> The pair (segment s of A, B): segments(3,2) and X(3,8).
  subroutine pair_a_b(s, shift, segs, X)
    integer, intent(in) :: s
    real(c_double), intent(in) :: shift(3)
    integer, intent(out) :: segs(3, 2)
    real(c_double), intent(out) :: X(3, 8)
    integer :: k
    call segment_a(s, beam_a(shift), segs(:, 1), X(:, 1:4))
    segs(:, 2) = seg_b
    do k = 1, 4
      X(:, 4 + k) = [0.5_c_double, yb(k), -0.3_c_double]
    end do
  end subroutine

  ! ------------------------------------------------------------- parameters

  !> A finalized friction parameter set through the module.
  subroutine make_params(q)
    type(b2b_params), intent(inout) :: q
    integer :: ierr
    character(len=B2B_ERRMSG_LEN) :: msg
    call b2b_params_create(q, ierr, msg)
    call check(ierr == B2B_OK, 'create [' // trim(msg) // ']')
    call b2b_params_set_real(q, 'penalty', eps_n, ierr, msg)
    call check(ierr == B2B_OK, 'set penalty [' // trim(msg) // ']')
    call b2b_params_set_real(q, 'friction', mu, ierr, msg)
    call check(ierr == B2B_OK .and. msg == '', 'set friction [' // trim(msg) // ']')
    call b2b_params_set_real(q, 'tangential_penalty', eps_t, ierr, msg)
    call check(ierr == B2B_OK .and. msg == '', 'set tangential_penalty [' // trim(msg) // ']')
    call b2b_params_finalize(q, ierr, msg)
    call check(ierr == B2B_OK, 'finalize [' // trim(msg) // ']')
  end subroutine

  !> The same set through direct C calls.
  function make_c_params() result(q)
    type(c_ptr) :: q
    q = c_null_ptr
    call check(c_params_create(q, c_null_ptr, 0_c_int) == B2B_OK .and. c_associated(q), &
               'C create')
    call check(c_params_set_real(q, 'penalty' // c_null_char, eps_n, c_null_ptr, 0_c_int) &
               == B2B_OK, 'C set penalty')
    call check(c_params_set_real(q, 'friction' // c_null_char, mu, c_null_ptr, 0_c_int) &
               == B2B_OK, 'C set friction')
    call check(c_params_set_real(q, 'tangential_penalty' // c_null_char, eps_t, c_null_ptr, &
                                 0_c_int) == B2B_OK, 'C set tangential_penalty')
    call check(c_params_finalize(q, c_null_ptr, 0_c_int) == B2B_OK, 'C finalize')
  end function

  subroutine test_constants()
    call check(B2B_INFO_TANGENTIAL_FORCE == 17, 'B2B_INFO_TANGENTIAL_FORCE == 17')
    call check(B2B_INFO_SLIP == 20, 'B2B_INFO_SLIP == 20')
    call check(B2B_INFO_FRICTION_STATE == 23, 'B2B_INFO_FRICTION_STATE == 23')
    call check(B2B_INFO_DISSIPATION == 24, 'B2B_INFO_DISSIPATION == 24')
    call check(B2B_FRICTION_NONE == 0, 'B2B_FRICTION_NONE == 0')
    call check(B2B_FRICTION_STICK == 1, 'B2B_FRICTION_STICK == 1')
    call check(B2B_FRICTION_SLIP == 2, 'B2B_FRICTION_SLIP == 2')
    call check(B2B_PAIR_INFO_LEN == 32, 'B2B_PAIR_INFO_LEN == 32')
  end subroutine

  subroutine test_params()
    type(b2b_params) :: q, plain, bad
    real(c_double) :: v
    integer :: n, ierr
    character(len=B2B_ERRMSG_LEN) :: msg

    call make_params(q)
    v = sentinel
    call b2b_params_get_real(q, 'friction', v, ierr, msg)
    call check(ierr == B2B_OK .and. v == mu, 'get friction == 0.3')
    v = sentinel
    call b2b_params_get_real(q, 'tangential_penalty', v, ierr, msg)
    call check(ierr == B2B_OK .and. v == eps_t, 'get tangential_penalty == 50')
    n = isentinel
    call b2b_params_history_size(q, n, ierr, msg)
    call check(ierr == B2B_OK .and. n == 12, 'friction: history size ' // int_str(n) // &
               ' == 12')
    call b2b_params_destroy(q)

    ! Frictionless: the default friction is 0, the history is 8 long.
    call b2b_params_create(plain, ierr, msg)
    call b2b_params_set_real(plain, 'penalty', eps_n, ierr, msg)
    v = sentinel
    call b2b_params_get_real(plain, 'friction', v, ierr, msg)
    call check(ierr == B2B_OK .and. v == 0, 'default friction == 0')
    call b2b_params_finalize(plain, ierr, msg)
    call check(ierr == B2B_OK, 'frictionless finalize [' // trim(msg) // ']')
    n = isentinel
    call b2b_params_history_size(plain, n, ierr, msg)
    call check(ierr == B2B_OK .and. n == 8, 'frictionless: history size ' // int_str(n) // &
               ' == 8')
    call b2b_params_destroy(plain)

    ! friction > 0 without tangential_penalty cannot be finalized; bad values.
    call b2b_params_create(bad, ierr, msg)
    call b2b_params_set_real(bad, 'penalty', eps_n, ierr, msg)
    call b2b_params_set_real(bad, 'friction', mu, ierr, msg)
    call b2b_params_finalize(bad, ierr, msg)
    call check(ierr == B2B_ERR_STATE .and. contains_text(msg, 'tangential_penalty'), &
               'finalize with friction, no tangential_penalty: B2B_ERR_STATE [' // &
               trim(msg) // ']')
    call b2b_params_set_real(bad, 'friction', -0.1_c_double, ierr, msg)
    call check(ierr == B2B_ERR_RANGE .and. contains_text(msg, 'friction'), &
               'friction -0.1: B2B_ERR_RANGE [' // trim(msg) // ']')
    call b2b_params_set_real(bad, 'tangential_penalty', 0.0_c_double, ierr, msg)
    call check(ierr == B2B_ERR_RANGE .and. contains_text(msg, 'tangential_penalty'), &
               'tangential_penalty 0: B2B_ERR_RANGE [' // trim(msg) // ']')
    call b2b_params_destroy(bad)
  end subroutine

  ! ------------------------------------------------------------ stick, slip

  !> Module b2b_pair_eval of the pair (A's segment s, B), tangent present;
  !> with vs_c = .true. also compare_c of the same evaluation.
  subroutine eval_f(s, shift, hist_old, hist_new, status, info, res, Kt, label, vs_c)
    integer, intent(in) :: s
    real(c_double), intent(in) :: shift(3), hist_old(:)
    real(c_double), intent(inout) :: hist_new(:), info(32), res(24), Kt(24, 24)
    integer, intent(inout) :: status
    character(len=*), intent(in) :: label
    logical, intent(in), optional :: vs_c
    integer :: segs(3, 2), ierr
    real(c_double) :: X(3, 8)
    character(len=B2B_ERRMSG_LEN) :: msg
    call pair_a_b(s, shift, segs, X)
    hist_new = sentinel
    info = sentinel
    res = sentinel
    Kt = sentinel
    status = isentinel
    call b2b_pair_eval(p, segs, X, radii0, hist_old, hist_new, status, info, res, Kt, &
                       ierr=ierr, errmsg=msg)
    call check(ierr == B2B_OK .and. msg == '', label // ': eval succeeds [' // trim(msg) // ']')
    if (present(vs_c)) then
      if (vs_c) call compare_c(s, shift, hist_old, hist_new, status, info, res, Kt, label)
    end if
  end subroutine

  !> The same through the C function; all outputs must equal the module's.
  subroutine compare_c(s, shift, hist_old, hist_new, status, info, res, Kt, label)
    integer, intent(in) :: s, status
    real(c_double), intent(in) :: shift(3), hist_old(:), hist_new(:), info(32), res(24), &
                                  Kt(24, 24)
    character(len=*), intent(in) :: label
    integer :: segs(3, 2)
    real(c_double) :: X(3, 8)
    integer(c_int), target :: segs_c(6), status_c
    real(c_double), target :: X_c(24), radii_c(2), info_c(32), res_c(24), K_c(576)
    real(c_double), target :: hold_c(12), hnew_c(12)
    character(kind=c_char), target :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    call pair_a_b(s, shift, segs, X)
    segs_c = int(reshape(segs, [6]), c_int)
    X_c = reshape(X, [24])
    radii_c = radii0
    hold_c = hist_old
    hnew_c = sentinel_c
    info_c = sentinel_c
    res_c = sentinel_c
    K_c = sentinel_c
    status_c = -99
    buf = c_null_char
    st = c_pair_eval(cp, c_loc(segs_c), c_loc(X_c), c_null_ptr, c_loc(radii_c), c_loc(hold_c), &
                     c_loc(hnew_c), 12_c_int, c_loc(status_c), c_loc(info_c), c_loc(res_c), &
                     c_loc(K_c), 24_c_int, c_loc(buf), int(size(buf), c_int))
    call check(st == B2B_OK, label // ': C eval succeeds')
    call check(status == status_c, label // ': contact_status module == C')
    call check(same_bits(info, info_c), label // ': info module == C bit for bit')
    call check(same_bits(res, res_c), label // ': residual module == C bit for bit')
    call check(same_bits(reshape(Kt, [576]), K_c), label // ': tangent module == C bit for bit')
    call check(same_bits(hist_new, hnew_c), label // ': hist_new module == C bit for bit')
  end subroutine

  !> The friction part of info: f_N, the tangential force T and the slip
  !> increment.
  subroutine friction_info(info, fn, T, slip)
    real(c_double), intent(in) :: info(32)
    real(c_double), intent(out) :: fn, T(3), slip(3)
    fn = info(B2B_INFO_NORMAL_FORCE + 1)
    T = info(B2B_INFO_TANGENTIAL_FORCE + 1:B2B_INFO_TANGENTIAL_FORCE + 3)
    slip = info(B2B_INFO_SLIP + 1:B2B_INFO_SLIP + 3)
  end subroutine

  subroutine test_stick_slip()
    real(c_double), parameter :: small = 0.01_c_double, large = 0.2_c_double
    real(c_double) :: hist0(12), hist1(12), hist2(12), info(32), res(24), Kt(24, 24)
    real(c_double) :: T(3), slip(3), fn, tnorm, fa(3), excess
    integer :: status, k

    ! Press: fresh history, active, stick with no force yet.
    hist0 = 0
    call eval_f(3, [0.0_c_double, 0.0_c_double, 0.0_c_double], hist0, hist1, status, info, &
                res, Kt, 'press', vs_c=.true.)
    call check(status == B2B_CONTACT_ACTIVE, 'press: active')
    call check(abs(info(B2B_INFO_GAP + 1) + 0.05_c_double) <= 1.0e-12_c_double, &
               'press: gap == -0.05')
    call check(abs(info(B2B_INFO_XI + 1)) < 1 .and. abs(info(B2B_INFO_ETA + 1)) < 1, &
               'press: xi, eta inside the segments')
    call check(info(B2B_INFO_FRICTION_STATE + 1) == B2B_FRICTION_STICK, 'press: stick')
    call check(all_equal_to(info(B2B_INFO_TANGENTIAL_FORCE + 1:B2B_INFO_TANGENTIAL_FORCE + 3), &
               0.0_c_double), 'press: T == 0')
    ! Commit: hist1 is the committed history from here on.

    ! ---- small sideways move: stick, |T| = eps_T delta
    call eval_f(3, [0.0_c_double, small, 0.0_c_double], hist1, hist2, status, info, res, Kt, &
                'stick', vs_c=.true.)
    call friction_info(info, fn, T, slip)
    tnorm = norm2(T)
    call check(status == B2B_CONTACT_ACTIVE, 'stick: active')
    call check(abs(fn - eps_n * 0.05_c_double) <= 1.0e-12_c_double * fn, 'stick: f_N == 5')
    call check(info(B2B_INFO_FRICTION_STATE + 1) == B2B_FRICTION_STICK, 'stick: state ' // &
               int_str(int(info(B2B_INFO_FRICTION_STATE + 1))) // ' == B2B_FRICTION_STICK')
    call check(abs(tnorm - eps_t * small) <= 1.0e-10_c_double * eps_t * small, &
               'stick: |T| == eps_T delta (rel 1e-10)')
    call check(T(2) > 0 .and. abs(T(1)) + abs(T(3)) <= 1.0e-10_c_double * tnorm, &
               'stick: T along +y (B dragged with A)')
    call check(tnorm < mu * fn, 'stick: |T| < mu f_N')
    call check(all_equal_to(slip, 0.0_c_double), 'stick: slip == 0')
    call check(info(B2B_INFO_DISSIPATION + 1) == 0, 'stick: dissipation == 0')
    call check(info(B2B_INFO_SYMMETRIC + 1) == 0, 'stick: tangent reported non-symmetric')
    ! The contact forces on A's nodes add up to -f_N n + T (residual =
    ! internal forces: A is pushed along +n and held back by -T).
    fa = 0
    do k = 1, 4
      fa = fa + res(3 * k - 2:3 * k)
    end do
    call check(maxval(abs(fa - (-fn * info(B2B_INFO_NORMAL + 1:B2B_INFO_NORMAL + 3) + T))) <= &
               1.0e-12_c_double * fn, 'stick: residual on A sums to -f_N n + T')
    call check(all_equal_to(info(26:32), 0.0_c_double), 'stick: reserved info are 0')

    ! ---- large sideways move: slip, |T| = mu f_N
    call eval_f(3, [0.0_c_double, large, 0.0_c_double], hist1, hist2, status, info, res, Kt, &
                'slip', vs_c=.true.)
    call friction_info(info, fn, T, slip)
    tnorm = norm2(T)
    excess = (eps_t * large - mu * fn) / eps_t
    call check(status == B2B_CONTACT_ACTIVE, 'slip: active')
    call check(info(B2B_INFO_FRICTION_STATE + 1) == B2B_FRICTION_SLIP, 'slip: state ' // &
               int_str(int(info(B2B_INFO_FRICTION_STATE + 1))) // ' == B2B_FRICTION_SLIP')
    call check(abs(tnorm - mu * fn) <= 1.0e-12_c_double * mu * fn, 'slip: |T| == mu f_N')
    call check(T(2) > 0, 'slip: T along +y')
    call check(abs(norm2(slip) - excess) <= 1.0e-10_c_double * excess .and. slip(2) > 0, &
               'slip: slip increment (eps_T delta - mu f_N) / eps_T along T')
    call check(info(B2B_INFO_DISSIPATION + 1) > 0, 'slip: dissipation > 0')
    call check(abs(info(B2B_INFO_DISSIPATION + 1) - mu * fn * excess) <= &
               1.0e-10_c_double * mu * fn * excess, 'slip: dissipation == mu f_N |slip|')
    call check(info(B2B_INFO_SYMMETRIC + 1) == 0, 'slip: tangent reported non-symmetric')
    call check(maxval(abs(reshape(Kt - transpose(Kt), [576]))) > 0, 'slip: tangent not symmetric')
  end subroutine

  ! --------------------------------------------------------------- handover

  !> The committed history of the press and a sticking step, for handovers.
  subroutine committed_history(h)
    real(c_double), intent(out) :: h(12)
    real(c_double) :: hist0(12), hist1(12), info(32), res(24), Kt(24, 24)
    integer :: status
    hist0 = 0
    call eval_f(3, [0.0_c_double, 0.0_c_double, 0.0_c_double], hist0, hist1, status, info, &
                res, Kt, 'handover setup press')
    call eval_f(3, [0.0_c_double, 0.01_c_double, 0.0_c_double], hist1, h, status, info, res, &
                Kt, 'handover setup stick')
    call check(status == B2B_CONTACT_ACTIVE, 'handover setup: active')
  end subroutine

  !> Direct C handover; hist_to is written only on success (pre-set to
  !> sentinel_c).
  function c_handover_call(cbeam, direction, from_seg, from_X, to_seg, to_X, hist_from, &
                           hist_to, from_t, to_t) result(st)
    integer, intent(in) :: cbeam, direction, from_seg(3), to_seg(3)
    real(c_double), intent(in) :: from_X(3, 4), to_X(3, 4), hist_from(12)
    real(c_double), intent(out) :: hist_to(12)
    real(c_double), intent(in), optional :: from_t(3, 2), to_t(3, 2)
    integer(c_int) :: st
    integer(c_int), target :: fs(3), ts(3)
    real(c_double), target :: fx(12), tx(12), ft(6), tt(6), hf(12), ht(12)
    character(kind=c_char), target :: buf(B2B_ERRMSG_LEN)
    type(c_ptr) :: pft, ptt
    fs = int(from_seg, c_int)
    ts = int(to_seg, c_int)
    fx = reshape(from_X, [12])
    tx = reshape(to_X, [12])
    hf = hist_from
    ht = sentinel_c
    pft = c_null_ptr
    ptt = c_null_ptr
    if (present(from_t)) then
      ft = reshape(from_t, [6])
      pft = c_loc(ft)
    end if
    if (present(to_t)) then
      tt = reshape(to_t, [6])
      ptt = c_loc(tt)
    end if
    buf = c_null_char
    st = c_pair_history_handover(cp, int(cbeam, c_int), int(direction, c_int), c_loc(fs), &
                                 c_loc(fx), pft, c_loc(ts), c_loc(tx), ptt, c_loc(hf), &
                                 c_loc(ht), 12_c_int, c_loc(buf), int(size(buf), c_int))
    hist_to = ht
  end function

  subroutine test_handover_parity()
    real(c_double) :: h(12), hf(12), hc(12), hc_other(12), XA(3, n_a)
    real(c_double) :: P3(3, 4), P4(3, 4), P5(3, 4)
    integer :: s3(3), s4(3), s5(3), s5t(3), ierr, beam
    character(len=B2B_ERRMSG_LEN) :: msg
    character(len=:), allocatable :: label

    call committed_history(h)
    XA = beam_a([0.0_c_double, 0.01_c_double, 0.0_c_double])
    call segment_a(3, XA, s3, P3)
    call segment_a(4, XA, s4, P4)
    call segment_a(5, XA, s5, P5)
    call check(all(s3 == [kind_a, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR]) .and. &
               all(s5 == [kind_a, B2B_END_NEIGHBOUR, B2B_END_REFLECT]), &
               'segment_patch: interior rules, REFLECT at the beam end')

    ! Both beams, both directions; Fortran beam b is C beam b - 1.
    do beam = 1, 2
      label = 'handover beam ' // int_str(beam) // ' 3 -> 4'
      hf = sentinel
      call b2b_pair_history_handover(p, beam, +1, s3, P3, s4, P4, h, hf, ierr=ierr, errmsg=msg)
      call check(ierr == B2B_OK .and. msg == '', label // ': succeeds [' // trim(msg) // ']')
      call check(c_handover_call(beam - 1, +1, s3, P3, s4, P4, h, hc) == B2B_OK, &
                 label // ': C succeeds')
      call check(same_bits(hf, hc), label // ': module == C (beam ' // int_str(beam - 1) // &
                 ') bit for bit')
      call check(c_handover_call(2 - beam, +1, s3, P3, s4, P4, h, hc_other) == B2B_OK .and. &
                 .not. same_bits(hf, hc_other), label // ': differs from C beam ' // &
                 int_str(2 - beam) // ' (the other parameter is mapped)')
      call check(.not. same_bits(hf, h), label // ': the history changed')

      label = 'handover beam ' // int_str(beam) // ' 4 -> 3'
      hf = sentinel
      call b2b_pair_history_handover(p, beam, -1, s4, P4, s3, P3, h, hf, ierr=ierr, errmsg=msg)
      call check(ierr == B2B_OK, label // ': succeeds [' // trim(msg) // ']')
      call check(c_handover_call(beam - 1, -1, s4, P4, s3, P3, h, hc) == B2B_OK .and. &
                 same_bits(hf, hc), label // ': module == C bit for bit')
    end do

    ! Host end tangents: segment 5 ends at the beam end, with a TANGENT rule.
    s5t = [kind_a, B2B_END_NEIGHBOUR, B2B_END_TANGENT]
    label = 'handover 4 -> 5 (TANGENT end)'
    hf = sentinel
    call b2b_pair_history_handover(p, 1, +1, s4, P4, s5t, P5, h, hf, &
                                   to_end_tangents=tangents0, ierr=ierr, errmsg=msg)
    call check(ierr == B2B_OK, label // ': succeeds [' // trim(msg) // ']')
    call check(c_handover_call(0, +1, s4, P4, s5t, P5, h, hc, to_t=tangents0) == B2B_OK .and. &
               same_bits(hf, hc), label // ': module == C bit for bit')
    label = 'handover 5 -> 4 (TANGENT end)'
    hf = sentinel
    call b2b_pair_history_handover(p, 1, -1, s5t, P5, s4, P4, h, hf, &
                                   from_end_tangents=tangents0, ierr=ierr, errmsg=msg)
    call check(ierr == B2B_OK, label // ': succeeds [' // trim(msg) // ']')
    call check(c_handover_call(0, -1, s5t, P5, s4, P4, h, hc, from_t=tangents0) == B2B_OK &
               .and. same_bits(hf, hc), label // ': module == C bit for bit')

    ! A fresh history (no contact) is copied as it is; success without ierr
    ! returns normally.
    hc = 0
    hf = sentinel
    call b2b_pair_history_handover(p, 1, +1, s3, P3, s4, P4, hc, hf)
    call check(all_equal_to(hf, 0.0_c_double), 'handover of a fresh history: a copy')
  end subroutine

  !> The contact point crosses A's joint 3|4: A moves by -0.2 along its axis,
  !> so the material point at x = 0.7 (segment 4) now touches B at x = 0.5.
  subroutine test_handover_physics()
    real(c_double), parameter :: shift(3) = [-0.2_c_double, 0.0_c_double, 0.0_c_double]
    real(c_double) :: hist0(12), hist1(12), hist2(12), hto(12), info(32), res(24), Kt(24, 24)
    real(c_double) :: XA(3, n_a), P3(3, 4), P4(3, 4), T(3), slip(3), fn, gt
    integer :: s3(3), s4(3), status, ierr
    character(len=B2B_ERRMSG_LEN) :: msg

    ! Press at rest and commit (stick, T = 0, anchors at the contact point).
    hist0 = 0
    call eval_f(3, [0.0_c_double, 0.0_c_double, 0.0_c_double], hist0, hist1, status, info, &
                res, Kt, 'crossing: press')
    call check(status == B2B_CONTACT_ACTIVE, 'crossing: press active on segment 3')

    ! The old pair no longer owns the point.
    call eval_f(3, shift, hist1, hist2, status, info, res, Kt, 'crossing: pair (3, B)')
    call check(status == B2B_CONTACT_OUTSIDE, 'crossing: pair (3, B) status ' // &
               int_str(status) // ' == B2B_CONTACT_OUTSIDE')

    ! Hand the committed history over to the pair (4, B) and evaluate it.
    XA = beam_a(shift)
    call segment_a(3, XA, s3, P3)
    call segment_a(4, XA, s4, P4)
    hto = sentinel
    call b2b_pair_history_handover(p, 1, +1, s3, P3, s4, P4, hist1, hto, ierr=ierr, errmsg=msg)
    call check(ierr == B2B_OK, 'crossing: handover succeeds [' // trim(msg) // ']')
    call eval_f(4, shift, hto, hist2, status, info, res, Kt, 'crossing: pair (4, B)', &
                vs_c=.true.)
    call friction_info(info, fn, T, slip)
    call check(status == B2B_CONTACT_ACTIVE, 'crossing: pair (4, B) active')
    call check(info(B2B_INFO_FRICTION_STATE + 1) == B2B_FRICTION_SLIP, &
               'crossing: handed-over history slips')
    call check(abs(norm2(T) - mu * fn) <= 1.0e-12_c_double * mu * fn .and. T(1) < 0, &
               'crossing: |T| == mu f_N along -x (B dragged with A)')
    call check(info(B2B_INFO_DISSIPATION + 1) > 0, 'crossing: dissipation > 0')
    ! The tangential displacement since the commit, |slip| + mu f_N / eps_T,
    ! is A's move, 0.2, up to the first-order map of the anchor.
    gt = norm2(slip) + mu * fn / eps_t
    call check(abs(gt - 0.2_c_double) <= 1.0e-3_c_double, 'crossing: |g_T| = ' // &
               real_str(gt) // ' ~ 0.2')

    ! Without the handover the pair would restart in stick with no force.
    call eval_f(4, shift, hist0, hist2, status, info, res, Kt, 'crossing: fresh pair (4, B)')
    call check(status == B2B_CONTACT_ACTIVE .and. &
               info(B2B_INFO_FRICTION_STATE + 1) == B2B_FRICTION_STICK .and. &
               all_equal_to(info(B2B_INFO_TANGENTIAL_FORCE + 1:B2B_INFO_TANGENTIAL_FORCE + 3), &
               0.0_c_double), 'crossing: a fresh history restarts in stick with T == 0')
  end subroutine

  function real_str(x) result(s)
    real(c_double), intent(in) :: x
    character(len=:), allocatable :: s
    character(len=32) :: t
    write (t, '(es16.9)') x
    s = trim(adjustl(t))
  end function

  subroutine test_handover_errors()
    real(c_double) :: h(12), hto(12), h8(8), hto8(8), hempty(0), htoempty(0), XA(3, n_a)
    real(c_double) :: P3(3, 4), P4(3, 4), P5(3, 4), X33(3, 3), bad_t(3, 1), zero_t(3, 2)
    integer :: s3(3), s4(3), s5(3), ierr
    type(b2b_params) :: never, unfinished
    character(len=B2B_ERRMSG_LEN) :: msg

    call committed_history(h)
    XA = beam_a([0.0_c_double, 0.01_c_double, 0.0_c_double])
    call segment_a(3, XA, s3, P3)
    call segment_a(4, XA, s4, P4)
    call segment_a(5, XA, s5, P5)
    X33 = P3(:, 1:3)
    bad_t = 1

    hto = sentinel
    call b2b_pair_history_handover(p, 3, +1, s3, P3, s4, P4, h, hto, ierr=ierr, errmsg=msg)
    call expect('beam 3', ierr, msg, B2B_ERR_UNKNOWN_KIND, 'beam is 3', hto)
    call b2b_pair_history_handover(p, 0, +1, s3, P3, s4, P4, h, hto, ierr=ierr, errmsg=msg)
    call expect('beam 0', ierr, msg, B2B_ERR_UNKNOWN_KIND, 'beam', hto)
    call b2b_pair_history_handover(p, 1, 2, s3, P3, s4, P4, h, hto, ierr=ierr, errmsg=msg)
    call expect('direction 2', ierr, msg, B2B_ERR_UNKNOWN_KIND, 'direction', hto)
    call b2b_pair_history_handover(p, 1, 0, s3, P3, s4, P4, h, hto, ierr=ierr, errmsg=msg)
    call expect('direction 0', ierr, msg, B2B_ERR_UNKNOWN_KIND, 'direction', hto)

    ! History lengths: 8 (frictionless length) with a friction set, 0, and
    ! hist_from / hist_to of different sizes.
    h8 = 0
    hto8 = sentinel
    call b2b_pair_history_handover(p, 1, +1, s3, P3, s4, P4, h8, hto8, ierr=ierr, errmsg=msg)
    call expect('history length 8', ierr, msg, B2B_ERR_SIZE, 'hist', hto8)
    call b2b_pair_history_handover(p, 1, +1, s3, P3, s4, P4, hempty, htoempty, ierr=ierr, &
                                   errmsg=msg)
    call expect('history length 0', ierr, msg, B2B_ERR_SIZE, 'hist', hto)
    call b2b_pair_history_handover(p, 1, +1, s3, P3, s4, P4, h, hto8, ierr=ierr, errmsg=msg)
    call expect('hist_from 12, hist_to 8', ierr, msg, B2B_ERR_SIZE, 'differ in size', hto8)

    ! Shapes.
    call b2b_pair_history_handover(p, 1, +1, s3, X33, s4, P4, h, hto, ierr=ierr, errmsg=msg)
    call expect('from_X(3,3)', ierr, msg, B2B_ERR_SIZE, 'from_X', hto)
    call b2b_pair_history_handover(p, 1, +1, s3, P3, s4, P4(:, 1:2), h, hto, ierr=ierr, errmsg=msg)
    call expect('to_X(3,2)', ierr, msg, B2B_ERR_SIZE, 'to_X', hto)
    call b2b_pair_history_handover(p, 1, +1, s3(1:2), P3, s4, P4, h, hto, ierr=ierr, errmsg=msg)
    call expect('from_segment(2)', ierr, msg, B2B_ERR_SIZE, 'from_segment', hto)
    call b2b_pair_history_handover(p, 1, +1, s3, P3, [s4, 0], P4, h, hto, ierr=ierr, errmsg=msg)
    call expect('to_segment(4)', ierr, msg, B2B_ERR_SIZE, 'to_segment', hto)
    call b2b_pair_history_handover(p, 1, +1, s3, P3, s4, P4, h, hto, to_end_tangents=bad_t, &
                                   ierr=ierr, errmsg=msg)
    call expect('to_end_tangents(3,1)', ierr, msg, B2B_ERR_SIZE, 'to_end_tangents', hto)
    call b2b_pair_history_handover(p, 1, +1, s3, P3, s4, P4, h, hto, from_end_tangents=bad_t, &
                                   ierr=ierr, errmsg=msg)
    call expect('from_end_tangents(3,1)', ierr, msg, B2B_ERR_SIZE, 'from_end_tangents', hto)

    ! Segments that do not share the joint.
    call b2b_pair_history_handover(p, 1, +1, s3, P3, s5, P5, h, hto, ierr=ierr, errmsg=msg)
    call expect('3 -> 5', ierr, msg, B2B_ERR_RANGE, 'joint', hto)
    call b2b_pair_history_handover(p, 1, -1, s3, P3, s4, P4, h, hto, ierr=ierr, errmsg=msg)
    call expect('3 -> 4 with direction -1', ierr, msg, B2B_ERR_RANGE, 'joint', hto)

    ! A TANGENT rule without end tangents; a bad kind.
    call b2b_pair_history_handover(p, 1, +1, s4, P4, [kind_a, B2B_END_NEIGHBOUR, &
                                   B2B_END_TANGENT], P5, h, hto, ierr=ierr, errmsg=msg)
    call expect('TANGENT rule, no end tangents', ierr, msg, B2B_ERR_NULL, 'tangent', hto)
    zero_t = 0
    call b2b_pair_history_handover(p, 1, +1, s4, P4, [kind_a, B2B_END_NEIGHBOUR, &
                                   B2B_END_TANGENT], P5, h, hto, to_end_tangents=zero_t, &
                                   ierr=ierr, errmsg=msg)
    call expect('TANGENT rule, zero end tangent', ierr, msg, B2B_ERR_RANGE, 'tangent', hto)
    call b2b_pair_history_handover(p, 1, +1, [17, 0, 0], P3, s4, P4, h, hto, ierr=ierr, errmsg=msg)
    call expect('from kind 17', ierr, msg, B2B_ERR_UNKNOWN_KIND, 'kind', hto)

    ! A history not written by b2b.
    h8 = h(1:8)
    h(1) = 5
    call b2b_pair_history_handover(p, 1, +1, s3, P3, s4, P4, h, hto, ierr=ierr, errmsg=msg)
    call expect('foreign history tag', ierr, msg, B2B_ERR_RANGE, 'hist_from', hto)
    h(1:8) = h8

    ! Handles: never created, not finalized.
    call b2b_pair_history_handover(never, 1, +1, s3, P3, s4, P4, h, hto, ierr=ierr, errmsg=msg)
    call expect('never-created params', ierr, msg, B2B_ERR_NULL, 'params', hto)
    call b2b_params_create(unfinished, ierr, msg)
    call b2b_params_set_real(unfinished, 'penalty', eps_n, ierr, msg)
    call b2b_pair_history_handover(unfinished, 1, +1, s3, P3, s4, P4, h, hto, ierr=ierr, errmsg=msg)
    call expect('unfinalized params', ierr, msg, B2B_ERR_STATE, 'finalize', hto)
    call b2b_params_destroy(unfinished)

    ! After all that, a good call still works and clears ierr and errmsg.
    msg = 'garbage'
    call b2b_pair_history_handover(p, 1, +1, s3, P3, s4, P4, h, hto, ierr=ierr, errmsg=msg)
    call check(ierr == B2B_OK .and. msg == '' .and. .not. all_equal_to(hto, sentinel), &
               'good call after failures: ierr == 0, errmsg == '''', hist_to written')
  end subroutine

  !> ierr == code, errmsg names the problem, hist_to still all sentinel.
  subroutine expect(label, ierr, msg, code, needle, hist_to)
    character(len=*), intent(in) :: label, msg, needle
    integer, intent(in) :: ierr, code
    real(c_double), intent(in) :: hist_to(:)
    call check(ierr == code, 'handover ' // label // ': ierr ' // int_str(ierr) // ' == ' // &
               int_str(code) // ' [' // trim(msg) // ']')
    call check(contains_text(msg, needle), 'handover ' // label // ': errmsg "' // trim(msg) // &
               '" contains "' // needle // '"')
    call check(all_equal_to(hist_to, sentinel), 'handover ' // label // ': hist_to untouched')
  end subroutine

end program ftest_pair_friction
