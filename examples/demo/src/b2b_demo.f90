!> b2b_demo: solves one scene file.
!>   b2b_demo scene.nml [output_dir]
!> or prints the trade table (demo_trade; scene_dir default examples/demo/scenes):
!>   b2b_demo --trade-table [short|full|line] [scene_dir [output_dir]]
!> Prints one line per load step, writes VTK and CSV files (demo_output) and
!> exits with 0 only if every step converged and the scene's &check (if any)
!> passed; a failed check exits with 1, any error with a message and 2.
program b2b_demo
  use demo_model, only: scene_model
  use demo_scene_reader, only: read_scene
  use demo_solver, only: solve_scene
  use demo_errors, only: fatal
  use demo_output, only: output_remove_stale, output_prepare_dir
  use demo_checks, only: check_finish
  use demo_trade, only: trade_table
  use b2b, only: b2b_version
  implicit none
  character(len=*), parameter :: usage = 'usage: b2b_demo scene.nml [output_dir]' // new_line('a') &
    // '       b2b_demo --trade-table [short|full|line] [scene_dir [output_dir]]'
  type(scene_model) :: m
  character(len=1024) :: file, dir, mode, scene_dir
  integer :: major, minor, patch, i, j
  logical :: passed

  if (command_argument_count() < 1 .or. command_argument_count() > 4) call fatal(usage)
  call get_command_argument(1, file)
  if (file == '--trade-table') then
    ! the trade table (demo_trade): many variants of the sliding scenes in this process
    mode = 'short'
    scene_dir = 'examples/demo/scenes'
    dir = '.'
    if (command_argument_count() >= 2) call get_command_argument(2, mode)
    if (command_argument_count() >= 3) call get_command_argument(3, scene_dir)
    if (command_argument_count() >= 4) call get_command_argument(4, dir)
    call trade_table(trim(mode), trim(scene_dir), trim(dir), passed)
    if (.not. passed) error stop 1
    stop
  end if
  if (command_argument_count() > 2) call fatal(usage)
  call b2b_version(major, minor, patch)
  write (*, '(a,i0,a,i0,a,i0,a)') 'b2b_demo (b2b ', major, '.', minor, '.', patch, '): ' // trim(file)
  dir = ''
  if (command_argument_count() == 2) then
    ! the output directory is made (or found writable) first, and results
    ! of an earlier run go before anything can fail, so that a failed run
    ! never leaves a complete-looking result behind
    call get_command_argument(2, dir)
    i = index(file, '/', back=.true.)
    j = index(file, '.', back=.true.)
    if (j <= i) j = len_trim(file) + 1
    call output_prepare_dir(trim(dir), file(i + 1:j - 1), 'the second argument')
    call output_remove_stale(trim(dir), file(i + 1:j - 1))
  end if
  call read_scene(trim(file), m)
  if (len_trim(dir) > 0) then
    m%out_dir = dir
  else
    call output_prepare_dir(trim(m%out_dir), trim(m%name), '&output dir of ' // trim(file))
  end if
  call solve_scene(m)
  write (*, '(a)') trim(m%name) // ': complete, results in ' // trim(m%out_dir)
  ! the scene's own check (&check): exit code 1 if it fails
  if (.not. check_finish(m)) error stop 1
end program b2b_demo
