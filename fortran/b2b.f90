!> Fortran 2003 interface to b2b, beam-to-beam contact for finite-element codes.
!>
!> use b2b gives every function of the C ABI (include/b2b/b2b.h) as a module
!> procedure of the same name, plus every C constant (B2B_OK, B2B_CURVE_*, ...)
!> as a parameter of the same name and value, generated from the C headers.
!>
!> Conventions of the wrappers:
!>  * Arrays are assumed-shape and must be contiguous (sections are copied in
!>    by the compiler); their shapes are checked, a wrong shape gives
!>    B2B_ERR_SIZE. Node coordinates are (3, nodes) arrays.
!>  * Node and segment numbers are 1-based; a missing node is 0.
!>  * Every procedure ends with two optional arguments: ierr (the status, 0 on
!>    success) and errmsg (the message naming the problem, '' on success).
!>    If ierr is absent and the call fails, the program stops with the message.
!>  * On failure no output argument is changed (outputs are intent(inout)).
!>  * Integer arguments are default integers and are converted to C int.
module b2b
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_ptr, c_null_ptr, &
                                         c_null_char, c_loc, c_f_pointer, c_associated
  use, intrinsic :: iso_fortran_env, only: error_unit
  implicit none
  private

  include 'b2b_constants.inc'

  public :: b2b_strerror, b2b_version, b2b_abi_version
  public :: b2b_segment_eval, b2b_beam_segment_count, b2b_beam_segment_patch

  interface
    function c_b2b_strerror(status) bind(C, name='b2b_strerror') result(msg)
      import :: c_int, c_ptr
      integer(c_int), value :: status
      type(c_ptr) :: msg
    end function

    function c_b2b_version(major, minor, patch) bind(C, name='b2b_version') result(st)
      import :: c_int
      integer(c_int), intent(out) :: major, minor, patch
      integer(c_int) :: st
    end function

    function c_b2b_abi_version(abi) bind(C, name='b2b_abi_version') result(st)
      import :: c_int
      integer(c_int), intent(out) :: abi
      integer(c_int) :: st
    end function

    function c_b2b_segment_eval(kind, start_rule, end_rule, patch, end_tangents, xi, &
                                x, dx, d2x, errmsg, errmsg_len) &
        bind(C, name='b2b_segment_eval') result(st)
      import :: c_int, c_double, c_ptr, c_char
      integer(c_int), value :: kind, start_rule, end_rule
      real(c_double), intent(in) :: patch(*)
      type(c_ptr), value :: end_tangents, x, dx, d2x
      real(c_double), value :: xi
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_beam_segment_count(kind, n_nodes, closed, n_segments, errmsg, errmsg_len) &
        bind(C, name='b2b_beam_segment_count') result(st)
      import :: c_int, c_char
      integer(c_int), value :: kind, n_nodes, closed
      integer(c_int), intent(inout) :: n_segments
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_beam_segment_patch(kind, n_nodes, closed, segment, nodes, start_rule, &
                                      end_rule, errmsg, errmsg_len) &
        bind(C, name='b2b_beam_segment_patch') result(st)
      import :: c_int, c_char
      integer(c_int), value :: kind, n_nodes, closed, segment
      integer(c_int), intent(inout) :: nodes(4), start_rule, end_rule
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function
  end interface

