!> Error paths of module b2b with ierr and errmsg present: the status, a
!> message naming the problem, and outputs left untouched on failure (they are
!> pre-filled with a sentinel); on success ierr == 0 and errmsg == ''.
program ftest_errors
  use, intrinsic :: iso_c_binding, only: c_double
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf
  use b2b
  use ftest_check
  implicit none

  real(c_double), parameter :: sentinel = -7.0_c_double
  integer, parameter :: isentinel = -77
  real(c_double), parameter :: patch0(3, 4) = reshape([ &
    0.0_c_double, 0.0_c_double, 0.0_c_double, &
    1.0_c_double, 0.3_c_double, -0.2_c_double, &
    2.1_c_double, 1.1_c_double, 0.1_c_double, &
    2.7_c_double, 2.4_c_double, 0.8_c_double], [3, 4])
  real(c_double), parameter :: tangents0(3, 2) = reshape([ &
    1.0_c_double, 0.2_c_double, 0.1_c_double, &
    0.4_c_double, 1.0_c_double, 0.5_c_double], [3, 2])
  real(c_double), parameter :: xi = 0.3_c_double

  ! Outputs of b2b_segment_eval, reset to the sentinel before every call.
  real(c_double) :: x(3, 3), dx(3, 12, 2), d2x(3, 12, 12, 2)
  integer :: ierr
  character(len=B2B_ERRMSG_LEN) :: msg

  call test_shapes()
  call test_bad_values()
  call test_topology_errors()
  call test_success_clears()
  call test_message_buffers()
  call check_summary('ftest_errors')

