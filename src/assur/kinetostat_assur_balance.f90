!> Counterweight balancing of an &assur linkage (`kinetostat balance`): the counterweights
!> that make the shaking force vanish (full static balance by linearly independent vectors,
!> Berkof-Lowen), that put the crank's own centre of mass on its pivot, or that balance a
!> slider-crank's rotating mass and a fraction of its reciprocating mass. The result is a
!> list of deck assignments (the changed masses, moments of inertia and centres of mass of
!> the links that carry counterweights) and the lines of a report, in English or in Russian
!> (`--lang ru`: the course's words, противовес, уравновешивание, главный вектор сил
!> инерции).
!>
!> Full balance: the total first moment of mass sum m_i r_Si(phi1) must not change with the
!> crank angle. A link pivoted on the frame (its origin fixed) adds R(theta_i) w_i to it,
!> with w_i = m_i s_i its first moment in its own axes, and a mass at its pivot adds a
!> constant; so the w_i of those links and a constant C solve, in the least-squares sense
!> over a turn of the crank, sum_i R(theta_i) w_i - C = -(the rest of the first moment).
!> The loop closure of a four-bar makes the coupler's terms a combination of the crank's,
!> the rocker's and a constant (Berkof-Lowen), so there the residual vanishes; a link whose
!> origin moves on the frame (a slider) leaves a residual: full balance is impossible.
module kinetostat_assur_balance
  use kinetostat_kinds, only: wp, deg_to_rad, rad_to_deg
  use kinetostat_error, only: error_t, fatal_error, exit_usage, exit_geometry
  use kinetostat_text, only: int_str
  use kinetostat_labels, only: balance_words => in_language
  use kinetostat_override, only: override_t
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_counterweights, only: balance_full, balance_crank, balance_partial, balance_method_names, &
    fit_full_balance, report_full_balance, report_partial_balance, counterweight_note, add_counterweight_assignments
  use kinetostat_assur_kinematics, only: link_state_t, dyad_pose_t, kind_rrr, kind_rrp
  use kinetostat_assur, only: assur_kinematics, link_a, link_b
  use kinetostat_assur_deck, only: assur_deck_t, assur_phi1_deg
  implicit none
  private
  public :: assur_balance, balance_full, balance_crank, balance_partial, balance_method_names, balance_words

  !> Crank angles of the sample turn (every 5 deg).
  integer, parameter :: sample_count = 72
  !> A link's origin is fixed when it moves by at most this times the mechanism's size.
  real(wp), parameter :: fixed_rel = 1.0e-12_wp

