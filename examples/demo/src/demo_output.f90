!> Result files of a scene, in out_dir:
!>   <name>_NNNN.vtp   beam axes of step NNNN (VTK XML PolyData, ASCII): one
!>                     polyline per beam, point data radius, displacement,
!>                     rotation (rotation vector); cell data beam, group.
!>                     With contact, one vertex per active contact after the
!>                     beam nodes (at the midpoint of the closest points),
!>                     with point data normal_force (f_N n, the force on
!>                     beam A of the pair; n points from B to A) and
!>                     friction_force (-T, the friction force on beam A),
!>                     zero on the beam nodes; vertex cells have beam = group = 0
!>   <name>.pvd        the collection of those files by load factor
!>   <name>_history.csv, <name>_convergence.csv,
!>   <name>_contacts.csv (with contact: every active contact of every step)
!>   <name>.gp, <name>.png  a gnuplot script (force histories or the monitored
!>                     motion against the load factor; the residual of every
!>                     Newton iteration) and, when gnuplot is installed
!>                     (command -v gnuplot), the plot it draws; without
!>                     gnuplot the run says so once and writes the script only
!> The .pvd and the CSV files are written only when the whole run succeeded,
!> and the stale ones of an earlier run are deleted when a run starts: a
!> failed run never leaves a result that looks complete.
module demo_output
  use demo_kinds, only: dp
  use demo_model, only: scene_model
  use demo_history, only: run_history
  use demo_rotation, only: quat_to_rotvec
  use demo_errors, only: fatal
  use demo_contact_report, only: contact_snapshot, contact_report_snapshot, contact_point
  implicit none
  private
  public :: output_begin, output_step, output_finish, output_path, output_remove_stale, output_contacts
  public :: output_prepare_dir

  integer :: n_files = 0
  real(dp), allocatable :: file_lam(:)
  character(len=256), allocatable :: file_name(:)

  !> Rows of the contacts CSV, kept until the run is complete.
  type :: contact_row
    integer :: step = 0
    real(dp) :: lam = 0.0_dp
    type(contact_point) :: c
  end type contact_row
  integer :: n_rows = 0
  type(contact_row), allocatable :: rows(:)

  !> gnuplot: 0 not looked for yet, 1 found, -1 not installed (said once)
  integer, save :: gnuplot_state = 0

