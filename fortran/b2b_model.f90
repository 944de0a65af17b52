!> Submodule model_layer of module b2b (b2b.f90): the bodies of
!> the contact model (type(b2b_model)).
!> The interfaces and documentation of its public procedures are in
!> b2b.f90; this file holds their bodies (module procedure) and the
!> bind(C) interfaces of the C functions they call.
submodule (b2b) model_layer
  implicit none

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

    function c_b2b_model_set_beam_global(model, beam, global_beam, first_segment, start_cut, &
                                         end_cut, errmsg, errmsg_len) &
        bind(C, name='b2b_model_set_beam_global') result(st)
      import :: c_int, c_ptr, c_char, c_int64_t
      type(c_ptr), value :: model
      integer(c_int), value :: beam, first_segment, start_cut, end_cut
      integer(c_int64_t), value :: global_beam
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_set_ghost_segments(model, beam, first, count, errmsg, errmsg_len) &
        bind(C, name='b2b_model_set_ghost_segments') result(st)
      import :: c_int, c_ptr, c_char
      type(c_ptr), value :: model
      integer(c_int), value :: beam, first, count
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_get_contact_global(model, k, pair, errmsg, errmsg_len) &
        bind(C, name='b2b_model_get_contact_global') result(st)
      import :: c_int, c_ptr, c_char, c_int64_t
      type(c_ptr), value :: model
      integer(c_int), value :: k
      integer(c_int64_t), intent(inout) :: pair(*)
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_migration_count(model, n, errmsg, errmsg_len) &
        bind(C, name='b2b_model_migration_count') result(st)
      import :: c_int, c_ptr, c_char
      type(c_ptr), value :: model
      integer(c_int), intent(inout) :: n
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_migration_info(model, k, target, size, errmsg, errmsg_len) &
        bind(C, name='b2b_model_migration_info') result(st)
      import :: c_int, c_ptr, c_char
      type(c_ptr), value :: model, target, size
      integer(c_int), value :: k
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_migration_pack(model, k, buffer, size, errmsg, errmsg_len) &
        bind(C, name='b2b_model_migration_pack') result(st)
      import :: c_int, c_ptr, c_char, c_int64_t, c_int8_t
      type(c_ptr), value :: model
      integer(c_int), value :: k
      integer(c_int8_t), intent(inout) :: buffer(*)
      integer(c_int64_t), value :: size
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_migration_unpack(model, buffer, size, changed, errmsg, errmsg_len) &
        bind(C, name='b2b_model_migration_unpack') result(st)
      import :: c_int, c_ptr, c_char, c_int64_t
      type(c_ptr), value :: model, buffer
      integer(c_int64_t), value :: size
      integer(c_int), intent(inout) :: changed
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
    function c_b2b_model_update_xu(model, x, ldx, u, ldu, n_cols, want_tangent, errmsg, &
                                   errmsg_len) bind(C, name='b2b_model_update_xu') result(st)
      import :: c_int, c_ptr, c_char, c_double
      type(c_ptr), value :: model
      real(c_double), intent(in) :: x(*), u(*)
      integer(c_int), value :: ldx, ldu, n_cols, want_tangent
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_add_residual_scaled(model, eq, ldeq, eq_base, n_eq, scale, f, errmsg, &
                                             errmsg_len) &
        bind(C, name='b2b_model_add_residual_scaled') result(st)
      import :: c_int, c_ptr, c_char, c_double
      type(c_ptr), value :: model
      integer(c_int), intent(in) :: eq(*)
      integer(c_int), value :: ldeq, eq_base, n_eq
      real(c_double), value :: scale
      real(c_double), intent(inout) :: f(*)
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_add_tangent_dense_scaled(model, eq, ldeq, eq_base, n_eq, scale, K, ldk, &
                                                  errmsg, errmsg_len) &
        bind(C, name='b2b_model_add_tangent_dense_scaled') result(st)
      import :: c_int, c_ptr, c_char, c_double
      type(c_ptr), value :: model
      integer(c_int), intent(in) :: eq(*)
      integer(c_int), value :: ldeq, eq_base, n_eq
      real(c_double), value :: scale
      real(c_double), intent(inout) :: K(*)
      integer(c_int), value :: ldk
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_add_tangent_banded_scaled(model, eq, ldeq, eq_base, n_eq, kl, ku, &
                                                   scale, AB, ldab, errmsg, errmsg_len) &
        bind(C, name='b2b_model_add_tangent_banded_scaled') result(st)
      import :: c_int, c_ptr, c_char, c_double
      type(c_ptr), value :: model
      integer(c_int), intent(in) :: eq(*)
      integer(c_int), value :: ldeq, eq_base, n_eq, kl, ku
      real(c_double), value :: scale
      real(c_double), intent(inout) :: AB(*)
      integer(c_int), value :: ldab
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_tangent_profile(model, eq, ldeq, eq_base, n_eq, heights, kl, ku, &
                                         errmsg, errmsg_len) &
        bind(C, name='b2b_model_tangent_profile') result(st)
      import :: c_int, c_ptr, c_char
      type(c_ptr), value :: model
      integer(c_int), intent(in) :: eq(*)
      integer(c_int), value :: ldeq, eq_base, n_eq
      integer(c_int), intent(inout) :: heights(*)
      integer(c_int), intent(inout) :: kl, ku
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_add_tangent_profile(model, eq, ldeq, eq_base, n_eq, scale, jp, ad, au, &
                                             al, errmsg, errmsg_len) &
        bind(C, name='b2b_model_add_tangent_profile') result(st)
      import :: c_int, c_ptr, c_char, c_double
      type(c_ptr), value :: model
      integer(c_int), intent(in) :: eq(*)
      integer(c_int), value :: ldeq, eq_base, n_eq
      real(c_double), value :: scale
      integer(c_int), intent(in) :: jp(*)
      real(c_double), intent(inout) :: ad(*), au(*)
      type(c_ptr), value :: al
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function

    function c_b2b_model_add_constrained_product(model, eq, ldeq, eq_base, n_eq, du, ldu, &
                                                 n_cols, scale, f, errmsg, errmsg_len) &
        bind(C, name='b2b_model_add_constrained_product') result(st)
      import :: c_int, c_ptr, c_char, c_double
      type(c_ptr), value :: model
      integer(c_int), intent(in) :: eq(*)
      integer(c_int), value :: ldeq, eq_base, n_eq
      real(c_double), intent(in) :: du(*)
      integer(c_int), value :: ldu, n_cols
      real(c_double), value :: scale
      real(c_double), intent(inout) :: f(*)
      character(kind=c_char), intent(inout) :: errmsg(*)
      integer(c_int), value :: errmsg_len
      integer(c_int) :: st
    end function
  end interface

