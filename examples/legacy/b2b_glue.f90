! b2b_glue.f90 -- all of the legacy frame code's calls into b2b: external
! subroutines, called from FORTRAN 77 like its own; the model is kept here.
! The F77 numbers pass as they are: nodes, x(ndm,*), u(ndf,*), id(ndf,*)
! (0: constrained), FEAP's jp, ad, au, al, b = F_ext - F_int. A failing call
! stops with b2b's message (not cbupd).
module b2b_glue_model
  use b2b
  implicit none
  type(b2b_model), save :: model
  type(b2b_params), save :: params
end module
! The model, and its contact law: 0 linear, 1 quadratic (gap g0); penalty
! pen; Coulomb fmu with tangential penalty pent (fmu = 0: frictionless).
subroutine cbinit(law, pen, g0, fmu, pent)
  use b2b_glue_model
  integer, intent(in) :: law
  real(c_double), intent(in) :: pen, g0, fmu, pent
  call b2b_params_create(params)
  call b2b_params_set_real(params, 'penalty', pen)
  call b2b_params_set_int(params, 'law', law)
  if (law == B2B_LAW_QUADRATIC) call b2b_params_set_real(params, 'regularization_gap', g0)
  if (fmu > 0) call b2b_params_set_real(params, 'friction', fmu)
  if (fmu > 0) call b2b_params_set_real(params, 'tangential_penalty', pent)
  call b2b_params_finalize(params)
  call b2b_model_create(model)
end subroutine
! A beam: nodes(1:nn), radius rad, group igrp. cbfin: ig1, ig2 touch; numnp.
subroutine cbbeam(nodes, nn, rad, igrp)
  use b2b_glue_model
  integer, intent(in) :: nn, nodes(nn), igrp
  real(c_double), intent(in) :: rad
  integer :: ib
  call b2b_model_add_beam(model, nodes, .false., rad, B2B_CURVE_HERMITE_NODAL, igrp, ib)
end subroutine
subroutine cbfin(ig1, ig2, numnp)
  use b2b_glue_model
  integer, intent(in) :: ig1, ig2, numnp
  call b2b_model_set_group_pair(model, ig1, ig2, params)
  call b2b_model_finalize(model, numnp)
end subroutine
! Every iteration: contacts at x + u. ierr /= 0: failed, the caller cuts back.
subroutine cbupd(x, u, ndm, ndf, numnp, ierr)
  use b2b_glue_model
  integer, intent(in) :: ndm, ndf, numnp
  real(c_double), intent(in) :: x(ndm, numnp), u(ndf, numnp)
  integer, intent(out) :: ierr
  character(len=256) :: msg
  call b2b_model_update_xu(model, x, u, ierr=ierr, errmsg=msg)
  if (ierr /= 0) write (*, '(2a)') '   b2b: ', trim(msg)
end subroutine
! After cbupd: ihc(j) the contacts' column height of equation j (0: none).
subroutine cbprof(id, ndf, numnp, neq, ihc)
  use b2b_glue_model
  integer, intent(in) :: ndf, numnp, neq, id(ndf, numnp)
  integer, intent(inout) :: ihc(neq)
  call b2b_model_tangent_profile(model, id, ihc)
end subroutine
! b = b - contact residual (part of F_int), the tangent into ad, au, al.
subroutine cbasm(id, ndf, numnp, neq, jp, ad, au, al, b)
  use b2b_glue_model
  integer, intent(in) :: ndf, numnp, neq, id(ndf, numnp), jp(neq)
  real(c_double), intent(inout) :: ad(neq), au(*), al(*), b(neq)
  call b2b_model_add_residual_scaled(model, id, -1.0_c_double, b)
  call b2b_model_add_tangent_profile(model, id, 1.0_c_double, jp, ad, au(1:jp(neq)), &
                                     al(1:jp(neq)))
end subroutine
! Iteration 1 of a step: b = b - K_contact(free, prescribed) dup (per node).
subroutine cbcpr(id, ndf, numnp, neq, dup, b)
  use b2b_glue_model
  integer, intent(in) :: ndf, numnp, neq, id(ndf, numnp)
  real(c_double), intent(in) :: dup(ndf, numnp)
  real(c_double), intent(inout) :: b(neq)
  call b2b_model_add_constrained_product(model, id, dup, -1.0_c_double, b)
end subroutine
! For reactions: r(i,n) += the contact's internal force on dof i <= 3 of
! node n, free or constrained (here every dof has an equation of its own).
subroutine cbreac(ndf, numnp, r)
  use b2b_glue_model
  integer, intent(in) :: ndf, numnp
  real(c_double), intent(inout) :: r(ndf * numnp)
  integer :: ieq(ndf, numnp), i
  ieq = reshape([(i, i = 1, ndf * numnp)], [ndf, numnp])
  call b2b_model_add_residual(model, ieq, r)
end subroutine
! Last update: active, slipping, hops, lost, crossed contacts; fn: sum f_N.
subroutine cbstat(nact, nslip, nhop, nlost, ncrs, fn)
  use b2b_glue_model
  integer, intent(out) :: nact, nslip, nhop, nlost, ncrs
  real(c_double), intent(out) :: fn
  integer :: c(B2B_MODEL_COUNTS_LEN)
  real(c_double) :: s(B2B_MODEL_TOTALS_LEN)
  call b2b_model_stats(model, c, s)
  nact = c(B2B_IX_COUNT_ACTIVE)
  nslip = c(B2B_IX_COUNT_SLIP)
  nhop = c(B2B_IX_COUNT_HANDOVERS)
  nlost = c(B2B_IX_COUNT_LOST)
  ncrs = c(B2B_IX_COUNT_CROSSED)
  fn = s(B2B_IX_TOTAL_NORMAL_FORCE)
end subroutine
! The audit: pairs overlapping by > 1% of the smaller radius without force.
subroutine cbaud(nfnd)
  use b2b_glue_model
  integer, intent(out) :: nfnd
  nfnd = 0
  call b2b_model_audit(model, 0.01_c_double, nfnd)
end subroutine
! Converged step: commit; cut-back: revert; the end: free the model.
subroutine cbcmt()
  use b2b_glue_model
  call b2b_model_commit(model)
end subroutine
subroutine cbrvt()
  use b2b_glue_model
  call b2b_model_revert(model)
end subroutine
subroutine cbend()
  use b2b_glue_model
  call b2b_model_destroy(model)
  call b2b_params_destroy(params)
end subroutine
