! Wrapper of the README's contact-model fragment in Fortran (section "The
! contact model"): a host's arrays for one beam of 17 nodes on the x axis,
! every translational dof free (equations 1..51), LAPACK band storage with
! kl = ku = 11, and a finalized parameter set. The fragment (in the block,
! where its use statement and declarations may stand) declares m and runs the
! life cycle once; a failing call without ierr stops the program with a
! non-zero exit code, which is the verdict.
program readme_model_f
  use b2b
  implicit none
  integer, parameter :: n_nodes = 17, kl = 11, ku = 11
  integer :: i, beam, eq(3, n_nodes)
  real(c_double) :: x(3, n_nodes), f(3 * n_nodes), AB(2 * kl + ku + 1, 3 * n_nodes)
  type(b2b_params) :: params

  do i = 1, n_nodes
    x(:, i) = [0.25_c_double * (i - 1), 0.0_c_double, 0.0_c_double]
    eq(:, i) = [3 * i - 2, 3 * i - 1, 3 * i]
  end do
  f = 0
  AB = 0
  beam = -1
  call b2b_params_create(params)
  call b2b_params_set_real(params, 'penalty', 1.0e3_c_double)
  call b2b_params_finalize(params)

  block
    ! README SNIPPET
    call b2b_model_destroy(m)
  end block
  call b2b_params_destroy(params)
  if (beam /= 1) error stop 'README model (Fortran): the beam is not number 1'
  print '(a)', 'README model (Fortran): one beam, the life cycle ran without an error'
end program
