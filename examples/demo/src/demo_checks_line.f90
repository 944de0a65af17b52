!> The checks of the line-contact scenes (&contact contact_type = 'line' or
!> 'all_angle'; b2b_pair.h "Line contact"), called by demo_checks with one
!> line per kind. Each computes its closed form from the scene's own data.
!>
!>  euler_eytelwein  beam_a (the rope, added first, so the line contact
!>                   integrates along it) wrapped around beam_b (a fixed
!>                   straight beam of larger radius, the cylinder); its
!>                   loaded node holds T_in, its pulled node (a prescribed
!>                   motion) gives T_out = |reaction of beam_a's supports|.
!>                   Whole-rope slip is told by the kinematics: once the
!>                   load is fully applied, a step in which the loaded end
!>                   moves by the pulled end's motion to 5% (norms of the
!>                   step's displacements: steady sliding, at a fixed
!>                   tension profile every point moves alike; in the step
!>                   the rope breaks loose the loaded end moves further,
!>                   the profile still forming). In every such step
!>                   T_out / T_in = exp(mu theta) within tolerance, theta the
!>                   total turning of the rope's initial polygon (sum of its
!>                   corner angles: the wrap angle of a planar wrap, and
!>                   theta cos(beta) of a helix of helix angle beta, the
!>                   helix's own exponent, since a helix's curvature times
!>                   length is 2 pi cos(beta) per turn). At least two steps.
!>  line_load        beam_a lying along beam_b (both straight, parallel),
!>                   pressed onto it by nodal loads of a uniform line load
!>                   q = |load on beam_a| / L_a; beam_b supported. Linear
!>                   law: the contact line load f / L_a (f the integrated
!>                   normal forces of the line contacts) equals q (1e-9:
!>                   equilibrium), and every line contact's deepest
!>                   penetration -g_min equals q / line_penalty within
!>                   tolerance (a uniform settlement of a stiff beam on a
!>                   uniform foundation), at every step.
!>  angle_sweep      beam_a turned over beam_b under a constant pressing load
!>                   (contact_type 'all_angle'): once the load is fully
!>                   applied, the sum of the contact normal forces changes
!>                   between consecutive steps by at most tolerance * P
!>                   (P = |load on beam_a|), the crossing angle (of the
!>                   chords) passes through the blending range
!>                   [line_angle, point_angle] going down and coming back,
!>                   and every step converged; cut-backs are reported.
module demo_checks_line
  use demo_kinds, only: dp, pi
  use demo_model, only: scene_model, external_force
  use demo_history, only: step_row
  use demo_contact_report, only: contact_snapshot
  use demo_errors, only: str
  use b2b, only: B2B_IX_INFO_GAP, B2B_IX_INFO_NORMAL_FORCE, B2B_IX_INFO_LINE_POINTS, &
                 B2B_IX_COUNT_STICK, B2B_IX_COUNT_SLIP, B2B_IX_COUNT_LINE, B2B_IX_TOTAL_LINE_POINTS, B2B_IX_TOTAL_DISSIPATION
  implicit none
  private
  public :: line_check_step, line_check_finish, line_check_reset, line_check_result

  !> The kinds of this module (demo_scene_reader accepts them).
  character(len=*), parameter, public :: line_check_kinds = 'euler_eytelwein line_load angle_sweep'

  logical, save :: ok = .true.
  logical, save :: quiet = .false.
  logical, save :: started = .false.
  integer, save :: n_checked = 0, n_steps = 0, total_cut = 0, iters_total = 0, iters_max = 0
  real(dp), save :: worst = 0.0_dp
  ! euler_eytelwein
  integer, save :: node_in = 0, node_out = 0, first_step = 0, n_stick_last = 0, n_slip_last = 0
  real(dp), save :: theta = 0.0_dp, ratio_formula = 0.0_dp, ratio_first = 0.0_dp, ratio_last = 0.0_dp
  real(dp), save :: x_in_prev(3) = 0.0_dp, x_out_prev(3) = 0.0_dp, follow_last = 0.0_dp, dissipation = 0.0_dp
  ! line_load
  real(dp), save :: q_last = 0.0_dp, line_load_last = 0.0_dp, pen_min = 0.0_dp, pen_max = 0.0_dp, &
                    pen_closed = 0.0_dp, err_load = 0.0_dp
  integer, save :: n_line_last = 0, n_points_last = 0
  ! angle_sweep
  real(dp), save :: f_prev = -1.0_dp, angle_prev = -1.0_dp, angle_min = huge(1.0_dp), p_load = 0.0_dp
  real(dp), save :: f_min = huge(1.0_dp), f_max = 0.0_dp, line_angle = 5.0_dp, point_angle = 15.0_dp
  integer, save :: n_blend_down = 0, n_blend_up = 0, worst_step = 0
  real(dp), save :: pen_prev = -1.0_dp, pen_jump_blend = 0.0_dp, pen_jump_all = 0.0_dp, pen_point = 0.0_dp
  logical, save :: coming_back = .false.

