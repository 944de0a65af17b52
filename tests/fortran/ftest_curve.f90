!> Parity and behaviour of module b2b's curve procedures.
!>
!> The heart of it: every call of b2b_segment_eval through the module is
!> repeated through the direct bind(C) interface of module ftest_capi, with flat
!> arrays of 9, 72 and 864 doubles, and the two results must agree bit for bit
!> under the documented layout
!>   x(i,k)       = C x[i + 3k]
!>   dx(i,a,w)    = C dx[i + 3a + 36w]
!>   d2x(i,a,b,w) = C d2x[i + 3(a + 12b) + 432w]     (i, a, b, w, k 0-based in C)
!> which proves that the wrapper passes its arguments in the right order and
!> layout. Then known values, optional outputs, array sections, topology
!> (1-based), version and constants.
program ftest_curve
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_ptr, c_char, c_loc, c_null_ptr, &
                                         c_null_char
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  use b2b
  use ftest_check
  use ftest_capi
  implicit none

  ! The curve kinds are 0 .. B2B_CURVE_KIND_COUNT - 1: the loops below cover
  ! every kind the library has. What a test expects of a kind follows its
  ! family (b2b_curve.h): the chord, a curve centred on a node (midpoint), a
  ! node-preserving curve; family() fails a check for a kind it does not
  ! know yet (one the library added later: give it its case there).
  integer, parameter :: fam_chord = 1, fam_centred = 2, fam_nodal = 3
  character(len=*), parameter :: rule_names(0:2) = [character(len=9) :: 'NEIGHBOUR', &
                                                    'REFLECT', 'TANGENT']
  ! (start_rule, end_rule) pairs.
  integer, parameter :: n_rule_pairs = 9
  integer, parameter :: rule_pairs(2, n_rule_pairs) = reshape([ &
    B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, &
    B2B_END_REFLECT, B2B_END_NEIGHBOUR, &
    B2B_END_NEIGHBOUR, B2B_END_REFLECT, &
    B2B_END_REFLECT, B2B_END_REFLECT, &
    B2B_END_TANGENT, B2B_END_NEIGHBOUR, &
    B2B_END_NEIGHBOUR, B2B_END_TANGENT, &
    B2B_END_TANGENT, B2B_END_TANGENT, &
    B2B_END_REFLECT, B2B_END_TANGENT, &
    B2B_END_TANGENT, B2B_END_REFLECT], [2, n_rule_pairs])
  real(c_double), parameter :: xis(6) = [-1.0_c_double, 1.0_c_double, 0.3_c_double, &
                                         1.7_c_double, 0.0_c_double, -0.55_c_double]
  real(c_double), parameter :: sentinel_f = -7.0_c_double, sentinel_c = -9.0_c_double

  ! A curved, non-uniform, non-planar patch x1..x4 and host end tangents
  ! (not unit length: only their direction counts).
  real(c_double), parameter :: patch(3, 4) = reshape([ &
    0.0_c_double, 0.0_c_double, 0.0_c_double, &
    1.0_c_double, 0.3_c_double, -0.2_c_double, &
    2.1_c_double, 1.1_c_double, 0.1_c_double, &
    2.7_c_double, 2.4_c_double, 0.8_c_double], [3, 4])
  real(c_double), parameter :: tangents(3, 2) = reshape([ &
    1.0_c_double, 0.2_c_double, 0.1_c_double, &
    0.4_c_double, 1.0_c_double, 0.5_c_double], [3, 2])

  call test_constants()
  call test_version()
  call test_parity()
  call test_known_values()
  call test_optional_outputs()
  call test_sections()
  call test_topology()
  call test_beam_walk()
  call check_summary('ftest_curve')

