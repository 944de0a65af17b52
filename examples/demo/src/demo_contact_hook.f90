!> THE CONTACT HOOK: the one place where the contact model of b2b is coupled
!> to this host, through the Fortran module b2b exactly as a user's code
!> would call it. The host never evaluates a pair itself.
!>
!>  * contact_hook_init: b2b_model_create; b2b_model_add_beam for every beam
!>    (its global node numbers, closed or not, radius, the curve kind of
!>    &contact, its group); one b2b_params (penalty, law, regularization_gap,
!>    friction, tangential_penalty, tangent) given to b2b_model_set_group_pair for
!>    every pair of groups (and each group with itself, plus
!>    b2b_model_set_self_contact per beam, with self_contact);
!>    b2b_model_finalize(model, n_nodes).
!>  * contact_hook_forces, every assembly, with the current positions m%x:
!>    b2b_model_update; b2b_model_add_residual into r (the contact part of
!>    the INTERNAL force: r = f_int + f_contact - lambda f_ext, so it is
!>    added) and into f_int on every dof (the reactions include the contact);
!>    the tangent with b2b_model_add_tangent_banded (or _dense). When the band
!>    is too narrow for a contact (B2B_ERR_RANGE, nothing added), the width
!>    the contacts need is computed from their nodes (b2b_model_get_contact)
!>    and reported as an overflow of the linear system: the Newton loop
!>    widens the band (or goes dense) and assembles again.
!>  * contact_hook_audit after a converged (sub)step, before its commit:
!>    b2b_model_audit (tolerance audit_tolerance of the smaller radius) lists
!>    the pairs that overlap with no force; each is printed, and the count
!>    goes into the snapshot, which the scene check fails on (demo_checks).
!>  * contact_hook_commit after a converged (sub)step: b2b_model_commit.
!>  * contact_hook_revert on a cut-back: b2b_model_revert.
!> A failed update (e.g. a segment folded by a wild Newton iterate) is not
!> fatal: contact_hook_failed reports it and the step is cut back.
module demo_contact_hook
  use demo_kinds, only: dp, ndf
  use demo_model, only: scene_model
  use demo_linear_system, only: linear_system
  use demo_errors, only: fatal, str
  use b2b, only: b2b_model, b2b_params, b2b_params_create, b2b_params_set_real, b2b_params_set_int, &
                 b2b_params_finalize, b2b_params_destroy, b2b_model_create, b2b_model_add_beam, &
                 b2b_model_set_group_pair, b2b_model_set_self_contact, b2b_model_finalize, &
                 b2b_model_update, b2b_model_contact_count, b2b_model_get_contact, b2b_model_add_residual, &
                 b2b_model_add_tangent_banded, b2b_model_add_tangent_dense, b2b_model_commit, &
                 b2b_model_revert, b2b_model_stats, b2b_model_destroy, b2b_model_audit, &
                 B2B_AUDIT_OTHER, B2B_AUDIT_PARALLEL, B2B_AUDIT_OUTSIDE_BOTH, B2B_AUDIT_NEVER_EVALUATED, &
                 B2B_AUDIT_EXCLUDED_SELF, B2B_AUDIT_CROSSED, B2B_IX_COUNT_CROSSED, B2B_IX_COUNT_ACTIVE, &
                 B2B_MODEL_COUNTS_LEN, &
                 B2B_CURVE_LINEAR, B2B_CURVE_HERMITE_MIDPOINT, B2B_CURVE_HERMITE_NODAL, &
                 B2B_CURVE_HERMITE_NODAL_WEIGHTED, B2B_LAW_LINEAR, B2B_LAW_QUADRATIC, B2B_ERR_RANGE, &
                 B2B_TANGENT_EXACT, B2B_TANGENT_SYMMETRIC, B2B_TANGENT_MAIN, B2B_TANGENT_FD
  use, intrinsic :: iso_fortran_env, only: int64
  implicit none
  private
  public :: contact_hook_init, contact_hook_forces, contact_hook_commit, contact_hook_revert
  public :: contact_hook_failed, contact_hook_signature, contact_hook_snapshot, contact_hook_finish
  public :: contact_hook_audit, contact_hook_crossed

  !> Overlaps below this fraction of the smaller radius are not reported by the audit.
  real(dp), parameter, public :: audit_tolerance = 0.01_dp

  !> One active contact of the last update, as b2b_model_get_contact gives it.
  type, public :: contact_point
    integer :: pair(4) = 0        !< beam A, segment A, beam B, segment B (1-based)
    integer :: nodes(8) = 0       !< host nodes of A's patch slots, then B's (0: none)
    real(dp) :: info(32) = 0.0_dp !< B2B_INFO_*: the C entry info[k] is info(k + 1)
  end type contact_point

  !> The contacts of the last update and the model's statistics.
  type, public :: contact_snapshot
    integer :: n = 0
    type(contact_point), allocatable :: c(:)
    integer :: counts(16) = 0
    real(dp) :: totals(8) = 0.0_dp
    integer :: audit_found = 0    !< findings of the run's audits so far (b2b_model_audit)
  end type contact_snapshot

  type(b2b_model), save :: model
  logical, save :: debug = .false.
  logical, save :: on = .false.        !< a model exists (contact_hook_init ran with &contact)
  logical, save :: updated = .false.   !< an update since the last commit or revert
  logical, save :: failed = .false.
  character(len=512), save :: fail_msg = ''
  type(contact_snapshot), save :: last
  integer, save :: audit_total = 0     !< findings of every audit since contact_hook_init
  integer, allocatable, save :: eq_all(:, :)   !< every dof numbered, for the contact part of f_int

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

  subroutine contact_hook_init(m, quiet)
    type(scene_model), intent(in) :: m
    logical, intent(in), optional :: quiet
    type(b2b_params) :: params
    integer :: b, k, g, beam, ierr, i, node
    integer, allocatable :: nodes(:)
    character(len=512) :: msg
    logical :: have_self_pair
    integer :: counts(B2B_MODEL_COUNTS_LEN)

    if (on) call b2b_model_destroy(model)
    on = .false.
    updated = .false.
    failed = .false.
    last%n = 0
    audit_total = 0
    if (.not. m%contact%enabled) return
    call get_environment_variable('B2B_DEMO_DEBUG', length=i)
    debug = i > 0
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
    if (allocated(eq_all)) deallocate (eq_all)
    allocate (eq_all(ndf, m%n_nodes))
    eq_all = reshape([(i, i = 1, ndf * m%n_nodes)], [ndf, m%n_nodes])
    on = .true.
    node = 0
    if (present(quiet)) then
      if (quiet) return
    end if
    write (*, '(a)') '  contact: curve ' // trim(m%contact%curve) // ', law ' // trim(m%contact%law) // ', penalty ' &
      // str(m%contact%penalty) // ', friction ' // str(m%contact%friction) // trim(merge(', self-contact', &
      '              ', m%contact%self_contact)) // ', ' // str(m%contact%n_pairs) // ' group pair(s), tangent ' &
      // trim(m%contact%tangent)
  end subroutine contact_hook_init

  !> Adds the contact part of the internal force to r (free dofs, numbered
  !> by eq) and to fint (all dofs), and its tangent to sys if want_tangent.
  subroutine contact_hook_forces(m, eq, want_tangent, sys, r, fint)
    type(scene_model), intent(in) :: m
    integer, intent(in) :: eq(:, :)
    logical, intent(in) :: want_tangent
    type(linear_system), intent(inout) :: sys
    real(dp), intent(inout) :: r(:), fint(:, :)
    real(dp), allocatable :: f_all(:)
    integer :: ierr, k, need, lo, hi, s, e
    character(len=512) :: msg

    failed = .false.
    if (.not. on) return
    call b2b_model_update(model, m%x, want_tangent, ierr, msg)
    if (ierr /= 0) then
      failed = .true.
      fail_msg = msg
      return
    end if
    updated = .true.
    call refresh()
    call b2b_model_add_residual(model, eq, r, ierr, msg)
    call check(ierr, msg, 'add_residual')
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
        need = 0
        do k = 1, last%n
          lo = huge(1)
          hi = 0
          do s = 1, 8
            if (last%c(k)%nodes(s) <= 0) cycle
            do e = 1, 3
              if (eq(e, last%c(k)%nodes(s)) <= 0) cycle
              lo = min(lo, eq(e, last%c(k)%nodes(s)))
              hi = max(hi, eq(e, last%c(k)%nodes(s)))
            end do
          end do
          if (hi > 0) need = max(need, hi - lo)
        end do
        sys%overflow = .true.
        sys%need = max(sys%need, need)
      else
        call check(ierr, msg, 'add_tangent_banded')
      end if
    end if
  end subroutine contact_hook_forces

  !> The active contacts and statistics of the last update into `last`.
  subroutine refresh()
    integer :: n, k, ierr
    character(len=512) :: msg
    call b2b_model_contact_count(model, n, ierr, msg)
    call check(ierr, msg, 'contact_count')
    if (.not. allocated(last%c)) allocate (last%c(max(n, 16)))
    if (size(last%c) < n) then
      deallocate (last%c)
      allocate (last%c(2 * n))
    end if
    last%n = n
    do k = 1, n
      call b2b_model_get_contact(model, k, nodes=last%c(k)%nodes, pair=last%c(k)%pair, info=last%c(k)%info, &
                                 ierr=ierr, errmsg=msg)
      call check(ierr, msg, 'get_contact ' // str(k))
    end do
    call b2b_model_stats(model, last%counts, last%totals, ierr, msg)
    call check(ierr, msg, 'stats')
    if (debug) write (*, '(a,16i5)') '      [contact counts]', last%counts
    if (debug .and. n > 0) write (*, '(a,4i4,6es12.4)') '      [c1]', last%c(1)%pair, last%c(1)%info(1:2), &
      last%c(1)%info(12:13), last%c(1)%info(3:5:2)
  end subroutine refresh

  !> Pairs of beams whose axes lie through each other in the last update
  !> (B2B_COUNT_CROSSED). Within the iterations the signed gap pushes them
  !> back; a converged state that still has one is cut back (solver): a
  !> penalty cannot resolve an axis that went through another beam.
  integer function contact_hook_crossed() result(n)
    n = 0
    if (on .and. updated) n = last%counts(B2B_IX_COUNT_CROSSED)
  end function contact_hook_crossed

  !> .true. (with the model's message) if the last update failed.
  logical function contact_hook_failed(why) result(f)
    character(len=:), allocatable, intent(out) :: why
    f = failed
    why = 'contact update failed: ' // trim(fail_msg)
  end function contact_hook_failed

  !> A number that changes when the set of active contacts (their pairs) does.
  integer(int64) function contact_hook_signature() result(h)
    integer :: k, i
    h = int(last%n, int64)
    do k = 1, last%n
      do i = 1, 4
        ! modulo a prime below 2^30, so that h * 1000003 stays far inside int64
        h = modulo(h * 1000003_int64 + int(last%c(k)%pair(i), int64), 1000000007_int64)
      end do
    end do
  end function contact_hook_signature

  !> The contacts and statistics of the last update (n = 0 before any).
  subroutine contact_hook_snapshot(s)
    type(contact_snapshot), intent(out) :: s
    s%n = last%n
    allocate (s%c(last%n))
    if (last%n > 0) s%c = last%c(1:last%n)
    s%counts = last%counts
    s%totals = last%totals
    s%audit_found = audit_total
  end subroutine contact_hook_snapshot

  !> The interpenetration audit of the converged update (before its commit,
  !> so that pairs crossed since the last commit are told): prints every pair
  !> that overlaps by more than audit_tolerance of the smaller radius with no
  !> force, and adds the count to the run's total (in the snapshot).
  subroutine contact_hook_audit(m, step)
    type(scene_model), intent(in) :: m
    integer, intent(in) :: step
    integer :: n, k, ierr
    integer, allocatable :: pairs(:, :), reasons(:)
    real(dp), allocatable :: overlap(:)
    character(len=512) :: msg
    if (.not. (on .and. m%contact%enabled .and. updated)) return
    call b2b_model_audit(model, audit_tolerance, n, ierr=ierr, errmsg=msg)
    call check(ierr, msg, 'audit')
    if (n == 0) return
    allocate (pairs(4, n), reasons(n), overlap(n))
    call b2b_model_audit(model, audit_tolerance, n, pairs, overlap, reasons, ierr, msg)
    call check(ierr, msg, 'audit')
    audit_total = audit_total + n
    write (*, '(2x,a,i0,a,i0,a)') 'audit, step ', step, ': ', n, ' pair(s) overlap with no force'
    do k = 1, n
      write (*, '(4x,a,i0,a,i0,a,i0,a,i0,a,es10.3,a,es9.2,a)') 'beam ', pairs(1, k), ' segment ', pairs(2, k), &
        ' / beam ', pairs(3, k), ' segment ', pairs(4, k), ': overlap ', overlap(k), ' (', &
        overlap(k) / min(m%beam_radius(pairs(1, k)), m%beam_radius(pairs(3, k))), ' r), ' // &
        trim(audit_reason(reasons(k)))
    end do
  end subroutine contact_hook_audit

  function audit_reason(r) result(name)
    integer, intent(in) :: r
    character(len=:), allocatable :: name
    select case (r)
    case (B2B_AUDIT_PARALLEL); name = 'parallel (below parallel_angle)'
    case (B2B_AUDIT_OUTSIDE_BOTH); name = 'outside on both sides (a convex joint or a beam end)'
    case (B2B_AUDIT_NEVER_EVALUATED); name = 'never evaluated (not a candidate of the search)'
    case (B2B_AUDIT_EXCLUDED_SELF); name = 'excluded by the self-contact length'
    case (B2B_AUDIT_CROSSED); name = 'crossed since the last commit'
    case (B2B_AUDIT_OTHER); name = 'other'
    case default; name = 'unknown reason ' // str(r)
    end select
  end function audit_reason

  subroutine contact_hook_commit(m)
    type(scene_model), intent(in) :: m
    integer :: ierr
    character(len=512) :: msg
    if (.not. (on .and. m%contact%enabled .and. updated)) return
    call b2b_model_commit(model, ierr, msg)
    call check(ierr, msg, 'commit')
    updated = .false.
  end subroutine contact_hook_commit

  subroutine contact_hook_revert(m)
    type(scene_model), intent(in) :: m
    integer :: ierr
    character(len=512) :: msg
    if (.not. (on .and. m%contact%enabled .and. updated)) return
    call b2b_model_revert(model, ierr, msg)
    call check(ierr, msg, 'revert')
    updated = .false.
    last%n = 0
  end subroutine contact_hook_revert

  !> Frees the model at the end of a run.
  subroutine contact_hook_finish()
    if (on) call b2b_model_destroy(model)
    on = .false.
    updated = .false.
    last%n = 0
  end subroutine contact_hook_finish

end module demo_contact_hook