contains

  !> The counterweights of `method` for the validated deck `deck`: the deck assignments
  !> that add them (each mass assignment carries the counterweight in a comment) and the
  !> report's lines (what each counterweight is; for the partial method the primary and
  !> secondary components of the shaking force before and after).
  pure subroutine assur_balance(deck, method, fraction, lang, overrides, report, error)
    !> The validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> balance_full, balance_crank or balance_partial.
    integer, intent(in) :: method
    !> Partial method: the fraction of the reciprocating mass balanced, 0..1.
    real(wp), intent(in) :: fraction
    !> Language of the report and of the comments in the deck (lang_en, lang_ru).
    integer, intent(in) :: lang
    !> The assignments (name, value in namelist syntax with the comment).
    type(override_t), allocatable, intent(out) :: overrides(:)
    !> The report's lines.
    type(text_buffer_t), intent(inout) :: report
    !> No balance of that kind exists for the deck (exit 3), or the deck does not fit the
    !> method (exit 1).
    type(error_t), allocatable, intent(out) :: error
    integer :: nl, i, d
    real(wp), allocatable :: w_new(:, :)
    logical, allocatable :: carries(:)
    real(wp) :: pin(2), m_rec, m_rot, share, omega

    allocate (overrides(0))
    nl = 2 * size(deck%mech%dyads) + 1
    allocate (w_new(2, nl), source=0.0_wp)
    allocate (carries(nl), source=.false.)
    select case (method)
    case (balance_crank)
      carries(1) = .true.
      call report%put(balance_words("crank balance: the crank's own centre of mass onto its pivot", &
        "уравновешивание кривошипа: центр масс кривошипа переносится на "// &
          "ось его вращения", lang))
    case (balance_partial)
      call slider_crank(deck, d, error)
      if (allocated(error)) return
      associate (rod => deck%mech%links(link_a(d)), slider => deck%mech%links(link_b(d)))
        pin = deck%mech%dyads(d)%at(:, 1)
        ! the rod as two masses: at the crank pin and at the slider's pin (static equivalent)
        share = rod%s(1) / deck%mech%dyads(d)%geom%l2
        m_rec = slider%m + rod%m * share
        m_rot = rod%m * (1.0_wp - share)
        w_new(:, 1) = -(m_rot + fraction * m_rec) * pin
        carries(1) = .true.
        omega = abs(deck%omega1_const)
        if (deck%prescribed) omega = abs(deck%omega1_values(1))
        call report_partial_balance(report, lang, " (dyad "//int_str(d)//")", " (диада "//int_str(d)//")", m_rot, &
          m_rec, fraction, share, norm2(pin), deck%mech%dyads(d)%geom%l2, omega)
      end associate
    case default
      call full_balance(deck, lang, w_new, carries, report, error)
      if (allocated(error)) return
    end select
    do i = 1, nl
      if (carries(i)) call add_counterweight(deck, i, w_new(:, i), method, lang, overrides, report, error)
      if (allocated(error)) return
    end do
    if (size(overrides) == 0) call report%put(balance_words("no counterweight needed: the deck is balanced already", &
      "противовесы не нужны: механизм уже уравновешен", lang))
  end subroutine assur_balance

  !> Full static balance: the first moments of the links pivoted on the frame.
  pure subroutine full_balance(deck, lang, w_new, carries, report, error)
    type(assur_deck_t), intent(in) :: deck
    !> Language of the report.
    integer, intent(in) :: lang
    !> New first moments (link axes), kg*m, of the links that carry counterweights.
    real(wp), intent(inout) :: w_new(:, :)
    !> Which links carry one.
    logical, intent(inout) :: carries(:)
    type(text_buffer_t), intent(inout) :: report
    type(error_t), allocatable, intent(out) :: error
    type(link_state_t), allocatable :: states(:, :)
    real(wp), allocatable :: x(:), moment(:, :), theta(:, :), own(:, :), mass(:)
    integer, allocatable :: pivoted(:)
    integer :: nl, ns, i, k, j, nu
    real(wp) :: size_scale

    call sample_states(deck, states, error)
    if (allocated(error)) return
    nl = size(carries)
    ns = size(states, 2)
    ! the first moment of mass at every sample, and the mechanism's size
    allocate (moment(2, ns), source=0.0_wp)
    size_scale = 0.0_wp
    do k = 1, ns
      do i = 1, nl
        associate (l => deck%mech%links(i), st => states(i, k))
          moment(:, k) = moment(:, k) + l%m * (st%o + turned(st%th, l%s))
          size_scale = max(size_scale, norm2(st%o))
        end associate
      end do
    end do
    if (.not. size_scale > 0.0_wp) size_scale = 1.0_wp
    allocate (pivoted(0))
    do i = 1, nl
      if (maxval(abs(states(i, :)%o(1) - states(i, 1)%o(1))) > fixed_rel * size_scale) cycle
      if (maxval(abs(states(i, :)%o(2) - states(i, 1)%o(2))) > fixed_rel * size_scale) cycle
      if (maxval(abs(cos(states(i, :)%th) - cos(states(i, 1)%th))) + &
          maxval(abs(sin(states(i, :)%th) - sin(states(i, 1)%th))) < 1.0e-9_wp) cycle
      pivoted = [pivoted, i]
    end do
    theta = states%th
    own = reshape([(deck%mech%links(i)%s, i = 1, nl)], [2, nl])
    mass = deck%mech%links(1:nl)%m
    call fit_full_balance(moment, theta, mass, own, pivoted, lang, report, w_new, carries, x, error)
    if (allocated(error) .or. .not. allocated(x)) return
    nu = size(x)
    ! C is the total first moment but for the counterweights' own m_c o (o: the fixed origin)
    do j = 1, size(pivoted)
      associate (l => deck%mech%links(pivoted(j)))
        x(nu - 1:nu) = x(nu - 1:nu) + norm2(x(2 * j - 1:2 * j) - l%m * l%s) / link_radius(deck, pivoted(j)) * &
          states(pivoted(j), 1)%o
      end associate
    end do
    call report_full_balance(report, lang, size(pivoted), x(nu - 1:nu) / total_mass())
  contains
    !> The mass of the moving links after balancing: the centre of mass C / M needs it.
    pure real(wp) function total_mass()
      integer :: q
      real(wp) :: extra(2)
      total_mass = 0.0_wp
      do q = 1, nl
        total_mass = total_mass + deck%mech%links(q)%m
      end do
      do q = 1, size(pivoted)
        associate (l => deck%mech%links(pivoted(q)))
          extra = x(2 * q - 1:2 * q) - l%m * l%s
          if (norm2(extra) > 0.0_wp) total_mass = total_mass + norm2(extra) / link_radius(deck, pivoted(q))
        end associate
      end do
    end function total_mass
  end subroutine full_balance

  !> Link frames over a turn of the crank from phi_start (72 angles), or over the deck's
  !> steps when the linkage does not assemble over a whole turn.
  pure subroutine sample_states(deck, states, error)
    type(assur_deck_t), intent(in) :: deck
    !> states(link, sample), links 1..2*nd+1.
    type(link_state_t), allocatable, intent(out) :: states(:, :)
    type(error_t), allocatable, intent(out) :: error
    type(link_state_t) :: st(0:2 * size(deck%mech%dyads) + 1)
    type(dyad_pose_t) :: poses(size(deck%mech%dyads))
    integer :: k, nl
    nl = 2 * size(deck%mech%dyads) + 1
    allocate (states(nl, sample_count))
    do k = 1, sample_count
      call assur_kinematics(deck%mech, (assur_phi1_deg(deck, 1) + 5.0_wp * real(k - 1, wp)) * deg_to_rad, st, &
                            poses, error)
      if (allocated(error)) exit
      states(:, k) = st(1:nl)
    end do
    if (.not. allocated(error)) return
    deallocate (error, states)
    allocate (states(nl, deck%n))
    do k = 1, deck%n
      call assur_kinematics(deck%mech, assur_phi1_deg(deck, k) * deg_to_rad, st, poses, error)
      if (allocated(error)) return
      states(:, k) = st(1:nl)
    end do
  end subroutine sample_states

  !> The slider-crank dyad of the partial method: the deck's only dyad, an RRP on the crank
  !> and a frame guide.
  pure subroutine slider_crank(deck, d, error)
    type(assur_deck_t), intent(in) :: deck
    integer, intent(out) :: d
    type(error_t), allocatable, intent(out) :: error
    d = 1
    if (size(deck%mech%dyads) == 1) then
      associate (dy => deck%mech%dyads(1))
        if (dy%geom%kind == kind_rrp .and. dy%on(1) == 1 .and. dy%on(2) == 0) return
      end associate
    end if
    call fatal_error(error, exit_usage, "--method partial balances a slider-crank: one RRP dyad (kind 2) "// &
      "hung on the crank (on2 = crank_id) and a guide on the frame (on3 = frame_id); use --method full or crank")
  end subroutine slider_crank

  !> The assignments of link `i`'s counterweight, for the new first moment `w` (link axes):
  !> a point mass at the link's radius on the side w - m*s points to.
  pure subroutine add_counterweight(deck, i, w, method, lang, overrides, report, error)
    type(assur_deck_t), intent(in) :: deck
    integer, intent(in) :: i
    real(wp), intent(in) :: w(2)
    integer, intent(in) :: method
    !> Language of the report and the deck's comment.
    integer, intent(in) :: lang
    type(override_t), allocatable, intent(inout) :: overrides(:)
    type(text_buffer_t), intent(inout) :: report
    type(error_t), allocatable, intent(out) :: error
    type(link_state_t), allocatable :: ref(:)
    type(dyad_pose_t) :: poses(size(deck%mech%dyads))
    real(wp) :: dw(2), radius, mc, c(2), m_new, s_new(2), j_new, s_deck(2), angle
    character(len=:), allocatable :: prefix, mname, jname, sname, note
    associate (l => deck%mech%links(i))
      dw = w - l%m * l%s
      if (norm2(dw) <= 1.0e-15_wp * max(norm2(w), norm2(l%m * l%s))) return
      radius = link_radius(deck, i)
      mc = norm2(dw) / radius
      c = radius * dw / norm2(dw)
      angle = atan2(c(2), c(1)) * rad_to_deg
      m_new = l%m + mc
      s_new = w / m_new
      j_new = l%j + l%m * sum((l%s - s_new)**2) + mc * sum((c - s_new)**2)
      s_deck = s_new
      if (deck%global) then
        ! the deck gives centres of mass as global points at phi_ref
        allocate (ref(0:2 * size(deck%mech%dyads) + 1))
        call assur_kinematics(deck%mech, deck%phi_ref * deg_to_rad, ref, poses, error)
        if (allocated(error)) return
        s_deck = ref(i)%o + turned(ref(i)%th, s_new)
      end if
      if (i == 1) then
        mname = "crank_m"
        jname = "crank_j"
        sname = "crank_s"
      else
        prefix = "dyad("//int_str(i / 2)//")%"
        mname = prefix//merge("m2", "m3", mod(i, 2) == 0)
        jname = prefix//merge("j2", "j3", mod(i, 2) == 0)
        sname = prefix//merge("s2", "s3", mod(i, 2) == 0)
      end if
      note = counterweight_note(lang, l%id, mc, radius, angle, "in the link's axes", "в осях звена")
      call add_counterweight_assignments(overrides, report, lang, method, note, &
        mname, jname, sname, l%m, m_new, l%j, j_new, l%s, s_new, s_deck, &
        " in the link's axes", " в осях звена")
    end associate
  end subroutine add_counterweight


  !> Where link `i` carries a counterweight: at the distance of its farthest joint from its
  !> origin (the crank radius for the crank), m; 0.1 m for a link without joints off its origin.
  pure real(wp) function link_radius(deck, i) result(radius)
    type(assur_deck_t), intent(in) :: deck
    integer, intent(in) :: i
    integer :: d, q
    radius = 0.0_wp
    do d = 1, size(deck%mech%dyads)
      associate (dy => deck%mech%dyads(d))
        do q = 1, 2
          if (dy%on(q) == i) radius = max(radius, norm2(dy%at(:, q)))
        end do
        if (i == link_a(d) .and. (dy%geom%kind == kind_rrr .or. dy%geom%kind == kind_rrp)) radius = max(radius, dy%geom%l2)
        if (i == link_b(d) .and. dy%geom%kind == kind_rrr) radius = max(radius, dy%geom%l3)
      end associate
    end do
    if (.not. radius > 0.0_wp) radius = 0.1_wp
  end function link_radius

  !> Vector `v` turned by `th` (rad).
  pure function turned(th, v) result(u)
    real(wp), intent(in) :: th, v(2)
    real(wp) :: u(2)
    u = [cos(th) * v(1) - sin(th) * v(2), sin(th) * v(1) + cos(th) * v(2)]
  end function turned

end module kinetostat_assur_balance
