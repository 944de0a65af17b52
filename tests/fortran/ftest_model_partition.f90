!> Distributed models through module b2b, against the C functions called
!> directly. Global beam 1 (Hermite, nodes 1..11 along x, 10 segments) is cut
!> between segments 5 and 6: rank 1 owns segments 1..5 and holds 6 (ghost) and
!> 7 (padding), rank 2 owns 6..10 and holds 5 (ghost) and 4 (padding); global
!> beam 2 (linear, nodes 12..16 along y, pressed onto beam 1) is rank 1's and
!> a ghost on rank 2. Beam 2 slides along x from segment 5 into segment 6 with
!> friction, so that rank 1's contact migrates to rank 2. Every rank model is
!> built twice, through the module (1-based) and through C (0-based), and
!> every new procedure's result is compared with the C function's:
!> get_contact_global (+1), migration_count, migration_info (+1, bytes),
!> migration_pack (the same bytes), migration_unpack (changed, the end of a
!> round). The migrated contact's friction force is the single model's bit
!> for bit. Error paths with ierr and errmsg, in Fortran numbering.
program ftest_model_partition
  use, intrinsic :: iso_c_binding, only: c_double, c_int, c_int64_t, c_int8_t, c_ptr, &
                                         c_null_ptr, c_null_char, c_loc
  use b2b
  use ftest_check
  use ftest_capi
  implicit none

  integer, parameter :: nn = 16
  real(c_double), parameter :: r = 0.1_c_double
  type(b2b_params) :: p
  type(c_ptr) :: cp
  type(b2b_model) :: fm(2), single
  type(c_ptr) :: cm(2)
  real(c_double), target :: x(3, nn)
  real(c_double) :: info_f(32), info_s(32)
  real(c_double), target :: info_c(32)
  integer(c_int64_t) :: gpair(4), target_f(4), nbytes
  integer(c_int64_t), target :: gpair_c(4), target_c(4), size_c
  integer(c_int8_t), allocatable, target :: buf_f(:), buf_c(:)
  integer(c_int), target :: ch_c
  integer(c_int) :: n_c
  integer :: step, ierr, n, rk, k, n_s
  logical :: changed
  character(len=B2B_ERRMSG_LEN) :: msg
  real(c_double), parameter :: xb(3) = [2.3_c_double, 2.4_c_double, 2.6_c_double]

  call b2b_params_create(p)
  call b2b_params_set_real(p, 'penalty', 1000.0_c_double)
  call b2b_params_set_real(p, 'friction', 0.3_c_double)
  call b2b_params_set_real(p, 'tangential_penalty', 2000.0_c_double)
  call b2b_params_finalize(p)
  cp = c_null_ptr
  call check(c_params_create(cp, c_null_ptr, 0_c_int) == B2B_OK, 'C params create')
  call check(c_params_set_real(cp, 'penalty' // c_null_char, 1000.0_c_double, c_null_ptr, &
                               0_c_int) == B2B_OK, 'C penalty')
  call check(c_params_set_real(cp, 'friction' // c_null_char, 0.3_c_double, c_null_ptr, &
                               0_c_int) == B2B_OK, 'C friction')
  call check(c_params_set_real(cp, 'tangential_penalty' // c_null_char, 2000.0_c_double, &
                               c_null_ptr, 0_c_int) == B2B_OK, 'C tangential penalty')
  call check(c_params_finalize(cp, c_null_ptr, 0_c_int) == B2B_OK, 'C params finalize')

  do rk = 1, 2
    call build_f(fm(rk), rk)
    cm(rk) = build_c(rk)
  end do
  ! the single model: both beams whole
  call b2b_model_create(single)
  call b2b_model_add_beam(single, [(k, k = 1, 11)], .false., r, B2B_CURVE_HERMITE_NODAL, 0, n)
  call b2b_model_add_beam(single, [(k, k = 12, 16)], .false., r, B2B_CURVE_LINEAR, 1, n)
  call b2b_model_set_group_pair(single, 0, 1, p)
  call b2b_model_finalize(single, nn)

  ! errors before an update, in Fortran numbering
  n = -7
  call b2b_model_migration_count(fm(1), n, ierr, msg)
  call check(ierr == B2B_ERR_STATE .and. n == -7, 'migration_count before an update: STATE')
  call b2b_model_set_ghost_segments(fm(1), 1, 1, 1, ierr, msg)
  call check(ierr == B2B_ERR_STATE .and. contains_text(msg, 'finalized'), &
             'set_ghost_segments after finalize: ' // trim(msg))

  do step = 1, 3
    call place(xb(step))
    call b2b_model_update(single, x)
    do rk = 1, 2
      call b2b_model_update(fm(rk), x)
      call check(c_model_update(cm(rk), c_loc(x), 3_c_int, int(nn, c_int), 1_c_int, c_null_ptr, &
                                0_c_int) == B2B_OK, 'C update')
    end do
    ! migration: count, info, pack through both, unpack at rank 2 through both
    call b2b_model_migration_count(fm(1), n)
    n_c = -1
    call check(c_model_migration_count(cm(1), n_c, c_null_ptr, 0_c_int) == B2B_OK, 'C count')
    call check(n == n_c, 'migration_count = C')
    call check(n == merge(1, 0, step == 3), 'step ' // int_str(step) // ': ' // int_str(n) // &
               ' migrating')
    call b2b_model_migration_count(fm(2), n)
    call check(n == 0, 'rank 2 sends nothing')
    if (step == 3) then
      call b2b_model_migration_info(fm(1), 1, target_f, nbytes)
      call check(c_model_migration_info(cm(1), 0_c_int, c_loc(target_c), c_loc(size_c), &
                                        c_null_ptr, 0_c_int) == B2B_OK, 'C info')
      call check(all(target_f == target_c + 1) .and. nbytes == size_c, 'migration_info = C + 1')
      call check(target_f(1) == 1 .and. target_f(2) == 6 .and. target_f(3) == 2, &
                 'target: global beam 1 segment 6, beam 2')
      allocate(buf_f(nbytes), buf_c(size_c))
      call b2b_model_migration_pack(fm(1), 1, buf_f)
      call check(c_model_migration_pack(cm(1), 0_c_int, c_loc(buf_c), size_c, c_null_ptr, &
                                        0_c_int) == B2B_OK, 'C pack')
      call check(all(buf_f == buf_c), 'migration_pack: the bytes of C')
      changed = .false.
      call b2b_model_migration_unpack(fm(2), buf_f, changed)
      ch_c = -1
      call check(c_model_migration_unpack(cm(2), c_loc(buf_c), size_c, ch_c, c_null_ptr, &
                                          0_c_int) == B2B_OK, 'C unpack')
      call check(changed .and. ch_c == 1, 'unpack: changed, as C')
      call b2b_model_migration_unpack(fm(2), buf_f, changed)
      call check(.not. changed, 'a second unpack changes nothing')
      ! the end of the round: it was unpacked since the last update
      call b2b_model_migration_unpack(fm(2), changed=changed)
      call check(c_model_migration_unpack(cm(2), c_null_ptr, 0_c_int64_t, ch_c, c_null_ptr, &
                                          0_c_int) == B2B_OK, 'C end of round')
      call check(.not. changed .and. ch_c == 0, 'end of round: nothing dropped, as C')
      ! errors, outputs untouched
      changed = .true.
      call b2b_model_migration_unpack(fm(2), buf_f(1:nbytes - 1), changed, ierr, msg)
      call check(ierr == B2B_ERR_RANGE .and. changed .and. contains_text(msg, 'size'), &
                 'truncated: ' // trim(msg))
      call b2b_model_migration_unpack(fm(1), buf_f, changed, ierr, msg)
      call check(ierr == B2B_ERR_RANGE .and. contains_text(msg, 'evaluates'), &
                 'not its pair: ' // trim(msg))
      target_f = -7
      call b2b_model_migration_info(fm(1), 2, target_f, ierr=ierr, errmsg=msg)
      call check(ierr == B2B_ERR_RANGE .and. contains_text(msg, 'migrating contact 2 does') &
                 .and. all(target_f == -7), 'info k = 2: ' // trim(msg))
      call b2b_model_migration_pack(fm(1), 1, buf_f(1:4), ierr, msg)
      call check(ierr == B2B_ERR_SIZE, 'pack into 4 bytes: ' // trim(msg))
      ! (a main program's allocatables are not freed at its end: LeakSanitizer
      ! reports them)
      deallocate(buf_f, buf_c)
      ! rank 2 again, with the contact
      call b2b_model_update(fm(2), x)
      call check(c_model_update(cm(2), c_loc(x), 3_c_int, int(nn, c_int), 1_c_int, c_null_ptr, &
                                0_c_int) == B2B_OK, 'C update')
    end if
    ! contacts in global ids, both ways; the friction force is the single model's
    call b2b_model_contact_count(single, n_s)
    call check(n_s == 1, 'the single model has one contact')
    call b2b_model_get_contact(single, 1, info=info_s)
    rk = merge(2, 1, step == 3)
    call b2b_model_contact_count(fm(rk), n)
    call check(n == 1, 'step ' // int_str(step) // ': rank ' // int_str(rk) // ' has the contact')
    call b2b_model_contact_count(fm(3 - rk), n)
    call check(n == 0, 'the other rank has none')
    call b2b_model_get_contact_global(fm(rk), 1, gpair)
    call check(c_model_get_contact_global(cm(rk), 0_c_int, c_loc(gpair_c), c_null_ptr, 0_c_int) &
               == B2B_OK, 'C get_contact_global')
    call check(all(gpair == gpair_c + 1), 'get_contact_global = C + 1')
    call check(gpair(1) == 1 .and. gpair(2) == merge(6, 5, step == 3) .and. gpair(3) == 2, &
               'the contact is on global beam 1, segment ' // int_str(int(gpair(2))))
    call b2b_model_get_contact(fm(rk), 1, info=info_f)
    call check(c_model_get_contact(cm(rk), 0_c_int, c_null_ptr, c_null_ptr, c_loc(info_c), &
                                   c_null_ptr, c_null_ptr, 24_c_int, c_null_ptr, 0_c_int) &
               == B2B_OK, 'C get_contact')
    call check(all(same_bits_v(info_f, info_c)), 'module = C (info)')
    call check(all(same_bits_v(info_f, info_s)), 'step ' // int_str(step) // &
               ': the friction force and the rest of info are the single model''s')
    if (step == 3) call check(nint(info_f(B2B_IX_INFO_FRICTION_STATE)) == B2B_FRICTION_SLIP, &
                              'the migrated contact slips (its history came along)')
    call b2b_model_commit(single)
    do rk = 1, 2
      call b2b_model_commit(fm(rk))
      call check(c_model_commit(cm(rk), c_null_ptr, 0_c_int) == B2B_OK, 'C commit')
    end do
  end do
  call b2b_model_get_contact_global(fm(2), 2, gpair, ierr, msg)
  call check(ierr == B2B_ERR_RANGE .and. contains_text(msg, 'contact 2 does'), &
             'get_contact_global k = 2: ' // trim(msg))

  do rk = 1, 2
    call b2b_model_destroy(fm(rk))
    call check(c_model_destroy(cm(rk)) == B2B_OK, 'C destroy')
  end do
  call b2b_model_destroy(single)
  call b2b_params_destroy(p)
  call check(c_params_destroy(cp) == B2B_OK, 'C params destroy')
  call check_summary('ftest_model_partition')

contains

  elemental logical function same_bits_v(a, b)
    real(c_double), intent(in) :: a, b
    same_bits_v = transfer(a, 0_c_int64_t) == transfer(b, 0_c_int64_t)
  end function

  subroutine place(xpos)
    real(c_double), intent(in) :: xpos
    integer :: j
    do j = 1, 11
      x(:, j) = [0.5_c_double * (j - 1), 0.0_c_double, 0.0_c_double]
    end do
    do j = 1, 5
      x(:, 11 + j) = [xpos, 0.5_c_double * (j - 3) + 0.13_c_double, 0.19_c_double]
    end do
  end subroutine

  ! Rank rk through the module (1-based).
  subroutine build_f(m, rk)
    type(b2b_model), intent(inout) :: m
    integer, intent(in) :: rk
    integer :: beam, j
    call b2b_model_create(m)
    if (rk == 1) then
      call b2b_model_add_beam(m, [(j, j = 1, 8)], .false., r, B2B_CURVE_HERMITE_NODAL, 0, beam)
      call b2b_model_set_beam_global(m, beam, 1_c_int64_t, 1, .false., .true.)
      call b2b_model_set_ghost_segments(m, beam, 6, 2)
    else
      call b2b_model_add_beam(m, [(j, j = 4, 11)], .false., r, B2B_CURVE_HERMITE_NODAL, 0, beam)
      call b2b_model_set_beam_global(m, beam, 1_c_int64_t, 4, .true., .false.)
      call b2b_model_set_ghost_segments(m, beam, 1, 2)
    end if
    call b2b_model_add_beam(m, [(j, j = 12, 16)], .false., r, B2B_CURVE_LINEAR, 1, beam)
    call b2b_model_set_beam_global(m, beam, 2_c_int64_t, 1, .false., .false.)
    if (rk == 2) call b2b_model_set_ghost_segments(m, beam, 1, 4)
    call b2b_model_set_group_pair(m, 0, 1, p)
    call b2b_model_finalize(m, nn)
  end subroutine

  ! The same through C (0-based).
  function build_c(rk) result(m)
    integer, intent(in) :: rk
    type(c_ptr) :: m
    integer(c_int), target :: nodes(8)
    integer(c_int) :: beam
    integer :: j
    m = c_null_ptr
    call check(c_model_create(m, c_null_ptr, 0_c_int) == B2B_OK, 'C create')
    if (rk == 1) then
      nodes = [(int(j - 1, c_int), j = 1, 8)]
    else
      nodes = [(int(j - 1, c_int), j = 4, 11)]
    end if
    call check(c_model_add_beam(m, c_loc(nodes), 8_c_int, 0_c_int, r, &
                                int(B2B_CURVE_HERMITE_NODAL, c_int), 0_c_int, beam, c_null_ptr, &
                                0_c_int) == B2B_OK, 'C add beam 1')
    if (rk == 1) then
      call check(c_model_set_beam_global(m, 0_c_int, 0_c_int64_t, 0_c_int, 0_c_int, 1_c_int, &
                                         c_null_ptr, 0_c_int) == B2B_OK, 'C global 1')
      call check(c_model_set_ghost_segments(m, 0_c_int, 5_c_int, 2_c_int, c_null_ptr, 0_c_int) &
                 == B2B_OK, 'C ghosts 1')
    else
      call check(c_model_set_beam_global(m, 0_c_int, 0_c_int64_t, 3_c_int, 1_c_int, 0_c_int, &
                                         c_null_ptr, 0_c_int) == B2B_OK, 'C global 1')
      call check(c_model_set_ghost_segments(m, 0_c_int, 0_c_int, 2_c_int, c_null_ptr, 0_c_int) &
                 == B2B_OK, 'C ghosts 1')
    end if
    nodes(1:5) = [(int(j - 1, c_int), j = 12, 16)]
    call check(c_model_add_beam(m, c_loc(nodes), 5_c_int, 0_c_int, r, &
                                int(B2B_CURVE_LINEAR, c_int), 1_c_int, beam, c_null_ptr, &
                                0_c_int) == B2B_OK, 'C add beam 2')
    call check(c_model_set_beam_global(m, 1_c_int, 1_c_int64_t, 0_c_int, 0_c_int, 0_c_int, &
                                       c_null_ptr, 0_c_int) == B2B_OK, 'C global 2')
    if (rk == 2) call check(c_model_set_ghost_segments(m, 1_c_int, 0_c_int, 4_c_int, c_null_ptr, &
                                                       0_c_int) == B2B_OK, 'C ghosts 2')
    call check(c_model_set_group_pair(m, 0_c_int, 1_c_int, cp, c_null_ptr, 0_c_int) == B2B_OK, &
               'C group pair')
    call check(c_model_finalize(m, int(nn, c_int), c_null_ptr, 0_c_int) == B2B_OK, 'C finalize')
  end function

end program ftest_model_partition
