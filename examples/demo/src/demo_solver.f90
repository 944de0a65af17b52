!> Load stepping with full Newton and cut-backs.
!>
!> The load factor goes from 0 to 1 in n_steps equal steps; loads are
!> lambda f_ext, prescribed motions lambda * value. A step whose Newton
!> iteration fails (max_iter reached, a singular or non-finite system) is
!> undone (state and contact history reverted) and retried in halves; after
!> max_cutbacks halvings within one step the run stops with an error naming
!> the step. Sub-steps continue with the reduced increment until the planned
!> load factor is reached, so every planned step is reported and the checks
!> of the tests land on the load factors they ask for.
!>
!> Newton: r = f_int + f_contact - lambda f_ext on the free dofs; converged
!> when |r| <= max(tol * max(|lambda f_ext|, |f_int| over all dofs), noise)
!> (the second term includes the reactions, the scale of a run driven by
!> motions only). noise is the residual's round-off: an element's axial
!> force EA (l - l0)/l0 carries the rounding of the coordinates, about
!> EA/l0 * eps * |x|, and slender sections (EA/EI = 1/r^2 large) make that
!> floor larger than tol * ref; below it Newton can only wander, so
!> noise = 2 eps sqrt(n_elements) max(EA/l0) max|x| ends the iteration there.
!> Update: x <- x + du, R <- exp(S(dw)) R with the spin dw solved for.
module demo_solver
  use demo_kinds, only: dp, ndf
  use demo_model, only: scene_model
  use demo_rotation, only: quat_spin_update, quat_to_rotvec
  use demo_numbering, only: rcm_order, number_equations, half_bandwidth
  use demo_linear_system, only: linear_system, sys_setup, sys_solve
  use demo_assembly, only: assemble
  use demo_contact_hook, only: contact_hook_init, contact_hook_commit, contact_hook_revert
  use demo_history, only: run_history, step_row, iter_row
  use demo_output, only: output_begin, output_step, output_finish
  use demo_errors, only: fatal, str
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  implicit none
  private
  public :: solve_scene, step_callback, newton_state

  abstract interface
    !> Called after each planned step has converged (tests check the state).
    subroutine step_callback(m, step, lam)
      import :: scene_model, dp
      type(scene_model), intent(in) :: m
      integer, intent(in) :: step
      real(dp), intent(in) :: lam
    end subroutine step_callback
  end interface

  !> Everything the Newton loop needs besides the model.
  type :: newton_state
    integer, allocatable :: eq(:, :)
    integer :: neq = 0, hb = 0
    type(linear_system) :: sys
    real(dp), allocatable :: r(:), fint(:, :)
  end type newton_state