contains

  subroutine reset()
    x = sentinel
    dx = sentinel
    d2x = sentinel
    ierr = isentinel
    msg = 'garbage'
  end subroutine

  logical function outputs_untouched()
    outputs_untouched = all_equal_to(reshape(x, [9]), sentinel) .and. &
                        all_equal_to(reshape(dx, [72]), sentinel) .and. &
                        all_equal_to(reshape(d2x, [864]), sentinel)
  end function

  !> ierr == expected, a non-empty errmsg that contains `needle`, outputs untouched.
  subroutine expect_failure(label, expected, needle)
    character(len=*), intent(in) :: label, needle
    integer, intent(in) :: expected
    call check(ierr == expected, label // ': ierr ' // int_str(ierr) // ' == ' // &
               int_str(expected) // ' [' // trim(msg) // ']')
    call check(len_trim(msg) > 0, label // ': errmsg is not empty')
    call check(contains_text(msg, needle), label // ': errmsg "' // trim(msg) // &
               '" contains "' // needle // '"')
    call check(outputs_untouched(), label // ': outputs untouched')
  end subroutine

  ! ----------------------------------------------------------- wrong shapes

  subroutine test_shapes()
    real(c_double) :: p33(3, 3), x32(3, 2), dx1(3, 12, 1), d2x1(3, 12, 12, 1), t31(3, 1)
    real(c_double) :: p43(4, 3), p12(12), x33t(3, 3)
    integer :: nodes3(3), nodes5(5), nodes4(4), sr, er
    character(len=*), parameter :: nodal_label = 'HERMITE_NODAL'

    p33 = patch0(:, 1:3)
    call reset()
    call b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, p33, xi, &
                          x=x, dx=dx, d2x=d2x, ierr=ierr, errmsg=msg)
    call expect_failure('patch(3,3)', B2B_ERR_SIZE, ' patch ')
    call check(contains_text(msg, '(3,3)') .and. contains_text(msg, '(3,4)'), &
               'patch(3,3): errmsg gives the shapes')

    p43 = 1.0_c_double
    call reset()
    call b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, p43, xi, &
                          x=x, dx=dx, d2x=d2x, ierr=ierr, errmsg=msg)
    call expect_failure('patch(4,3)', B2B_ERR_SIZE, ' patch ')

    ! 12 doubles are not enough: the shape must be (3,4). (patch is rank 2,
    ! so a rank-1 array is passed as a (12,1) reshape.)
    p12 = reshape(patch0, [12])
    call reset()
    call b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, &
                          reshape(p12, [12, 1]), xi, x=x, dx=dx, d2x=d2x, ierr=ierr, errmsg=msg)
    call expect_failure('patch(12,1)', B2B_ERR_SIZE, ' patch ')

    x32 = sentinel
    call reset()
    call b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, patch0, &
                          xi, x=x32, dx=dx, d2x=d2x, ierr=ierr, errmsg=msg)
    call expect_failure('x(3,2)', B2B_ERR_SIZE, ' x ')
    call check(all_equal_to(reshape(x32, [6]), sentinel), 'x(3,2): x untouched')

    ! The transposed shape of a square array is the same shape: (3,3) is
    ! right, whatever the caller meant. Sanity check that it succeeds.
    x33t = sentinel
    call reset()
    call b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, patch0, &
                          xi, x=x33t, ierr=ierr, errmsg=msg)
    call check(ierr == B2B_OK, 'x(3,3) succeeds')

    dx1 = sentinel
    call reset()
    call b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, patch0, &
                          xi, x=x, dx=dx1, d2x=d2x, ierr=ierr, errmsg=msg)
    call expect_failure('dx(3,12,1)', B2B_ERR_SIZE, ' dx ')
    call check(all_equal_to(reshape(dx1, [36]), sentinel), 'dx(3,12,1): dx untouched')

    d2x1 = sentinel
    call reset()
    call b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, patch0, &
                          xi, x=x, dx=dx, d2x=d2x1, ierr=ierr, errmsg=msg)
    call expect_failure('d2x(3,12,12,1)', B2B_ERR_SIZE, ' d2x ')
    call check(all_equal_to(reshape(d2x1, [432]), sentinel), 'd2x(3,12,12,1): d2x untouched')

    t31 = tangents0(:, 1:1)
    call reset()
    call b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_TANGENT, B2B_END_NEIGHBOUR, patch0, &
                          xi, x=x, dx=dx, d2x=d2x, end_tangents=t31, ierr=ierr, errmsg=msg)
    call expect_failure('end_tangents(3,1)', B2B_ERR_SIZE, ' end_tangents ')

    ! A wrong shape is reported even where the array would not be read.
    call reset()
    call b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, patch0, &
                          xi, x=x, dx=dx, d2x=d2x, end_tangents=t31, ierr=ierr, errmsg=msg)
    call expect_failure('end_tangents(3,1), rules NEIGHBOUR', B2B_ERR_SIZE, ' end_tangents ')

    nodes3 = isentinel
    sr = isentinel
    er = isentinel
    call reset()
    call b2b_beam_segment_patch(B2B_CURVE_HERMITE_NODAL, 5, .false., 2, nodes3, sr, er, ierr, msg)
    call check(ierr == B2B_ERR_SIZE, 'nodes(3): ierr == B2B_ERR_SIZE [' // trim(msg) // ']')
    call check(contains_text(msg, ' nodes '), 'nodes(3): errmsg "' // trim(msg) // &
               '" names nodes')
    call check(all(nodes3 == isentinel) .and. sr == isentinel .and. er == isentinel, &
               'nodes(3): nodes, start_rule, end_rule untouched')

    nodes5 = isentinel
    call reset()
    call b2b_beam_segment_patch(B2B_CURVE_HERMITE_NODAL, 5, .false., 2, nodes5, sr, er, ierr, msg)
    call check(ierr == B2B_ERR_SIZE .and. contains_text(msg, ' nodes '), &
               'nodes(5): ierr == B2B_ERR_SIZE, errmsg names nodes')
    call check(all(nodes5 == isentinel) .and. sr == isentinel .and. er == isentinel, &
               'nodes(5): outputs untouched')

    nodes4 = isentinel
    call reset()
    call b2b_beam_segment_patch(B2B_CURVE_HERMITE_NODAL, 5, .false., 2, nodes4, sr, er, ierr, msg)
    call check(ierr == B2B_OK .and. msg == '' .and. all(nodes4 == [1, 2, 3, 4]), &
               'nodes(4) ' // nodal_label // ' segment 2: succeeds with [1,2,3,4]')
  end subroutine

  ! ------------------------------------------------------------- bad values

  subroutine test_bad_values()
    real(c_double) :: p(3, 4), nan, inf
    integer :: c, i

    nan = ieee_value(0.0_c_double, ieee_quiet_nan)
    inf = ieee_value(0.0_c_double, ieee_positive_inf)

    ! NaN in each coordinate of node 3 (column 3) for each kind: every kind reads x3.
    do i = 1, 3
      p = patch0
      p(i, 3) = nan
      call reset()
      call b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, p, xi, &
                            x=x, dx=dx, d2x=d2x, ierr=ierr, errmsg=msg)
      call expect_failure('NaN in patch(' // int_str(i) // ',3)', B2B_ERR_NONFINITE, 'x3')
      call check(contains_text(msg, 'xyz'(i:i) // ' coordinate'), &
                 'NaN in patch(' // int_str(i) // ',3): errmsg names the ' // 'xyz'(i:i) // &
                 ' coordinate')
    end do
    do c = B2B_CURVE_LINEAR, B2B_CURVE_HERMITE_NODAL_WEIGHTED
      p = patch0
      p(2, 3) = nan
      call reset()
      call b2b_segment_eval(c, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, p, xi, &
                            x=x, dx=dx, d2x=d2x, ierr=ierr, errmsg=msg)
      call expect_failure('NaN in x3, kind ' // int_str(c), B2B_ERR_NONFINITE, 'x3')
    end do
    ! The other columns name their node.
    do c = 1, 4
      p = patch0
      p(1, c) = inf
      call reset()
      call b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, p, xi, &
                            x=x, dx=dx, d2x=d2x, ierr=ierr, errmsg=msg)
      call expect_failure('Inf in column ' // int_str(c), B2B_ERR_NONFINITE, 'x' // int_str(c))
    end do
    ! A NaN in a slot the kind does not read is never looked at.
    p = patch0
    p(:, 1) = nan
    p(:, 4) = nan
    call reset()
    call b2b_segment_eval(B2B_CURVE_LINEAR, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, p, xi, &
                          x=x, dx=dx, d2x=d2x, ierr=ierr, errmsg=msg)
    call check(ierr == B2B_OK .and. msg == '', 'LINEAR ignores NaN in slots 1 and 4 [' // &
               trim(msg) // ']')
    call reset()
    call b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_REFLECT, B2B_END_REFLECT, p, xi, &
                          x=x, dx=dx, d2x=d2x, ierr=ierr, errmsg=msg)
    call check(ierr == B2B_OK .and. msg == '', 'HERMITE_NODAL REFLECT/REFLECT ignores NaN in ' // &
               'slots 1 and 4 [' // trim(msg) // ']')
    ! NaN xi.
    call reset()
    call b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, patch0, &
                          nan, x=x, dx=dx, d2x=d2x, ierr=ierr, errmsg=msg)
    call expect_failure('NaN xi', B2B_ERR_NONFINITE, 'xi')
    ! NaN in a used end tangent.
    call reset()
    call b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_TANGENT, patch0, xi, &
                          x=x, dx=dx, d2x=d2x, end_tangents=reshape([tangents0(:, 1), nan, &
                          0.0_c_double, 1.0_c_double], [3, 2]), ierr=ierr, errmsg=msg)
    call expect_failure('NaN end tangent', B2B_ERR_NONFINITE, 'last')
    ! Zero end tangent.
    call reset()
    call b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_TANGENT, B2B_END_NEIGHBOUR, patch0, xi, &
                          x=x, dx=dx, d2x=d2x, end_tangents=reshape([0.0_c_double, &
                          0.0_c_double, 0.0_c_double, tangents0(:, 2)], [3, 2]), ierr=ierr, &
                          errmsg=msg)
    call expect_failure('zero end tangent', B2B_ERR_RANGE, 'zero')
    ! A coordinate beyond B2B_COORD_MAX.
    p = patch0
    p(3, 2) = 2 * B2B_COORD_MAX
    call reset()
    call b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, p, xi, &
                          x=x, dx=dx, d2x=d2x, ierr=ierr, errmsg=msg)
    call expect_failure('coordinate beyond B2B_COORD_MAX', B2B_ERR_RANGE, 'x2')

    ! Coincident nodes 2 and 3, for every kind.
    do c = B2B_CURVE_LINEAR, B2B_CURVE_HERMITE_NODAL_WEIGHTED
      p = patch0
      p(:, 3) = p(:, 2)
      call reset()
      call b2b_segment_eval(c, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, p, xi, &
                            x=x, dx=dx, d2x=d2x, ierr=ierr, errmsg=msg)
      call expect_failure('coincident x2 == x3, kind ' // int_str(c), B2B_ERR_COINCIDENT, 'x2')
      call check(contains_text(msg, 'x3'), 'coincident x2 == x3, kind ' // int_str(c) // &
                 ': errmsg names x3')
    end do

    ! Folded: x1 == x3, so the tangent at x2 has no direction.
    do c = B2B_CURVE_HERMITE_NODAL, B2B_CURVE_HERMITE_NODAL_WEIGHTED
      p = patch0
      p(:, 1) = p(:, 3)
      call reset()
      call b2b_segment_eval(c, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, p, xi, &
                            x=x, dx=dx, d2x=d2x, ierr=ierr, errmsg=msg)
      call expect_failure('folded x1 == x3, kind ' // int_str(c), B2B_ERR_FOLDED, 'x1')
      ! Same with x4 == x2 at the other end.
      p = patch0
      p(:, 4) = p(:, 2)
      call reset()
      call b2b_segment_eval(c, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, p, xi, &
                            x=x, dx=dx, d2x=d2x, ierr=ierr, errmsg=msg)
      call expect_failure('folded x4 == x2, kind ' // int_str(c), B2B_ERR_FOLDED, 'x4')
    end do

    ! Unknown kind and rules.
    call reset()
    call b2b_segment_eval(17, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, patch0, xi, &
                          x=x, dx=dx, d2x=d2x, ierr=ierr, errmsg=msg)
    call expect_failure('kind 17', B2B_ERR_UNKNOWN_KIND, '17')
    call reset()
    call b2b_segment_eval(-1, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, patch0, xi, &
                          x=x, dx=dx, d2x=d2x, ierr=ierr, errmsg=msg)
    call expect_failure('kind -1', B2B_ERR_UNKNOWN_KIND, '-1')
    call reset()
    call b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, 3, B2B_END_NEIGHBOUR, patch0, xi, &
                          x=x, dx=dx, d2x=d2x, ierr=ierr, errmsg=msg)
    call expect_failure('start_rule 3', B2B_ERR_UNKNOWN_KIND, 'start_rule')
    call reset()
    call b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, 9, patch0, xi, &
                          x=x, dx=dx, d2x=d2x, ierr=ierr, errmsg=msg)
    call expect_failure('end_rule 9', B2B_ERR_UNKNOWN_KIND, 'end_rule')

    ! B2B_END_TANGENT without end_tangents.
    call reset()
    call b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_TANGENT, B2B_END_NEIGHBOUR, patch0, xi, &
                          x=x, dx=dx, d2x=d2x, ierr=ierr, errmsg=msg)
    call expect_failure('start TANGENT without end_tangents', B2B_ERR_NULL, 'end_tangents')
    call reset()
    call b2b_segment_eval(B2B_CURVE_HERMITE_MIDPOINT, B2B_END_NEIGHBOUR, B2B_END_TANGENT, patch0, &
                          xi, x=x, dx=dx, d2x=d2x, ierr=ierr, errmsg=msg)
    call expect_failure('midpoint end TANGENT without end_tangents', B2B_ERR_NULL, 'end_tangents')

    ! A midpoint segment cannot both start and end the beam.
    call reset()
    call b2b_segment_eval(B2B_CURVE_HERMITE_MIDPOINT, B2B_END_REFLECT, B2B_END_REFLECT, patch0, &
                          xi, x=x, dx=dx, d2x=d2x, ierr=ierr, errmsg=msg)
    call expect_failure('midpoint REFLECT/REFLECT', B2B_ERR_RANGE, 'B2B_CURVE_HERMITE_MIDPOINT')

    ! ierr without errmsg.
    call reset()
    call b2b_segment_eval(17, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, patch0, xi, x=x, ierr=ierr)
    call check(ierr == B2B_ERR_UNKNOWN_KIND .and. outputs_untouched(), &
               'kind 17, ierr without errmsg: ierr == B2B_ERR_UNKNOWN_KIND, x untouched')
    call reset()
    call b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, &
                          patch0(:, 1:3), xi, x=x, ierr=ierr)
    call check(ierr == B2B_ERR_SIZE .and. outputs_untouched(), &
               'patch(3,3), ierr without errmsg: ierr == B2B_ERR_SIZE, x untouched')
  end subroutine

  ! ----------------------------------------------------------- topology errors

  subroutine test_topology_errors()
    integer :: nodes(4), sr, er, n_seg, c

    do c = B2B_CURVE_LINEAR, B2B_CURVE_HERMITE_NODAL_WEIGHTED
      ! Segment 0 is not a segment (1-based).
      nodes = isentinel
      sr = isentinel
      er = isentinel
      call reset()
      call b2b_beam_segment_patch(c, 5, .false., 0, nodes, sr, er, ierr, msg)
      call check(ierr == B2B_ERR_RANGE, 'segment 0, kind ' // int_str(c) // &
                 ': ierr == B2B_ERR_RANGE [' // trim(msg) // ']')
      call check(len_trim(msg) > 0 .and. contains_text(msg, 'segment'), 'segment 0, kind ' // &
                 int_str(c) // ': errmsg names the segment')
      call check(all(nodes == isentinel) .and. sr == isentinel .and. er == isentinel, &
                 'segment 0, kind ' // int_str(c) // ': outputs untouched')
      ! One past the last segment.
      call b2b_beam_segment_count(c, 5, .false., n_seg, ierr)
      call check(ierr == B2B_OK, 'count for kind ' // int_str(c))
      call reset()
      call b2b_beam_segment_patch(c, 5, .false., n_seg + 1, nodes, sr, er, ierr, msg)
      call check(ierr == B2B_ERR_RANGE .and. all(nodes == isentinel), 'segment n_seg + 1, kind ' &
                 // int_str(c) // ': ierr == B2B_ERR_RANGE, nodes untouched [' // trim(msg) // ']')
      ! The last segment itself is fine.
      call reset()
      call b2b_beam_segment_patch(c, 5, .false., n_seg, nodes, sr, er, ierr, msg)
      call check(ierr == B2B_OK .and. msg == '', 'segment n_seg, kind ' // int_str(c) // &
                 ': succeeds')
    end do

    ! Too few nodes: an open beam needs 2, a ring 3.
    n_seg = isentinel
    call reset()
    call b2b_beam_segment_count(B2B_CURVE_HERMITE_NODAL, 1, .false., n_seg, ierr, msg)
    call check(ierr == B2B_ERR_RANGE .and. len_trim(msg) > 0 .and. n_seg == isentinel, &
               'count n_nodes = 1: B2B_ERR_RANGE, errmsg, n_segments untouched [' // &
               trim(msg) // ']')
    call reset()
    call b2b_beam_segment_count(B2B_CURVE_HERMITE_NODAL, 2, .true., n_seg, ierr, msg)
    call check(ierr == B2B_ERR_RANGE .and. n_seg == isentinel, &
               'count closed n_nodes = 2: B2B_ERR_RANGE [' // trim(msg) // ']')
    nodes = isentinel
    call reset()
    call b2b_beam_segment_patch(B2B_CURVE_HERMITE_NODAL, 1, .false., 1, nodes, sr, er, ierr, msg)
    call check(ierr == B2B_ERR_RANGE .and. len_trim(msg) > 0 .and. all(nodes == isentinel), &
               'patch n_nodes = 1: B2B_ERR_RANGE, errmsg, nodes untouched [' // trim(msg) // ']')
    call reset()
    call b2b_beam_segment_count(17, 5, .false., n_seg, ierr, msg)
    call check(ierr == B2B_ERR_UNKNOWN_KIND .and. contains_text(msg, '17') .and. &
               n_seg == isentinel, 'count kind 17: B2B_ERR_UNKNOWN_KIND [' // trim(msg) // ']')
    call reset()
    call b2b_beam_segment_patch(17, 5, .false., 1, nodes, sr, er, ierr, msg)
    call check(ierr == B2B_ERR_UNKNOWN_KIND .and. all(nodes == isentinel), &
               'patch kind 17: B2B_ERR_UNKNOWN_KIND [' // trim(msg) // ']')
  end subroutine

  ! --------------------------------------------------------- success clears

  !> After a failure, a successful call sets ierr = 0 and errmsg = ''.
  subroutine test_success_clears()
    integer :: nodes(4), sr, er, n_seg, c, major, minor, patch_v, abi

    do c = B2B_CURVE_LINEAR, B2B_CURVE_HERMITE_NODAL_WEIGHTED
      call reset()
      call b2b_segment_eval(c, B2B_END_NEIGHBOUR, B2B_END_TANGENT, patch0, xi, x=x, dx=dx, &
                            d2x=d2x, end_tangents=tangents0, ierr=ierr, errmsg=msg)
      call check(ierr == 0 .and. msg == '', 'segment_eval kind ' // int_str(c) // &
                 ': success gives ierr == 0 and errmsg == '''' [' // trim(msg) // ']')
      call check(all(x /= sentinel) .and. all(dx /= sentinel) .and. all(d2x /= sentinel), &
                 'segment_eval kind ' // int_str(c) // ': success writes every output')
    end do
    call reset()
    call b2b_beam_segment_count(B2B_CURVE_HERMITE_NODAL, 5, .false., n_seg, ierr, msg)
    call check(ierr == 0 .and. msg == '' .and. n_seg == 4, 'count: success clears')
    call reset()
    call b2b_beam_segment_patch(B2B_CURVE_HERMITE_NODAL, 5, .false., 1, nodes, sr, er, ierr, msg)
    call check(ierr == 0 .and. msg == '', 'patch: success clears')
    call reset()
    call b2b_version(major, minor, patch_v, ierr, msg)
    call check(ierr == 0 .and. msg == '', 'version: success clears')
    call reset()
    call b2b_abi_version(abi, ierr, msg)
    call check(ierr == 0 .and. msg == '', 'abi_version: success clears')
  end subroutine

  ! -------------------------------------------------------- message buffers

  !> errmsg of any length: a short one holds the start of the message, a long
  !> one the whole message padded with blanks.
  subroutine test_message_buffers()
    character(len=10) :: short
    character(len=1000) :: long
    character(len=:), allocatable :: whole

    call reset()
    call b2b_segment_eval(17, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, patch0, xi, x=x, &
                          ierr=ierr, errmsg=msg)
    whole = trim(msg)
    call check(ierr == B2B_ERR_UNKNOWN_KIND .and. len(whole) > 10, 'reference message')
    call check(whole(1:18) == 'b2b_segment_eval: ', 'message starts with the function name')

    short = 'garbage'
    call b2b_segment_eval(17, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, patch0, xi, x=x, &
                          ierr=ierr, errmsg=short)
    call check(ierr == B2B_ERR_UNKNOWN_KIND .and. short == whole(1:10), &
               'errmsg(len=10) holds the first 10 characters: "' // short // '"')

    long = 'garbage'
    call b2b_segment_eval(17, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, patch0, xi, x=x, &
                          ierr=ierr, errmsg=long)
    call check(ierr == B2B_ERR_UNKNOWN_KIND .and. long == whole, &
               'errmsg(len=1000) holds the whole message')

    ! The module's own shape messages too.
    long = 'garbage'
    call b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, &
                          patch0(:, 1:3), xi, ierr=ierr, errmsg=long)
    call check(ierr == B2B_ERR_SIZE .and. trim(long) == &
               'b2b_segment_eval: patch has shape (3,3), expected (3,4)', &
               'shape message: "' // trim(long) // '"')
    short = 'garbage'
    call b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, &
                          patch0(:, 1:3), xi, ierr=ierr, errmsg=short)
    call check(ierr == B2B_ERR_SIZE .and. short == 'b2b_segmen', 'short shape message')
  end subroutine

end program ftest_errors
