!> Direct bind(C) interfaces of the C ABI, for comparing the module b2b with
!> the C calls.
!>
!> The tests declare these themselves rather than reach into module b2b (whose
!> own interfaces are private), so that a wrong argument order or layout in a
!> wrapper cannot be hidden by the same mistake on both sides. Every array,
!> optional output and errmsg buffer is a type(c_ptr) passed by value: a test
!> passes c_loc of a flat array, or c_null_ptr for an absent output or for no
!> message (with errmsg_len 0). The C names lose their b2b_ prefix for a c_
!> one; the C signatures are in include/b2b.h.
module ftest_capi
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_ptr, c_char
  implicit none
  private

  public :: c_segment_eval
  public :: c_params_create, c_params_destroy, c_params_set_real, c_params_set_int
  public :: c_params_finalize, c_params_history_size
  public :: c_pair_eval, c_pair_history_handover

  interface
    function c_segment_eval(kind, start_rule, end_rule, patch, end_tangents, xi, x, dx, d2x, &
                            errmsg, errmsg_len) bind(C, name='b2b_segment_eval') result(st)
      import :: c_int, c_double, c_ptr
      integer(c_int), value :: kind, start_rule, end_rule
      type(c_ptr), value :: patch, end_tangents
      real(c_double), value :: xi
      type(c_ptr), value :: x, dx, d2x, errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_params_create(params, errmsg, errmsg_len) bind(C, name='b2b_params_create') &
        result(st)
      import :: c_int, c_ptr
      type(c_ptr), intent(inout) :: params
      type(c_ptr), value :: errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_params_destroy(params) bind(C, name='b2b_params_destroy') result(st)
      import :: c_int, c_ptr
      type(c_ptr), intent(inout) :: params
      integer(c_int) :: st
    end function

    !> key: a NUL-terminated string ('penalty' // c_null_char).
    function c_params_set_real(params, key, value, errmsg, errmsg_len) &
        bind(C, name='b2b_params_set_real') result(st)
      import :: c_int, c_double, c_ptr, c_char
      type(c_ptr), value :: params
      character(kind=c_char), intent(in) :: key(*)
      real(c_double), value :: value
      type(c_ptr), value :: errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_params_set_int(params, key, value, errmsg, errmsg_len) &
        bind(C, name='b2b_params_set_int') result(st)
      import :: c_int, c_ptr, c_char
      type(c_ptr), value :: params
      character(kind=c_char), intent(in) :: key(*)
      integer(c_int), value :: value
      type(c_ptr), value :: errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_params_finalize(params, errmsg, errmsg_len) &
        bind(C, name='b2b_params_finalize') result(st)
      import :: c_int, c_ptr
      type(c_ptr), value :: params
      type(c_ptr), value :: errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_params_history_size(params, n, errmsg, errmsg_len) &
        bind(C, name='b2b_params_history_size') result(st)
      import :: c_int, c_ptr
      type(c_ptr), value :: params
      integer(c_int), intent(inout) :: n
      type(c_ptr), value :: errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_pair_eval(params, segments, X, end_tangents, radii, hist_old, hist_new, &
                         hist_len, contact_status, info, residual, tangent, ldk, errmsg, &
                         errmsg_len) bind(C, name='b2b_pair_eval') result(st)
      import :: c_int, c_ptr
      type(c_ptr), value :: params, segments, X, end_tangents, radii, hist_old, hist_new
      integer(c_int), value :: hist_len
      type(c_ptr), value :: contact_status, info, residual, tangent
      integer(c_int), value :: ldk
      type(c_ptr), value :: errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    !> beam is C's 0 or 1 (the module's 1 or 2).
    function c_pair_history_handover(params, beam, direction, from_segment, from_X, &
                                     from_end_tangents, to_segment, to_X, to_end_tangents, &
                                     hist_from, hist_to, hist_len, errmsg, errmsg_len) &
        bind(C, name='b2b_pair_history_handover') result(st)
      import :: c_int, c_ptr
      type(c_ptr), value :: params
      integer(c_int), value :: beam, direction
      type(c_ptr), value :: from_segment, from_X, from_end_tangents
      type(c_ptr), value :: to_segment, to_X, to_end_tangents
      type(c_ptr), value :: hist_from, hist_to
      integer(c_int), value :: hist_len
      type(c_ptr), value :: errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function
  end interface

end module ftest_capi
