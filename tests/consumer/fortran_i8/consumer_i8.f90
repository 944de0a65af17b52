!> A legacy Fortran host: compiled with -fdefault-integer-8 -fdefault-real-8,
!> together with the module source b2b installs (share/b2b/fortran/b2b.f90 and
!> b2b_constants.inc), linked against libb2b only. Its variables are plain
!> `integer` and `real`, 8 bytes each, as in such hosts. Checked:
!>  * the flags took effect (else the test would prove nothing);
!>  * the B2B_* constants pass to the module's procedures and compare with
!>    their results (the constants are default integers, like the arguments);
!>  * a pair with a known answer read through B2B_IX_INFO_*: gap -0.05,
!>    f_N 50; a contact model with 1-based nodes and equations, its counts
!>    and totals through B2B_IX_COUNT_* / B2B_IX_TOTAL_*, the assembled
!>    residual equal to the element's;
!>  * integers beyond C's int range are B2B_ERR_RANGE with a message naming
!>    the argument, never truncated: 2**32 + B2B_CURVE_LINEAR would otherwise
!>    read as B2B_CURVE_LINEAR, and 2**31 as a negative count.
!> Exits with a non-zero status on any failure.
program consumer_i8
  use b2b
  implicit none
  real, parameter :: tol = 1.0e-12, penalty = 1000.0, r = 0.1, depth = 0.15, xc = 0.2
  integer :: failures, ierr, status, n, beam, k, segs(3, 2), counts(B2B_MODEL_COUNTS_LEN), &
             eq(3, 6), big, wrap, major, minor, patch, abi, seg_nodes(4), sr, er
  real :: X(3, 8), info(B2B_PAIR_INFO_LEN), residual(B2B_PAIR_NDOF), &
          totals(B2B_MODEL_TOTALS_LEN), xm(3, 6), f(18), patch_x(3, 4), pt(3, 3)
  real, allocatable :: h0(:), h1(:)
  type(b2b_params) :: p
  type(b2b_model) :: m
  character(len=B2B_ERRMSG_LEN) :: msg

  failures = 0
  if (storage_size(0) /= 64 .or. storage_size(0.0) /= 64) then
    write (*, '(a)') 'FAIL: not compiled with -fdefault-integer-8 -fdefault-real-8'
    error stop 2
  end if
  big = huge(0_c_int)
  big = big + 1          ! 2**31: one beyond C's int
  wrap = 2 * big         ! 2**32: truncated to 32 bits it would be 0

  ! Versions through default (8-byte) integers.
  call b2b_version(major, minor, patch, ierr)
  call check(ierr == B2B_OK .and. major == B2B_VERSION_MAJOR .and. minor == B2B_VERSION_MINOR &
             .and. patch == B2B_VERSION_PATCH, 'b2b_version == B2B_VERSION_*')
  call b2b_abi_version(abi, ierr)
  call check(ierr == B2B_OK .and. abi == B2B_SOVERSION, 'b2b_abi_version == B2B_SOVERSION')

  ! A curve with constants as arguments and a default-real patch.
  patch_x = reshape([0, 0, 0, 1, 0, 0, 2, 1, 0, 3, 1, 1], [3, 4]) * 1.0
  call b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, patch_x, &
                        -1.0, x=pt, ierr=ierr, errmsg=msg)
  call check(ierr == B2B_OK .and. all(abs(pt(:, 1) - patch_x(:, 2)) <= tol), &
             'b2b_segment_eval: x(-1) is node x2 [' // trim(msg) // ']')
  call b2b_beam_segment_patch(B2B_CURVE_LINEAR, 5, .false., 2, seg_nodes, sr, er, ierr, msg)
  call check(ierr == B2B_OK .and. all(seg_nodes == [0, 2, 3, 0]) .and. &
             sr == B2B_END_NEIGHBOUR .and. er == B2B_END_NEIGHBOUR, &
             'b2b_beam_segment_patch: segment 2 of 5 nodes is nodes 2, 3 [' // trim(msg) // ']')

  ! The pair of ftest_index: A along x, B along y through x = 0.2, 0.15 below.
  call b2b_params_create(p, ierr, msg)
  call b2b_params_set_real(p, 'penalty', penalty, ierr, msg)
  call b2b_params_set_int(p, 'law', B2B_LAW_LINEAR, ierr, msg)
  call b2b_params_finalize(p, ierr, msg)
  call check(ierr == B2B_OK, 'params [' // trim(msg) // ']')
  n = -1
  call b2b_params_history_size(p, n, ierr, msg)
  allocate (h0(n), h1(n))
  h0 = 0
  segs = B2B_END_NEIGHBOUR
  segs(1, :) = B2B_CURVE_LINEAR
  do k = 1, 4
    X(:, k) = [k - 2.5, 0.0, 0.0]
    X(:, 4 + k) = [xc, k - 2.5, -depth]
  end do
  call b2b_pair_eval(p, segs, X, [r, r], h0, h1, status, info, residual, ierr=ierr, errmsg=msg)
  call check(ierr == B2B_OK .and. status == B2B_CONTACT_ACTIVE, 'pair: active [' // &
             trim(msg) // ']')
  call check(abs(info(B2B_IX_INFO_GAP) - (depth - 2 * r)) <= tol, 'info(B2B_IX_INFO_GAP) == -0.05')
  call check(abs(info(B2B_IX_INFO_NORMAL_FORCE) - 50) <= 1.0e-9, &
             'info(B2B_IX_INFO_NORMAL_FORCE) == 50')
  call check(abs(info(B2B_IX_INFO_NORMAL + 2) - 1) <= tol, 'info(B2B_IX_INFO_NORMAL + 2) == 1')

  ! The same two beams as a contact model (host nodes 1..3 and 4..6, all
  ! dofs free: equation 3 (k - 1) + i for dof i of node k).
  call b2b_model_create(m, ierr, msg)
  call b2b_model_add_beam(m, [1, 2, 3], .false., r, B2B_CURVE_LINEAR, 0, beam, ierr, msg)
  call b2b_model_add_beam(m, [4, 5, 6], .false., r, B2B_CURVE_LINEAR, 0, beam, ierr, msg)
  call check(ierr == B2B_OK .and. beam == 2, 'add_beam: beam 2 [' // trim(msg) // ']')
  call b2b_model_set_group_pair(m, 0, 0, p, ierr, msg)
  call b2b_model_set_int(m, 'threads', 1, ierr, msg)
  call b2b_model_finalize(m, 6, ierr, msg)
  call check(ierr == B2B_OK, 'finalize [' // trim(msg) // ']')
  xm = reshape([-1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, &
                xc, -1.0, -depth, xc, 0.3, -depth, xc, 1.3, -depth], [3, 6])
  call b2b_model_update(m, xm, ierr=ierr, errmsg=msg)
  call check(ierr == B2B_OK, 'update [' // trim(msg) // ']')
  call b2b_model_contact_count(m, n, ierr, msg)
  call check(ierr == B2B_OK .and. n == 1, 'one contact')
  call b2b_model_get_contact(m, 1, info=info, ierr=ierr, errmsg=msg)
  call check(ierr == B2B_OK .and. abs(info(B2B_IX_INFO_GAP) - (depth - 2 * r)) <= tol, &
             'model contact: gap -0.05 [' // trim(msg) // ']')
  call b2b_model_stats(m, counts, totals, ierr, msg)
  call check(ierr == B2B_OK .and. counts(B2B_IX_COUNT_ACTIVE) == 1, &
             'counts(B2B_IX_COUNT_ACTIVE) == 1')
  call check(abs(totals(B2B_IX_TOTAL_NORMAL_FORCE) - 50) <= 1.0e-9, &
             'totals(B2B_IX_TOTAL_NORMAL_FORCE) == 50')
  eq = reshape([(k, k = 1, 18)], [3, 6])
  f = 0
  call b2b_model_add_residual(m, eq, f, ierr, msg)
  ! Equal and opposite: A is pushed up (+z), B down; the z forces sum to 0.
  call check(ierr == B2B_OK .and. abs(sum(f(3:18:3))) <= 1.0e-9 .and. abs(sum(f(3:9:3)) + 50) &
             <= 1.0e-9, 'add_residual: A''s z residual -f_N, B''s +f_N [' // trim(msg) // ']')

  ! Beyond C's int: reported, not truncated.
  call b2b_segment_eval(wrap + B2B_CURVE_LINEAR, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, patch_x, &
                        0.0, x=pt, ierr=ierr, errmsg=msg)
  call expect_range('segment_eval, kind 2**32', 'b2b_segment_eval: kind = 4294967296')
  call b2b_beam_segment_count(B2B_CURVE_LINEAR, big, .false., n, ierr, msg)
  call expect_range('segment_count, n_nodes 2**31', 'b2b_beam_segment_count: n_nodes = 2147483648')
  call b2b_params_set_int(p, 'law', wrap + 1, ierr, msg)
  call expect_range('params_set_int, 2**32 + 1', 'b2b_params_set_int: value = 4294967297')
  segs(2, 2) = -big
  call b2b_pair_eval(p, segs, X, [r, r], h0, h1, status, info, residual, ierr=ierr, errmsg=msg)
  call expect_range('pair_eval, segments(2,2) = -2**31', 'segments(2,2) = -2147483648')
  call b2b_model_get_contact(m, wrap + 1, info=info, ierr=ierr, errmsg=msg)
  call expect_range('get_contact, k 2**32 + 1', 'b2b_model_get_contact: k = 4294967297')
  eq(2, 5) = big
  call b2b_model_add_residual(m, eq, f, ierr, msg)
  call expect_range('add_residual, eq(2,5) = 2**31', 'b2b_model_add_residual: eq(2,5) = 2147483648')
  call check(b2b_strerror(wrap + B2B_ERR_NULL) == b2b_strerror(-1), &
             'b2b_strerror(2**32 + 1) is "unknown status"')

  call b2b_model_destroy(m)
  call b2b_params_destroy(p)
  if (failures /= 0) then
    write (*, '(a, i0, a)') 'b2b Fortran -fdefault-integer-8 consumer: ', failures, ' failure(s)'
    error stop 1
  end if
  write (*, '(a)') 'b2b Fortran -fdefault-integer-8 -fdefault-real-8 consumer: OK'

contains

  subroutine check(ok, what)
    logical, intent(in) :: ok
    character(len=*), intent(in) :: what
    if (.not. ok) then
      write (*, '(a)') 'FAIL: ' // what
      failures = failures + 1
    end if
  end subroutine

  subroutine expect_range(label, needle)
    character(len=*), intent(in) :: label, needle
    call check(ierr == B2B_ERR_RANGE, label // ': B2B_ERR_RANGE [' // trim(msg) // ']')
    call check(index(msg, needle) > 0 .and. index(msg, 'beyond the range of a C int') > 0, &
               label // ': message "' // trim(msg) // '" names "' // needle // '"')
  end subroutine

end program consumer_i8
