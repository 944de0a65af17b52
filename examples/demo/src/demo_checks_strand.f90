!> The checks of the line-contact scenes (issue 18, item 5), called from
!> demo_checks with one line per kind; the verdict joins the others'.
!>
!>  strand        a 1+n strand pressed radially: beam_a the centre wire,
!>                every other beam an outer wire loaded towards the axis
!>                of beam_a. Per outer wire k, C_k = the line contacts'
!>                integrated normal force with the centre, S_k the mean
!>                over its two neighbours. Closed form (equal outer wires
!>                on a circle, n-fold symmetric; the centre held; one
!>                penalty per unit length eps_L for every pair): the outer
!>                wire moves in by u, the centre contact closes by u, the
!>                neighbour contact by 2 u s, s = sin(pi/n); with the
!>                initial overlaps d_C, d_S and the load F per wire,
!>                    F = C + 2 s S,   C = eps_L L (d_C + u),
!>                    S = eps_L L max(0, d_S + 2 s u),
!>                so u = (F/(eps_L L) - d_C - 2 s d_S) / (1 + 4 s^2) while
!>                the neighbours touch (else S = 0, C = F). Checked at
!>                every step within tolerance: every C_k and S_k against
!>                the closed form, and the resultant of the contact forces
!>                on beam_a below tolerance * F.
module demo_checks_strand
  use demo_kinds, only: dp, pi
  use demo_model, only: scene_model, external_force
  use demo_history, only: step_row
  use demo_contact_report, only: contact_snapshot
  use demo_errors, only: str
  implicit none
  private
  public :: strand_kind, strand_check_step, strand_check_finish

  logical, save :: ok = .true.
  integer, save :: n_checked = 0
  real(dp), save :: worst_c = 0.0_dp, worst_s = 0.0_dp, worst_res = 0.0_dp, worst_spread = 0.0_dp
  ! double_helix
  real(dp), save :: last_bound = 0.0_dp, phi_prev = 0.0_dp, worst_ax = 0.0_dp, last_phi = 0.0_dp
  real(dp), save :: last_u(3) = 0.0_dp, last_ucf(3) = 0.0_dp
  ! arc_slide
  integer, save :: n_line_steps = 0, n_point_steps = 0, total_cut = 0, max_lost = 0, min_active = huge(1)
  real(dp), save :: worst_f = 0.0_dp, angle_min = huge(1.0_dp), angle_max = -huge(1.0_dp), first_f = 0.0_dp, first_cf = 0.0_dp
  real(dp), save :: last_c = 0.0_dp, last_s = 0.0_dp, last_cf = 0.0_dp, last_sf = 0.0_dp, last_f = 0.0_dp

