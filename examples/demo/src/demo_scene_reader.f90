!> Reads one scene file (Fortran namelist groups, see examples/demo/README.md),
!> validates every value, generates the mesh and fills a scene_model.
!> Any error stops the program (demo_errors%fatal) with the file, the line,
!> the group and key, and what to change.
module demo_scene_reader
  use demo_kinds, only: dp, pi, ndf
  use demo_errors, only: fatal, str
  use demo_model, only: scene_model, name_len, max_ramp_points, option_model_real, option_model_int, &
                        option_params_real, option_params_int
  use demo_contact_hook, only: contact_hook_options
  use demo_checks_line, only: line_check_kinds
  use b2b, only: b2b_model, b2b_params, b2b_model_create, b2b_model_destroy, b2b_params_create, b2b_params_destroy, &
                 B2B_CONTACT_TYPE_POINT, B2B_CONTACT_TYPE_LINE, B2B_CONTACT_TYPE_ALL_ANGLE
  use demo_nml_scan, only: nml_index, nml_scan, lower
  use demo_geometry, only: straight_points => line_points, arc_points, element_frame
  use demo_rotation, only: quat_identity
  use, intrinsic :: iso_fortran_env, only: iostat_end
  implicit none
  private
  public :: read_scene

  real(dp), parameter :: unset = -huge(1.0_dp)
  integer, parameter :: iunset = -huge(1)

  character(len=*), parameter :: groups_valid = 'scene material beam support load motion output contact check'
  character(len=*), parameter :: keys_scene = 'title n_steps max_iter max_cutbacks tol solver'
  character(len=*), parameter :: keys_material = 'id E nu radius A Iy Iz J contact_radius'
  character(len=*), parameter :: keys_beam = 'shape p1 p2 centre start axis angle points n_el material group up'
  character(len=*), parameter :: keys_support = 'beam node all group dofs'
  character(len=*), parameter :: keys_load = 'beam node all group force moment ramp'
  character(len=*), parameter :: keys_motion = 'beam node all group dof value ramp'
  character(len=*), parameter :: keys_output = 'vtk csv vtk_every dir monitor_beam monitor_node'
  character(len=*), parameter :: keys_contact = 'curve law penalty regularization_gap friction ' &
                                                // 'tangential_penalty self_contact pairs tangent ' &
                                                // 'search_margin threads max_handover_hops max_candidates ' &
                                                // 'parallel_angle warm_start max_iterations contact_type ' &
                                                // 'line_penalty line_tangential_penalty line_points line_angle ' &
                                                // 'point_angle'
  character(len=*), parameter :: keys_check = 'kind beam_a beam_b tolerance min_rate min_contacts ' &
                                              // 'min_nodes_crossed reference'

  integer, parameter :: max_pairs = 64
  integer, parameter :: max_poly_points = 64   !< corner points of a 'polyline' beam

  type(nml_index) :: idx   ! where the keys are, for messages

