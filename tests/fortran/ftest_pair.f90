!> Parity and behaviour of module b2b's contact procedures (type b2b_params,
!> b2b_params_*, b2b_pair_eval).
!>
!> The heart of it: every b2b_pair_eval through the module is repeated through
!> the direct bind(C) interface of module ftest_capi, with flat arrays and a
!> parameter handle created by direct C calls with the same options, and the
!> two results (status, info, residual, tangent, new history) must agree bit
!> for bit, with the tangent present and absent, with a leading dimension of 24
!> and of 30, and with host end tangents. The layout is
!>   segments(j,b) = C segments[j + 3b],  X(i,k) = C X[i + 3k],
!>   end_tangents(i,k) = C end_tangents[i + 3k],  info(k+1) = C info[k],
!>   tangent(r,c) = C tangent[r + ldk c]                (0-based in C).
!> Then the physics a host relies on: an active contact with a negative gap,
!> equal and opposite forces on the two beams, a symmetric tangent, a
!> repeatable evaluation from the committed history; and the parameter
!> getters, defaults and history size.
program ftest_pair
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_ptr, c_char, c_loc, c_null_ptr, &
                                         c_null_char, c_associated
  use b2b
  use ftest_check
  use ftest_capi
  implicit none

  real(c_double), parameter :: sentinel_f = -7.0_c_double, sentinel_c = -9.0_c_double
  real(c_double), parameter :: penalty = 1.0e3_c_double, g0 = 0.02_c_double
  real(c_double), parameter :: radii0(2) = [0.2_c_double, 0.15_c_double]
  ! Host end tangents: A's first and last node, then B's (only their
  ! direction counts; read only where a rule is B2B_END_TANGENT).
  real(c_double), parameter :: tangents0(3, 4) = reshape([ &
    1.0_c_double, 0.15_c_double, -0.1_c_double, &
    1.0_c_double, 0.1_c_double, 0.12_c_double, &
    0.05_c_double, 1.0_c_double, 0.0_c_double, &
    0.05_c_double, 1.0_c_double, -0.1_c_double], [3, 4])

  call test_constants()
  call test_params()
  call test_parity_and_physics()
  call check_summary('ftest_pair')