contains

  !> .true. for the kinds this module checks.
  logical function strand_kind(kind)
    character(len=*), intent(in) :: kind
    strand_kind = any(trim(kind) == [character(len=16) :: 'strand', 'arc_slide', 'double_helix'])
  end function strand_kind

  subroutine fail(msg)
    character(len=*), intent(in) :: msg
    write (*, '(a)') '  CHECK FAILED: ' // msg
    ok = .false.
  end subroutine fail

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

  !> Distance of point p from the line through q along unit vector e.
  real(dp) function line_distance(p, q, e) result(d)
    real(dp), intent(in) :: p(3), q(3), e(3)
    real(dp) :: w(3)
    w = p - q
    d = norm2(w - dot_product(w, e) * e)
  end function line_distance

  !> The line-penalty of the scene's &contact (option line_penalty).
  real(dp) function line_penalty(m) result(eps)
    type(scene_model), intent(in) :: m
    eps = option_real(m, 'line_penalty', 0.0_dp)
  end function line_penalty

  !> A library option of the scene's &contact, or its default.
  real(dp) function option_real(m, key, default) result(v)
    type(scene_model), intent(in) :: m
    character(len=*), intent(in) :: key
    real(dp), intent(in) :: default
    integer :: k
    v = default
    do k = 1, m%contact%n_options
      if (trim(m%contact%option_key(k)) == key) v = m%contact%option_value(k)
    end do
  end function option_real

  !> Called after every converged planned step (for the kinds of strand_kind).
  subroutine strand_check_step(m, row, snap, fint)
    type(scene_model), intent(in) :: m
    type(step_row), intent(in) :: row
    type(contact_snapshot), intent(in) :: snap
    real(dp), intent(in) :: fint(:, :)
    select case (trim(m%check%kind))
    case ('strand'); call strand_step(m, row, snap)
    case ('arc_slide'); call arc_step(m, row, snap)
    case ('double_helix'); call helix_step(m, row)
    end select
    if (.false.) write (*, *) size(fint)
  end subroutine strand_check_step

  subroutine strand_step(m, row, snap)
    type(scene_model), intent(in) :: m
    type(step_row), intent(in) :: row
    type(contact_snapshot), intent(in) :: snap
    integer :: n_out, k, b, j, other, i
    integer, allocatable :: outer(:)
    real(dp), allocatable :: c(:), s(:)
    real(dp) :: q(3), e(3), ring, f, eps, len, rc, ro, d_c, d_s, sn, u, c_cf, s_cf, res(3), sign_a, spread, err_c, err_s
    real(dp) :: pk(3), pn(3)
    associate (ba => m%check%beam_a, tol => m%check%tolerance)
      n_out = m%n_beams - 1
      outer = pack([(b, b = 1, m%n_beams)], [(b, b = 1, m%n_beams)] /= ba)
      allocate (c(n_out), s(n_out))
      ! the geometry of the initial configuration: axis of the centre wire,
      ! ring radius of the outer wires (from their first nodes), radii
      q = m%x0(:, m%beam_first_node(ba))
      e = m%x0(:, m%beam_first_node(ba) + m%beam_n_nodes(ba) - 1) - q
      len = norm2(e)
      e = e / len
      ring = line_distance(m%x0(:, m%beam_first_node(outer(1))), q, e)
      rc = m%beam_radius(ba)
      ro = m%beam_radius(outer(1))
      sn = sin(pi / real(n_out, dp))
      d_c = rc + ro - ring
      d_s = 2.0_dp * ro - 2.0_dp * ring * sn
      f = norm2(beam_load(m, outer(1), row%lam))
      eps = line_penalty(m)
      u = (f / (eps * len) - d_c - 2.0_dp * sn * d_s) / (1.0_dp + 4.0_dp * sn**2)
      if (d_s + 2.0_dp * sn * u <= 0.0_dp) u = f / (eps * len) - d_c   ! the neighbours do not touch
      c_cf = eps * len * (d_c + u)
      s_cf = eps * len * max(0.0_dp, d_s + 2.0_dp * sn * u)
      ! the model: per outer wire the force with the centre and with the neighbours
      c = 0.0_dp
      s = 0.0_dp
      res = 0.0_dp
      do i = 1, snap%n
        associate (ct => snap%c(i))
          if (ct%pair(1) == ba .or. ct%pair(3) == ba) then
            other = merge(ct%pair(3), ct%pair(1), ct%pair(1) == ba)
            sign_a = merge(1.0_dp, -1.0_dp, ct%pair(1) == ba)   ! the normal points from B to A
            res = res + sign_a * ct%info(13) * ct%info(9:11)
            do k = 1, n_out
              if (outer(k) == other) c(k) = c(k) + ct%info(13)
            end do
          else
            do k = 1, n_out
              if (outer(k) == ct%pair(1) .or. outer(k) == ct%pair(3)) s(k) = s(k) + 0.5_dp * ct%info(13)
            end do
          end if
        end associate
      end do
      ! outer wires must each have two neighbours for the mean (a ring)
      do k = 1, n_out
        pk = m%x0(:, m%beam_first_node(outer(k)))
        j = 0
        do b = 1, n_out
          if (b == k) cycle
          pn = m%x0(:, m%beam_first_node(outer(b)))
          if (norm2(pk - pn) < 2.0_dp * ring * sn * (1.0_dp + 1.0e-6_dp)) j = j + 1
        end do
        if (j /= 2) call fail('outer wire (beam ' // str(outer(k)) // ') does not have two neighbours at the ring ' &
                              // 'spacing: not a symmetric strand')
      end do
      n_checked = n_checked + 1
      err_c = maxval(abs(c - c_cf)) / f
      err_s = maxval(abs(s - s_cf)) / f
      spread = (maxval(c) - minval(c)) / f
      worst_c = max(worst_c, err_c)
      worst_s = max(worst_s, err_s)
      worst_spread = max(worst_spread, spread)
      worst_res = max(worst_res, norm2(res) / f)
      write (*, '(4x,a,es12.5,a,es12.5,a,es12.5,a,es12.5,a,es12.5,a,es12.5,a,es9.2,a,es9.2,a,es9.2)') 'check: load per wire ', f, &
        '  centre contacts ', minval(c), ' .. ', maxval(c), '  closed form ', c_cf, '  neighbours ', sum(s) / n_out, &
        '  closed form ', s_cf, '  rel. errors ', err_c, ', ', err_s, '  centre resultant / F ', norm2(res) / f
      if (err_c > tol) call fail('step ' // str(row%step) // ': a centre contact force off the closed form')
      if (err_s > tol) call fail('step ' // str(row%step) // ': a neighbour contact force off the closed form')
      if (norm2(res) > tol * f) call fail('step ' // str(row%step) // ': the centre wire''s contact resultant ' &
                                          // 'is not zero')
      last_c = sum(c) / n_out
      last_s = sum(s) / n_out
      last_cf = c_cf
      last_sf = s_cf
      last_f = f
    end associate
  end subroutine strand_step

  !> The circle through the first, middle and last initial nodes of beam b.
  subroutine beam_circle(m, b, c, r, a)
    type(scene_model), intent(in) :: m
    integer, intent(in) :: b
    real(dp), intent(out) :: c(3), r, a(3)
    real(dp) :: p1(3), p2(3), p3(3), u(3), v(3), w(3), uu, vv, uv
    p1 = m%x0(:, m%beam_first_node(b))
    p2 = m%x0(:, m%beam_first_node(b) + (m%beam_n_nodes(b) - 1) / 2)
    p3 = m%x0(:, m%beam_first_node(b) + m%beam_n_nodes(b) - 1)
    u = p2 - p1
    v = p3 - p1
    w = cross(u, v)
    a = w / norm2(w)
    uu = dot_product(u, u); vv = dot_product(v, v); uv = dot_product(u, v)
    c = p1 + (uu * vv - vv * uv) / (2.0_dp * dot_product(w, w)) * u + (vv * uu - uu * uv) / (2.0_dp * dot_product(w, w)) * v
    r = norm2(p1 - c)
  end subroutine beam_circle

  pure function cross(a, b) result(c)
    real(dp), intent(in) :: a(3), b(3)
    real(dp) :: c(3)
    c = [a(2) * b(3) - a(3) * b(2), a(3) * b(1) - a(1) * b(3), a(1) * b(2) - a(2) * b(1)]
  end function cross

  !> arc_slide: beam_a, straight and horizontal (normal to its load P),
  !> pressed onto the fixed circular arc beam_b (radius R in a plane
  !> containing P, axis e_y, centre c) and moved over it. With X the
  !> horizontal position of beam_a's middle node in the arc's plane, psi the
  !> angle of beam_a to that plane, rho = r_a + r_b, the contact on the
  !> arc at angle phi from the top solves
  !>     X = R sin(phi) + rho tan(phi) / (sin(psi) sqrt(sin(psi)^2 + tan(phi)^2))
  !> and the frictionless contact force balancing P is
  !>     f_N = P sqrt(1 + tan(phi)^2 / sin(psi)^2)
  !> (psi = 90 degrees: sin(phi) = X/(R + rho), f_N = P/cos(phi); psi -> 0:
  !> phi -> 0, f_N -> P).
  subroutine arc_step(m, row, snap)
    type(scene_model), intent(in) :: m
    type(step_row), intent(in) :: row
    type(contact_snapshot), intent(in) :: snap
    real(dp) :: c(3), rad, ey(3), ez(3), ex(3), p(3), pm(3), d(3), sp, x, rho, lo, hi, phi, g, f_cf, f_model, err, pl
    integer :: k, it, n_line
    associate (ba => m%check%beam_a, bb => m%check%beam_b, tol => m%check%tolerance)
      call beam_circle(m, bb, c, rad, ey)
      p = beam_load(m, ba, row%lam)
      pl = norm2(p)
      ez = -p / pl
      ex = cross(ey, ez)
      ex = ex / norm2(ex)
      pm = m%x(:, m%beam_first_node(ba) + (m%beam_n_nodes(ba) - 1) / 2)
      d = m%x(:, m%beam_first_node(ba) + m%beam_n_nodes(ba) - 1) - m%x(:, m%beam_first_node(ba))
      d = d / norm2(d)
      sp = abs(dot_product(d, ey))
      x = dot_product(pm - c, ex)
      rho = m%beam_radius(ba) + m%beam_radius(bb)
      phi = 0.0_dp
      f_cf = pl
      if (sp > 1.0e-6_dp) then
        lo = -1.5_dp
        hi = 1.5_dp
        do it = 1, 200
          phi = 0.5_dp * (lo + hi)
          g = rad * sin(phi) + rho * tan(phi) / (sp * sqrt(sp**2 + tan(phi)**2))
          if (g > x) then
            hi = phi
          else
            lo = phi
          end if
        end do
        f_cf = pl * sqrt(1.0_dp + tan(phi)**2 / sp**2)
      end if
      f_model = 0.0_dp
      do k = 1, snap%n
        f_model = f_model + snap%c(k)%info(13)
        angle_min = min(angle_min, snap%c(k)%info(15))
        angle_max = max(angle_max, snap%c(k)%info(15))
      end do
      n_line = snap%counts(16)
      ! the regime of the all-angle blend by the contacts' crossing angles
      if (any(snap%c(1:snap%n)%info(15) <= option_real(m, 'line_angle', 5.0_dp))) n_line_steps = n_line_steps + 1
      if (any(snap%c(1:snap%n)%info(15) >= option_real(m, 'point_angle', 15.0_dp))) n_point_steps = n_point_steps + 1
      total_cut = total_cut + row%cutbacks
      max_lost = max(max_lost, snap%counts(12))
      min_active = min(min_active, snap%n)
      err = abs(f_model - f_cf) / f_cf
      worst_f = max(worst_f, err)
      n_checked = n_checked + 1
      if (n_checked == 1) then
        first_f = f_model
        first_cf = f_cf
      end if
      last_f = f_model
      last_cf = f_cf
      write (*, '(4x,a,f7.2,a,f8.4,a,f7.3,a,i0,a,i0,a,i0,a,es13.6,a,es13.6,a,es9.2)') 'check: psi ', &
        asin(min(sp, 1.0_dp)) * 180.0_dp / pi, '  X ', x, '  phi ', phi * 180.0_dp / pi, '  contacts ', snap%n, &
        ' (line ', n_line, ', lost ', snap%counts(12), ')  f_N ', f_model, '  closed form ', f_cf, '  rel. error ', err
      if (err > tol) call fail('step ' // str(row%step) // ': contact force off the closed form')
      if (snap%n == 0) call fail('step ' // str(row%step) // ': no active contact')
      if (snap%counts(12) > 0) call fail('step ' // str(row%step) // ': B2B_COUNT_LOST = ' // str(snap%counts(12)))
      if (row%cutbacks > 0) call fail('step ' // str(row%step) // ': ' // str(row%cutbacks) // ' cut-back(s)')
    end associate
  end subroutine arc_step

  !> double_helix: beam_a and beam_b, parallel and touching, their first
  !> ends held, their last ends turned about the common axis by Phi (and
  !> pulled along it by N each, free to move along it). If they stay in
  !> contact along their length, both lie on a helix of radius
  !> r_h = (r_a + r_b + g)/2 about the axis (g the gap of the contact law,
  !> 0 .. regularization_gap: taken as half of it), turning by Phi over the
  !> axial length h; arc length L_s = L (1 + N_t/EA) with N_t = N / cos(beta)
  !> the tension along the rod, so h = sqrt(L_s^2 - (r_h Phi)^2). By the
  !> symmetry of the pair (half-turn about the axis through the middle at
  !> angle Phi/2), the middle node of beam_a lies at angle Phi/2, radius
  !> r_h, axial position h/2: its displacement is
  !>     u = (h - L)/2 e + r_h (cos(Phi/2) e_r + sin(Phi/2) e_t) - r_0 e_r.
  !> Checked from a turn of 1 rad on (before, the contact pressure is too
  !> small to hold the rods on the helix): |u - u_cf| <= tolerance |u_cf|
  !> + regularization_gap/4, and the shortening by the twist (L_s - h)/2
  !> within 2 sqrt(EI/N_t)/L (the bending boundary layers at the ends) +
  !> regularization_gap/r_h (the gap's range in r_h^2).
  subroutine helix_step(m, row)
    type(scene_model), intent(in) :: m
    type(step_row), intent(in) :: row
    real(dp) :: q(3), e(3), er(3), et(3), len, rh, r0, w(3), phi, dphi, n_ax, ea, ls, h, cb, u(3), ucf(3), err, err_ax
    real(dp) :: s_cf, s_mod, bound_ax
    integer :: it, mid
    associate (ba => m%check%beam_a, bb => m%check%beam_b, tol => m%check%tolerance)
      q = 0.5_dp * (m%x0(:, m%beam_first_node(ba)) + m%x0(:, m%beam_first_node(bb)))
      e = m%x0(:, m%beam_first_node(ba) + m%beam_n_nodes(ba) - 1) - m%x0(:, m%beam_first_node(ba))
      len = norm2(e)
      e = e / len
      er = m%x0(:, m%beam_first_node(ba)) - q
      er = er - dot_product(er, e) * e
      r0 = norm2(er)
      er = er / r0
      et = cross(e, er)
      rh = 0.5_dp * (m%beam_radius(ba) + m%beam_radius(bb) + 0.5_dp * m%contact%regularization_gap)
      ! the turn of the last end, continued from the last step
      w = m%x(:, m%beam_first_node(ba) + m%beam_n_nodes(ba) - 1) - q
      phi = atan2(dot_product(w, et), dot_product(w, er))
      dphi = modulo(phi - phi_prev + pi, 2.0_dp * pi) - pi
      phi = phi_prev + dphi
      phi_prev = phi
      n_ax = dot_product(beam_load(m, ba, row%lam), e)
      ea = m%el_stiff(1, m%beam_first_el(ba))
      cb = 1.0_dp
      do it = 1, 20
        ls = len * (1.0_dp + n_ax / (ea * cb))
        h = sqrt(ls**2 - (rh * phi)**2)
        cb = h / ls
      end do
      ucf = 0.5_dp * (h - len) * e + rh * (cos(0.5_dp * phi) * er + sin(0.5_dp * phi) * et) - r0 * er
      mid = m%beam_first_node(ba) + (m%beam_n_nodes(ba) - 1) / 2
      u = m%x(:, mid) - m%x0(:, mid)
      err = norm2(u - ucf) / norm2(ucf)
      ! the shortening by the twist alone at the middle, (L_s - h)/2, model and closed form
      s_cf = 0.5_dp * (ls - h)
      s_mod = 0.5_dp * (ls - len) - dot_product(u, e)
      err_ax = abs(s_mod - s_cf) / s_cf
      ! its bound: bending boundary layers sqrt(EI/N_t) at both ends, and the gap's range in r_h^2
      bound_ax = 2.0_dp * sqrt(m%el_stiff(3, m%beam_first_el(ba)) * cb / n_ax) / len &
                 + m%contact%regularization_gap / rh
      n_checked = n_checked + 1
      if (abs(phi) >= 1.0_dp) worst_f = max(worst_f, err)
      if (abs(phi) >= 1.0_dp) worst_ax = max(worst_ax, err_ax)
      last_bound = bound_ax
      last_u = u
      last_ucf = ucf
      last_phi = phi
      write (*, '(4x,a,f9.3,a,3es13.5,a,3es13.5,a,es9.2,a,es10.3,a,es10.3,a,es9.2,a,es9.2)') 'check: turn ', &
        phi * 180.0_dp / pi, ' deg  middle u ', u, '  closed form ', ucf, '  rel. error ', err, &
        '  twist shortening ', s_mod, ' closed form ', s_cf, ' rel. error ', err_ax, ' bound ', bound_ax
      if (abs(phi) >= 1.0_dp .and. norm2(u - ucf) > tol * norm2(ucf) + 0.25_dp * m%contact%regularization_gap) &
        call fail('step ' // str(row%step) // ': the middle node off the helix by more than the tolerance')
      if (abs(phi) >= 1.0_dp .and. err_ax > bound_ax) call fail('step ' // str(row%step) // ': the twist ' &
          // 'shortening off the closed form by more than its bound')
    end associate
  end subroutine helix_step

  !> Prints the summary of the scene's check; .false. if any part failed.
  logical function strand_check_finish(m) result(passed)
    type(scene_model), intent(in) :: m
    select case (trim(m%check%kind))
    case ('strand')
      if (n_checked == 0) call fail('no step checked')
      write (*, '(a,es13.6,a,es13.6,a,es13.6,a,es13.6,a,es13.6,a)') trim(m%name) // ': check strand: load per wire ', &
        last_f, ', centre contact ', last_c, ' (closed form ', last_cf, '), neighbour contact ', last_s, &
        ' (closed form ', last_sf, ')'
      write (*, '(a,i0,a,es9.2,a,es9.2,a,es9.2,a,es9.2,a,es9.2)') '  steps checked ', n_checked, &
        ', worst rel. error centre ', worst_c, ', neighbours ', worst_s, ', spread of the six ', worst_spread, &
        ', centre resultant / F ', worst_res, ', tolerance ', m%check%tolerance
    case ('double_helix')
      if (n_checked == 0) call fail('no step checked')
      write (*, '(a,f9.3,a,3es13.5,a,3es13.5,a)') trim(m%name) // ': check double_helix: turn ', &
        last_phi * 180.0_dp / pi, ' degrees, middle node u ', last_u, ' (closed form ', last_ucf, ')'
      write (*, '(a,i0,a,es9.2,a,es9.2,a,es9.2,a,es9.2,a)') '  steps checked ', n_checked, ', worst rel. error ', &
        worst_f, ' (tolerance ', m%check%tolerance, ' + regularization_gap/4 absolute); twist shortening worst ', &
        worst_ax, ' (bound 2 sqrt(EI/N)/L + g0/r_h = ', last_bound, ', turns from 1 rad)'
    case ('arc_slide')
      if (n_checked == 0) call fail('no step checked')
      write (*, '(a,es13.6,a,es13.6,a,es13.6,a,es13.6,a,es9.2,a,es9.2)') trim(m%name) // ': check arc_slide: f_N first ', &
        first_f, ' (closed form ', first_cf, '), last ', last_f, ' (closed form ', last_cf, '); worst rel. error ', &
        worst_f, ', tolerance ', m%check%tolerance
      write (*, '(a,i0,a,i0,a,i0,a,i0,a,i0,a,f6.2,a,f6.2,a)') '  steps ', n_checked, ', cut-backs ', total_cut, &
        ', B2B_COUNT_LOST at most ', max_lost, ', steps with a contact below line_angle ', n_line_steps, ', above point_angle ', &
        n_point_steps, ', crossing angles ', angle_min, ' .. ', angle_max, ' degrees'
      if (n_line_steps == 0 .or. n_point_steps == 0) call fail('the motion did not pass from point contact ' &
        // '(above point_angle) to line contact (below line_angle)')
      if (min_active == 0) call fail('a step without contact')
    end select
    passed = ok
  end function strand_check_finish

end module demo_checks_strand