contains

  subroutine read_scene(file, m)
    character(len=*), intent(in) :: file
    type(scene_model), intent(out) :: m
    logical :: ok
    character(len=:), allocatable :: msg
    integer :: u, ios
    integer, allocatable :: mat_id(:)
    real(dp), allocatable :: mat_stiff(:, :), mat_radius(:)

    call nml_scan(file, idx, ok, msg)
    if (.not. ok) call fatal(msg)
    call check_names()
    m%file = file
    m%name = base_name(file)
    open (newunit=u, file=file, status='old', action='read', iostat=ios)
    if (ios /= 0) call fatal(file // ': cannot open the scene file')
    call read_scene_group(u, m)
    call read_materials(u, mat_id, mat_stiff, mat_radius)
    call read_beams(u, m, mat_id, mat_stiff, mat_radius)
    call read_supports(u, m)
    call read_loads(u, m)
    call read_motions(u, m)
    call read_output(u, m)
    call read_contact(u, m)
    call read_check(u, m)
    close (u)
    allocate (m%x(3, m%n_nodes), m%q(4, m%n_nodes))
    m%x = m%x0
    m%q = spread(quat_identity(), 2, m%n_nodes)
  end subroutine read_scene

  ! ---------------------------------------------------------------- checks

  !> Unknown groups and keys, with their line and the valid names.
  subroutine check_names()
    integer :: i
    character(len=:), allocatable :: valid
    valid = ''
    do i = 1, idx%n_groups
      if (.not. in_list(idx%groups(i)%name, groups_valid)) &
        call fatal(idx%file // ':' // str(idx%groups(i)%line) // ': unknown group &' &
                   // trim(idx%groups(i)%name) // '; valid groups: ' // groups_valid)
    end do
    do i = 1, idx%n_keys
      select case (idx%keys(i)%group)
      case ('scene'); valid = keys_scene
      case ('material'); valid = keys_material
      case ('beam'); valid = keys_beam
      case ('support'); valid = keys_support
      case ('load'); valid = keys_load
      case ('motion'); valid = keys_motion
      case ('output'); valid = keys_output
      case ('contact'); valid = keys_contact
      case default; valid = keys_check
      end select
      if (.not. in_list(idx%keys(i)%key, valid)) &
        call fatal(idx%file // ':' // str(idx%keys(i)%line) // ': unknown key ''' // trim(idx%keys(i)%key) &
                   // ''' in &' // trim(idx%keys(i)%group) // '; valid keys: ' // valid)
    end do
    if (idx%count('scene') /= 1) call fatal(idx%file // ': needs exactly one &scene group (found ' &
                                             // str(idx%count('scene')) // ')')
    if (idx%count('material') < 1) call fatal(idx%file // ': needs at least one &material group')
    if (idx%count('beam') < 1) call fatal(idx%file // ': needs at least one &beam group')
    if (idx%count('output') > 1) call fatal(idx%file // ': at most one &output group')
    if (idx%count('contact') > 1) call fatal(idx%file // ': at most one &contact group')
    if (idx%count('check') > 1) call fatal(idx%file // ': at most one &check group')
  end subroutine check_names

  !> Stops naming file:line, group occurrence and key.
  subroutine bad(group, k, key, what)
    character(len=*), intent(in) :: group, key, what
    integer, intent(in) :: k
    call fatal(idx%file // ':' // str(idx%key_line(group, k, key)) // ': &' // group // ' (number ' &
               // str(k) // '), key ' // key // ': ' // what)
  end subroutine bad

  subroutine need_real(group, k, key, x)
    character(len=*), intent(in) :: group, key
    integer, intent(in) :: k
    real(dp), intent(in) :: x(:)
    if (any(x < -0.5_dp * huge(1.0_dp))) call bad(group, k, key, 'missing: set ' // key // ' = ' &
                                                    // trim(merge('a value         ', 'three components', size(x) == 1)))
  end subroutine need_real

  subroutine need_int(group, k, key, i)
    character(len=*), intent(in) :: group, key
    integer, intent(in) :: k, i
    if (i == iunset) call bad(group, k, key, 'missing: set ' // key // ' = an integer')
  end subroutine need_int

  subroutine positive(group, k, key, x)
    character(len=*), intent(in) :: group, key
    integer, intent(in) :: k
    real(dp), intent(in) :: x
    if (.not. (x > 0.0_dp)) call bad(group, k, key, 'is ' // str(x) // '; it must be positive')
  end subroutine positive

  subroutine read_failed(group, k, ios, iomsg)
    character(len=*), intent(in) :: group, iomsg
    integer, intent(in) :: k, ios
    call fatal(idx%file // ':' // str(idx%group_line(group, k)) // ': cannot read &' // group // ' (number ' &
               // str(k) // '): ' // trim(iomsg) // ' (iostat ' // str(ios) // '); check the values'' types')
  end subroutine read_failed

  ! ---------------------------------------------------------------- groups

  subroutine read_scene_group(u, m)
    integer, intent(in) :: u
    type(scene_model), intent(inout) :: m
    character(len=name_len) :: title
    character(len=16) :: solver
    integer :: n_steps, max_iter, max_cutbacks, ios
    real(dp) :: tol
    character(len=256) :: iomsg
    namelist /scene/ title, n_steps, max_iter, max_cutbacks, tol, solver
    title = ''; n_steps = iunset; max_iter = 25; max_cutbacks = 6; tol = 1.0e-9_dp; solver = 'auto'
    rewind (u)
    read (u, nml=scene, iostat=ios, iomsg=iomsg)
    if (ios /= 0) call read_failed('scene', 1, ios, iomsg)
    call need_int('scene', 1, 'n_steps', n_steps)
    if (n_steps < 1) call bad('scene', 1, 'n_steps', 'is ' // str(n_steps) // '; it must be at least 1')
    if (max_iter < 1) call bad('scene', 1, 'max_iter', 'is ' // str(max_iter) // '; it must be at least 1')
    if (max_cutbacks < 0) call bad('scene', 1, 'max_cutbacks', 'is ' // str(max_cutbacks) // '; it must be >= 0')
    if (.not. (tol > 0.0_dp .and. tol < 1.0_dp)) call bad('scene', 1, 'tol', 'is ' // str(tol) &
                                                            // '; it must be in (0, 1), e.g. 1e-9')
    solver = lower(solver)
    if (.not. in_list(solver, 'auto banded dense')) call bad('scene', 1, 'solver', '''' // trim(solver) &
                                                               // ''' is not one of auto, banded, dense')
    m%title = title; m%n_steps = n_steps; m%max_iter = max_iter; m%max_cutbacks = max_cutbacks
    m%tol = tol; m%solver = solver
  end subroutine read_scene_group

  subroutine read_materials(u, mat_id, mat_stiff, mat_radius)
    integer, intent(in) :: u
    integer, allocatable, intent(out) :: mat_id(:)
    real(dp), allocatable, intent(out) :: mat_stiff(:, :), mat_radius(:)
    integer :: id
    real(dp) :: e, nu, radius, a, iy, iz, j, contact_radius
    namelist /material/ id, e, nu, radius, a, iy, iz, j, contact_radius
    integer :: n_mat, k, ios
    character(len=256) :: iomsg
    ! materials
    n_mat = idx%count('material')
    allocate (mat_id(n_mat), mat_stiff(4, n_mat), mat_radius(n_mat))
    rewind (u)
    do k = 1, n_mat
      id = k; e = unset; nu = unset; radius = unset; a = unset; iy = unset; iz = unset; j = unset
      contact_radius = unset
      read (u, nml=material, iostat=ios, iomsg=iomsg)
      if (ios /= 0) call read_failed('material', k, ios, iomsg)
      call need_real('material', k, 'E', [e])
      call positive('material', k, 'E', e)
      call need_real('material', k, 'nu', [nu])
      if (.not. (nu > -1.0_dp .and. nu < 0.5_dp)) call bad('material', k, 'nu', 'is ' // str(nu) &
                                                           // '; it must be in (-1, 0.5)')
      if (radius > -0.5_dp * huge(1.0_dp)) then
        ! circular solid section
        call positive('material', k, 'radius', radius)
        if (idx%has_key('material', k, 'a') .or. idx%has_key('material', k, 'iy') .or. &
            idx%has_key('material', k, 'iz') .or. idx%has_key('material', k, 'j')) &
          call bad('material', k, 'radius', 'given together with A/Iy/Iz/J: give either radius or all of A, Iy, Iz, J')
        a = pi * radius**2
        iy = 0.25_dp * pi * radius**4
        iz = iy
        j = 2.0_dp * iy
      else
        if (.not. (a > -0.5_dp * huge(1.0_dp))) call bad('material', k, 'radius', &
            'missing: give radius (circular section) or all of A, Iy, Iz, J')
        call need_real('material', k, 'Iy', [iy])
        call need_real('material', k, 'Iz', [iz])
        call need_real('material', k, 'J', [j])
        call positive('material', k, 'A', a)
        call positive('material', k, 'Iy', iy)
        call positive('material', k, 'Iz', iz)
        call positive('material', k, 'J', j)
        radius = sqrt(a / pi)   ! the circle of the same area
      end if
      ! the contact (and plotting) radius: by default the section's radius,
      ! or that of the circle of area A; contact_radius sets it apart from
      ! the stiffness (A, I, J stay as given or as radius made them)
      if (idx%has_key('material', k, 'contact_radius')) then
        call positive('material', k, 'contact_radius', contact_radius)
        radius = contact_radius
      end if
      if (any(mat_id(1:k - 1) == id)) call bad('material', k, 'id', 'id ' // str(id) // ' is used twice')
      mat_id(k) = id
      ! [EA, GJ, EIy, EIz] with G = E / (2 (1 + nu))
      mat_stiff(:, k) = [e * a, 0.5_dp * e / (1.0_dp + nu) * j, e * iy, e * iz]
      mat_radius(k) = radius
    end do

  end subroutine read_materials

  subroutine read_beams(u, m, mat_id, mat_stiff, mat_radius)
    integer, intent(in) :: u
    type(scene_model), intent(inout) :: m
    integer, intent(in) :: mat_id(:)
    real(dp), intent(in) :: mat_stiff(:, :), mat_radius(:)
    character(len=16) :: shape
    real(dp) :: p1(3), p2(3), centre(3), start(3), axis(3), angle, up(3), points(3, max_poly_points)
    integer :: n_el, material, group
    namelist /beam/ shape, p1, p2, centre, start, axis, angle, points, n_el, material, group, up
    integer :: n_beam, ios, b, i, first, nn, ne, el, n_pts, n_el_beam
    real(dp), allocatable :: pts(:, :), all_x(:, :), b_up(:, :)
    character(len=256) :: iomsg
    logical :: ok, closed

    ! beams: first pass for sizes, generating the points
    n_beam = idx%count('beam')
    m%n_beams = n_beam
    allocate (m%beam_first_node(n_beam), m%beam_n_nodes(n_beam), m%beam_first_el(n_beam), m%beam_n_el(n_beam), &
              m%beam_closed(n_beam), m%beam_radius(n_beam), m%beam_group(n_beam), b_up(3, n_beam))
    allocate (all_x(3, 0))
    allocate (m%conn(2, 0), m%el_beam(0), m%el_stiff(4, 0))
    rewind (u)
    nn = 0
    ne = 0
    do b = 1, n_beam
      shape = ''; p1 = unset; p2 = unset; centre = unset; start = unset; axis = unset; angle = unset
      n_el = iunset; material = 1; group = 1; up = unset; points = unset
      read (u, nml=beam, iostat=ios, iomsg=iomsg)
      if (ios /= 0) call read_failed('beam', b, ios, iomsg)
      if (len_trim(shape) == 0) call bad('beam', b, 'shape', 'missing: set shape = ''line'', ''arc'', ''ring''' &
                                         // ' or ''polyline''')
      call need_int('beam', b, 'n_el', n_el)
      if (n_el < 1) call bad('beam', b, 'n_el', 'is ' // str(n_el) // '; it must be at least 1')
      shape = lower(shape)
      closed = .false.
      n_el_beam = n_el
      select case (shape)
      case ('line')
        call need_real('beam', b, 'p1', p1)
        call need_real('beam', b, 'p2', p2)
        if (.not. (norm2(p2 - p1) > 0.0_dp)) call bad('beam', b, 'p2', 'equals p1: a line needs two distinct points')
        pts = straight_points(p1, p2, n_el)
        if (up(1) < -0.5_dp * huge(1.0_dp)) then
          ! default cross-section axis: global z, or y for a vertical line
          up = [0.0_dp, 0.0_dp, 1.0_dp]
          if (norm2(cross(p2 - p1, up)) < 1.0e-6_dp * norm2(p2 - p1)) up = [0.0_dp, 1.0_dp, 0.0_dp]
        end if
      case ('arc', 'ring')
        call need_real('beam', b, 'centre', centre)
        call need_real('beam', b, 'start', start)
        call need_real('beam', b, 'axis', axis)
        if (.not. (norm2(axis) > 0.0_dp)) call bad('beam', b, 'axis', 'is zero: give the normal of the arc''s plane')
        if (.not. (norm2(cross(axis, start - centre)) > 1.0e-9_dp * norm2(start - centre))) &
          call bad('beam', b, 'start', 'must lie off the axis through centre (radius > 0)')
        if (shape == 'arc') then
          call need_real('beam', b, 'angle', [angle])
          if (.not. (abs(angle) > 0.0_dp .and. abs(angle) < 360.0_dp)) &
            call bad('beam', b, 'angle', 'is ' // str(angle) // ' degrees; an arc needs 0 < |angle| < 360' &
                     // ' (use shape = ''ring'' for a closed one)')
          n_pts = n_el + 1
        else
          if (n_el < 3) call bad('beam', b, 'n_el', 'a ring needs at least 3 elements')
          angle = 360.0_dp
          closed = .true.
          n_pts = n_el
        end if
        pts = arc_points(centre, start, axis, angle, n_el, n_pts)
        if (up(1) < -0.5_dp * huge(1.0_dp)) up = axis   ! default: local z normal to the plane of the arc
      case ('polyline')
        ! points = x1, y1, z1, x2, y2, z2, ...: straight legs between them,
        ! n_el elements per leg; the corners are nodes (kinks, stress-free)
        call polyline(points, n_el, pts, up)
        n_el_beam = size(pts, 2) - 1
      case default
        call bad('beam', b, 'shape', '''' // trim(shape) // ''' is not one of line, arc, ring, polyline')
      end select
      if (.not. any(mat_id == material)) call bad('beam', b, 'material', 'no &material with id = ' // str(material))
      i = findloc(mat_id, material, dim=1)
      if (group < 1) call bad('beam', b, 'group', 'is ' // str(group) // '; contact groups are numbered from 1')

      m%beam_first_node(b) = nn + 1
      m%beam_n_nodes(b) = size(pts, 2)
      m%beam_first_el(b) = ne + 1
      m%beam_n_el(b) = n_el_beam
      m%beam_closed(b) = closed
      m%beam_radius(b) = mat_radius(i)
      m%beam_group(b) = group
      b_up(:, b) = up
      all_x = reshape([all_x, pts], [3, nn + size(pts, 2)])
      first = nn
      nn = nn + size(pts, 2)
      m%conn = reshape([m%conn, new_conn(first, n_el_beam, size(pts, 2), closed)], [2, ne + n_el_beam])
      m%el_beam = [m%el_beam, spread(b, 1, n_el_beam)]
      m%el_stiff = reshape([m%el_stiff, spread(mat_stiff(:, i), 2, n_el_beam)], [4, ne + n_el_beam])
      ne = ne + n_el_beam
    end do
    m%n_nodes = nn
    m%n_elements = ne
    call move_alloc(all_x, m%x0)

    allocate (m%el_l0(ne), m%el_frame(3, 3, ne))
    do el = 1, ne
      associate (xa => m%x0(:, m%conn(1, el)), xb => m%x0(:, m%conn(2, el)))
        m%el_l0(el) = norm2(xb - xa)
        if (.not. (m%el_l0(el) > 0.0_dp)) call bad('beam', m%el_beam(el), 'n_el', 'element ' // str(el) // ' has zero length')
        call element_frame(xa, xb, b_up(:, m%el_beam(el)), m%el_frame(:, :, el), ok)
        if (.not. ok) call bad('beam', m%el_beam(el), 'up', 'is parallel to element ' // str(el) &
                               // ': give a cross-section axis up = (3 components) not along the beam')
      end associate
    end do

    allocate (m%fixed(ndf, nn), m%prescribed(ndf, nn), m%fext(ndf, nn), m%fext_ramp(ndf, nn), m%presc_ramp(ndf, nn))
    m%fext_ramp = 0
    m%presc_ramp = 0
    allocate (m%ramp_n(0), m%ramp_t(max_ramp_points, 0), m%ramp_v(max_ramp_points, 0))
    m%fixed = .false.
    m%prescribed = 0.0_dp
    m%fext = 0.0_dp

  contains

    !> Nodes of a 'polyline' beam: the given points (at least two, each
    !> distinct from the one before) joined by straight legs of n_per_leg
    !> equal elements. Default cross-section axis: the normal of the plane
    !> of the first corner, or as for a line when the points are collinear.
    subroutine polyline(points, n_per_leg, pts, up)
      real(dp), intent(in) :: points(:, :)
      integer, intent(in) :: n_per_leg
      real(dp), allocatable, intent(out) :: pts(:, :)
      real(dp), intent(inout) :: up(3)
      integer :: n_corner, j, k
      real(dp) :: nrm(3)
      n_corner = 0
      do j = 1, size(points, 2)
        if (all(points(:, j) < -0.5_dp * huge(1.0_dp))) exit
        if (any(points(:, j) < -0.5_dp * huge(1.0_dp))) call bad('beam', b, 'points', 'point ' // str(j) &
            // ' is incomplete: give points = x1, y1, z1, x2, y2, z2, ... (three components each)')
        n_corner = j
      end do
      if (n_corner < 2) call bad('beam', b, 'points', 'needs at least two points: points = x1, y1, z1, x2, y2, z2, ...')
      do j = 2, n_corner
        if (.not. (norm2(points(:, j) - points(:, j - 1)) > 0.0_dp)) call bad('beam', b, 'points', 'point ' &
            // str(j) // ' equals the point before it: a leg needs two distinct points')
      end do
      allocate (pts(3, (n_corner - 1) * n_per_leg + 1))
      pts(:, 1) = points(:, 1)
      do j = 1, n_corner - 1
        do k = 1, n_per_leg
          pts(:, (j - 1) * n_per_leg + k + 1) = points(:, j) + (points(:, j + 1) - points(:, j)) &
                                                * (real(k, dp) / real(n_per_leg, dp))
        end do
        pts(:, j * n_per_leg + 1) = points(:, j + 1)   ! the corners exactly as given
      end do
      if (up(1) > -0.5_dp * huge(1.0_dp)) return
      up = [0.0_dp, 0.0_dp, 1.0_dp]
      associate (d1 => points(:, 2) - points(:, 1))
        if (norm2(cross(d1, up)) < 1.0e-6_dp * norm2(d1)) up = [0.0_dp, 1.0_dp, 0.0_dp]
        do j = 2, n_corner - 1
          nrm = cross(points(:, j) - points(:, j - 1), points(:, j + 1) - points(:, j))
          if (norm2(nrm) > 1.0e-6_dp * norm2(points(:, j) - points(:, j - 1)) * norm2(points(:, j + 1) - points(:, j))) &
            then
            up = nrm / norm2(nrm)
            exit
          end if
        end do
      end associate
    end subroutine polyline
  end subroutine read_beams

  !> Element connectivity of a chain of n_pts nodes after node `first`.
  pure function new_conn(first, n_el, n_pts, closed) result(c)
    integer, intent(in) :: first, n_el, n_pts
    logical, intent(in) :: closed
    integer :: c(2, n_el), i
    do i = 1, n_el
      c(:, i) = [first + i, first + i + 1]
    end do
    if (closed) c(2, n_el) = first + 1
    if (.not. closed .and. n_pts /= n_el + 1) c = 0
  end function new_conn

  !> Global node of (beam, node) from a group occurrence; node < 0 counts from the end.
  integer function node_of(m, group, k, beam, node) result(g)
    type(scene_model), intent(in) :: m
    character(len=*), intent(in) :: group
    integer, intent(in) :: k, beam, node
    integer :: n
    call need_int(group, k, 'beam', beam)
    if (beam < 1 .or. beam > m%n_beams) call bad(group, k, 'beam', 'beam ' // str(beam) // ' does not exist; the' &
                                                  // ' scene has beams 1..' // str(m%n_beams))
    call need_int(group, k, 'node', node)
    n = m%beam_n_nodes(beam)
    if (node == 0 .or. abs(node) > n) call bad(group, k, 'node', 'node ' // str(node) // ' is out of range: beam ' &
        // str(beam) // ' has nodes 1..' // str(n) // ' (or -1..-' // str(n) // ' counted from its end)')
    if (node > 0) then
      g = m%beam_first_node(beam) + node - 1
    else
      g = m%beam_first_node(beam) + n + node
    end if
  end function node_of

  subroutine read_supports(u, m)
    integer, intent(in) :: u
    type(scene_model), intent(inout) :: m
    integer :: beam, node, group, k, ios, i, d
    logical :: all
    character(len=16) :: dofs
    character(len=256) :: iomsg
    integer, allocatable :: nodes(:)
    namelist /support/ beam, node, all, group, dofs
    rewind (u)
    do k = 1, idx%count('support')
      beam = iunset; node = iunset; all = .false.; group = iunset; dofs = ''
      read (u, nml=support, iostat=ios, iomsg=iomsg)
      if (ios /= 0) call read_failed('support', k, ios, iomsg)
      if (len_trim(dofs) /= ndf .or. verify(trim(dofs), '01') /= 0) call bad('support', k, 'dofs', &
          '''' // trim(dofs) // ''' is not 6 characters 0/1 (ux uy uz rx ry rz; 1 = fixed), e.g. dofs = ''111111''')
      call entry_nodes(m, 'support', k, beam, node, all, group, nodes)
      do i = 1, size(nodes)
        do d = 1, ndf
          if (dofs(d:d) == '1') m%fixed(d, nodes(i)) = .true.
        end do
      end do
    end do
  end subroutine read_supports

  !> The global nodes one &support, &load or &motion entry (number k of
  !> group grp) applies to: node of beam; with all = .true. every node of
  !> beam, or, given group instead of beam, every node of every beam of
  !> that contact group (e.g. a rigid indenter made of several beams).
  subroutine entry_nodes(m, grp, k, beam, node, all, group, nodes)
    type(scene_model), intent(in) :: m
    character(len=*), intent(in) :: grp
    integer, intent(in) :: k, beam, node, group
    logical, intent(in) :: all
    integer, allocatable, intent(out) :: nodes(:)
    integer :: b, i, n
    if (.not. all) then
      if (idx%has_key(grp, k, 'group')) call bad(grp, k, 'group', 'needs all = .true. (every node of the ' &
          // 'beams of that group); for one node give beam and node')
      allocate (nodes(1))
      nodes(1) = node_of(m, grp, k, beam, node)
      return
    end if
    if (idx%has_key(grp, k, 'node')) call bad(grp, k, 'node', 'given with all = .true.: give one of them')
    if (idx%has_key(grp, k, 'group')) then
      if (idx%has_key(grp, k, 'beam')) call bad(grp, k, 'group', 'given with beam: with all = .true. give ' &
          // 'beam (its nodes) or group (the nodes of its beams), not both')
      n = sum(m%beam_n_nodes, mask=m%beam_group == group)
      if (n == 0) call bad(grp, k, 'group', 'no beam belongs to contact group ' // str(group) &
          // ' (set group = on the &beam groups)')
      allocate (nodes(n))
      n = 0
      do b = 1, m%n_beams
        if (m%beam_group(b) /= group) cycle
        do i = 0, m%beam_n_nodes(b) - 1
          n = n + 1
          nodes(n) = m%beam_first_node(b) + i
        end do
      end do
    else
      if (beam == iunset) call bad(grp, k, 'beam', 'missing: with all = .true. give beam = (its nodes) or ' &
          // 'group = (the nodes of every beam of that contact group)')
      if (beam < 1 .or. beam > m%n_beams) call bad(grp, k, 'beam', 'beam ' // str(beam) &
          // ' does not exist; the scene has beams 1..' // str(m%n_beams))
      allocate (nodes(m%beam_n_nodes(beam)))
      do i = 1, m%beam_n_nodes(beam)
        nodes(i) = m%beam_first_node(beam) + i - 1
      end do
    end if
  end subroutine entry_nodes

  subroutine read_loads(u, m)
    integer, intent(in) :: u
    type(scene_model), intent(inout) :: m
    integer :: beam, node, group, k, ios, g, i, id
    logical :: all
    real(dp) :: force(3), moment(3), ramp(2 * max_ramp_points)
    character(len=256) :: iomsg
    integer, allocatable :: nodes(:)
    namelist /load/ beam, node, all, group, force, moment, ramp
    rewind (u)
    do k = 1, idx%count('load')
      beam = iunset; node = iunset; all = .false.; group = iunset; force = unset; moment = unset; ramp = unset
      read (u, nml=load, iostat=ios, iomsg=iomsg)
      if (ios /= 0) call read_failed('load', k, ios, iomsg)
      call entry_nodes(m, 'load', k, beam, node, all, group, nodes)
      if (any(force < -0.5_dp * huge(1.0_dp)) .and. any(moment < -0.5_dp * huge(1.0_dp))) &
        call bad('load', k, 'force', 'missing: give force = (3 components) and/or moment = (3 components)')
      if (idx%has_key('load', k, 'force')) call need_real('load', k, 'force', force)
      if (idx%has_key('load', k, 'moment')) call need_real('load', k, 'moment', moment)
      id = new_ramp(m, 'load', k, ramp)
      do i = 1, size(nodes)
        g = nodes(i)
        if (idx%has_key('load', k, 'force')) then
          call set_ramp(m%fext_ramp(1:3, g), m%fext(1:3, g), force, id, 'load', k)
          m%fext(1:3, g) = m%fext(1:3, g) + force
        end if
        if (idx%has_key('load', k, 'moment')) then
          call set_ramp(m%fext_ramp(4:6, g), m%fext(4:6, g), moment, id, 'load', k)
          m%fext(4:6, g) = m%fext(4:6, g) + moment
        end if
      end do
    end do
  end subroutine read_loads

  !> Records the ramp of the nonzero components; two loads with different
  !> ramps on one component cannot be added into one value.
  subroutine set_ramp(ramp_of, old, new, id, group, k)
    integer, intent(inout) :: ramp_of(:)
    real(dp), intent(in) :: old(:), new(:)
    integer, intent(in) :: id, k
    character(len=*), intent(in) :: group
    integer :: i
    do i = 1, size(ramp_of)
      if (.not. abs(new(i)) > 0.0_dp) cycle
      if (abs(old(i)) > 0.0_dp .and. ramp_of(i) /= id) call bad(group, k, 'ramp', 'a component already loaded ' &
          // 'with another ramp: put loads with different ramps on different nodes')
      ramp_of(i) = id
    end do
  end subroutine set_ramp

  !> ramp = t1, v1, t2, v2, ... (t increasing): a new ramp and its number;
  !> 0 (the load factor itself) when the key is absent.
  integer function new_ramp(m, group, k, ramp) result(id)
    type(scene_model), intent(inout) :: m
    character(len=*), intent(in) :: group
    integer, intent(in) :: k
    real(dp), intent(in) :: ramp(:)
    integer :: n, i
    integer, allocatable :: tn(:)
    real(dp), allocatable :: tt(:, :), tv(:, :)
    id = 0
    if (.not. idx%has_key(group, k, 'ramp')) return
    n = 0
    do i = 1, size(ramp) / 2
      if (ramp(2 * i - 1) < -0.5_dp * huge(1.0_dp)) exit
      if (ramp(2 * i) < -0.5_dp * huge(1.0_dp)) call bad(group, k, 'ramp', 'point ' // str(i) // ' has a t but no value:' &
                                                        // ' give ramp = t1, v1, t2, v2, ...')
      n = i
    end do
    if (n < 2) call bad(group, k, 'ramp', 'needs at least two points: ramp = t1, v1, t2, v2, ...')
    do i = 2, n
      if (.not. ramp(2 * i - 1) > ramp(2 * i - 3)) call bad(group, k, 'ramp', 'the times t must increase (point ' &
                                                           // str(i) // ')')
    end do
    m%n_ramps = m%n_ramps + 1
    id = m%n_ramps
    allocate (tn(id), tt(max_ramp_points, id), tv(max_ramp_points, id))
    tn(1:id - 1) = m%ramp_n
    tt(:, 1:id - 1) = m%ramp_t
    tv(:, 1:id - 1) = m%ramp_v
    tn(id) = n
    tt(:, id) = 0.0_dp
    tv(:, id) = 0.0_dp
    tt(1:n, id) = ramp(1:2 * n - 1:2)
    tv(1:n, id) = ramp(2:2 * n:2)
    call move_alloc(tn, m%ramp_n)
    call move_alloc(tt, m%ramp_t)
    call move_alloc(tv, m%ramp_v)
  end function new_ramp

  subroutine read_motions(u, m)
    integer, intent(in) :: u
    type(scene_model), intent(inout) :: m
    integer :: beam, node, group, dof, k, ios, i, id
    logical :: all
    real(dp) :: value, ramp(2 * max_ramp_points)
    character(len=256) :: iomsg
    integer, allocatable :: nodes(:)
    namelist /motion/ beam, node, all, group, dof, value, ramp
    rewind (u)
    do k = 1, idx%count('motion')
      beam = iunset; node = iunset; all = .false.; group = iunset; dof = iunset; value = unset; ramp = unset
      read (u, nml=motion, iostat=ios, iomsg=iomsg)
      if (ios /= 0) call read_failed('motion', k, ios, iomsg)
      call entry_nodes(m, 'motion', k, beam, node, all, group, nodes)
      call need_int('motion', k, 'dof', dof)
      if (dof < 1 .or. dof > ndf) call bad('motion', k, 'dof', 'is ' // str(dof) // '; dofs are 1..6 (ux uy uz rx ry rz)')
      call need_real('motion', k, 'value', [value])
      id = new_ramp(m, 'motion', k, ramp)
      do i = 1, size(nodes)
        m%fixed(dof, nodes(i)) = .true.
        m%prescribed(dof, nodes(i)) = value
        m%presc_ramp(dof, nodes(i)) = id
      end do
    end do
  end subroutine read_motions

  subroutine read_output(u, m)
    integer, intent(in) :: u
    type(scene_model), intent(inout) :: m
    logical :: vtk, csv
    integer :: vtk_every, monitor_beam, monitor_node, ios
    character(len=name_len) :: dir
    character(len=256) :: iomsg
    namelist /output/ vtk, csv, vtk_every, dir, monitor_beam, monitor_node
    vtk = .true.; csv = .true.; vtk_every = 1; dir = '.'
    monitor_beam = m%n_beams; monitor_node = -1
    if (idx%count('output') == 1) then
      rewind (u)
      read (u, nml=output, iostat=ios, iomsg=iomsg)
      if (ios /= 0) call read_failed('output', 1, ios, iomsg)
    end if
    if (vtk_every < 1) call bad('output', 1, 'vtk_every', 'is ' // str(vtk_every) // '; it must be at least 1')
    if (len_trim(dir) == 0) call bad('output', 1, 'dir', 'is empty; use ''.'' for the current directory')
    m%vtk = vtk; m%csv = csv; m%vtk_every = vtk_every; m%out_dir = dir
    m%monitor_node = node_of(m, 'output', 1, monitor_beam, monitor_node)
  end subroutine read_output

  subroutine read_contact(u, m)
    integer, intent(in) :: u
    type(scene_model), intent(inout) :: m
    character(len=32) :: curve, law
    character(len=16) :: tangent
    real(dp) :: penalty, regularization_gap, friction, tangential_penalty
    logical :: self_contact
    integer :: pairs(2, max_pairs), ios, n, i
    character(len=256) :: iomsg
    ! the library's options, passed as they are (demo_contact_hook)
    real(dp) :: search_margin, parallel_angle
    integer :: threads, max_handover_hops, max_candidates, warm_start, max_iterations
    ! line contact (b2b_pair.h "Line contact"): the element per pair of groups
    character(len=16) :: contact_type
    real(dp) :: line_penalty, line_tangential_penalty, line_angle, point_angle
    integer :: line_points
    namelist /contact/ curve, law, penalty, regularization_gap, friction, tangential_penalty, self_contact, pairs, &
                       tangent, search_margin, threads, max_handover_hops, max_candidates, parallel_angle, &
                       warm_start, max_iterations, contact_type, line_penalty, line_tangential_penalty, &
                       line_points, line_angle, point_angle
    if (idx%count('contact') == 0) return
    curve = ''; law = 'linear'; penalty = unset; regularization_gap = 0.0_dp; friction = 0.0_dp
    tangential_penalty = 0.0_dp; self_contact = .false.; pairs = 0; tangent = 'exact'
    search_margin = 0.0_dp; parallel_angle = 0.0_dp; threads = 0; max_handover_hops = 0; max_candidates = 0
    warm_start = 0; max_iterations = 0
    contact_type = 'point'; line_penalty = 0.0_dp; line_tangential_penalty = 0.0_dp; line_points = 0
    line_angle = 0.0_dp; point_angle = 0.0_dp
    rewind (u)
    read (u, nml=contact, iostat=ios, iomsg=iomsg)
    if (ios /= 0) call read_failed('contact', 1, ios, iomsg)
    curve = lower(curve)
    if (len_trim(curve) == 0) call bad('contact', 1, 'curve', 'missing: set curve = ''linear'', ''hermite_midpoint'', ' &
                                       // '''hermite_nodal'' or ''hermite_nodal_weighted''')
    if (.not. in_list(curve, 'linear hermite_midpoint hermite_nodal hermite_nodal_weighted')) &
      call bad('contact', 1, 'curve', '''' // trim(curve) // ''' is not one of linear, hermite_midpoint, ' &
               // 'hermite_nodal, hermite_nodal_weighted')
    law = lower(law)
    if (.not. in_list(law, 'linear quadratic')) call bad('contact', 1, 'law', '''' // trim(law) &
                                                          // ''' is not one of linear, quadratic')
    tangent = lower(tangent)
    if (.not. in_list(tangent, 'exact symmetric main fd')) call bad('contact', 1, 'tangent', '''' // trim(tangent) &
        // ''' is not one of exact, symmetric, main, fd')
    call need_real('contact', 1, 'penalty', [penalty])
    call positive('contact', 1, 'penalty', penalty)
    if (regularization_gap < 0.0_dp) call bad('contact', 1, 'regularization_gap', 'is ' // str(regularization_gap) &
                                              // '; it must be >= 0')
    if (law == 'quadratic' .and. .not. (regularization_gap > 0.0_dp)) call bad('contact', 1, 'regularization_gap', &
        'the quadratic law needs regularization_gap > 0 (the gap at which contact starts)')
    if (friction < 0.0_dp) call bad('contact', 1, 'friction', 'is ' // str(friction) // '; it must be >= 0')
    if (friction > 0.0_dp) call positive('contact', 1, 'tangential_penalty', tangential_penalty)
    if (tangential_penalty < 0.0_dp) call bad('contact', 1, 'tangential_penalty', 'is ' // str(tangential_penalty) &
                                              // '; it must be >= 0')
    n = 0
    do i = 1, max_pairs
      if (all(pairs(:, i) == 0)) exit
      if (any(pairs(:, i) < 1)) call bad('contact', 1, 'pairs', 'pair ' // str(i) // ' is incomplete or not positive:' &
                                         // ' give pairs = ga, gb, ... with contact group numbers >= 1')
      if (.not. any(m%beam_group == pairs(1, i)) .or. .not. any(m%beam_group == pairs(2, i))) &
        call bad('contact', 1, 'pairs', 'pair ' // str(i) // ' (' // str(pairs(1, i)) // ', ' // str(pairs(2, i)) &
                 // ') names a group no beam belongs to (set group = on the &beam groups)')
      n = i
    end do
    if (n == 0 .and. .not. self_contact) call bad('contact', 1, 'pairs', &
        'missing: give pairs = ga, gb (groups that touch) or self_contact = .true.')
    m%contact%enabled = .true.
    m%contact%curve = curve; m%contact%law = law; m%contact%penalty = penalty; m%contact%tangent = tangent
    m%contact%regularization_gap = regularization_gap; m%contact%friction = friction
    m%contact%tangential_penalty = tangential_penalty; m%contact%self_contact = self_contact
    m%contact%n_pairs = n
    m%contact%pairs = pairs(:, 1:n)
    call option('search_margin', option_model_real, search_margin)
    call option('threads', option_model_int, real(threads, dp))
    call option('max_handover_hops', option_model_int, real(max_handover_hops, dp))
    call option('max_candidates', option_model_int, real(max_candidates, dp))
    call option('parallel_angle', option_params_real, parallel_angle)
    call option('warm_start', option_params_int, real(warm_start, dp))
    call option('max_iterations', option_params_int, real(max_iterations, dp))
    contact_type = lower(contact_type)
    if (.not. in_list(contact_type, 'point line all_angle')) call bad('contact', 1, 'contact_type', '''' &
        // trim(contact_type) // ''' is not one of point, line, all_angle')
    select case (contact_type)
    case ('line'); call option('contact_type', option_params_int, real(B2B_CONTACT_TYPE_LINE, dp))
    case ('all_angle'); call option('contact_type', option_params_int, real(B2B_CONTACT_TYPE_ALL_ANGLE, dp))
    case default; call option('contact_type', option_params_int, real(B2B_CONTACT_TYPE_POINT, dp))
    end select
    call option('line_penalty', option_params_real, line_penalty)
    call option('line_tangential_penalty', option_params_real, line_tangential_penalty)
    call option('line_points', option_params_int, real(line_points, dp))
    call option('line_angle', option_params_real, line_angle)
    call option('point_angle', option_params_real, point_angle)
    call check_options(m)
  contains
    !> Records a library option the scene gives (and only then).
    subroutine option(key, kind, value)
      character(len=*), intent(in) :: key
      integer, intent(in) :: kind
      real(dp), intent(in) :: value
      if (.not. idx%has_key('contact', 1, key)) return
      m%contact%n_options = m%contact%n_options + 1
      m%contact%option_key(m%contact%n_options) = key
      m%contact%option_kind(m%contact%n_options) = kind
      m%contact%option_value(m%contact%n_options) = value
    end subroutine option
  end subroutine read_contact

  !> The library's own check of the options of &contact, now, with the line:
  !> they are set on a model and a parameter set made for it, exactly as the
  !> contact hook sets them later, and the first refused stops the program
  !> with the library's message.
  subroutine check_options(m)
    type(scene_model), intent(in) :: m
    type(b2b_model) :: model
    type(b2b_params) :: params
    integer :: ierr
    character(len=512) :: msg
    character(len=:), allocatable :: key
    if (m%contact%n_options == 0) return
    call b2b_model_create(model, ierr, msg)
    if (ierr /= 0) call fatal('contact model: create: ' // trim(msg))
    call b2b_params_create(params, ierr, msg)
    if (ierr /= 0) call fatal('contact model: parameters: ' // trim(msg))
    call contact_hook_options(m, model, params, ierr, msg, key)
    call b2b_params_destroy(params)
    call b2b_model_destroy(model)
    if (ierr /= 0) call bad('contact', 1, key, trim(msg))
  end subroutine check_options

  subroutine read_check(u, m)
    integer, intent(in) :: u
    type(scene_model), intent(inout) :: m
    character(len=32) :: kind
    integer :: beam_a, beam_b, min_contacts, min_nodes_crossed, ios
    real(dp) :: tolerance, min_rate, reference
    character(len=256) :: iomsg
    namelist /check/ kind, beam_a, beam_b, tolerance, min_rate, min_contacts, min_nodes_crossed, reference
    if (idx%count('check') == 0) return
    kind = ''; beam_a = 1; beam_b = 2; tolerance = 0.01_dp; min_rate = 1.8_dp; min_contacts = 1
    min_nodes_crossed = 0; reference = -1.0_dp
    rewind (u)
    read (u, nml=check, iostat=ios, iomsg=iomsg)
    if (ios /= 0) call read_failed('check', 1, ios, iomsg)
    kind = lower(kind)
    if (.not. in_list(kind, 'crossed_beams cantilever_crossbar sliding friction_pull many_contacts capstan ' &
                      // 'reference strand arc_slide double_helix ' // line_check_kinds)) &
      call bad('check', 1, 'kind', '''' // trim(kind) // ''' is not one of crossed_beams, cantilever_crossbar, ' &
               // 'sliding, friction_pull, many_contacts, capstan, reference, strand, arc_slide, double_helix, ' &
               // line_check_kinds)
    if (kind == 'reference' .and. .not. reference > 0.0_dp) &
      call bad('check', 1, 'reference', 'kind ''reference'' needs reference > 0 (the final displacement)')
    if (.not. m%contact%enabled) call bad('check', 1, 'kind', 'a contact check needs a &contact group')
    if (beam_a < 1 .or. beam_a > m%n_beams) call bad('check', 1, 'beam_a', 'beam ' // str(beam_a) // ' does not exist')
    if (beam_b < 1 .or. beam_b > m%n_beams .or. beam_b == beam_a) call bad('check', 1, 'beam_b', 'beam ' &
        // str(beam_b) // ' does not exist or equals beam_a')
    call positive('check', 1, 'tolerance', tolerance)
    call positive('check', 1, 'min_rate', min_rate)
    m%check%kind = kind; m%check%beam_a = beam_a; m%check%beam_b = beam_b; m%check%tolerance = tolerance
    m%check%min_rate = min_rate; m%check%min_contacts = min_contacts; m%check%min_nodes_crossed = min_nodes_crossed
    m%check%reference = reference
  end subroutine read_check

  ! ---------------------------------------------------------------- helpers

  logical function in_list(word, list)
    character(len=*), intent(in) :: word, list
    in_list = index(' ' // lower(list) // ' ', ' ' // trim(lower(word)) // ' ') > 0 .and. len_trim(word) > 0
  end function in_list

  pure function cross(a, b) result(c)
    real(dp), intent(in) :: a(3), b(3)
    real(dp) :: c(3)
    c = [a(2) * b(3) - a(3) * b(2), a(3) * b(1) - a(1) * b(3), a(1) * b(2) - a(2) * b(1)]
  end function cross

  pure function base_name(file) result(s)
    character(len=*), intent(in) :: file
    character(len=name_len) :: s
    integer :: i, j
    i = index(file, '/', back=.true.)
    s = file(i + 1:)
    j = index(s, '.', back=.true.)
    if (j > 1) s = s(1:j - 1)
  end function base_name

end module demo_scene_reader
