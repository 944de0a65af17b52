!> The host-integration procedures of module b2b (issue 19) on the scene of
!> ftest_model (beam 1 on beams 2 and 3, friction against beam 3), with
!> Fortran-numbered groups: beams 1 and 2 in group 1, beam 3 in group 2.
!>   groups       groups 1, 2 give bit for bit the model of groups 0, 1 (labels);
!>                a message prints a group as given
!>   update_xu    = update(x + u) bit for bit, u(6, nn) with NaN rotations;
!>                a NaN displacement: B2B_ERR_NONFINITE naming the Fortran node
!>   *_scaled     scale -1 = -(unscaled) exactly
!>   profile      heights, kl, ku = what the dense tangent implies; ad, au, al
!>                in FEAP's 1-based layout = the dense tangent entry by entry;
!>                au too short: B2B_ERR_SIZE, nothing added
!>   constrained  = K_all(free, constrained) du_c of the all-free dense tangent
program ftest_model_host
  use, intrinsic :: iso_c_binding, only: c_double, c_int
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  use b2b
  use ftest_check
  implicit none

  integer, parameter :: nn = 16, nb = 3
  real(c_double), parameter :: radius = 0.1_c_double, dist = 0.15_c_double
  integer, parameter :: beam_nodes(5, nb) = reshape([1, 2, 3, 4, 5, 6, 7, 8, 9, 10, &
                                                     12, 13, 14, 15, 16], [5, nb])
  integer, parameter :: beam_kind(nb) = [B2B_CURVE_HERMITE_NODAL, &
                                         B2B_CURVE_HERMITE_NODAL_WEIGHTED, B2B_CURVE_LINEAR]
  type(b2b_params) :: plin, pfric
  type(b2b_model) :: m, m0
  integer :: feq(3, nn), all_eq(3, nn), n_free, ierr
  character(len=B2B_ERRMSG_LEN) :: msg
  real(c_double) :: nan

  nan = ieee_value(0.0_c_double, ieee_quiet_nan)
  call make_params()
  call make_equations()
  call build(m, [1, 1, 2])
  call build(m0, [0, 0, 1])
  call step_both(0)
  call b2b_model_commit(m, ierr)
  call b2b_model_commit(m0, ierr)
  call step_both(1)

  call test_groups()
  call test_update_xu()
  call test_scaled()
  call test_profile()
  call test_constrained()

  call b2b_model_destroy(m)
  call b2b_model_destroy(m0)
  call b2b_params_destroy(plin)
  call b2b_params_destroy(pfric)
  call check_summary('ftest_model_host')

