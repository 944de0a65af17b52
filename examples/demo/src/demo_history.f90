!> What a run records: one row per converged load step (for the history CSV
!> and the per-step line) and one row per Newton iteration (convergence CSV).
module demo_history
  use demo_kinds, only: dp
  implicit none
  private

  integer, parameter, public :: max_norms = 64

  !> What the step line and the summaries print for a rate that cannot be
  !> measured (step_row%rate < 0), right-aligned like the f5.2 of a rate.
  !> UTF-8, as the trade table's "—".
  character(len=*), parameter, public :: rate_unmeasured = '   —'

  type, public :: step_row
    integer :: step = 0, iterations = 0, cutbacks = 0
    real(dp) :: lam = 0.0_dp
    real(dp) :: u(3) = 0.0_dp          !< displacement of the monitored node
    real(dp) :: rot(3) = 0.0_dp        !< rotation vector of the monitored node
    real(dp) :: last_norm = 0.0_dp, ref = 0.0_dp
    ! contact: active contacts, sum of f_N, sum of |T|, contacts in slip,
    ! handover hops; convergence rate (< 0: not measurable) and whether the
    ! active set stayed the same in the iterations it is measured on
    integer :: n_active = 0, n_slip = 0, handovers = 0
    real(dp) :: fn = 0.0_dp, ft = 0.0_dp, rate = -1.0_dp
    logical :: stable = .false.
  end type step_row

  type, public :: iter_row
    integer :: step = 0, iteration = 0
    real(dp) :: lam = 0.0_dp, norm = 0.0_dp, ref = 0.0_dp
  end type iter_row

  type, public :: run_history
    integer :: n_steps = 0, n_iters = 0
    type(step_row), allocatable :: steps(:)
    type(iter_row), allocatable :: iters(:)
  contains
    procedure :: add_step, add_iter
  end type run_history

contains

  subroutine add_step(h, row)
    class(run_history), intent(inout) :: h
    type(step_row), intent(in) :: row
    type(step_row), allocatable :: tmp(:)
    if (.not. allocated(h%steps)) allocate (h%steps(16))
    if (h%n_steps == size(h%steps)) then
      allocate (tmp(2 * size(h%steps)))
      tmp(1:h%n_steps) = h%steps(1:h%n_steps)
      call move_alloc(tmp, h%steps)
    end if
    h%n_steps = h%n_steps + 1
    h%steps(h%n_steps) = row
  end subroutine add_step

  subroutine add_iter(h, row)
    class(run_history), intent(inout) :: h
    type(iter_row), intent(in) :: row
    type(iter_row), allocatable :: tmp(:)
    if (.not. allocated(h%iters)) allocate (h%iters(64))
    if (h%n_iters == size(h%iters)) then
      allocate (tmp(2 * size(h%iters)))
      tmp(1:h%n_iters) = h%iters(1:h%n_iters)
      call move_alloc(tmp, h%iters)
    end if
    h%n_iters = h%n_iters + 1
    h%iters(h%n_iters) = row
  end subroutine add_iter

end module demo_history
