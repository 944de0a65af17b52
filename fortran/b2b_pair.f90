!> Submodule pair_layer of module b2b (b2b.f90): the bodies of
!> the contact parameters (type(b2b_params)) and the contact element.
!> The interfaces and documentation of its public procedures are in
!> b2b.f90; this file holds their bodies (module procedure) and the
!> bind(C) interfaces of the C functions they call.
submodule (b2b) pair_layer
  implicit none

  interface
    function c_b2b_params_create(params, errmsg, errmsg_len) &
        bind(C, name='b2b_params_create') result(st)
      import :: c_int, c_ptr, c_char
      type(c_ptr), intent(inout) :: params
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_params_destroy(params) bind(C, name='b2b_params_destroy') result(st)
      import :: c_int, c_ptr
      type(c_ptr), intent(inout) :: params
      integer(c_int) :: st
    end function

    function c_b2b_params_set_real(params, key, value, errmsg, errmsg_len) &
        bind(C, name='b2b_params_set_real') result(st)
      import :: c_int, c_double, c_ptr, c_char
      type(c_ptr), value :: params
      character(kind=c_char), intent(in) :: key(*)
      real(c_double), value :: value
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_params_set_int(params, key, value, errmsg, errmsg_len) &
        bind(C, name='b2b_params_set_int') result(st)
      import :: c_int, c_ptr, c_char
      type(c_ptr), value :: params
      character(kind=c_char), intent(in) :: key(*)
      integer(c_int), value :: value
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_params_get_real(params, key, value, errmsg, errmsg_len) &
        bind(C, name='b2b_params_get_real') result(st)
      import :: c_int, c_double, c_ptr, c_char
      type(c_ptr), value :: params
      character(kind=c_char), intent(in) :: key(*)
      real(c_double), intent(inout) :: value
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_params_get_int(params, key, value, errmsg, errmsg_len) &
        bind(C, name='b2b_params_get_int') result(st)
      import :: c_int, c_ptr, c_char
      type(c_ptr), value :: params
      character(kind=c_char), intent(in) :: key(*)
      integer(c_int), intent(inout) :: value
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_params_finalize(params, errmsg, errmsg_len) &
        bind(C, name='b2b_params_finalize') result(st)
      import :: c_int, c_ptr, c_char
      type(c_ptr), value :: params
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_params_history_size(params, n, errmsg, errmsg_len) &
        bind(C, name='b2b_params_history_size') result(st)
      import :: c_int, c_ptr, c_char
      type(c_ptr), value :: params
      integer(c_int), intent(inout) :: n
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_pair_eval(params, segments, X, end_tangents, radii, hist_old, hist_new, &
                             hist_len, contact_status, info, residual, tangent, ldk, errmsg, &
                             errmsg_len) bind(C, name='b2b_pair_eval') result(st)
      import :: c_int, c_double, c_ptr, c_char
      type(c_ptr), value :: params
      integer(c_int), intent(in) :: segments(6)
      real(c_double), intent(in) :: X(*)
      type(c_ptr), value :: end_tangents
      real(c_double), intent(in) :: radii(*), hist_old(*)
      real(c_double), intent(inout) :: hist_new(*)
      integer(c_int), value :: hist_len
      integer(c_int), intent(inout) :: contact_status
      real(c_double), intent(inout) :: info(*), residual(*)
      type(c_ptr), value :: tangent
      integer(c_int), value :: ldk
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_pair_eval_ends(params, segments, X, end_tangents, radii, ends, hist_old, &
                                  hist_new, hist_len, contact_status, info, residual, tangent, &
                                  ldk, errmsg, errmsg_len) bind(C, name='b2b_pair_eval_ends') &
                                  result(st)
      import :: c_int, c_double, c_ptr, c_char
      type(c_ptr), value :: params
      integer(c_int), intent(in) :: segments(6)
      real(c_double), intent(in) :: X(*)
      type(c_ptr), value :: end_tangents
      real(c_double), intent(in) :: radii(*)
      integer(c_int), intent(in) :: ends(2)
      real(c_double), intent(in) :: hist_old(*)
      real(c_double), intent(inout) :: hist_new(*)
      integer(c_int), value :: hist_len
      integer(c_int), intent(inout) :: contact_status
      real(c_double), intent(inout) :: info(*), residual(*)
      type(c_ptr), value :: tangent
      integer(c_int), value :: ldk
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_pair_history_handover(params, beam, direction, from_segment, from_X, &
                                         from_end_tangents, to_segment, to_X, &
                                         to_end_tangents, hist_from, hist_to, hist_len, &
                                         errmsg, errmsg_len) &
        bind(C, name='b2b_pair_history_handover') result(st)
      import :: c_int, c_double, c_ptr, c_char
      type(c_ptr), value :: params
      integer(c_int), value :: beam, direction
      integer(c_int), intent(in) :: from_segment(3)
      real(c_double), intent(in) :: from_X(*)
      type(c_ptr), value :: from_end_tangents
      integer(c_int), intent(in) :: to_segment(3)
      real(c_double), intent(in) :: to_X(*)
      type(c_ptr), value :: to_end_tangents
      real(c_double), intent(in) :: hist_from(*)
      real(c_double), intent(inout) :: hist_to(*)
      integer(c_int), value :: hist_len
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function
  end interface

