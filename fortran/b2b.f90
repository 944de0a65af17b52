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
!>              b2b_pair_eval (with Coulomb friction), b2b_pair_eval_ends
!>              (end contact), b2b_pair_history_handover; line contact:
!>              b2b_pair_eval_line, b2b_pair_line_points
!>  * model:    type(b2b_model) with b2b_model_create, _destroy, _add_beam,
!>              _set_group_pair, _set_self_contact, _set_real, _set_int,
!>              _finalize, _update, _contact_count, _get_contact, _add_residual,
!>              _add_tangent_dense, _add_tangent_banded, _tangent_coo, _commit,
!>              _revert, _save_size, _save, _restore, _stats
!>              and the interpenetration audit b2b_model_audit;
!>              for a host's solver (b2b_model.h, Assembly, Sparsity,
!>              Prescribed dofs; doc/host-integration.md): _update_xu,
!>              _add_residual_scaled, _add_tangent_dense_scaled,
!>              _add_tangent_banded_scaled, _tangent_profile,
!>              _add_tangent_profile, _add_constrained_product;
!>              distributed models (doc/distributed.md): _set_beam_global,
!>              _set_ghost_segments, _get_contact_global, _migration_count,
!>              _migration_info, _migration_pack, _migration_unpack
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
!>
!> Source layout. One module, b2b, whose procedure bodies live in Fortran 2008
!> submodules by layer, so that `use b2b` is all a caller needs and the
!> library's symbols are those of module b2b (gfortran: __b2b_MOD_<name>)
!> wherever a body is:
!>  * b2b.f90          module b2b: the types, the interface and documentation
!>                     of every procedure (the private helpers' too)
!>  * b2b_curve.f90    submodule curve_layer: core and curve bodies
!>  * b2b_pair.f90     submodule pair_layer: contact parameters and element
!>  * b2b_pair_line.f90 submodule line_layer: the line-contact element
!>  * b2b_model.f90    submodule model_layer: contact model
!>  * b2b_support.f90  submodule support_layer: the private helpers all
!>                     layers share (status and message handling, integer
!>                     and shape checks)
!> Each submodule also holds the bind(C) interfaces of the C functions it
!> calls. A new procedure: its interface with its documentation here, in its
!> layer's interface block; its body (module procedure) and its bind(C)
!> interface in its layer's file. The helpers are separate module procedures
!> too (not contained in b2b), because gfortran gives a private procedure
!> contained in a module internal linkage, which the submodules could not
!> reach. Compile b2b.f90 first, then the submodules (any order).
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
  public :: b2b_pair_eval_line, b2b_pair_line_points
  public :: b2b_model_create, b2b_model_destroy, b2b_model_add_beam, b2b_model_set_group_pair
  public :: b2b_model_set_self_contact, b2b_model_set_real, b2b_model_set_int
  public :: b2b_model_finalize, b2b_model_update, b2b_model_contact_count
  public :: b2b_model_get_contact, b2b_model_add_residual, b2b_model_add_tangent_dense
  public :: b2b_model_add_tangent_banded, b2b_model_tangent_coo, b2b_model_commit
  public :: b2b_model_revert, b2b_model_save_size, b2b_model_save, b2b_model_restore
  public :: b2b_model_stats
  public :: b2b_model_audit
  public :: b2b_model_update_xu, b2b_model_add_residual_scaled
  public :: b2b_model_add_tangent_dense_scaled, b2b_model_add_tangent_banded_scaled
  public :: b2b_model_tangent_profile, b2b_model_add_tangent_profile
  public :: b2b_model_add_constrained_product
  public :: b2b_model_set_beam_global, b2b_model_set_ghost_segments
  public :: b2b_model_get_contact_global, b2b_model_migration_count
  public :: b2b_model_migration_info, b2b_model_migration_pack, b2b_model_migration_unpack

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

  ! ---------------------------------------------- core and curve
  ! Bodies: submodule curve_layer (b2b_curve.f90).
  interface
    !> English name of a status code (never empty; "unknown status" for a code
    !> the library does not know, also one beyond C's int range).
    module function b2b_strerror(status) result(msg)
      integer, intent(in) :: status
      character(len=:), allocatable :: msg
    end function

    !> Run-time release version of the library.
    module subroutine b2b_version(major, minor, patch, ierr, errmsg)
      integer, intent(out) :: major, minor, patch
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Run-time ABI version: the N of libb2b.so.N.
    module subroutine b2b_abi_version(abi, ierr, errmsg)
      integer, intent(out) :: abi
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
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
    module subroutine b2b_segment_eval(kind, start_rule, end_rule, patch, xi, x, dx, d2x, &
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
    end subroutine

    !> Number of segments of a beam of n_nodes nodes (closed = .true.: a ring).
    module subroutine b2b_beam_segment_count(kind, n_nodes, closed, n_segments, ierr, errmsg)
      integer, intent(in) :: kind, n_nodes
      logical, intent(in) :: closed
      integer, intent(inout) :: n_segments
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> The patch of segment `segment` (1-based) of a beam: nodes(k) is the beam
    !> node (1-based) in patch slot k, 0 where the slot is missing or unused;
    !> start_rule, end_rule are B2B_END_REFLECT at beam ends, else
    !> B2B_END_NEIGHBOUR.
    module subroutine b2b_beam_segment_patch(kind, n_nodes, closed, segment, nodes, start_rule, &
                                      end_rule, ierr, errmsg)
      integer, intent(in) :: kind, n_nodes, segment
      logical, intent(in) :: closed
      integer, intent(inout), contiguous :: nodes(:)
      integer, intent(inout) :: start_rule, end_rule
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine
  end interface

  ! ------------------------------ contact parameters and element
  ! Bodies: submodule pair_layer (b2b_pair.f90).
  interface
    !> Creates a parameter handle holding the defaults (the keys are listed in
    !> the C header b2b_pair.h). params must be null (never created, or
    !> destroyed): creating over a live handle would lose it, so that is
    !> B2B_ERR_STATE and params is left as it is.
    module subroutine b2b_params_create(params, ierr, errmsg)
      type(b2b_params), intent(inout) :: params
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Frees the handle and nulls it. A null handle (never created, or already
    !> destroyed) is a no-op, so destroying twice is safe. Never fails.
    module subroutine b2b_params_destroy(params, ierr, errmsg)
      type(b2b_params), intent(inout) :: params
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Sets the real option key (trailing blanks ignored), before finalize.
    module subroutine b2b_params_set_real(params, key, value, ierr, errmsg)
      type(b2b_params), intent(inout) :: params
      character(len=*), intent(in) :: key
      real(c_double), intent(in) :: value
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Sets the integer option key (trailing blanks ignored), before finalize.
    module subroutine b2b_params_set_int(params, key, value, ierr, errmsg)
      type(b2b_params), intent(inout) :: params
      character(len=*), intent(in) :: key
      integer, intent(in) :: value
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> The value of the real option key (its default if it was never set).
    module subroutine b2b_params_get_real(params, key, value, ierr, errmsg)
      type(b2b_params), intent(in) :: params
      character(len=*), intent(in) :: key
      real(c_double), intent(inout) :: value
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> The value of the integer option key (its default if it was never set).
    module subroutine b2b_params_get_int(params, key, value, ierr, errmsg)
      type(b2b_params), intent(in) :: params
      character(len=*), intent(in) :: key
      integer, intent(inout) :: value
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Checks the options together and makes the handle read-only (setting an
    !> option afterwards is B2B_ERR_STATE). Finalizing twice is allowed.
    module subroutine b2b_params_finalize(params, ierr, errmsg)
      type(b2b_params), intent(inout) :: params
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> n: the length of a pair history (hist_old, hist_new of b2b_pair_eval) for
    !> this finalized parameter set.
    module subroutine b2b_params_history_size(params, n, ierr, errmsg)
      type(b2b_params), intent(in) :: params
      integer, intent(inout) :: n
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
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
    module subroutine b2b_pair_eval(params, segments, X, radii, hist_old, hist_new, &
                                    contact_status, info, residual, tangent, end_tangents, &
                                    ierr, errmsg)
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
    end subroutine

    !> b2b_pair_eval with parameters held at segment ends (End contact in the
    !> C header b2b_pair.h: node-to-segment and node-to-node contact).
    !>   ends(2)              A's, then B's: -1 (the segment's start node), +1
    !>                        (its end node) or 0 (free); anything else is
    !>                        B2B_ERR_RANGE. The other arguments as b2b_pair_eval;
    !>                        info(B2B_IX_INFO_END_A), info(B2B_IX_INFO_END_B)
    !>                        echo ends.
    module subroutine b2b_pair_eval_ends(params, segments, X, radii, ends, hist_old, hist_new, &
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
    end subroutine

    !> The line-contact element (Line contact in the C header b2b_pair.h;
    !> doc/line-contact.md): n_points Gauss points along segment A, each
    !> projected onto B, a normal law per unit length ("line_penalty"),
    !> friction per point; with "contact_type" B2B_CONTACT_TYPE_ALL_ANGLE
    !> blended with the point element by the crossing angle.
    !>   params, segments, X, radii, end_tangents   as b2b_pair_eval
    !>   n_points             1 .. B2B_LINE_POINTS_MAX (b2b_pair_line_points
    !>                        gives the default)
    !>   hist_old(:), hist_new(:)  (n_points + 1) * b2b_params_history_size
    !>                        doubles each, distinct arrays (the point
    !>                        element's history, then each point's)
    !>   contact_status       B2B_CONTACT_* of the pair
    !>   line_info(16)        index it with B2B_LINE_INFO_* + 1
    !>   residual(24), tangent(ldk,24)  as b2b_pair_eval
    !>   point_info(32,n_points)  each integration point's info (per unit
    !>                        length), optional
    module subroutine b2b_pair_eval_line(params, segments, X, radii, n_points, hist_old, &
                                         hist_new, contact_status, line_info, residual, tangent, &
                                         point_info, end_tangents, ierr, errmsg)
      type(b2b_params), intent(in) :: params
      integer, intent(in), contiguous :: segments(:, :)
      real(c_double), intent(in), contiguous :: X(:, :)
      real(c_double), intent(in), contiguous :: radii(:)
      integer, intent(in) :: n_points
      real(c_double), intent(in), contiguous, target :: hist_old(:)
      real(c_double), intent(inout), contiguous, target :: hist_new(:)
      integer, intent(inout) :: contact_status
      real(c_double), intent(inout), contiguous :: line_info(:)
      real(c_double), intent(inout), contiguous :: residual(:)
      real(c_double), intent(inout), contiguous, target, optional :: tangent(:, :)
      real(c_double), intent(inout), contiguous, target, optional :: point_info(:, :)
      real(c_double), intent(in), contiguous, target, optional :: end_tangents(:, :)
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Integration points of a segment of chord length `length` between
    !> beams of radii radius_a, radius_b: "line_points" if set, else the
    !> default rule (b2b_pair_line_points in b2b_pair.h).
    module subroutine b2b_pair_line_points(params, length, radius_a, radius_b, n_points, ierr, &
                                           errmsg)
      type(b2b_params), intent(in) :: params
      real(c_double), intent(in) :: length, radius_a, radius_b
      integer, intent(inout) :: n_points
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
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
    module subroutine b2b_pair_history_handover(params, beam, direction, from_segment, from_X, &
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
    end subroutine
  end interface

  ! ----------------------------------------------- contact model
  ! Bodies: submodule model_layer (b2b_model.f90).
  interface
    !> Creates a contact model (b2b_model in C; the contract is in the C header
    !> b2b_model.h). Its messages speak Fortran numbers (1-based beams, nodes,
    !> segments, contacts). model must be null (never created, or destroyed).
    module subroutine b2b_model_create(model, ierr, errmsg)
      type(b2b_model), intent(inout) :: model
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Frees the model and nulls the handle; a null handle is a no-op.
    module subroutine b2b_model_destroy(model, ierr, errmsg)
      type(b2b_model), intent(inout) :: model
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Adds a beam: nodes(:) the host's node numbers (1-based) along it, closed
    !> .true. for a ring (do not repeat the first node), radius > 0, kind
    !> B2B_CURVE_*, group >= 0 (the host's contact group). beam: its number (1, 2, ...).
    !> Groups are labels, passed to the library as given (not shifted like
    !> beams, nodes and segments): no array is indexed by them, any integer
    !> >= 0 will do, and messages print them as given. Number them from 1
    !> like everything else in Fortran (groups 1 and 2, and
    !> b2b_model_set_group_pair(model, 1, 2, ...)); 0 is a group too.
    module subroutine b2b_model_add_beam(model, nodes, closed, radius, kind, group, beam, ierr, &
                                         errmsg)
      type(b2b_model), intent(inout) :: model
      integer, intent(in) :: nodes(:)
      logical, intent(in) :: closed
      real(c_double), intent(in) :: radius
      integer, intent(in) :: kind, group
      integer, intent(inout) :: beam
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Groups ga and gb (host group numbers, either order; ga = gb for beams of
    !> one group) touch with the finalized parameter set params (copied).
    module subroutine b2b_model_set_group_pair(model, ga, gb, params, ierr, errmsg)
      type(b2b_model), intent(inout) :: model
      integer, intent(in) :: ga, gb
      type(b2b_params), intent(in) :: params
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Self-contact of beam (1-based) on or off; exclusion_length (optional,
    !> default 4 r): arc length within which its own segments are not paired.
    module subroutine b2b_model_set_self_contact(model, beam, on, exclusion_length, ierr, errmsg)
      type(b2b_model), intent(inout) :: model
      integer, intent(in) :: beam
      logical, intent(in) :: on
      real(c_double), intent(in), optional :: exclusion_length
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Sets a real option of the model ("search_margin").
    module subroutine b2b_model_set_real(model, key, value, ierr, errmsg)
      type(b2b_model), intent(inout) :: model
      character(len=*), intent(in) :: key
      real(c_double), intent(in) :: value
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Sets an integer option of the model ("threads", "max_handover_hops",
    !> "message_base", "max_candidates"; b2b_model.h).
    module subroutine b2b_model_set_int(model, key, value, ierr, errmsg)
      type(b2b_model), intent(inout) :: model
      character(len=*), intent(in) :: key
      integer, intent(in) :: value
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Builds the segment tables; the host has n_nodes nodes (numbers 1 .. n_nodes).
    module subroutine b2b_model_finalize(model, n_nodes, ierr, errmsg)
      type(b2b_model), intent(inout) :: model
      integer, intent(in) :: n_nodes
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> One Newton iteration: x(ldx, n) the current coordinates of the host's
    !> nodes (rows 1..3: x, y, z; ldx = size(x, 1) >= 3), n = size(x, 2) >=
    !> n_nodes. want_tangent (default .true.): .false. skips the tangents.
    !> Current, not reference: FEAP's x(ndm, numnp) is the reference geometry;
    !> a host that keeps x and u(ndf, numnp) apart calls b2b_model_update_xu.
    module subroutine b2b_model_update(model, x, want_tangent, ierr, errmsg)
      type(b2b_model), intent(inout) :: model
      real(c_double), intent(in), contiguous :: x(:, :)
      logical, intent(in), optional :: want_tangent
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> The number of active contacts of the last update.
    module subroutine b2b_model_contact_count(model, n, ierr, errmsg)
      type(b2b_model), intent(in) :: model
      integer, intent(inout) :: n
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Contact k (1 .. count) of the last update; every output is optional:
    !>   nodes(8)        host nodes (1-based) of A's patch slots, then B's; 0: no node
    !>   pair(4)         beam A, segment A, beam B, segment B (1-based)
    !>   info(32)        as b2b_pair_eval: index it with B2B_IX_INFO_*
    !>   residual(24)    the element residual on the 24 coordinates of nodes
    !>   tangent(ldk,24) its tangent (ldk >= 24), if the update computed one
    module subroutine b2b_model_get_contact(model, k, nodes, pair, info, residual, tangent, &
                                            ierr, errmsg)
      type(b2b_model), intent(in) :: model
      integer, intent(in) :: k
      integer, intent(inout), optional :: nodes(:), pair(:)
      real(c_double), intent(inout), contiguous, target, optional :: info(:), residual(:)
      real(c_double), intent(inout), contiguous, target, optional :: tangent(:, :)
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> f(e) += the contacts' residuals, through eq(ldeq, n_nodes) (ldeq >= 3):
    !> the host's equation numbers of node k's x, y, z dofs in eq(1:3, k), 1-based,
    !> <= 0 for a constrained dof (a FEAP-style id(ndf, numnp) works as is);
    !> n_eq = size(f).
    module subroutine b2b_model_add_residual(model, eq, f, ierr, errmsg)
      type(b2b_model), intent(in) :: model
      integer, intent(in) :: eq(:, :)
      real(c_double), intent(inout), contiguous :: f(:)
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> K(e_r, e_c) += the contacts' tangents (a dense matrix; n_eq = size(K, 2),
    !> size(K, 1) >= n_eq); eq as for b2b_model_add_residual.
    module subroutine b2b_model_add_tangent_dense(model, eq, K, ierr, errmsg)
      type(b2b_model), intent(in) :: model
      integer, intent(in) :: eq(:, :)
      real(c_double), intent(inout), contiguous :: K(:, :)
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Adds the contacts' tangents into AB(ldab, n_eq), LAPACK's general band
    !> storage for dgbsv with kl sub- and ku superdiagonals (ldab >= 2 kl + ku + 1:
    !> K(i, j) is AB(kl + ku + 1 + i - j, j)); eq as for b2b_model_add_residual.
    !> An entry outside the band is B2B_ERR_RANGE, and nothing is added.
    module subroutine b2b_model_add_tangent_banded(model, eq, kl, ku, AB, ierr, errmsg)
      type(b2b_model), intent(in) :: model
      integer, intent(in) :: eq(:, :)
      integer, intent(in) :: kl, ku
      real(c_double), intent(inout), contiguous :: AB(:, :)
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> The tangent as COO triplets in the host's 1-based equation numbers
    !> (duplicates are to be summed). Without rows, cols and values only nnz is
    !> set (the size query); with them, each must hold at least nnz entries.
    module subroutine b2b_model_tangent_coo(model, eq, n_eq, nnz, rows, cols, values, ierr, errmsg)
      type(b2b_model), intent(in) :: model
      integer, intent(in) :: eq(:, :)
      integer, intent(in) :: n_eq
      integer, intent(inout) :: nnz
      integer(c_int), intent(inout), contiguous, target, optional :: rows(:), cols(:)
      real(c_double), intent(inout), contiguous, target, optional :: values(:)
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Accepts the state of the last update (a converged step).
    module subroutine b2b_model_commit(model, ierr, errmsg)
      type(b2b_model), intent(inout) :: model
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Returns to the last commit (a cut-back).
    module subroutine b2b_model_revert(model, ierr, errmsg)
      type(b2b_model), intent(inout) :: model
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Bytes b2b_model_save needs for the committed state.
    module subroutine b2b_model_save_size(model, nbytes, ierr, errmsg)
      type(b2b_model), intent(in) :: model
      integer(c_int64_t), intent(inout) :: nbytes
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> The committed state into buffer (at least b2b_model_save_size bytes).
    module subroutine b2b_model_save(model, buffer, ierr, errmsg)
      type(b2b_model), intent(in) :: model
      integer(c_int8_t), intent(inout), contiguous :: buffer(:)
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Restores a committed state saved by b2b_model_save from a model built the same way.
    module subroutine b2b_model_restore(model, buffer, ierr, errmsg)
      type(b2b_model), intent(inout) :: model
      integer(c_int8_t), intent(in), contiguous :: buffer(:)
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> counts(16) and totals(8) of the last update, either optional: index them
    !> with B2B_IX_COUNT_* and B2B_IX_TOTAL_* (counts(B2B_IX_COUNT_ACTIVE) is the
    !> C counts[B2B_COUNT_ACTIVE]).
    module subroutine b2b_model_stats(model, counts, totals, ierr, errmsg)
      type(b2b_model), intent(in) :: model
      integer, intent(inout), optional :: counts(:)
      real(c_double), intent(inout), optional :: totals(:)
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Distributed models (b2b_model.h, "Distributed models"; doc/distributed.md),
    !> in Fortran numbering: beams, segments and global ids are 1-based.
    !> Local beam `beam` is a piece of global beam global_beam (>= 1, the same on
    !> every rank); its first segment is segment first_segment (>= 1) of the
    !> global beam; start_cut / end_cut: its first / last node is a cut (the
    !> segment there is padding and must be a ghost). Before finalize.
    module subroutine b2b_model_set_beam_global(model, beam, global_beam, first_segment, &
                                                start_cut, end_cut, ierr, errmsg)
      type(b2b_model), intent(inout) :: model
      integer, intent(in) :: beam
      integer(c_int64_t), intent(in) :: global_beam
      integer, intent(in) :: first_segment
      logical, intent(in) :: start_cut, end_cut
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Segments first .. first + count - 1 (1-based) of beam are ghosts (owned
    !> by another rank). Before finalize.
    module subroutine b2b_model_set_ghost_segments(model, beam, first, count, ierr, errmsg)
      type(b2b_model), intent(inout) :: model
      integer, intent(in) :: beam, first, count
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Contact k (1 .. count) in global ids: pair(4) = global beam and segment
    !> of its A, then of its B (1-based).
    module subroutine b2b_model_get_contact_global(model, k, pair, ierr, errmsg)
      type(b2b_model), intent(in) :: model
      integer, intent(in) :: k
      integer(c_int64_t), intent(inout) :: pair(:)
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> The number of migrating contacts of the last update.
    module subroutine b2b_model_migration_count(model, n, ierr, errmsg)
      type(b2b_model), intent(in) :: model
      integer, intent(inout) :: n
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Migrating contact k (1 .. n): target(4), global beam and segment of the
    !> target pair's A, then of its B (1-based; its owner owns the smaller),
    !> and nbytes, the size of its packed form; both optional.
    module subroutine b2b_model_migration_info(model, k, target, nbytes, ierr, errmsg)
      type(b2b_model), intent(in) :: model
      integer, intent(in) :: k
      integer(c_int64_t), intent(inout), optional :: target(:)
      integer(c_int64_t), intent(inout), optional :: nbytes
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Packs migrating contact k into buffer (at least nbytes of migration_info).
    module subroutine b2b_model_migration_pack(model, k, buffer, ierr, errmsg)
      type(b2b_model), intent(in) :: model
      integer, intent(in) :: k
      integer(c_int8_t), intent(inout), contiguous :: buffer(:)
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Unpacks a contact packed by another rank (buffer: exactly its bytes);
    !> changed: whether the model's set of received contacts changed. Without
    !> buffer: the end of a round of receiving (drops the received contacts not
    !> unpacked since the last update). Call it as
    !> b2b_model_migration_unpack(model, changed=ch) for the end of a round.
    module subroutine b2b_model_migration_unpack(model, buffer, changed, ierr, errmsg)
      type(b2b_model), intent(inout) :: model
      integer(c_int8_t), intent(in), contiguous, target, optional :: buffer(:)
      logical, intent(inout) :: changed
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
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
    module subroutine b2b_model_audit(model, tolerance, n_found, pairs, overlap, reasons, ierr, &
                                      errmsg)
      type(b2b_model), intent(in) :: model
      real(c_double), intent(in) :: tolerance
      integer, intent(inout) :: n_found
      integer, intent(inout), optional :: pairs(:, :)
      real(c_double), intent(inout), optional :: overlap(:)
      integer, intent(inout), optional :: reasons(:)
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> One Newton iteration from reference coordinates and displacements: the
    !> current coordinates are x + u, read from rows 1..3 of x(ldx, n) and of
    !> u(ldu, n2) (FEAP: x(ndm, numnp) with ndm = 3, u(ndf, numnp) with
    !> ndf >= 3, e.g. u(:, :, 1); rows beyond 3 are not read), n and n2 >=
    !> n_nodes. The result is b2b_model_update(x + u) bit for bit. A
    !> non-finite u is B2B_ERR_NONFINITE naming node and axis; x + u beyond
    !> B2B_COORD_MAX is B2B_ERR_RANGE. want_tangent as b2b_model_update.
    module subroutine b2b_model_update_xu(model, x, u, want_tangent, ierr, errmsg)
      type(b2b_model), intent(inout) :: model
      real(c_double), intent(in), contiguous :: x(:, :), u(:, :)
      logical, intent(in), optional :: want_tangent
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> f(e) += scale * the contacts' residuals (b2b_model_add_residual
    !> scaled). The residual is the contact part of the internal force
    !> (gradient of the contact potential): a host whose right-hand side is
    !> F_ext - F_int, as FEAP's, passes scale = -1. A non-finite scale is
    !> B2B_ERR_NONFINITE, nothing added.
    module subroutine b2b_model_add_residual_scaled(model, eq, scale, f, ierr, errmsg)
      type(b2b_model), intent(in) :: model
      integer, intent(in) :: eq(:, :)
      real(c_double), intent(in) :: scale
      real(c_double), intent(inout), contiguous :: f(:)
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> K(e_r, e_c) += scale * the contacts' tangents (b2b_model_add_tangent_dense).
    module subroutine b2b_model_add_tangent_dense_scaled(model, eq, scale, K, ierr, errmsg)
      type(b2b_model), intent(in) :: model
      integer, intent(in) :: eq(:, :)
      real(c_double), intent(in) :: scale
      real(c_double), intent(inout), contiguous :: K(:, :)
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> scale * the contacts' tangents into dgbsv's band storage AB
    !> (b2b_model_add_tangent_banded).
    module subroutine b2b_model_add_tangent_banded_scaled(model, eq, kl, ku, scale, AB, ierr, &
                                                         errmsg)
      type(b2b_model), intent(in) :: model
      integer, intent(in) :: eq(:, :)
      integer, intent(in) :: kl, ku
      real(c_double), intent(in) :: scale
      real(c_double), intent(inout), contiguous :: AB(:, :)
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> The contacts' coupling pattern in the host's equations (1-based), to
    !> size a profile or band before assembling; n_eq = size(heights).
    !>   heights(j)  j - (the smallest equation i <= j that a contact couples
    !>               with j, as K(i, j) or K(j, i)), 0 if none: FEAP's column
    !>               heights of the contacts alone (its jp before nwprof)
    !>   kl, ku      the band: largest e_r - e_c and e_c - e_r of a coupled entry
    !> Contact couples dofs outside the element connectivity, across beams,
    !> and the pattern changes as contacts come and go: query it after every
    !> update, merge with the host's own (max), and re-size and re-factor
    !> when it grew. No tangent needed (want_tangent may be .false.).
    module subroutine b2b_model_tangent_profile(model, eq, heights, kl, ku, ierr, errmsg)
      type(b2b_model), intent(in) :: model
      integer, intent(in) :: eq(:, :)
      integer, intent(inout), contiguous :: heights(:)
      integer, intent(inout), optional :: kl, ku
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> scale * the contacts' tangents into FEAP's profile storage with its
    !> pointer array jp(n_eq) (jp(1) = 0, jp(j) = jp(j-1) + height of column j):
    !> K(j, j) into ad(j), K(i, j), i < j, into au(jp(j) - j + i + 1) and
    !> K(j, i) into al(jp(j) - j + i + 1), as FEAP's dasble. n_eq = size(ad)
    !> = size(jp); au (and al) hold at least jp(n_eq) entries. al absent: the
    !> upper triangle only (a symmetric solver; with friction the tangent is
    !> not symmetric). An entry outside the profile is B2B_ERR_RANGE naming
    !> both equations, nothing added.
    module subroutine b2b_model_add_tangent_profile(model, eq, scale, jp, ad, au, al, ierr, &
                                                    errmsg)
      type(b2b_model), intent(in) :: model
      integer, intent(in) :: eq(:, :)
      real(c_double), intent(in) :: scale
      integer, intent(in) :: jp(:)
      real(c_double), intent(inout), contiguous :: ad(:), au(:)
      real(c_double), intent(inout), contiguous, target, optional :: al(:)
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> f(e) += scale * sum_c K(e, c) du_c over the free rows e and the
    !> constrained columns c (eq <= 0) of every contact: the coupling of the
    !> free dofs to prescribed increments, which the assembly helpers skip.
    !> du(ldu, n): node k's increments in du(1:3, k) (ldu >= 3, n >= n_nodes);
    !> only the entries of constrained dofs are read. n_eq = size(f). A host
    !> with right-hand side F_ext - F_int passes scale = -1
    !> (rhs_free -= K_fc du_c).
    module subroutine b2b_model_add_constrained_product(model, eq, du, scale, f, ierr, errmsg)
      type(b2b_model), intent(in) :: model
      integer, intent(in) :: eq(:, :)
      real(c_double), intent(in), contiguous :: du(:, :)
      real(c_double), intent(in) :: scale
      real(c_double), intent(inout), contiguous :: f(:)
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine
  end interface

  ! ------------------------------------ shared helpers (private)
  ! Bodies: submodule support_layer (b2b_support.f90).
  interface
    !> Hands the status to the caller: through ierr/errmsg when present; when
    !> ierr is absent, a failure stops the program with the message.
    module subroutine finish(procname, st, buf, ierr, errmsg)
      character(len=*), intent(in) :: procname
      integer(c_int), intent(in) :: st
      character(kind=c_char), intent(in) :: buf(:)
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Reports an array of the wrong shape as B2B_ERR_SIZE.
    module subroutine finish_size(procname, argname, got, want, ierr, errmsg)
      character(len=*), intent(in) :: procname, argname
      integer, intent(in) :: got(:), want(:)
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Reports a failure the module detects itself, with its message.
    module subroutine finish_text(procname, st, text, ierr, errmsg)
      character(len=*), intent(in) :: procname, text
      integer(c_int), intent(in) :: st
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Whether a default integer is a C int: always, unless the host compiled
    !> this module with a wider default integer (-fdefault-integer-8). The
    !> range is symmetric, so that a 1-based value minus 1 is a C int too.
    module elemental logical function fits_c_int(v)
      integer, intent(in) :: v
    end function

    !> ok = .true. if every values(i) fits a C int; else reports B2B_ERR_RANGE
    !> for the first that does not, names(i) being its argument.
    module subroutine check_ints(procname, names, values, ok, ierr, errmsg)
      character(len=*), intent(in) :: procname, names(:)
      integer, intent(in) :: values(:)
      logical, intent(out) :: ok
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> check_ints for the elements of an array argument a(:).
    module subroutine check_int_array(procname, argname, a, ok, ierr, errmsg)
      character(len=*), intent(in) :: procname, argname
      integer, intent(in) :: a(:)
      logical, intent(out) :: ok
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> The arguments every pair procedure shares (b2b_pair_eval, _ends,
    !> _line): segments(3,2) within C's int range, X(3,8), radii(2); ok =
    !> .false. after the first problem is reported.
    module subroutine check_pair_shapes(procname, segments, X, radii, ok, ierr, errmsg)
      character(len=*), intent(in) :: procname
      integer, intent(in) :: segments(:, :)
      real(c_double), intent(in) :: X(:, :), radii(:)
      logical, intent(out) :: ok
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> An optional array's address and shape, as the pair procedures pass
    !> them on: (c_null_ptr, -1) where absent. (gfortran 12 passing an absent
    !> optional contiguous array on to another optional dummy loads through
    !> its null data pointer: an UBSan finding.)
    module subroutine optional_address(p, sh, addr, actual_shape)
      type(c_ptr), intent(out) :: p
      integer, intent(out) :: sh(2)
      type(c_ptr), intent(in), optional :: addr
      integer, intent(in), optional :: actual_shape(2)
    end subroutine

    !> The optional tangent (ldk,24) and end tangents (3,4) of a pair
    !> procedure, given by address and shape (shape -1: absent), as its C
    !> call takes them: pk and ldk (24 where absent), pt. A wrong shape is
    !> B2B_ERR_SIZE (ok = .false.).
    module subroutine check_pair_optionals(procname, tangent, kshape, end_tangents, tshape, pk, &
                                           ldk, pt, ok, ierr, errmsg)
      character(len=*), intent(in) :: procname
      type(c_ptr), intent(in) :: tangent, end_tangents
      integer, intent(in) :: kshape(2), tshape(2)
      type(c_ptr), intent(out) :: pk, pt
      integer(c_int), intent(out) :: ldk
      logical, intent(out) :: ok
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> check_ints for the elements of an array argument a(:, :).
    module subroutine check_int_matrix(procname, argname, a, ok, ierr, errmsg)
      character(len=*), intent(in) :: procname, argname
      integer, intent(in) :: a(:, :)
      logical, intent(out) :: ok
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Reports an integer argument beyond C's int range as B2B_ERR_RANGE.
    module subroutine finish_range(procname, argname, v, ierr, errmsg)
      character(len=*), intent(in) :: procname, argname
      integer, intent(in) :: v
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Whether two arrays share memory, even in part (arrays of no elements
    !> share none).
    module logical function overlap(a, b)
      real(c_double), intent(in), contiguous, target :: a(:), b(:)
    end function

    !> Reports an output array that shares memory with an input array.
    module subroutine finish_alias(procname, outname, inname, ierr, errmsg)
      character(len=*), intent(in) :: procname, outname, inname
      integer, intent(out), optional :: ierr
      character(len=*), intent(out), optional :: errmsg
    end subroutine

    !> Rewrites a message of the C curve and pair functions in the terms of
    !> the Fortran call: an end_tangents argument the caller left out is
    !> "absent", not "NULL"; and for the history argument hist (if not ''),
    !> "<hist>[k]" and "entry k" (0-based) become "<hist>(k+1)", and the C
    !> length argument "hist_len" becomes "size(<hist>)".
    module subroutine fortran_terms(buf, hist)
      character(kind=c_char), intent(inout) :: buf(:)
      character(len=*), intent(in) :: hist
    end subroutine

    !> msg with every old replaced by new.
    module function replace_all(msg, old, new) result(out)
      character(len=*), intent(in) :: msg, old, new
      character(len=:), allocatable :: out
    end function

    !> msg with every "<key><k><close>" (k a non-negative integer) replaced by
    !> "<new_key><k+1><new_close>".
    module function renumber(msg, key, new_key, close, new_close) result(out)
      character(len=*), intent(in) :: msg, key, new_key, close, new_close
      character(len=:), allocatable :: out
    end function

    module logical function shape_is(got, want)
      integer, intent(in) :: got(:), want(:)
    end function

    module function shape_text(s) result(t)
      integer, intent(in) :: s(:)
      character(len=:), allocatable :: t
    end function

    module function int_text(i) result(t)
      integer, intent(in) :: i
      character(len=24) :: t
    end function

    module integer(c_int) function c_flag(flag)
      logical, intent(in) :: flag
    end function

    !> An empty, NUL-terminated message buffer (for calls that carry none).
    module function blank_message() result(buf)
      character(kind=c_char) :: buf(1)
    end function

    !> The characters of a NUL-terminated C char array (all of them if no NUL).
    module function c_chars(buf) result(s)
      character(kind=c_char), intent(in) :: buf(:)
      character(len=:), allocatable :: s
    end function

    !> A Fortran copy of a NUL-terminated C string owned by the library.
    module function c_string(p) result(s)
      type(c_ptr), intent(in) :: p
      character(len=:), allocatable :: s
    end function
  end interface

end module b2b
