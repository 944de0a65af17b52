!> The checks a scene asks for in its &check group, computed by the program
!> from the scene's own data (geometry, sections, loads, penalty) and the
!> converged steps, and printed against the closed form. check_finish
!> returns the verdict; b2b_demo exits with 1 when a check fails.
!>
!>  crossed_beams        two simply supported beams crossing, beam_a loaded
!>                       at mid-span towards beam_b: at every step where the
!>                       closed form predicts contact,
!>                       F = (c_a P - g0) / (c_a + c_b + 1/eps),
!>                       c_i = L_i^3 / (48 E I_i), within tolerance; the
!>                       model's f_N and the reaction of beam_b both checked;
!>                       and the deflection of beam_a below 1e-3 L_a (linear
!>                       theory).
!>  cantilever_crossbar  beam_a clamped at its first node, loaded at its tip
!>                       towards the rigid crossbar beam_b at distance a from
!>                       the clamp: F = (P a^2 (3L - a)/(6EI) - g0) / (a^3/(3EI) + 1/eps).
!>                       P, L, a, g0 and EI come from the scene: P the load on
!>                       beam_a, L its chord, a and g0 from the closest points
!>                       of the two initial chords and the radii.
!>  sliding              no cut-back at all, and a convergence rate >=
!>                       min_rate in every step whose active set did not
!>                       change in the iterations the rate is measured on
!>                       (both for the smoothed curve kinds; reported only
!>                       for 'linear', the straight segments they are
!>                       compared with); the contact crosses at least
!>                       min_nodes_crossed nodes of beam_b.
!>  friction_pull        beam_a pulled over beam_b: the tangential reaction of
!>                       beam_a's supports is below mu f_N in stick, equals
!>                       mu f_N within tolerance in every slip step, and
!>                       takes both signs in slip (reversal).
!>  many_contacts        at least min_contacts active contacts at every step;
!>                       the contact forces on beam_a balance its load along
!>                       the load (1e-6); at least min_nodes_crossed handover
!>                       hops in the run (the contacts slide across nodes).
!>  reference            the monitored node's final displacement |u| within
!>                       tolerance (relative) of reference, a value measured by
!>                       the same scene in many more steps (the scene says
!>                       which): large steps must give the answer of small ones.
!>  capstan              beam_a (the rope) led over pegs, its first node
!>                       loaded (the held tension T_in), its last node pulled
!>                       by a prescribed motion: in every step where all
!>                       active contacts slip and the pull exceeds T_in,
!>                       T_out / T_in within tolerance of the product over
!>                       the rope's initial corners (turning angles a_k) of
!>                       (1 + mu tan(a_k/2)) / (1 - mu tan(a_k/2)), i.e.
!>                       [(1 + mu tan(a/2)) / (1 - mu tan(a/2))]^n for n
!>                       equal turns; T_out = |reaction| of beam_a's
!>                       supports (its pulled node), T_in = |load on beam_a|.
!>                       At least two such steps (a plateau) are required.
!> And for every scene with contact, whatever its &check (or none): the
!> interpenetration audit (demo_contact_report, after every converged step)
!> found no pair that overlaps with no force (issue 16).
module demo_checks
  use demo_kinds, only: dp, pi
  use demo_model, only: scene_model, external_force
  use demo_history, only: step_row, rate_unmeasured
  use demo_contact_report, only: contact_snapshot
  use demo_errors, only: str
  use demo_checks_line, only: line_check_step, line_check_finish
  use demo_checks_strand, only: strand_kind, strand_check_step, strand_check_finish
  implicit none
  private
  public :: check_step, check_finish

  logical, save :: ok = .true.
  integer, save :: n_slow = 0
  integer, save :: n_checked = 0, n_rate = 0, total_cut = 0, seg_min = huge(1), seg_max = -huge(1)
  integer, save :: n_stick = 0, n_slip_pos = 0, n_slip_neg = 0, total_hops = 0, min_active = huge(1)
  real(dp), save :: worst = 0.0_dp, worst_rate = huge(1.0_dp), e_dir(3) = 0.0_dp
  real(dp), save :: f_last = 0.0_dp, f_closed_last = 0.0_dp, r_last = 0.0_dp, f_closed_max = 0.0_dp
  ! capstan: the formula, its corners and total turn, the last ratio seen
  integer, save :: n_corners = -1
  integer, save :: first_slip_step = 0
  real(dp), save :: ratio_formula = 0.0_dp, turn_total = 0.0_dp, ratio_first = 0.0_dp, ratio_last = 0.0_dp
  real(dp), save :: t_in_last = 0.0_dp
  real(dp), save :: u_last = 0.0_dp  !< |u| of the monitored node at the last step (reference)
  integer, save :: audit_found = 0