contains

  module procedure b2b_params_create
    character(len=*), parameter :: me = 'b2b_params_create'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    type(c_ptr) :: p
    integer(c_int) :: st
    if (c_associated(params%ptr)) then
      call finish_text(me, int(B2B_ERR_STATE, c_int), me // ': params already holds a ' // &
                       'handle (b2b_params_destroy it first)', ierr, errmsg)
      return
    end if
    buf = c_null_char
    p = c_null_ptr
    st = c_b2b_params_create(p, buf, int(size(buf), c_int))
    if (st == B2B_OK) params%ptr = p
    call finish(me, st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_params_destroy
    integer(c_int) :: st
    st = c_b2b_params_destroy(params%ptr)
    params%ptr = c_null_ptr
    call finish('b2b_params_destroy', st, blank_message(), ierr, errmsg)
  end procedure

  module procedure b2b_params_set_real
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    buf = c_null_char
    st = c_b2b_params_set_real(params%ptr, trim(key) // c_null_char, value, buf, &
                               int(size(buf), c_int))
    call finish('b2b_params_set_real', st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_params_set_int
    character(len=*), parameter :: me = 'b2b_params_set_int'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    logical :: ok
    call check_ints(me, [character(len=5) :: 'value'], [value], ok, ierr, errmsg)
    if (.not. ok) return
    buf = c_null_char
    st = c_b2b_params_set_int(params%ptr, trim(key) // c_null_char, int(value, c_int), buf, &
                              int(size(buf), c_int))
    call finish(me, st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_params_get_real
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    real(c_double) :: cvalue
    integer(c_int) :: st
    buf = c_null_char
    cvalue = 0
    st = c_b2b_params_get_real(params%ptr, trim(key) // c_null_char, cvalue, buf, &
                               int(size(buf), c_int))
    if (st == B2B_OK) value = cvalue
    call finish('b2b_params_get_real', st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_params_get_int
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: cvalue, st
    buf = c_null_char
    cvalue = 0
    st = c_b2b_params_get_int(params%ptr, trim(key) // c_null_char, cvalue, buf, &
                              int(size(buf), c_int))
    if (st == B2B_OK) value = cvalue
    call finish('b2b_params_get_int', st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_params_finalize
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    buf = c_null_char
    st = c_b2b_params_finalize(params%ptr, buf, int(size(buf), c_int))
    call finish('b2b_params_finalize', st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_params_history_size
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: cn, st
    buf = c_null_char
    cn = 0
    st = c_b2b_params_history_size(params%ptr, cn, buf, int(size(buf), c_int))
    if (st == B2B_OK) n = cn
    call finish('b2b_params_history_size', st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_pair_eval
    type(c_ptr) :: pk, pt
    integer :: kshape(2), tshape(2)
    ! The optional arrays go on as addresses and shapes: gfortran 12 passing
    ! an absent optional contiguous array on to another optional dummy loads
    ! through its null data pointer (an UBSan finding in every call without
    ! end_tangents or tangent).
    call optional_address(pk, kshape)
    if (present(tangent)) call optional_address(pk, kshape, c_loc(tangent), shape(tangent))
    call optional_address(pt, tshape)
    if (present(end_tangents)) &
      call optional_address(pt, tshape, c_loc(end_tangents), shape(end_tangents))
    call eval_pair('b2b_pair_eval', params, segments, X, radii, hist_old, hist_new, &
                   contact_status, info, residual, pk, kshape, pt, tshape, ierr, errmsg)
  end procedure

  module procedure b2b_pair_eval_ends
    character(len=*), parameter :: me = 'b2b_pair_eval_ends'
    logical :: ok
    type(c_ptr) :: pk, pt
    integer :: kshape(2), tshape(2)
    if (.not. shape_is(shape(ends), [2])) then
      call finish_size(me, 'ends', shape(ends), [2], ierr, errmsg)
      return
    end if
    call check_int_matrix(me, 'ends', reshape(ends, [2, 1]), ok, ierr, errmsg)
    if (.not. ok) return
    call optional_address(pk, kshape)  ! as in b2b_pair_eval
    if (present(tangent)) call optional_address(pk, kshape, c_loc(tangent), shape(tangent))
    call optional_address(pt, tshape)
    if (present(end_tangents)) &
      call optional_address(pt, tshape, c_loc(end_tangents), shape(end_tangents))
    call eval_pair(me, params, segments, X, radii, hist_old, hist_new, contact_status, info, &
                   residual, pk, kshape, pt, tshape, ierr, errmsg, int(ends, c_int))
  end procedure

  ! b2b_pair_eval and b2b_pair_eval_ends (cends present): the argument checks
  ! and the call. tangent and end_tangents by address and shape (shape -1:
  ! absent; see b2b_pair_eval).
  subroutine eval_pair(me, params, segments, X, radii, hist_old, hist_new, contact_status, &
                       info, residual, tangent, kshape, end_tangents, tshape, ierr, errmsg, &
                       cends)
    character(len=*), intent(in) :: me
    type(b2b_params), intent(in) :: params
    integer, intent(in), contiguous :: segments(:, :)
    real(c_double), intent(in), contiguous :: X(:, :)
    real(c_double), intent(in), contiguous :: radii(:)
    real(c_double), intent(in), contiguous, target :: hist_old(:)
    real(c_double), intent(inout), contiguous, target :: hist_new(:)
    integer, intent(inout) :: contact_status
    real(c_double), intent(inout), contiguous :: info(:)
    real(c_double), intent(inout), contiguous :: residual(:)
    type(c_ptr), intent(in) :: tangent, end_tangents
    integer, intent(in) :: kshape(2), tshape(2)
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    integer(c_int), intent(in), optional :: cends(2)
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    type(c_ptr) :: pk, pt
    integer(c_int) :: st, cseg(6), cstatus, ldk
    real(c_double) :: h0(1), h1(1)
    logical :: ok

    call check_pair_shapes(me, segments, X, radii, ok, ierr, errmsg)
    if (.not. ok) return
    if (size(hist_new) /= size(hist_old)) then
      call finish_text(me, int(B2B_ERR_SIZE, c_int), me // ': hist_old and hist_new differ ' // &
                       'in size (' // trim(int_text(size(hist_old))) // ' and ' // &
                       trim(int_text(size(hist_new))) // ')', ierr, errmsg)
      return
    end if
    call check_ints(me, [character(len=14) :: 'size(hist_old)'], [size(hist_old)], ok, ierr, &
                    errmsg)
    if (.not. ok) return
    if (overlap(hist_old, hist_new)) then
      call finish_alias(me, 'hist_new', 'hist_old', ierr, errmsg)
      return
    end if
    if (.not. shape_is(shape(info), [B2B_PAIR_INFO_LEN])) then
      call finish_size(me, 'info', shape(info), [B2B_PAIR_INFO_LEN], ierr, errmsg)
      return
    end if
    if (.not. shape_is(shape(residual), [B2B_PAIR_NDOF])) then
      call finish_size(me, 'residual', shape(residual), [B2B_PAIR_NDOF], ierr, errmsg)
      return
    end if
    call check_pair_optionals(me, tangent, kshape, end_tangents, tshape, pk, ldk, pt, ok, ierr, &
                              errmsg)
    if (.not. ok) return
    cseg = int(reshape(segments, [6]), c_int)
    cstatus = 0
    buf = c_null_char
    if (size(hist_old) > 0) then
      if (present(cends)) then
        st = c_b2b_pair_eval_ends(params%ptr, cseg, X, pt, radii, cends, hist_old, hist_new, &
                                  int(size(hist_old), c_int), cstatus, info, residual, pk, &
                                  ldk, buf, int(size(buf), c_int))
      else
        st = c_b2b_pair_eval(params%ptr, cseg, X, pt, radii, hist_old, hist_new, &
                             int(size(hist_old), c_int), cstatus, info, residual, pk, ldk, &
                             buf, int(size(buf), c_int))
      end if
    else
      ! A zero-size array may have any address, even NULL: pass a dummy and
      ! let the library report the length.
      h0 = 0
      if (present(cends)) then
        st = c_b2b_pair_eval_ends(params%ptr, cseg, X, pt, radii, cends, h0, h1, 0_c_int, &
                                  cstatus, info, residual, pk, ldk, buf, int(size(buf), c_int))
      else
        st = c_b2b_pair_eval(params%ptr, cseg, X, pt, radii, h0, h1, 0_c_int, cstatus, info, &
                             residual, pk, ldk, buf, int(size(buf), c_int))
      end if
    end if
    if (st == B2B_OK) contact_status = cstatus
    if (st /= B2B_OK) call fortran_terms(buf, 'hist_old')
    call finish(me, st, buf, ierr, errmsg)
  end subroutine

  module procedure b2b_pair_history_handover
    character(len=*), parameter :: me = 'b2b_pair_history_handover'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    type(c_ptr) :: ptf, ptt
    integer(c_int) :: st, cfrom(3), cto(3)
    real(c_double) :: h0(1), h1(1)
    logical :: ok

    if (.not. shape_is(shape(from_segment), [3])) then
      call finish_size(me, 'from_segment', shape(from_segment), [3], ierr, errmsg)
      return
    end if
    if (.not. shape_is(shape(from_X), [3, 4])) then
      call finish_size(me, 'from_X', shape(from_X), [3, 4], ierr, errmsg)
      return
    end if
    if (.not. shape_is(shape(to_segment), [3])) then
      call finish_size(me, 'to_segment', shape(to_segment), [3], ierr, errmsg)
      return
    end if
    if (.not. shape_is(shape(to_X), [3, 4])) then
      call finish_size(me, 'to_X', shape(to_X), [3, 4], ierr, errmsg)
      return
    end if
    if (size(hist_to) /= size(hist_from)) then
      call finish_text(me, int(B2B_ERR_SIZE, c_int), me // ': hist_from and hist_to ' // &
                       'differ in size (' // trim(int_text(size(hist_from))) // ' and ' // &
                       trim(int_text(size(hist_to))) // ')', ierr, errmsg)
      return
    end if
    call check_int_array(me, 'from_segment', from_segment, ok, ierr, errmsg)
    if (.not. ok) return
    call check_int_array(me, 'to_segment', to_segment, ok, ierr, errmsg)
    if (.not. ok) return
    call check_ints(me, [character(len=15) :: 'direction', 'size(hist_from)'], &
                    [direction, size(hist_from)], ok, ierr, errmsg)
    if (.not. ok) return
    if (overlap(hist_from, hist_to)) then
      call finish_alias(me, 'hist_to', 'hist_from', ierr, errmsg)
      return
    end if
    ptf = c_null_ptr
    ptt = c_null_ptr
    if (present(from_end_tangents)) then
      if (.not. shape_is(shape(from_end_tangents), [3, 2])) then
        call finish_size(me, 'from_end_tangents', shape(from_end_tangents), [3, 2], ierr, &
                         errmsg)
        return
      end if
      ptf = c_loc(from_end_tangents)
    end if
    if (present(to_end_tangents)) then
      if (.not. shape_is(shape(to_end_tangents), [3, 2])) then
        call finish_size(me, 'to_end_tangents', shape(to_end_tangents), [3, 2], ierr, errmsg)
        return
      end if
      ptt = c_loc(to_end_tangents)
    end if
    ! The C function numbers the beams 0, 1: check the 1-based number here so
    ! that the message speaks of the caller's value.
    if (beam /= 1 .and. beam /= 2) then
      call finish_text(me, int(B2B_ERR_UNKNOWN_KIND, c_int), me // ': beam is ' // &
                       trim(int_text(beam)) // ': 1 (beam A) or 2 (beam B) expected', &
                       ierr, errmsg)
      return
    end if
    cfrom = int(from_segment, c_int)
    cto = int(to_segment, c_int)
    buf = c_null_char
    if (size(hist_from) > 0) then
      st = c_b2b_pair_history_handover(params%ptr, int(beam - 1, c_int), &
                                       int(direction, c_int), cfrom, from_X, ptf, cto, to_X, &
                                       ptt, hist_from, hist_to, int(size(hist_from), c_int), &
                                       buf, int(size(buf), c_int))
    else
      ! A zero-size array may have any address, even NULL: pass a dummy and
      ! let the library report the length.
      h0 = 0
      st = c_b2b_pair_history_handover(params%ptr, int(beam - 1, c_int), &
                                       int(direction, c_int), cfrom, from_X, ptf, cto, to_X, &
                                       ptt, h0, h1, 0_c_int, buf, int(size(buf), c_int))
    end if
    if (st /= B2B_OK) call fortran_terms(buf, 'hist_from')
    call finish(me, st, buf, ierr, errmsg)
  end procedure

end submodule pair_layer