contains

  !> English name of a status code (never empty).
  function b2b_strerror(status) result(msg)
    integer, intent(in) :: status
    character(len=:), allocatable :: msg
    msg = c_string(c_b2b_strerror(int(status, c_int)))
  end function

  !> Run-time release version of the library.
  subroutine b2b_version(major, minor, patch, ierr, errmsg)
    integer, intent(out) :: major, minor, patch
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    integer(c_int) :: cmaj, cmin, cpat, st
    st = c_b2b_version(cmaj, cmin, cpat)
    major = cmaj
    minor = cmin
    patch = cpat
    call finish('b2b_version', st, blank_message(), ierr, errmsg)
  end subroutine

  !> Run-time ABI version: the N of libb2b.so.N.
  subroutine b2b_abi_version(abi, ierr, errmsg)
    integer, intent(out) :: abi
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    integer(c_int) :: cabi, st
    st = c_b2b_abi_version(cabi)
    abi = cabi
    call finish('b2b_abi_version', st, blank_message(), ierr, errmsg)
  end subroutine

  !> Evaluates one segment of a smoothed centreline at xi (b2b_segment_eval in
  !> the C header documents kinds, rules and derivatives).
  !>   patch(3,4)           coordinates of the patch nodes x1..x4
  !>   x(3,3)               point, dx/dxi, d2x/dxi2 (columns)
  !>   dx(3,12,2)           dx(i,a,1) = d x_i/d X_a, dx(i,a,2) = d (dx_i/dxi)/d X_a
  !>   d2x(3,12,12,2)       second derivatives, likewise
  !>   end_tangents(3,2)    host end tangents (first node, last node); needed
  !>                        only where a rule is B2B_END_TANGENT
  !> Absent outputs are not computed.
  subroutine b2b_segment_eval(kind, start_rule, end_rule, patch, xi, x, dx, d2x, &
                              end_tangents, ierr, errmsg)
    integer, intent(in) :: kind, start_rule, end_rule
    real(c_double), intent(in), contiguous :: patch(:, :)
    real(c_double), intent(in) :: xi
    real(c_double), intent(inout), contiguous, target, optional :: x(:, :)
    real(c_double), intent(inout), contiguous, target, optional :: dx(:, :, :)
    real(c_double), intent(inout), contiguous, target, optional :: d2x(:, :, :, :)
    real(c_double), intent(in), contiguous, target, optional :: end_tangents(:, :)
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(len=*), parameter :: me = 'b2b_segment_eval'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    type(c_ptr) :: px, pdx, pd2x, pt
    integer(c_int) :: st

    if (.not. shape_is(shape(patch), [3, 4])) then
      call finish_size(me, 'patch', shape(patch), [3, 4], ierr, errmsg)
      return
    end if
    px = c_null_ptr
    pdx = c_null_ptr
    pd2x = c_null_ptr
    pt = c_null_ptr
    if (present(x)) then
      if (.not. shape_is(shape(x), [3, 3])) then
        call finish_size(me, 'x', shape(x), [3, 3], ierr, errmsg)
        return
      end if
      px = c_loc(x)
    end if
    if (present(dx)) then
      if (.not. shape_is(shape(dx), [3, 12, 2])) then
        call finish_size(me, 'dx', shape(dx), [3, 12, 2], ierr, errmsg)
        return
      end if
      pdx = c_loc(dx)
    end if
    if (present(d2x)) then
      if (.not. shape_is(shape(d2x), [3, 12, 12, 2])) then
        call finish_size(me, 'd2x', shape(d2x), [3, 12, 12, 2], ierr, errmsg)
        return
      end if
      pd2x = c_loc(d2x)
    end if
    if (present(end_tangents)) then
      if (.not. shape_is(shape(end_tangents), [3, 2])) then
        call finish_size(me, 'end_tangents', shape(end_tangents), [3, 2], ierr, errmsg)
        return
      end if
      pt = c_loc(end_tangents)
    end if
    buf = c_null_char
    st = c_b2b_segment_eval(int(kind, c_int), int(start_rule, c_int), int(end_rule, c_int), &
                            patch, pt, xi, px, pdx, pd2x, buf, int(size(buf), c_int))
    call finish(me, st, buf, ierr, errmsg)
  end subroutine

  !> Number of segments of a beam of n_nodes nodes (closed = .true.: a ring).
  subroutine b2b_beam_segment_count(kind, n_nodes, closed, n_segments, ierr, errmsg)
    integer, intent(in) :: kind, n_nodes
    logical, intent(in) :: closed
    integer, intent(inout) :: n_segments
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st, cnseg
    buf = c_null_char
    cnseg = 0
    st = c_b2b_beam_segment_count(int(kind, c_int), int(n_nodes, c_int), c_flag(closed), &
                                  cnseg, buf, int(size(buf), c_int))
    if (st == B2B_OK) n_segments = cnseg
    call finish('b2b_beam_segment_count', st, buf, ierr, errmsg)
  end subroutine

  !> The patch of segment `segment` (1-based) of a beam: nodes(k) is the beam
  !> node (1-based) in patch slot k, 0 where the slot is missing or unused;
  !> start_rule, end_rule are B2B_END_REFLECT at beam ends, else
  !> B2B_END_NEIGHBOUR.
  subroutine b2b_beam_segment_patch(kind, n_nodes, closed, segment, nodes, start_rule, &
                                    end_rule, ierr, errmsg)
    integer, intent(in) :: kind, n_nodes, segment
    logical, intent(in) :: closed
    integer, intent(inout), contiguous :: nodes(:)
    integer, intent(inout) :: start_rule, end_rule
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(len=*), parameter :: me = 'b2b_beam_segment_patch'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st, cnodes(4), csr, cer
    if (size(nodes) /= 4) then
      call finish_size(me, 'nodes', shape(nodes), [4], ierr, errmsg)
      return
    end if
    buf = c_null_char
    cnodes = -1
    csr = 0
    cer = 0
    st = c_b2b_beam_segment_patch(int(kind, c_int), int(n_nodes, c_int), c_flag(closed), &
                                  int(segment - 1, c_int), cnodes, csr, cer, buf, &
                                  int(size(buf), c_int))
    if (st == B2B_OK) then
      nodes = cnodes + 1
      start_rule = csr
      end_rule = cer
    end if
    call finish(me, st, buf, ierr, errmsg)
  end subroutine

  ! ---------------------------------------------------------------- helpers

  !> Hands the status to the caller: through ierr/errmsg when present; when
  !> ierr is absent, a failure stops the program with the message.
  subroutine finish(procname, st, buf, ierr, errmsg)
    character(len=*), intent(in) :: procname
    integer(c_int), intent(in) :: st
    character(kind=c_char), intent(in) :: buf(:)
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(len=:), allocatable :: msg
    if (st == B2B_OK) then
      msg = ''
    else
      msg = c_chars(buf)
      if (len(msg) == 0) msg = procname // ': ' // b2b_strerror(int(st))
    end if
    if (present(errmsg)) errmsg = msg
    if (present(ierr)) then
      ierr = int(st)
    else if (st /= B2B_OK) then
      write (error_unit, '(a)') 'b2b error ' // trim(int_text(int(st))) // ': ' // msg
      error stop 'b2b: a call failed and no ierr argument was given to receive the status'
    end if
  end subroutine

  !> Reports an array of the wrong shape as B2B_ERR_SIZE.
  subroutine finish_size(procname, argname, got, want, ierr, errmsg)
    character(len=*), intent(in) :: procname, argname
    integer, intent(in) :: got(:), want(:)
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(len=B2B_ERRMSG_LEN) :: text
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer :: i
    text = procname // ': ' // argname // ' has shape (' // shape_text(got) // &
           '), expected (' // shape_text(want) // ')'
    buf = c_null_char
    do i = 1, min(len_trim(text), size(buf) - 1)
      buf(i) = text(i:i)
    end do
    call finish(procname, int(B2B_ERR_SIZE, c_int), buf, ierr, errmsg)
  end subroutine

  logical function shape_is(got, want)
    integer, intent(in) :: got(:), want(:)
    shape_is = size(got) == size(want)
    if (shape_is) shape_is = all(got == want)
  end function

  function shape_text(s) result(t)
    integer, intent(in) :: s(:)
    character(len=:), allocatable :: t
    integer :: i
    t = ''
    do i = 1, size(s)
      if (i > 1) t = t // ','
      t = t // trim(int_text(s(i)))
    end do
  end function

  function int_text(i) result(t)
    integer, intent(in) :: i
    character(len=24) :: t
    write (t, '(i0)') i
  end function

  integer(c_int) function c_flag(flag)
    logical, intent(in) :: flag
    c_flag = merge(1_c_int, 0_c_int, flag)
  end function

  !> An empty, NUL-terminated message buffer (for calls that carry none).
  function blank_message() result(buf)
    character(kind=c_char) :: buf(1)
    buf = c_null_char
  end function

  !> The characters of a NUL-terminated C char array (all of them if no NUL).
  function c_chars(buf) result(s)
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

  !> A Fortran copy of a NUL-terminated C string owned by the library.
  function c_string(p) result(s)
    type(c_ptr), intent(in) :: p
    character(len=:), allocatable :: s
    character(kind=c_char), pointer :: chars(:)
    integer :: n
    if (.not. c_associated(p)) then
      s = ''
      return
    end if
    call c_f_pointer(p, chars, [huge(0)])
    n = 0
    do while (chars(n + 1) /= c_null_char)
      n = n + 1
    end do
    s = c_chars(chars(1:n))
  end function

end module b2b