contains

  subroutine solve_scene(m, on_step, quiet)
    type(scene_model), intent(inout) :: m
    procedure(step_callback), optional :: on_step
    logical, intent(in), optional :: quiet
    type(newton_state) :: ns
    type(run_history) :: hist
    integer, allocatable :: order(:)
    real(dp), allocatable :: x_save(:, :), q_save(:, :)
    real(dp) :: lam, lam_target, dlam, norms(64)
    integer :: step, cut, iters, n_norms, sub_iters
    logical :: ok, talk
    type(step_row) :: row
    character(len=:), allocatable :: why

    talk = .true.
    if (present(quiet)) talk = .not. quiet

    allocate (order(m%n_nodes), ns%eq(ndf, m%n_nodes), ns%fint(ndf, m%n_nodes))
    call rcm_order(m%n_nodes, m%conn, order)
    call number_equations(order, m%fixed, ns%eq, ns%neq)
    ns%hb = half_bandwidth(ns%eq, m%conn)
    call sys_setup(ns%sys, ns%neq, ns%hb, m%solver)
    allocate (ns%r(ns%neq))
    if (talk) write (*, '(a)') trim(m%name) // ': ' // trim(m%title)
    if (talk) write (*, '(2x,i0,a,i0,a,i0,a,i0,a,a)') m%n_nodes, ' nodes, ', m%n_elements, ' elements, ', ns%neq, &
      ' equations, half bandwidth ', ns%hb, ', solver ', trim(merge('dense dgesv  ', 'banded dgbsv ', ns%sys%dense))
    call contact_hook_init(m)
    call output_begin(m)
    call output_step(m, 0, 0.0_dp)

    lam = 0.0_dp
    n_norms = 0
    norms = 0.0_dp
    do step = 1, m%n_steps
      lam_target = real(step, dp) / real(m%n_steps, dp)
      dlam = lam_target - lam
      cut = 0
      iters = 0
      do while (lam_target - lam > 1.0e-12_dp)
        dlam = min(dlam, lam_target - lam)
        x_save = m%x
        q_save = m%q
        call newton(m, ns, hist, step, lam, lam + dlam, ok, sub_iters, norms, n_norms, why)
        iters = iters + sub_iters
        if (ok) then
          call contact_hook_commit(m)
          lam = lam + dlam
        else
          m%x = x_save
          m%q = q_save
          call contact_hook_revert(m)
          cut = cut + 1
          if (talk) write (*, '(2x,a,i0,a,f8.6,a,f8.6,a,4es10.2)') 'step ', step, ': no convergence from load ', lam, &
            ' to ', lam + dlam, ' (' // why // '), cutting the increment in half; |r|:', &
            norms(max(1, n_norms - 3):n_norms)
          if (cut > m%max_cutbacks) call fatal(trim(m%file) // ': load step ' // str(step) // ' (load factor ' &
            // str(lam) // ' to ' // str(lam_target) // ') did not converge after ' // str(m%max_cutbacks) &
            // ' cut-backs (last try: ' // why // '); no result written. Change: more n_steps or max_iter in' &
            // ' &scene, or check supports and loads')
          dlam = 0.5_dp * dlam
        end if
      end do
      if (abs(lam - lam_target) < 1.0e-12_dp) lam = lam_target

      row%step = step
      row%lam = lam
      row%iterations = iters
      row%cutbacks = cut
      row%last_norm = norms(max(n_norms, 1))
      row%ref = hist%iters(hist%n_iters)%ref
      row%u = m%x(:, m%monitor_node) - m%x0(:, m%monitor_node)
      row%rot = quat_to_rotvec(m%q(:, m%monitor_node))
      call hist%add_step(row)
      if (talk) call step_line(row, norms(max(1, n_norms - 3):n_norms))
      if (mod(step, m%vtk_every) == 0 .or. step == m%n_steps) call output_step(m, step, lam)
      if (present(on_step)) call on_step(m, step, lam)
    end do
    call output_finish(m, hist)
  end subroutine solve_scene

  !> One (sub)step from lam_old to lam_new. ok = .false. with a reason if it fails.
  subroutine newton(m, ns, hist, step, lam_old, lam_new, ok, iters, norms, n_norms, why)
    type(scene_model), intent(inout) :: m
    type(newton_state), intent(inout) :: ns
    type(run_history), intent(inout) :: hist
    integer, intent(in) :: step
    real(dp), intent(in) :: lam_old, lam_new
    logical, intent(out) :: ok
    integer, intent(out) :: iters, n_norms
    real(dp), intent(out) :: norms(:)
    character(len=:), allocatable, intent(out) :: why
    integer :: it, node, info
    real(dp) :: nrm, ref, noise
    type(iter_row) :: irow

    ok = .false.
    why = 'max_iter reached'
    n_norms = 0
    iters = 0
    call prescribe(m, lam_new - lam_old)
    do it = 1, m%max_iter + 1
      call assemble(m, ns%eq, lam_new, .true., ns%sys, ns%r, ns%fint)
      if (ns%sys%overflow) then
        ! couplings beyond the band (contacts between distant nodes): widen and redo
        ns%hb = max(ns%hb, ns%sys%need)
        call sys_setup(ns%sys, ns%neq, ns%hb, m%solver)
        call assemble(m, ns%eq, lam_new, .true., ns%sys, ns%r, ns%fint)
      end if
      nrm = norm2(ns%r)
      ref = max(lam_new * norm2(m%fext), norm2(ns%fint))
      noise = 2.0_dp * epsilon(1.0_dp) * sqrt(real(m%n_elements, dp)) * maxval(m%el_stiff(1, :) / m%el_l0) &
              * maxval(abs(m%x))
      n_norms = min(n_norms + 1, size(norms))
      if (n_norms == size(norms)) norms(1:n_norms - 1) = norms(2:n_norms)
      norms(n_norms) = nrm
      irow = iter_row(step=step, iteration=it - 1, lam=lam_new, norm=nrm, ref=ref)
      call hist%add_iter(irow)
      if (.not. ieee_is_finite(nrm)) then
        why = 'non-finite residual'
        return
      end if
      if (nrm <= max(m%tol * ref, noise)) then
        ok = .true.
        return
      end if
      if (it > m%max_iter) exit
      ns%r = -ns%r
      call sys_solve(ns%sys, ns%r, info)
      if (info /= 0) then
        why = 'singular Newton matrix at equation ' // str(info) // ' (a free rigid motion? check supports)'
        return
      end if
      iters = it
      do node = 1, m%n_nodes
        call update_node(m, ns%eq(:, node), node, ns%r)
      end do
    end do
  end subroutine newton

  subroutine update_node(m, e, node, du)
    type(scene_model), intent(inout) :: m
    integer, intent(in) :: e(ndf), node
    real(dp), intent(in) :: du(:)
    real(dp) :: w(3)
    integer :: d
    do d = 1, 3
      if (e(d) > 0) m%x(d, node) = m%x(d, node) + du(e(d))
    end do
    w = 0.0_dp
    do d = 1, 3
      if (e(3 + d) > 0) w(d) = du(e(3 + d))
    end do
    if (any(e(4:6) > 0)) m%q(:, node) = quat_spin_update(m%q(:, node), w)
  end subroutine update_node

  !> Increments of the prescribed motions (fixed dofs with a value): a
  !> translation adds, a rotation is applied as a spin about the global axis.
  subroutine prescribe(m, dlam)
    type(scene_model), intent(inout) :: m
    real(dp), intent(in) :: dlam
    integer :: node
    do node = 1, m%n_nodes
      m%x(:, node) = m%x(:, node) + dlam * m%prescribed(1:3, node)
      if (any(abs(m%prescribed(4:6, node)) > 0.0_dp)) &
        m%q(:, node) = quat_spin_update(m%q(:, node), dlam * m%prescribed(4:6, node))
    end do
  end subroutine prescribe

  subroutine step_line(row, last)
    type(step_row), intent(in) :: row
    real(dp), intent(in) :: last(:)
    character(len=200) :: buf
    write (buf, '(a,i4,a,f9.5,a,i3,a,i2,a)') 'step', row%step, '  load', row%lam, '  iterations', row%iterations, &
      '  cut-backs', row%cutbacks, '  |r|:'
    write (*, '(2x,a,4es10.2)') trim(buf), last
  end subroutine step_line

end module demo_solver
