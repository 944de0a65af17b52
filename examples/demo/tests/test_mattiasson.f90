!> Mattiasson's cantilever (scenes/mattiasson.nml, 20 elements; and
!> scenes/mattiasson_coarse.nml, 10 elements): tip deflection w/L,
!> shortening u/L and tip rotation at P L^2/EI = 1, 5, 10 against the
!> elliptic-integral values (Mattiasson 1981, 5 digits).
!>
!> Tolerance, from the mesh: the corotational chain's error falls as h^2.
!> The test asserts (1) every quantity of the 20-element mesh within 1e-3
!> of the reference (relative), and (2) that the largest error of the
!> 10-element mesh is at least 3 times the 20-element one at the same
!> quantity (second order: 4), so the tolerance is the mesh's, not luck.
module mattiasson_record
  use demo_kinds, only: dp
  use demo_model, only: scene_model
  use demo_rotation, only: quat_to_rotvec
  implicit none
  real(dp), parameter :: load_factor(3) = [0.1_dp, 0.5_dp, 1.0_dp], length = 10.0_dp
  real(dp) :: got(3, 3, 2) = -1.0_dp     !< (quantity, load, mesh)
  integer :: mesh = 1
contains
  !> Solver callback: records w/L, u/L and the tip rotation at the checked load factors.
  subroutine record(m, step, lam)
    type(scene_model), intent(in) :: m
    integer, intent(in) :: step   ! the load factor identifies the step here
    real(dp), intent(in) :: lam
    integer :: k
    real(dp) :: u(3)
    do k = 1, 3
      if (abs(lam - load_factor(k)) < 1.0e-12_dp) then
        u = m%x(:, m%monitor_node) - m%x0(:, m%monitor_node)
        got(:, k, mesh) = [-u(3) / length, -u(1) / length, norm2(quat_to_rotvec(m%q(:, m%monitor_node)))]
      end if
    end do
    if (step < 1) error stop 'test_mattiasson: bad step number'
  end subroutine record
end module mattiasson_record

program test_mattiasson
  use demo_kinds, only: dp
  use demo_model, only: scene_model
  use demo_scene_reader, only: read_scene
  use demo_solver, only: solve_scene
  use mattiasson_record
  implicit none
  real(dp), parameter :: ref(3, 3) = reshape([0.30172_dp, 0.05643_dp, 0.46135_dp, &
                                              0.71379_dp, 0.38763_dp, 1.21537_dp, &
                                              0.81061_dp, 0.55500_dp, 1.43029_dp], [3, 3])
  real(dp), parameter :: tol = 1.0e-3_dp
  character(len=12), parameter :: qname(3) = [character(len=12) :: 'w/L', 'u/L', 'tip rotation']
  real(dp) :: err(3, 3, 2), ratio
  character(len=1024) :: file
  integer :: i, j, worst(2)
  type(scene_model) :: m
  logical :: ok

  do mesh = 1, 2
    call get_command_argument(mesh, file)
    call read_scene(trim(file), m)
    m%vtk = .false.
    m%csv = .false.
    call solve_scene(m, record, quiet=.true.)
    if (any(got(:, :, mesh) < 0.0_dp)) error stop 'test_mattiasson: a load factor was not reached'
  end do
  err = abs(got - spread(ref, 3, 2)) / spread(ref, 3, 2)
  ok = .true.
  write (*, '(a)') 'P L^2/EI  quantity        reference  20 elements  rel. error  10 elements  rel. error'
  do j = 1, 3
    do i = 1, 3
      write (*, '(f6.1,4x,a12,f12.5,2(f13.5,es12.2))') 10 * load_factor(j), qname(i), ref(i, j), &
        got(i, j, 1), err(i, j, 1), got(i, j, 2), err(i, j, 2)
    end do
  end do
  if (any(err(:, :, 1) > tol)) then
    write (*, '(a,es9.2,a)') 'FAIL: a 20-element value is off by more than ', tol, ' (relative)'
    ok = .false.
  end if
  worst = maxloc(err(:, :, 2))
  ratio = err(worst(1), worst(2), 2) / max(err(worst(1), worst(2), 1), tiny(1.0_dp))
  write (*, '(a,f6.2,a)') 'error ratio 10 -> 20 elements at the largest error: ', ratio, ' (>= 3 asserted)'
  if (ratio < 3.0_dp) then
    write (*, '(a)') 'FAIL: the error does not fall as the mesh is refined'
    ok = .false.
  end if
  if (.not. ok) error stop 'test_mattiasson: FAILED'
  write (*, '(a)') 'Mattiasson: all checks passed'
end program test_mattiasson
