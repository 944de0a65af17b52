!> The data of one scene: mesh, sections, boundary conditions, loads,
!> controls, output options, the contact settings, and the current state
!> (positions and nodal rotations). Filled by demo_scene_reader; the solver
!> changes only the state.
module demo_model
  use demo_kinds, only: dp, ndf
  implicit none
  private

  integer, parameter, public :: name_len = 1024

  !> Kinds of the library options of &contact (contact_settings%option_kind).
  integer, parameter, public :: option_model_real = 1, option_model_int = 2, option_params_real = 3, &
                                option_params_int = 4
  integer, parameter, public :: max_contact_options = 16

  !> Contact modelling, read and validated now, handed to the contact model
  !> by demo_contact_hook once it exists.
  type, public :: contact_settings
    logical :: enabled = .false.
    character(len=32) :: curve = 'hermite_nodal'
    character(len=32) :: law = 'linear'
    character(len=16) :: tangent = 'exact' !< exact | symmetric | main | fd (b2b_params "tangent")
    real(dp) :: penalty = 0.0_dp
    real(dp) :: regularization_gap = 0.0_dp
    real(dp) :: friction = 0.0_dp
    real(dp) :: tangential_penalty = 0.0_dp
    logical :: self_contact = .false.
    integer :: n_pairs = 0
    integer, allocatable :: pairs(:, :)      !< (2, n_pairs): contact groups that interact
    ! the library's options the scene sets (&contact keys of the same name),
    ! passed as they are: b2b_model_set_real/_int (model options) or
    ! b2b_params_set_real/_int (parameter set); the library checks them
    integer :: n_options = 0
    character(len=24) :: option_key(max_contact_options) = ''
    integer :: option_kind(max_contact_options) = 0   !< option_model_real ... option_params_int
    real(dp) :: option_value(max_contact_options) = 0.0_dp  !< an int option's value is whole
  end type contact_settings

  !> What the program checks at the end of a run (&check group; kind '' = none).
  type, public :: check_settings
    character(len=32) :: kind = ''          !< crossed_beams | cantilever_crossbar | sliding | friction_pull | many_contacts | capstan | reference
    integer :: beam_a = 1, beam_b = 2       !< the loaded (or moving) beam and the other one
    real(dp) :: tolerance = 0.01_dp         !< relative tolerance of the closed form
    real(dp) :: min_rate = 1.8_dp           !< quadratic convergence: least rate where the active set is fixed
    integer :: min_contacts = 1             !< least number of active contacts (many_contacts)
    integer :: min_nodes_crossed = 0        !< nodes of beam_b the contact must cross (sliding)
    real(dp) :: reference = 0.0_dp          !< final |displacement| of the monitored node (reference)
  end type check_settings

  !> Piecewise-linear time function of a load or motion (&load / &motion key ramp).
  integer, parameter, public :: max_ramp_points = 16

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
    real(dp), allocatable :: beam_radius(:) !< contact and plotting radius (&material contact_radius)
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
    type(check_settings) :: check

    ! ramps: the factor of a load or motion as a function of the load factor
    ! (pseudo-time) t; ramp 0 is t itself
    integer :: n_ramps = 0
    integer, allocatable :: ramp_n(:)       !< points of each ramp
    real(dp), allocatable :: ramp_t(:, :), ramp_v(:, :)  !< (max_ramp_points, n_ramps)
    integer, allocatable :: fext_ramp(:, :) !< (ndf, n_nodes) ramp of each load component
    integer, allocatable :: presc_ramp(:, :) !< (ndf, n_nodes) ramp of each prescribed dof

    ! state
    real(dp), allocatable :: x(:, :)        !< (3, n_nodes) current positions
    real(dp), allocatable :: q(:, :)        !< (4, n_nodes) nodal rotations (unit quaternions)
  end type scene_model

  public :: ndf, ramp_value, external_force

contains

  !> The factor of ramp id at load factor t (ramp 0: t itself; constant
  !> beyond the first and last points).
  pure real(dp) function ramp_value(m, id, t) result(v)
    type(scene_model), intent(in) :: m
    integer, intent(in) :: id
    real(dp), intent(in) :: t
    integer :: i, n
    real(dp) :: s
    if (id <= 0) then
      v = t
      return
    end if
    n = m%ramp_n(id)
    if (t <= m%ramp_t(1, id)) then
      v = m%ramp_v(1, id)
      return
    end if
    v = m%ramp_v(n, id)
    do i = 2, n
      if (t <= m%ramp_t(i, id)) then
        s = (t - m%ramp_t(i - 1, id)) / (m%ramp_t(i, id) - m%ramp_t(i - 1, id))
        v = m%ramp_v(i - 1, id) + s * (m%ramp_v(i, id) - m%ramp_v(i - 1, id))
        return
      end if
    end do
  end function ramp_value

  !> The external forces and moments (ndf, n_nodes) at load factor t.
  pure function external_force(m, t) result(f)
    type(scene_model), intent(in) :: m
    real(dp), intent(in) :: t
    real(dp) :: f(ndf, m%n_nodes)
    integer :: node, d
    do node = 1, m%n_nodes
      do d = 1, ndf
        f(d, node) = m%fext(d, node) * ramp_value(m, m%fext_ramp(d, node), t)
      end do
    end do
  end function external_force
end module demo_model
