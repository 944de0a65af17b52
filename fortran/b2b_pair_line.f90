!> Submodule line_layer of module b2b (b2b.f90): the bodies of the
!> line-contact element's procedures (b2b_pair_eval_line,
!> b2b_pair_line_points) and the bind(C) interfaces of the C functions they
!> call. Interfaces and documentation are in b2b.f90.
submodule (b2b) line_layer
  implicit none

  interface
    function c_b2b_pair_eval_line(params, segments, X, end_tangents, radii, n_points, hist_old, &
                                  hist_new, hist_len, contact_status, line_info, point_info, &
                                  residual, tangent, ldk, errmsg, errmsg_len) &
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

    function c_b2b_pair_line_points(params, length, radius_a, radius_b, n_points, errmsg, &
                                    errmsg_len) bind(C, name='b2b_pair_line_points') result(st)
      import :: c_int, c_double, c_ptr, c_char
      type(c_ptr), value :: params
      real(c_double), value :: length, radius_a, radius_b
      integer(c_int), intent(inout) :: n_points
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function
  end interface

contains

  module procedure b2b_pair_eval_line
    character(len=*), parameter :: me = 'b2b_pair_eval_line'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    type(c_ptr) :: ka, ta, pk, pt, pp
    integer :: kshape(2), tshape(2)
    integer(c_int) :: st, cseg(6), cstatus, ldk
    real(c_double) :: h0(1), h1(1)
    logical :: ok

    call check_pair_shapes(me, segments, X, radii, ok, ierr, errmsg)
    if (.not. ok) return
    call check_ints(me, [character(len=14) :: 'n_points', 'size(hist_old)'], &
                    [n_points, size(hist_old)], ok, ierr, errmsg)
    if (.not. ok) return
    if (size(hist_new) /= size(hist_old)) then
      call finish_text(me, int(B2B_ERR_SIZE, c_int), me // ': hist_old and hist_new differ ' // &
                       'in size (' // trim(int_text(size(hist_old))) // ' and ' // &
                       trim(int_text(size(hist_new))) // ')', ierr, errmsg)
      return
    end if
    if (overlap(hist_old, hist_new)) then
      call finish_alias(me, 'hist_new', 'hist_old', ierr, errmsg)
      return
    end if
    if (.not. shape_is(shape(line_info), [B2B_LINE_INFO_LEN])) then
      call finish_size(me, 'line_info', shape(line_info), [B2B_LINE_INFO_LEN], ierr, errmsg)
      return
    end if
    if (.not. shape_is(shape(residual), [B2B_PAIR_NDOF])) then
      call finish_size(me, 'residual', shape(residual), [B2B_PAIR_NDOF], ierr, errmsg)
      return
    end if
    ! Optional arrays by address (see optional_address).
    call optional_address(ka, kshape)
    if (present(tangent)) call optional_address(ka, kshape, c_loc(tangent), shape(tangent))
    call optional_address(ta, tshape)
    if (present(end_tangents)) &
      call optional_address(ta, tshape, c_loc(end_tangents), shape(end_tangents))
    call check_pair_optionals(me, ka, kshape, ta, tshape, pk, ldk, pt, ok, ierr, errmsg)
    if (.not. ok) return
    pp = c_null_ptr
    if (present(point_info)) then
      if (.not. shape_is(shape(point_info), [B2B_PAIR_INFO_LEN, n_points])) then
        call finish_size(me, 'point_info', shape(point_info), [B2B_PAIR_INFO_LEN, n_points], &
                         ierr, errmsg)
        return
      end if
      pp = c_loc(point_info)
    end if
    cseg = int(reshape(segments, [6]), c_int)
    cstatus = 0
    buf = c_null_char
    if (size(hist_old) > 0) then
      st = c_b2b_pair_eval_line(params%ptr, cseg, X, pt, radii, int(n_points, c_int), hist_old, &
                                hist_new, int(size(hist_old), c_int), cstatus, line_info, pp, &
                                residual, pk, ldk, buf, int(size(buf), c_int))
    else
      h0 = 0  ! a zero-size array may have any address: the library reports the length
      st = c_b2b_pair_eval_line(params%ptr, cseg, X, pt, radii, int(n_points, c_int), h0, h1, &
                                0_c_int, cstatus, line_info, pp, residual, pk, ldk, buf, &
                                int(size(buf), c_int))
    end if
    if (st == B2B_OK) contact_status = cstatus
    if (st /= B2B_OK) call fortran_terms(buf, 'hist_old')
    call finish(me, st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_pair_line_points
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: cn, st
    buf = c_null_char
    cn = 0
    st = c_b2b_pair_line_points(params%ptr, length, radius_a, radius_b, cn, buf, &
                                int(size(buf), c_int))
    if (st == B2B_OK) n_points = cn
    call finish('b2b_pair_line_points', st, buf, ierr, errmsg)
  end procedure

end submodule
