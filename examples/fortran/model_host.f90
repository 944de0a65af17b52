!> A small host with the contact model, in Fortran: the scene of
!> examples/c/model_host.c through module b2b (1-based node numbers, a
!> FEAP-style eq(3, n) array with 0 for constrained dofs, LAPACK dgesv).
!>
!> Beam A, an arc of radius 3 (16 hermite-nodal elements, unevenly meshed),
!> is fixed; beam B, 5 nodes across it, hangs on springs whose anchors press
!> it onto A and drag it along, with Coulomb friction (mu 0.3) and the C1
!> regularized normal law. Each load step: a predictor, then Newton with the
!> model's residual and tangent; converged steps are committed.
!> Stops with a non-zero code unless: every step converges, with exactly one
!> contact; the last step clear of round-off squares the residual
!> (r_{k+1} <= r_k^2, forces O(10)); the contact crosses at least 8 of A's
!> nodes (2 with --quick); it slips at mu f_N.
program model_host
  use b2b
  implicit none
  integer, parameter :: na = 17, nb = 5, nn = na + nb, neq = 3 * nb
  real(c_double), parameter :: pi = 3.14159265358979d0, radius_a = 3.0d0, r = 0.1d0
  real(c_double), parameter :: k_spring = 400.0d0, mu = 0.3d0, press = 0.05d0
  type(b2b_params) :: params
  type(b2b_model) :: model
  real(c_double) :: x(3, nn), anchor(3, nb), anchor_prev(3, nb), phis(na), phi, theta, dtheta
  real(c_double) :: f(neq), K(neq, neq), norms(0:40), info(B2B_PAIR_INFO_LEN), fn, tn, rho, c2
  real(c_double) :: worst_c
  integer :: eq(3, nn), ipiv(neq), lapack_info, beam, i, j, step, it, steps, n_contacts
  integer :: pair(4), seg_prev, crossings, errors, last, total_iterations, sets(0:40), n_checked
  character(len=32) :: arg
  logical :: quick, converged

  quick = .false.
  if (command_argument_count() > 0) then
    call get_command_argument(1, arg)
    quick = trim(arg) == '--quick'
  end if

  ! A's nodes on the arc, angles alternating 1.2 h and 0.8 h
  phi = 0
  do i = 1, na
    phis(i) = phi
    x(:, i) = [radius_a * cos(phi), radius_a * sin(phi), 0.0d0]
    phi = phi + merge(1.2d0, 0.8d0, mod(i, 2) == 1) * (pi / 16)
  end do
  ! equation numbers: A fixed (0), B's 15 dofs 1 .. 15
  eq = 0
  do j = 1, nb
    eq(:, na + j) = [(3 * (j - 1) + i, i = 1, 3)]
  end do

  call b2b_params_create(params)
  call b2b_params_set_real(params, 'penalty', 2.0d4)
  call b2b_params_set_int(params, 'law', B2B_LAW_QUADRATIC)
  call b2b_params_set_real(params, 'regularization_gap', 0.02d0)
  call b2b_params_set_real(params, 'friction', mu)
  call b2b_params_set_real(params, 'tangential_penalty', 2.0d4)
  call b2b_params_finalize(params)

  call b2b_model_create(model)
  call b2b_model_add_beam(model, [(i, i = 1, na)], .false., r, B2B_CURVE_HERMITE_NODAL, 0, beam)
  call b2b_model_add_beam(model, [(na + j, j = 1, nb)], .false., r, B2B_CURVE_HERMITE_NODAL, 1, &
                          beam)
  call b2b_model_set_group_pair(model, 0, 1, params)
  call b2b_model_finalize(model, nn)

  steps = merge(12, 40, quick)
  theta = 0.3d0
  dtheta = (phis(na) - 0.6d0) / 40
  errors = 0
  crossings = 0
  seg_prev = -1
  total_iterations = 0
  n_checked = 0
  worst_c = 0
  x(:, na + 1:) = 0
  anchor_prev = 0
  do step = 1, steps
    theta = theta + dtheta
    rho = radius_a + 2 * r - press
    do j = 1, nb
      anchor(:, j) = [rho * cos(theta), rho * sin(theta), 0.3d0 * (j - 3) + 0.05d0]
    end do
    if (step == 1) then
      x(:, na + 1:) = anchor
    else
      x(:, na + 1:) = x(:, na + 1:) + (anchor - anchor_prev)
    end if
    anchor_prev = anchor
    converged = .false.
    do it = 0, 39
      call b2b_model_update(model, x)
      f = k_spring * reshape(x(:, na + 1:) - anchor, [neq])
      K = 0
      do i = 1, neq
        K(i, i) = k_spring
      end do
      call b2b_model_add_residual(model, eq, f)
      call b2b_model_add_tangent_dense(model, eq, K)
      norms(it) = norm2(f)
      call b2b_model_contact_count(model, n_contacts)
      sets(it) = n_contacts
      if (n_contacts > 0) then
        call b2b_model_get_contact(model, 1, pair=pair, info=info)
        sets(it) = 100000 * n_contacts + 100 * pair(2) + nint(info(B2B_IX_INFO_FRICTION_STATE))
      end if
      if (norms(it) < 1.0d-9) then
        converged = .true.
        exit
      end if
      call dgesv(neq, 1, K, neq, ipiv, f, neq, lapack_info)
      if (lapack_info /= 0) error stop 'model_host: dgesv failed'
      x(:, na + 1:) = x(:, na + 1:) - reshape(f, [3, nb])
    end do
    total_iterations = total_iterations + it
    call b2b_model_contact_count(model, n_contacts)
    if (.not. converged .or. n_contacts /= 1) then
      write (*, '(a,i0,a,l1,a,i0)') 'model_host: step ', step, ': converged ', converged, &
        ', contacts ', n_contacts
      errors = errors + 1
      exit
    end if
    call b2b_model_get_contact(model, 1, pair=pair, info=info)
    fn = info(B2B_IX_INFO_NORMAL_FORCE)
    tn = norm2(info(B2B_IX_INFO_TANGENTIAL_FORCE:B2B_IX_INFO_TANGENTIAL_FORCE + 2))
    ! the last Newton step clear of round-off squares the residual
    last = it
    do while (last >= 0)
      if (norms(last) > 1.0d-10) exit
      last = last - 1
    end do
    if (last >= 1) then
      if (sets(last) == sets(last - 1)) then
        c2 = norms(last) / norms(last - 1)**2
        worst_c = max(worst_c, c2)
        n_checked = n_checked + 1
        if (c2 > 1) then
          write (*, '(a,i0,a)') 'model_host: step ', step, ': not quadratic'
          errors = errors + 1
        end if
      end if
    end if
    if (step > 2 .and. abs(tn / (mu * fn) - 1) > 1.0d-6) then
      write (*, '(a,i0,a)') 'model_host: step ', step, ': not slipping at mu f_N'
      errors = errors + 1
    end if
    if (seg_prev >= 0 .and. pair(2) /= seg_prev) crossings = crossings + 1
    seg_prev = pair(2)
    write (*, '(i4,f7.3,i5,4es10.2,i6,f9.3)') step, theta, it, &
      (norms(j), j = max(0, it - 3), it), pair(2), fn
    call b2b_model_commit(model)
  end do
  write (*, '(i0,a,i0,a,i0,a)') steps, ' steps, ', total_iterations, &
    ' Newton iterations, the contact crossed ', crossings, ' of A''s nodes'
  write (*, '(a,es10.3,a,i0,a)') 'quadratic convergence: r_{k+1} <= ', worst_c, &
    ' r_k^2 in the last step of all ', n_checked, ' steps checked'
  if (crossings < merge(2, 8, quick)) errors = errors + 1
  if (n_checked < steps / 2) errors = errors + 1
  call b2b_model_destroy(model)
  call b2b_params_destroy(params)
  if (errors > 0) then
    write (*, '(a)') 'model_host (Fortran): FAILED'
    error stop 1
  end if
  write (*, '(a)') 'model_host (Fortran): all checks passed'
end program
