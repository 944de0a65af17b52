!> The demo's extras around the contact hook (demo_contact_hook): what the
!> demo reads from the contact model for its output, checks and tests, and
!> a host does not need to couple it. Every routine only reads the model.
!>
!>  * contact_report_begin(m, quiet) at the start of a run: forgets the
!>    last run's contacts and audit count, prints the contact settings.
!>  * contact_report_refresh(model) after each successful update: the
!>    active contacts (b2b_model_get_contact) and the statistics
!>    (b2b_model_stats) into a snapshot; with B2B_DEMO_DEBUG=1 in the
!>    environment the counts and the first contact are printed.
!>  * contact_report_forget() on a revert (the contacts are gone).
!>  * contact_report_signature(): a number that changes with the active set
!>    (the convergence rate is checked only where it stays the same).
!>  * contact_report_snapshot(s): the contacts and counts of the last update,
!>    for the output (VTK vertices, contacts CSV) and the checks.
!>  * contact_report_audit(model, m, step) after a converged (sub)step,
!>    before its commit: b2b_model_audit (tolerance audit_tolerance of the
!>    smaller radius) lists the pairs that overlap with no force; each is
!>    printed, and the count goes into the snapshot, which the scene check
!>    fails on (demo_checks).
module demo_contact_report
  use demo_kinds, only: dp
  use demo_model, only: scene_model
  use demo_errors, only: fatal, str
  use b2b, only: b2b_model, b2b_model_contact_count, b2b_model_get_contact, b2b_model_stats, b2b_model_audit, &
                 B2B_AUDIT_OTHER, B2B_AUDIT_PARALLEL, B2B_AUDIT_OUTSIDE_BOTH, B2B_AUDIT_NEVER_EVALUATED, &
                 B2B_AUDIT_EXCLUDED_SELF, B2B_AUDIT_CROSSED
  use, intrinsic :: iso_fortran_env, only: int64
  implicit none
  private
  public :: contact_report_begin, contact_report_refresh, contact_report_forget, contact_report_signature
  public :: contact_report_snapshot, contact_report_audit

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

  logical, save :: debug = .false.
  type(contact_snapshot), save :: last
  integer, save :: audit_total = 0     !< findings of every audit since contact_report_begin

contains

  subroutine check(ierr, errmsg, what)
    integer, intent(in) :: ierr
    character(len=*), intent(in) :: errmsg, what
    if (ierr /= 0) call fatal('contact model: ' // what // ': ' // trim(errmsg))
  end subroutine check

  !> A new run: no contacts, no audit findings; the contact line unless quiet.
  subroutine contact_report_begin(m, quiet)
    type(scene_model), intent(in) :: m
    logical, intent(in) :: quiet
    integer :: i
    last%n = 0
    audit_total = 0
    if (.not. m%contact%enabled) return
    call get_environment_variable('B2B_DEMO_DEBUG', length=i)
    debug = i > 0
    if (quiet) return
    write (*, '(a)') '  contact: curve ' // trim(m%contact%curve) // ', law ' // trim(m%contact%law) // ', penalty ' &
      // str(m%contact%penalty) // ', friction ' // str(m%contact%friction) // trim(merge(', self-contact', &
      '              ', m%contact%self_contact)) // ', ' // str(m%contact%n_pairs) // ' group pair(s), tangent ' &
      // trim(m%contact%tangent)
  end subroutine contact_report_begin

  !> The active contacts and statistics of the last update into `last`.
  subroutine contact_report_refresh(model)
    type(b2b_model), intent(in) :: model
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
  end subroutine contact_report_refresh

  !> After a revert: the contacts of the reverted updates are gone.
  subroutine contact_report_forget()
    last%n = 0
  end subroutine contact_report_forget

  !> A number that changes when the set of active contacts (their pairs) does.
  integer(int64) function contact_report_signature() result(h)
    integer :: k, i
    h = int(last%n, int64)
    do k = 1, last%n
      do i = 1, 4
        ! modulo a prime below 2^30, so that h * 1000003 stays far inside int64
        h = modulo(h * 1000003_int64 + int(last%c(k)%pair(i), int64), 1000000007_int64)
      end do
    end do
  end function contact_report_signature

  !> The contacts and statistics of the last update (n = 0 before any).
  subroutine contact_report_snapshot(s)
    type(contact_snapshot), intent(out) :: s
    s%n = last%n
    allocate (s%c(last%n))
    if (last%n > 0) s%c = last%c(1:last%n)
    s%counts = last%counts
    s%totals = last%totals
    s%audit_found = audit_total
  end subroutine contact_report_snapshot

  !> The interpenetration audit of the converged update (before its commit,
  !> so that pairs crossed since the last commit are told): prints every pair
  !> that overlaps by more than audit_tolerance of the smaller radius with no
  !> force, and adds the count to the run's total (in the snapshot).
  subroutine contact_report_audit(model, m, step)
    type(b2b_model), intent(in) :: model
    type(scene_model), intent(in) :: m
    integer, intent(in) :: step
    integer :: n, k, ierr
    integer, allocatable :: pairs(:, :), reasons(:)
    real(dp), allocatable :: overlap(:)
    character(len=512) :: msg
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
  end subroutine contact_report_audit

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

end module demo_contact_report