contains

  !> A crossing: beam A a curved, non-uniform 4-node patch along x, beam B
  !> along y, slightly tilted and curved, about 0.3 below A where they cross
  !> (near x = 0.1, y = 0.01), so with radii 0.2 and 0.15 the gap is about
  !> -0.05.
  function crossing() result(X)
    real(c_double) :: X(3, 8)
    real(c_double), parameter :: xa(4) = [-1.5_c_double, -0.5_c_double, 0.6_c_double, &
                                          1.4_c_double]
    real(c_double), parameter :: yb(4) = [-1.4_c_double, -0.5_c_double, 0.5_c_double, &
                                          1.6_c_double]
    integer :: k
    do k = 1, 4
      X(:, k) = [xa(k), 0.1_c_double * xa(k), 0.05_c_double * xa(k)**2]
      X(:, 4 + k) = [0.1_c_double + 0.05_c_double * yb(k), yb(k), &
                     -0.3_c_double - 0.03_c_double * yb(k)**2]
    end do
  end function

  !> A finalized module handle: penalty, law (and g0 for the quadratic law).
  subroutine make_params(p, law)
    type(b2b_params), intent(inout) :: p
    integer, intent(in) :: law
    integer :: ierr
    character(len=B2B_ERRMSG_LEN) :: msg
    call b2b_params_create(p, ierr, msg)
    call check(ierr == B2B_OK, 'module create [' // trim(msg) // ']')
    call b2b_params_set_real(p, 'penalty', penalty, ierr, msg)
    call check(ierr == B2B_OK, 'module set penalty [' // trim(msg) // ']')
    call b2b_params_set_int(p, 'law', law, ierr, msg)
    call check(ierr == B2B_OK, 'module set law [' // trim(msg) // ']')
    if (law == B2B_LAW_QUADRATIC) then
      call b2b_params_set_real(p, 'regularization_gap', g0, ierr, msg)
      call check(ierr == B2B_OK, 'module set regularization_gap [' // trim(msg) // ']')
    end if
    call b2b_params_finalize(p, ierr, msg)
    call check(ierr == B2B_OK, 'module finalize [' // trim(msg) // ']')
  end subroutine

  !> The same through direct C calls.
  function make_c_params(law) result(cp)
    integer, intent(in) :: law
    type(c_ptr) :: cp
    cp = c_null_ptr
    call check(c_params_create(cp, c_null_ptr, 0_c_int) == B2B_OK .and. c_associated(cp), &
               'C create')
    call check(c_params_set_real(cp, 'penalty' // c_null_char, penalty, c_null_ptr, 0_c_int) &
               == B2B_OK, 'C set penalty')
    call check(c_params_set_int(cp, 'law' // c_null_char, int(law, c_int), c_null_ptr, &
                                0_c_int) == B2B_OK, 'C set law')
    if (law == B2B_LAW_QUADRATIC) &
      call check(c_params_set_real(cp, 'regularization_gap' // c_null_char, g0, c_null_ptr, &
                                   0_c_int) == B2B_OK, 'C set regularization_gap')
    call check(c_params_finalize(cp, c_null_ptr, 0_c_int) == B2B_OK, 'C finalize')
  end function

  ! ------------------------------------------------------------------ constants

  subroutine test_constants()
    call check(B2B_ERR_STATE == 10, 'B2B_ERR_STATE == 10')
    call check(B2B_ERR_UNKNOWN_KEY == 11, 'B2B_ERR_UNKNOWN_KEY == 11')
    call check(B2B_LAW_LINEAR == 0, 'B2B_LAW_LINEAR == 0')
    call check(B2B_LAW_QUADRATIC == 1, 'B2B_LAW_QUADRATIC == 1')
    ! Laws are appended: the count only grows past the last fixed value.
    call check(B2B_LAW_COUNT >= B2B_LAW_QUADRATIC + 1, 'B2B_LAW_COUNT >= 2')
    call check(B2B_CONTACT_OPEN == 0, 'B2B_CONTACT_OPEN == 0')
    call check(B2B_CONTACT_ACTIVE == 1, 'B2B_CONTACT_ACTIVE == 1')
    call check(B2B_CONTACT_OUTSIDE == 2, 'B2B_CONTACT_OUTSIDE == 2')
    call check(B2B_CONTACT_PARALLEL == 3, 'B2B_CONTACT_PARALLEL == 3')
    call check(B2B_CONTACT_NOT_CONVERGED == 4, 'B2B_CONTACT_NOT_CONVERGED == 4')
    call check(B2B_CONTACT_NO_NORMAL == 5, 'B2B_CONTACT_NO_NORMAL == 5')
    call check(B2B_INFO_XI == 0, 'B2B_INFO_XI == 0')
    call check(B2B_INFO_ETA == 1, 'B2B_INFO_ETA == 1')
    call check(B2B_INFO_POINT_A == 2, 'B2B_INFO_POINT_A == 2')
    call check(B2B_INFO_POINT_B == 5, 'B2B_INFO_POINT_B == 5')
    call check(B2B_INFO_NORMAL == 8, 'B2B_INFO_NORMAL == 8')
    call check(B2B_INFO_GAP == 11, 'B2B_INFO_GAP == 11')
    call check(B2B_INFO_NORMAL_FORCE == 12, 'B2B_INFO_NORMAL_FORCE == 12')
    call check(B2B_INFO_ENERGY == 13, 'B2B_INFO_ENERGY == 13')
    call check(B2B_INFO_ANGLE == 14, 'B2B_INFO_ANGLE == 14')
    call check(B2B_INFO_ITERATIONS == 15, 'B2B_INFO_ITERATIONS == 15')
    call check(B2B_INFO_SYMMETRIC == 16, 'B2B_INFO_SYMMETRIC == 16')
    call check(B2B_PAIR_INFO_LEN == 32, 'B2B_PAIR_INFO_LEN == 32')
    call check(B2B_PAIR_NDOF == 24, 'B2B_PAIR_NDOF == 24')
  end subroutine

  ! ------------------------------------------------------------------- params

  subroutine test_params()
    type(b2b_params) :: p, fresh
    real(c_double) :: v
    integer :: iv, n, ierr
    character(len=B2B_ERRMSG_LEN) :: msg

    ! Defaults of a new handle (b2b_pair.h).
    call b2b_params_create(fresh, ierr, msg)
    call check(ierr == B2B_OK .and. msg == '', 'create: ierr == 0, errmsg == '''' [' // &
               trim(msg) // ']')
    v = sentinel_f
    call b2b_params_get_real(fresh, 'parallel_angle', v, ierr, msg)
    call check(ierr == B2B_OK .and. v == 0.5_c_double, 'default parallel_angle == 0.5')
    iv = -77
    call b2b_params_get_int(fresh, 'law', iv, ierr, msg)
    call check(ierr == B2B_OK .and. iv == B2B_LAW_LINEAR, 'default law == B2B_LAW_LINEAR')
    iv = -77
    call b2b_params_get_int(fresh, 'warm_start', iv, ierr, msg)
    call check(ierr == B2B_OK .and. iv == 0, 'default warm_start == 0')
    iv = -77
    call b2b_params_get_int(fresh, 'max_iterations', iv, ierr, msg)
    call check(ierr == B2B_OK .and. iv == 50, 'default max_iterations == 50')
    call b2b_params_destroy(fresh)

    ! Every key set, then read back, before and after finalize.
    call b2b_params_create(p, ierr, msg)
    call b2b_params_set_real(p, 'penalty', 1234.5_c_double, ierr, msg)
    call check(ierr == B2B_OK .and. msg == '', 'set penalty [' // trim(msg) // ']')
    call b2b_params_set_int(p, 'law', B2B_LAW_QUADRATIC, ierr, msg)
    call check(ierr == B2B_OK, 'set law [' // trim(msg) // ']')
    call b2b_params_set_real(p, 'regularization_gap', 0.0125_c_double, ierr, msg)
    call check(ierr == B2B_OK, 'set regularization_gap [' // trim(msg) // ']')
    ! Trailing blanks of a key are ignored (keys are trimmed).
    call b2b_params_set_real(p, 'parallel_angle      ', 2.5_c_double, ierr, msg)
    call check(ierr == B2B_OK, 'set parallel_angle (key with trailing blanks) [' // &
               trim(msg) // ']')
    call b2b_params_set_int(p, 'warm_start', 1, ierr, msg)
    call check(ierr == B2B_OK, 'set warm_start [' // trim(msg) // ']')
    call b2b_params_set_int(p, 'max_iterations', 40, ierr, msg)
    call check(ierr == B2B_OK, 'set max_iterations [' // trim(msg) // ']')
    call check_getters(p, 'before finalize')
    call b2b_params_finalize(p, ierr, msg)
    call check(ierr == B2B_OK .and. msg == '', 'finalize [' // trim(msg) // ']')
    call check_getters(p, 'after finalize')
    ! Finalizing again is allowed.
    call b2b_params_finalize(p, ierr, msg)
    call check(ierr == B2B_OK, 'finalize twice')

    n = -77
    call b2b_params_history_size(p, n, ierr, msg)
    call check(ierr == B2B_OK .and. msg == '', 'history_size: ierr == 0 [' // trim(msg) // ']')
    call check(n > 0, 'history_size: n = ' // int_str(n) // ' > 0')
    ! Without ierr a successful call returns normally.
    n = -77
    call b2b_params_history_size(p, n)
    call check(n > 0, 'history_size without ierr')
    call b2b_params_destroy(p)
  end subroutine

  subroutine check_getters(p, when)
    type(b2b_params), intent(in) :: p
    character(len=*), intent(in) :: when
    real(c_double) :: v
    integer :: iv, ierr
    character(len=B2B_ERRMSG_LEN) :: msg
    v = sentinel_f
    call b2b_params_get_real(p, 'penalty', v, ierr, msg)
    call check(ierr == B2B_OK .and. msg == '' .and. v == 1234.5_c_double, &
               when // ': get penalty == 1234.5')
    v = sentinel_f
    call b2b_params_get_real(p, 'regularization_gap', v, ierr, msg)
    call check(ierr == B2B_OK .and. v == 0.0125_c_double, when // ': get regularization_gap')
    v = sentinel_f
    call b2b_params_get_real(p, 'parallel_angle', v, ierr, msg)
    call check(ierr == B2B_OK .and. v == 2.5_c_double, when // ': get parallel_angle')
    iv = -77
    call b2b_params_get_int(p, 'law', iv, ierr, msg)
    call check(ierr == B2B_OK .and. msg == '' .and. iv == B2B_LAW_QUADRATIC, &
               when // ': get law == B2B_LAW_QUADRATIC')
    iv = -77
    call b2b_params_get_int(p, 'warm_start', iv, ierr, msg)
    call check(ierr == B2B_OK .and. iv == 1, when // ': get warm_start == 1')
    iv = -77
    call b2b_params_get_int(p, 'max_iterations   ', iv, ierr, msg)
    call check(ierr == B2B_OK .and. iv == 40, when // ': get max_iterations == 40')
  end subroutine

  ! ----------------------------------------------------- parity and physics

  subroutine test_parity_and_physics()
    integer, parameter :: n_cases = 4
    integer :: segs(3, 2), c, law
    logical :: with_tangents
    character(len=:), allocatable :: label

    do c = 1, n_cases
      law = B2B_LAW_LINEAR
      with_tangents = .false.
      label = ''
      segs(:, 1) = [B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR]
      select case (c)
      case (1)
        segs(:, 2) = [B2B_CURVE_LINEAR, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR]
        label = 'A HERMITE_NODAL, B LINEAR'
      case (2)
        segs(:, 2) = [B2B_CURVE_HERMITE_NODAL_WEIGHTED, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR]
        label = 'A HERMITE_NODAL, B HERMITE_NODAL_WEIGHTED'
      case (3)
        ! Host end tangents at A's first node and B's last node.
        segs(:, 1) = [B2B_CURVE_HERMITE_NODAL, B2B_END_TANGENT, B2B_END_NEIGHBOUR]
        segs(:, 2) = [B2B_CURVE_HERMITE_NODAL_WEIGHTED, B2B_END_NEIGHBOUR, B2B_END_TANGENT]
        with_tangents = .true.
        label = 'A HERMITE_NODAL start TANGENT, B WEIGHTED end TANGENT'
      case (4)
        segs(:, 2) = [B2B_CURVE_LINEAR, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR]
        law = B2B_LAW_QUADRATIC
        label = 'A HERMITE_NODAL, B LINEAR, QUADRATIC law'
      end select
      call check_case(segs, law, with_tangents, label)
    end do
  end subroutine

  subroutine check_case(segs, law, with_tangents, label)
    integer, intent(in) :: segs(3, 2), law
    logical, intent(in) :: with_tangents
    character(len=*), intent(in) :: label

    type(b2b_params) :: p
    type(c_ptr) :: cp
    integer :: n, ierr, status_f, status_f2, k
    integer(c_int) :: cn, st
    real(c_double) :: X(3, 8), radii(2), fa(3), fb(3), scale
    real(c_double), allocatable :: hist0(:), hist_f(:), hist_f2(:)
    real(c_double) :: info_f(32), info_f2(32), res_f(24), res_f2(24), K_f(24, 24), K_f2(24, 24)
    real(c_double) :: K30(30, 24)
    real(c_double), target :: K30c(30, 24)
    character(len=B2B_ERRMSG_LEN) :: msg
    ! Flat arrays of the direct C call.
    integer(c_int), target :: segs_c(6), status_c
    real(c_double), target :: X_c(24), t_c(12), radii_c(2), info_c(32), res_c(24), K_c(576)
    real(c_double), allocatable, target :: hist0_c(:), hist_c(:)
    character(kind=c_char), target :: buf(B2B_ERRMSG_LEN)
    type(c_ptr) :: pt_c

    X = crossing()
    radii = radii0
    call make_params(p, law)
    cp = make_c_params(law)

    n = -77
    call b2b_params_history_size(p, n, ierr, msg)
    cn = -77
    st = c_params_history_size(cp, cn, c_null_ptr, 0_c_int)
    call check(ierr == B2B_OK .and. st == B2B_OK .and. n == cn .and. n > 0, label // &
               ': history_size module == C > 0')
    if (n <= 0) return
    allocate (hist0(n), hist_f(n), hist_f2(n), hist0_c(n), hist_c(n))
    hist0 = 0
    hist0_c = 0

    ! ---- module, tangent present (ldk 24)
    hist_f = sentinel_f
    info_f = sentinel_f
    res_f = sentinel_f
    K_f = sentinel_f
    status_f = -77
    if (with_tangents) then
      call b2b_pair_eval(p, segs, X, radii, hist0, hist_f, status_f, info_f, res_f, &
                         tangent=K_f, end_tangents=tangents0, ierr=ierr, errmsg=msg)
    else
      call b2b_pair_eval(p, segs, X, radii, hist0, hist_f, status_f, info_f, res_f, &
                         tangent=K_f, ierr=ierr, errmsg=msg)
    end if
    call check(ierr == B2B_OK .and. msg == '', label // ': module eval succeeds [' // &
               trim(msg) // ']')

    ! ---- direct C call, tangent present
    segs_c = int(reshape(segs, [6]), c_int)
    X_c = reshape(X, [24])
    t_c = reshape(tangents0, [12])
    radii_c = radii
    pt_c = c_null_ptr
    if (with_tangents) pt_c = c_loc(t_c)
    hist_c = sentinel_c
    info_c = sentinel_c
    res_c = sentinel_c
    K_c = sentinel_c
    status_c = -99
    buf = c_null_char
    st = c_pair_eval(cp, c_loc(segs_c), c_loc(X_c), pt_c, c_loc(radii_c), c_loc(hist0_c), &
                     c_loc(hist_c), int(n, c_int), c_loc(status_c), c_loc(info_c), &
                     c_loc(res_c), c_loc(K_c), 24_c_int, c_loc(buf), int(size(buf), c_int))
    call check(st == B2B_OK, label // ': C eval succeeds')
    call check(status_f == status_c, label // ': contact_status module == C')
    call check(same_bits(info_f, info_c), label // ': info module == C bit for bit')
    call check(same_bits(res_f, res_c), label // ': residual module == C bit for bit')
    call check(same_bits(reshape(K_f, [576]), K_c), label // ': tangent module == C bit for bit')
    call check(same_bits(hist_f, hist_c), label // ': hist_new module == C bit for bit')

    ! ---- physics
    call check(status_f == B2B_CONTACT_ACTIVE, label // ': contact_status ' // &
               int_str(status_f) // ' == B2B_CONTACT_ACTIVE')
    call check(info_f(B2B_INFO_GAP + 1) < 0, label // ': gap < 0')
    call check(info_f(B2B_INFO_NORMAL_FORCE + 1) > 0, label // ': normal force > 0')
    call check(abs(info_f(B2B_INFO_XI + 1)) < 1 .and. abs(info_f(B2B_INFO_ETA + 1)) < 1, &
               label // ': xi, eta inside the segments')
    ! The gap is about 0.3 - 0.35 (-0.04 .. -0.06 with the curvature and the
    ! end tangents); the point on A is about (0.1, 0.01, 0).
    call check(info_f(B2B_INFO_GAP + 1) > -0.1_c_double .and. &
               info_f(B2B_INFO_GAP + 1) < -0.02_c_double, label // ': gap in (-0.1, -0.02)')
    call check(abs(info_f(B2B_INFO_NORMAL_FORCE + 1) - merge(penalty * (g0 / 2), &
               0.0_c_double, law == B2B_LAW_QUADRATIC) + penalty * info_f(B2B_INFO_GAP + 1)) &
               <= 1.0e-12_c_double * penalty, label // ': normal force of the law')
    call check(abs(info_f(B2B_INFO_POINT_A + 1) - 0.1_c_double) < 0.05_c_double .and. &
               abs(info_f(B2B_INFO_POINT_A + 2) - 0.01_c_double) < 0.05_c_double, &
               label // ': point on A near (0.1, 0.01)')
    ! Normal from B to A: up.
    call check(info_f(B2B_INFO_NORMAL + 3) > 0.99_c_double, label // ': normal points up (+z)')
    fa = 0
    fb = 0
    do k = 1, 4
      fa = fa + res_f(3 * k - 2:3 * k)
      fb = fb + res_f(12 + 3 * k - 2:12 + 3 * k)
    end do
    scale = maxval(abs(fa))
    call check(scale > 0, label // ': a non-zero force on A')
    call check(maxval(abs(fa + fb)) <= 1.0e-12_c_double * scale, label // &
               ': forces on A and B are equal and opposite')
    call check(rel_diff(reshape(K_f, [576]), reshape(transpose(K_f), [576]), 0.0_c_double) &
               <= 1.0e-10_c_double .and. maxval(abs(K_f)) > 0, label // ': tangent symmetric')
    call check(info_f(B2B_INFO_SYMMETRIC + 1) == 1, label // ': info says symmetric')
    call check(all_equal_to(info_f(18:32), 0.0_c_double), label // ': reserved info are 0')

    ! ---- tangent absent: module and C with NULL, and the same residual
    info_f2 = sentinel_f
    res_f2 = sentinel_f
    hist_f2 = sentinel_f
    status_f2 = -77
    if (with_tangents) then
      call b2b_pair_eval(p, segs, X, radii, hist0, hist_f2, status_f2, info_f2, res_f2, &
                         end_tangents=tangents0, ierr=ierr, errmsg=msg)
    else
      call b2b_pair_eval(p, segs, X, radii, hist0, hist_f2, status_f2, info_f2, res_f2, &
                         ierr=ierr, errmsg=msg)
    end if
    call check(ierr == B2B_OK, label // ', no tangent: module eval succeeds [' // &
               trim(msg) // ']')
    hist_c = sentinel_c
    info_c = sentinel_c
    res_c = sentinel_c
    status_c = -99
    st = c_pair_eval(cp, c_loc(segs_c), c_loc(X_c), pt_c, c_loc(radii_c), c_loc(hist0_c), &
                     c_loc(hist_c), int(n, c_int), c_loc(status_c), c_loc(info_c), &
                     c_loc(res_c), c_null_ptr, 0_c_int, c_loc(buf), int(size(buf), c_int))
    call check(st == B2B_OK, label // ', no tangent: C eval succeeds')
    call check(status_f2 == status_c .and. same_bits(info_f2, info_c) .and. &
               same_bits(res_f2, res_c) .and. same_bits(hist_f2, hist_c), &
               label // ', no tangent: module == C bit for bit')
    call check(status_f2 == status_f .and. same_bits(info_f2, info_f) .and. &
               same_bits(res_f2, res_f) .and. same_bits(hist_f2, hist_f), &
               label // ', no tangent: same status, info, residual, history as with it')

    ! ---- second evaluation from the committed history
    info_f2 = sentinel_f
    res_f2 = sentinel_f
    K_f2 = sentinel_f
    hist_f2 = sentinel_f
    status_f2 = -77
    if (with_tangents) then
      call b2b_pair_eval(p, segs, X, radii, hist_f, hist_f2, status_f2, info_f2, res_f2, &
                         tangent=K_f2, end_tangents=tangents0, ierr=ierr, errmsg=msg)
    else
      call b2b_pair_eval(p, segs, X, radii, hist_f, hist_f2, status_f2, info_f2, res_f2, &
                         tangent=K_f2, ierr=ierr, errmsg=msg)
    end if
    call check(ierr == B2B_OK, label // ', from history: succeeds [' // trim(msg) // ']')
    call check(status_f2 == status_f .and. same_bits(info_f2, info_f) .and. &
               same_bits(res_f2, res_f) .and. same_bits(reshape(K_f2, [576]), &
               reshape(K_f, [576])) .and. same_bits(hist_f2, hist_f), &
               label // ', from history: the same result bit for bit')

    ! ---- leading dimension 30: rows 1..24 the same, rows 25..30 untouched;
    ! and the same as C with ldk 30.
    K30 = sentinel_f
    if (with_tangents) then
      call b2b_pair_eval(p, segs, X, radii, hist0, hist_f2, status_f2, info_f2, res_f2, &
                         tangent=K30, end_tangents=tangents0, ierr=ierr, errmsg=msg)
    else
      call b2b_pair_eval(p, segs, X, radii, hist0, hist_f2, status_f2, info_f2, res_f2, &
                         tangent=K30, ierr=ierr, errmsg=msg)
    end if
    call check(ierr == B2B_OK, label // ', tangent(30,24): succeeds [' // trim(msg) // ']')
    call check(same_bits(reshape(K30(1:24, :), [576]), reshape(K_f, [576])), &
               label // ', tangent(30,24): rows 1..24 == tangent(24,24) bit for bit')
    call check(all_equal_to(reshape(K30(25:30, :), [144]), sentinel_f), &
               label // ', tangent(30,24): rows 25..30 untouched')
    K30c = sentinel_f
    st = c_pair_eval(cp, c_loc(segs_c), c_loc(X_c), pt_c, c_loc(radii_c), c_loc(hist0_c), &
                     c_loc(hist_c), int(n, c_int), c_loc(status_c), c_loc(info_c), &
                     c_loc(res_c), c_loc(K30c), 30_c_int, c_loc(buf), int(size(buf), c_int))
    call check(st == B2B_OK .and. same_bits(reshape(K30, [720]), reshape(K30c, [720])), &
               label // ', tangent(30,24): module == C with ldk 30 bit for bit')

    ! ---- a non-contiguous section K30(1:24, :) (copied in and out)
    K30 = sentinel_f
    if (with_tangents) then
      call b2b_pair_eval(p, segs, X, radii, hist0, hist_f2, status_f2, info_f2, res_f2, &
                         tangent=K30(1:24, :), end_tangents=tangents0, ierr=ierr, errmsg=msg)
    else
      call b2b_pair_eval(p, segs, X, radii, hist0, hist_f2, status_f2, info_f2, res_f2, &
                         tangent=K30(1:24, :), ierr=ierr, errmsg=msg)
    end if
    call check(ierr == B2B_OK .and. same_bits(reshape(K30(1:24, :), [576]), &
               reshape(K_f, [576])) .and. all_equal_to(reshape(K30(25:30, :), [144]), &
               sentinel_f), label // ', section tangent K30(1:24,:): the same numbers')

    ! ---- history and info as sections of larger host arrays
    call check_sections(p, segs, X, radii, n, with_tangents, info_f, res_f, hist_f, label)

    call b2b_params_destroy(p)
    st = c_params_destroy(cp)
    call check(.not. c_associated(cp), label // ': C destroy nulls the handle')
  end subroutine

  !> A host keeps histories in a (n, pairs) array and the residual in a
  !> global vector: columns and slices go straight in.
  subroutine check_sections(p, segs, X, radii, n, with_tangents, info_ref, res_ref, hist_ref, &
                            label)
    type(b2b_params), intent(in) :: p
    integer, intent(in) :: segs(3, 2), n
    real(c_double), intent(in) :: X(3, 8), radii(2), info_ref(32), res_ref(24), hist_ref(n)
    logical, intent(in) :: with_tangents
    character(len=*), intent(in) :: label
    real(c_double) :: hist_all(n, 3), res_all(40), info_all(32, 2), X_all(3, 10)
    integer :: status, ierr
    character(len=B2B_ERRMSG_LEN) :: msg
    hist_all = sentinel_f
    hist_all(:, 1) = 0
    res_all = sentinel_f
    info_all = sentinel_f
    X_all = sentinel_f
    X_all(:, 2:9) = X
    status = -77
    if (with_tangents) then
      call b2b_pair_eval(p, segs, X_all(:, 2:9), radii, hist_all(:, 1), hist_all(:, 3), status, &
                         info_all(:, 2), res_all(11:34), end_tangents=tangents0, ierr=ierr, &
                         errmsg=msg)
    else
      call b2b_pair_eval(p, segs, X_all(:, 2:9), radii, hist_all(:, 1), hist_all(:, 3), status, &
                         info_all(:, 2), res_all(11:34), ierr=ierr, errmsg=msg)
    end if
    call check(ierr == B2B_OK .and. status == B2B_CONTACT_ACTIVE, label // &
               ', sections: succeeds [' // trim(msg) // ']')
    call check(same_bits(hist_all(:, 3), hist_ref) .and. same_bits(info_all(:, 2), info_ref) &
               .and. same_bits(res_all(11:34), res_ref), label // &
               ', sections: the same numbers')
    call check(all_equal_to(hist_all(:, 2), sentinel_f) .and. &
               all_equal_to(res_all(1:10), sentinel_f) .and. &
               all_equal_to(res_all(35:40), sentinel_f) .and. &
               all_equal_to(info_all(:, 1), sentinel_f), label // &
               ', sections: the rest of the host arrays untouched')
  end subroutine

end program ftest_pair
