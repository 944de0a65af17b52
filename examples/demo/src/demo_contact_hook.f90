!> THE CONTACT HOOK: the one place where the contact model of b2b will be
!> coupled to this host. Every routine here is called by the solver at the
!> point the contact model needs; today they do nothing but report, because
!> the contact-model API (b2b_model_*) is being written concurrently.
!>
!> What goes where (names as announced; check fortran/b2b.f90 when it lands):
!>  * contact_hook_init: b2b_model_create; b2b_model_add_beam for every beam
!>    (its global node numbers m%beam_first_node(b) + 0.., m%beam_closed(b),
!>    m%beam_radius(b), the curve kind m%contact%curve, m%beam_group(b));
!>    b2b_params with law/penalty/friction/tangential_penalty and
!>    b2b_model_set_group_pair for every m%contact%pairs(:, k) (and each
!>    group with itself when self_contact); b2b_model_finalize(model, n_nodes).
!>  * contact_hook_forces, every Newton iteration, with x = m%x (3, n_nodes),
!>    the current positions: b2b_model_update(model, x, want_tangent);
!>    b2b_model_add_residual(model, eq(1:3, :), r) adds the contact part of
!>    the INTERNAL force (r = f_int + f_contact - lambda f_ext here, so it is
!>    added with a plus sign); and for the tangent, the contact stiffness
!>    d f_contact / d x into sys (non-symmetric with friction). Couplings
!>    of distant nodes need no preparation: sys_add records entries outside
!>    the band and the solver widens it (or goes dense) and reassembles.
!>  * contact_hook_commit after a converged (sub)step: b2b_model_commit.
!>  * contact_hook_revert on a cut-back: b2b_model_revert.
module demo_contact_hook
  use demo_kinds, only: dp
  use demo_model, only: scene_model
  use demo_linear_system, only: linear_system
  implicit none
  private
  public :: contact_hook_init, contact_hook_forces, contact_hook_commit, contact_hook_revert

contains

  subroutine contact_hook_init(m)
    type(scene_model), intent(in) :: m
    if (m%contact%enabled) then
      write (*, '(a)') '  &contact read and validated (curve ' // trim(m%contact%curve) // ', law ' &
        // trim(m%contact%law) // '); the contact model is not coupled yet: no contact forces in this run'
    end if
  end subroutine contact_hook_init

  !> Adds the contact part of the internal force to r (free dofs, numbered
  !> by eq) and to fint (all dofs), and its tangent to sys if want_tangent.
  subroutine contact_hook_forces(m, eq, want_tangent, sys, r, fint)
    type(scene_model), intent(in) :: m
    integer, intent(in) :: eq(:, :)
    logical, intent(in) :: want_tangent
    type(linear_system), intent(inout) :: sys
    real(dp), intent(inout) :: r(:), fint(:, :)
    ! nothing yet: see the module header for the calls that go here
    ! (the stubs' unused arguments are allowed by the CMake file)
    if (.not. m%contact%enabled) return
  end subroutine contact_hook_forces

  subroutine contact_hook_commit(m)
    type(scene_model), intent(in) :: m
    if (.not. m%contact%enabled) return
  end subroutine contact_hook_commit

  subroutine contact_hook_revert(m)
    type(scene_model), intent(in) :: m
    if (.not. m%contact%enabled) return
  end subroutine contact_hook_revert

end module demo_contact_hook