contains

  subroutine fail(msg)
    character(len=*), intent(in) :: msg
    write (*, '(a)') '  CHECK FAILED: ' // msg
    ok = .false.
  end subroutine fail

  !> Chord of beam b in the initial configuration: first node and vector to the last.
  subroutine chord(m, b, p, u)
    type(scene_model), intent(in) :: m
    integer, intent(in) :: b
    real(dp), intent(out) :: p(3), u(3)
    p = m%x0(:, m%beam_first_node(b))
    u = m%x0(:, m%beam_first_node(b) + m%beam_n_nodes(b) - 1) - p
  end subroutine chord

  !> Closest points of the two initial chords (as infinite lines): s, t in
  !> units of the chords, and the distance of the axes.
  subroutine chord_closest(m, a, b, s, t, dist)
    type(scene_model), intent(in) :: m
    integer, intent(in) :: a, b
    real(dp), intent(out) :: s, t, dist
    real(dp) :: p(3), u(3), q(3), v(3), w(3), uu, uv, vv, uw, vw, det
    call chord(m, a, p, u)
    call chord(m, b, q, v)
    w = p - q
    uu = dot_product(u, u); uv = dot_product(u, v); vv = dot_product(v, v)
    uw = dot_product(u, w); vw = dot_product(v, w)
    det = uu * vv - uv * uv
    s = (uv * vw - vv * uw) / det
    t = (uu * vw - uv * uw) / det
    dist = norm2(p + s * u - q - t * v)
  end subroutine chord_closest

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

  real(dp) function max_deflection(m, b) result(w)
    type(scene_model), intent(in) :: m
    integer, intent(in) :: b
    integer :: node
    w = 0.0_dp
    do node = m%beam_first_node(b), m%beam_first_node(b) + m%beam_n_nodes(b) - 1
      w = max(w, norm2(m%x(:, node) - m%x0(:, node)))
    end do
  end function max_deflection

  !> Bending stiffness of beam b (its sections must be round: Iy = Iz).
  real(dp) function bending_stiffness(m, b) result(ei)
    type(scene_model), intent(in) :: m
    integer, intent(in) :: b
    integer :: el
    el = m%beam_first_el(b)
    ei = m%el_stiff(3, el)
    if (abs(m%el_stiff(4, el) - ei) > 1.0e-12_dp * ei) call fail('beam ' // str(b) // ' needs Iy = Iz for this check')
  end function bending_stiffness

  !> The capstan formula from beam b's initial polygon: a corner at every
  !> inner node whose legs turn by more than 1e-6 rad; per corner
  !> (1 + mu tan(a/2)) / (1 - mu tan(a/2)) (exact for a string over a
  !> point-like peg: normal force along the bisector, friction mu f_N along
  !> the string), the product over the corners.
  subroutine capstan_formula(m, b)
    type(scene_model), intent(in) :: m
    integer, intent(in) :: b
    integer :: node
    real(dp) :: t1(3), t2(3), c(3), a, mt
    n_corners = 0
    turn_total = 0.0_dp
    ratio_formula = 1.0_dp
    do node = m%beam_first_node(b) + 1, m%beam_first_node(b) + m%beam_n_nodes(b) - 2
      t1 = m%x0(:, node) - m%x0(:, node - 1)
      t2 = m%x0(:, node + 1) - m%x0(:, node)
      c = [t1(2) * t2(3) - t1(3) * t2(2), t1(3) * t2(1) - t1(1) * t2(3), t1(1) * t2(2) - t1(2) * t2(1)]
      a = atan2(norm2(c), dot_product(t1, t2))
      if (a <= 1.0e-6_dp) cycle
      n_corners = n_corners + 1
      turn_total = turn_total + a
      mt = m%contact%friction * tan(0.5_dp * a)
      if (mt >= 1.0_dp) call fail('a corner with mu tan(a/2) >= 1: the rope cannot slip there')
      ratio_formula = ratio_formula * (1.0_dp + mt) / (1.0_dp - mt)
    end do
    if (n_corners == 0) call fail('beam_a has no corner: no capstan')
  end subroutine capstan_formula


  !> Called after every converged planned step.
  subroutine check_step(m, row, snap, fint)
    type(scene_model), intent(in) :: m
    type(step_row), intent(in) :: row
    type(contact_snapshot), intent(in) :: snap
    real(dp), intent(in) :: fint(:, :)
    real(dp) :: la, lb, ca, cb, eia, eib, p, g0, s, t, dist, f_model, f_closed, err, rb(3), a, rt(3), n(3), fn, mu
    real(dp) :: fc(3), pext(3), sgn, w
    integer :: k, seg

    audit_found = snap%audit_found
    if (len_trim(m%check%kind) == 0) return
    total_cut = total_cut + row%cutbacks
    u_last = norm2(row%u)
    min_active = min(min_active, snap%n)
    f_model = 0.0_dp
    do k = 1, snap%n
      f_model = f_model + snap%c(k)%info(13)
    end do
    if (strand_kind(m%check%kind)) call strand_check_step(m, row, snap, fint)   ! demo_checks_strand
    associate (ba => m%check%beam_a, bb => m%check%beam_b, tol => m%check%tolerance)
      select case (trim(m%check%kind))
      case ('crossed_beams', 'cantilever_crossbar')
        eia = bending_stiffness(m, ba)
        call chord_closest(m, ba, bb, s, t, dist)
        g0 = dist - m%beam_radius(ba) - m%beam_radius(bb)
        la = norm2(m%x0(:, m%beam_first_node(ba) + m%beam_n_nodes(ba) - 1) - m%x0(:, m%beam_first_node(ba)))
        p = norm2(beam_load(m, ba, row%lam))
        if (m%check%kind == 'crossed_beams') then
          eib = bending_stiffness(m, bb)
          lb = norm2(m%x0(:, m%beam_first_node(bb) + m%beam_n_nodes(bb) - 1) - m%x0(:, m%beam_first_node(bb)))
          ca = la**3 / (48.0_dp * eia)
          cb = lb**3 / (48.0_dp * eib)
          f_closed = max(0.0_dp, (ca * p - g0) / (ca + cb + 1.0_dp / m%contact%penalty))
        else
          a = s * la
          f_closed = max(0.0_dp, (p * a**2 * (3.0_dp * la - a) / (6.0_dp * eia) - g0) &
                                 / (a**3 / (3.0_dp * eia) + 1.0_dp / m%contact%penalty))
        end if
        rb = reaction(m, bb, fint, row%lam)
        w = max_deflection(m, ba)
        f_closed_max = max(f_closed_max, f_closed)
        if (f_closed > 0.05_dp * f_closed_max .and. f_closed > 0.0_dp) then
          n_checked = n_checked + 1
          err = abs(f_model - f_closed) / f_closed
          worst = max(worst, err, abs(norm2(rb) - f_closed) / f_closed)
          write (*, '(4x,a,es13.6,a,es13.6,a,es13.6,a,es9.2,a,es9.2)') 'check: f_N ', f_model, '  reaction of beam_b ', &
            norm2(rb), '  closed form ', f_closed, '  rel. error ', err, '  w/L ', w / la
          if (err > tol) call fail('contact force off the closed form by more than the tolerance')
          if (abs(norm2(rb) - f_closed) > tol * f_closed) call fail('reaction of beam_b off the closed form')
        end if
        if (w > 1.0e-3_dp * la) call fail('deflection above 1e-3 L: outside linear theory, reduce the load')
        f_last = f_model
        f_closed_last = f_closed
        r_last = norm2(rb)
      case ('sliding')
        do k = 1, snap%n
          seg = 0
          if (snap%c(k)%pair(1) == bb) seg = snap%c(k)%pair(2)
          if (snap%c(k)%pair(3) == bb) seg = snap%c(k)%pair(4)
          if (seg > 0) then
            seg_min = min(seg_min, seg)
            seg_max = max(seg_max, seg)
          end if
        end do
        if (row%stable .and. row%rate >= 0.0_dp) then
          n_rate = n_rate + 1
          worst_rate = min(worst_rate, row%rate)
          if (row%rate < m%check%min_rate) then
            if (trim(m%contact%curve) == 'linear') then
              n_slow = n_slow + 1
              write (*, '(4x,a)') 'note: rate below min_rate with straight segments (reported, not a failure)'
            else
              call fail('step ' // str(row%step) // ': convergence rate below min_rate with an unchanged active set')
            end if
          end if
        end if
        if (snap%n == 0) call fail('step ' // str(row%step) // ': no active contact (the beam lost contact)')
      case ('friction_pull')
        mu = m%contact%friction
        if (snap%n > 0) then
          n = snap%c(1)%info(9:11)
          rb = reaction(m, ba, fint, row%lam)
          rt = rb - dot_product(rb, n) * n
          fn = f_model
          if (row%n_slip == 0) then
            if (norm2(rt) > 1.0e-9_dp * fn) then
              n_stick = n_stick + 1
              write (*, '(4x,a,es13.6,a,es13.6,a,f8.5)') 'check: stick, tangential reaction ', norm2(rt), &
                '  mu f_N ', mu * fn, '  ratio ', norm2(rt) / (mu * fn)
              if (norm2(rt) > mu * fn * (1.0_dp + 1.0e-9_dp)) call fail('stick beyond mu f_N')
            end if
          else if (row%n_slip == snap%n) then
            if (.not. any(abs(e_dir) > 0.0_dp)) e_dir = rt / norm2(rt)
            sgn = sign(1.0_dp, dot_product(rt, e_dir))
            if (sgn > 0.0_dp) n_slip_pos = n_slip_pos + 1
            if (sgn < 0.0_dp) n_slip_neg = n_slip_neg + 1
            err = abs(norm2(rt) - mu * fn) / (mu * fn)
            worst = max(worst, err)
            n_checked = n_checked + 1
            write (*, '(4x,a,es13.6,a,es13.6,a,es9.2,a,f5.1)') 'check: slip, tangential reaction ', &
              sgn * norm2(rt), '  mu f_N ', mu * fn, '  rel. error ', err, '  direction', sgn
            if (err > tol) call fail('slip force off mu f_N by more than the tolerance')
          end if
        end if
      case ('capstan')
        if (n_corners < 0) call capstan_formula(m, ba)
        rb = reaction(m, ba, fint, row%lam)
        p = norm2(beam_load(m, ba, row%lam))
        if (snap%n >= n_corners .and. row%n_slip == snap%n .and. p > 0.0_dp) then
          if (norm2(rb) > p) then
            n_checked = n_checked + 1
            ratio_last = norm2(rb) / p
            if (n_checked == 1) then
              ratio_first = ratio_last
              first_slip_step = row%step
            end if
            t_in_last = p
            err = abs(ratio_last - ratio_formula) / ratio_formula
            worst = max(worst, err)
            write (*, '(4x,a,es13.6,a,es13.6,a,f9.6,a,f9.6,a,es9.2)') 'check: all contacts slip, T_out ', norm2(rb), &
              '  T_in ', p, '  T_out/T_in ', ratio_last, '  formula ', ratio_formula, '  rel. error ', err
            if (err > tol) call fail('T_out/T_in off the capstan formula by more than the tolerance')
          end if
        end if
      case ('euler_eytelwein'); call line_check_step(m, row, snap, fint)
      case ('line_load'); call line_check_step(m, row, snap, fint)
      case ('angle_sweep'); call line_check_step(m, row, snap, fint)
      case ('many_contacts')
        if (row%step > 1 .and. snap%n < m%check%min_contacts) call fail('step ' // str(row%step) // ': ' &
            // str(snap%n) // ' active contacts, fewer than min_contacts')
        total_hops = total_hops + row%handovers
        fc = 0.0_dp
        do k = 1, snap%n
          if (snap%c(k)%pair(1) == ba) then
            fc = fc + snap%c(k)%info(13) * snap%c(k)%info(9:11) - snap%c(k)%info(18:20)
          else if (snap%c(k)%pair(3) == ba) then
            fc = fc - snap%c(k)%info(13) * snap%c(k)%info(9:11) + snap%c(k)%info(18:20)
          end if
        end do
        pext = beam_load(m, ba, row%lam)
        if (norm2(pext) > 0.0_dp) then
          err = abs(dot_product(fc + pext, pext)) / dot_product(pext, pext)
          worst = max(worst, err)
          write (*, '(4x,a,i0,a,es13.6,a,es13.6,a,es9.2,a,i0)') 'check: contacts ', snap%n, '  contact force along ' &
            // 'the load ', -dot_product(fc, pext) / norm2(pext), '  load ', norm2(pext), '  rel. error ', err, &
            '  handover hops so far ', total_hops
          if (err > 1.0e-6_dp) call fail('contact forces do not balance the load on beam_a')
        end if
      end select
    end associate
  end subroutine check_step

  !> The audit part of every scene's check: no finding in the whole run.
  subroutine audit_verdict(m)
    type(scene_model), intent(in) :: m
    if (.not. m%contact%enabled) return
    write (*, '(a,i0,a)') trim(m%name) // ': check audit: ', audit_found, &
      ' pair(s) overlapping with no force after converged steps'
    if (audit_found > 0) call fail('the audit found ' // str(audit_found) // &
                                   ' pair(s) overlapping with no force (see "audit, step")')
  end subroutine audit_verdict

  !> Prints the summary of the scene's check; .false. if any part failed.
  logical function check_finish(m) result(passed)
    type(scene_model), intent(in) :: m
    character(len=*), parameter :: fmt_err = '(a,es13.6,a,es13.6,a,es9.2)'
    character(len=16) :: worst_text
    call audit_verdict(m)
    if (len_trim(m%check%kind) == 0) then
      passed = ok
      return
    end if
    select case (trim(m%check%kind))
    case ('crossed_beams', 'cantilever_crossbar')
      if (n_checked == 0) call fail('no step with contact predicted: nothing checked')
      write (*, fmt_err) trim(m%name) // ': check ' // trim(m%check%kind) // ': final f_N ', f_last, &
        ', closed form ', f_closed_last, ', rel. error ', abs(f_last - f_closed_last) / max(f_closed_last, tiny(1.0_dp))
      write (*, '(a,i0,a,es9.2,a,es9.2)') '  steps checked ', n_checked, ', worst rel. error (f_N and reaction) ', &
        worst, ', tolerance ', m%check%tolerance
    case ('sliding')
      worst_text = adjustl(rate_unmeasured)
      if (n_rate > 0) write (worst_text, '(f6.3)') worst_rate
      write (*, '(a,i0,a,i0,a,a,a,i0,a,i0,a)') trim(m%name) // ': check sliding: cut-backs ', total_cut, &
        ', steps with a fixed active set and a measurable rate ', n_rate, ' (worst rate ', &
        trim(worst_text), '), contact crossed segments ', seg_min, '..', seg_max, ' of beam_b'
      if (trim(m%contact%curve) /= 'linear' .and. total_cut > 0) call fail('cut-backs with a smoothed curve kind')
      if (trim(m%contact%curve) == 'linear') write (*, '(a,i0,a,i0,a)') '  straight segments (reported, not ' &
        // 'failures): ', total_cut, ' cut-backs, ', n_slow, ' steps with a rate below min_rate'
      if (n_rate == 0) call fail('no step to measure the convergence rate on')
      if (seg_max - seg_min < m%check%min_nodes_crossed) call fail('the contact crossed ' // str(max(seg_max - seg_min, &
          0)) // ' nodes of beam_b, fewer than min_nodes_crossed = ' // str(m%check%min_nodes_crossed))
    case ('friction_pull')
      write (*, '(a,i0,a,i0,a,i0,a,es9.2,a,es9.2)') trim(m%name) // ': check friction_pull: stick steps ', n_stick, &
        ', slip steps forward ', n_slip_pos, ', after reversal ', n_slip_neg, '; worst plateau error ', worst, &
        ', tolerance ', m%check%tolerance
      if (n_stick == 0) call fail('no stick step seen')
      if (n_slip_pos < 2 .or. n_slip_neg < 2) call fail('fewer than two slip steps in one direction: no plateau' &
                                                        // ' or no reversal')
    case ('reference')
      write (*, '(a,es13.6,a,es13.6,a,es9.2,a,i0)') trim(m%name) // ': check reference: final |u| ', u_last, &
        ', reference ', m%check%reference, ', rel. error ', abs(u_last - m%check%reference) / m%check%reference, &
        ', cut-backs ', total_cut
      if (abs(u_last - m%check%reference) > m%check%tolerance * m%check%reference) &
        call fail('final displacement off the reference by more than the tolerance')
    case ('many_contacts')
      write (*, '(a,i0,a,i0,a,es9.2)') trim(m%name) // ': check many_contacts: fewest active contacts ', min_active, &
        ', handover hops ', total_hops, ', worst balance error ', worst
      if (total_hops < m%check%min_nodes_crossed) call fail('the contacts crossed ' // str(total_hops) &
          // ' nodes, fewer than min_nodes_crossed = ' // str(m%check%min_nodes_crossed))
    case ('euler_eytelwein'); if (.not. line_check_finish(m)) ok = .false.
    case ('line_load'); if (.not. line_check_finish(m)) ok = .false.
    case ('angle_sweep'); if (.not. line_check_finish(m)) ok = .false.
    case ('capstan')
      if (n_corners < 0) call capstan_formula(m, m%check%beam_a)
      write (*, '(a,i0,a,f8.3,a,f5.3,a,f9.6,a,i0,a,f9.6,a,es9.2)') trim(m%name) // ': check capstan: n = ', &
        n_corners, ' corners turning ', turn_total * 180.0_dp / pi, ' degrees, mu = ', m%contact%friction, &
        ': formula T_out/T_in = ', ratio_formula, '; computed at slip (step ', first_slip_step, ') ', ratio_first, &
        ', rel. error ', abs(ratio_first - ratio_formula) / ratio_formula
      write (*, '(a,i0,a,f9.6,a,es9.2)') '  slip steps checked ', n_checked, ', last ', ratio_last, &
        ', worst rel. error ', worst
      write (*, '(a,es9.2,a,es9.2,a,es9.2)') '  bending length sqrt(EI/T_in) ', &
        sqrt(bending_stiffness(m, m%check%beam_a) / max(t_in_last, tiny(1.0_dp))), ', shortest element of the rope ', &
        minval(m%el_l0(m%beam_first_el(m%check%beam_a):m%beam_first_el(m%check%beam_a) &
                       + m%beam_n_el(m%check%beam_a) - 1)), ', tolerance ', m%check%tolerance
      if (n_checked < 2) call fail('fewer than two steps with every contact in slip under the pull: no plateau')
    end select
    if (strand_kind(m%check%kind)) ok = strand_check_finish(m) .and. ok   ! demo_checks_strand
    passed = ok
    write (*, '(a)') trim(m%name) // ': check ' // trim(merge('PASSED', 'FAILED', ok))
  end function check_finish

end module demo_checks
