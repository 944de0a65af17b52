!> Submodule curve_layer of module b2b (b2b.f90): the bodies of
!> the core (status text, versions) and the smoothed centreline.
!> The interfaces and documentation of its public procedures are in
!> b2b.f90; this file holds their bodies (module procedure) and the
!> bind(C) interfaces of the C functions they call.
submodule (b2b) curve_layer
  implicit none

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

  module procedure b2b_strerror
    integer(c_int) :: cstatus
    cstatus = -1
    if (fits_c_int(status)) cstatus = int(status, c_int)
    msg = c_string(c_b2b_strerror(cstatus))
  end procedure

  module procedure b2b_version
    integer(c_int) :: cmaj, cmin, cpat, st
    st = c_b2b_version(cmaj, cmin, cpat)
    major = cmaj
    minor = cmin
    patch = cpat
    call finish('b2b_version', st, blank_message(), ierr, errmsg)
  end procedure

  module procedure b2b_abi_version
    integer(c_int) :: cabi, st
    st = c_b2b_abi_version(cabi)
    abi = cabi
    call finish('b2b_abi_version', st, blank_message(), ierr, errmsg)
  end procedure

  module procedure b2b_segment_eval
    character(len=*), parameter :: me = 'b2b_segment_eval'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    type(c_ptr) :: px, pdx, pd2x, pt
    integer(c_int) :: st
    logical :: ok

    call check_ints(me, [character(len=10) :: 'kind', 'start_rule', 'end_rule'], &
                    [kind, start_rule, end_rule], ok, ierr, errmsg)
    if (.not. ok) return
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
    if (st /= B2B_OK) call fortran_terms(buf, '')
    call finish(me, st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_beam_segment_count
    character(len=*), parameter :: me = 'b2b_beam_segment_count'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st, cnseg
    logical :: ok
    call check_ints(me, [character(len=7) :: 'kind', 'n_nodes'], [kind, n_nodes], ok, ierr, &
                    errmsg)
    if (.not. ok) return
    buf = c_null_char
    cnseg = 0
    st = c_b2b_beam_segment_count(int(kind, c_int), int(n_nodes, c_int), c_flag(closed), &
                                  cnseg, buf, int(size(buf), c_int))
    if (st == B2B_OK) n_segments = cnseg
    call finish(me, st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_beam_segment_patch
    character(len=*), parameter :: me = 'b2b_beam_segment_patch'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st, cnodes(4), csr, cer, cnseg
    logical :: ok
    call check_ints(me, [character(len=7) :: 'kind', 'n_nodes', 'segment'], &
                    [kind, n_nodes, segment], ok, ierr, errmsg)
    if (.not. ok) return
    if (size(nodes) /= 4) then
      call finish_size(me, 'nodes', shape(nodes), [4], ierr, errmsg)
      return
    end if
    ! The C message numbers segments from 0: check the range here, so that it
    ! speaks of the caller's 1-based numbers. A beam the count rejects is
    ! left to the C call, which reports it under this procedure's name.
    buf = c_null_char
    cnseg = 0
    st = c_b2b_beam_segment_count(int(kind, c_int), int(n_nodes, c_int), c_flag(closed), &
                                  cnseg, buf, int(size(buf), c_int))
    if (st == B2B_OK .and. (segment < 1 .or. segment > cnseg)) then
      call finish_text(me, int(B2B_ERR_RANGE, c_int), me // ': segment ' // &
                       trim(int_text(segment)) // ' is out of range: this beam has segments 1 .. ' &
                       // trim(int_text(int(cnseg))), ierr, errmsg)
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
  end procedure

end submodule curve_layer
