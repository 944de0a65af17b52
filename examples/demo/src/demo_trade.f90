!> The trade table: speed against accuracy on the large-sliding scenes.
!>
!>   b2b_demo --trade-table [short|full|line] [scene_dir [output_dir]]
!>
!> Runs the demo's own solver in this process on variants of the scenes
!> sliding_hermite.nml (frictionless) and sliding_friction.nml (mu = 0.2)
!> from scene_dir (default examples/demo/scenes): every curve kind x two
!> meshes of the curved beam (20 and 40 elements; the variant scene files
!> are written to output_dir) x every tangent option x two penalties (1e6
!> and 1e8; the tangential penalty of the friction scene follows). Per run:
!>
!>  * force error: max over the steps of |f_N - f_N,ref| and |f_T - f_T,ref|
!>    (sums over the active contacts, as in the history CSV), divided by the
!>    reference's largest f_N. The reference is the same scene and penalty
!>    with a refined curved beam (80 elements), curve hermite_nodal and the
!>    exact tangent. The full mode also runs the reference with 160
!>    elements and prints its error against the 80-element one (at the first
!>    penalty).
!>  * f_N oscillation: with d = f_N - f_N,ref, the max over the steps with
!>    the load fully applied (the drag) of |d(i) - (d(i-1) + d(i+1))/2| (the
!>    step's distance from the chord of its neighbours: a jump where the
!>    point crosses a node shows up as about half the jump; the smooth trend
!>    of the history, which the reference shares, drops out), same scale.
!>  * Newton iterations per planned step (all attempts, cut-backs included),
!>    mean and max (a step that stopped the run not included); cut-backs (a
!>    step's increment halved after a failed Newton solve); "stopped": the
!>    step at which the run gave up after max_cutbacks (error and oscillation
!>    are then not given); wall time of the run (reading, solving; no output).
!>
!> The short mode is a subset (mesh 40, penalty 1e6; the exact tangent for
!> every curve kind, every tangent for hermite_nodal). The full mode adds
!> the line-contact scenes (line_section: contact_type, curve kind,
!> line_points, each with the scene's own check); mode 'line' runs only those. The table is printed
!> as Markdown and written to output_dir/trade_table_<mode>.md.
module demo_trade
  use demo_kinds, only: dp
  use demo_model, only: scene_model, external_force
  use demo_scene_reader, only: read_scene
  use demo_solver, only: solve_scene
  use demo_history, only: run_history
  use demo_output, only: output_prepare_dir
  use demo_errors, only: fatal, str
  use demo_nml_scan, only: lower
  use demo_model, only: option_params_int
  use demo_checks_line, only: line_check_reset, line_check_finish, line_check_result
  use b2b, only: b2b_version, B2B_CONTACT_TYPE_POINT, B2B_CONTACT_TYPE_LINE, B2B_CONTACT_TYPE_ALL_ANGLE
  use, intrinsic :: iso_fortran_env, only: int64, output_unit
  implicit none
  private
  public :: trade_table

  character(len=*), parameter :: curves(4) = [character(len=22) :: 'linear', 'hermite_midpoint', 'hermite_nodal', &
                                                                   'hermite_nodal_weighted']
  character(len=*), parameter :: tangents(4) = [character(len=9) :: 'exact', 'symmetric', 'main', 'fd']
  integer, parameter :: meshes(2) = [20, 40], ref_mesh = 80, check_mesh = 160
  real(dp), parameter :: penalties(2) = [1.0e6_dp, 1.0e8_dp]
  character(len=*), parameter :: scenes(2) = [character(len=16) :: 'sliding_hermite', 'sliding_friction']
  character(len=*), parameter :: scene_what(2) = [character(len=40) :: 'frictionless', 'friction mu = 0.2']

  ! the line-contact scenes (full mode): file (relative to scene_dir) and name
  character(len=*), parameter :: line_scenes(5) = [character(len=48) :: 'capstan_cylinder_90', &
    'capstan_cylinder_180', 'capstan_cylinder_360', 'line_load', &
    'angle_sweep']
  character(len=*), parameter :: contact_types(3) = [character(len=9) :: 'point', 'line', 'all_angle']
  integer, parameter :: line_point_counts(3) = [4, 8, 16]

  type :: run_result
    integer :: stopped = 0, n = 0, cutbacks = 0, it_max = 0, drag_from = 1
    real(dp) :: it_mean = 0.0_dp, time = 0.0_dp, err = -1.0_dp, osc = -1.0_dp, fn_max = 0.0_dp
    real(dp), allocatable :: fn(:), ft(:)
  end type run_result

contains

  subroutine trade_table(mode, scene_dir, out_dir, passed)
    character(len=*), intent(in) :: mode, scene_dir, out_dir
    logical, intent(out) :: passed
    type(run_result) :: ref, r
    integer :: s, c, k, t, p, u, ios, major, minor, patch, n_runs
    character(len=:), allocatable :: file
    character(len=1024) :: md
    real(dp) :: total
    integer(int64) :: c0, c1, rate

    if (mode /= 'short' .and. mode /= 'full' .and. mode /= 'line') &
      call fatal('--trade-table: mode ''' // mode // ''' is not short, full or line')
    passed = .true.
    call output_prepare_dir(out_dir, 'trade_table_' // mode, 'the output directory of --trade-table')
    call system_clock(c0, rate)
    md = trim(out_dir) // '/trade_table_' // mode // '.md'
    open (newunit=u, file=trim(md), status='replace', action='write', iostat=ios)
    if (ios /= 0) call fatal(trim(md) // ': cannot write (does the output directory exist?)')
    call b2b_version(major, minor, patch)
    call emit(u, '## Trade table (' // mode // ')')
    call emit(u, '')
    call emit(u, 'Machine: ' // cpu_model() // ', ' // str(cpu_count()) // ' logical CPUs; b2b ' // str(major) // '.' &
              // str(minor) // '.' // str(patch) // '; command: `b2b_demo --trade-table ' // mode // '`')
    call emit(u, '')
    if (mode /= 'line') call emit(u, 'Slider pressed by P = 1000 into a clamped arc (R = 5, 100 degrees) and ' &
              // 'dragged up it (80 load steps). ' &
              // 'Force error and f_N oscillation (of f_N - f_N,ref) relative to the reference''s largest f_N; ' &
              // 'reference: the same ' &
              // 'scene and penalty, arc of ' // str(ref_mesh) // ' elements, hermite_nodal, exact tangent. ' &
              // 'Iterations per load step (all attempts). A run that gives up after max_cutbacks shows the step.')
    n_runs = 0
    do s = 1, size(scenes)
      if (mode == 'line') exit   ! the line-contact rows only
      file = trim(scene_dir) // '/' // trim(scenes(s)) // '.nml'
      do p = 1, size(penalties)
        if (mode == 'short' .and. p > 1) cycle
        ref = run_variant(file, trim(scenes(s)), ref_mesh, 'hermite_nodal', 'exact', penalties(p), out_dir)
        n_runs = n_runs + 1
        if (ref%stopped > 0) then
          call emit(u, '')
          call emit(u, 'REFERENCE RUN FAILED: ' // trim(scenes(s)) // ', penalty ' // es(penalties(p)) &
                    // ', stopped at step ' // str(ref%stopped))
          passed = .false.
          cycle
        end if
        r = ref
        call measure(ref, r)
        call emit(u, '')
        call emit(u, '### ' // trim(scenes(s)) // ' (' // trim(scene_what(s)) // '), penalty ' // es(penalties(p)))
        call emit(u, '')
        call emit(u, 'Reference: largest f_N ' // es(ref%fn_max) // ', ' // fx(ref%it_mean) &
                  // ' iterations per step, ' // fx(ref%time) // ' s.')
        if (mode == 'full' .and. p == 1) then
          ! how good is the reference itself: against a twice finer arc
          r = run_variant(file, trim(scenes(s)), check_mesh, 'hermite_nodal', 'exact', penalties(p), out_dir)
          n_runs = n_runs + 1
          call measure(r, ref)
          call emit(u, '')
          call emit(u, 'The reference against a ' // str(check_mesh) // '-element arc (same settings): force error ' &
                    // opt(es(r%err), r%stopped == 0) // ', f_N oscillation ' // opt(es(r%osc), r%stopped == 0) &
                    // ', ' // fx(r%time) // ' s.')
        end if
        call emit(u, '')
        call emit(u, '| curve | arc el. | tangent | force error | f_N oscillation | iter. mean | iter. max |' &
                  // ' cut-backs | stopped | time s |')
        call emit(u, '|---|---:|---|---:|---:|---:|---:|---:|---|---:|')
        do c = 1, size(curves)
          do k = 1, size(meshes)
            if (mode == 'short' .and. meshes(k) /= 40) cycle
            do t = 1, size(tangents)
              if (mode == 'short' .and. t > 1 .and. trim(curves(c)) /= 'hermite_nodal') cycle
              r = run_variant(file, trim(scenes(s)), meshes(k), trim(curves(c)), trim(tangents(t)), penalties(p), &
                              out_dir)
              n_runs = n_runs + 1
              call measure(r, ref)
              call emit(u, '| ' // trim(curves(c)) // ' | ' // str(meshes(k)) // ' | ' // trim(tangents(t)) // ' | ' &
                        // opt(es(r%err), r%stopped == 0) // ' | ' // opt(es(r%osc), r%stopped == 0) // ' | ' &
                        // fx(r%it_mean) // ' | ' // str(r%it_max) // ' | ' // str(r%cutbacks) // ' | ' &
                        // opt('step ' // str(r%stopped), r%stopped > 0) // ' | ' // fx(r%time) // ' |')
            end do
          end do
        end do
      end do
    end do
    if (mode == 'full' .or. mode == 'line') call line_section(u, scene_dir, out_dir, n_runs)
    call system_clock(c1)
    total = real(c1 - c0, dp) / real(rate, dp)
    call emit(u, '')
    call emit(u, str(n_runs) // ' runs in ' // fx(total) // ' s.')
    close (u)
    write (output_unit, '(a)') 'trade table written to ' // trim(md)
  end subroutine trade_table

  !> The line-contact scenes (b2b_pair.h "Line contact"), each with its own
  !> &check: the scene as it is, then with every contact_type (point, line,
  !> all_angle), every curve kind, and line_points 4, 8, 16 (one change at a
  !> time; a variant equal to the scene is not run twice). Per run the
  !> check's verdict and worst error (demo_checks_line), the Newton
  !> iterations per step, cut-backs, the step that stopped the run, and time.
  subroutine line_section(u, scene_dir, out_dir, n_runs)
    integer, intent(in) :: u
    character(len=*), intent(in) :: scene_dir, out_dir
    integer, intent(inout) :: n_runs
    integer :: s, k
    character(len=:), allocatable :: file, name, ct0, cv0
    integer :: lp0
    type(scene_model) :: m
    call emit(u, '')
    call emit(u, '### Line contact (contact_type, curve kind, integration points)')
    call emit(u, '')
    call emit(u, 'The line-contact scenes with their own &check (README, "Line contact scenes"): the scene as it is ' &
              // '(first row), then one setting changed at a time. check error: the check''s worst relative error ' &
              // '(euler_eytelwein: T_out/T_in against exp(mu theta) over the steps where the rope slides steadily; ' &
              // 'line_load: the penetration against q / line_penalty; angle_sweep: the largest change of sum f_N ' &
              // 'between steps over P). The capstans need line contact: the point element''s closest-point problem ' &
              // 'is singular there (a rope equidistant from the cylinder''s axis).')
    call emit(u, '')
    call emit(u, '| scene | contact_type | curve | line_points | check | check error | iter. mean | iter. max |' &
              // ' cut-backs | stopped | time s |')
    call emit(u, '|---|---|---|---:|---|---:|---:|---:|---:|---|---:|')
    do s = 1, size(line_scenes)
      file = trim(scene_dir) // '/' // trim(line_scenes(s)) // '.nml'
      name = trim(line_scenes(s))
      name = name(index(name, '/', back=.true.) + 1:)
      call read_scene(file, m)
      ct0 = contact_type_of(m)
      cv0 = trim(m%contact%curve)
      lp0 = nint(option_of(m, 'line_points'))
      call line_row(u, file, name, ct0, cv0, lp0, out_dir, n_runs)
      do k = 1, size(contact_types)
        if (trim(contact_types(k)) /= ct0) call line_row(u, file, name, trim(contact_types(k)), cv0, lp0, out_dir, n_runs)
      end do
      do k = 1, size(curves)
        if (trim(curves(k)) /= cv0) call line_row(u, file, name, ct0, trim(curves(k)), lp0, out_dir, n_runs)
      end do
      do k = 1, size(line_point_counts)
        if (line_point_counts(k) /= lp0) call line_row(u, file, name, ct0, cv0, line_point_counts(k), out_dir, n_runs)
      end do
    end do
  end subroutine line_section

  !> One run of a line-contact scene with contact_type, curve and line_points set; one table row.
  subroutine line_row(u, file, name, ctype, curve, points, out_dir, n_runs)
    integer, intent(in) :: u, points
    character(len=*), intent(in) :: file, name, ctype, curve, out_dir
    integer, intent(inout) :: n_runs
    type(scene_model) :: m
    type(run_history) :: h
    integer(int64) :: c0, c1, rate
    integer :: stopped, n, checked, it_max, cuts
    real(dp) :: time, err, it_mean
    logical :: passed
    character(len=:), allocatable :: verdict, err_text, points_text

    call system_clock(c0, rate)
    call read_scene(file, m)
    m%contact%curve = curve
    select case (ctype)
    case ('line'); call set_option(m, 'contact_type', real(B2B_CONTACT_TYPE_LINE, dp))
    case ('all_angle'); call set_option(m, 'contact_type', real(B2B_CONTACT_TYPE_ALL_ANGLE, dp))
    case default; call set_option(m, 'contact_type', real(B2B_CONTACT_TYPE_POINT, dp))
    end select
    if (points > 0) call set_option(m, 'line_points', real(points, dp))
    m%vtk = .false.
    m%csv = .false.
    m%out_dir = out_dir
    call line_check_reset(.true.)
    call solve_scene(m, quiet=.true., history=h, failed_step=stopped)
    call system_clock(c1)
    time = real(c1 - c0, dp) / real(rate, dp)
    n_runs = n_runs + 1
    n = h%n_steps
    if (stopped > 0) then
      verdict = '—'
      err_text = '—'
    else
      passed = line_check_finish(m)
      call line_check_result(err, passed, checked)
      verdict = trim(merge('passed', 'FAILED', passed))
      err_text = opt(es(err), checked > 0)
    end if
    it_mean = 0.0_dp
    it_max = 0
    cuts = 0
    if (n > 0) then
      it_mean = real(sum(h%steps(1:n)%iterations), dp) / real(n, dp)
      it_max = maxval(h%steps(1:n)%iterations)
      cuts = sum(h%steps(1:n)%cutbacks)
    end if
    if (stopped > 0) cuts = cuts + m%max_cutbacks
    points_text = 'default'
    if (points > 0) points_text = str(points)
    call emit(u, '| ' // name // ' | ' // ctype // ' | ' // curve // ' | ' // points_text // ' | ' // verdict // ' | ' &
              // err_text // ' | ' // opt(fx(it_mean), n > 0) // ' | ' // opt(str(it_max), n > 0) // ' | ' &
              // str(cuts) // ' | ' // opt('step ' // str(stopped), stopped > 0) // ' | ' // fx(time) // ' |')
  end subroutine line_row

  !> The contact_type a scene sets (point if none).
  function contact_type_of(m) result(s)
    type(scene_model), intent(in) :: m
    character(len=:), allocatable :: s
    select case (nint(option_of(m, 'contact_type')))
    case (B2B_CONTACT_TYPE_LINE); s = 'line'
    case (B2B_CONTACT_TYPE_ALL_ANGLE); s = 'all_angle'
    case default; s = 'point'
    end select
  end function contact_type_of

  real(dp) function option_of(m, key) result(v)
    type(scene_model), intent(in) :: m
    character(len=*), intent(in) :: key
    integer :: k
    v = 0.0_dp
    do k = 1, m%contact%n_options
      if (trim(m%contact%option_key(k)) == key) v = m%contact%option_value(k)
    end do
  end function option_of

  !> Sets (or adds) an integer option of the parameter set.
  subroutine set_option(m, key, value)
    type(scene_model), intent(inout) :: m
    character(len=*), intent(in) :: key
    real(dp), intent(in) :: value
    integer :: k
    do k = 1, m%contact%n_options
      if (trim(m%contact%option_key(k)) == key) then
        m%contact%option_value(k) = value
        return
      end if
    end do
    m%contact%n_options = m%contact%n_options + 1
    m%contact%option_key(m%contact%n_options) = key
    m%contact%option_kind(m%contact%n_options) = option_params_int
    m%contact%option_value(m%contact%n_options) = value
  end subroutine set_option

  subroutine emit(u, line)
    integer, intent(in) :: u
    character(len=*), intent(in) :: line
    write (u, '(a)') line
    write (output_unit, '(a)') line
    flush (output_unit)
  end subroutine emit

  !> One variant: the scene with n_el elements on its arc, the given curve
  !> kind, tangent and penalty; no output files, no check, quiet.
  function run_variant(file, name, n_el, curve, tangent, penalty, out_dir) result(r)
    character(len=*), intent(in) :: file, name, curve, tangent, out_dir
    integer, intent(in) :: n_el
    real(dp), intent(in) :: penalty
    type(run_result) :: r
    type(scene_model) :: m
    type(run_history) :: h
    character(len=:), allocatable :: variant
    integer(int64) :: c0, c1, rate
    integer :: i, full
    real(dp) :: f1

    variant = trim(out_dir) // '/trade_' // name // '_' // str(n_el) // '.nml'
    call write_variant(file, variant, n_el)
    call system_clock(c0, rate)
    call read_scene(variant, m)
    m%contact%curve = curve
    m%contact%tangent = tangent
    m%contact%penalty = penalty
    if (m%contact%friction > 0.0_dp) m%contact%tangential_penalty = penalty
    m%check%kind = ''
    m%vtk = .false.
    m%csv = .false.
    m%out_dir = out_dir
    call solve_scene(m, quiet=.true., history=h, failed_step=r%stopped)
    call system_clock(c1)
    r%time = real(c1 - c0, dp) / real(rate, dp)
    r%n = h%n_steps
    allocate (r%fn(r%n), r%ft(r%n))
    r%it_max = 0
    r%it_mean = 0.0_dp
    r%cutbacks = 0
    if (r%n > 0) then
      r%fn = h%steps(1:r%n)%fn
      r%ft = h%steps(1:r%n)%ft
      r%cutbacks = sum(h%steps(1:r%n)%cutbacks)
      r%it_max = maxval(h%steps(1:r%n)%iterations)
      r%it_mean = real(sum(h%steps(1:r%n)%iterations), dp) / real(r%n, dp)
    end if
    ! the step that stopped the run: max_cutbacks halvings, max_cutbacks + 1 failed solves
    if (r%stopped > 0) r%cutbacks = r%cutbacks + m%max_cutbacks
    ! the drag: the steps from which the external load is fully applied
    f1 = norm2(external_force(m, 1.0_dp))
    full = r%n + 1
    do i = 1, r%n
      if (norm2(external_force(m, h%steps(i)%lam)) >= (1.0_dp - 1.0e-12_dp) * f1) then
        full = i
        exit
      end if
    end do
    r%drag_from = full
  end function run_variant

  !> Force error against ref and the f_N oscillation, scaled by ref's largest f_N.
  subroutine measure(r, ref)
    type(run_result), intent(inout) :: r
    type(run_result), intent(in) :: ref
    real(dp) :: scale
    integer :: i
    r%fn_max = 0.0_dp
    if (r%n > 0) r%fn_max = maxval(r%fn)
    scale = max(maxval(ref%fn), tiny(1.0_dp))
    if (r%stopped > 0 .or. r%n /= ref%n) return
    r%err = max(maxval(abs(r%fn - ref%fn)), maxval(abs(r%ft - ref%ft))) / scale
    ! the wiggle of f_N - f_N,ref: its distance from the chord of its neighbours
    r%osc = 0.0_dp
    do i = r%drag_from + 1, r%n - 1
      r%osc = max(r%osc, abs(d(i) - 0.5_dp * (d(i - 1) + d(i + 1))))
    end do
    r%osc = r%osc / scale
  contains
    real(dp) function d(j)
      integer, intent(in) :: j
      d = r%fn(j) - ref%fn(j)
    end function d
  end subroutine measure

  !> Copies the scene file, changing n_el of its one arc beam.
  subroutine write_variant(file, variant, n_el)
    character(len=*), intent(in) :: file, variant
    integer, intent(in) :: n_el
    integer :: ui, uo, ios, found, i, j, e
    character(len=2048) :: line, low
    open (newunit=ui, file=file, status='old', action='read', iostat=ios)
    if (ios /= 0) call fatal(file // ': cannot open the scene for the trade table (give the scene directory:' &
                             // ' b2b_demo --trade-table short|full scene_dir [output_dir])')
    open (newunit=uo, file=variant, status='replace', action='write', iostat=ios)
    if (ios /= 0) call fatal(variant // ': cannot write (does the output directory exist?)')
    found = 0
    do
      read (ui, '(a)', iostat=ios) line
      if (ios /= 0) exit
      low = lower(line)
      if (index(low, '&beam') > 0 .and. index(low, '''arc''') > 0) then
        i = index(low, 'n_el')
        if (i == 0) call fatal(file // ': the arc''s &beam line has no n_el')
        j = i + index(low(i:), '=')
        e = j - 1 + scan(low(j:), ',/')
        line = line(1:j - 1) // ' ' // str(n_el) // line(e:)
        found = found + 1
      end if
      write (uo, '(a)') trim(line)
    end do
    close (ui)
    close (uo)
    if (found /= 1) call fatal(file // ': the trade table needs exactly one arc beam (&beam shape = ''arc'' on one' &
                               // ' line); found ' // str(found))
  end subroutine write_variant

  function cpu_model() result(s)
    character(len=:), allocatable :: s
    character(len=512) :: line
    integer :: u, ios, i
    s = 'unknown CPU'
    open (newunit=u, file='/proc/cpuinfo', status='old', action='read', iostat=ios)
    if (ios /= 0) return
    do
      read (u, '(a)', iostat=ios) line
      if (ios /= 0) exit
      if (index(line, 'model name') == 1) then
        i = index(line, ':')
        s = trim(adjustl(line(i + 1:)))
        exit
      end if
    end do
    close (u)
  end function cpu_model

  integer function cpu_count() result(n)
    character(len=512) :: line
    integer :: u, ios
    n = 0
    open (newunit=u, file='/proc/cpuinfo', status='old', action='read', iostat=ios)
    if (ios /= 0) return
    do
      read (u, '(a)', iostat=ios) line
      if (ios /= 0) exit
      if (index(line, 'processor') == 1) n = n + 1
    end do
    close (u)
  end function cpu_count

  !> text if show, else a dash
  function opt(text, show) result(s)
    character(len=*), intent(in) :: text
    logical, intent(in) :: show
    character(len=:), allocatable :: s
    if (show) then
      s = text
    else
      s = '—'
    end if
  end function opt

  function es(x) result(s)
    real(dp), intent(in) :: x
    character(len=:), allocatable :: s
    character(len=16) :: buf
    write (buf, '(es9.1)') x
    s = trim(adjustl(buf))
  end function es

  function fx(x) result(s)
    real(dp), intent(in) :: x
    character(len=:), allocatable :: s
    character(len=16) :: buf
    write (buf, '(f10.2)') x
    s = trim(adjustl(buf))
  end function fx

end module demo_trade
