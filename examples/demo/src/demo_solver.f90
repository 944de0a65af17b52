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
!> noise = 2 eps sqrt(n_elements) k max|x| ends the iteration there, with k
!> the stiffest element stiffness, max(EA/l0, 12 EI/l0^3) (bending governs
!> for thick or built-up sections).
!> Update: x <- x + du, R <- exp(S(dw)) R with the spin dw solved for.
module demo_solver
  use demo_kinds, only: dp, ndf
  use demo_model, only: scene_model, ramp_value, external_force
  use demo_rotation, only: quat_spin_update, quat_to_rotvec
  use demo_numbering, only: rcm_order, number_equations, half_bandwidth
  use demo_linear_system, only: linear_system, sys_setup, sys_solve
  use demo_assembly, only: assemble
  use demo_contact_hook, only: contact_hook_build, contact_hook_commit, contact_hook_revert, contact_hook_crossed
  use demo_contact_report, only: contact_report_begin, contact_report_refresh, contact_report_forget, &
                                 contact_report_signature, contact_report_snapshot, contact_snapshot, &
                                 contact_report_audit
  use b2b, only: b2b_model, b2b_model_destroy
  use demo_history, only: run_history, step_row, iter_row, rate_unmeasured
  use demo_output, only: output_begin, output_step, output_finish, output_contacts
  use demo_checks, only: check_step
  use, intrinsic :: iso_fortran_env, only: int64
  use demo_errors, only: fatal, str
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  implicit none
  private
  public :: solve_scene, step_callback, newton_state, perturb_dof, convergence_rate

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

  !> Solves the scene. Optional, for programs that run many scenes in one
  !> process (the trade table): quiet (no per-step lines), history (the
  !> step rows of the run) and failed_step: when present, a step that does
  !> not converge within max_cutbacks ends the run with failed_step = that
  !> step (and no .pvd or CSV written) instead of stopping the program;
  !> 0 when every step converged. model: the contact model, for a caller
  !> that uses it after the run (and destroys it); without it the run's own
  !> model is destroyed at its end.
  subroutine solve_scene(m, on_step, quiet, history, failed_step, model)
    type(scene_model), intent(inout) :: m
    procedure(step_callback), optional :: on_step
    logical, intent(in), optional :: quiet
    type(run_history), intent(out), optional :: history
    integer, intent(out), optional :: failed_step
    type(b2b_model), intent(inout), optional :: model
    type(b2b_model) :: own
    if (present(model)) then
      call solve_with(m, model, on_step, quiet, history, failed_step)
    else
      call solve_with(m, own, on_step, quiet, history, failed_step)
      call b2b_model_destroy(own)
    end if
  end subroutine solve_scene

  subroutine solve_with(m, model, on_step, quiet, history, failed_step)
    type(scene_model), intent(inout) :: m
    type(b2b_model), intent(inout) :: model
    procedure(step_callback), optional :: on_step
    logical, intent(in), optional :: quiet
    type(run_history), intent(out), optional :: history
    integer, intent(out), optional :: failed_step
    type(newton_state) :: ns
    type(run_history) :: hist
    integer, allocatable :: order(:)
    real(dp), allocatable :: x_save(:, :), q_save(:, :)
    real(dp) :: lam, lam_target, dlam, norms(64), floor
    integer(int64) :: sigs(64)
    integer :: step, cut, iters, n_norms, sub_iters, k
    logical :: ok, talk
    type(step_row) :: row
    character(len=:), allocatable :: why
    type(contact_snapshot) :: snap

    talk = .true.
    if (present(quiet)) talk = .not. quiet
    if (present(failed_step)) failed_step = 0

    allocate (order(m%n_nodes), ns%eq(ndf, m%n_nodes), ns%fint(ndf, m%n_nodes))
    call rcm_order(m%n_nodes, m%conn, order)
    call number_equations(order, m%fixed, ns%eq, ns%neq)
    ns%hb = half_bandwidth(ns%eq, m%conn)
    call sys_setup(ns%sys, ns%neq, ns%hb, m%solver)
    allocate (ns%r(ns%neq))
    if (talk) write (*, '(a)') trim(m%name) // ': ' // trim(m%title)
    if (talk) write (*, '(2x,i0,a,i0,a,i0,a,i0,a,a)') m%n_nodes, ' nodes, ', m%n_elements, ' elements, ', ns%neq, &
      ' equations, half bandwidth ', ns%hb, ', solver ', trim(merge('dense dgesv  ', 'banded dgbsv ', ns%sys%dense))
    if (m%contact%enabled) call contact_hook_build(model, m)
    call contact_report_begin(m, quiet=.not. talk)
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
        call newton(m, model, ns, hist, step, lam, lam + dlam, ok, sub_iters, norms, sigs, n_norms, floor, why)
        floor = rounding_floor(m)
        iters = iters + sub_iters
        if (ok) then
          if (m%contact%enabled) call contact_report_audit(model, m, step)
          call contact_report_snapshot(snap)
          if (m%contact%enabled) call contact_hook_commit(model)
          lam = lam + dlam
        else
          m%x = x_save
          m%q = q_save
          if (m%contact%enabled) call contact_hook_revert(model)
          call contact_report_forget()
          cut = cut + 1
          if (talk) write (*, '(2x,a,i0,a,f8.6,a,f8.6,a,4es10.2)') 'step ', step, ': no convergence from load ', lam, &
            ' to ', lam + dlam, ' (' // why // '), cutting the increment in half; |r|:', &
            norms(max(1, n_norms - 3):n_norms)
          if (cut > m%max_cutbacks .and. present(failed_step)) then
            failed_step = step
            if (present(history)) history = hist
            return
          end if
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
      call convergence_rate(norms(1:n_norms), sigs(1:n_norms), floor, row%rate, row%stable)
      row%n_active = snap%n
      row%fn = 0.0_dp
      row%ft = 0.0_dp
      row%n_slip = 0
      do k = 1, snap%n
        row%fn = row%fn + snap%c(k)%info(13)
        row%ft = row%ft + norm2(snap%c(k)%info(18:20))
        if (nint(snap%c(k)%info(24)) == 2) row%n_slip = row%n_slip + 1
      end do
      row%handovers = snap%counts(11)
      call hist%add_step(row)
      call output_contacts(step, lam, snap)
      if (talk) call step_line(row, norms(max(1, n_norms - 3):n_norms), m%contact%enabled)
      call check_step(m, row, snap, ns%fint)
      if (mod(step, m%vtk_every) == 0 .or. step == m%n_steps) call output_step(m, step, lam)
      if (present(on_step)) call on_step(m, step, lam)
    end do
    call output_finish(m, hist)
    if (present(history)) history = hist
  end subroutine solve_with

  !> One (sub)step from lam_old to lam_new. ok = .false. with a reason if it fails.
  subroutine newton(m, model, ns, hist, step, lam_old, lam_new, ok, iters, norms, sigs, n_norms, noise, why)
    type(scene_model), intent(inout) :: m
    type(b2b_model), intent(inout) :: model
    type(newton_state), intent(inout) :: ns
    type(run_history), intent(inout) :: hist
    integer, intent(in) :: step
    real(dp), intent(in) :: lam_old, lam_new
    logical, intent(out) :: ok
    integer, intent(out) :: iters, n_norms
    real(dp), intent(out) :: norms(:), noise
    integer(int64), intent(out) :: sigs(:)
    character(len=:), allocatable, intent(out) :: why
    integer :: it, node, info, widen
    character(len=:), allocatable :: cwhy
    logical :: cok
    real(dp) :: nrm, ref, extent
    type(iter_row) :: irow

    ok = .false.
    why = 'max_iter reached'
    n_norms = 0
    iters = 0
    noise = 0.0_dp
    call prescribe(m, lam_old, lam_new)
    do it = 1, m%max_iter + 1
      call assemble(m, ns%eq, lam_new, .true., ns%sys, ns%r, ns%fint, model, cok, cwhy)
      widen = 0
      do
        if (.not. ns%sys%overflow) exit
        if (.not. cok) exit
        ! couplings beyond the band (contacts between distant nodes): widen and redo
        widen = widen + 1
        if (widen > 2) call fatal(trim(m%file) // ': the band could not be widened to hold the contacts')
        ns%hb = max(ns%hb, ns%sys%need)
        call sys_setup(ns%sys, ns%neq, ns%hb, m%solver)
        call assemble(m, ns%eq, lam_new, .true., ns%sys, ns%r, ns%fint, model, cok, cwhy)
      end do
      if (.not. cok) then
        why = cwhy
        return
      end if
      if (m%contact%enabled) call contact_report_refresh(model)
      nrm = norm2(ns%r)
      ref = max(norm2(external_force(m, lam_new)), norm2(ns%fint))
      ! the floor scales with the coordinates, capped at 10 times the scene's
      ! size: an iterate thrown far away (a body left without support) must
      ! not raise its own convergence floor
      extent = max(maxval(abs(m%x0)), maxval(m%el_l0))
      noise = 2.0_dp * sqrt(real(m%n_elements, dp)) * rounding_floor(m) * min(maxval(abs(m%x)), 10.0_dp * extent) &
              / max(maxval(abs(m%x)), tiny(1.0_dp))
      n_norms = min(n_norms + 1, size(norms))
      if (n_norms == size(norms)) then
        norms(1:n_norms - 1) = norms(2:n_norms)
        sigs(1:n_norms - 1) = sigs(2:n_norms)
      end if
      norms(n_norms) = nrm
      sigs(n_norms) = contact_report_signature()
      irow = iter_row(step=step, iteration=it - 1, lam=lam_new, norm=nrm, ref=ref)
      call hist%add_iter(irow)
      if (.not. ieee_is_finite(nrm)) then
        why = 'non-finite residual'
        return
      end if
      if (maxval(abs(m%x - m%x0)) > 100.0_dp * extent) then
        why = 'diverged: a node moved more than 100 times the size of the scene'
        return
      end if
      if (nrm <= max(m%tol * ref, noise)) then
        ! Converged, but with beams whose axes passed through each other
        ! (B2B_COUNT_CROSSED): the step was too large for the contact to
        ! catch them, cut back.
        if (m%contact%enabled) then
          if (contact_hook_crossed(model) > 0) then
            why = str(contact_hook_crossed(model)) // ' pair(s) of beams passed through each other'
            return
          end if
        end if
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

  !> Moves one generalized dof d (1..6) of a node by s: a translation along
  !> axis d, or a spin s about global axis d - 3 (as update_node does for a
  !> whole increment). For tests that difference the assembled residual.
  subroutine perturb_dof(m, node, d, s)
    type(scene_model), intent(inout) :: m
    integer, intent(in) :: node, d
    real(dp), intent(in) :: s
    real(dp) :: w(3)
    if (d <= 3) then
      m%x(d, node) = m%x(d, node) + s
    else
      w = 0.0_dp
      w(d - 3) = s
      m%q(:, node) = quat_spin_update(m%q(:, node), w)
    end if
  end subroutine perturb_dof

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

  !> Increments of the prescribed motions (fixed dofs with a value) from load
  !> factor t0 to t1, each through its ramp: a translation adds, a rotation
  !> is applied as a spin about the global axis.
  subroutine prescribe(m, t0, t1)
    type(scene_model), intent(inout) :: m
    real(dp), intent(in) :: t0, t1
    integer :: node, d
    real(dp) :: inc(6)
    do node = 1, m%n_nodes
      do d = 1, 6
        inc(d) = 0.0_dp
        if (abs(m%prescribed(d, node)) > 0.0_dp) inc(d) = m%prescribed(d, node) &
          * (ramp_value(m, m%presc_ramp(d, node), t1) - ramp_value(m, m%presc_ramp(d, node), t0))
      end do
      m%x(:, node) = m%x(:, node) + inc(1:3)
      if (any(abs(inc(4:6)) > 0.0_dp)) m%q(:, node) = quat_spin_update(m%q(:, node), inc(4:6))
    end do
  end subroutine prescribe

  !> Convergence rate of a converged step from its residual norms:
  !> p = log(r_k / r_(k-1)) / log(r_(k-1) / r_(k-2)) on the last three norms
  !> after the first (r_0, the residual of the load or motion increment
  !> before any correction, is the size of the step, not a Newton iterate)
  !> and above the round-off floor (the final norms are dropped while they
  !> lie within 3 times the floor of rounding_floor, where they measure the
  !> rounding, not the iteration; a zero norm is always dropped).
  !> rate < 0 (printed "rate —"): not measurable, fewer than three usable
  !> norms after r_0. rate = 0: measured, but the three norms did not
  !> decrease (no convergence order). stable: the active contacts (their
  !> pairs) were the same in those iterations.
  subroutine convergence_rate(norms, sigs, floor, rate, stable)
    real(dp), intent(in) :: norms(:), floor
    integer(int64), intent(in) :: sigs(:)
    real(dp), intent(out) :: rate
    logical, intent(out) :: stable
    integer :: n
    n = size(norms)
    rate = -1.0_dp
    stable = .false.
    do while (n >= 1)
      if (norms(n) > 3.0_dp * floor .and. norms(n) > 0.0_dp) exit
      n = n - 1
    end do
    if (n < 4) return
    if (.not. (norms(n - 1) < norms(n - 2) .and. norms(n) < norms(n - 1))) then
      rate = 0.0_dp
    else
      rate = log(norms(n) / norms(n - 1)) / log(norms(n - 1) / norms(n - 2))
    end if
    stable = all(sigs(n - 2:size(sigs)) == sigs(size(sigs)))
  end subroutine convergence_rate

  !> The rounding level of the residual: an element force carries the
  !> rounding of the coordinates, eps |x|, times the element's stiffest
  !> translational stiffness, axial EA/l0 or bending 12 EI/l0^3.
  real(dp) function rounding_floor(m) result(f)
    type(scene_model), intent(in) :: m
    real(dp) :: k
    integer :: el
    k = 0.0_dp
    do el = 1, m%n_elements
      k = max(k, m%el_stiff(1, el) / m%el_l0(el), 12.0_dp * maxval(m%el_stiff(3:4, el)) / m%el_l0(el)**3)
    end do
    f = epsilon(1.0_dp) * maxval(abs(m%x)) * k
  end function rounding_floor

  subroutine step_line(row, last, contact)
    type(step_row), intent(in) :: row
    real(dp), intent(in) :: last(:)
    logical, intent(in) :: contact
    character(len=200) :: buf
    character(len=120) :: cbuf
    write (buf, '(a,i4,a,f9.5,a,i3,a,i2,a)') 'step', row%step, '  load', row%lam, '  iterations', row%iterations, &
      '  cut-backs', row%cutbacks, '  |r|:'
    cbuf = ''
    if (contact) then
      write (cbuf, '(a,i3,a,es10.3,a,es10.3)') '  contacts', row%n_active, '  f_N', row%fn, '  f_T', row%ft
      if (row%rate >= 0.0_dp) then
        write (cbuf(len_trim(cbuf) + 1:), '(a,f5.2,a)') '  rate', row%rate, trim(merge('  ', ' *', row%stable))
      else
        cbuf = trim(cbuf) // '  rate ' // rate_unmeasured   ! fewer than three usable norms
      end if
    end if
    write (*, '(2x,a,4es10.2)', advance='no') trim(buf), last
    write (*, '(a)') trim(cbuf)
  end subroutine step_line

end module demo_solver
