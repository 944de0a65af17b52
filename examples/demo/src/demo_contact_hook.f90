!> THE CONTACT HOOK: all a host needs to couple the contact model of b2b,
!> through the Fortran module b2b, and nothing else: the file a host author
!> copies (replacing scene_model by the host's mesh and state, linear_system
!> by its Newton matrix, fatal by its error handling). The model is the
!> caller's, a type(b2b_model) passed to every routine; this module keeps no
!> state. The demo's extras (contacts for the output, the audit, the
!> per-iteration signature of the active set, debug printing) are in
!> demo_contact_report and only read the model.
!>
!>  * contact_hook_build(model, m), once before the first step:
!>    b2b_model_create; b2b_model_add_beam for every beam (its global node
!>    numbers, closed or not, contact radius, the curve kind of &contact,
!>    its group); one b2b_params (penalty, law, regularization_gap,
!>    friction, tangential_penalty, tangent, and the scene's parallel_angle,
!>    warm_start, max_iterations) given to b2b_model_set_group_pair for
!>    every pair of groups (and each group with itself, plus
!>    b2b_model_set_self_contact per beam, with self_contact); the scene's
!>    model options (search_margin, threads, max_handover_hops,
!>    max_candidates: b2b_model_set_real/_int, contact_hook_options);
!>    b2b_model_finalize(model, n_nodes); an update of the initial
!>    configuration, committed where it carries no contact force.
!>  * contact_hook_forces(model, m, eq, want_tangent, sys, r, fint, ok, why),
!>    every assembly, with the current positions m%x: b2b_model_update;
!>    b2b_model_add_residual into r (the contact part of the INTERNAL force:
!>    r = f_int + f_contact - lambda f_ext, so it is added) and into f_int on
!>    every dof (the reactions include the contact); the tangent with
!>    b2b_model_add_tangent_banded (or _dense). When the band is too narrow
!>    for a contact (B2B_ERR_RANGE, nothing added), the width the contacts
!>    need is computed from their nodes (b2b_model_get_contact) and reported
!>    as an overflow of the linear system: the Newton loop widens the band
!>    (or goes dense) and assembles again. A failed update (e.g. a segment
!>    folded by a wild Newton iterate) is not fatal: ok = .false. with the
!>    model's message, and the caller cuts the step back.
!>  * contact_hook_commit(model) after a converged (sub)step: b2b_model_commit.
!>  * contact_hook_revert(model) on a cut-back: b2b_model_revert.
!>  * contact_hook_crossed(model): pairs of beams whose axes passed through
!>    each other in the last update (B2B_COUNT_CROSSED); a converged state
!>    with one is cut back.
!>  * at the end: b2b_model_destroy(model).
module demo_contact_hook
  use demo_kinds, only: dp, ndf
  use demo_model, only: scene_model, option_model_real, option_model_int, option_params_real, option_params_int
  use demo_linear_system, only: linear_system
  use demo_errors, only: fatal, str
  use b2b, only: b2b_model, b2b_params, b2b_params_create, b2b_params_set_real, b2b_params_set_int, &
                 b2b_model_set_real, b2b_model_set_int, &
                 b2b_params_finalize, b2b_params_destroy, b2b_model_create, b2b_model_add_beam, &
                 b2b_model_set_group_pair, b2b_model_set_self_contact, b2b_model_finalize, &
                 b2b_model_update, b2b_model_contact_count, b2b_model_get_contact, b2b_model_add_residual, &
                 b2b_model_add_tangent_banded, b2b_model_add_tangent_dense, b2b_model_commit, &
                 b2b_model_revert, b2b_model_stats, b2b_model_destroy, &
                 B2B_IX_COUNT_CROSSED, B2B_IX_COUNT_ACTIVE, B2B_MODEL_COUNTS_LEN, &
                 B2B_CURVE_LINEAR, B2B_CURVE_HERMITE_MIDPOINT, B2B_CURVE_HERMITE_NODAL, &
                 B2B_CURVE_HERMITE_NODAL_WEIGHTED, B2B_LAW_LINEAR, B2B_LAW_QUADRATIC, B2B_ERR_RANGE, &
                 B2B_TANGENT_EXACT, B2B_TANGENT_SYMMETRIC, B2B_TANGENT_MAIN, B2B_TANGENT_FD
  implicit none
  private
  public :: contact_hook_build, contact_hook_forces, contact_hook_commit, contact_hook_revert
  public :: contact_hook_crossed, contact_hook_options

