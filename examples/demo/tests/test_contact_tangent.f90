!> The assembled Newton matrix WITH contact (beams + b2b_model_add_tangent_*)
!> against central finite differences of the assembled residual (beams +
!> b2b_model_add_residual), at the converged end state of a contact scene
!> moved off equilibrium by a small smooth perturbation (so that no contact
!> opens or closes under the differences). The model is used exactly as in
!> the program: update at every assembly, no commit between the
!> evaluations (the tangent is the derivative with the committed history
!> fixed, which is what the differences see).
!> Asserts max |K - K_fd| / max |K| <= tol (second argument, default 1e-6)
!> and that the state has active contacts.
program test_contact_tangent
  use demo_kinds, only: dp, ndf
  use demo_model, only: scene_model
  use demo_scene_reader, only: read_scene
  use demo_solver, only: solve_scene, perturb_dof
  use demo_numbering, only: rcm_order, number_equations, half_bandwidth
  use demo_linear_system, only: linear_system, sys_setup
  use demo_assembly, only: assemble
  use demo_contact_report, only: contact_snapshot, contact_report_snapshot, contact_report_refresh
  use b2b, only: b2b_model, b2b_model_destroy
  implicit none
  type(scene_model) :: m
  type(b2b_model) :: model
  type(linear_system) :: dense, dummy
  type(contact_snapshot) :: snap, snap2
  character(len=1024) :: file, arg
  integer, allocatable :: order(:), eq(:, :)
  real(dp), allocatable :: r(:), rp(:), rm(:), fint(:, :), kfd(:, :), x_keep(:, :), q_keep(:, :)
  integer :: neq, hb, node, d, j, worst_i, worst_j
  real(dp) :: h, err, tol, amp
  logical :: ok

  call get_command_argument(1, file)
  tol = 1.0e-6_dp
  if (command_argument_count() >= 2) then
    call get_command_argument(2, arg)
    read (arg, *) tol
  end if
  call read_scene(trim(file), m)
  m%vtk = .false.
  m%csv = .false.
  call solve_scene(m, quiet=.true., model=model)

  allocate (order(m%n_nodes), eq(ndf, m%n_nodes), fint(ndf, m%n_nodes))
  call rcm_order(m%n_nodes, m%conn, order)
  call number_equations(order, m%fixed, eq, neq)
  hb = half_bandwidth(eq, m%conn)
  allocate (r(neq), rp(neq), rm(neq), kfd(neq, neq))

  ! off equilibrium: a smooth perturbation of 1e-5 of the beams' size
  amp = 1.0e-5_dp * maxval(m%el_l0)
  do node = 1, m%n_nodes
    if (any(eq(1:3, node) > 0)) m%x(:, node) = m%x(:, node) + amp * [sin(1.3_dp * node), cos(0.7_dp * node), &
                                                                      sin(0.4_dp * node + 1.0_dp)]
  end do
  call sys_setup(dense, neq, neq, 'dense')
  call sys_setup(dummy, neq, neq, 'dense')
  call assemble(m, eq, 1.0_dp, .true., dense, r, fint, model)
  call contact_report_refresh(model)
  call contact_report_snapshot(snap)
  x_keep = m%x
  q_keep = m%q
  h = 1.0e-7_dp * maxval(m%el_l0)
  do node = 1, m%n_nodes
    do d = 1, ndf
      j = eq(d, node)
      if (j == 0) cycle
      call perturb_dof(m, node, d, +h)
      call assemble(m, eq, 1.0_dp, .false., dummy, rp, fint, model)
      m%x = x_keep; m%q = q_keep
      call perturb_dof(m, node, d, -h)
      call assemble(m, eq, 1.0_dp, .false., dummy, rm, fint, model)
      call contact_report_refresh(model)
      call contact_report_snapshot(snap2)
      m%x = x_keep; m%q = q_keep
      if (snap2%n /= snap%n) then
        write (*, '(a)') 'FAIL: the active set changed under the differences; perturb less'
        error stop 1
      end if
      kfd(:, j) = (rp - rm) / (2.0_dp * h)
    end do
  end do
  err = maxval(abs(dense%a - kfd)) / maxval(abs(dense%a))
  worst_i = maxloc(maxval(abs(dense%a - kfd), dim=2), dim=1)
  worst_j = maxloc(abs(dense%a(worst_i, :) - kfd(worst_i, :)), dim=1)
  write (*, '(a,a,i0,a,i0,a,es10.3,a,2i5)') trim(m%name), ': ', snap%n, ' active contacts, ', neq, &
    ' equations; assembled tangent with contact vs central differences: relative error ', err, &
    ', worst entry (row, col)', worst_i, worst_j
  ok = err <= tol .and. snap%n > 0
  ! freed here, not left to the end of the program (LeakSanitizer counts them)
  deallocate (order, eq, fint, r, rp, rm, kfd, x_keep, q_keep)
  call b2b_model_destroy(model)
  if (.not. ok) then
    write (*, '(a,es9.2)') 'FAIL: tangent with contact differs from the differences by more than ', tol
    error stop 1
  end if
  write (*, '(a)') 'contact tangent: passed'

end program test_contact_tangent