contains

  function output_path(m, suffix) result(p)
    type(scene_model), intent(in) :: m
    character(len=*), intent(in) :: suffix
    character(len=:), allocatable :: p
    p = trim(m%out_dir) // '/' // trim(m%name) // suffix
  end function output_path

  subroutine output_begin(m)
    type(scene_model), intent(in) :: m
    n_files = 0
    if (allocated(file_lam)) deallocate (file_lam, file_name)
    allocate (file_lam(16), file_name(16))
    n_rows = 0
    if (allocated(rows)) deallocate (rows)
    allocate (rows(64))
    call output_remove_stale(m%out_dir, m%name)
  end subroutine output_begin

  !> Makes sure the output directory dir exists and takes files, before any
  !> work: a file <name>_write_test.tmp is created there and deleted; if
  !> that fails, the directory is created (mkdir -p, parents included) and
  !> the test repeated. A directory that cannot be created or written is a
  !> fatal error naming it (where stands for where it came from, e.g. 'the
  !> second argument'), so that a run never solves for minutes and then
  !> finds it cannot write its result.
  subroutine output_prepare_dir(dir, name, where)
    character(len=*), intent(in) :: dir, name, where
    character(len=:), allocatable :: probe, quoted
    character(len=256) :: iomsg
    integer :: stat, cstat, i
    probe = trim(dir) // '/' // trim(name) // '_write_test.tmp'
    if (try_write(probe, iomsg)) return
    ! not there (or not writable): create it with its parents; the name
    ! goes to the shell in single quotes, a quote in it as '\''
    quoted = ''
    do i = 1, len_trim(dir)
      if (dir(i:i) == '''') then
        quoted = quoted // '''\'''''
      else
        quoted = quoted // dir(i:i)
      end if
    end do
    stat = 1
    cstat = 0
    call execute_command_line('mkdir -p -- ''' // quoted // ''' 2> /dev/null', exitstat=stat, cmdstat=cstat)
    if (cstat /= 0 .or. stat /= 0) call fatal('output directory ''' // trim(dir) // ''' (' // where &
      // ') cannot be created (mkdir -p failed: is a part of the path a regular file, or not writable?);' &
      // ' give a directory that exists or can be created')
    if (.not. try_write(probe, iomsg)) call fatal('output directory ''' // trim(dir) // ''' (' // where &
      // ') takes no files: ' // probe // ': ' // trim(iomsg) // '; give a writable directory')
  contains
    logical function try_write(path, msg) result(ok)
      character(len=*), intent(in) :: path
      character(len=*), intent(out) :: msg
      integer :: u, ios2
      msg = ''
      open (newunit=u, file=path, status='replace', action='write', iostat=ios2, iomsg=msg)
      ok = ios2 == 0
      if (ok) close (u, status='delete', iostat=ios2)
    end function try_write
  end subroutine output_prepare_dir

  !> Deletes the complete-run files of scene `name` in dir, if any.
  subroutine output_remove_stale(dir, name)
    character(len=*), intent(in) :: dir, name
    call remove(trim(dir) // '/' // trim(name) // '.pvd')
    call remove(trim(dir) // '/' // trim(name) // '_history.csv')
    call remove(trim(dir) // '/' // trim(name) // '_convergence.csv')
    call remove(trim(dir) // '/' // trim(name) // '_contacts.csv')
    call remove(trim(dir) // '/' // trim(name) // '.gp')
    call remove(trim(dir) // '/' // trim(name) // '.png')
    call remove(trim(dir) // '/' // trim(name) // '_gnuplot.log')
  end subroutine output_remove_stale

  subroutine remove(path)
    character(len=*), intent(in) :: path
    integer :: u, ios
    logical :: there
    inquire (file=path, exist=there)
    if (.not. there) return
    open (newunit=u, file=path, iostat=ios)
    if (ios == 0) close (u, status='delete', iostat=ios)
  end subroutine remove

  !> The .vtp file of a converged step (step 0 = initial state).
  subroutine output_step(m, step, lam)
    type(scene_model), intent(in) :: m
    integer, intent(in) :: step
    real(dp), intent(in) :: lam
    character(len=16) :: tag
    character(len=256), allocatable :: tmpn(:)
    real(dp), allocatable :: tmpl(:)
    character(len=:), allocatable :: path
    integer :: u, ios, i, b, n, k
    type(contact_snapshot) :: snap

    if (.not. m%vtk) return
    call contact_report_snapshot(snap)
    if (step == 0) snap%n = 0
    write (tag, '(a,i4.4,a)') '_', step, '.vtp'
    path = output_path(m, trim(tag))
    open (newunit=u, file=path, status='replace', action='write', iostat=ios)
    if (ios /= 0) call fatal(path // ': cannot write (does the output directory ' // trim(m%out_dir) // ' exist?)')
    write (u, '(a)') '<?xml version="1.0"?>'
    write (u, '(a)') '<VTKFile type="PolyData" version="1.0" byte_order="LittleEndian">'
    write (u, '(a)') '<PolyData>'
    write (u, '(a,i0,a,i0,a,i0,a)') '<Piece NumberOfPoints="', m%n_nodes + snap%n, '" NumberOfVerts="', snap%n, &
      '" NumberOfLines="', m%n_beams, '">'
    write (u, '(a)') '<Points>'
    write (u, '(a)') '<DataArray type="Float64" NumberOfComponents="3" format="ascii">'
    write (u, '(3es24.15e3)') m%x
    do k = 1, snap%n
      write (u, '(3es24.15e3)') 0.5_dp * (snap%c(k)%info(3:5) + snap%c(k)%info(6:8))
    end do
    write (u, '(a)') '</DataArray>'
    write (u, '(a)') '</Points>'
    write (u, '(a)') '<Verts>'
    write (u, '(a)') '<DataArray type="Int32" Name="connectivity" format="ascii">'
    write (u, '(i0)') (m%n_nodes + k - 1, k = 1, snap%n)
    write (u, '(a)') '</DataArray>'
    write (u, '(a)') '<DataArray type="Int32" Name="offsets" format="ascii">'
    write (u, '(i0)') (k, k = 1, snap%n)
    write (u, '(a)') '</DataArray>'
    write (u, '(a)') '</Verts>'
    write (u, '(a)') '<Lines>'
    write (u, '(a)') '<DataArray type="Int32" Name="connectivity" format="ascii">'
    do b = 1, m%n_beams
      ! 0-based point ids; a ring repeats its first node to close the line
      write (u, '(20(i0,1x))') (m%beam_first_node(b) - 1 + i, i = 0, m%beam_n_nodes(b) - 1), &
        (m%beam_first_node(b) - 1, k = 1, merge(1, 0, m%beam_closed(b)))
    end do
    write (u, '(a)') '</DataArray>'
    write (u, '(a)') '<DataArray type="Int32" Name="offsets" format="ascii">'
    n = 0
    do b = 1, m%n_beams
      n = n + m%beam_n_nodes(b) + merge(1, 0, m%beam_closed(b))
      write (u, '(i0)') n
    end do
    write (u, '(a)') '</DataArray>'
    write (u, '(a)') '</Lines>'
    write (u, '(a)') '<PointData Scalars="radius" Vectors="displacement">'
    write (u, '(a)') '<DataArray type="Float64" Name="radius" format="ascii">'
    do b = 1, m%n_beams
      write (u, '(es24.15e3)') (m%beam_radius(b), i = 1, m%beam_n_nodes(b))
    end do
    write (u, '(es24.15e3)') (0.0_dp, k = 1, snap%n)
    write (u, '(a)') '</DataArray>'
    write (u, '(a)') '<DataArray type="Float64" Name="displacement" NumberOfComponents="3" format="ascii">'
    write (u, '(3es24.15e3)') m%x - m%x0
    write (u, '(3es24.15e3)') (0.0_dp, 0.0_dp, 0.0_dp, k = 1, snap%n)
    write (u, '(a)') '</DataArray>'
    write (u, '(a)') '<DataArray type="Float64" Name="rotation" NumberOfComponents="3" format="ascii">'
    do i = 1, m%n_nodes
      write (u, '(3es24.15e3)') quat_to_rotvec(m%q(:, i))
    end do
    write (u, '(3es24.15e3)') (0.0_dp, 0.0_dp, 0.0_dp, k = 1, snap%n)
    write (u, '(a)') '</DataArray>'
    if (m%contact%enabled) then
      write (u, '(a)') '<DataArray type="Float64" Name="normal_force" NumberOfComponents="3" format="ascii">'
      write (u, '(3es24.15e3)') (0.0_dp, 0.0_dp, 0.0_dp, i = 1, m%n_nodes)
      write (u, '(3es24.15e3)') (snap%c(k)%info(13) * snap%c(k)%info(9:11), k = 1, snap%n)
      write (u, '(a)') '</DataArray>'
      write (u, '(a)') '<DataArray type="Float64" Name="friction_force" NumberOfComponents="3" format="ascii">'
      write (u, '(3es24.15e3)') (0.0_dp, 0.0_dp, 0.0_dp, i = 1, m%n_nodes)
      write (u, '(3es24.15e3)') (-snap%c(k)%info(18:20), k = 1, snap%n)
      write (u, '(a)') '</DataArray>'
    end if
    write (u, '(a)') '</PointData>'
    ! cells: the contact vertices first, then the beams' polylines (VTK's order)
    write (u, '(a)') '<CellData Scalars="beam">'
    write (u, '(a)') '<DataArray type="Int32" Name="beam" format="ascii">'
    write (u, '(i0)') (0, k = 1, snap%n)
    write (u, '(i0)') (b, b = 1, m%n_beams)
    write (u, '(a)') '</DataArray>'
    write (u, '(a)') '<DataArray type="Int32" Name="group" format="ascii">'
    write (u, '(i0)') (0, k = 1, snap%n)
    write (u, '(i0)') m%beam_group
    write (u, '(a)') '</DataArray>'
    write (u, '(a)') '</CellData>'
    write (u, '(a)') '</Piece>'
    write (u, '(a)') '</PolyData>'
    write (u, '(a)') '</VTKFile>'
    close (u)

    if (n_files == size(file_lam)) then
      allocate (tmpl(2 * n_files), tmpn(2 * n_files))
      tmpl(1:n_files) = file_lam(1:n_files)
      tmpn(1:n_files) = file_name(1:n_files)
      call move_alloc(tmpl, file_lam)
      call move_alloc(tmpn, file_name)
    end if
    n_files = n_files + 1
    file_lam(n_files) = lam
    file_name(n_files) = trim(m%name) // trim(tag)
  end subroutine output_step

  !> Keeps the active contacts of a converged step for the contacts CSV.
  subroutine output_contacts(step, lam, snap)
    integer, intent(in) :: step
    real(dp), intent(in) :: lam
    type(contact_snapshot), intent(in) :: snap
    type(contact_row), allocatable :: tmp(:)
    integer :: k
    if (.not. allocated(rows)) allocate (rows(64))
    do k = 1, snap%n
      if (n_rows == size(rows)) then
        allocate (tmp(2 * n_rows))
        tmp(1:n_rows) = rows(1:n_rows)
        call move_alloc(tmp, rows)
      end if
      n_rows = n_rows + 1
      rows(n_rows) = contact_row(step=step, lam=lam, c=snap%c(k))
    end do
  end subroutine output_contacts

  !> CSV files and the .pvd collection, after a complete run.
  subroutine output_finish(m, h)
    type(scene_model), intent(in) :: m
    type(run_history), intent(in) :: h
    character(len=:), allocatable :: path
    integer :: u, ios, i

    if (m%csv) then
      path = output_path(m, '_history.csv')
      open (newunit=u, file=path, status='replace', action='write', iostat=ios)
      if (ios /= 0) call fatal(path // ': cannot write')
      write (u, '(a)') 'step,load_factor,iterations,cutbacks,residual,residual_ref,' &
                       // 'ux,uy,uz,rx,ry,rz,contacts,slipping,normal_force,friction_force,rate,active_set_fixed'
      do i = 1, h%n_steps
        associate (s => h%steps(i))
          write (u, '(i0,",",es23.15e3,2(",",i0),8(",",es23.15e3),2(",",i0),3(",",es23.15e3),",",i0)') s%step, &
            s%lam, s%iterations, s%cutbacks, s%last_norm, s%ref, s%u, s%rot, s%n_active, s%n_slip, s%fn, s%ft, &
            s%rate, merge(1, 0, s%stable)
        end associate
      end do
      close (u)
      if (m%contact%enabled) then
        path = output_path(m, '_contacts.csv')
        open (newunit=u, file=path, status='replace', action='write', iostat=ios)
        if (ios /= 0) call fatal(path // ': cannot write')
        write (u, '(a)') 'step,load_factor,beam_a,segment_a,beam_b,segment_b,xi,eta,x,y,z,nx,ny,nz,gap,' &
                         // 'normal_force,tx,ty,tz,friction_state'
        do i = 1, n_rows
          associate (r => rows(i))
            write (u, '(i0,",",es23.15e3,4(",",i0),13(",",es23.15e3),",",i0)') r%step, r%lam, r%c%pair, &
              r%c%info(1:2), 0.5_dp * (r%c%info(3:5) + r%c%info(6:8)), r%c%info(9:11), r%c%info(12), &
              r%c%info(13), r%c%info(18:20), nint(r%c%info(24))
          end associate
        end do
        close (u)
      end if
      path = output_path(m, '_convergence.csv')
      open (newunit=u, file=path, status='replace', action='write', iostat=ios)
      if (ios /= 0) call fatal(path // ': cannot write')
      write (u, '(a)') 'step,load_factor,iteration,residual,residual_ref'
      do i = 1, h%n_iters
        associate (s => h%iters(i))
          write (u, '(i0,",",es23.15e3,",",i0,2(",",es23.15e3))') s%step, s%lam, s%iteration, s%norm, s%ref
        end associate
      end do
      close (u)
      call output_plot(m)
    end if

    if (m%vtk) then
      path = output_path(m, '.pvd')
      open (newunit=u, file=path, status='replace', action='write', iostat=ios)
      if (ios /= 0) call fatal(path // ': cannot write')
      write (u, '(a)') '<?xml version="1.0"?>'
      write (u, '(a)') '<VTKFile type="Collection" version="1.0" byte_order="LittleEndian">'
      write (u, '(a)') '<Collection>'
      do i = 1, n_files
        write (u, '(a,es23.15e3,a)') '<DataSet timestep="', file_lam(i), '" group="" part="0" file="' &
          // trim(file_name(i)) // '"/>'
      end do
      write (u, '(a)') '</Collection>'
      write (u, '(a)') '</VTKFile>'
      close (u)
    end if
  end subroutine output_finish

  !> Writes <name>.gp next to the CSV files and, when gnuplot is installed,
  !> runs it in the output directory to draw <name>.png: top, the sums of
  !> f_N and |T| against the load factor (with contact) or the motion of the
  !> monitored node (without); bottom, the residual norm of every Newton
  !> iteration of the run (log scale). Without gnuplot the first call says
  !> so and no call runs anything; a failing gnuplot is reported, never
  !> fatal (its messages go to <name>_gnuplot.log).
  subroutine output_plot(m)
    type(scene_model), intent(in) :: m
    character(len=:), allocatable :: path, name, dir
    integer :: u, ios, stat, cstat
    character(len=256) :: cmsg

    name = trim(m%name)
    dir = trim(m%out_dir)
    path = output_path(m, '.gp')
    open (newunit=u, file=path, status='replace', action='write', iostat=ios)
    if (ios /= 0) call fatal(path // ': cannot write')
    write (u, '(a)') '# gnuplot script written by b2b_demo for scene ' // name // ': run it in this directory'
    write (u, '(a)') '# (gnuplot ' // name // '.gp) to draw ' // name // '.png from the CSV files.'
    write (u, '(a)') 'if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {'
    write (u, '(a)') '  set terminal pngcairo size 900,900 noenhanced'
    write (u, '(a)') '} else {'
    write (u, '(a)') '  set terminal png size 900,900 noenhanced'
    write (u, '(a)') '}'
    write (u, '(a)') 'set output "' // name // '.png"'
    write (u, '(a)') 'set datafile separator ","'
    write (u, '(a)') 'set key autotitle columnhead'
    write (u, '(a)') 'set grid'
    write (u, '(a)') 'set key below'
    write (u, '(a)') 'set multiplot layout 2,1 title "' // name // ': ' // quote_free(m%title) // '"'
    write (u, '(a)') 'set xlabel "load factor"'
    if (m%contact%enabled) then
      write (u, '(a)') 'set ylabel "force"'
      write (u, '(a)') 'set title "contact force histories (sums over the active contacts)"'
      write (u, '(a)') 'plot "' // name // '_history.csv" using 2:15 with linespoints title "f_N", \'
      write (u, '(a)') '     "' // name // '_history.csv" using 2:16 with linespoints title "|T| (friction)"'
    else
      write (u, '(a)') 'set ylabel "displacement"'
      write (u, '(a)') 'set title "motion of the monitored node"'
      write (u, '(a)') 'plot "' // name // '_history.csv" using 2:7 with linespoints title "ux", \'
      write (u, '(a)') '     "' // name // '_history.csv" using 2:8 with linespoints title "uy", \'
      write (u, '(a)') '     "' // name // '_history.csv" using 2:9 with linespoints title "uz"'
    end if
    write (u, '(a)') 'set title "convergence: residual norm of every Newton iteration"'
    write (u, '(a)') 'set xlabel "Newton iteration (all steps in order)"'
    write (u, '(a)') 'set ylabel "|r|"'
    write (u, '(a)') 'set logscale y'
    write (u, '(a)') 'set format y "%.0e"'
    write (u, '(a)') 'plot "' // name // '_convergence.csv" using 0:($4 > 0 ? $4 : 1/0) with linespoints pt 7 ps 0.4 ' &
                     // 'title "|r|", \'
    write (u, '(a,es10.3,a)') '     "' // name // '_convergence.csv" using 0:($5 * ', m%tol, ') with lines title ' &
      // '"tol x scale (converged below it or at the round-off floor)"'
    write (u, '(a)') 'unset multiplot'
    close (u)

    if (gnuplot_state == 0) then
      stat = 1
      cstat = 0
      call execute_command_line('command -v gnuplot > /dev/null 2>&1', exitstat=stat, cmdstat=cstat)
      gnuplot_state = merge(1, -1, cstat == 0 .and. stat == 0)
      if (gnuplot_state < 0) write (*, '(a)') 'b2b_demo: gnuplot not found (command -v gnuplot): no PNG plots, ' &
        // 'only the gnuplot scripts <scene>.gp next to the CSV files'
    end if
    if (gnuplot_state < 0) return
    if (index(dir, '''') > 0) then
      write (*, '(a)') 'b2b_demo: output directory name contains a quote; ' // name // '.png not drawn (run gnuplot ' &
        // name // '.gp there)'
      return
    end if
    stat = 1
    cstat = 0
    cmsg = ''
    call execute_command_line('cd ''' // dir // ''' && gnuplot ''' // name // '.gp'' > ''' // name &
                              // '_gnuplot.log'' 2>&1', exitstat=stat, cmdstat=cstat, cmdmsg=cmsg)
    if (cstat /= 0 .or. stat /= 0) then
      write (*, '(a)') 'b2b_demo: gnuplot failed on ' // path // ' (see ' // output_path(m, '_gnuplot.log') &
        // '); no plot, the run is not affected'
    else
      write (*, '(a)') trim(m%name) // ': plot ' // output_path(m, '.png')
    end if
  end subroutine output_plot

  !> The text with its double quotes replaced (for a gnuplot string).
  pure function quote_free(text) result(t)
    character(len=*), intent(in) :: text
    character(len=len_trim(text)) :: t
    integer :: i
    t = text(1:len_trim(text))
    do i = 1, len(t)
      if (t(i:i) == '"') t(i:i) = ''''
    end do
  end function quote_free

end module demo_output