contains

  integer function curve_kind(name) result(k)
    character(len=*), intent(in) :: name
    select case (trim(name))
    case ('linear'); k = B2B_CURVE_LINEAR
    case ('hermite_midpoint'); k = B2B_CURVE_HERMITE_MIDPOINT
    case ('hermite_nodal_weighted'); k = B2B_CURVE_HERMITE_NODAL_WEIGHTED
    case default; k = B2B_CURVE_HERMITE_NODAL
    end select
  end function curve_kind

  !> b2b_params "tangent" of the &contact key tangent (validated by the reader).
  integer function tangent_option(name) result(k)
    character(len=*), intent(in) :: name
    select case (trim(name))
    case ('symmetric'); k = B2B_TANGENT_SYMMETRIC
    case ('main'); k = B2B_TANGENT_MAIN
    case ('fd'); k = B2B_TANGENT_FD
    case default; k = B2B_TANGENT_EXACT
    end select
  end function tangent_option

  subroutine check(ierr, errmsg, what)
    integer, intent(in) :: ierr
    character(len=*), intent(in) :: errmsg, what
    if (ierr /= 0) call fatal('contact model: ' // what // ': ' // trim(errmsg))
  end subroutine check

  !> Builds the contact model of scene m (which has &contact) into model; a
  !> model left from an earlier run is freed first.
  subroutine contact_hook_build(model, m)
    type(b2b_model), intent(inout) :: model
    type(scene_model), intent(in) :: m
    type(b2b_params) :: params
    integer :: b, k, g, beam, ierr, i
    integer, allocatable :: nodes(:)
    character(len=512) :: msg
    character(len=:), allocatable :: key
    logical :: have_self_pair
    integer :: counts(B2B_MODEL_COUNTS_LEN)

    call b2b_model_destroy(model)
    call b2b_model_create(model, ierr, msg)
    call check(ierr, msg, 'create')
    do b = 1, m%n_beams
      nodes = [(m%beam_first_node(b) + i, i = 0, m%beam_n_nodes(b) - 1)]
      call b2b_model_add_beam(model, nodes, m%beam_closed(b), m%beam_radius(b), curve_kind(m%contact%curve), &
                              m%beam_group(b), beam, ierr, msg)
      call check(ierr, msg, 'beam ' // str(b))
    end do
    call b2b_params_create(params, ierr, msg)
    call check(ierr, msg, 'parameters')
    call b2b_params_set_real(params, 'penalty', m%contact%penalty, ierr, msg)
    call check(ierr, msg, 'penalty')
    if (m%contact%law == 'quadratic') then
      call b2b_params_set_int(params, 'law', int(B2B_LAW_QUADRATIC), ierr, msg)
      call check(ierr, msg, 'law')
      call b2b_params_set_real(params, 'regularization_gap', m%contact%regularization_gap, ierr, msg)
      call check(ierr, msg, 'regularization_gap')
    else
      call b2b_params_set_int(params, 'law', int(B2B_LAW_LINEAR), ierr, msg)
      call check(ierr, msg, 'law')
    end if
    if (m%contact%friction > 0.0_dp) then
      call b2b_params_set_real(params, 'friction', m%contact%friction, ierr, msg)
      call check(ierr, msg, 'friction')
      call b2b_params_set_real(params, 'tangential_penalty', m%contact%tangential_penalty, ierr, msg)
      call check(ierr, msg, 'tangential_penalty')
    end if
    call b2b_params_set_int(params, 'tangent', tangent_option(m%contact%tangent), ierr, msg)
    call check(ierr, msg, 'tangent')
    call contact_hook_options(m, model, params, ierr, msg, key)
    call check(ierr, msg, key)
    call b2b_params_finalize(params, ierr, msg)
    call check(ierr, msg, 'parameters')
    do k = 1, m%contact%n_pairs
      call b2b_model_set_group_pair(model, m%contact%pairs(1, k), m%contact%pairs(2, k), params, ierr, msg)
      call check(ierr, msg, 'group pair ' // str(k))
    end do
    if (m%contact%self_contact) then
      do b = 1, m%n_beams
        g = m%beam_group(b)
        have_self_pair = .false.
        do k = 1, m%contact%n_pairs
          if (all(m%contact%pairs(:, k) == g)) have_self_pair = .true.
        end do
        if (.not. have_self_pair) then
          call b2b_model_set_group_pair(model, g, g, params, ierr, msg)
          call check(ierr, msg, 'group pair (' // str(g) // ', ' // str(g) // ')')
        end if
        call b2b_model_set_self_contact(model, b, .true., ierr=ierr, errmsg=msg)
        call check(ierr, msg, 'self-contact of beam ' // str(b))
      end do
    end if
    call b2b_params_destroy(params)
    call b2b_model_finalize(model, m%n_nodes, ierr, msg)
    call check(ierr, msg, 'finalize')
    ! The initial configuration, where it carries no contact force, is an
    ! equilibrium at load 0, the first converged state: committed, it is
    ! what the model checks the first step against for beams that pass
    ! through each other (B2B_COUNT_CROSSED). One with active contacts is
    ! not (their forces are not yet balanced, and committing it would anchor
    ! their friction there): it is reverted, and the first step has no such
    ! reference.
    call b2b_model_update(model, m%x, .false., ierr, msg)
    call check(ierr, msg, 'update (initial configuration)')
    call b2b_model_stats(model, counts, ierr=ierr, errmsg=msg)
    call check(ierr, msg, 'stats (initial configuration)')
    if (counts(B2B_IX_COUNT_ACTIVE) == 0) then
      call b2b_model_commit(model, ierr, msg)
      call check(ierr, msg, 'commit (initial configuration)')
    else
      call b2b_model_revert(model, ierr, msg)
      call check(ierr, msg, 'revert (initial configuration)')
    end if
  end subroutine contact_hook_build

  !> The library options the scene sets (&contact search_margin, threads,
  !> max_handover_hops, max_candidates: b2b_model_set_real/_int on model;
  !> parallel_angle, warm_start, max_iterations: b2b_params_set_real/_int
  !> on params, before it is finalized), passed as they are. The first the
  !> library refuses ends it: ierr, the library's message and its key.
  subroutine contact_hook_options(m, model, params, ierr, errmsg, key)
    type(scene_model), intent(in) :: m
    type(b2b_model), intent(inout) :: model
    type(b2b_params), intent(inout) :: params
    integer, intent(out) :: ierr
    character(len=*), intent(out) :: errmsg
    character(len=:), allocatable, intent(out) :: key
    integer :: k
    ierr = 0
    errmsg = ''
    key = ''
    do k = 1, m%contact%n_options
      key = trim(m%contact%option_key(k))
      associate (v => m%contact%option_value(k))
        select case (m%contact%option_kind(k))
        case (option_model_real); call b2b_model_set_real(model, key, v, ierr, errmsg)
        case (option_model_int); call b2b_model_set_int(model, key, nint(v), ierr, errmsg)
        case (option_params_real); call b2b_params_set_real(params, key, v, ierr, errmsg)
        case (option_params_int); call b2b_params_set_int(params, key, nint(v), ierr, errmsg)
        end select
      end associate
      if (ierr /= 0) return
    end do
  end subroutine contact_hook_options

  !> Updates the model at the positions m%x and adds the contact part of the
  !> internal force to r (free dofs, numbered by eq) and to fint (all dofs),
  !> and its tangent to sys if want_tangent. ok = .false. (why: the model's
  !> message) if the update failed; nothing is added then.
  subroutine contact_hook_forces(model, m, eq, want_tangent, sys, r, fint, ok, why)
    type(b2b_model), intent(inout) :: model
    type(scene_model), intent(in) :: m
    integer, intent(in) :: eq(:, :)
    logical, intent(in) :: want_tangent
    type(linear_system), intent(inout) :: sys
    real(dp), intent(inout) :: r(:), fint(:, :)
    logical, intent(out) :: ok
    character(len=:), allocatable, intent(out) :: why
    real(dp), allocatable :: f_all(:)
    integer, allocatable :: eq_all(:, :)
    integer :: ierr, i
    character(len=512) :: msg

    ok = .true.
    why = ''
    call b2b_model_update(model, m%x, want_tangent, ierr, msg)
    if (ierr /= 0) then
      ok = .false.
      why = 'contact update failed: ' // trim(msg)
      return
    end if
    call b2b_model_add_residual(model, eq, r, ierr, msg)
    call check(ierr, msg, 'add_residual')
    ! the contact part of f_int on every dof (every dof numbered)
    eq_all = reshape([(i, i = 1, ndf * m%n_nodes)], [ndf, m%n_nodes])
    allocate (f_all(size(fint)))
    f_all = 0.0_dp
    call b2b_model_add_residual(model, eq_all, f_all, ierr, msg)
    call check(ierr, msg, 'add_residual (all dofs)')
    fint = fint + reshape(f_all, shape(fint))
    if (.not. want_tangent) return
    if (sys%dense) then
      call b2b_model_add_tangent_dense(model, eq, sys%a, ierr, msg)
      call check(ierr, msg, 'add_tangent_dense')
    else
      call b2b_model_add_tangent_banded(model, eq, sys%kl, sys%ku, sys%a, ierr, msg)
      if (ierr == B2B_ERR_RANGE) then
        ! a contact couples equations beyond the band: the width it needs
        sys%overflow = .true.
        sys%need = max(sys%need, band_needed(model, eq))
      else
        call check(ierr, msg, 'add_tangent_banded')
      end if
    end if
  end subroutine contact_hook_forces

  !> The half bandwidth the active contacts of the last update need: the
  !> widest span of the equations of one contact's nodes.
  integer function band_needed(model, eq) result(need)
    type(b2b_model), intent(in) :: model
    integer, intent(in) :: eq(:, :)
    integer :: n, k, s, e, lo, hi, nodes(8), ierr
    character(len=512) :: msg
    call b2b_model_contact_count(model, n, ierr, msg)
    call check(ierr, msg, 'contact_count')
    need = 0
    do k = 1, n
      call b2b_model_get_contact(model, k, nodes=nodes, ierr=ierr, errmsg=msg)
      call check(ierr, msg, 'get_contact ' // str(k))
      lo = huge(1)
      hi = 0
      do s = 1, 8
        if (nodes(s) <= 0) cycle
        do e = 1, 3
          if (eq(e, nodes(s)) <= 0) cycle
          lo = min(lo, eq(e, nodes(s)))
          hi = max(hi, eq(e, nodes(s)))
        end do
      end do
      if (hi > 0) need = max(need, hi - lo)
    end do
  end function band_needed

  !> Pairs of beams whose axes lie through each other in the last update
  !> (B2B_COUNT_CROSSED). Within the iterations the signed gap pushes them
  !> back; a converged state that still has one is cut back by the caller:
  !> a penalty cannot resolve an axis that went through another beam.
  integer function contact_hook_crossed(model) result(n)
    type(b2b_model), intent(in) :: model
    integer :: counts(B2B_MODEL_COUNTS_LEN), ierr
    character(len=512) :: msg
    call b2b_model_stats(model, counts, ierr=ierr, errmsg=msg)
    call check(ierr, msg, 'stats')
    n = counts(B2B_IX_COUNT_CROSSED)
  end function contact_hook_crossed

  subroutine contact_hook_commit(model)
    type(b2b_model), intent(inout) :: model
    integer :: ierr
    character(len=512) :: msg
    call b2b_model_commit(model, ierr, msg)
    call check(ierr, msg, 'commit')
  end subroutine contact_hook_commit

  subroutine contact_hook_revert(model)
    type(b2b_model), intent(inout) :: model
    integer :: ierr
    character(len=512) :: msg
    call b2b_model_revert(model, ierr, msg)
    call check(ierr, msg, 'revert')
  end subroutine contact_hook_revert

end module demo_contact_hook