contains

  !> The kind's name for messages.
  function kind_name(kind) result(s)
    integer, intent(in) :: kind
    character(len=:), allocatable :: s
    select case (kind)
    case (B2B_CURVE_LINEAR)
      s = 'LINEAR'
    case (B2B_CURVE_HERMITE_MIDPOINT)
      s = 'HERMITE_MIDPOINT'
    case (B2B_CURVE_HERMITE_NODAL)
      s = 'HERMITE_NODAL'
    case (B2B_CURVE_HERMITE_NODAL_WEIGHTED)
      s = 'HERMITE_NODAL_WEIGHTED'
    case default
      s = 'kind ' // int_str(kind)
    end select
  end function

  !> The kind's family (see above).
  function family(kind) result(f)
    integer, intent(in) :: kind
    integer :: f
    select case (kind)
    case (B2B_CURVE_LINEAR)
      f = fam_chord
    case (B2B_CURVE_HERMITE_MIDPOINT)
      f = fam_centred
    case (B2B_CURVE_HERMITE_NODAL, B2B_CURVE_HERMITE_NODAL_WEIGHTED)
      f = fam_nodal
    case default
      f = 0
      call check(.false., 'no expectation for curve kind ' // int_str(kind) // &
                 ' (a kind added to the library needs its case in family())')
    end select
  end function

  function case_label(kind, start_rule, end_rule, xi) result(s)
    integer, intent(in) :: kind, start_rule, end_rule
    real(c_double), intent(in) :: xi
    character(len=:), allocatable :: s
    character(len=32) :: t
    write (t, '(f0.2)') xi
    s = kind_name(kind) // ' start=' // trim(rule_names(start_rule)) // ' end=' // &
        trim(rule_names(end_rule)) // ' xi=' // trim(t)
  end function

  !> The C string in a NUL-terminated char buffer.
  function c_text(buf) result(s)
    character(kind=c_char), intent(in) :: buf(:)
    character(len=:), allocatable :: s
    integer :: n, i
    n = 0
    do while (n < size(buf))
      if (buf(n + 1) == c_null_char) exit
      n = n + 1
    end do
    allocate (character(len=n) :: s)
    do i = 1, n
      s(i:i) = buf(i)
    end do
  end function

  ! ------------------------------------------------------------------ constants

  subroutine test_constants()
    call check(B2B_OK == 0, 'B2B_OK == 0')
    call check(B2B_ERR_NULL == 1, 'B2B_ERR_NULL == 1')
    call check(B2B_ERR_SIZE == 2, 'B2B_ERR_SIZE == 2')
    call check(B2B_ERR_NONFINITE == 3, 'B2B_ERR_NONFINITE == 3')
    call check(B2B_ERR_UNKNOWN_KIND == 4, 'B2B_ERR_UNKNOWN_KIND == 4')
    call check(B2B_ERR_COINCIDENT == 5, 'B2B_ERR_COINCIDENT == 5')
    call check(B2B_ERR_FOLDED == 6, 'B2B_ERR_FOLDED == 6')
    call check(B2B_ERR_RANGE == 7, 'B2B_ERR_RANGE == 7')
    call check(B2B_ERR_NOMEM == 8, 'B2B_ERR_NOMEM == 8')
    call check(B2B_ERR_INTERNAL == 9, 'B2B_ERR_INTERNAL == 9')
    call check(B2B_ERRMSG_LEN == 256, 'B2B_ERRMSG_LEN == 256')
    call check(B2B_CURVE_LINEAR == 0, 'B2B_CURVE_LINEAR == 0')
    call check(B2B_CURVE_HERMITE_MIDPOINT == 1, 'B2B_CURVE_HERMITE_MIDPOINT == 1')
    call check(B2B_CURVE_HERMITE_NODAL == 2, 'B2B_CURVE_HERMITE_NODAL == 2')
    call check(B2B_CURVE_HERMITE_NODAL_WEIGHTED == 3, 'B2B_CURVE_HERMITE_NODAL_WEIGHTED == 3')
    ! Kinds are appended: the count only grows past the last fixed value.
    call check(B2B_CURVE_KIND_COUNT >= B2B_CURVE_HERMITE_NODAL_WEIGHTED + 1, &
               'B2B_CURVE_KIND_COUNT >= 4')
    call check(B2B_END_NEIGHBOUR == 0, 'B2B_END_NEIGHBOUR == 0')
    call check(B2B_END_REFLECT == 1, 'B2B_END_REFLECT == 1')
    call check(B2B_END_TANGENT == 2, 'B2B_END_TANGENT == 2')
    call check(B2B_PATCH_NODES == 4, 'B2B_PATCH_NODES == 4')
    call check(B2B_PATCH_LEN == 12, 'B2B_PATCH_LEN == 12')
    call check(B2B_POINT_LEN == 9, 'B2B_POINT_LEN == 9')
    call check(B2B_DPOINT_LEN == 72, 'B2B_DPOINT_LEN == 72')
    call check(B2B_D2POINT_LEN == 864, 'B2B_D2POINT_LEN == 864')
    call check(B2B_COORD_MAX == 1.0e100_c_double, 'B2B_COORD_MAX == 1e100')
    call check(B2B_LENGTH_MIN == 1.0e-100_c_double, 'B2B_LENGTH_MIN == 1e-100')
    call check(kind(B2B_OK) == c_int, 'B2B_OK is integer(c_int)')
  end subroutine

  ! -------------------------------------------------------------------- version

  subroutine test_version()
    integer :: major, minor, patch_v, abi, ierr, st
    character(len=B2B_ERRMSG_LEN) :: msg
    character(len=:), allocatable :: s_ok, s_folded, s_i, s_j

    major = -1
    minor = -1
    patch_v = -1
    call b2b_version(major, minor, patch_v)
    call check(major == B2B_VERSION_MAJOR, 'b2b_version major == B2B_VERSION_MAJOR')
    call check(minor == B2B_VERSION_MINOR, 'b2b_version minor == B2B_VERSION_MINOR')
    call check(patch_v == B2B_VERSION_PATCH, 'b2b_version patch == B2B_VERSION_PATCH')
    ierr = -5
    msg = 'garbage'
    call b2b_version(major, minor, patch_v, ierr=ierr, errmsg=msg)
    call check(ierr == 0 .and. msg == '', 'b2b_version: ierr == 0 and errmsg == ''''')

    abi = -1
    call b2b_abi_version(abi)
    call check(abi == B2B_SOVERSION, 'b2b_abi_version == B2B_SOVERSION')
    ierr = -5
    msg = 'garbage'
    abi = -1
    call b2b_abi_version(abi, ierr, msg)
    call check(ierr == 0 .and. msg == '' .and. abi == B2B_SOVERSION, &
               'b2b_abi_version(abi, ierr, errmsg): ierr == 0, errmsg == '''', abi')

    s_ok = b2b_strerror(B2B_OK)
    s_folded = b2b_strerror(B2B_ERR_FOLDED)
    call check(len(s_folded) > 0, 'b2b_strerror(B2B_ERR_FOLDED) is non-empty')
    call check(len(s_ok) > 0, 'b2b_strerror(B2B_OK) is non-empty')
    call check(s_folded /= s_ok, 'b2b_strerror(B2B_ERR_FOLDED) /= b2b_strerror(B2B_OK)')
    call check(index(s_folded, char(0)) == 0, 'b2b_strerror holds no NUL')
    call check(b2b_strerror(12345) == 'unknown status', 'b2b_strerror(12345) == unknown status')
    call check(b2b_strerror(-1) == 'unknown status', 'b2b_strerror(-1) == unknown status')
    do st = B2B_OK, B2B_ERR_INTERNAL
      s_i = b2b_strerror(st)
      call check(len(s_i) > 0 .and. s_i /= 'unknown status', &
                 'b2b_strerror(' // int_str(st) // ') names the code')
      s_j = b2b_strerror(modulo(st + 1, B2B_ERR_INTERNAL + 1))
      call check(s_i /= s_j, 'b2b_strerror(' // int_str(st) // ') differs from the next code''s')
    end do
  end subroutine

  ! --------------------------------------------------------------------- parity

  subroutine test_parity()
    integer :: kind, ir, ix, with_t
    do kind = 0, B2B_CURVE_KIND_COUNT - 1
      do ir = 1, n_rule_pairs
        do ix = 1, size(xis)
          do with_t = 0, 1
            ! Without end tangents only where no rule asks for them.
            if (with_t == 0 .and. any(rule_pairs(:, ir) == B2B_END_TANGENT)) cycle
            call compare_paths(kind, rule_pairs(1, ir), rule_pairs(2, ir), xis(ix), &
                               with_t == 1)
          end do
        end do
      end do
    end do
  end subroutine

  !> One evaluation through the module and through the C function directly.
  subroutine compare_paths(kind, start_rule, end_rule, xi, with_tangents)
    integer, intent(in) :: kind, start_rule, end_rule
    real(c_double), intent(in) :: xi
    logical, intent(in) :: with_tangents
    real(c_double) :: xf(3, 3), dxf(3, 12, 2), d2xf(3, 12, 12, 2)
    real(c_double), target :: pc(12), tc(6), xc(9), dxc(72), d2xc(864)
    character(kind=c_char), target :: cmsg(B2B_ERRMSG_LEN)
    character(len=B2B_ERRMSG_LEN) :: fmsg
    character(len=:), allocatable :: label
    type(c_ptr) :: ptan
    integer :: ierr, expected, i, k, a, b, w
    integer(c_int) :: stc
    logical :: ok, nodal, start_nonlinear, end_nonlinear
    real(c_double) :: scale

    label = case_label(kind, start_rule, end_rule, xi)
    if (with_tangents) label = label // ' (end_tangents given)'
    xf = sentinel_f
    dxf = sentinel_f
    d2xf = sentinel_f
    xc = sentinel_c
    dxc = sentinel_c
    d2xc = sentinel_c
    cmsg = c_null_char
    pc = reshape(patch, [12])
    tc = reshape(tangents, [6])
    ierr = -5
    fmsg = 'garbage'

    if (with_tangents) then
      call b2b_segment_eval(kind, start_rule, end_rule, patch, xi, x=xf, dx=dxf, d2x=d2xf, &
                            end_tangents=tangents, ierr=ierr, errmsg=fmsg)
      ptan = c_loc(tc)
    else
      call b2b_segment_eval(kind, start_rule, end_rule, patch, xi, x=xf, dx=dxf, d2x=d2xf, &
                            ierr=ierr, errmsg=fmsg)
      ptan = c_null_ptr
    end if
    stc = c_segment_eval(int(kind, c_int), int(start_rule, c_int), int(end_rule, c_int), &
                         c_loc(pc), ptan, xi, c_loc(xc), c_loc(dxc), c_loc(d2xc), c_loc(cmsg), &
                         int(size(cmsg), c_int))

    ! A midpoint segment cannot both start and end its beam: B2B_ERR_RANGE.
    expected = B2B_OK
    if (family(kind) == fam_centred .and. start_rule /= B2B_END_NEIGHBOUR .and. &
        end_rule /= B2B_END_NEIGHBOUR) expected = B2B_ERR_RANGE
    call check(stc == expected, label // ': C status ' // int_str(int(stc)) // ' == ' // &
               int_str(expected) // ' ' // c_text(cmsg))
    call check(ierr == stc, label // ': module ierr ' // int_str(ierr) // ' == C status ' // &
               int_str(int(stc)))
    call check(fmsg == c_text(cmsg), label // ': module errmsg == C errmsg')

    if (stc /= B2B_OK) then
      call check(all_equal_to(reshape(xf, [9]), sentinel_f) .and. &
                 all_equal_to(reshape(dxf, [72]), sentinel_f) .and. &
                 all_equal_to(reshape(d2xf, [864]), sentinel_f), &
                 label // ': module outputs untouched on failure')
      call check(all_equal_to(xc, sentinel_c) .and. all_equal_to(dxc, sentinel_c) .and. &
                 all_equal_to(d2xc, sentinel_c), label // ': C outputs untouched on failure')
      return
    end if

    ! Element by element under the documented index maps (0-based i, k, a, b, w).
    ok = .true.
    do k = 0, 2
      do i = 0, 2
        ok = ok .and. same_bits([xf(i + 1, k + 1)], [xc(1 + i + 3 * k)])
      end do
    end do
    call check(ok, label // ': x(i,k) == C x[i+3k] bit for bit')
    ok = .true.
    do w = 0, 1
      do a = 0, 11
        do i = 0, 2
          ok = ok .and. same_bits([dxf(i + 1, a + 1, w + 1)], [dxc(1 + i + 3 * a + 36 * w)])
        end do
      end do
    end do
    call check(ok, label // ': dx(i,a,w) == C dx[i+3a+36w] bit for bit')
    ok = .true.
    do w = 0, 1
      do b = 0, 11
        do a = 0, 11
          do i = 0, 2
            ok = ok .and. same_bits([d2xf(i + 1, a + 1, b + 1, w + 1)], &
                                    [d2xc(1 + i + 3 * (a + 12 * b) + 432 * w)])
          end do
        end do
      end do
    end do
    call check(ok, label // ': d2x(i,a,b,w) == C d2x[i+3(a+12b)+432w] bit for bit')
    ! The same, as whole arrays in array element order.
    call check(same_bits(reshape(xf, [9]), xc) .and. same_bits(reshape(dxf, [72]), dxc) .and. &
               same_bits(reshape(d2xf, [864]), d2xc), label // ': whole arrays bit for bit')

    ! The comparison is not between two arrays of zeros: P = dx/dX is never
    ! zero, and the second derivatives are non-zero exactly for the terms that
    ! are nonlinear in X (nodal tangents from neighbours, host tangents).
    ! (The start tangent's Hermite weights h2, h2' vanish at xi = 1, the end
    ! tangent's h4, h4' at xi = -1.)
    call check(any(dxf(:, :, 1) /= 0.0_c_double), label // ': dx/dX is not zero')
    nodal = family(kind) == fam_nodal
    start_nonlinear = family(kind) /= fam_chord .and. (start_rule == B2B_END_TANGENT .or. &
                      (nodal .and. start_rule == B2B_END_NEIGHBOUR))
    end_nonlinear = family(kind) /= fam_chord .and. (end_rule == B2B_END_TANGENT .or. &
                    (nodal .and. end_rule == B2B_END_NEIGHBOUR))
    if (.not. (start_nonlinear .or. end_nonlinear)) then
      call check(all(d2xf == 0.0_c_double), label // ': d2x is zero (linear in X)')
    else if ((start_nonlinear .and. xi /= 1.0_c_double) .or. &
             (end_nonlinear .and. xi /= -1.0_c_double)) then
      call check(any(d2xf /= 0.0_c_double), label // ': d2x is not zero (nonlinear in X)')
    end if
    ! Symmetry of the second derivatives in a, b: up to rounding (the library
    ! computes both triangles, which may differ in the last bit).
    ok = .true.
    scale = max(maxval(abs(d2xf)), tiny(1.0_c_double))
    do w = 1, 2
      do b = 1, 12
        do a = 1, 12
          ok = ok .and. all(abs(d2xf(:, a, b, w) - d2xf(:, b, a, w)) <= 1.0e-14_c_double * scale)
        end do
      end do
    end do
    call check(ok, label // ': d2x(:,a,b,:) == d2x(:,b,a,:) to 1e-14 relative')
  end subroutine

  ! --------------------------------------------------------------- known values

  !> Evaluates through the module; x only.
  subroutine eval_x(kind, start_rule, end_rule, xi, x)
    integer, intent(in) :: kind, start_rule, end_rule
    real(c_double), intent(in) :: xi
    real(c_double), intent(out) :: x(3, 3)
    integer :: ierr
    character(len=B2B_ERRMSG_LEN) :: msg
    x = sentinel_f
    call b2b_segment_eval(kind, start_rule, end_rule, patch, xi, x=x, end_tangents=tangents, &
                          ierr=ierr, errmsg=msg)
    call check(ierr == B2B_OK, case_label(kind, start_rule, end_rule, xi) // &
               ': succeeds (' // trim(msg) // ')')
  end subroutine

  real(c_double) function norm(v)
    real(c_double), intent(in) :: v(:)
    norm = sqrt(sum(v**2))
  end function

  subroutine test_known_values()
    real(c_double) :: x(3, 3), x1(3), x2(3), x3(3), x4(3), l12, l13, l23, l24, l34, t(3)
    character(len=:), allocatable :: lab
    integer :: ir, kind, sr, er

    x1 = patch(:, 1)
    x2 = patch(:, 2)
    x3 = patch(:, 3)
    x4 = patch(:, 4)
    l12 = norm(x2 - x1)
    l13 = norm(x3 - x1)
    l23 = norm(x3 - x2)
    l24 = norm(x4 - x2)
    l34 = norm(x4 - x3)

    ! Nodal kinds pass through x2 at xi = -1 and x3 at xi = 1 under every rule.
    do kind = 0, B2B_CURVE_KIND_COUNT - 1
      if (family(kind) /= fam_nodal) cycle
      do ir = 1, n_rule_pairs
        sr = rule_pairs(1, ir)
        er = rule_pairs(2, ir)
        call eval_x(kind, sr, er, -1.0_c_double, x)
        call check(rel_diff(x(:, 1), x2, 0.0_c_double) <= 1.0e-15_c_double, &
                   case_label(kind, sr, er, -1.0_c_double) // ': x == x2')
        call eval_x(kind, sr, er, 1.0_c_double, x)
        call check(rel_diff(x(:, 1), x3, 0.0_c_double) <= 1.0e-15_c_double, &
                   case_label(kind, sr, er, 1.0_c_double) // ': x == x3')
      end do
    end do

    ! End tangents of the nodal kinds (b2b_curve.h).
    kind = B2B_CURVE_HERMITE_NODAL
    call eval_x(kind, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, -1.0_c_double, x)
    call check(rel_diff(x(:, 2), l23 * (x3 - x1) / (2 * l13), 1.0_c_double) <= 1.0e-14_c_double, &
               'HERMITE_NODAL: dx/dxi(-1) == l23 (x3 - x1)/(2 l13)')
    call eval_x(kind, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, 1.0_c_double, x)
    call check(rel_diff(x(:, 2), l23 * (x4 - x2) / (2 * l24), 1.0_c_double) <= 1.0e-14_c_double, &
               'HERMITE_NODAL: dx/dxi(1) == l23 (x4 - x2)/(2 l24)')
    kind = B2B_CURVE_HERMITE_NODAL_WEIGHTED
    t = l23**2 * (x2 - x1) + l12**2 * (x3 - x2)
    call eval_x(kind, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, -1.0_c_double, x)
    call check(rel_diff(x(:, 2), l23 / 2 * t / norm(t), 1.0_c_double) <= 1.0e-14_c_double, &
               'HERMITE_NODAL_WEIGHTED: dx/dxi(-1) == l23/2 unit(l23^2 (x2-x1) + l12^2 (x3-x2))')
    t = l34**2 * (x3 - x2) + l23**2 * (x4 - x3)
    call eval_x(kind, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, 1.0_c_double, x)
    call check(rel_diff(x(:, 2), l23 / 2 * t / norm(t), 1.0_c_double) <= 1.0e-14_c_double, &
               'HERMITE_NODAL_WEIGHTED: dx/dxi(1) == l23/2 unit(l34^2 (x3-x2) + l23^2 (x4-x3))')
    do kind = 0, B2B_CURVE_KIND_COUNT - 1
      if (family(kind) /= fam_nodal) cycle
      lab = kind_name(kind)
      call eval_x(kind, B2B_END_REFLECT, B2B_END_REFLECT, -1.0_c_double, x)
      call check(rel_diff(x(:, 2), (x3 - x2) / 2, 1.0_c_double) <= 1.0e-15_c_double, &
                 lab // ' REFLECT: dx/dxi(-1) == (x3 - x2)/2')
      call eval_x(kind, B2B_END_REFLECT, B2B_END_REFLECT, 1.0_c_double, x)
      call check(rel_diff(x(:, 2), (x3 - x2) / 2, 1.0_c_double) <= 1.0e-15_c_double, &
                 lab // ' REFLECT: dx/dxi(1) == (x3 - x2)/2')
      call eval_x(kind, B2B_END_TANGENT, B2B_END_TANGENT, -1.0_c_double, x)
      call check(rel_diff(x(:, 2), l23 / 2 * tangents(:, 1) / norm(tangents(:, 1)), &
                          1.0_c_double) <= 1.0e-14_c_double, &
                 lab // ' TANGENT: dx/dxi(-1) == l23/2 unit(end_tangents(:,1))')
      call eval_x(kind, B2B_END_TANGENT, B2B_END_TANGENT, 1.0_c_double, x)
      call check(rel_diff(x(:, 2), l23 / 2 * tangents(:, 2) / norm(tangents(:, 2)), &
                          1.0_c_double) <= 1.0e-14_c_double, &
                 lab // ' TANGENT: dx/dxi(1) == l23/2 unit(end_tangents(:,2))')
    end do

    ! Midpoint kind: from the midpoint of x1-x2 to the midpoint of x2-x3.
    kind = B2B_CURVE_HERMITE_MIDPOINT
    call eval_x(kind, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, -1.0_c_double, x)
    call check(rel_diff(x(:, 1), (x1 + x2) / 2, 0.0_c_double) <= 1.0e-15_c_double, &
               'HERMITE_MIDPOINT: x(-1) == (x1 + x2)/2')
    call check(rel_diff(x(:, 2), (x2 - x1) / 2, 0.0_c_double) <= 1.0e-15_c_double, &
               'HERMITE_MIDPOINT: dx/dxi(-1) == (x2 - x1)/2')
    call eval_x(kind, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, 1.0_c_double, x)
    call check(rel_diff(x(:, 1), (x2 + x3) / 2, 0.0_c_double) <= 1.0e-15_c_double, &
               'HERMITE_MIDPOINT: x(1) == (x2 + x3)/2')
    call check(rel_diff(x(:, 2), (x3 - x2) / 2, 0.0_c_double) <= 1.0e-15_c_double, &
               'HERMITE_MIDPOINT: dx/dxi(1) == (x3 - x2)/2')
    ! A midpoint segment at the beam's start is a half element from x2.
    call eval_x(kind, B2B_END_REFLECT, B2B_END_NEIGHBOUR, -1.0_c_double, x)
    call check(rel_diff(x(:, 1), x2, 0.0_c_double) <= 1.0e-15_c_double, &
               'HERMITE_MIDPOINT start REFLECT: x(-1) == x2')
    call eval_x(kind, B2B_END_NEIGHBOUR, B2B_END_REFLECT, 1.0_c_double, x)
    call check(rel_diff(x(:, 1), x2, 0.0_c_double) <= 1.0e-15_c_double, &
               'HERMITE_MIDPOINT end REFLECT: x(1) == x2')

    ! Linear kind: the chord; dx/dxi is exactly (x3 - x2)/2 at any xi.
    kind = B2B_CURVE_LINEAR
    call eval_x(kind, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, -1.0_c_double, x)
    call check(rel_diff(x(:, 1), x2, 0.0_c_double) <= 1.0e-15_c_double, 'LINEAR: x(-1) == x2')
    call check(all(x(:, 2) == (x3 - x2) / 2), 'LINEAR: dx/dxi(-1) == (x3 - x2)/2')
    call check(all(x(:, 3) == 0.0_c_double), 'LINEAR: d2x/dxi2(-1) == 0')
    call eval_x(kind, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, 1.7_c_double, x)
    call check(all(x(:, 2) == (x3 - x2) / 2), 'LINEAR: dx/dxi(1.7) == (x3 - x2)/2')
    call check(rel_diff(x(:, 1), x2 + 2.7_c_double * (x3 - x2) / 2, 1.0_c_double) <= &
               1.0e-15_c_double, 'LINEAR: x(1.7) on the extended chord')
    call eval_x(kind, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, 1.0_c_double, x)
    call check(rel_diff(x(:, 1), x3, 0.0_c_double) <= 1.0e-15_c_double, 'LINEAR: x(1) == x3')
  end subroutine

  ! ----------------------------------------------------------- optional outputs

  subroutine test_optional_outputs()
    real(c_double) :: xa(3, 3), dxa(3, 12, 2), d2xa(3, 12, 12, 2)
    real(c_double) :: xo(3, 3), dxo(3, 12, 2), d2xo(3, 12, 12, 2)
    integer :: kind, ierr
    character(len=:), allocatable :: lab
    real(c_double), parameter :: xi = 0.3_c_double

    do kind = 0, B2B_CURVE_KIND_COUNT - 1
      lab = kind_name(kind) // ' optional outputs'
      xa = sentinel_f
      dxa = sentinel_f
      d2xa = sentinel_f
      call b2b_segment_eval(kind, B2B_END_NEIGHBOUR, B2B_END_TANGENT, patch, xi, xa, dxa, d2xa, &
                            tangents, ierr)
      call check(ierr == B2B_OK, lab // ': all outputs, positional arguments')

      xo = sentinel_f
      call b2b_segment_eval(kind, B2B_END_NEIGHBOUR, B2B_END_TANGENT, patch, xi, x=xo, &
                            end_tangents=tangents, ierr=ierr)
      call check(ierr == B2B_OK, lab // ': x only succeeds')
      call check(same_bits(reshape(xo, [9]), reshape(xa, [9])), lab // ': x only == x of all')

      dxo = sentinel_f
      call b2b_segment_eval(kind, B2B_END_NEIGHBOUR, B2B_END_TANGENT, patch, xi, dx=dxo, &
                            end_tangents=tangents, ierr=ierr)
      call check(ierr == B2B_OK, lab // ': dx only succeeds')
      call check(same_bits(reshape(dxo, [72]), reshape(dxa, [72])), lab // ': dx only == dx of all')

      d2xo = sentinel_f
      call b2b_segment_eval(kind, B2B_END_NEIGHBOUR, B2B_END_TANGENT, patch, xi, d2x=d2xo, &
                            end_tangents=tangents, ierr=ierr)
      call check(ierr == B2B_OK, lab // ': d2x only succeeds')
      call check(same_bits(reshape(d2xo, [864]), reshape(d2xa, [864])), &
                 lab // ': d2x only == d2x of all')

      xo = sentinel_f
      d2xo = sentinel_f
      call b2b_segment_eval(kind, B2B_END_NEIGHBOUR, B2B_END_TANGENT, patch, xi, x=xo, d2x=d2xo, &
                            end_tangents=tangents, ierr=ierr)
      call check(ierr == B2B_OK .and. same_bits(reshape(xo, [9]), reshape(xa, [9])) .and. &
                 same_bits(reshape(d2xo, [864]), reshape(d2xa, [864])), &
                 lab // ': x and d2x without dx == those of all')

      ! No output at all: only the checks run.
      call b2b_segment_eval(kind, B2B_END_NEIGHBOUR, B2B_END_TANGENT, patch, xi, &
                            end_tangents=tangents, ierr=ierr)
      call check(ierr == B2B_OK, lab // ': no outputs succeeds')

      ! No ierr, no errmsg on success: returns normally.
      xo = sentinel_f
      call b2b_segment_eval(kind, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, patch, xi, x=xo)
      call check(all(xo /= sentinel_f), lab // ': success without ierr returns with x set')
    end do
  end subroutine

  ! ------------------------------------------------------------- array sections

  !> Non-contiguous actual arguments (the module's dummies are contiguous:
  !> the compiler copies in and out) give the same bits as plain arrays and
  !> leave the rest of the parent arrays alone.
  subroutine test_sections()
    real(c_double) :: pbig(5, 6), tbig(4, 3), xbig(5, 4), dxbig(4, 13, 2), d2xbig(3, 12, 13, 3)
    real(c_double) :: xa(3, 3), dxa(3, 12, 2), d2xa(3, 12, 12, 2)
    integer :: kind, ierr
    character(len=:), allocatable :: lab
    logical :: ok
    real(c_double), parameter :: xi = -0.55_c_double

    do kind = 0, B2B_CURVE_KIND_COUNT - 1
      lab = kind_name(kind) // ' sections'
      call b2b_segment_eval(kind, B2B_END_TANGENT, B2B_END_NEIGHBOUR, patch, xi, x=xa, dx=dxa, &
                            d2x=d2xa, end_tangents=tangents, ierr=ierr)
      call check(ierr == B2B_OK, lab // ': plain call succeeds')
      pbig = ieee_value(0.0_c_double, ieee_quiet_nan)
      pbig(2:4, 2:5) = patch
      tbig = ieee_value(0.0_c_double, ieee_quiet_nan)
      tbig(2:4, 2:3) = tangents
      xbig = sentinel_f
      dxbig = sentinel_f
      d2xbig = sentinel_f
      call b2b_segment_eval(kind, B2B_END_TANGENT, B2B_END_NEIGHBOUR, pbig(2:4, 2:5), xi, &
                            x=xbig(2:4, 2:4), dx=dxbig(2:4, 2:13, :), &
                            d2x=d2xbig(:, :, 2:13, 2:3), end_tangents=tbig(2:4, 2:3), ierr=ierr)
      call check(ierr == B2B_OK, lab // ': call with sections succeeds')
      call check(same_bits(reshape(xbig(2:4, 2:4), [9]), reshape(xa, [9])), lab // ': x')
      call check(same_bits(reshape(dxbig(2:4, 2:13, :), [72]), reshape(dxa, [72])), lab // ': dx')
      call check(same_bits(reshape(d2xbig(:, :, 2:13, 2:3), [864]), reshape(d2xa, [864])), &
                 lab // ': d2x')
      ok = all(xbig(1, :) == sentinel_f) .and. all(xbig(5, :) == sentinel_f) .and. &
           all(xbig(:, 1) == sentinel_f)
      ok = ok .and. all(dxbig(1, :, :) == sentinel_f) .and. all(dxbig(:, 1, :) == sentinel_f)
      ok = ok .and. all(d2xbig(:, :, 1, :) == sentinel_f) .and. &
           all(d2xbig(:, :, :, 1) == sentinel_f)
      call check(ok, lab // ': elements outside the sections untouched')
    end do
  end subroutine

  ! ------------------------------------------------------------------- topology

  subroutine expect_count(kind, n_nodes, closed, expected)
    integer, intent(in) :: kind, n_nodes, expected
    logical, intent(in) :: closed
    integer :: n_seg, ierr
    character(len=B2B_ERRMSG_LEN) :: msg
    character(len=:), allocatable :: lab
    lab = 'b2b_beam_segment_count ' // kind_name(kind) // ' ' // &
          merge('closed', 'open  ', closed) // ' n=' // int_str(n_nodes)
    n_seg = -1
    msg = 'garbage'
    call b2b_beam_segment_count(kind, n_nodes, closed, n_seg, ierr, msg)
    call check(ierr == B2B_OK .and. msg == '', lab // ': succeeds')
    call check(n_seg == expected, lab // ': ' // int_str(n_seg) // ' == ' // int_str(expected))
    n_seg = -1
    call b2b_beam_segment_count(kind, n_nodes, closed, n_seg)
    call check(n_seg == expected, lab // ' (no ierr): ' // int_str(n_seg))
  end subroutine

  subroutine expect_patch(kind, n_nodes, closed, segment, nodes_expected, sr_expected, &
                          er_expected)
    integer, intent(in) :: kind, n_nodes, segment, nodes_expected(4), sr_expected, er_expected
    logical, intent(in) :: closed
    integer :: nodes(4), sr, er, ierr
    character(len=B2B_ERRMSG_LEN) :: msg
    character(len=:), allocatable :: lab
    character(len=64) :: got
    lab = 'b2b_beam_segment_patch ' // kind_name(kind) // ' ' // &
          merge('closed', 'open  ', closed) // ' n=' // int_str(n_nodes) // ' segment ' // &
          int_str(segment)
    nodes = -99
    sr = -99
    er = -99
    msg = 'garbage'
    call b2b_beam_segment_patch(kind, n_nodes, closed, segment, nodes, sr, er, ierr, msg)
    call check(ierr == B2B_OK .and. msg == '', lab // ': succeeds')
    write (got, '(4(i0, 1x))') nodes
    call check(all(nodes == nodes_expected), lab // ': nodes = ' // trim(got))
    call check(sr == sr_expected, lab // ': start_rule = ' // int_str(sr))
    call check(er == er_expected, lab // ': end_rule = ' // int_str(er))
  end subroutine

  subroutine test_topology()
    integer, parameter :: N = B2B_END_NEIGHBOUR, R = B2B_END_REFLECT
    integer :: kind, n_seg, ierr

    call expect_count(B2B_CURVE_HERMITE_NODAL, 5, .false., 4)
    call expect_count(B2B_CURVE_HERMITE_NODAL_WEIGHTED, 5, .false., 4)
    call expect_count(B2B_CURVE_LINEAR, 5, .false., 4)
    call expect_count(B2B_CURVE_HERMITE_MIDPOINT, 5, .false., 5)
    do kind = 0, B2B_CURVE_KIND_COUNT - 1
      call expect_count(kind, 5, .true., 5)
      call expect_count(kind, 3, .true., 3)
    end do
    ! The first value past the last kind is not a kind.
    call b2b_beam_segment_count(B2B_CURVE_KIND_COUNT, 5, .false., n_seg, ierr)
    call check(ierr == B2B_ERR_UNKNOWN_KIND, 'b2b_beam_segment_count(B2B_CURVE_KIND_COUNT): ' // &
               'B2B_ERR_UNKNOWN_KIND')
    call expect_count(B2B_CURVE_HERMITE_NODAL, 2, .false., 1)
    call expect_count(B2B_CURVE_HERMITE_MIDPOINT, 2, .false., 2)

    ! Open nodal beam of 5 nodes: 0 marks the missing ghost slots.
    do kind = 0, B2B_CURVE_KIND_COUNT - 1
      if (family(kind) /= fam_nodal) cycle
      call expect_patch(kind, 5, .false., 1, [0, 1, 2, 3], R, N)
      call expect_patch(kind, 5, .false., 2, [1, 2, 3, 4], N, N)
      call expect_patch(kind, 5, .false., 4, [3, 4, 5, 0], N, R)
      ! Closed ring of 5 nodes wraps around.
      call expect_patch(kind, 5, .true., 1, [5, 1, 2, 3], N, N)
      call expect_patch(kind, 5, .true., 4, [3, 4, 5, 1], N, N)
      call expect_patch(kind, 5, .true., 5, [4, 5, 1, 2], N, N)
    end do
    ! A single nodal segment both starts and ends the beam.
    call expect_patch(B2B_CURVE_HERMITE_NODAL, 2, .false., 1, [0, 1, 2, 0], R, R)
    ! The linear kind never reads slots 1 and 4.
    call expect_patch(B2B_CURVE_LINEAR, 5, .false., 1, [0, 1, 2, 0], R, N)
    call expect_patch(B2B_CURVE_LINEAR, 5, .false., 2, [0, 2, 3, 0], N, N)
    call expect_patch(B2B_CURVE_LINEAR, 5, .false., 4, [0, 4, 5, 0], N, R)
    call expect_patch(B2B_CURVE_LINEAR, 5, .true., 1, [0, 1, 2, 0], N, N)
    call expect_patch(B2B_CURVE_LINEAR, 5, .true., 5, [0, 5, 1, 0], N, N)
    ! Midpoint kind: segment s is centred on node s; slot 4 is never read.
    call expect_patch(B2B_CURVE_HERMITE_MIDPOINT, 5, .false., 1, [0, 1, 2, 0], R, N)
    call expect_patch(B2B_CURVE_HERMITE_MIDPOINT, 5, .false., 3, [2, 3, 4, 0], N, N)
    call expect_patch(B2B_CURVE_HERMITE_MIDPOINT, 5, .false., 5, [4, 5, 0, 0], N, R)
    call expect_patch(B2B_CURVE_HERMITE_MIDPOINT, 5, .true., 1, [5, 1, 2, 0], N, N)
    call expect_patch(B2B_CURVE_HERMITE_MIDPOINT, 5, .true., 5, [4, 5, 1, 0], N, N)
  end subroutine

  ! ---------------------------------------------------------------- a beam walk

  !> Gathers every segment's patch of an open beam and of a ring with the
  !> 1-based topology (missing and unused slots hold NaN, so a slot that is
  !> read by mistake fails the call) and checks that neighbouring segments
  !> meet, and that nodal segments start at their node.
  subroutine test_beam_walk()
    integer, parameter :: n_nodes = 6
    real(c_double) :: coords(3, n_nodes), p(3, 4), xa(3, 3), xb(3, 3), nan
    integer :: kind, n_seg, s, k, nodes(4), sr, er, ierr, ic
    logical :: closed
    character(len=B2B_ERRMSG_LEN) :: msg
    character(len=:), allocatable :: lab

    nan = ieee_value(0.0_c_double, ieee_quiet_nan)
    do k = 1, n_nodes
      coords(:, k) = [cos(0.7_c_double * k), sin(0.7_c_double * k), 0.15_c_double * k**1.3_c_double]
    end do
    do ic = 0, 1
      closed = ic == 1
      do kind = 0, B2B_CURVE_KIND_COUNT - 1
        call b2b_beam_segment_count(kind, n_nodes, closed, n_seg, ierr)
        call check(ierr == B2B_OK, 'beam walk: count')
        xb = 0
        do s = 1, n_seg
          lab = 'beam walk ' // kind_name(kind) // merge(' closed', ' open  ', closed) // &
                ' segment ' // int_str(s)
          call b2b_beam_segment_patch(kind, n_nodes, closed, s, nodes, sr, er, ierr, msg)
          call check(ierr == B2B_OK, lab // ': patch ' // trim(msg))
          do k = 1, 4
            if (nodes(k) == 0) then
              p(:, k) = nan
            else
              p(:, k) = coords(:, nodes(k))
            end if
          end do
          call b2b_segment_eval(kind, sr, er, p, -1.0_c_double, x=xa, ierr=ierr, errmsg=msg)
          call check(ierr == B2B_OK, lab // ': eval at -1 ' // trim(msg))
          if (family(kind) /= fam_centred) then
            call check(rel_diff(xa(:, 1), coords(:, s), 1.0_c_double) <= 1.0e-15_c_double, &
                       lab // ': starts at node ' // int_str(s))
          end if
          if (s > 1) then
            call check(rel_diff(xa(:, 1), xb(:, 1), 1.0_c_double) <= 1.0e-15_c_double, &
                       lab // ': meets the previous segment')
          end if
          call b2b_segment_eval(kind, sr, er, p, 1.0_c_double, x=xb, ierr=ierr, errmsg=msg)
          call check(ierr == B2B_OK, lab // ': eval at 1 ' // trim(msg))
        end do
      end do
    end do
  end subroutine

end program ftest_curve