contains

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
    call b2b_params_create(plin, ierr, msg)
    call b2b_params_set_real(plin, 'penalty', 100.0_c_double, ierr, msg)
    call b2b_params_finalize(plin, ierr, msg)
    call check(ierr == B2B_OK, 'linear params [' // trim(msg) // ']')
    call b2b_params_create(pfric, ierr, msg)
    call b2b_params_set_real(pfric, 'penalty', 100.0_c_double, ierr, msg)
    call b2b_params_set_real(pfric, 'friction', 0.3_c_double, ierr, msg)
    call b2b_params_set_real(pfric, 'tangential_penalty', 50.0_c_double, ierr, msg)
    call b2b_params_finalize(pfric, ierr, msg)
    call check(ierr == B2B_OK, 'friction params [' // trim(msg) // ']')
  end subroutine

  !> feq: node 1 fixed in z, node 7 in x and y (both in contacts); all_eq:
  !> every dof free, numbered node by node.
  subroutine make_equations()
    integer :: k, i
    n_free = 0
    do k = 1, nn
      do i = 1, 3
        all_eq(i, k) = 3 * (k - 1) + i
        if ((k == 1 .and. i == 3) .or. (k == 7 .and. i <= 2)) then
          feq(i, k) = 0
        else
          n_free = n_free + 1
          feq(i, k) = n_free
        end if
      end do
    end do
  end subroutine

  subroutine build(model, groups)
    type(b2b_model), intent(inout) :: model
    integer, intent(in) :: groups(nb)
    integer :: b, beam
    call b2b_model_create(model, ierr, msg)
    do b = 1, nb
      call b2b_model_add_beam(model, beam_nodes(:, b), .false., radius, beam_kind(b), &
                              groups(b), beam, ierr, msg)
      call check(ierr == B2B_OK, 'add_beam group ' // int_str(groups(b)) // ' [' // &
                 trim(msg) // ']')
    end do
    call b2b_model_set_group_pair(model, groups(1), groups(1), plin, ierr, msg)
    call check(ierr == B2B_OK, 'pair (' // int_str(groups(1)) // ') [' // trim(msg) // ']')
    call b2b_model_set_group_pair(model, groups(3), groups(1), pfric, ierr, msg)
    call check(ierr == B2B_OK, 'pair (' // int_str(groups(3)) // ') [' // trim(msg) // ']')
    call b2b_model_finalize(model, nn, ierr, msg)
    call check(ierr == B2B_OK, 'finalize [' // trim(msg) // ']')
  end subroutine

  subroutine step_both(step)
    integer, intent(in) :: step
    call b2b_model_update(m, scene_x(step), ierr=ierr, errmsg=msg)
    call check(ierr == B2B_OK, 'update [' // trim(msg) // ']')
    call b2b_model_update(m0, scene_x(step), ierr=ierr, errmsg=msg)
    call check(ierr == B2B_OK, 'update groups 0, 1 [' // trim(msg) // ']')
  end subroutine

  !> All contacts' residuals and tangents, flattened.
  function record(model) result(r)
    type(b2b_model), intent(in) :: model
    real(c_double), allocatable :: r(:)
    real(c_double) :: res(24), tan(24, 24)
    integer :: n, k
    call b2b_model_contact_count(model, n, ierr)
    allocate (r(0))
    do k = 1, n
      call b2b_model_get_contact(model, k, residual=res, tangent=tan, ierr=ierr)
      r = [r, res, reshape(tan, [576])]
    end do
  end function

  function dense(model, eq, neq) result(K)
    type(b2b_model), intent(in) :: model
    integer, intent(in) :: eq(:, :), neq
    real(c_double), allocatable :: K(:, :)
    allocate (K(neq, neq))
    K = 0
    call b2b_model_add_tangent_dense(model, eq, K, ierr, msg)
    call check(ierr == B2B_OK, 'dense [' // trim(msg) // ']')
  end function

  subroutine test_groups()
    integer :: n, k, pair(4), n3
    type(b2b_model) :: bad
    real(c_double), allocatable :: r1(:), r0(:)
    call b2b_model_contact_count(m, n, ierr)
    n3 = 0
    do k = 1, n
      call b2b_model_get_contact(m, k, pair=pair, ierr=ierr)
      if (pair(3) == 3 .or. pair(1) == 3) n3 = n3 + 1
    end do
    call check(n >= 2 .and. n3 >= 1, 'groups 1, 2: contacts on both group pairs (' // &
               int_str(n) // ', ' // int_str(n3) // ' with beam 3)')
    r1 = record(m)
    r0 = record(m0)
    call check(size(r1) > 0 .and. same_bits(r1, r0), 'groups 1, 2 = groups 0, 1 bit for bit')
    ! a group prints as given
    call b2b_model_create(bad, ierr)
    call b2b_model_set_group_pair(bad, 2, -1, plin, ierr, msg)
    call check(ierr == B2B_ERR_RANGE .and. contains_text(msg, 'groups 2 and -1'), &
               'group message as given: ' // trim(msg))
    call b2b_model_destroy(bad)
    write (*, '(a, i0, a, i0, a)') 'groups 1 and 2: ', n, ' contacts (', n3, &
      ' with beam 3 of group 2), equal to groups 0 and 1 bit for bit'
  end subroutine

  subroutine test_update_xu()
    type(b2b_model) :: a
    real(c_double) :: xr(3, nn), u(6, nn, 2), x(3, nn)
    real(c_double), allocatable :: ra(:), rb(:)
    integer :: k, i
    x = scene_x(1)
    u = nan
    do k = 1, nn
      do i = 1, 3
        u(i, k, 1) = 0.29_c_double * cos(1.1_c_double * k + i)
        xr(i, k) = x(i, k) - u(i, k, 1)
        x(i, k) = xr(i, k) + u(i, k, 1)
      end do
    end do
    call build(a, [1, 1, 2])
    call b2b_model_update(a, scene_x(0), ierr=ierr)
    call b2b_model_commit(a, ierr)
    call b2b_model_update(a, x, ierr=ierr, errmsg=msg)
    call check(ierr == B2B_OK, 'update(x + u) [' // trim(msg) // ']')
    ra = record(a)
    call b2b_model_revert(a, ierr)
    ! FEAP's u(ndf, numnp, 3): the first of the three, rows 4..6 NaN
    call b2b_model_update_xu(a, xr, u(:, :, 1), ierr=ierr, errmsg=msg)
    call check(ierr == B2B_OK, 'update_xu [' // trim(msg) // ']')
    rb = record(a)
    call check(size(ra) > 0 .and. same_bits(ra, rb), 'update_xu = update(x + u) bit for bit')
    u(2, 3, 1) = nan
    call b2b_model_update_xu(a, xr, u(:, :, 1), ierr=ierr, errmsg=msg)
    call check(ierr == B2B_ERR_NONFINITE .and. &
               contains_text(msg, 'node 3 has a non-finite y displacement'), &
               'NaN displacement: ' // trim(msg))
    call b2b_model_update_xu(a, xr, u(1:2, :, 1), ierr=ierr, errmsg=msg)
    call check(ierr == B2B_ERR_SIZE .and. contains_text(msg, 'ldu'), 'u(2, n): ' // trim(msg))
    call b2b_model_update_xu(a, xr, u(:, 1:nn - 1, 1), ierr=ierr, errmsg=msg)
    call check(ierr == B2B_ERR_SIZE, 'u(6, n - 1): ' // trim(msg))
    call b2b_model_destroy(a)
    write (*, '(a, i0, a)') 'update_xu: ', size(ra) / 600, &
      ' contacts equal to update(x + u) bit for bit; NaN u refused naming node 3'
  end subroutine

  subroutine test_scaled()
    real(c_double) :: f(n_free), fm(n_free), K(n_free, n_free), Km(n_free, n_free)
    real(c_double) :: AB(2 * 2 * n_free + 1, n_free), ABm(2 * 2 * n_free + 1, n_free)
    integer :: kl, ku, heights(n_free)
    f = 0
    fm = 0
    call b2b_model_add_residual(m, feq, f, ierr)
    call b2b_model_add_residual_scaled(m, feq, -1.0_c_double, fm, ierr, msg)
    call check(ierr == B2B_OK .and. all(fm == -f) .and. any(f /= 0), 'residual scaled -1')
    fm = 7
    call b2b_model_add_residual_scaled(m, feq, nan, fm, ierr, msg)
    call check(ierr == B2B_ERR_NONFINITE .and. all(fm == 7), 'NaN scale: ' // trim(msg))
    K = dense(m, feq, n_free)
    Km = 0
    call b2b_model_add_tangent_dense_scaled(m, feq, -1.0_c_double, Km, ierr, msg)
    call check(ierr == B2B_OK .and. all(Km == -K), 'dense scaled -1 [' // trim(msg) // ']')
    call b2b_model_tangent_profile(m, feq, heights, kl, ku, ierr, msg)
    AB = 0
    ABm = 0
    call b2b_model_add_tangent_banded(m, feq, kl, ku, AB(1:2 * kl + ku + 1, :), ierr, msg)
    call b2b_model_add_tangent_banded_scaled(m, feq, kl, ku, -1.0_c_double, &
                                             ABm(1:2 * kl + ku + 1, :), ierr, msg)
    call check(ierr == B2B_OK .and. all(ABm == -AB), 'banded scaled -1 [' // trim(msg) // ']')
    write (*, '(a)') 'scaled: residual, dense, banded with scale -1 = -(unscaled) exactly'
  end subroutine

  subroutine test_profile()
    real(c_double), allocatable :: K(:, :), au(:), al(:), ad(:), au2(:), values(:)
    integer(c_int), allocatable :: rows(:), cols(:)
    integer :: heights(n_free), hd(n_free), hc(n_free), jp(n_free), kl, ku, kld, kud, i, j, &
               nnz, n_zero
    logical :: same
    allocate (K(n_free, n_free))
    K = dense(m, feq, n_free)
    ! the structural pattern (every pair of free dofs of a contact, zero
    ! values too), from the COO entries
    call b2b_model_tangent_coo(m, feq, n_free, nnz, ierr=ierr)
    allocate (rows(nnz), cols(nnz), values(nnz))
    call b2b_model_tangent_coo(m, feq, n_free, nnz, rows, cols, values, ierr=ierr)
    hc = 0
    do i = 1, nnz
      j = max(rows(i), cols(i))
      hc(j) = max(hc(j), abs(rows(i) - cols(i)))
    end do
    hd = 0
    kld = 0
    kud = 0
    do j = 1, n_free
      do i = 1, n_free
        if (K(i, j) /= 0) then
          kld = max(kld, i - j)
          kud = max(kud, j - i)
          hd(max(i, j)) = max(hd(max(i, j)), abs(i - j))
        end if
      end do
    end do
    heights = -1
    call b2b_model_tangent_profile(m, feq, heights, kl, ku, ierr, msg)
    ! the query is the structural pattern: it covers every nonzero of the
    ! dense tangent, and here more (beams 2 and 3 are straight along y, so
    ! some of their entries are exactly 0)
    n_zero = count(heights > hd)
    call check(ierr == B2B_OK .and. all(heights == hc) .and. all(heights >= hd) .and. &
               kl >= kld .and. ku >= kud, 'profile query = COO pattern, covers the dense ' // &
               'nonzeros [' // trim(msg) // ']')
    call check(any(abs(K - transpose(K)) > 0), 'the tangent is not symmetric (friction)')
    jp(1) = 0
    do j = 2, n_free
      jp(j) = jp(j - 1) + heights(j)
    end do
    allocate (ad(n_free), au(jp(n_free)), al(jp(n_free)))
    ad = 0
    au = 0
    al = 0
    call b2b_model_add_tangent_profile(m, feq, 1.0_c_double, jp, ad, au, al, ierr, msg)
    call check(ierr == B2B_OK, 'add_tangent_profile [' // trim(msg) // ']')
    same = .true.
    do j = 1, n_free
      same = same .and. ad(j) == K(j, j)
      do i = j - heights(j), j - 1
        same = same .and. au(jp(j) - j + i + 1) == K(i, j) .and. al(jp(j) - j + i + 1) == K(j, i)
      end do
      do i = 1, j - heights(j) - 1
        same = same .and. K(i, j) == 0 .and. K(j, i) == 0
      end do
    end do
    call check(same, 'profile ad, au, al (FEAP layout) = dense entry by entry')
    ! too short an au: refused, nothing added
    allocate (au2(jp(n_free) - 1))
    au2 = 0
    ad = 0
    call b2b_model_add_tangent_profile(m, feq, 1.0_c_double, jp, ad, au2, ierr=ierr, errmsg=msg)
    call check(ierr == B2B_ERR_SIZE .and. all(ad == 0) .and. all(au2 == 0), &
               'au too short: ' // trim(msg))
    write (*, '(a, i0, a, i0, a, i0, a, i0, a, i0, a)') 'profile: ', n_free, &
      ' equations, jp(n_eq) = ', jp(n_free), ', kl ', kl, ', ku ', ku, '; ', n_zero, &
      ' columns taller than the dense nonzeros (exact zeros); ad/au/al = dense'
  end subroutine

  subroutine test_constrained()
    real(c_double), allocatable :: Kall(:, :)
    real(c_double) :: du(3, nn), f(n_free), want(n_free), big, err
    integer :: ka, ia, kb, ib
    allocate (Kall(3 * nn, 3 * nn))
    Kall = dense(m, all_eq, 3 * nn)
    du = nan
    du(3, 1) = 1.0e-3_c_double
    du(1, 7) = -2.0e-3_c_double
    du(2, 7) = 0.5e-3_c_double
    want = 0
    big = 0
    do ka = 1, nn
      do ia = 1, 3
        if (feq(ia, ka) <= 0) cycle
        do kb = 1, nn
          do ib = 1, 3
            if (feq(ib, kb) > 0) cycle
            want(feq(ia, ka)) = want(feq(ia, ka)) + &
                                Kall(all_eq(ia, ka), all_eq(ib, kb)) * du(ib, kb)
            big = max(big, abs(Kall(all_eq(ia, ka), all_eq(ib, kb)) * du(ib, kb)))
          end do
        end do
      end do
    end do
    f = 0
    call b2b_model_add_constrained_product(m, feq, du, 1.0_c_double, f, ierr, msg)
    err = maxval(abs(f - want))
    call check(ierr == B2B_OK .and. any(want /= 0) .and. err <= 1e-13_c_double * big, &
               'constrained product = K_all(free, constrained) du_c [' // trim(msg) // ']')
    du(2, 7) = nan
    f = 3
    call b2b_model_add_constrained_product(m, feq, du, 1.0_c_double, f, ierr, msg)
    call check(ierr == B2B_ERR_NONFINITE .and. all(f == 3) .and. &
               contains_text(msg, 'node 7 has a non-finite prescribed y'), &
               'NaN increment: ' // trim(msg))
    write (*, '(a, es9.2, a, es9.2, a)') 'constrained product: equals K_all(free, ' // &
      'constrained) du_c to ', err, ' (terms up to ', big, '); NaN du refused naming node 7'
  end subroutine

end program ftest_model_host
