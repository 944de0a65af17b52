!> Direct bind(C) interfaces of the C ABI, for comparing the module b2b with
!> the C calls.
!>
!> The tests declare these themselves rather than reach into module b2b (whose
!> own interfaces are private), so that a wrong argument order or layout in a
!> wrapper cannot be hidden by the same mistake on both sides. Every array,
!> optional output and errmsg buffer is a type(c_ptr) passed by value: a test
!> passes c_loc of a flat array, or c_null_ptr for an absent output or for no
!> message (with errmsg_len 0). The C names lose their b2b_ prefix for a c_
!> one; the C signatures are in include/b2b/b2b*.h.
module ftest_capi
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_ptr, c_char, c_int64_t
  implicit none
  private

  public :: c_segment_eval
  public :: c_params_create, c_params_destroy, c_params_set_real, c_params_set_int
  public :: c_params_finalize, c_params_history_size
  public :: c_pair_eval, c_pair_history_handover
  public :: c_model_create, c_model_destroy, c_model_add_beam, c_model_set_group_pair
  public :: c_model_set_self_contact, c_model_set_real, c_model_set_int, c_model_finalize
  public :: c_model_update, c_model_contact_count, c_model_get_contact, c_model_add_residual
  public :: c_model_add_tangent_dense, c_model_add_tangent_banded, c_model_tangent_coo
  public :: c_model_commit, c_model_revert, c_model_save_size, c_model_save, c_model_restore
  public :: c_model_stats
  public :: c_model_set_beam_global, c_model_set_ghost_segments, c_model_get_contact_global
  public :: c_model_migration_count, c_model_migration_info, c_model_migration_pack
  public :: c_model_migration_unpack

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

    ! ------------------------------------------------ contact model (b2b_model)
    ! model is the C handle (type(c_ptr), by value); node, beam, segment and
    ! contact numbers are C's (0-based); eq arrays are C ints.

    function c_model_create(model, errmsg, errmsg_len) bind(C, name='b2b_model_create') &
        result(st)
      import :: c_int, c_ptr
      type(c_ptr), intent(inout) :: model
      type(c_ptr), value :: errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_model_destroy(model) bind(C, name='b2b_model_destroy') result(st)
      import :: c_int, c_ptr
      type(c_ptr), intent(inout) :: model
      integer(c_int) :: st
    end function

    function c_model_add_beam(model, nodes, n_nodes, closed, radius, kind, group, beam, errmsg, &
                              errmsg_len) bind(C, name='b2b_model_add_beam') result(st)
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: model, nodes
      integer(c_int), value :: n_nodes, closed
      real(c_double), value :: radius
      integer(c_int), value :: kind, group
      integer(c_int), intent(inout) :: beam
      type(c_ptr), value :: errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_model_set_group_pair(model, ga, gb, params, errmsg, errmsg_len) &
        bind(C, name='b2b_model_set_group_pair') result(st)
      import :: c_int, c_ptr
      type(c_ptr), value :: model
      integer(c_int), value :: ga, gb
      type(c_ptr), value :: params, errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_model_set_self_contact(model, beam, on, exclusion_length, errmsg, errmsg_len) &
        bind(C, name='b2b_model_set_self_contact') result(st)
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: model
      integer(c_int), value :: beam, on
      real(c_double), value :: exclusion_length
      type(c_ptr), value :: errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    !> key: a NUL-terminated string.
    function c_model_set_real(model, key, value, errmsg, errmsg_len) &
        bind(C, name='b2b_model_set_real') result(st)
      import :: c_int, c_double, c_ptr, c_char
      type(c_ptr), value :: model
      character(kind=c_char), intent(in) :: key(*)
      real(c_double), value :: value
      type(c_ptr), value :: errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_model_set_int(model, key, value, errmsg, errmsg_len) &
        bind(C, name='b2b_model_set_int') result(st)
      import :: c_int, c_ptr, c_char
      type(c_ptr), value :: model
      character(kind=c_char), intent(in) :: key(*)
      integer(c_int), value :: value
      type(c_ptr), value :: errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_model_finalize(model, n_nodes, errmsg, errmsg_len) &
        bind(C, name='b2b_model_finalize') result(st)
      import :: c_int, c_ptr
      type(c_ptr), value :: model
      integer(c_int), value :: n_nodes
      type(c_ptr), value :: errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_model_update(model, x, ldx, n_cols, want_tangent, errmsg, errmsg_len) &
        bind(C, name='b2b_model_update') result(st)
      import :: c_int, c_ptr
      type(c_ptr), value :: model, x
      integer(c_int), value :: ldx, n_cols, want_tangent
      type(c_ptr), value :: errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_model_contact_count(model, n, errmsg, errmsg_len) &
        bind(C, name='b2b_model_contact_count') result(st)
      import :: c_int, c_ptr
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: n
      type(c_ptr), value :: errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_model_get_contact(model, k, nodes, pair, info, residual, tangent, ldk, errmsg, &
                                 errmsg_len) bind(C, name='b2b_model_get_contact') result(st)
      import :: c_int, c_ptr
      type(c_ptr), value :: model
      integer(c_int), value :: k
      type(c_ptr), value :: nodes, pair, info, residual, tangent
      integer(c_int), value :: ldk
      type(c_ptr), value :: errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_model_add_residual(model, eq, ldeq, eq_base, n_eq, f, errmsg, errmsg_len) &
        bind(C, name='b2b_model_add_residual') result(st)
      import :: c_int, c_ptr
      type(c_ptr), value :: model, eq
      integer(c_int), value :: ldeq, eq_base, n_eq
      type(c_ptr), value :: f, errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_model_add_tangent_dense(model, eq, ldeq, eq_base, n_eq, K, ldk, errmsg, &
                                       errmsg_len) bind(C, name='b2b_model_add_tangent_dense') &
        result(st)
      import :: c_int, c_ptr
      type(c_ptr), value :: model, eq
      integer(c_int), value :: ldeq, eq_base, n_eq
      type(c_ptr), value :: K
      integer(c_int), value :: ldk
      type(c_ptr), value :: errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_model_add_tangent_banded(model, eq, ldeq, eq_base, n_eq, kl, ku, AB, ldab, &
                                        errmsg, errmsg_len) &
        bind(C, name='b2b_model_add_tangent_banded') result(st)
      import :: c_int, c_ptr
      type(c_ptr), value :: model, eq
      integer(c_int), value :: ldeq, eq_base, n_eq, kl, ku
      type(c_ptr), value :: AB
      integer(c_int), value :: ldab
      type(c_ptr), value :: errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_model_tangent_coo(model, eq, ldeq, eq_base, n_eq, nnz, rows, cols, values, &
                                 capacity, errmsg, errmsg_len) &
        bind(C, name='b2b_model_tangent_coo') result(st)
      import :: c_int, c_ptr
      type(c_ptr), value :: model, eq
      integer(c_int), value :: ldeq, eq_base, n_eq
      integer(c_int), intent(inout) :: nnz
      type(c_ptr), value :: rows, cols, values
      integer(c_int), value :: capacity
      type(c_ptr), value :: errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_model_commit(model, errmsg, errmsg_len) bind(C, name='b2b_model_commit') &
        result(st)
      import :: c_int, c_ptr
      type(c_ptr), value :: model, errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_model_revert(model, errmsg, errmsg_len) bind(C, name='b2b_model_revert') &
        result(st)
      import :: c_int, c_ptr
      type(c_ptr), value :: model, errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_model_save_size(model, size, errmsg, errmsg_len) &
        bind(C, name='b2b_model_save_size') result(st)
      import :: c_int, c_ptr, c_int64_t
      type(c_ptr), value :: model
      integer(c_int64_t), intent(inout) :: size
      type(c_ptr), value :: errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_model_save(model, buffer, size, errmsg, errmsg_len) &
        bind(C, name='b2b_model_save') result(st)
      import :: c_int, c_ptr, c_int64_t
      type(c_ptr), value :: model, buffer
      integer(c_int64_t), value :: size
      type(c_ptr), value :: errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_model_restore(model, buffer, size, errmsg, errmsg_len) &
        bind(C, name='b2b_model_restore') result(st)
      import :: c_int, c_ptr, c_int64_t
      type(c_ptr), value :: model, buffer
      integer(c_int64_t), value :: size
      type(c_ptr), value :: errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_model_stats(model, counts, totals, errmsg, errmsg_len) &
        bind(C, name='b2b_model_stats') result(st)
      import :: c_int, c_ptr
      type(c_ptr), value :: model, counts, totals, errmsg
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    ! Distributed models (ABI 1.4)
    function c_model_set_beam_global(model, beam, global_beam, first_segment, start_cut, &
                                     end_cut, errmsg, errmsg_len) &
        bind(C, name='b2b_model_set_beam_global') result(st)
      import :: c_int, c_ptr, c_int64_t
      type(c_ptr), value :: model, errmsg
      integer(c_int), value :: beam, first_segment, start_cut, end_cut, errmsg_len
      integer(c_int64_t), value :: global_beam
      integer(c_int) :: st
    end function

    function c_model_set_ghost_segments(model, beam, first, count, errmsg, errmsg_len) &
        bind(C, name='b2b_model_set_ghost_segments') result(st)
      import :: c_int, c_ptr
      type(c_ptr), value :: model, errmsg
      integer(c_int), value :: beam, first, count, errmsg_len
      integer(c_int) :: st
    end function

    function c_model_get_contact_global(model, k, pair, errmsg, errmsg_len) &
        bind(C, name='b2b_model_get_contact_global') result(st)
      import :: c_int, c_ptr
      type(c_ptr), value :: model, pair, errmsg
      integer(c_int), value :: k, errmsg_len
      integer(c_int) :: st
    end function

    function c_model_migration_count(model, n, errmsg, errmsg_len) &
        bind(C, name='b2b_model_migration_count') result(st)
      import :: c_int, c_ptr
      type(c_ptr), value :: model, errmsg
      integer(c_int), intent(inout) :: n
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_model_migration_info(model, k, target, size, errmsg, errmsg_len) &
        bind(C, name='b2b_model_migration_info') result(st)
      import :: c_int, c_ptr
      type(c_ptr), value :: model, target, size, errmsg
      integer(c_int), value :: k, errmsg_len
      integer(c_int) :: st
    end function

    function c_model_migration_pack(model, k, buffer, size, errmsg, errmsg_len) &
        bind(C, name='b2b_model_migration_pack') result(st)
      import :: c_int, c_ptr, c_int64_t
      type(c_ptr), value :: model, buffer, errmsg
      integer(c_int), value :: k, errmsg_len
      integer(c_int64_t), value :: size
      integer(c_int) :: st
    end function

    function c_model_migration_unpack(model, buffer, size, changed, errmsg, errmsg_len) &
        bind(C, name='b2b_model_migration_unpack') result(st)
      import :: c_int, c_ptr, c_int64_t
      type(c_ptr), value :: model, buffer, errmsg
      integer(c_int64_t), value :: size
      integer(c_int), intent(inout) :: changed
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function
  end interface

end module ftest_capi