contains

  subroutine fail(msg)
    character(len=*), intent(in) :: msg
    if (.not. quiet) write (*, '(a)') '  CHECK FAILED: ' // msg
    ok = .false.
  end subroutine fail

  !> A new run (the trade table runs many in one process); quiet_run: no printing.
  subroutine line_check_reset(quiet_run)
    logical, intent(in) :: quiet_run
    ok = .true.
    quiet = quiet_run
    started = .false.
    n_checked = 0; n_steps = 0; total_cut = 0; iters_total = 0; iters_max = 0; worst = 0.0_dp
    node_in = 0; node_out = 0; first_step = 0; theta = 0.0_dp; ratio_formula = 0.0_dp; ratio_first = 0.0_dp
    ratio_last = 0.0_dp; follow_last = 0.0_dp; dissipation = 0.0_dp; n_stick_last = 0; n_slip_last = 0
    q_last = 0.0_dp; line_load_last = 0.0_dp; pen_min = 0.0_dp; pen_max = 0.0_dp; pen_closed = 0.0_dp
    err_load = 0.0_dp; n_line_last = 0; n_points_last = 0
    f_prev = -1.0_dp; angle_prev = -1.0_dp; angle_min = huge(1.0_dp); p_load = 0.0_dp; f_min = huge(1.0_dp)
    f_max = 0.0_dp; n_blend_down = 0; n_blend_up = 0; worst_step = 0; coming_back = .false.
    pen_prev = -1.0_dp; pen_jump_blend = 0.0_dp; pen_jump_all = 0.0_dp; pen_point = 0.0_dp
  end subroutine line_check_reset

  !> The worst relative error of the check so far and its verdict (for the trade table).
  subroutine line_check_result(err, passed, checked)
    real(dp), intent(out) :: err
    logical, intent(out) :: passed
    integer, intent(out) :: checked
    err = worst
    passed = ok
    checked = n_checked
  end subroutine line_check_result

  !> A library option of &contact by key (default if the scene does not set it).
  real(dp) function contact_option(m, key, default) result(v)
    type(scene_model), intent(in) :: m
    character(len=*), intent(in) :: key
    real(dp), intent(in) :: default
    integer :: k
    v = default
    do k = 1, m%contact%n_options
      if (trim(m%contact%option_key(k)) == key) v = m%contact%option_value(k)
    end do
  end function contact_option

  !> The external force on beam b at load factor lam (vector sum).
  function beam_load(m, b, lam) result(p)
    type(scene_model), intent(in) :: m
    integer, intent(in) :: b
    real(dp), intent(in) :: lam
    real(dp) :: p(3), f(6, m%n_nodes)
    integer :: node
    f = external_force(m, lam)
    p = 0.0_dp
    do node = m%beam_first_node(b), m%beam_first_node(b) + m%beam_n_nodes(b) - 1
      p = p + f(1:3, node)
    end do
  end function beam_load

  !> Sum of the reactions (f_int - f_ext on constrained translations) of beam b.
  function reaction(m, b, fint, lam) result(r)
    type(scene_model), intent(in) :: m
    integer, intent(in) :: b
    real(dp), intent(in) :: fint(:, :), lam
    real(dp) :: r(3), f(6, m%n_nodes)
    integer :: node, d
    f = external_force(m, lam)
    r = 0.0_dp
    do node = m%beam_first_node(b), m%beam_first_node(b) + m%beam_n_nodes(b) - 1
      do d = 1, 3
        if (m%fixed(d, node)) r(d) = r(d) + fint(d, node) - f(d, node)
      end do
    end do
  end function reaction

  !> Initial length of beam b (sum of its elements).
  real(dp) function beam_length(m, b) result(l)
    type(scene_model), intent(in) :: m
    integer, intent(in) :: b
    l = sum(m%el_l0(m%beam_first_el(b):m%beam_first_el(b) + m%beam_n_el(b) - 1))
  end function beam_length

  !> Total turning angle of beam b's initial polygon (sum of its corner angles).
  real(dp) function polygon_turning(m, b) result(a)
    type(scene_model), intent(in) :: m
    integer, intent(in) :: b
    integer :: node
    real(dp) :: t1(3), t2(3), c(3)
    a = 0.0_dp
    do node = m%beam_first_node(b) + 1, m%beam_first_node(b) + m%beam_n_nodes(b) - 2
      t1 = m%x0(:, node) - m%x0(:, node - 1)
      t2 = m%x0(:, node + 1) - m%x0(:, node)
      c = [t1(2) * t2(3) - t1(3) * t2(2), t1(3) * t2(1) - t1(1) * t2(3), t1(1) * t2(2) - t1(2) * t2(1)]
      a = a + atan2(norm2(c), dot_product(t1, t2))
    end do
  end function polygon_turning

  !> Crossing angle (degrees, 0 .. 90) of the current chords of beams a and b.
  real(dp) function chord_angle(m, a, b) result(deg)
    type(scene_model), intent(in) :: m
    integer, intent(in) :: a, b
    real(dp) :: u(3), v(3)
    u = m%x(:, m%beam_first_node(a) + m%beam_n_nodes(a) - 1) - m%x(:, m%beam_first_node(a))
    v = m%x(:, m%beam_first_node(b) + m%beam_n_nodes(b) - 1) - m%x(:, m%beam_first_node(b))
    deg = acos(min(1.0_dp, abs(dot_product(u, v)) / (norm2(u) * norm2(v)))) * 180.0_dp / pi
  end function chord_angle

  !> Called by demo_checks%check_step for the kinds of this module.
  subroutine line_check_step(m, row, snap, fint)
    type(scene_model), intent(in) :: m
    type(step_row), intent(in) :: row
    type(contact_snapshot), intent(in) :: snap
    real(dp), intent(in) :: fint(:, :)
    real(dp) :: f_n, p_now(3), p_full, err, rb(3), t_in, t_out, du_in, du_out(3), follow, q, eps_l, la, pen, ang
    integer :: k, node, n_line, n_pts

    n_steps = n_steps + 1
    total_cut = total_cut + row%cutbacks
    iters_total = iters_total + row%iterations
    iters_max = max(iters_max, row%iterations)
    f_n = 0.0_dp
    n_line = 0
    n_pts = 0
    do k = 1, snap%n
      f_n = f_n + snap%c(k)%info(B2B_IX_INFO_NORMAL_FORCE)
      if (snap%c(k)%info(B2B_IX_INFO_LINE_POINTS) > 0.0_dp) n_line = n_line + 1
    end do
    n_line = snap%counts(B2B_IX_COUNT_LINE)
    n_pts = nint(snap%totals(B2B_IX_TOTAL_LINE_POINTS))
    associate (ba => m%check%beam_a, bb => m%check%beam_b, tol => m%check%tolerance)
      p_now = beam_load(m, ba, row%lam)
      p_full = norm2(beam_load(m, ba, 1.0_dp))
      select case (trim(m%check%kind))
      case ('euler_eytelwein')
        if (.not. started) then
          started = .true.
          theta = polygon_turning(m, ba)
          ratio_formula = exp(m%contact%friction * theta)
          do node = m%beam_first_node(ba), m%beam_first_node(ba) + m%beam_n_nodes(ba) - 1
            if (any(abs(m%fext(1:3, node)) > 0.0_dp)) node_in = node
            if (any(abs(m%prescribed(1:3, node)) > 0.0_dp)) node_out = node
          end do
          if (node_in == 0 .or. node_out == 0) call fail('beam_a needs one loaded node (T_in) and one pulled ' &
                                                         // 'node (a &motion): no capstan')
          x_in_prev = m%x0(:, max(node_in, 1))
          x_out_prev = m%x0(:, max(node_out, 1))
        end if
        if (node_in == 0 .or. node_out == 0) return
        rb = reaction(m, ba, fint, row%lam)
        t_in = norm2(p_now)
        t_out = norm2(rb)
        du_out = m%x(:, node_out) - x_out_prev
        du_in = norm2(m%x(:, node_in) - x_in_prev)
        follow = du_in / max(norm2(du_out), tiny(1.0_dp))
        x_in_prev = m%x(:, node_in)
        x_out_prev = m%x(:, node_out)
        n_stick_last = snap%counts(B2B_IX_COUNT_STICK)
        n_slip_last = snap%counts(B2B_IX_COUNT_SLIP)
        dissipation = snap%totals(B2B_IX_TOTAL_DISSIPATION)
        if (t_in >= (1.0_dp - 1.0e-12_dp) * p_full .and. norm2(du_out) > 0.0_dp .and. t_in > 0.0_dp) then
          follow_last = follow
          ratio_last = t_out / t_in
          if (abs(follow - 1.0_dp) <= 0.05_dp) then
            n_checked = n_checked + 1
            if (n_checked == 1) then
              ratio_first = ratio_last
              first_step = row%step
            end if
            err = abs(ratio_last - ratio_formula) / ratio_formula
            worst = max(worst, err)
            if (.not. quiet) write (*, '(4x,a,f7.4,a,es13.6,a,es13.6,a,f9.6,a,f9.6,a,es9.2,a,i0,a,i0)') &
              'check: whole rope slides (loaded end follows', follow, '), T_out ', t_out, '  T_in ', t_in, &
              '  T_out/T_in ', ratio_last, '  exp(mu theta) ', ratio_formula, '  rel. error ', err, &
              '  line contacts ', n_line, ', points ', n_pts
            if (err > tol) call fail('step ' // str(row%step) // ': T_out/T_in off exp(mu theta) by more than ' &
                                     // 'the tolerance')
          else if (.not. quiet) then
            write (*, '(4x,a,f7.4,a,f9.6)') 'check: rope not sliding steadily (loaded end follows', follow, &
              '), T_out/T_in ', ratio_last
          end if
        end if
      case ('line_load')
        la = beam_length(m, ba)
        q = norm2(p_now) / la
        if (.not. (q > 0.0_dp)) return
        eps_l = contact_option(m, 'line_penalty', 0.0_dp)
        if (.not. started) then
          started = .true.
          if (.not. (eps_l > 0.0_dp)) call fail('line_load needs &contact line_penalty > 0')
          if (m%contact%law /= 'linear') call fail('line_load needs the linear law (penetration q / line_penalty)')
        end if
        if (.not. (eps_l > 0.0_dp)) return
        pen_closed = q / eps_l
        pen_min = huge(1.0_dp)
        pen_max = -huge(1.0_dp)
        do k = 1, snap%n
          if (snap%c(k)%info(B2B_IX_INFO_LINE_POINTS) <= 0.0_dp) cycle
          pen = -snap%c(k)%info(B2B_IX_INFO_GAP)
          pen_min = min(pen_min, pen)
          pen_max = max(pen_max, pen)
        end do
        n_checked = n_checked + 1
        q_last = q
        line_load_last = f_n / la
        n_line_last = n_line
        n_points_last = n_pts
        err_load = abs(line_load_last - q) / q
        if (n_line == 0) then
          call fail('step ' // str(row%step) // ': no line contact')
          return
        end if
        err = max(abs(pen_min - pen_closed), abs(pen_max - pen_closed)) / pen_closed
        worst = max(worst, err)
        if (.not. quiet) write (*, '(4x,a,es13.6,a,es13.6,a,es9.2,a,es13.6,a,es13.6,a,es13.6,a,es9.2,a,i0,a,i0)') &
          'check: line load ', line_load_last, '  q ', q, '  rel. error ', err_load, '  penetration ', pen_min, &
          ' .. ', pen_max, '  q/line_penalty ', pen_closed, '  rel. error ', err, '  line contacts ', n_line, &
          ', points ', n_pts
        if (err_load > 1.0e-9_dp) call fail('step ' // str(row%step) // ': contact line load differs from q')
        if (err > tol) call fail('step ' // str(row%step) // ': penetration off q / line_penalty by more than ' &
                                 // 'the tolerance')
      case ('angle_sweep')
        if (.not. started) then
          started = .true.
          line_angle = contact_option(m, 'line_angle', 5.0_dp)
          point_angle = contact_option(m, 'point_angle', 15.0_dp)
          p_load = p_full
          pen_point = p_full / m%contact%penalty
          if (.not. (p_load > 0.0_dp)) call fail('angle_sweep needs a load on beam_a')
        end if
        ang = chord_angle(m, ba, bb)
        if (norm2(p_now) >= (1.0_dp - 1.0e-12_dp) * p_full .and. p_load > 0.0_dp) then
          if (angle_prev >= 0.0_dp .and. ang > angle_prev + 1.0e-9_dp .and. angle_min < 0.5_dp * line_angle) &
            coming_back = .true.
          angle_min = min(angle_min, ang)
          if (ang >= line_angle .and. ang <= point_angle) then
            if (coming_back) then
              n_blend_up = n_blend_up + 1
            else
              n_blend_down = n_blend_down + 1
            end if
          end if
          f_min = min(f_min, f_n)
          f_max = max(f_max, f_n)
          err = 0.0_dp
          if (f_prev >= 0.0_dp) then
            err = abs(f_n - f_prev) / p_load
            n_checked = n_checked + 1
            if (err > worst) worst_step = row%step
            worst = max(worst, err)
          end if
          ! the deepest penetration (reported, not checked): its change per step
          pen = 0.0_dp
          do k = 1, snap%n
            pen = max(pen, -snap%c(k)%info(B2B_IX_INFO_GAP))
          end do
          if (pen_prev >= 0.0_dp) then
            pen_jump_all = max(pen_jump_all, abs(pen - pen_prev) / pen_point)
            if (ang >= line_angle .and. ang <= point_angle .and. angle_prev >= line_angle .and. &
                angle_prev <= point_angle) pen_jump_blend = max(pen_jump_blend, abs(pen - pen_prev) / pen_point)
          end if
          pen_prev = pen
          if (.not. quiet) write (*, '(4x,a,f8.3,a,es13.6,a,es9.2,a,es10.3,a,i0,a,i0,a,i0,a,i0)') 'check: angle ', ang, &
            '  sum f_N ', f_n, '  jump/P ', err, '  penetration ', pen, '  contacts ', snap%n, ' (line ', n_line, &
            ', points ', n_pts, ')  iterations ', row%iterations
          if (err > tol) call fail('step ' // str(row%step) // ': the normal force jumps by more than tolerance * P')
          f_prev = f_n
          angle_prev = ang
        end if
      end select
    end associate
  end subroutine line_check_step

  !> Summary of the check (printed unless quiet); .false. if any part failed.
  logical function line_check_finish(m) result(passed)
    type(scene_model), intent(in) :: m
    select case (trim(m%check%kind))
    case ('euler_eytelwein')
      if (.not. quiet) then
        write (*, '(a,f8.3,a,f5.3,a,f9.6,a,i0,a,f9.6,a,es9.2)') trim(m%name) // ': check euler_eytelwein: theta ', &
          theta * 180.0_dp / pi, ' degrees (turning of the rope), mu = ', m%contact%friction, &
          ': exp(mu theta) = ', ratio_formula, '; whole rope slides from step ', first_step, ', T_out/T_in ', &
          ratio_first, ', rel. error ', abs(ratio_first - ratio_formula) / max(ratio_formula, tiny(1.0_dp))
        write (*, '(a,i0,a,f9.6,a,es9.2,a,es9.2,a,f7.4,a,i0,a,i0,a,es9.2)') '  slide steps checked ', n_checked, &
          ', last T_out/T_in ', ratio_last, ', worst rel. error ', worst, ', tolerance ', m%check%tolerance, &
          '; last step: loaded end follows ', follow_last, ', contacts in stick ', n_stick_last, ', in slip ', &
          n_slip_last, ', dissipation ', dissipation
      end if
      if (abs(ratio_last - 1.0_dp) < 1.0e-3_dp .and. m%contact%friction > 0.0_dp .and. n_steps > 0) &
        call fail('T_out/T_in = ' // str(ratio_last) // ' at the end of the pull: no friction reaches the rope ' &
                  // '(the slip of a rope sliding round a straight beam''s axis is a rotation about that axis, ' &
                  // 'which the centreline slip measure does not see)')
      if (n_checked < 2) call fail('fewer than two steps in which the whole rope slides: no plateau')
    case ('line_load')
      if (.not. quiet) then
        write (*, '(a,es13.6,a,es13.6,a,es9.2,a,es13.6,a,es13.6,a,es13.6,a,i0,a,i0)') trim(m%name) &
          // ': check line_load: final line load ', line_load_last, ', q ', q_last, ', rel. error ', err_load, &
          '; penetration ', pen_min, ' .. ', pen_max, ', q/line_penalty ', pen_closed, '; line contacts ', &
          n_line_last, ', points ', n_points_last
        write (*, '(a,i0,a,es9.2,a,es9.2)') '  steps checked ', n_checked, ', worst rel. error of the penetration ', &
          worst, ', tolerance ', m%check%tolerance
      end if
      if (n_checked == 0) call fail('no step with load: nothing checked')
    case ('angle_sweep')
      if (.not. quiet) then
        write (*, '(a,f7.3,a,f7.3,a,f7.3,a,i0,a,i0,a,es9.2,a,i0,a,es9.2)') trim(m%name) &
          // ': check angle_sweep: blending range ', line_angle, ' .. ', point_angle, &
          ' degrees; smallest angle ', angle_min, '; steps in the range going down ', n_blend_down, ', coming back ', &
          n_blend_up, '; largest jump of sum f_N between steps ', worst, ' P (step ', worst_step, '), tolerance ', &
          m%check%tolerance
        write (*, '(a,es13.6,a,es13.6,a,es13.6,a,i0,a,f6.2,a,i0,a,i0)') '  sum f_N from ', f_min, ' to ', f_max, &
          ' (P = ', p_load, '); steps ', n_steps, ', iterations per step mean ', &
          real(iters_total, dp) / real(max(n_steps, 1), dp), ', max ', iters_max, ', cut-backs ', total_cut
        write (*, '(a,es9.2,a,es9.2,a,es9.2,a)') '  deepest penetration (reported): largest change between steps ', &
          pen_jump_blend, ' (both in the blending range), ', pen_jump_all, ' (anywhere), of P / penalty = ', &
          pen_point, ' (the point contact''s)'
      end if
      if (n_blend_down == 0 .or. n_blend_up == 0) call fail('the sweep did not pass through the blending range ' &
                                                            // 'both ways')
      if (n_checked < 2) call fail('fewer than two steps under the full load: nothing checked')
    end select
    passed = ok
  end function line_check_finish

end module demo_checks_line
