!> Global internal force, residual and Newton matrix.
!>   r = f_int(x, R) + f_contact(x) - lambda f_ext   on the free dofs,
!>   K = d r / d(u, spin)                            (assembled into sys),
!> and f_int on every dof (fint, whose constrained entries are the reactions).
!> The contact part comes from the contact model, when one is given (the
!> caller's, built by demo_contact_hook) and the scene has contact.
module demo_assembly
  use demo_kinds, only: dp, ndf
  use demo_model, only: scene_model, external_force
  use demo_rotation, only: quat_to_matrix
  use demo_beam_element, only: beam_element
  use demo_linear_system, only: linear_system, sys_zero, sys_add
  use demo_contact_hook, only: contact_hook_forces
  use b2b, only: b2b_model
  implicit none
  private
  public :: assemble

contains

  !> ok = .false. (why: the model's message) if the contact update failed.
  subroutine assemble(m, eq, lam, want_tangent, sys, r, fint, model, ok, why)
    type(scene_model), intent(in) :: m
    integer, intent(in) :: eq(:, :)
    real(dp), intent(in) :: lam
    logical, intent(in) :: want_tangent
    type(linear_system), intent(inout) :: sys
    real(dp), intent(out) :: r(:), fint(:, :)
    type(b2b_model), intent(inout), optional :: model
    logical, intent(out), optional :: ok
    character(len=:), allocatable, intent(out), optional :: why
    logical :: c_ok
    character(len=:), allocatable :: c_why
    real(dp) :: fe(12), ke(12, 12), ta(3, 3), tb(3, 3)
    integer :: el, a, b, i, j, ei, ej, node, d
    integer :: dof_node(12), dof_d(12)
    real(dp) :: fext(ndf, m%n_nodes)

    r = 0.0_dp
    fint = 0.0_dp
    if (want_tangent) call sys_zero(sys)
    do el = 1, m%n_elements
      a = m%conn(1, el)
      b = m%conn(2, el)
      ta = matmul(quat_to_matrix(m%q(:, a)), m%el_frame(:, :, el))
      tb = matmul(quat_to_matrix(m%q(:, b)), m%el_frame(:, :, el))
      call beam_element(m%x(:, a), m%x(:, b), ta, tb, m%el_stiff(:, el), m%el_l0(el), fe, ke)
      ! element dof i -> (node, dof): translations then spins of a, then of b
      do i = 1, 12
        dof_node(i) = merge(a, b, i <= 6)
        dof_d(i) = mod(i - 1, 6) + 1
      end do
      do i = 1, 12
        fint(dof_d(i), dof_node(i)) = fint(dof_d(i), dof_node(i)) + fe(i)
      end do
      if (want_tangent) then
        do j = 1, 12
          ej = eq(dof_d(j), dof_node(j))
          if (ej == 0) cycle
          do i = 1, 12
            ei = eq(dof_d(i), dof_node(i))
            if (ei == 0) cycle
            call sys_add(sys, ei, ej, ke(i, j))
          end do
        end do
      end if
    end do

    fext = external_force(m, lam)
    do node = 1, m%n_nodes
      do d = 1, ndf
        if (eq(d, node) > 0) r(eq(d, node)) = fint(d, node) - fext(d, node)
      end do
    end do

    ! ---- contact hook: contact part of the internal force and its tangent,
    !      at the current positions m%x (see demo_contact_hook)
    c_ok = .true.
    c_why = ''
    if (present(model) .and. m%contact%enabled) call contact_hook_forces(model, m, eq, want_tangent, sys, r, fint, &
                                                                          c_ok, c_why)
    if (present(ok)) ok = c_ok
    if (present(why)) why = c_why
  end subroutine assemble

end module demo_assembly
