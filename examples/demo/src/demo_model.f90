!> The data of one scene: mesh, sections, boundary conditions, loads,
!> controls, output options, the contact settings, and the current state
!> (positions and nodal rotations). Filled by demo_scene_reader; the solver
!> changes only the state.
module demo_model
  use demo_kinds, only: dp, ndf
  implicit none
  private

  integer, parameter, public :: name_len = 1024

  !> Contact modelling, read and validated now, handed to the contact model
  !> by demo_contact_hook once it exists.
  type, public :: contact_settings
    logical :: enabled = .false.
    character(len=32) :: curve = 'hermite_nodal'
    character(len=32) :: law = 'linear'
    real(dp) :: penalty = 0.0_dp
    real(dp) :: regularization_gap = 0.0_dp
    real(dp) :: friction = 0.0_dp
    real(dp) :: tangential_penalty = 0.0_dp
    logical :: self_contact = .false.
    integer :: n_pairs = 0
    integer, allocatable :: pairs(:, :)      !< (2, n_pairs): contact groups that interact
  end type contact_settings

  type, public :: scene_model
    character(len=name_len) :: file = ''
    character(len=name_len) :: title = ''
    character(len=name_len) :: name = ''    !< file name without directory and extension

    ! mesh
    integer :: n_nodes = 0, n_elements = 0, n_beams = 0
    real(dp), allocatable :: x0(:, :)       !< (3, n_nodes) initial positions
    integer, allocatable :: conn(:, :)      !< (2, n_elements) node numbers
    integer, allocatable :: el_beam(:)      !< beam of each element
    real(dp), allocatable :: el_l0(:)       !< initial lengths
    real(dp), allocatable :: el_frame(:, :, :)  !< (3,3,n_elements) initial frames [e1 e2 e3]
    real(dp), allocatable :: el_stiff(:, :) !< (4, n_elements): EA, GJ, EIy, EIz

    ! beams (chains of consecutive nodes; a ring's last element closes it)
    integer, allocatable :: beam_first_node(:), beam_n_nodes(:), beam_first_el(:), beam_n_el(:)
    logical, allocatable :: beam_closed(:)
    real(dp), allocatable :: beam_radius(:) !< contact and plotting radius
    integer, allocatable :: beam_group(:)   !< contact group

    ! boundary conditions and loads, per unit load factor
    logical, allocatable :: fixed(:, :)     !< (ndf, n_nodes)
    real(dp), allocatable :: prescribed(:, :) !< (ndf, n_nodes) value at load factor 1 (fixed dofs)
    real(dp), allocatable :: fext(:, :)     !< (ndf, n_nodes) forces and moments at load factor 1

    ! controls
    integer :: n_steps = 0, max_iter = 25, max_cutbacks = 6
    real(dp) :: tol = 1.0e-9_dp             !< relative residual tolerance
    character(len=16) :: solver = 'auto'    !< auto | banded | dense

    ! output
    logical :: vtk = .true., csv = .true.
    integer :: vtk_every = 1
    character(len=name_len) :: out_dir = '.'
    integer :: monitor_node = 0             !< global node whose motion goes to the CSV history

    type(contact_settings) :: contact

    ! state
    real(dp), allocatable :: x(:, :)        !< (3, n_nodes) current positions
    real(dp), allocatable :: q(:, :)        !< (4, n_nodes) nodal rotations (unit quaternions)
  end type scene_model

  public :: ndf
end module demo_model
