!> Fortran 2003 interface to b2b, beam-to-beam contact for finite-element codes.
!>
!> use b2b gives every function of the C ABI (include/b2b/b2b.h) as a module
!> procedure of the same name, plus every C constant (B2B_OK, B2B_CURVE_*, ...)
!> as a parameter of the same name and value, generated from the C headers.
!>
!> Procedures:
!>  * core:     b2b_strerror, b2b_version, b2b_abi_version
!>  * curve:    b2b_segment_eval, b2b_beam_segment_count, b2b_beam_segment_patch
!>  * contact:  type(b2b_params) with b2b_params_create, b2b_params_destroy,
!>              b2b_params_set_real, b2b_params_set_int, b2b_params_get_real,
!>              b2b_params_get_int, b2b_params_finalize, b2b_params_history_size;
!>              b2b_pair_eval (with Coulomb friction), b2b_pair_history_handover
!>  * model:    type(b2b_model) with b2b_model_create, _destroy, _add_beam,
!>              _set_group_pair, _set_self_contact, _set_real, _set_int,
!>              _finalize, _update, _contact_count, _get_contact, _add_residual,
!>              _add_tangent_dense, _add_tangent_banded, _tangent_coo, _commit,
!>              _revert, _save_size, _save, _restore, _stats
!>              and the interpenetration audit b2b_model_audit
!>
!> Conventions of the wrappers:
!>  * Arrays are assumed-shape and must be contiguous (sections are copied in
!>    by the compiler); their shapes are checked, a wrong shape gives
!>    B2B_ERR_SIZE. Node coordinates are (3, nodes) arrays.
!>  * Node and segment numbers are 1-based; a missing node is 0. The two beams
!>    of a pair are numbered 1 (A) and 2 (B), as the columns of segments(3,2)
!>    of b2b_pair_eval (beam of b2b_pair_history_handover). Messages use
!>    these numbers and the Fortran arguments: hist_old(k), size(hist_old),
!>    "end_tangents is absent".
!>  * Constants that index a C array (B2B_INFO_*, B2B_COUNT_*, B2B_TOTAL_*)
!>    keep their 0-based C values. Index Fortran arrays with their 1-based
!>    twins B2B_IX_* (= the C value + 1): info(B2B_IX_INFO_GAP) is the C
!>    info[B2B_INFO_GAP], info(B2B_IX_INFO_NORMAL:B2B_IX_INFO_NORMAL + 2) the
!>    normal, counts(B2B_IX_COUNT_ACTIVE), totals(B2B_IX_TOTAL_ENERGY).
!>  * A C handle is a derived type with a private pointer (type(b2b_params)),
!>    null until created; destroy nulls it again. Copies of a handle share the
!>    C object: destroy it once.
!>  * Every procedure ends with two optional arguments: ierr (the status, 0 on
!>    success) and errmsg (the message naming the problem, '' on success).
!>    If ierr is absent and the call fails, the program stops with the message.
!>  * On failure no output argument is changed (outputs are intent(inout)).
!>  * Integer arguments and the integer constants are default integers; the
!>    arguments are converted to C int. A host may compile this source with
!>    a wider default integer (gfortran -fdefault-integer-8) and real
!>    (-fdefault-real-8): the C interface keeps its explicit kinds, and a
!>    value beyond C's int range is B2B_ERR_RANGE, never truncated. Arrays
!>    the library reads or writes in place keep explicit kinds:
!>    real(c_double) everywhere, integer(c_int) for the rows and cols of
!>    b2b_model_tangent_coo, integer(c_int8_t)/integer(c_int64_t) for
!>    b2b_model_save/_restore.
!>  * Histories: hist_new (b2b_pair_eval) and hist_to
!>    (b2b_pair_history_handover) must not share memory with hist_old /
!>    hist_from (C allows it, Fortran does not: an intent(in) argument may not
!>    change during the call). Sharing is B2B_ERR_RANGE and nothing is
!>    written; to update h in place pass a copy, e.g. hist_old=(h), hist_new=h.
module b2b
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_ptr, c_null_ptr, &
                                         c_null_char, c_loc, c_f_pointer, c_associated, &
                                         c_int64_t, c_int8_t, c_intptr_t
  use, intrinsic :: iso_fortran_env, only: error_unit
  implicit none
  private

  include 'b2b_constants.inc'

  ! The kinds of the module's interface, so that `use b2b` is all a caller
  ! needs to declare its arguments (real(c_double), integer(c_int64_t) ...).
  public :: c_double, c_int, c_int64_t, c_int8_t
  public :: b2b_strerror, b2b_version, b2b_abi_version
  public :: b2b_segment_eval, b2b_beam_segment_count, b2b_beam_segment_patch
  public :: b2b_params_create, b2b_params_destroy, b2b_params_set_real, b2b_params_set_int
  public :: b2b_params_get_real, b2b_params_get_int, b2b_params_finalize
  public :: b2b_params_history_size, b2b_pair_eval, b2b_pair_eval_ends, b2b_pair_history_handover
  public :: b2b_model_create, b2b_model_destroy, b2b_model_add_beam, b2b_model_set_group_pair
  public :: b2b_model_set_self_contact, b2b_model_set_real, b2b_model_set_int
  public :: b2b_model_finalize, b2b_model_update, b2b_model_contact_count
  public :: b2b_model_get_contact, b2b_model_add_residual, b2b_model_add_tangent_dense
  public :: b2b_model_add_tangent_banded, b2b_model_tangent_coo, b2b_model_commit
  public :: b2b_model_revert, b2b_model_save_size, b2b_model_save, b2b_model_restore
  public :: b2b_model_stats
  public :: b2b_model_audit

  !> Contact parameters (b2b_params in C): an opaque handle, null until
  !> b2b_params_create. Set options by key, finalize, then pass it to
  !> b2b_pair_eval; free it with b2b_params_destroy.
  type, public :: b2b_params
    private
    type(c_ptr) :: ptr = c_null_ptr
  end type

  !> Contact model (b2b_model in C): an opaque handle, null until
  !> b2b_model_create; free it with b2b_model_destroy. Copies share the C
  !> object: destroy it once.
  type, public :: b2b_model
    private
    type(c_ptr) :: ptr = c_null_ptr
    ! The host's node count once finalized: the assembly wrappers check the
    ! columns of eq against it (the C functions trust the caller's array).
    integer :: n_nodes = -1
  end type

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

  ! ------------------------------------------------------ contact model (C)
  interface
    function c_b2b_model_create(model, errmsg, errmsg_len) bind(C, name='b2b_model_create') &
        result(st)
      import :: c_int, c_ptr, c_char
      type(c_ptr), intent(inout) :: model
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_destroy(model) bind(C, name='b2b_model_destroy') result(st)
      import :: c_int, c_ptr
      type(c_ptr), intent(inout) :: model
      integer(c_int) :: st
    end function

    function c_b2b_model_add_beam(model, nodes, n_nodes, closed, radius, kind, group, beam, &
                                  errmsg, errmsg_len) bind(C, name='b2b_model_add_beam') result(st)
      import :: c_int, c_ptr, c_char, c_double
      type(c_ptr), value :: model
      integer(c_int), intent(in) :: nodes(*)
      integer(c_int), value :: n_nodes, closed, kind, group
      real(c_double), value :: radius
      integer(c_int), intent(inout) :: beam
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_set_group_pair(model, ga, gb, params, errmsg, errmsg_len) &
        bind(C, name='b2b_model_set_group_pair') result(st)
      import :: c_int, c_ptr, c_char
      type(c_ptr), value :: model, params
      integer(c_int), value :: ga, gb
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_set_self_contact(model, beam, on, exclusion_length, errmsg, &
                                          errmsg_len) bind(C, name='b2b_model_set_self_contact') &
        result(st)
      import :: c_int, c_ptr, c_char, c_double
      type(c_ptr), value :: model
      integer(c_int), value :: beam, on
      real(c_double), value :: exclusion_length
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_set_real(model, key, value, errmsg, errmsg_len) &
        bind(C, name='b2b_model_set_real') result(st)
      import :: c_int, c_ptr, c_char, c_double
      type(c_ptr), value :: model
      character(kind=c_char), intent(in) :: key(*)
      real(c_double), value :: value
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_set_int(model, key, value, errmsg, errmsg_len) &
        bind(C, name='b2b_model_set_int') result(st)
      import :: c_int, c_ptr, c_char
      type(c_ptr), value :: model
      character(kind=c_char), intent(in) :: key(*)
      integer(c_int), value :: value
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_finalize(model, n_nodes, errmsg, errmsg_len) &
        bind(C, name='b2b_model_finalize') result(st)
      import :: c_int, c_ptr, c_char
      type(c_ptr), value :: model
      integer(c_int), value :: n_nodes
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_update(model, x, ldx, n_cols, want_tangent, errmsg, errmsg_len) &
        bind(C, name='b2b_model_update') result(st)
      import :: c_int, c_ptr, c_char, c_double
      type(c_ptr), value :: model
      real(c_double), intent(in) :: x(*)
      integer(c_int), value :: ldx, n_cols, want_tangent
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_contact_count(model, n, errmsg, errmsg_len) &
        bind(C, name='b2b_model_contact_count') result(st)
      import :: c_int, c_ptr, c_char
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: n
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_get_contact(model, k, nodes, pair, info, residual, tangent, ldk, &
                                     errmsg, errmsg_len) bind(C, name='b2b_model_get_contact') &
        result(st)
      import :: c_int, c_ptr, c_char
      type(c_ptr), value :: model, nodes, pair, info, residual, tangent
      integer(c_int), value :: k, ldk
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_add_residual(model, eq, ldeq, eq_base, n_eq, f, errmsg, errmsg_len) &
        bind(C, name='b2b_model_add_residual') result(st)
      import :: c_int, c_ptr, c_char, c_double
      type(c_ptr), value :: model
      integer(c_int), intent(in) :: eq(*)
      integer(c_int), value :: ldeq, eq_base, n_eq
      real(c_double), intent(inout) :: f(*)
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_add_tangent_dense(model, eq, ldeq, eq_base, n_eq, K, ldk, errmsg, &
                                           errmsg_len) bind(C, name='b2b_model_add_tangent_dense') &
        result(st)
      import :: c_int, c_ptr, c_char, c_double
      type(c_ptr), value :: model
      integer(c_int), intent(in) :: eq(*)
      integer(c_int), value :: ldeq, eq_base, n_eq, ldk
      real(c_double), intent(inout) :: K(*)
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_add_tangent_banded(model, eq, ldeq, eq_base, n_eq, kl, ku, AB, ldab, &
                                            errmsg, errmsg_len) &
        bind(C, name='b2b_model_add_tangent_banded') result(st)
      import :: c_int, c_ptr, c_char, c_double
      type(c_ptr), value :: model
      integer(c_int), intent(in) :: eq(*)
      integer(c_int), value :: ldeq, eq_base, n_eq, kl, ku, ldab
      real(c_double), intent(inout) :: AB(*)
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_tangent_coo(model, eq, ldeq, eq_base, n_eq, nnz, rows, cols, values, &
                                     capacity, errmsg, errmsg_len) &
        bind(C, name='b2b_model_tangent_coo') result(st)
      import :: c_int, c_ptr, c_char
      type(c_ptr), value :: model, rows, cols, values
      integer(c_int), intent(in) :: eq(*)
      integer(c_int), value :: ldeq, eq_base, n_eq, capacity
      integer(c_int), intent(inout) :: nnz
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_commit(model, errmsg, errmsg_len) bind(C, name='b2b_model_commit') &
        result(st)
      import :: c_int, c_ptr, c_char
      type(c_ptr), value :: model
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_revert(model, errmsg, errmsg_len) bind(C, name='b2b_model_revert') &
        result(st)
      import :: c_int, c_ptr, c_char
      type(c_ptr), value :: model
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_save_size(model, size, errmsg, errmsg_len) &
        bind(C, name='b2b_model_save_size') result(st)
      import :: c_int, c_ptr, c_char, c_int64_t
      type(c_ptr), value :: model
      integer(c_int64_t), intent(inout) :: size
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_save(model, buffer, size, errmsg, errmsg_len) &
        bind(C, name='b2b_model_save') result(st)
      import :: c_int, c_ptr, c_char, c_int64_t, c_int8_t
      type(c_ptr), value :: model
      integer(c_int8_t), intent(inout) :: buffer(*)
      integer(c_int64_t), value :: size
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_restore(model, buffer, size, errmsg, errmsg_len) &
        bind(C, name='b2b_model_restore') result(st)
      import :: c_int, c_ptr, c_char, c_int64_t, c_int8_t
      type(c_ptr), value :: model
      integer(c_int8_t), intent(in) :: buffer(*)
      integer(c_int64_t), value :: size
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_stats(model, counts, totals, errmsg, errmsg_len) &
        bind(C, name='b2b_model_stats') result(st)
      import :: c_int, c_ptr, c_char, c_double
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: counts(*)
      real(c_double), intent(inout) :: totals(*)
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_audit(model, tolerance, n_found, pairs, overlap, reasons, capacity, &
                               errmsg, errmsg_len) bind(C, name='b2b_model_audit') result(st)
      import :: c_int, c_ptr, c_char, c_double
      type(c_ptr), value :: model, pairs, overlap, reasons
      real(c_double), value :: tolerance
      integer(c_int), intent(inout) :: n_found
      integer(c_int), value :: capacity
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function
  end interface

contains

  !> English name of a status code (never empty; "unknown status" for a code
  !> the library does not know, also one beyond C's int range).
  function b2b_strerror(status) result(msg)
    integer, intent(in) :: status
    character(len=:), allocatable :: msg
    integer(c_int) :: cstatus
    cstatus = -1
    if (fits_c_int(status)) cstatus = int(status, c_int)
    msg = c_string(c_b2b_strerror(cstatus))
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
  end subroutine

  !> Number of segments of a beam of n_nodes nodes (closed = .true.: a ring).
  subroutine b2b_beam_segment_count(kind, n_nodes, closed, n_segments, ierr, errmsg)
    integer, intent(in) :: kind, n_nodes
    logical, intent(in) :: closed
    integer, intent(inout) :: n_segments
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
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
  end subroutine

  ! ------------------------------------------------------------- contact

  !> Creates a parameter handle holding the defaults (the keys are listed in
  !> the C header b2b_pair.h). params must be null (never created, or
  !> destroyed): creating over a live handle would lose it, so that is
  !> B2B_ERR_STATE and params is left as it is.
  subroutine b2b_params_create(params, ierr, errmsg)
    type(b2b_params), intent(inout) :: params
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
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
  end subroutine

  !> Frees the handle and nulls it. A null handle (never created, or already
  !> destroyed) is a no-op, so destroying twice is safe. Never fails.
  subroutine b2b_params_destroy(params, ierr, errmsg)
    type(b2b_params), intent(inout) :: params
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    integer(c_int) :: st
    st = c_b2b_params_destroy(params%ptr)
    params%ptr = c_null_ptr
    call finish('b2b_params_destroy', st, blank_message(), ierr, errmsg)
  end subroutine

  !> Sets the real option key (trailing blanks ignored), before finalize.
  subroutine b2b_params_set_real(params, key, value, ierr, errmsg)
    type(b2b_params), intent(inout) :: params
    character(len=*), intent(in) :: key
    real(c_double), intent(in) :: value
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    buf = c_null_char
    st = c_b2b_params_set_real(params%ptr, trim(key) // c_null_char, value, buf, &
                               int(size(buf), c_int))
    call finish('b2b_params_set_real', st, buf, ierr, errmsg)
  end subroutine

  !> Sets the integer option key (trailing blanks ignored), before finalize.
  subroutine b2b_params_set_int(params, key, value, ierr, errmsg)
    type(b2b_params), intent(inout) :: params
    character(len=*), intent(in) :: key
    integer, intent(in) :: value
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
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
  end subroutine

  !> The value of the real option key (its default if it was never set).
  subroutine b2b_params_get_real(params, key, value, ierr, errmsg)
    type(b2b_params), intent(in) :: params
    character(len=*), intent(in) :: key
    real(c_double), intent(inout) :: value
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    real(c_double) :: cvalue
    integer(c_int) :: st
    buf = c_null_char
    cvalue = 0
    st = c_b2b_params_get_real(params%ptr, trim(key) // c_null_char, cvalue, buf, &
                               int(size(buf), c_int))
    if (st == B2B_OK) value = cvalue
    call finish('b2b_params_get_real', st, buf, ierr, errmsg)
  end subroutine

  !> The value of the integer option key (its default if it was never set).
  subroutine b2b_params_get_int(params, key, value, ierr, errmsg)
    type(b2b_params), intent(in) :: params
    character(len=*), intent(in) :: key
    integer, intent(inout) :: value
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: cvalue, st
    buf = c_null_char
    cvalue = 0
    st = c_b2b_params_get_int(params%ptr, trim(key) // c_null_char, cvalue, buf, &
                              int(size(buf), c_int))
    if (st == B2B_OK) value = cvalue
    call finish('b2b_params_get_int', st, buf, ierr, errmsg)
  end subroutine

  !> Checks the options together and makes the handle read-only (setting an
  !> option afterwards is B2B_ERR_STATE). Finalizing twice is allowed.
  subroutine b2b_params_finalize(params, ierr, errmsg)
    type(b2b_params), intent(inout) :: params
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    buf = c_null_char
    st = c_b2b_params_finalize(params%ptr, buf, int(size(buf), c_int))
    call finish('b2b_params_finalize', st, buf, ierr, errmsg)
  end subroutine

  !> n: the length of a pair history (hist_old, hist_new of b2b_pair_eval) for
  !> this finalized parameter set.
  subroutine b2b_params_history_size(params, n, ierr, errmsg)
    type(b2b_params), intent(in) :: params
    integer, intent(inout) :: n
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: cn, st
    buf = c_null_char
    cn = 0
    st = c_b2b_params_history_size(params%ptr, cn, buf, int(size(buf), c_int))
    if (st == B2B_OK) n = cn
    call finish('b2b_params_history_size', st, buf, ierr, errmsg)
  end subroutine

  !> Evaluates one contact pair, segment A against segment B (b2b_pair_eval
  !> in the C header documents the closest points, the gap and its sign,
  !> ownership, the history and the contact status).
  !>   params               a finalized parameter handle
  !>   segments(3,2)        column b: kind, start_rule, end_rule of beam b (A, B)
  !>   X(3,8)               the 24 contact coordinates: A's patch nodes x1..x4,
  !>                        then B's
  !>   radii(2)             cross-section radii of A and B (>= 0)
  !>   hist_old(:)          the pair's history: b2b_params_history_size doubles,
  !>                        all zero for a fresh pair
  !>   hist_new(:)          the updated history, of the same size as hist_old;
  !>                        a distinct array (copy it into hist_old to commit):
  !>                        sharing memory with hist_old is B2B_ERR_RANGE (to
  !>                        update h in place pass hist_old=(h), hist_new=h)
  !>   contact_status       B2B_CONTACT_* (a physical outcome, not an error)
  !>   info(32)             index it with B2B_IX_INFO_* (the C entry
  !>                        info[B2B_INFO_GAP] is info(B2B_IX_INFO_GAP));
  !>                        with friction also the tangential force, slip,
  !>                        B2B_FRICTION_* state and dissipation
  !>   residual(24)         the contact contribution to the internal forces
  !>   tangent(ldk,24)      d residual/dX in rows 1..24, ldk = size(tangent,1)
  !>                        >= 24 (rows 25..ldk are not touched)
  !>   end_tangents(3,4)    host end tangents: A's first and last node, then
  !>                        B's; needed only where a rule is B2B_END_TANGENT
  !> An absent tangent is not computed (which is cheaper). With "friction" > 0
  !> an active pair's tangent is not symmetric (info(B2B_IX_INFO_SYMMETRIC) = 0).
  subroutine b2b_pair_eval(params, segments, X, radii, hist_old, hist_new, contact_status, &
                           info, residual, tangent, end_tangents, ierr, errmsg)
    type(b2b_params), intent(in) :: params
    integer, intent(in), contiguous :: segments(:, :)
    real(c_double), intent(in), contiguous :: X(:, :)
    real(c_double), intent(in), contiguous :: radii(:)
    real(c_double), intent(in), contiguous, target :: hist_old(:)
    real(c_double), intent(inout), contiguous, target :: hist_new(:)
    integer, intent(inout) :: contact_status
    real(c_double), intent(inout), contiguous :: info(:)
    real(c_double), intent(inout), contiguous :: residual(:)
    real(c_double), intent(inout), contiguous, target, optional :: tangent(:, :)
    real(c_double), intent(in), contiguous, target, optional :: end_tangents(:, :)
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
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
  end subroutine

  ! An optional array's address and shape for eval_pair: (c_null_ptr, -1)
  ! where absent.
  subroutine optional_address(p, sh, addr, actual_shape)
    type(c_ptr), intent(out) :: p
    integer, intent(out) :: sh(2)
    type(c_ptr), intent(in), optional :: addr
    integer, intent(in), optional :: actual_shape(2)
    p = c_null_ptr
    sh = -1
    if (present(addr)) then
      p = addr
      sh = actual_shape
    end if
  end subroutine

  !> b2b_pair_eval with parameters held at segment ends (End contact in the
  !> C header b2b_pair.h: node-to-segment and node-to-node contact).
  !>   ends(2)              A's, then B's: -1 (the segment's start node), +1
  !>                        (its end node) or 0 (free); anything else is
  !>                        B2B_ERR_RANGE. The other arguments as b2b_pair_eval;
  !>                        info(B2B_IX_INFO_END_A), info(B2B_IX_INFO_END_B)
  !>                        echo ends.
  subroutine b2b_pair_eval_ends(params, segments, X, radii, ends, hist_old, hist_new, &
                                contact_status, info, residual, tangent, end_tangents, ierr, &
                                errmsg)
    type(b2b_params), intent(in) :: params
    integer, intent(in), contiguous :: segments(:, :)
    real(c_double), intent(in), contiguous :: X(:, :)
    real(c_double), intent(in), contiguous :: radii(:)
    integer, intent(in), contiguous :: ends(:)
    real(c_double), intent(in), contiguous, target :: hist_old(:)
    real(c_double), intent(inout), contiguous, target :: hist_new(:)
    integer, intent(inout) :: contact_status
    real(c_double), intent(inout), contiguous :: info(:)
    real(c_double), intent(inout), contiguous :: residual(:)
    real(c_double), intent(inout), contiguous, target, optional :: tangent(:, :)
    real(c_double), intent(in), contiguous, target, optional :: end_tangents(:, :)
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
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
  end subroutine

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

    if (.not. shape_is(shape(segments), [3, 2])) then
      call finish_size(me, 'segments', shape(segments), [3, 2], ierr, errmsg)
      return
    end if
    call check_int_matrix(me, 'segments', segments, ok, ierr, errmsg)
    if (.not. ok) return
    if (.not. shape_is(shape(X), [3, 8])) then
      call finish_size(me, 'X', shape(X), [3, 8], ierr, errmsg)
      return
    end if
    if (.not. shape_is(shape(radii), [2])) then
      call finish_size(me, 'radii', shape(radii), [2], ierr, errmsg)
      return
    end if
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
    pk = c_null_ptr
    pt = c_null_ptr
    ldk = B2B_PAIR_NDOF
    if (kshape(1) >= 0) then
      if (kshape(1) < B2B_PAIR_NDOF .or. kshape(2) /= B2B_PAIR_NDOF) then
        call finish_text(me, int(B2B_ERR_SIZE, c_int), me // ': tangent has shape (' // &
                         shape_text(kshape) // '), expected (ldk,24) with ldk >= 24', &
                         ierr, errmsg)
        return
      end if
      call check_ints(me, [character(len=15) :: 'size(tangent,1)'], [kshape(1)], ok, &
                      ierr, errmsg)
      if (.not. ok) return
      pk = tangent
      ldk = int(kshape(1), c_int)
    end if
    if (tshape(1) >= 0) then
      if (.not. shape_is(tshape, [3, 4])) then
        call finish_size(me, 'end_tangents', tshape, [3, 4], ierr, errmsg)
        return
      end if
      pt = end_tangents
    end if
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

  !> Re-expresses a committed pair history for the neighbouring segment of one
  !> beam, when the contact point crosses a joint of that beam (Handover in
  !> the C header b2b_pair.h: the anchor parameter is mapped across the joint,
  !> the rest is copied).
  !>   params               a finalized parameter handle (the pair's)
  !>   beam                 1 (A) or 2 (B): the beam whose segment changes, as
  !>                        the columns of segments(3,2) of b2b_pair_eval
  !>                        (C: 0 or 1); anything else is B2B_ERR_UNKNOWN_KIND
  !>   direction            +1 if `to` follows `from` along the beam, -1 if it
  !>                        precedes it (else B2B_ERR_UNKNOWN_KIND)
  !>   from_segment(3)      kind, start_rule, end_rule of the old segment
  !>   from_X(3,4)          its patch nodes x1..x4
  !>   to_segment(3), to_X(3,4)  the same for the new segment
  !>   hist_from(:)         the committed history of the old pair
  !>                        (b2b_params_history_size doubles)
  !>   hist_to(:)           the history for the new pair, of the same size; a
  !>                        distinct array: sharing memory with hist_from is
  !>                        B2B_ERR_RANGE (to hand over h in place pass
  !>                        hist_from=(h), hist_to=h)
  !>   from_end_tangents(3,2), to_end_tangents(3,2)
  !>                        host end tangents (first node, last node) of each
  !>                        segment; needed only where a rule is B2B_END_TANGENT
  !> Segments that do not share the joint give B2B_ERR_RANGE.
  subroutine b2b_pair_history_handover(params, beam, direction, from_segment, from_X, &
                                       to_segment, to_X, hist_from, hist_to, &
                                       from_end_tangents, to_end_tangents, ierr, errmsg)
    type(b2b_params), intent(in) :: params
    integer, intent(in) :: beam, direction
    integer, intent(in), contiguous :: from_segment(:)
    real(c_double), intent(in), contiguous :: from_X(:, :)
    integer, intent(in), contiguous :: to_segment(:)
    real(c_double), intent(in), contiguous :: to_X(:, :)
    real(c_double), intent(in), contiguous, target :: hist_from(:)
    real(c_double), intent(inout), contiguous, target :: hist_to(:)
    real(c_double), intent(in), contiguous, target, optional :: from_end_tangents(:, :)
    real(c_double), intent(in), contiguous, target, optional :: to_end_tangents(:, :)
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
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
  end subroutine

  ! ------------------------------------------------------- contact model

  !> Creates a contact model (b2b_model in C; the contract is in the C header
  !> b2b_model.h). Its messages speak Fortran numbers (1-based beams, nodes,
  !> segments, contacts). model must be null (never created, or destroyed).
  subroutine b2b_model_create(model, ierr, errmsg)
    type(b2b_model), intent(inout) :: model
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(len=*), parameter :: me = 'b2b_model_create'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    type(c_ptr) :: p
    integer(c_int) :: st
    if (c_associated(model%ptr)) then
      call finish_text(me, int(B2B_ERR_STATE, c_int), me // ': model already holds a ' // &
                       'handle (b2b_model_destroy it first)', ierr, errmsg)
      return
    end if
    buf = c_null_char
    p = c_null_ptr
    st = c_b2b_model_create(p, buf, int(size(buf), c_int))
    if (st == B2B_OK) then
      model%ptr = p
      st = c_b2b_model_set_int(p, 'message_base' // c_null_char, 1_c_int, buf, int(size(buf), c_int))
    end if
    call finish(me, st, buf, ierr, errmsg)
  end subroutine

  !> Frees the model and nulls the handle; a null handle is a no-op.
  subroutine b2b_model_destroy(model, ierr, errmsg)
    type(b2b_model), intent(inout) :: model
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    integer(c_int) :: st
    st = c_b2b_model_destroy(model%ptr)
    model%ptr = c_null_ptr
    call finish('b2b_model_destroy', st, blank_message(), ierr, errmsg)
  end subroutine

  !> Adds a beam: nodes(:) the host's node numbers (1-based) along it, closed
  !> .true. for a ring (do not repeat the first node), radius > 0, kind
  !> B2B_CURVE_*, group >= 0 (the host's contact group). beam: its number (1, 2, ...).
  subroutine b2b_model_add_beam(model, nodes, closed, radius, kind, group, beam, ierr, errmsg)
    type(b2b_model), intent(inout) :: model
    integer, intent(in) :: nodes(:)
    logical, intent(in) :: closed
    real(c_double), intent(in) :: radius
    integer, intent(in) :: kind, group
    integer, intent(inout) :: beam
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(len=*), parameter :: me = 'b2b_model_add_beam'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st, cbeam, cnodes(max(size(nodes), 1))
    logical :: ok
    call check_int_array(me, 'nodes', nodes, ok, ierr, errmsg)
    if (.not. ok) return
    call check_ints(me, [character(len=11) :: 'kind', 'group', 'size(nodes)'], &
                    [kind, group, size(nodes)], ok, ierr, errmsg)
    if (.not. ok) return
    buf = c_null_char
    cbeam = 0
    cnodes = 0
    cnodes(1:size(nodes)) = int(nodes - 1, c_int)
    st = c_b2b_model_add_beam(model%ptr, cnodes, int(size(nodes), c_int), c_flag(closed), &
                              radius, int(kind, c_int), int(group, c_int), cbeam, buf, &
                              int(size(buf), c_int))
    if (st == B2B_OK) beam = int(cbeam) + 1
    call finish(me, st, buf, ierr, errmsg)
  end subroutine

  !> Groups ga and gb (host group numbers, either order; ga = gb for beams of
  !> one group) touch with the finalized parameter set params (copied).
  subroutine b2b_model_set_group_pair(model, ga, gb, params, ierr, errmsg)
    type(b2b_model), intent(inout) :: model
    integer, intent(in) :: ga, gb
    type(b2b_params), intent(in) :: params
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(len=*), parameter :: me = 'b2b_model_set_group_pair'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    logical :: ok
    call check_ints(me, [character(len=2) :: 'ga', 'gb'], [ga, gb], ok, ierr, errmsg)
    if (.not. ok) return
    buf = c_null_char
    st = c_b2b_model_set_group_pair(model%ptr, int(ga, c_int), int(gb, c_int), params%ptr, buf, &
                                    int(size(buf), c_int))
    call finish(me, st, buf, ierr, errmsg)
  end subroutine

  !> Self-contact of beam (1-based) on or off; exclusion_length (optional,
  !> default 4 r): arc length within which its own segments are not paired.
  subroutine b2b_model_set_self_contact(model, beam, on, exclusion_length, ierr, errmsg)
    type(b2b_model), intent(inout) :: model
    integer, intent(in) :: beam
    logical, intent(in) :: on
    real(c_double), intent(in), optional :: exclusion_length
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(len=*), parameter :: me = 'b2b_model_set_self_contact'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    real(c_double) :: excl
    logical :: ok
    call check_ints(me, [character(len=4) :: 'beam'], [beam], ok, ierr, errmsg)
    if (.not. ok) return
    excl = -1.0_c_double
    if (present(exclusion_length)) excl = exclusion_length
    buf = c_null_char
    st = c_b2b_model_set_self_contact(model%ptr, int(beam - 1, c_int), c_flag(on), excl, buf, &
                                      int(size(buf), c_int))
    call finish(me, st, buf, ierr, errmsg)
  end subroutine

  !> Sets a real option of the model ("search_margin").
  subroutine b2b_model_set_real(model, key, value, ierr, errmsg)
    type(b2b_model), intent(inout) :: model
    character(len=*), intent(in) :: key
    real(c_double), intent(in) :: value
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    buf = c_null_char
    st = c_b2b_model_set_real(model%ptr, trim(key) // c_null_char, value, buf, int(size(buf), c_int))
    call finish('b2b_model_set_real', st, buf, ierr, errmsg)
  end subroutine

  !> Sets an integer option of the model ("threads", "max_handover_hops",
  !> "message_base", "max_candidates"; b2b_model.h).
  subroutine b2b_model_set_int(model, key, value, ierr, errmsg)
    type(b2b_model), intent(inout) :: model
    character(len=*), intent(in) :: key
    integer, intent(in) :: value
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(len=*), parameter :: me = 'b2b_model_set_int'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    logical :: ok
    call check_ints(me, [character(len=5) :: 'value'], [value], ok, ierr, errmsg)
    if (.not. ok) return
    buf = c_null_char
    st = c_b2b_model_set_int(model%ptr, trim(key) // c_null_char, int(value, c_int), buf, &
                             int(size(buf), c_int))
    call finish(me, st, buf, ierr, errmsg)
  end subroutine

  !> Builds the segment tables; the host has n_nodes nodes (numbers 1 .. n_nodes).
  subroutine b2b_model_finalize(model, n_nodes, ierr, errmsg)
    type(b2b_model), intent(inout) :: model
    integer, intent(in) :: n_nodes
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(len=*), parameter :: me = 'b2b_model_finalize'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    logical :: ok
    call check_ints(me, [character(len=7) :: 'n_nodes'], [n_nodes], ok, ierr, errmsg)
    if (.not. ok) return
    buf = c_null_char
    st = c_b2b_model_finalize(model%ptr, int(n_nodes, c_int), buf, int(size(buf), c_int))
    if (st == B2B_OK) model%n_nodes = n_nodes
    call finish(me, st, buf, ierr, errmsg)
  end subroutine

  !> One Newton iteration: x(ldx, n) the current coordinates of the host's
  !> nodes (rows 1..3: x, y, z; ldx = size(x, 1) >= 3, so FEAP's x(ndm, numnp)
  !> works as is), n = size(x, 2) >= n_nodes. want_tangent (default .true.):
  !> .false. skips the tangents.
  subroutine b2b_model_update(model, x, want_tangent, ierr, errmsg)
    type(b2b_model), intent(inout) :: model
    real(c_double), intent(in), contiguous :: x(:, :)
    logical, intent(in), optional :: want_tangent
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(len=*), parameter :: me = 'b2b_model_update'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st, want
    real(c_double) :: dummy(3)
    logical :: ok
    call check_ints(me, [character(len=9) :: 'size(x,1)', 'size(x,2)'], [size(x, 1), size(x, 2)], &
                    ok, ierr, errmsg)
    if (.not. ok) return
    want = 1
    if (present(want_tangent)) want = c_flag(want_tangent)
    buf = c_null_char
    if (size(x) > 0) then
      st = c_b2b_model_update(model%ptr, x, int(size(x, 1), c_int), int(size(x, 2), c_int), &
                              want, buf, int(size(buf), c_int))
    else
      dummy = 0
      st = c_b2b_model_update(model%ptr, dummy, int(size(x, 1), c_int), 0_c_int, want, buf, &
                              int(size(buf), c_int))
    end if
    call finish(me, st, buf, ierr, errmsg)
  end subroutine

  !> The number of active contacts of the last update.
  subroutine b2b_model_contact_count(model, n, ierr, errmsg)
    type(b2b_model), intent(in) :: model
    integer, intent(inout) :: n
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st, cn
    buf = c_null_char
    cn = 0
    st = c_b2b_model_contact_count(model%ptr, cn, buf, int(size(buf), c_int))
    if (st == B2B_OK) n = int(cn)
    call finish('b2b_model_contact_count', st, buf, ierr, errmsg)
  end subroutine

  !> Contact k (1 .. count) of the last update; every output is optional:
  !>   nodes(8)        host nodes (1-based) of A's patch slots, then B's; 0: no node
  !>   pair(4)         beam A, segment A, beam B, segment B (1-based)
  !>   info(32)        as b2b_pair_eval: index it with B2B_IX_INFO_*
  !>   residual(24)    the element residual on the 24 coordinates of nodes
  !>   tangent(ldk,24) its tangent (ldk >= 24), if the update computed one
  subroutine b2b_model_get_contact(model, k, nodes, pair, info, residual, tangent, ierr, errmsg)
    type(b2b_model), intent(in) :: model
    integer, intent(in) :: k
    integer, intent(inout), optional :: nodes(:), pair(:)
    real(c_double), intent(inout), contiguous, target, optional :: info(:), residual(:)
    real(c_double), intent(inout), contiguous, target, optional :: tangent(:, :)
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(len=*), parameter :: me = 'b2b_model_get_contact'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int), target :: cnodes(8), cpair(4)
    type(c_ptr) :: pn, pp, pi, pr, pk
    integer(c_int) :: st, ldk
    logical :: ok
    call check_ints(me, [character(len=1) :: 'k'], [k], ok, ierr, errmsg)
    if (.not. ok) return
    pn = c_null_ptr
    pp = c_null_ptr
    pi = c_null_ptr
    pr = c_null_ptr
    pk = c_null_ptr
    ldk = 24
    if (present(nodes)) then
      if (.not. shape_is(shape(nodes), [8])) then
        call finish_size(me, 'nodes', shape(nodes), [8], ierr, errmsg)
        return
      end if
      pn = c_loc(cnodes)
    end if
    if (present(pair)) then
      if (.not. shape_is(shape(pair), [4])) then
        call finish_size(me, 'pair', shape(pair), [4], ierr, errmsg)
        return
      end if
      pp = c_loc(cpair)
    end if
    if (present(info)) then
      if (.not. shape_is(shape(info), [B2B_PAIR_INFO_LEN])) then
        call finish_size(me, 'info', shape(info), [B2B_PAIR_INFO_LEN], ierr, errmsg)
        return
      end if
      pi = c_loc(info)
    end if
    if (present(residual)) then
      if (.not. shape_is(shape(residual), [B2B_PAIR_NDOF])) then
        call finish_size(me, 'residual', shape(residual), [B2B_PAIR_NDOF], ierr, errmsg)
        return
      end if
      pr = c_loc(residual)
    end if
    if (present(tangent)) then
      if (size(tangent, 1) < B2B_PAIR_NDOF .or. size(tangent, 2) /= B2B_PAIR_NDOF) then
        call finish_text(me, int(B2B_ERR_SIZE, c_int), me // ': tangent has shape (' // &
                         shape_text(shape(tangent)) // '), expected (ldk,24) with ldk >= 24', &
                         ierr, errmsg)
        return
      end if
      call check_ints(me, [character(len=15) :: 'size(tangent,1)'], [size(tangent, 1)], ok, &
                      ierr, errmsg)
      if (.not. ok) return
      pk = c_loc(tangent)
      ldk = int(size(tangent, 1), c_int)
    end if
    buf = c_null_char
    st = c_b2b_model_get_contact(model%ptr, int(k - 1, c_int), pn, pp, pi, pr, pk, ldk, buf, &
                                 int(size(buf), c_int))
    if (st == B2B_OK .and. present(nodes)) nodes = int(cnodes) + 1
    if (st == B2B_OK .and. present(pair)) pair = int(cpair) + 1
    call finish(me, st, buf, ierr, errmsg)
  end subroutine

  !> f(e) += the contacts' residuals, through eq(ldeq, n_nodes) (ldeq >= 3):
  !> the host's equation numbers of node k's x, y, z dofs in eq(1:3, k), 1-based,
  !> <= 0 for a constrained dof (a FEAP-style id(ndf, numnp) works as is);
  !> n_eq = size(f).
  subroutine b2b_model_add_residual(model, eq, f, ierr, errmsg)
    type(b2b_model), intent(in) :: model
    integer, intent(in) :: eq(:, :)
    real(c_double), intent(inout), contiguous :: f(:)
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(len=*), parameter :: me = 'b2b_model_add_residual'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    integer(c_int), allocatable :: ceq(:, :)
    real(c_double) :: dummy(1)
    logical :: ok
    call check_equations(me, model, eq, ok, ierr, errmsg)
    if (.not. ok) return
    call check_ints(me, [character(len=7) :: 'size(f)'], [size(f)], ok, ierr, errmsg)
    if (.not. ok) return
    call c_equations(eq, ceq)
    buf = c_null_char
    if (size(f) > 0) then
      st = c_b2b_model_add_residual(model%ptr, ceq, int(size(eq, 1), c_int), 1_c_int, &
                                    int(size(f), c_int), f, buf, int(size(buf), c_int))
    else
      st = c_b2b_model_add_residual(model%ptr, ceq, int(size(eq, 1), c_int), 1_c_int, 0_c_int, &
                                    dummy, buf, int(size(buf), c_int))
    end if
    call finish(me, st, buf, ierr, errmsg)
  end subroutine

  !> K(e_r, e_c) += the contacts' tangents (a dense matrix; n_eq = size(K, 2),
  !> size(K, 1) >= n_eq); eq as for b2b_model_add_residual.
  subroutine b2b_model_add_tangent_dense(model, eq, K, ierr, errmsg)
    type(b2b_model), intent(in) :: model
    integer, intent(in) :: eq(:, :)
    real(c_double), intent(inout), contiguous :: K(:, :)
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(len=*), parameter :: me = 'b2b_model_add_tangent_dense'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    integer(c_int), allocatable :: ceq(:, :)
    logical :: ok
    call check_equations(me, model, eq, ok, ierr, errmsg)
    if (.not. ok) return
    call check_ints(me, [character(len=9) :: 'size(K,1)', 'size(K,2)'], [size(K, 1), size(K, 2)], &
                    ok, ierr, errmsg)
    if (.not. ok) return
    call c_equations(eq, ceq)
    buf = c_null_char
    st = c_b2b_model_add_tangent_dense(model%ptr, ceq, int(size(eq, 1), c_int), 1_c_int, &
                                       int(size(K, 2), c_int), K, int(size(K, 1), c_int), buf, &
                                       int(size(buf), c_int))
    call finish(me, st, buf, ierr, errmsg)
  end subroutine

  !> Adds the contacts' tangents into AB(ldab, n_eq), LAPACK's general band
  !> storage for dgbsv with kl sub- and ku superdiagonals (ldab >= 2 kl + ku + 1:
  !> K(i, j) is AB(kl + ku + 1 + i - j, j)); eq as for b2b_model_add_residual.
  !> An entry outside the band is B2B_ERR_RANGE, and nothing is added.
  subroutine b2b_model_add_tangent_banded(model, eq, kl, ku, AB, ierr, errmsg)
    type(b2b_model), intent(in) :: model
    integer, intent(in) :: eq(:, :)
    integer, intent(in) :: kl, ku
    real(c_double), intent(inout), contiguous :: AB(:, :)
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(len=*), parameter :: me = 'b2b_model_add_tangent_banded'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    integer(c_int), allocatable :: ceq(:, :)
    logical :: ok
    call check_equations(me, model, eq, ok, ierr, errmsg)
    if (.not. ok) return
    call check_ints(me, [character(len=10) :: 'kl', 'ku', 'size(AB,1)', 'size(AB,2)'], &
                    [kl, ku, size(AB, 1), size(AB, 2)], ok, ierr, errmsg)
    if (.not. ok) return
    call c_equations(eq, ceq)
    buf = c_null_char
    st = c_b2b_model_add_tangent_banded(model%ptr, ceq, int(size(eq, 1), c_int), 1_c_int, &
                                        int(size(AB, 2), c_int), int(kl, c_int), int(ku, c_int), &
                                        AB, int(size(AB, 1), c_int), buf, int(size(buf), c_int))
    call finish(me, st, buf, ierr, errmsg)
  end subroutine

  !> The tangent as COO triplets in the host's 1-based equation numbers
  !> (duplicates are to be summed). Without rows, cols and values only nnz is
  !> set (the size query); with them, each must hold at least nnz entries.
  subroutine b2b_model_tangent_coo(model, eq, n_eq, nnz, rows, cols, values, ierr, errmsg)
    type(b2b_model), intent(in) :: model
    integer, intent(in) :: eq(:, :)
    integer, intent(in) :: n_eq
    integer, intent(inout) :: nnz
    integer(c_int), intent(inout), contiguous, target, optional :: rows(:), cols(:)
    real(c_double), intent(inout), contiguous, target, optional :: values(:)
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(len=*), parameter :: me = 'b2b_model_tangent_coo'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st, cnnz, capacity
    integer(c_int), allocatable :: ceq(:, :)
    type(c_ptr) :: pr, pc, pv
    logical :: ok
    pr = c_null_ptr
    pc = c_null_ptr
    pv = c_null_ptr
    capacity = 0
    if (present(rows) .or. present(cols) .or. present(values)) then
      if (.not. (present(rows) .and. present(cols) .and. present(values))) then
        call finish_text(me, int(B2B_ERR_NULL, c_int), me // ': give rows, cols and values ' // &
                         'together (or none of them for the size query)', ierr, errmsg)
        return
      end if
      ! capacity is a bound: arrays longer than C's int range offer that much.
      capacity = int(min(size(rows), size(cols), size(values), int(huge(capacity))), c_int)
      if (capacity > 0) then
        pr = c_loc(rows)
        pc = c_loc(cols)
        pv = c_loc(values)
      end if
    end if
    call check_equations(me, model, eq, ok, ierr, errmsg)
    if (.not. ok) return
    call check_ints(me, [character(len=4) :: 'n_eq'], [n_eq], ok, ierr, errmsg)
    if (.not. ok) return
    call c_equations(eq, ceq)
    buf = c_null_char
    cnnz = 0
    if (present(rows) .and. capacity == 0) then
      ! no room: ask for the count and report the size like the library would
      st = c_b2b_model_tangent_coo(model%ptr, ceq, int(size(eq, 1), c_int), 1_c_int, &
                                   int(n_eq, c_int), cnnz, c_null_ptr, c_null_ptr, c_null_ptr, &
                                   0_c_int, buf, int(size(buf), c_int))
      if (st == B2B_OK .and. cnnz > 0) then
        call finish_text(me, int(B2B_ERR_SIZE, c_int), me // ': rows, cols and values are ' // &
                         'empty but the tangent has ' // trim(int_text(int(cnnz))) // ' entries', &
                         ierr, errmsg)
        return
      end if
    else
      st = c_b2b_model_tangent_coo(model%ptr, ceq, int(size(eq, 1), c_int), 1_c_int, &
                                   int(n_eq, c_int), cnnz, pr, pc, pv, capacity, buf, &
                                   int(size(buf), c_int))
    end if
    if (st == B2B_OK) nnz = int(cnnz)
    call finish(me, st, buf, ierr, errmsg)
  end subroutine

  !> Accepts the state of the last update (a converged step).
  subroutine b2b_model_commit(model, ierr, errmsg)
    type(b2b_model), intent(inout) :: model
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    buf = c_null_char
    st = c_b2b_model_commit(model%ptr, buf, int(size(buf), c_int))
    call finish('b2b_model_commit', st, buf, ierr, errmsg)
  end subroutine

  !> Returns to the last commit (a cut-back).
  subroutine b2b_model_revert(model, ierr, errmsg)
    type(b2b_model), intent(inout) :: model
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    buf = c_null_char
    st = c_b2b_model_revert(model%ptr, buf, int(size(buf), c_int))
    call finish('b2b_model_revert', st, buf, ierr, errmsg)
  end subroutine

  !> Bytes b2b_model_save needs for the committed state.
  subroutine b2b_model_save_size(model, nbytes, ierr, errmsg)
    type(b2b_model), intent(in) :: model
    integer(c_int64_t), intent(inout) :: nbytes
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    integer(c_int64_t) :: n
    buf = c_null_char
    n = 0
    st = c_b2b_model_save_size(model%ptr, n, buf, int(size(buf), c_int))
    if (st == B2B_OK) nbytes = n
    call finish('b2b_model_save_size', st, buf, ierr, errmsg)
  end subroutine

  !> The committed state into buffer (at least b2b_model_save_size bytes).
  subroutine b2b_model_save(model, buffer, ierr, errmsg)
    type(b2b_model), intent(in) :: model
    integer(c_int8_t), intent(inout), contiguous :: buffer(:)
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    integer(c_int8_t) :: dummy(1)
    buf = c_null_char
    if (size(buffer) > 0) then
      st = c_b2b_model_save(model%ptr, buffer, int(size(buffer), c_int64_t), buf, &
                            int(size(buf), c_int))
    else
      st = c_b2b_model_save(model%ptr, dummy, 0_c_int64_t, buf, int(size(buf), c_int))
    end if
    call finish('b2b_model_save', st, buf, ierr, errmsg)
  end subroutine

  !> Restores a committed state saved by b2b_model_save from a model built the same way.
  subroutine b2b_model_restore(model, buffer, ierr, errmsg)
    type(b2b_model), intent(inout) :: model
    integer(c_int8_t), intent(in), contiguous :: buffer(:)
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    integer(c_int8_t) :: dummy(1)
    buf = c_null_char
    if (size(buffer) > 0) then
      st = c_b2b_model_restore(model%ptr, buffer, int(size(buffer), c_int64_t), buf, &
                               int(size(buf), c_int))
    else
      dummy = 0
      st = c_b2b_model_restore(model%ptr, dummy, 0_c_int64_t, buf, int(size(buf), c_int))
    end if
    call finish('b2b_model_restore', st, buf, ierr, errmsg)
  end subroutine

  !> counts(16) and totals(8) of the last update, either optional: index them
  !> with B2B_IX_COUNT_* and B2B_IX_TOTAL_* (counts(B2B_IX_COUNT_ACTIVE) is the
  !> C counts[B2B_COUNT_ACTIVE]).
  subroutine b2b_model_stats(model, counts, totals, ierr, errmsg)
    type(b2b_model), intent(in) :: model
    integer, intent(inout), optional :: counts(:)
    real(c_double), intent(inout), optional :: totals(:)
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(len=*), parameter :: me = 'b2b_model_stats'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st, c(B2B_MODEL_COUNTS_LEN)
    real(c_double) :: t(B2B_MODEL_TOTALS_LEN)
    if (present(counts)) then
      if (.not. shape_is(shape(counts), [B2B_MODEL_COUNTS_LEN])) then
        call finish_size(me, 'counts', shape(counts), [B2B_MODEL_COUNTS_LEN], ierr, errmsg)
        return
      end if
    end if
    if (present(totals)) then
      if (.not. shape_is(shape(totals), [B2B_MODEL_TOTALS_LEN])) then
        call finish_size(me, 'totals', shape(totals), [B2B_MODEL_TOTALS_LEN], ierr, errmsg)
        return
      end if
    end if
    buf = c_null_char
    c = 0
    t = 0
    st = c_b2b_model_stats(model%ptr, c, t, buf, int(size(buf), c_int))
    if (st == B2B_OK .and. present(counts)) counts = int(c)
    if (st == B2B_OK .and. present(totals)) totals = t
    call finish(me, st, buf, ierr, errmsg)
  end subroutine

  !> The interpenetration audit of the last update (b2b_model.h, "Interpenetration
  !> audit"): n_found pairs of segments that overlap by more than
  !> tolerance * (the smaller radius) and carry no force. Without pairs,
  !> overlap and reasons only n_found is set (the size query); with them
  !> (all three), finding k is pairs(:, k) = beam A, segment A, beam B,
  !> segment B (1-based), overlap(k) = r_A + r_B - centreline distance and
  !> reasons(k) = B2B_AUDIT_*; pairs must be (4, n) and the capacity is the
  !> smallest of n, size(overlap), size(reasons) (fewer than the findings:
  !> B2B_ERR_SIZE, nothing written). Run it after the converged update of a
  !> step, before b2b_model_commit.
  subroutine b2b_model_audit(model, tolerance, n_found, pairs, overlap, reasons, ierr, errmsg)
    type(b2b_model), intent(in) :: model
    real(c_double), intent(in) :: tolerance
    integer, intent(inout) :: n_found
    integer, intent(inout), optional :: pairs(:, :)
    real(c_double), intent(inout), optional :: overlap(:)
    integer, intent(inout), optional :: reasons(:)
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(len=*), parameter :: me = 'b2b_model_audit'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st, cn, capacity
    integer(c_int), allocatable, target :: cpairs(:, :), creasons(:)
    real(c_double), allocatable, target :: coverlap(:)
    logical :: given
    given = present(pairs) .or. present(overlap) .or. present(reasons)
    if (given) then
      if (.not. (present(pairs) .and. present(overlap) .and. present(reasons))) then
        call finish_text(me, int(B2B_ERR_NULL, c_int), me // ': give pairs, overlap and ' // &
                         'reasons together (or none of them for the size query)', ierr, errmsg)
        return
      end if
      if (size(pairs, 1) /= 4) then
        call finish_text(me, int(B2B_ERR_SIZE, c_int), me // ': pairs has shape (' // &
                         shape_text(shape(pairs)) // '), expected (4,n)', ierr, errmsg)
        return
      end if
      capacity = int(min(size(pairs, 2), size(overlap), size(reasons), int(huge(capacity))), c_int)
    else
      capacity = 0
    end if
    ! The library writes into buffers of C ints, converted (and made 1-based) below.
    allocate (cpairs(4, max(capacity, 1_c_int)), creasons(max(capacity, 1_c_int)), &
              coverlap(max(capacity, 1_c_int)))
    buf = c_null_char
    cn = 0
    if (given) then
      st = c_b2b_model_audit(model%ptr, tolerance, cn, c_loc(cpairs), c_loc(coverlap), &
                             c_loc(creasons), capacity, buf, int(size(buf), c_int))
    else
      st = c_b2b_model_audit(model%ptr, tolerance, cn, c_null_ptr, c_null_ptr, c_null_ptr, &
                             0_c_int, buf, int(size(buf), c_int))
    end if
    if (st == B2B_OK) then
      n_found = int(cn)
      if (given .and. cn > 0) then
        pairs(:, 1:cn) = int(cpairs(:, 1:cn)) + 1
        overlap(1:cn) = coverlap(1:cn)
        reasons(1:cn) = int(creasons(1:cn))
      end if
    end if
    call finish(me, st, buf, ierr, errmsg)
  end subroutine

  !> ok = .true. if eq(ldeq, n) covers every node of a finalized model
  !> (ldeq >= 3; an unfinalized model passes: the library reports its state)
  !> and each equation number fits a C int. Otherwise reports the problem
  !> (B2B_ERR_SIZE, B2B_ERR_RANGE) for procedure procname.
  subroutine check_equations(procname, model, eq, ok, ierr, errmsg)
    character(len=*), intent(in) :: procname
    type(b2b_model), intent(in) :: model
    integer, intent(in) :: eq(:, :)
    logical, intent(out) :: ok
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    ok = model%n_nodes < 0 .or. (size(eq, 1) >= 3 .and. size(eq, 2) >= model%n_nodes)
    if (.not. ok) then
      call finish_text(procname, int(B2B_ERR_SIZE, c_int), procname // ': eq has shape (' // &
                       shape_text(shape(eq)) // '), expected (ldeq,n) with ldeq >= 3 and n >= ' &
                       // trim(int_text(model%n_nodes)) // ' (the nodes of the model)', ierr, &
                       errmsg)
      return
    end if
    call check_ints(procname, [character(len=10) :: 'size(eq,1)', 'size(eq,2)'], &
                    [size(eq, 1), size(eq, 2)], ok, ierr, errmsg)
    if (.not. ok) return
    call check_int_matrix(procname, 'eq', eq, ok, ierr, errmsg)
  end subroutine

  !> The host's equation numbers as C ints (a copy: the host's integers may
  !> be of another kind).
  subroutine c_equations(eq, ceq)
    integer, intent(in) :: eq(:, :)
    integer(c_int), allocatable, intent(out) :: ceq(:, :)
    allocate (ceq(max(size(eq, 1), 1), max(size(eq, 2), 1)))
    ceq = 0
    ceq(1:size(eq, 1), 1:size(eq, 2)) = int(eq, c_int)
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
    call finish_text(procname, int(B2B_ERR_SIZE, c_int), procname // ': ' // argname // &
                     ' has shape (' // shape_text(got) // '), expected (' // &
                     shape_text(want) // ')', ierr, errmsg)
  end subroutine

  !> Reports a failure the module detects itself, with its message.
  subroutine finish_text(procname, st, text, ierr, errmsg)
    character(len=*), intent(in) :: procname, text
    integer(c_int), intent(in) :: st
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer :: i
    buf = c_null_char
    do i = 1, min(len_trim(text), size(buf) - 1)
      buf(i) = text(i:i)
    end do
    call finish(procname, st, buf, ierr, errmsg)
  end subroutine

  !> Whether a default integer is a C int: always, unless the host compiled
  !> this module with a wider default integer (-fdefault-integer-8). The
  !> range is symmetric, so that a 1-based value minus 1 is a C int too.
  elemental logical function fits_c_int(v)
    integer, intent(in) :: v
    fits_c_int = v >= -huge(0_c_int) .and. v <= huge(0_c_int)
  end function

  !> ok = .true. if every values(i) fits a C int; else reports B2B_ERR_RANGE
  !> for the first that does not, names(i) being its argument.
  subroutine check_ints(procname, names, values, ok, ierr, errmsg)
    character(len=*), intent(in) :: procname, names(:)
    integer, intent(in) :: values(:)
    logical, intent(out) :: ok
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    integer :: i
    ok = .true.
    do i = 1, size(values)
      if (.not. fits_c_int(values(i))) then
        ok = .false.
        call finish_range(procname, trim(names(i)), values(i), ierr, errmsg)
        return
      end if
    end do
  end subroutine

  !> check_ints for the elements of an array argument a(:).
  subroutine check_int_array(procname, argname, a, ok, ierr, errmsg)
    character(len=*), intent(in) :: procname, argname
    integer, intent(in) :: a(:)
    logical, intent(out) :: ok
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    integer :: i
    ok = .true.
    do i = 1, size(a)
      if (.not. fits_c_int(a(i))) then
        ok = .false.
        call finish_range(procname, argname // '(' // trim(int_text(i)) // ')', a(i), ierr, &
                          errmsg)
        return
      end if
    end do
  end subroutine

  !> check_ints for the elements of an array argument a(:, :).
  subroutine check_int_matrix(procname, argname, a, ok, ierr, errmsg)
    character(len=*), intent(in) :: procname, argname
    integer, intent(in) :: a(:, :)
    logical, intent(out) :: ok
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    integer :: i, j
    ok = .true.
    do j = 1, size(a, 2)
      do i = 1, size(a, 1)
        if (.not. fits_c_int(a(i, j))) then
          ok = .false.
          call finish_range(procname, argname // '(' // trim(int_text(i)) // ',' // &
                            trim(int_text(j)) // ')', a(i, j), ierr, errmsg)
          return
        end if
      end do
    end do
  end subroutine

  !> Reports an integer argument beyond C's int range as B2B_ERR_RANGE.
  subroutine finish_range(procname, argname, v, ierr, errmsg)
    character(len=*), intent(in) :: procname, argname
    integer, intent(in) :: v
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    call finish_text(procname, int(B2B_ERR_RANGE, c_int), procname // ': ' // argname // &
                     ' = ' // trim(int_text(v)) // ' is beyond the range of a C int (+-' // &
                     trim(int_text(int(huge(0_c_int)))) // ')', ierr, errmsg)
  end subroutine

  !> Whether two arrays share memory, even in part (arrays of no elements
  !> share none).
  logical function overlap(a, b)
    real(c_double), intent(in), contiguous, target :: a(:), b(:)
    integer(c_intptr_t) :: pa, pb, na, nb
    overlap = .false.
    if (size(a) == 0 .or. size(b) == 0) return
    pa = transfer(c_loc(a), pa)
    pb = transfer(c_loc(b), pb)
    na = size(a, kind=c_intptr_t) * (storage_size(a, kind=c_intptr_t) / 8)
    nb = size(b, kind=c_intptr_t) * (storage_size(b, kind=c_intptr_t) / 8)
    overlap = pa < pb + nb .and. pb < pa + na
  end function

  !> Reports an output array that shares memory with an input array.
  subroutine finish_alias(procname, outname, inname, ierr, errmsg)
    character(len=*), intent(in) :: procname, outname, inname
    integer, intent(out), optional :: ierr
    character(len=*), intent(out), optional :: errmsg
    call finish_text(procname, int(B2B_ERR_RANGE, c_int), procname // ': ' // outname // &
                     ' shares memory with ' // inname // ' (the same array?), which Fortran ' // &
                     'does not allow; pass a distinct array, or ' // inname // '=(h), ' // &
                     outname // '=h to update h in place', ierr, errmsg)
  end subroutine

  !> Rewrites a message of the C curve and pair functions in the terms of
  !> the Fortran call: an end_tangents argument the caller left out is
  !> "absent", not "NULL"; and for the history argument hist (if not ''),
  !> "<hist>[k]" and "entry k" (0-based) become "<hist>(k+1)", and the C
  !> length argument "hist_len" becomes "size(<hist>)".
  subroutine fortran_terms(buf, hist)
    character(kind=c_char), intent(inout) :: buf(:)
    character(len=*), intent(in) :: hist
    character(len=:), allocatable :: msg
    integer :: i
    msg = replace_all(c_chars(buf), 'end_tangents is NULL', 'end_tangents is absent')
    if (len(hist) > 0) then
      msg = renumber(msg, hist // '[', hist // '(', ']', ')')
      msg = renumber(msg, 'but entry ', 'but ' // hist // '(', '', ')')
      msg = replace_all(msg, 'hist_len is ', 'size(' // hist // ') is ')
    end if
    buf = c_null_char
    do i = 1, min(len(msg), size(buf) - 1)
      buf(i) = msg(i:i)
    end do
  end subroutine

  !> msg with every old replaced by new.
  function replace_all(msg, old, new) result(out)
    character(len=*), intent(in) :: msg, old, new
    character(len=:), allocatable :: out
    integer :: i, at
    out = ''
    i = 1
    do
      at = index(msg(i:), old)
      if (at == 0) exit
      out = out // msg(i:i + at - 2) // new
      i = i + at - 1 + len(old)
    end do
    out = out // msg(i:)
  end function

  !> msg with every "<key><k><close>" (k a non-negative integer) replaced by
  !> "<new_key><k+1><new_close>".
  function renumber(msg, key, new_key, close, new_close) result(out)
    character(len=*), intent(in) :: msg, key, new_key, close, new_close
    character(len=:), allocatable :: out
    integer :: i, at, j, k, n, stat
    out = ''
    i = 1
    do
      at = index(msg(i:), key)
      if (at == 0) exit
      at = i + at - 1
      j = at + len(key)
      k = j
      do while (k <= len(msg))
        if (verify(msg(k:k), '0123456789') /= 0) exit
        k = k + 1
      end do
      stat = 1
      if (k > j .and. k - j < 10) then
        if (msg(k:min(k + len(close) - 1, len(msg))) == close) read (msg(j:k - 1), *, iostat=stat) n
      end if
      if (stat == 0) then
        out = out // msg(i:at - 1) // new_key // trim(int_text(n + 1)) // new_close
        i = k + len(close)
      else
        out = out // msg(i:j - 1)
        i = j
      end if
    end do
    out = out // msg(i:)
  end function

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