contains

  module procedure b2b_model_create
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
  end procedure

  module procedure b2b_model_destroy
    integer(c_int) :: st
    st = c_b2b_model_destroy(model%ptr)
    model%ptr = c_null_ptr
    call finish('b2b_model_destroy', st, blank_message(), ierr, errmsg)
  end procedure

  module procedure b2b_model_add_beam
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
  end procedure

  module procedure b2b_model_set_group_pair
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
  end procedure

  module procedure b2b_model_set_self_contact
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
  end procedure

  module procedure b2b_model_set_real
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    buf = c_null_char
    st = c_b2b_model_set_real(model%ptr, trim(key) // c_null_char, value, buf, int(size(buf), c_int))
    call finish('b2b_model_set_real', st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_model_set_int
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
  end procedure

  module procedure b2b_model_finalize
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
  end procedure

  module procedure b2b_model_update
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
  end procedure

  module procedure b2b_model_contact_count
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st, cn
    buf = c_null_char
    cn = 0
    st = c_b2b_model_contact_count(model%ptr, cn, buf, int(size(buf), c_int))
    if (st == B2B_OK) n = int(cn)
    call finish('b2b_model_contact_count', st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_model_get_contact
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
  end procedure

  module procedure b2b_model_add_residual
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
  end procedure

  module procedure b2b_model_add_tangent_dense
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
  end procedure

  module procedure b2b_model_add_tangent_banded
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
  end procedure

  module procedure b2b_model_tangent_coo
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
  end procedure

  module procedure b2b_model_commit
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    buf = c_null_char
    st = c_b2b_model_commit(model%ptr, buf, int(size(buf), c_int))
    call finish('b2b_model_commit', st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_model_revert
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    buf = c_null_char
    st = c_b2b_model_revert(model%ptr, buf, int(size(buf), c_int))
    call finish('b2b_model_revert', st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_model_save_size
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    integer(c_int64_t) :: n
    buf = c_null_char
    n = 0
    st = c_b2b_model_save_size(model%ptr, n, buf, int(size(buf), c_int))
    if (st == B2B_OK) nbytes = n
    call finish('b2b_model_save_size', st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_model_save
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
  end procedure

  module procedure b2b_model_restore
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
  end procedure

  module procedure b2b_model_set_beam_global
    character(len=*), parameter :: me = 'b2b_model_set_beam_global'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    logical :: ok
    call check_ints(me, [character(len=13) :: 'beam', 'first_segment'], [beam, first_segment], ok, &
                    ierr, errmsg)
    if (.not. ok) return
    buf = c_null_char
    st = c_b2b_model_set_beam_global(model%ptr, int(beam - 1, c_int), global_beam - 1_c_int64_t, &
                                     int(first_segment - 1, c_int), c_flag(start_cut), &
                                     c_flag(end_cut), buf, int(size(buf), c_int))
    call finish(me, st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_model_set_ghost_segments
    character(len=*), parameter :: me = 'b2b_model_set_ghost_segments'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    logical :: ok
    call check_ints(me, [character(len=5) :: 'beam', 'first', 'count'], [beam, first, count], ok, &
                    ierr, errmsg)
    if (.not. ok) return
    buf = c_null_char
    st = c_b2b_model_set_ghost_segments(model%ptr, int(beam - 1, c_int), int(first - 1, c_int), &
                                        int(count, c_int), buf, int(size(buf), c_int))
    call finish(me, st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_model_get_contact_global
    character(len=*), parameter :: me = 'b2b_model_get_contact_global'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    integer(c_int64_t) :: cpair(4)
    logical :: ok
    call check_ints(me, [character(len=1) :: 'k'], [k], ok, ierr, errmsg)
    if (.not. ok) return
    if (.not. shape_is(shape(pair), [4])) then
      call finish_size(me, 'pair', shape(pair), [4], ierr, errmsg)
      return
    end if
    buf = c_null_char
    st = c_b2b_model_get_contact_global(model%ptr, int(k - 1, c_int), cpair, buf, &
                                        int(size(buf), c_int))
    if (st == B2B_OK) pair = cpair + 1_c_int64_t
    call finish(me, st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_model_migration_count
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st, cn
    buf = c_null_char
    cn = 0
    st = c_b2b_model_migration_count(model%ptr, cn, buf, int(size(buf), c_int))
    if (st == B2B_OK) n = int(cn)
    call finish('b2b_model_migration_count', st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_model_migration_info
    character(len=*), parameter :: me = 'b2b_model_migration_info'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    integer(c_int64_t), target :: ctarget(4), csize
    type(c_ptr) :: pt, ps
    logical :: ok
    call check_ints(me, [character(len=1) :: 'k'], [k], ok, ierr, errmsg)
    if (.not. ok) return
    pt = c_null_ptr
    ps = c_null_ptr
    if (present(target)) then
      if (.not. shape_is(shape(target), [4])) then
        call finish_size(me, 'target', shape(target), [4], ierr, errmsg)
        return
      end if
      pt = c_loc(ctarget)
    end if
    if (present(nbytes)) ps = c_loc(csize)
    buf = c_null_char
    st = c_b2b_model_migration_info(model%ptr, int(k - 1, c_int), pt, ps, buf, &
                                    int(size(buf), c_int))
    if (st == B2B_OK .and. present(target)) target = ctarget + 1_c_int64_t
    if (st == B2B_OK .and. present(nbytes)) nbytes = csize
    call finish(me, st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_model_migration_pack
    character(len=*), parameter :: me = 'b2b_model_migration_pack'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    integer(c_int8_t) :: dummy(1)
    logical :: ok
    call check_ints(me, [character(len=1) :: 'k'], [k], ok, ierr, errmsg)
    if (.not. ok) return
    buf = c_null_char
    if (size(buffer) > 0) then
      st = c_b2b_model_migration_pack(model%ptr, int(k - 1, c_int), buffer, &
                                      int(size(buffer), c_int64_t), buf, int(size(buf), c_int))
    else
      st = c_b2b_model_migration_pack(model%ptr, int(k - 1, c_int), dummy, 0_c_int64_t, buf, &
                                      int(size(buf), c_int))
    end if
    call finish(me, st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_model_migration_unpack
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st, ch
    integer(c_int8_t), target :: dummy(1)
    buf = c_null_char
    ch = 0
    if (.not. present(buffer)) then
      st = c_b2b_model_migration_unpack(model%ptr, c_null_ptr, 0_c_int64_t, ch, buf, &
                                        int(size(buf), c_int))
    else if (size(buffer) > 0) then
      st = c_b2b_model_migration_unpack(model%ptr, c_loc(buffer), int(size(buffer), c_int64_t), &
                                        ch, buf, int(size(buf), c_int))
    else
      dummy = 0
      st = c_b2b_model_migration_unpack(model%ptr, c_loc(dummy), 0_c_int64_t, ch, buf, &
                                        int(size(buf), c_int))
    end if
    if (st == B2B_OK) changed = ch /= 0
    call finish('b2b_model_migration_unpack', st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_model_stats
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
  end procedure

  module procedure b2b_model_audit
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
  end procedure

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

  module procedure b2b_model_update_xu
    character(len=*), parameter :: me = 'b2b_model_update_xu'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st, want
    real(c_double) :: dummy(3)
    logical :: ok
    call check_ints(me, [character(len=9) :: 'size(x,1)', 'size(x,2)', 'size(u,1)', &
                    'size(u,2)'], [size(x, 1), size(x, 2), size(u, 1), size(u, 2)], ok, ierr, &
                    errmsg)
    if (.not. ok) return
    want = 1
    if (present(want_tangent)) want = c_flag(want_tangent)
    buf = c_null_char
    ! one column count for both: the smaller (the library wants n_nodes of each)
    if (size(x) > 0 .and. size(u) > 0) then
      st = c_b2b_model_update_xu(model%ptr, x, int(size(x, 1), c_int), u, &
                                 int(size(u, 1), c_int), int(min(size(x, 2), size(u, 2)), c_int), &
                                 want, buf, int(size(buf), c_int))
    else
      dummy = 0
      st = c_b2b_model_update_xu(model%ptr, dummy, int(max(size(x, 1), 0), c_int), dummy, &
                                 int(max(size(u, 1), 0), c_int), 0_c_int, want, buf, &
                                 int(size(buf), c_int))
    end if
    call finish(me, st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_model_add_residual_scaled
    character(len=*), parameter :: me = 'b2b_model_add_residual_scaled'
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
      st = c_b2b_model_add_residual_scaled(model%ptr, ceq, int(size(eq, 1), c_int), 1_c_int, &
                                           int(size(f), c_int), scale, f, buf, &
                                           int(size(buf), c_int))
    else
      st = c_b2b_model_add_residual_scaled(model%ptr, ceq, int(size(eq, 1), c_int), 1_c_int, &
                                           0_c_int, scale, dummy, buf, int(size(buf), c_int))
    end if
    call finish(me, st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_model_add_tangent_dense_scaled
    character(len=*), parameter :: me = 'b2b_model_add_tangent_dense_scaled'
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
    st = c_b2b_model_add_tangent_dense_scaled(model%ptr, ceq, int(size(eq, 1), c_int), 1_c_int, &
                                              int(size(K, 2), c_int), scale, K, &
                                              int(size(K, 1), c_int), buf, int(size(buf), c_int))
    call finish(me, st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_model_add_tangent_banded_scaled
    character(len=*), parameter :: me = 'b2b_model_add_tangent_banded_scaled'
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
    st = c_b2b_model_add_tangent_banded_scaled(model%ptr, ceq, int(size(eq, 1), c_int), &
                                               1_c_int, int(size(AB, 2), c_int), &
                                               int(kl, c_int), int(ku, c_int), scale, AB, &
                                               int(size(AB, 1), c_int), buf, &
                                               int(size(buf), c_int))
    call finish(me, st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_model_tangent_profile
    character(len=*), parameter :: me = 'b2b_model_tangent_profile'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st, ckl, cku
    integer(c_int), allocatable :: ceq(:, :), ch(:)
    logical :: ok
    call check_equations(me, model, eq, ok, ierr, errmsg)
    if (.not. ok) return
    call check_ints(me, [character(len=13) :: 'size(heights)'], [size(heights)], ok, ierr, &
                    errmsg)
    if (.not. ok) return
    call c_equations(eq, ceq)
    allocate (ch(max(size(heights), 1)))
    ch = 0
    ckl = 0
    cku = 0
    buf = c_null_char
    st = c_b2b_model_tangent_profile(model%ptr, ceq, int(size(eq, 1), c_int), 1_c_int, &
                                     int(size(heights), c_int), ch, ckl, cku, buf, &
                                     int(size(buf), c_int))
    if (st == B2B_OK) then
      heights = int(ch(1:size(heights)))
      if (present(kl)) kl = int(ckl)
      if (present(ku)) ku = int(cku)
    end if
    call finish(me, st, buf, ierr, errmsg)
  end procedure

  module procedure b2b_model_add_tangent_profile
    character(len=*), parameter :: me = 'b2b_model_add_tangent_profile'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    integer(c_int), allocatable :: ceq(:, :), cjp(:)
    real(c_double), target :: dummy(1)
    type(c_ptr) :: pal
    integer :: need
    logical :: ok
    call check_equations(me, model, eq, ok, ierr, errmsg)
    if (.not. ok) return
    call check_ints(me, [character(len=8) :: 'size(ad)'], [size(ad)], ok, ierr, errmsg)
    if (.not. ok) return
    call check_int_array(me, 'jp', jp, ok, ierr, errmsg)
    if (.not. ok) return
    if (size(jp) /= size(ad)) then
      call finish_size(me, 'jp', shape(jp), shape(ad), ierr, errmsg)
      return
    end if
    ! The library cannot see the lengths of au and al: the pointer of the
    ! last equation is how many it may touch (a bad jp is its to report).
    need = 0
    if (size(jp) > 0) need = jp(size(jp))
    if (size(au) < need) then
      call finish_text(me, int(B2B_ERR_SIZE, c_int), me // ': au has ' // &
                       trim(int_text(size(au))) // ' entries, the profile jp(n_eq) = ' // &
                       trim(int_text(need)), ierr, errmsg)
      return
    end if
    if (present(al)) then
      if (size(al) < need) then
        call finish_text(me, int(B2B_ERR_SIZE, c_int), me // ': al has ' // &
                         trim(int_text(size(al))) // ' entries, the profile jp(n_eq) = ' // &
                         trim(int_text(need)), ierr, errmsg)
        return
      end if
    end if
    call c_equations(eq, ceq)
    allocate (cjp(max(size(jp), 1)))
    cjp = 0
    cjp(1:size(jp)) = int(jp, c_int)
    buf = c_null_char
    if (size(ad) == 0) then
      st = c_b2b_model_add_tangent_profile(model%ptr, ceq, int(size(eq, 1), c_int), 1_c_int, &
                                           0_c_int, scale, cjp, dummy, dummy, c_null_ptr, buf, &
                                           int(size(buf), c_int))
    else
      ! absent al: NULL (no lower triangle); al of no entries (a diagonal
      ! profile) still needs an address
      pal = c_null_ptr
      if (present(al)) then
        pal = c_loc(dummy)
        if (size(al) > 0) pal = c_loc(al)
      end if
      st = add_profile(pal)
    end if
    call finish(me, st, buf, ierr, errmsg)

  contains

    integer(c_int) function add_profile(pal_address)
      type(c_ptr), intent(in) :: pal_address
      if (size(au) > 0) then
        add_profile = c_b2b_model_add_tangent_profile(model%ptr, ceq, int(size(eq, 1), c_int), &
                                                      1_c_int, int(size(ad), c_int), scale, &
                                                      cjp, ad, au, pal_address, buf, &
                                                      int(size(buf), c_int))
      else
        add_profile = c_b2b_model_add_tangent_profile(model%ptr, ceq, int(size(eq, 1), c_int), &
                                                      1_c_int, int(size(ad), c_int), scale, &
                                                      cjp, ad, dummy, pal_address, buf, &
                                                      int(size(buf), c_int))
      end if
    end function

  end procedure

  module procedure b2b_model_add_constrained_product
    character(len=*), parameter :: me = 'b2b_model_add_constrained_product'
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer(c_int) :: st
    integer(c_int), allocatable :: ceq(:, :)
    real(c_double) :: dummy(3)
    logical :: ok
    call check_equations(me, model, eq, ok, ierr, errmsg)
    if (.not. ok) return
    call check_ints(me, [character(len=10) :: 'size(f)', 'size(du,1)', 'size(du,2)'], &
                    [size(f), size(du, 1), size(du, 2)], ok, ierr, errmsg)
    if (.not. ok) return
    call c_equations(eq, ceq)
    buf = c_null_char
    dummy = 0
    if (size(du) > 0 .and. size(f) > 0) then
      st = c_b2b_model_add_constrained_product(model%ptr, ceq, int(size(eq, 1), c_int), &
                                               1_c_int, int(size(f), c_int), du, &
                                               int(size(du, 1), c_int), int(size(du, 2), c_int), &
                                               scale, f, buf, int(size(buf), c_int))
    else if (size(du) > 0) then
      st = c_b2b_model_add_constrained_product(model%ptr, ceq, int(size(eq, 1), c_int), &
                                               1_c_int, 0_c_int, du, int(size(du, 1), c_int), &
                                               int(size(du, 2), c_int), scale, dummy, buf, &
                                               int(size(buf), c_int))
    else
      st = c_b2b_model_add_constrained_product(model%ptr, ceq, int(size(eq, 1), c_int), &
                                               1_c_int, int(size(f), c_int), dummy, &
                                               int(max(size(du, 1), 0), c_int), 0_c_int, &
                                               scale, dummy, buf, int(size(buf), c_int))
    end if
    call finish(me, st, buf, ierr, errmsg)
  end procedure

end submodule model_layer
