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
  use kinetostat_format, only: full_number, short_number
  use kinetostat_labels, only: lang_ru, unit_symbol, balance_words => in_language
  use kinetostat_override, only: override_t, append_override
  use kinetostat_least_squares, only: least_squares
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_assur_kinematics, only: link_state_t, dyad_pose_t, kind_rrr, kind_rrp
  use kinetostat_assur, only: assur_kinematics, link_a, link_b
  use kinetostat_assur_deck, only: assur_deck_t, assur_phi1_deg
  implicit none
  private
  public :: assur_balance, balance_full, balance_crank, balance_partial, balance_method_names, balance_words

  !> --method full: the shaking force vanishes (Berkof-Lowen).
  integer, parameter :: balance_full = 1
  !> --method crank: the crank's own centre of mass on its pivot.
  integer, parameter :: balance_crank = 2
  !> --method partial: a slider-crank's rotating mass and a fraction of its reciprocating mass.
  integer, parameter :: balance_partial = 3
  !> The method names, in the order of their codes.
  character(*), parameter :: balance_method_names(*) = [character(len=7) :: "full", "crank", "partial"]

  !> Crank angles of the sample turn (every 5 deg).
  integer, parameter :: sample_count = 72
  !> Full balance exists when the least-squares residual of the first moment is at most this
  !> times its unbalanced variation.
  real(wp), parameter :: balance_rel = 1.0e-9_wp
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
    !> Units of the report.
    character(len=:), allocatable :: kg, m, n_unit

    kg = unit_symbol("kg", lang)
    m = unit_symbol("m", lang)
    n_unit = unit_symbol("N", lang)
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
        if (lang == lang_ru) then
          call report%put("частичное уравновешивание кривошипно-ползунного "// &
            "механизма (диада "//int_str(d)// &
            "): масса кривошипа, вращающаяся масса "//short_number(m_rot)//" "//kg//" и "// &
              "доля "// &
            short_number(fraction)//" возвратно-поступательно движущейся "// &
              "массы "//short_number(m_rec)//" "//kg// &
            " на радиусе кривошипа "//short_number(norm2(pin))//" "//m)
          call report%put("  (масса шатуна разнесена в две точки: доля "//short_number(share)// &
            " в шарнире ползуна)")
          call report%put("  сила инерции первого порядка (первая гармоника, "// &
            "m_rec*r*omega1^2 = "// &
            short_number(m_rec * norm2(pin) * omega**2)//" "//n_unit//" при omega1 = "//short_number(omega)//" "// &
            unit_symbol("rad/s", lang)//"): вдоль направляющей "//short_number(m_rec * norm2(pin) * omega**2)// &
            " "//n_unit//" до "// &
              "уравновешивания, "//short_number((1.0_wp - fraction) * m_rec * norm2(pin) * omega**2)// &
            " "//n_unit//" после; поперек направляющей 0 до, "// &
            short_number(fraction * m_rec * norm2(pin) * omega**2)//" "//n_unit//" после")
          call report%put("  сила инерции второго порядка (вторая гармоника, "// &
            "m_rec*r*omega1^2*r/l): "// &
            short_number(m_rec * norm2(pin) * omega**2 * norm2(pin) / deck%mech%dyads(d)%geom%l2)//" "//n_unit// &
            " вдоль направляющей, не меняется (противовес на кривошипе "// &
              "вращается с угловой скоростью omega1)")
        else
          call report%put("partial balance of the slider-crank (dyad "//int_str(d)//"): the crank's own mass, the "// &
            "rotating mass "//short_number(m_rot)//" kg and "//short_number(fraction)//" of the reciprocating mass "// &
            short_number(m_rec)//" kg at the crank radius "//short_number(norm2(pin))//" m")
          call report%put("  (rod as two masses: "//short_number(share)//" of it at the slider's pin)")
          call report%put("  primary component (first harmonic, m_rec*r*omega1^2 = "// &
            short_number(m_rec * norm2(pin) * omega**2)//" N at omega1 = "//short_number(omega)//" rad/s): along the "// &
            "guide "//short_number(m_rec * norm2(pin) * omega**2)//" N before, "// &
            short_number((1.0_wp - fraction) * m_rec * norm2(pin) * omega**2)//" N after; across the guide 0 before, "// &
            short_number(fraction * m_rec * norm2(pin) * omega**2)//" N after")
          call report%put("  secondary component (second harmonic, m_rec*r*omega1^2*r/l): "// &
            short_number(m_rec * norm2(pin) * omega**2 * norm2(pin) / deck%mech%dyads(d)%geom%l2)// &
            " N along the guide, unchanged (a crank counterweight turns at omega1 only)")
        end if
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
    real(wp), allocatable :: a(:, :), b(:), x(:), moment(:, :)
    integer, allocatable :: pivoted(:)
    integer :: nl, ns, i, k, j, nu
    real(wp) :: size_scale, mean(2), unbalanced, residual, r(2)

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
    mean = sum(moment, dim=2) / real(ns, wp)
    unbalanced = 0.0_wp
    do k = 1, ns
      unbalanced = max(unbalanced, norm2(moment(:, k) - mean))
    end do
    allocate (pivoted(0))
    do i = 1, nl
      if (maxval(abs(states(i, :)%o(1) - states(i, 1)%o(1))) > fixed_rel * size_scale) cycle
      if (maxval(abs(states(i, :)%o(2) - states(i, 1)%o(2))) > fixed_rel * size_scale) cycle
      if (maxval(abs(cos(states(i, :)%th) - cos(states(i, 1)%th))) + &
          maxval(abs(sin(states(i, :)%th) - sin(states(i, 1)%th))) < 1.0e-9_wp) cycle
      pivoted = [pivoted, i]
    end do
    if (.not. unbalanced > 0.0_wp) then
      call report%put(balance_words("full balance: the total centre of mass does not move (nothing to balance)", &
        "полное статическое уравновешивание: общий центр масс "// &
          "неподвижен (уравновешивать нечего)", lang))
      return
    end if
    ! unknowns: w of each pivoted link (x, y), then the constant C (x, y)
    nu = 2 * size(pivoted) + 2
    allocate (a(2 * ns, nu), b(2 * ns), x(nu))
    do k = 1, ns
      b(2 * k - 1:2 * k) = -moment(:, k)
      do j = 1, size(pivoted)
        i = pivoted(j)
        associate (l => deck%mech%links(i), st => states(i, k))
          b(2 * k - 1:2 * k) = b(2 * k - 1:2 * k) + l%m * turned(st%th, l%s)
          a(2 * k - 1:2 * k, 2 * j - 1) = turned(st%th, [1.0_wp, 0.0_wp])
          a(2 * k - 1:2 * k, 2 * j) = turned(st%th, [0.0_wp, 1.0_wp])
        end associate
      end do
      a(2 * k - 1:2 * k, nu - 1) = [-1.0_wp, 0.0_wp]
      a(2 * k - 1:2 * k, nu) = [0.0_wp, -1.0_wp]
    end do
    call least_squares(a, b, x, error)
    if (allocated(error)) then
      call fatal_error(error, exit_geometry, "full balance: the counterweights are not determined (the links "// &
        "pivoted on the frame move together); balance the crank alone (--method crank)")
      return
    end if
    residual = 0.0_wp
    do k = 1, ns
      r = -moment(:, k)
      do j = 1, size(pivoted)
        associate (l => deck%mech%links(pivoted(j)), st => states(pivoted(j), k))
          r = r + l%m * turned(st%th, l%s) - turned(st%th, x(2 * j - 1:2 * j))
        end associate
      end do
      residual = max(residual, norm2(r + x(nu - 1:nu)))
    end do
    if (residual > balance_rel * unbalanced) then
      call fatal_error(error, exit_geometry, "full balance is impossible: counterweights on the links pivoted on "// &
        "the frame leave "//short_number(residual / unbalanced * 100.0_wp)//" % of the centre of mass's travel "// &
        "(a link whose origin moves, such as a slider on the frame, cannot be balanced by them); "// &
        "use --method partial [--fraction F] (a slider-crank) or --method crank")
      return
    end if
    do j = 1, size(pivoted)
      w_new(:, pivoted(j)) = x(2 * j - 1:2 * j)
      carries(pivoted(j)) = .true.
    end do
    ! C is the total first moment but for the counterweights' own m_c o (o: the fixed origin)
    do j = 1, size(pivoted)
      associate (l => deck%mech%links(pivoted(j)))
        x(nu - 1:nu) = x(nu - 1:nu) + norm2(x(2 * j - 1:2 * j) - l%m * l%s) / link_radius(deck, pivoted(j)) * &
          states(pivoted(j), 1)%o
      end associate
    end do
    call report%put(balance_words("full balance (linearly independent vectors): counterweights on the "// &
      int_str(size(pivoted))//" links pivoted on the frame; the total centre of mass stays at (", &
      "полное статическое уравновешивание (метод линейно независимых "// &
        "векторов): противовесы на "// &
      int_str(size(pivoted))//" звеньях, вращающихся вокруг неподвижных осей; "// &
        "общий центр масс неподвижен в точке (", &
      lang)//short_number(x(nu - 1) / total_mass()) //", "//short_number(x(nu) / total_mass())//") "// &
      unit_symbol("m", lang))
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
        prefix = "crank_"
        mname = "crank_m"
        jname = "crank_j"
        sname = "crank_s"
      else
        prefix = "dyad("//int_str(i / 2)//")%"
        mname = prefix//merge("m2", "m3", mod(i, 2) == 0)
        jname = prefix//merge("j2", "j3", mod(i, 2) == 0)
        sname = prefix//merge("s2", "s3", mod(i, 2) == 0)
      end if
      if (lang == lang_ru) then
        note = "противовес на звене "//int_str(l%id)//": "//short_number(mc)//" "//unit_symbol("kg", lang)// &
          " на радиусе r = "//short_number(radius)//" "//unit_symbol("m", lang)//", "//short_number(angle)//" "// &
          unit_symbol("deg", lang)//" в осях звена (m*r = "//short_number(mc * radius)//" "// &
          unit_symbol("kg", lang)//"·"//unit_symbol("m", lang)//")"
      else
        note = "counterweight on link "//int_str(l%id)//": "//short_number(mc)//" kg at r = "// &
          short_number(radius)//" m, "//short_number(angle)//" deg in the link's axes (m*r = "// &
          short_number(mc * radius)//" kg*m)"
      end if
      call append_override(overrides, mname, full_number(m_new)//"   ! "//note//"; kinetostat balance --method "// &
        trim(balance_method_names(method)))
      call append_override(overrides, jname, full_number(j_new))
      call append_override(overrides, sname, full_number(s_deck(1))//", "//full_number(s_deck(2)))
      call report%put(note)
      call report%put("  "//mname//" "//short_number(l%m)//" -> "//short_number(m_new)//" "// &
        unit_symbol("kg", lang)//", "//jname//" "//short_number(l%j)//" -> "//short_number(j_new)//" "// &
        unit_symbol("kg*m^2", lang)//balance_words(", centre of mass (", ", центр масс (", lang)// &
        short_number(l%s(1))//", "//short_number(l%s(2))//") -> ("//short_number(s_new(1))//", "// &
        short_number(s_new(2))//") "//unit_symbol("m", lang)//balance_words(" in the link's axes", " в осях звена", lang))
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
