!> The contact model through module b2b against direct C calls.
!>
!> The scene (16 host nodes; Fortran node 11 = C node 10 is used by no beam):
!>   beam 1  nodes 1..5,   HERMITE_NODAL, along x in z = 0, bent in y, group 0
!>   beam 2  nodes 6..10,  HERMITE_NODAL_WEIGHTED, along y at x = 0.3, z = -0.15, group 0
!>   beam 3  nodes 12..16, LINEAR, along y at x = -0.7, z = +0.15, group 1
!> radius 0.1: beam 1 presses on beam 2 (group pair (0, 0), penalty 100) and
!> on beam 3 (group pair (0, 1), penalty 100 with friction 0.3, tangential
!> penalty 50). The same scene is built once through module b2b (1-based
!> node numbers, logical flags) and once through the C functions (0-based),
!> then both are updated, committed, moved and compared bit for bit:
!> contact count, nodes (Fortran = C + 1, 0 for a missing slot), pair
!> (1-based), info, residual, tangent (ldk 24, ldk 30 and an array section),
!> the assembled residual, dense, banded and COO tangents (Fortran equation
!> numbers 1-based with 0 = constrained against C's eq_base 0 with -1),
!> stats, save size and bytes, restore. Then the error paths with ierr and
!> errmsg: statuses, messages in Fortran numbering, wrong shapes
!> (B2B_ERR_SIZE) with the outputs untouched.
program ftest_model
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_ptr, c_char, c_loc, c_null_ptr, &
                                         c_null_char, c_associated, c_int8_t, c_int64_t
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  use b2b
  use ftest_check
  use ftest_capi
  implicit none

  integer, parameter :: nn = 16, nb = 3, neq = 3 * nn
  real(c_double), parameter :: radius = 0.1_c_double, dist = 0.15_c_double, &
                               pen = 100.0_c_double, mu = 0.3_c_double, eps_t = 50.0_c_double
  real(c_double), parameter :: sentinel = -7.0_c_double
  integer, parameter :: isentinel = -77
  integer, parameter :: beam_nodes(5, nb) = reshape([1, 2, 3, 4, 5, 6, 7, 8, 9, 10, &
                                                     12, 13, 14, 15, 16], [5, nb])
  integer, parameter :: beam_kind(nb) = [B2B_CURVE_HERMITE_NODAL, &
                                         B2B_CURVE_HERMITE_NODAL_WEIGHTED, B2B_CURVE_LINEAR]
  integer, parameter :: beam_group(nb) = [0, 0, 1]

  type(b2b_params) :: plin, pfric
  type(c_ptr) :: cplin, cpfric
  type(b2b_model) :: fm
  type(c_ptr) :: cm
  integer :: feq(3, nn)
  integer(c_int), target :: ceq(3, nn)

  call make_params()
  call make_equations()
  call build_f(fm)
  cm = build_c()

  call test_step(0, 'step 0')
  call commit_both()
  call test_step(1, 'step 1 (friction history)')
  call test_without_tangent()
  call commit_both()
  call test_step(2, 'step 2')
  call test_save_restore()
  call test_revert()
  call test_errors()
  call test_shapes()

  call b2b_model_destroy(fm)
  call check(c_model_destroy(cm) == B2B_OK .and. .not. c_associated(cm), 'C model destroy')
  call b2b_params_destroy(plin)
  call b2b_params_destroy(pfric)
  call check(c_params_destroy(cplin) == B2B_OK, 'C params destroy')
  call check(c_params_destroy(cpfric) == B2B_OK, 'C params destroy')
  call check_summary('ftest_model')

contains

  ! ------------------------------------------------------------- scene

  !> Host coordinates: beam 1 moved by step * (0.02, 0.005, 0).
  function scene_x(step) result(x)
    integer, intent(in) :: step
    real(c_double) :: x(3, nn)
    integer :: k
    real(c_double) :: s
    x = 0
    do k = 1, 5
      s = -2.0_c_double + (k - 1)
      x(:, beam_nodes(k, 1)) = [s + 0.02_c_double * step, 0.05_c_double * s * s + &
                                0.005_c_double * step, 0.0_c_double]
      x(:, beam_nodes(k, 2)) = [0.3_c_double, -1.8_c_double + (k - 1), -dist]
      x(:, beam_nodes(k, 3)) = [-0.7_c_double, -1.7_c_double + (k - 1), dist]
    end do
    x(:, 11) = 5.0_c_double
  end function

  subroutine make_params()
    integer :: ierr
    character(len=B2B_ERRMSG_LEN) :: msg
    call b2b_params_create(plin, ierr, msg)
    call b2b_params_set_real(plin, 'penalty', pen, ierr, msg)
    call b2b_params_finalize(plin, ierr, msg)
    call check(ierr == B2B_OK, 'linear params [' // trim(msg) // ']')
    call b2b_params_create(pfric, ierr, msg)
    call b2b_params_set_real(pfric, 'penalty', pen, ierr, msg)
    call b2b_params_set_real(pfric, 'friction', mu, ierr, msg)
    call b2b_params_set_real(pfric, 'tangential_penalty', eps_t, ierr, msg)
    call b2b_params_finalize(pfric, ierr, msg)
    call check(ierr == B2B_OK, 'friction params [' // trim(msg) // ']')
    cplin = c_null_ptr
    cpfric = c_null_ptr
    call check(c_params_create(cplin, c_null_ptr, 0_c_int) == B2B_OK, 'C params create')
    call check(c_params_set_real(cplin, 'penalty' // c_null_char, pen, c_null_ptr, 0_c_int) &
               == B2B_OK, 'C penalty')
    call check(c_params_finalize(cplin, c_null_ptr, 0_c_int) == B2B_OK, 'C finalize')
    call check(c_params_create(cpfric, c_null_ptr, 0_c_int) == B2B_OK, 'C params create')
    call check(c_params_set_real(cpfric, 'penalty' // c_null_char, pen, c_null_ptr, 0_c_int) &
               == B2B_OK, 'C penalty')
    call check(c_params_set_real(cpfric, 'friction' // c_null_char, mu, c_null_ptr, 0_c_int) &
               == B2B_OK, 'C friction')
    call check(c_params_set_real(cpfric, 'tangential_penalty' // c_null_char, eps_t, &
                                 c_null_ptr, 0_c_int) == B2B_OK, 'C tangential_penalty')
    call check(c_params_finalize(cpfric, c_null_ptr, 0_c_int) == B2B_OK, 'C finalize')
  end subroutine

  !> Equation numbers: 1-based in Fortran, a few dofs constrained (0); the
  !> C copy 0-based with -1 for the constrained ones.
  subroutine make_equations()
    integer :: k, i, e
    e = 0
    do k = 1, nn
      do i = 1, 3
        ! node 1 fixed in z, node 7 fixed in x and y (both in contacts)
        if ((k == 1 .and. i == 3) .or. (k == 7 .and. i <= 2)) then
          feq(i, k) = 0
        else
          e = e + 1
          feq(i, k) = e
        end if
      end do
    end do
    ceq = int(feq - 1, c_int)
  end subroutine

  subroutine build_f(m)
    type(b2b_model), intent(inout) :: m
    integer :: b, beam, ierr
    character(len=B2B_ERRMSG_LEN) :: msg
    call b2b_model_create(m, ierr, msg)
    call check(ierr == B2B_OK, 'F create [' // trim(msg) // ']')
    do b = 1, nb
      beam = isentinel
      call b2b_model_add_beam(m, beam_nodes(:, b), .false., radius, beam_kind(b), &
                              beam_group(b), beam, ierr, msg)
      call check(ierr == B2B_OK .and. beam == b, 'F add_beam ' // int_str(b) // ' -> ' // &
                 int_str(beam) // ' [' // trim(msg) // ']')
    end do
    call b2b_model_set_group_pair(m, 0, 0, plin, ierr, msg)
    call check(ierr == B2B_OK, 'F pair (0, 0) [' // trim(msg) // ']')
    call b2b_model_set_group_pair(m, 1, 0, pfric, ierr, msg)
    call check(ierr == B2B_OK, 'F pair (1, 0) [' // trim(msg) // ']')
    call b2b_model_finalize(m, nn, ierr, msg)
    call check(ierr == B2B_OK, 'F finalize [' // trim(msg) // ']')
  end subroutine

  function build_c() result(m)
    type(c_ptr) :: m
    integer(c_int), target :: nodes(5)
    integer(c_int) :: beam
    integer :: b
    m = c_null_ptr
    call check(c_model_create(m, c_null_ptr, 0_c_int) == B2B_OK, 'C create')
    do b = 1, nb
      nodes = int(beam_nodes(:, b) - 1, c_int)
      beam = -5
      call check(c_model_add_beam(m, c_loc(nodes), 5_c_int, 0_c_int, radius, &
                                  int(beam_kind(b), c_int), int(beam_group(b), c_int), beam, &
                                  c_null_ptr, 0_c_int) == B2B_OK .and. beam == b - 1, &
                 'C add_beam ' // int_str(b))
    end do
    call check(c_model_set_group_pair(m, 0_c_int, 0_c_int, cplin, c_null_ptr, 0_c_int) &
               == B2B_OK, 'C pair (0, 0)')
    call check(c_model_set_group_pair(m, 1_c_int, 0_c_int, cpfric, c_null_ptr, 0_c_int) &
               == B2B_OK, 'C pair (1, 0)')
    call check(c_model_finalize(m, int(nn, c_int), c_null_ptr, 0_c_int) == B2B_OK, 'C finalize')
  end function

  subroutine update_both(step, want)
    integer, intent(in) :: step
    logical, intent(in) :: want
    real(c_double), target :: x(3, nn)
    integer :: ierr
    character(len=B2B_ERRMSG_LEN) :: msg
    x = scene_x(step)
    call b2b_model_update(fm, x, want, ierr, msg)
    call check(ierr == B2B_OK, 'F update ' // int_str(step) // ' [' // trim(msg) // ']')
    call check(c_model_update(cm, c_loc(x), 3_c_int, int(nn, c_int), merge(1_c_int, 0_c_int, &
                              want), c_null_ptr, 0_c_int) == B2B_OK, 'C update ' // int_str(step))
  end subroutine

  subroutine commit_both()
    integer :: ierr
    call b2b_model_commit(fm, ierr)
    call check(ierr == B2B_OK, 'F commit')
    call check(c_model_commit(cm, c_null_ptr, 0_c_int) == B2B_OK, 'C commit')
  end subroutine

  ! ------------------------------------------------------------- parity

  subroutine test_step(step, label)
    integer, intent(in) :: step
    character(len=*), intent(in) :: label
    call update_both(step, .true.)
    call compare_models(fm, cm, label, .true.)
  end subroutine

  !> Everything a model reports, module b2b against C, bit for bit.
  subroutine compare_models(f, c, label, tangents, all_counts)
    type(b2b_model), intent(in) :: f
    type(c_ptr), intent(in) :: c
    character(len=*), intent(in) :: label
    logical, intent(in) :: tangents
    logical, intent(in), optional :: all_counts
    integer :: n, k, ierr, ctr(B2B_MODEL_COUNTS_LEN)
    logical :: some_missing, search_counts
    integer(c_int) :: cn
    integer(c_int), target :: cnodes(8), cpair(4), cctr(B2B_MODEL_COUNTS_LEN)
    integer :: fnodes(8), fpair(4)
    real(c_double), target :: cinfo(32), cres(24), cK(24, 24), ctot(B2B_MODEL_TOTALS_LEN)
    real(c_double) :: finfo(32), fres(24), fK(24, 24), fK30(30, 24), big(30, 24)
    real(c_double) :: tot(B2B_MODEL_TOTALS_LEN)
    character(len=B2B_ERRMSG_LEN) :: msg

    n = isentinel
    call b2b_model_contact_count(f, n, ierr, msg)
    call check(ierr == B2B_OK, label // ': F contact_count [' // trim(msg) // ']')
    cn = -5
    call check(c_model_contact_count(c, cn, c_null_ptr, 0_c_int) == B2B_OK, label // &
               ': C contact_count')
    call check(n == cn, label // ': contact count ' // int_str(n) // ' == C ' // int_str(int(cn)))
    call check(n == 2, label // ': 2 contacts')
    some_missing = .false.
    search_counts = .true.
    if (present(all_counts)) search_counts = all_counts
    do k = 1, min(n, int(cn))
      fnodes = isentinel
      fpair = isentinel
      finfo = sentinel
      fres = sentinel
      fK = sentinel
      call b2b_model_get_contact(f, k, nodes=fnodes, pair=fpair, info=finfo, residual=fres, &
                                 ierr=ierr, errmsg=msg)
      call check(ierr == B2B_OK, label // ': F get_contact [' // trim(msg) // ']')
      call check(c_model_get_contact(c, int(k - 1, c_int), c_loc(cnodes), c_loc(cpair), &
                                     c_loc(cinfo), c_loc(cres), c_null_ptr, 24_c_int, &
                                     c_null_ptr, 0_c_int) == B2B_OK, label // ': C get_contact')
      call check(all(fnodes == cnodes + 1), label // ': nodes == C + 1 (contact ' // &
                 int_str(k) // ')')
      call check(all((fnodes == 0) .eqv. (cnodes == -1)), label // ': missing slots are 0')
      some_missing = some_missing .or. any(cnodes == -1)
      call check(all(fpair == cpair + 1), label // ': pair == C + 1')
      call check(same_bits(finfo, cinfo), label // ': info bits')
      call check(same_bits(fres, cres), label // ': residual bits')
      if (.not. tangents) cycle
      ! tangent (24, 24)
      call b2b_model_get_contact(f, k, tangent=fK, ierr=ierr, errmsg=msg)
      call check(ierr == B2B_OK, label // ': F tangent [' // trim(msg) // ']')
      call check(c_model_get_contact(c, int(k - 1, c_int), c_null_ptr, c_null_ptr, c_null_ptr, &
                                     c_null_ptr, c_loc(cK), 24_c_int, c_null_ptr, 0_c_int) &
                 == B2B_OK, label // ': C tangent')
      call check(same_bits(reshape(fK, [576]), reshape(cK, [576])), label // ': tangent bits')
      ! ldk 30
      fK30 = sentinel
      call b2b_model_get_contact(f, k, tangent=fK30, ierr=ierr, errmsg=msg)
      call check(ierr == B2B_OK, label // ': F tangent ldk 30 [' // trim(msg) // ']')
      call check(same_bits(reshape(fK30(1:24, :), [576]), reshape(cK, [576])), label // &
                 ': tangent ldk 30 bits')
      call check(all_equal_to(reshape(fK30(25:30, :), [144]), sentinel), label // &
                 ': ldk 30 padding untouched')
      ! an array section (not contiguous)
      big = sentinel
      call b2b_model_get_contact(f, k, tangent=big(4:27, :), ierr=ierr, errmsg=msg)
      call check(ierr == B2B_OK, label // ': F tangent section [' // trim(msg) // ']')
      call check(same_bits(reshape(big(4:27, :), [576]), reshape(cK, [576])), label // &
                 ': tangent section bits')
      call check(all_equal_to(reshape(big(1:3, :), [72]), sentinel) .and. &
                 all_equal_to(reshape(big(28:30, :), [72]), sentinel), label // &
                 ': rows outside the section untouched')
    end do
    call check(some_missing, label // ': the LINEAR beam patch has missing slots')
    ! stats
    ctr = isentinel
    tot = sentinel
    call b2b_model_stats(f, ctr, tot, ierr, msg)
    call check(ierr == B2B_OK, label // ': F stats [' // trim(msg) // ']')
    call check(c_model_stats(c, c_loc(cctr), c_loc(ctot), c_null_ptr, 0_c_int) == B2B_OK, &
               label // ': C stats')
    if (.not. search_counts) then
      ! the search is a cache of each model: builds and candidates may differ
      ctr(B2B_COUNT_SEARCH_BUILDS + 1) = int(cctr(B2B_COUNT_SEARCH_BUILDS + 1))
      ctr(B2B_COUNT_CANDIDATES + 1) = int(cctr(B2B_COUNT_CANDIDATES + 1))
      ctr(B2B_COUNT_FAR + 1) = int(cctr(B2B_COUNT_FAR + 1))
    end if
    call check(all(ctr == cctr), label // ': counts == C')
    call check(same_bits(tot, ctot), label // ': totals bits')
    call check(ctr(B2B_COUNT_ACTIVE + 1) == 2, label // ': counts(B2B_COUNT_ACTIVE + 1) == 2')
    if (tangents) call compare_assembly(f, c, label)
  end subroutine

  subroutine compare_assembly(f, c, label)
    type(b2b_model), intent(in) :: f
    type(c_ptr), intent(in) :: c
    character(len=*), intent(in) :: label
    integer, parameter :: kl = neq - 1, ku = neq - 1, ldab = 2 * kl + ku + 1
    real(c_double) :: ff(neq), fK(neq, neq), fAB(ldab, neq)
    real(c_double), target :: cf(neq), cK(neq, neq), cAB(ldab, neq)
    integer(c_int), allocatable, target :: crows(:), ccols(:), frows(:), fcols(:)
    real(c_double), allocatable, target :: cvals(:), fvals(:)
    integer :: ierr, nnz
    integer(c_int) :: cnnz, neqc
    character(len=B2B_ERRMSG_LEN) :: msg
    neqc = int(maxval(feq), c_int)
    ff = 0
    cf = 0
    call b2b_model_add_residual(f, feq, ff(1:neqc), ierr, msg)
    call check(ierr == B2B_OK, label // ': F add_residual [' // trim(msg) // ']')
    call check(c_model_add_residual(c, c_loc(ceq), 3_c_int, 0_c_int, neqc, c_loc(cf), &
                                    c_null_ptr, 0_c_int) == B2B_OK, label // ': C add_residual')
    call check(same_bits(ff, cf), label // ': assembled residual bits')
    call check(maxval(abs(ff)) > 0, label // ': a nonzero residual')
    fK = 0
    cK = 0
    call b2b_model_add_tangent_dense(f, feq, fK(:, 1:neqc), ierr, msg)
    call check(ierr == B2B_OK, label // ': F dense [' // trim(msg) // ']')
    call check(c_model_add_tangent_dense(c, c_loc(ceq), 3_c_int, 0_c_int, neqc, c_loc(cK), &
                                         int(neq, c_int), c_null_ptr, 0_c_int) == B2B_OK, &
               label // ': C dense')
    call check(same_bits(reshape(fK, [neq * neq]), reshape(cK, [neq * neq])), label // &
               ': dense bits')
    fAB = 0
    cAB = 0
    call b2b_model_add_tangent_banded(f, feq, kl, ku, fAB(:, 1:neqc), ierr, msg)
    call check(ierr == B2B_OK, label // ': F banded [' // trim(msg) // ']')
    call check(c_model_add_tangent_banded(c, c_loc(ceq), 3_c_int, 0_c_int, neqc, &
                                          int(kl, c_int), int(ku, c_int), c_loc(cAB), &
                                          int(ldab, c_int), c_null_ptr, 0_c_int) == B2B_OK, &
               label // ': C banded')
    call check(same_bits(reshape(fAB, [ldab * neq]), reshape(cAB, [ldab * neq])), label // &
               ': banded bits')
    ! COO: size query, then the triplets
    nnz = isentinel
    call b2b_model_tangent_coo(f, feq, int(neqc), nnz, ierr=ierr, errmsg=msg)
    call check(ierr == B2B_OK, label // ': F COO size [' // trim(msg) // ']')
    cnnz = -5
    call check(c_model_tangent_coo(c, c_loc(ceq), 3_c_int, 0_c_int, neqc, cnnz, c_null_ptr, &
                                   c_null_ptr, c_null_ptr, 0_c_int, c_null_ptr, 0_c_int) &
               == B2B_OK, label // ': C COO size')
    call check(nnz == cnnz .and. nnz > 0, label // ': COO size ' // int_str(nnz) // ' == C ' // &
               int_str(int(cnnz)))
    allocate (frows(nnz + 2), fcols(nnz + 2), fvals(nnz + 2), crows(cnnz), ccols(cnnz), &
              cvals(cnnz))
    frows = isentinel
    fcols = isentinel
    fvals = sentinel
    call b2b_model_tangent_coo(f, feq, int(neqc), nnz, frows, fcols, fvals, ierr, msg)
    call check(ierr == B2B_OK, label // ': F COO [' // trim(msg) // ']')
    call check(c_model_tangent_coo(c, c_loc(ceq), 3_c_int, 0_c_int, neqc, cnnz, c_loc(crows), &
                                   c_loc(ccols), c_loc(cvals), cnnz, c_null_ptr, 0_c_int) &
               == B2B_OK, label // ': C COO')
    call check(all(frows(1:nnz) == crows + 1) .and. all(fcols(1:nnz) == ccols + 1), label // &
               ': COO rows, cols == C + 1')
    call check(same_bits(fvals(1:nnz), cvals), label // ': COO values bits')
    call check(all(frows(nnz + 1:) == isentinel) .and. all_equal_to(fvals(nnz + 1:), sentinel), &
               label // ': COO beyond nnz untouched')
    call check(minval(frows(1:nnz)) >= 1 .and. maxval(frows(1:nnz)) <= neqc, label // &
               ': COO rows in 1 .. n_eq')
  end subroutine

  !> A residual-only update: same info and residual; a tangent is B2B_ERR_STATE on both sides.
  subroutine test_without_tangent()
    real(c_double) :: fK(24, 24)
    real(c_double), target :: cK(24, 24)
    integer :: ierr, st
    character(len=B2B_ERRMSG_LEN) :: msg
    call update_both(1, .false.)
    call compare_models(fm, cm, 'residual only', .false.)
    fK = sentinel
    call b2b_model_get_contact(fm, 1, tangent=fK, ierr=ierr, errmsg=msg)
    st = c_model_get_contact(cm, 0_c_int, c_null_ptr, c_null_ptr, c_null_ptr, c_null_ptr, &
                             c_loc(cK), 24_c_int, c_null_ptr, 0_c_int)
    call check(ierr == B2B_ERR_STATE .and. st == B2B_ERR_STATE, 'tangent without want_tangent')
    call check(contains_text(msg, 'want_tangent'), 'message [' // trim(msg) // ']')
    call check(all_equal_to(reshape(fK, [576]), sentinel), 'tangent untouched')
    call update_both(1, .true.)
  end subroutine

  subroutine test_save_restore()
    integer(c_int64_t) :: fsize, csize
    integer(c_int8_t), allocatable :: fbuf(:)
    integer(c_int8_t), allocatable, target :: cbuf(:)
    type(b2b_model) :: fm2
    type(c_ptr) :: cm2
    integer :: ierr, n
    character(len=B2B_ERRMSG_LEN) :: msg
    fsize = -1
    csize = -2
    call b2b_model_save_size(fm, fsize, ierr, msg)
    call check(ierr == B2B_OK, 'F save_size [' // trim(msg) // ']')
    call check(c_model_save_size(cm, csize, c_null_ptr, 0_c_int) == B2B_OK, 'C save_size')
    call check(fsize == csize .and. fsize > 40, 'save size == C')
    allocate (fbuf(fsize), cbuf(csize))
    fbuf = 0
    cbuf = 1
    call b2b_model_save(fm, fbuf, ierr, msg)
    call check(ierr == B2B_OK, 'F save [' // trim(msg) // ']')
    call check(c_model_save(cm, c_loc(cbuf), csize, c_null_ptr, 0_c_int) == B2B_OK, 'C save')
    call check(all(fbuf == cbuf), 'save bytes == C')
    ! restore into fresh models: F bytes through the module, C bytes through C
    call build_f(fm2)
    cm2 = build_c()
    call b2b_model_restore(fm2, fbuf, ierr, msg)
    call check(ierr == B2B_OK, 'F restore [' // trim(msg) // ']')
    call check(c_model_restore(cm2, c_loc(cbuf), csize, c_null_ptr, 0_c_int) == B2B_OK, &
               'C restore')
    ! a restored model has no results
    n = isentinel
    call b2b_model_contact_count(fm2, n, ierr, msg)
    call check(ierr == B2B_ERR_STATE .and. n == isentinel, 'contact_count after restore: STATE')
    ! all four continue alike
    call update_both(3, .true.)
    call update_pair(fm2, cm2, 3)
    call compare_models(fm2, cm2, 'restored, step 3', .true.)
    ! against the originals: the same but for the search counts (each model's cache)
    call compare_models(fm2, cm, 'restored F vs original C, step 3', .true., .false.)
    call compare_models(fm, cm2, 'original F vs restored C, step 3', .true., .false.)
    call compare_models(fm, cm, 'original F vs original C, step 3', .true.)
    ! a truncated buffer through the module
    call b2b_model_restore(fm2, fbuf(1:fsize - 1), ierr, msg)
    call check(ierr == B2B_ERR_RANGE .and. contains_text(msg, 'truncated'), &
               'truncated restore [' // trim(msg) // ']')
    call b2b_model_restore(fm2, fbuf(1:0), ierr, msg)
    call check(ierr == B2B_ERR_RANGE, 'empty restore [' // trim(msg) // ']')
    ! save into too small a buffer: SIZE, untouched
    fbuf = 5
    call b2b_model_save(fm2, fbuf(1:fsize - 1), ierr, msg)
    call check(ierr == B2B_ERR_SIZE .and. all(fbuf == 5), 'save too small [' // trim(msg) // ']')
    call b2b_model_destroy(fm2)
    call check(c_model_destroy(cm2) == B2B_OK, 'C destroy')
  end subroutine

  subroutine update_pair(f, c, step)
    type(b2b_model), intent(inout) :: f
    type(c_ptr), intent(in) :: c
    integer, intent(in) :: step
    real(c_double), target :: x(3, nn)
    integer :: ierr
    x = scene_x(step)
    call b2b_model_update(f, x, ierr=ierr)
    call check(ierr == B2B_OK, 'F update')
    call check(c_model_update(c, c_loc(x), 3_c_int, int(nn, c_int), 1_c_int, c_null_ptr, &
                              0_c_int) == B2B_OK, 'C update')
  end subroutine

  subroutine test_revert()
    integer :: ierr, n
    integer(c_int) :: cn
    character(len=B2B_ERRMSG_LEN) :: msg
    call b2b_model_revert(fm, ierr, msg)
    call check(ierr == B2B_OK, 'F revert')
    call check(c_model_revert(cm, c_null_ptr, 0_c_int) == B2B_OK, 'C revert')
    n = isentinel
    call b2b_model_contact_count(fm, n, ierr, msg)
    call check(ierr == B2B_ERR_STATE .and. n == isentinel, 'F contact_count after revert')
    call check(c_model_contact_count(cm, cn, c_null_ptr, 0_c_int) == B2B_ERR_STATE, &
               'C contact_count after revert')
    call b2b_model_commit(fm, ierr, msg)
    call check(ierr == B2B_ERR_STATE .and. contains_text(msg, 'nothing to commit'), &
               'commit after revert [' // trim(msg) // ']')
    call update_both(3, .true.)
    call compare_models(fm, cm, 'after revert, step 3', .true.)
  end subroutine

  ! ------------------------------------------------------------- errors

  !> ierr, a message with each word, and no stop.
  subroutine expect(ierr, want, msg, words, label)
    integer, intent(in) :: ierr, want
    character(len=*), intent(in) :: msg, label
    character(len=*), intent(in) :: words(:)
    integer :: i
    call check(ierr == want, label // ': ierr ' // int_str(ierr) // ', expected ' // &
               int_str(want) // ' [' // trim(msg) // ']')
    do i = 1, size(words)
      call check(contains_text(msg, trim(words(i))), label // ': message "' // trim(msg) // &
                 '" lacks "' // trim(words(i)) // '"')
    end do
  end subroutine

  subroutine test_errors()
    type(b2b_model) :: m, unused
    type(b2b_params) :: raw
    integer :: ierr, beam, n, nodes(8)
    integer :: eq(3, nn + 1)
    real(c_double) :: x(3, nn), f(neq), AB(8, neq)
    real(c_double), allocatable :: big(:, :)
    character(len=B2B_ERRMSG_LEN) :: msg

    ! set-up errors, in Fortran numbers
    call b2b_model_create(m, ierr, msg)
    call b2b_model_create(m, ierr, msg)
    call expect(ierr, B2B_ERR_STATE, msg, ['b2b_model_destroy'], 'create twice')
    beam = isentinel
    call b2b_model_add_beam(m, [1, 2, 0, 4], .false., radius, B2B_CURVE_LINEAR, 0, beam, ierr, msg)
    call expect(ierr, B2B_ERR_RANGE, msg, [character(len=24) :: 'beam 1', 'node 0 ', &
                'position 3', 'numbered from 1'], 'node 0')
    call check(beam == isentinel, 'node 0: beam untouched')
    call b2b_model_add_beam(m, [1, 2, 3, 2], .false., radius, B2B_CURVE_LINEAR, 0, beam, ierr, msg)
    call expect(ierr, B2B_ERR_RANGE, msg, [character(len=24) :: 'beam 1', 'node 2 ', &
                'positions 2 and 4'], 'node twice')
    call b2b_model_add_beam(m, [1, 2], .true., radius, B2B_CURVE_LINEAR, 0, beam, ierr, msg)
    call expect(ierr, B2B_ERR_SIZE, msg, [character(len=24) :: 'beam 1', 'closed', '3'], &
                'ring of 2')
    call b2b_model_add_beam(m, [integer ::], .false., radius, B2B_CURVE_LINEAR, 0, beam, ierr, msg)
    call expect(ierr, B2B_ERR_SIZE, msg, [character(len=24) :: 'beam 1', '0 nodes'], 'no nodes')
    call b2b_model_add_beam(m, [1, 2], .false., -radius, B2B_CURVE_LINEAR, 0, beam, ierr, msg)
    call expect(ierr, B2B_ERR_RANGE, msg, [character(len=24) :: 'beam 1', 'radius'], 'radius < 0')
    call b2b_model_add_beam(m, [1, 2], .false., ieee_value(radius, ieee_quiet_nan), &
                            B2B_CURVE_LINEAR, 0, beam, ierr, msg)
    call expect(ierr, B2B_ERR_NONFINITE, msg, [character(len=24) :: 'beam 1', 'radius'], &
                'radius NaN')
    call b2b_model_add_beam(m, [1, 2], .false., radius, 9, 0, beam, ierr, msg)
    call expect(ierr, B2B_ERR_UNKNOWN_KIND, msg, [character(len=24) :: 'beam 1', 'kind 9'], &
                'kind 9')
    call b2b_model_add_beam(m, [1, 2], .false., radius, B2B_CURVE_LINEAR, -1, beam, ierr, msg)
    call expect(ierr, B2B_ERR_RANGE, msg, [character(len=24) :: 'beam 1', 'group -1'], &
                'group -1')
    call check(beam == isentinel, 'beam untouched by the failures')
    ! two good beams: beams 1 and 2
    call b2b_model_add_beam(m, beam_nodes(:, 1), .false., radius, beam_kind(1), 0, beam, ierr, msg)
    call check(ierr == B2B_OK .and. beam == 1, 'first good beam is beam 1')
    call b2b_model_add_beam(m, [6, 7, 8, 9, 17], .false., radius, beam_kind(2), 0, beam, ierr, msg)
    call check(ierr == B2B_OK .and. beam == 2, 'second good beam is beam 2')
    call b2b_model_set_self_contact(m, 3, .true., ierr=ierr, errmsg=msg)
    call expect(ierr, B2B_ERR_RANGE, msg, [character(len=24) :: 'beam 3', '1 .. 2'], &
                'self-contact of beam 3')
    call b2b_model_set_self_contact(m, 0, .true., ierr=ierr, errmsg=msg)
    call expect(ierr, B2B_ERR_RANGE, msg, [character(len=24) :: 'beam 0'], &
                'self-contact of beam 0')
    call b2b_model_finalize(m, nn, ierr, msg)
    call expect(ierr, B2B_ERR_STATE, msg, [character(len=24) :: 'pair of groups'], &
                'finalize without a group pair')
    call b2b_params_create(raw, ierr, msg)
    call b2b_model_set_group_pair(m, 0, 0, raw, ierr, msg)
    call expect(ierr, B2B_ERR_STATE, msg, [character(len=24) :: 'finalize'], 'unfinalized params')
    call b2b_params_destroy(raw)
    call b2b_model_set_group_pair(m, 0, -1, plin, ierr, msg)
    call expect(ierr, B2B_ERR_RANGE, msg, [character(len=24) :: '-1'], 'group -1 in a pair')
    call b2b_model_set_group_pair(m, 0, 0, plin, ierr, msg)
    call check(ierr == B2B_OK, 'pair (0, 0)')
    ! node 17 of beam 2 (position 5) is beyond 16 nodes
    call b2b_model_finalize(m, nn, ierr, msg)
    call expect(ierr, B2B_ERR_RANGE, msg, [character(len=24) :: 'beam 2', 'node 17', &
                'position 5', '1 .. 16'], 'node 17 of 16')
    call b2b_model_set_real(m, 'no_such_key', 1.0_c_double, ierr, msg)
    call expect(ierr, B2B_ERR_UNKNOWN_KEY, msg, [character(len=24) :: '"no_such_key"', &
                '"search_margin"'], 'unknown real key')
    call b2b_model_set_int(m, 'threads', -2, ierr, msg)
    call expect(ierr, B2B_ERR_RANGE, msg, [character(len=24) :: '"threads"', '-2'], 'threads -2')
    call b2b_model_set_int(m, 'max_candidates', 0, ierr, msg)
    call expect(ierr, B2B_ERR_RANGE, msg, [character(len=24) :: '"max_candidates"', '>= 1'], &
                'max_candidates 0')
    call b2b_model_set_int(m, 'max_candidates', 1000, ierr, msg)
    call check(ierr == B2B_OK, 'max_candidates 1000 [' // trim(msg) // ']')
    ! update before finalize
    x = scene_x(0)
    call b2b_model_update(m, x, ierr=ierr, errmsg=msg)
    call expect(ierr, B2B_ERR_STATE, msg, [character(len=24) :: 'finalize'], 'update first')
    call b2b_model_finalize(m, 17, ierr, msg)
    call check(ierr == B2B_OK, 'finalize with 17 nodes [' // trim(msg) // ']')
    call b2b_model_finalize(m, 17, ierr, msg)
    call expect(ierr, B2B_ERR_STATE, msg, [character(len=24) :: 'finalized'], 'finalize twice')
    call b2b_model_add_beam(m, [1, 2], .false., radius, B2B_CURVE_LINEAR, 0, beam, ierr, msg)
    call expect(ierr, B2B_ERR_STATE, msg, [character(len=24) :: 'finalized'], 'add after finalize')
    ! wrong shapes of x: 16 < 17 columns; 2 rows
    call b2b_model_update(m, x, ierr=ierr, errmsg=msg)
    call expect(ierr, B2B_ERR_SIZE, msg, [character(len=24) :: '16 columns', '17 nodes'], &
                'x with 16 columns')
    allocate (big(3, 17))
    big = 0
    big(:, 1:nn) = x
    big(:, 17) = [0.3_c_double, 2.2_c_double, -dist]
    call b2b_model_update(m, big(1:2, :), ierr=ierr, errmsg=msg)
    call expect(ierr, B2B_ERR_SIZE, msg, [character(len=24) :: 'ldx is 2'], 'x with 2 rows')
    ! a NaN at node 3 (beam 1), Fortran numbers
    big(2, 3) = ieee_value(radius, ieee_quiet_nan)
    call b2b_model_update(m, big, ierr=ierr, errmsg=msg)
    call expect(ierr, B2B_ERR_NONFINITE, msg, [character(len=24) :: 'node 3 ', ' y '], &
                'NaN at node 3')
    big(2, 3) = 2.0e100_c_double
    call b2b_model_update(m, big, ierr=ierr, errmsg=msg)
    call expect(ierr, B2B_ERR_RANGE, msg, [character(len=24) :: 'node 3 ', 'B2B_COORD_MAX'], &
                'beyond B2B_COORD_MAX at node 3')
    ! the same in node 11, used by no beam: accepted
    big(:, 3) = x(:, 3)
    big(:, 11) = ieee_value(radius, ieee_quiet_nan)
    call b2b_model_update(m, big, ierr=ierr, errmsg=msg)
    call check(ierr == B2B_OK, 'NaN at the unused node 11 [' // trim(msg) // ']')
    ! coincident nodes 2 and 3 of beam 1: named in Fortran numbers
    big(:, 3) = big(:, 2)
    call b2b_model_update(m, big, ierr=ierr, errmsg=msg)
    call expect(ierr, B2B_ERR_COINCIDENT, msg, [character(len=24) :: 'beam 1, segment', &
                'nodes 2 and 3'], 'coincident nodes')
    big(:, 3) = x(:, 3)
    ! contacts and assembly errors on the good update
    call b2b_model_update(m, big, ierr=ierr, errmsg=msg)
    call check(ierr == B2B_OK, 'update [' // trim(msg) // ']')
    n = isentinel
    call b2b_model_contact_count(m, n, ierr, msg)
    call check(ierr == B2B_OK .and. n == 1, 'one contact (beams 1 and 2)')
    nodes = isentinel
    call b2b_model_get_contact(m, 2, nodes=nodes, ierr=ierr, errmsg=msg)
    call expect(ierr, B2B_ERR_RANGE, msg, [character(len=24) :: 'contact 2 ', '1 active'], &
                'contact 2 of 1')
    call b2b_model_get_contact(m, 0, nodes=nodes, ierr=ierr, errmsg=msg)
    call expect(ierr, B2B_ERR_RANGE, msg, [character(len=24) :: 'contact 0 '], 'contact 0')
    call check(all(nodes == isentinel), 'nodes untouched')
    eq = reshape([(n, n = 1, 3 * (nn + 1))], [3, nn + 1])
    eq(2, 4) = 99
    f = sentinel
    call b2b_model_add_residual(m, eq, f, ierr, msg)
    call expect(ierr, B2B_ERR_RANGE, msg, [character(len=24) :: 'node 4,', 'y', '99'], &
                'equation 99 at node 4')
    call check(all_equal_to(f, sentinel), 'f untouched')
    eq(2, 4) = 11
    AB = sentinel
    call b2b_model_add_tangent_banded(m, eq, 2, 1, AB, ierr, msg)
    call expect(ierr, B2B_ERR_RANGE, msg, [character(len=24) :: 'band'], 'band too narrow')
    call check(all_equal_to(reshape(AB, [size(AB)]), sentinel), 'AB untouched')
    call b2b_model_add_tangent_banded(m, eq, 3, 2, AB, ierr, msg)
    call expect(ierr, B2B_ERR_SIZE, msg, [character(len=24) :: 'ldab is 8', '9'], 'ldab 8 < 9')
    call check(all_equal_to(reshape(AB, [size(AB)]), sentinel), 'AB untouched')
    ! eq with fewer columns than the model has nodes: refused by the wrapper
    ! (the C function would read past it)
    f = sentinel
    call b2b_model_add_residual(m, eq(:, 1:2), f, ierr, msg)
    call expect(ierr, B2B_ERR_SIZE, msg, [character(len=24) :: 'eq has shape (3,2)'], &
                'eq of 2 columns')
    call check(all_equal_to(f, sentinel), 'f untouched (short eq)')
    AB = sentinel
    call b2b_model_add_tangent_banded(m, eq(1:2, :), 3, 1, AB, ierr, msg)
    call expect(ierr, B2B_ERR_SIZE, msg, [character(len=24) :: 'ldeq >= 3'], 'eq of 2 rows')
    call check(all_equal_to(reshape(AB, [size(AB)]), sentinel), 'AB untouched (short eq)')
    call b2b_model_destroy(m)
    call check(.not. b2b_handle_check(m), 'destroyed')
    ! destroy of a null handle is a no-op
    call b2b_model_destroy(unused, ierr, msg)
    call check(ierr == B2B_OK, 'destroy a null handle')
    ! calls on a null handle
    call b2b_model_finalize(unused, nn, ierr, msg)
    call expect(ierr, B2B_ERR_NULL, msg, [character(len=24) :: 'model is NULL'], 'null handle')
  end subroutine

  logical function b2b_handle_check(m)
    type(b2b_model), intent(in) :: m
    integer :: ierr, n
    n = 0
    call b2b_model_contact_count(m, n, ierr)
    b2b_handle_check = ierr /= B2B_ERR_NULL
  end function

  !> Wrong shapes: B2B_ERR_SIZE naming the argument, outputs untouched.
  subroutine test_shapes()
    integer :: ierr, nodes7(7), pair5(5), ctr15(15), i
    real(c_double) :: info31(31), res25(25), k23(23, 24), k24(24, 23), tot9(9), info(32)
    character(len=B2B_ERRMSG_LEN) :: msg
    nodes7 = isentinel
    call b2b_model_get_contact(fm, 1, nodes=nodes7, ierr=ierr, errmsg=msg)
    call expect(ierr, B2B_ERR_SIZE, msg, [character(len=24) :: 'nodes', '(7)', '(8)'], 'nodes(7)')
    call check(all(nodes7 == isentinel), 'nodes(7) untouched')
    pair5 = isentinel
    call b2b_model_get_contact(fm, 1, pair=pair5, ierr=ierr, errmsg=msg)
    call expect(ierr, B2B_ERR_SIZE, msg, [character(len=24) :: 'pair', '(5)'], 'pair(5)')
    call check(all(pair5 == isentinel), 'pair(5) untouched')
    info31 = sentinel
    info = sentinel
    call b2b_model_get_contact(fm, 1, info=info, residual=res25, ierr=ierr, errmsg=msg)
    call expect(ierr, B2B_ERR_SIZE, msg, [character(len=24) :: 'residual', '(25)'], 'residual(25)')
    call check(all_equal_to(info, sentinel), 'info untouched when residual is wrong')
    call b2b_model_get_contact(fm, 1, info=info31, ierr=ierr, errmsg=msg)
    call expect(ierr, B2B_ERR_SIZE, msg, [character(len=24) :: 'info', '(31)'], 'info(31)')
    call check(all_equal_to(info31, sentinel), 'info(31) untouched')
    k23 = sentinel
    call b2b_model_get_contact(fm, 1, tangent=k23, ierr=ierr, errmsg=msg)
    call expect(ierr, B2B_ERR_SIZE, msg, [character(len=24) :: 'tangent', '23,24'], &
                'tangent(23, 24)')
    call check(all_equal_to(reshape(k23, [size(k23)]), sentinel), 'tangent(23,24) untouched')
    k24 = sentinel
    call b2b_model_get_contact(fm, 1, tangent=k24, ierr=ierr, errmsg=msg)
    call expect(ierr, B2B_ERR_SIZE, msg, [character(len=24) :: 'tangent', '24,23'], &
                'tangent(24, 23)')
    ctr15 = isentinel
    call b2b_model_stats(fm, counts=ctr15, ierr=ierr, errmsg=msg)
    call expect(ierr, B2B_ERR_SIZE, msg, [character(len=24) :: 'counts', '(15)'], 'counts(15)')
    call check(all(ctr15 == isentinel), 'counts(15) untouched')
    tot9 = sentinel
    call b2b_model_stats(fm, totals=tot9, ierr=ierr, errmsg=msg)
    call expect(ierr, B2B_ERR_SIZE, msg, [character(len=24) :: 'totals', '(9)'], 'totals(9)')
    call check(all_equal_to(tot9, sentinel), 'totals(9) untouched')
    ! COO with rows only
    i = isentinel
    call b2b_model_tangent_coo(fm, feq, neq, i, rows=pair5, ierr=ierr, errmsg=msg)
    call expect(ierr, B2B_ERR_NULL, msg, [character(len=24) :: 'together'], 'COO rows only')
    call check(i == isentinel, 'nnz untouched')
  end subroutine

end program ftest_model
