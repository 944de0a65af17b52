!> The assembled Newton matrix of a whole scene (scenes/ring_and_bar.nml: a
!> ring and a bar, supports, a prescribed motion, RCM numbering) against
!> central finite differences of the assembled residual, in an arbitrary
!> deformed and rotated state; and the band machinery the contact coupling
!> will rely on.
!> Asserts:
!>  * max |K - K_fd| / max |K| <= 1e-6 (dense storage);
!>  * the banded storage holds exactly the dense matrix (band unpacked);
!>  * with a band set too narrow on purpose, assembly reports the overflow
!>    and the half bandwidth it needs, which equals the one computed from
!>    the mesh (the path by which contacts between distant nodes widen it);
!>  * RCM keeps a ring of n nodes two nodes wide: half bandwidth <= 17.
program test_assembly_tangent
  use demo_kinds, only: dp, ndf
  use demo_model, only: scene_model
  use demo_scene_reader, only: read_scene
  use demo_numbering, only: rcm_order, number_equations, half_bandwidth
  use demo_linear_system, only: linear_system, sys_setup
  use demo_assembly, only: assemble
  use demo_rotation, only: quat_from_rotvec
  use demo_solver, only: perturb_dof
  implicit none
  type(scene_model) :: m
  type(linear_system) :: dense, band, narrow
  character(len=1024) :: file
  integer, allocatable :: order(:), eq(:, :)
  real(dp), allocatable :: r(:), rp(:), rm(:), fint(:, :), kfd(:, :), kband(:, :), x_keep(:, :), q_keep(:, :)
  integer :: neq, hb, node, d, j, i
  real(dp) :: h, err, band_err
  logical :: ok

  call get_command_argument(1, file)
  call read_scene(trim(file), m)
  allocate (order(m%n_nodes), eq(ndf, m%n_nodes), fint(ndf, m%n_nodes))
  call rcm_order(m%n_nodes, m%conn, order)
  call number_equations(order, m%fixed, eq, neq)
  hb = half_bandwidth(eq, m%conn)
  allocate (r(neq), rp(neq), rm(neq), kfd(neq, neq), kband(neq, neq))

  ! an arbitrary smooth deformation: translations ~ 0.05, rotations ~ 0.3 rad
  do node = 1, m%n_nodes
    m%x(:, node) = m%x0(:, node) + 0.05_dp * [sin(1.3_dp * node), cos(0.7_dp * node), sin(0.4_dp * node + 1.0_dp)]
    m%q(:, node) = quat_from_rotvec(0.3_dp * [cos(0.9_dp * node), sin(1.1_dp * node), cos(0.5_dp * node + 2.0_dp)])
  end do

  call sys_setup(dense, neq, hb, 'dense')
  call assemble(m, eq, 1.0_dp, .true., dense, r, fint)
  x_keep = m%x
  q_keep = m%q
  h = 1.0e-6_dp
  do node = 1, m%n_nodes
    do d = 1, ndf
      j = eq(d, node)
      if (j == 0) cycle
      call perturb_dof(m, node, d, +h)
      call assemble(m, eq, 1.0_dp, .false., band, rp, fint)
      m%x = x_keep; m%q = q_keep
      call perturb_dof(m, node, d, -h)
      call assemble(m, eq, 1.0_dp, .false., band, rm, fint)
      m%x = x_keep; m%q = q_keep
      kfd(:, j) = (rp - rm) / (2.0_dp * h)
    end do
  end do
  err = maxval(abs(dense%a - kfd)) / maxval(abs(dense%a))

  call sys_setup(band, neq, hb, 'banded')
  call assemble(m, eq, 1.0_dp, .true., band, r, fint)
  kband = 0.0_dp
  do j = 1, neq
    do i = max(1, j - band%ku), min(neq, j + band%kl)
      kband(i, j) = band%a(band%kl + band%ku + 1 + i - j, j)
    end do
  end do
  band_err = maxval(abs(kband - dense%a))

  call sys_setup(narrow, neq, 2, 'banded')
  call assemble(m, eq, 1.0_dp, .true., narrow, r, fint)

  ok = .true.
  write (*, '(a,i0,a,i0,a,es10.3)') 'equations ', neq, ', half bandwidth ', hb, &
    '; assembled tangent vs central differences: relative error ', err
  write (*, '(a,es10.3)') 'banded storage vs dense: max difference ', band_err
  write (*, '(a,l1,a,i0)') 'band of 2 on purpose: overflow reported ', narrow%overflow, ', width needed ', narrow%need
  if (err > 1.0e-6_dp) then
    write (*, '(a)') 'FAIL: assembled tangent differs from the finite differences (tolerance 1e-6)'
    ok = .false.
  end if
  if (band_err > 0.0_dp) then
    write (*, '(a)') 'FAIL: the banded matrix differs from the dense one'
    ok = .false.
  end if
  if (.not. narrow%overflow .or. narrow%need /= hb) then
    write (*, '(a)') 'FAIL: a too narrow band is not reported with the width it needs'
    ok = .false.
  end if
  if (hb > 17) then
    write (*, '(a)') 'FAIL: RCM did not keep the ring and the bar two nodes wide'
    ok = .false.
  end if
  ! main-program arrays are not freed automatically; free them for LeakSanitizer
  deallocate (order, eq, r, rp, rm, fint, kfd, kband, x_keep, q_keep)
  if (.not. ok) error stop 'test_assembly_tangent: FAILED'
  write (*, '(a)') 'assembly: all checks passed'

end program test_assembly_tangent
