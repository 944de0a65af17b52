!> The cantilever of scenes/roll_up.nml rolled into a full circle by an end
!> moment. Checked at load factors 0.25, 0.5, 0.75 and 1 (tip turned by
!> theta = pi/2, pi, 3 pi/2, 2 pi) against the exact circle.
!>
!> Tolerance, from the mesh: under a pure end moment every element carries
!> the same moment and no axial force, so each element keeps its length l0
!> and turns its chord by theta/n exactly (the local linear element is exact
!> for constant moment). The nodes therefore lie on the polygon inscribed in
!> a circle of radius rho_h = l0 / (2 sin(theta/(2n))) instead of
!> rho = L/theta, both tangent to x at the root; the tip is off by
!> (rho_h - rho) * 2 sin(theta/2). The test asserts the error is within
!> 1.01 times that mesh error plus 1e-6 L (the Newton tolerance) and that
!> the tip triad is the exact rotation by theta about -y to 1e-8.
module roll_up_check
  use demo_kinds, only: dp, pi
  use demo_model, only: scene_model
  use demo_rotation, only: quat_to_matrix, rotvec_to_matrix
  implicit none
  real(dp), parameter :: length = 10.0_dp
  integer :: n_checked = 0
  logical :: ok = .true.
contains

  subroutine check(mm, step, lam)
    type(scene_model), intent(in) :: mm
    integer, intent(in) :: step
    real(dp), intent(in) :: lam
    real(dp) :: theta, rho, rho_h, exact(3), tip(3), err, bound, rerr
    integer :: n_el
    if (mod(step, 5) /= 0) return
    n_checked = n_checked + 1
    n_el = mm%n_elements
    theta = 2.0_dp * pi * lam
    rho = length / theta
    rho_h = (length / n_el) / (2.0_dp * sin(theta / (2 * n_el)))
    exact = [rho * sin(theta), 0.0_dp, rho * (1.0_dp - cos(theta))]
    tip = mm%x(:, mm%monitor_node)
    err = norm2(tip - exact)
    bound = 1.01_dp * (rho_h - rho) * 2.0_dp * abs(sin(0.5_dp * theta)) + 1.0e-6_dp * length
    rerr = maxval(abs(quat_to_matrix(mm%q(:, mm%monitor_node)) - rotvec_to_matrix([0.0_dp, -theta, 0.0_dp])))
    write (*, '(a,f5.2,a,3f10.5,a,3f10.5,a,es9.2,a,es9.2,a,es9.2)') 'load ', lam, ': tip ', tip, '  exact ', exact, &
      '  |error| ', err, ' (bound ', bound, ')  rotation error ', rerr
    if (err > bound) then
      write (*, '(a)') '  FAIL: tip off the exact circle by more than the mesh error'
      ok = .false.
    end if
    if (rerr > 1.0e-8_dp) then
      write (*, '(a)') '  FAIL: tip rotation differs from theta about -y'
      ok = .false.
    end if
  end subroutine check

end module roll_up_check

program test_roll_up
  use demo_model, only: scene_model
  use demo_scene_reader, only: read_scene
  use demo_solver, only: solve_scene
  use roll_up_check
  implicit none
  type(scene_model) :: m
  character(len=1024) :: file

  call get_command_argument(1, file)
  call read_scene(trim(file), m)
  m%vtk = .false.
  m%csv = .false.
  call solve_scene(m, check)
  if (n_checked /= 4) then
    write (*, '(a,i0)') 'FAIL: expected 4 checked load factors, got ', n_checked
    ok = .false.
  end if
  if (.not. ok) error stop 'test_roll_up: FAILED'
  write (*, '(a)') 'roll-up: all checks passed'
end program test_roll_up
