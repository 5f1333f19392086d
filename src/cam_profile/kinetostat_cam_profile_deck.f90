!> `&cam_profile` decks: reading, validation and the commented template. The law of motion
!> as segments law(i), beta(i), lift(i) over one turn; the follower; its limits; the cam's
!> speed and the output step; and, for --format deck only, the guide and the load of the
!> `&cam` deck it writes.
module kinetostat_cam_profile_deck
  use kinetostat_kinds, only: wp, deg_to_rad
  use kinetostat_error, only: error_t
  use kinetostat_text, only: real_str, int_str
  use kinetostat_deck, only: begin_group, text_bytes, text_chars, deck_context_t, unset_real, deck_source_t, namelist_probe_t, &
    is_set, optional_default, max_steps, deck_rules_t
  use kinetostat_cam_profile, only: cam_design_t, cam_segment_t, law_names, law_dwell, follower_names, &
    follower_flat, follower_roller, follower_oscillating
  implicit none
  private
  public :: cam_profile_deck_t, read_cam_profile_deck, cam_profile_template, max_segments

  !> Largest number of segments.
  integer, parameter :: max_segments = 50

  !> A validated `&cam_profile` deck.
  type :: cam_profile_deck_t
    !> The cam as designed (its size is found by the run).
    type(cam_design_t) :: design
    !> Output step, deg, and the number of output angles (0 .. 360 deg).
    real(wp) :: step = 0.0_wp
    integer :: n = 0
    !> The lifts and the pressure-angle limits as given (m or deg; deg).
    real(wp), allocatable :: lift_given(:)
    real(wp) :: limit_rise_deg = 0.0_wp, limit_return_deg = 0.0_wp
    !> For --format deck: the guide length, overhang, guide friction, load and cam friction of
    !> the `&cam` deck; which were given.
    real(wp) :: l = 0.0_wp, l_over = 0.0_wp, f = 0.0_wp, f2 = 0.0_wp, f_cam = 0.0_wp
    logical :: has_guide(4) = .false.
    logical :: has_f_cam = .false.
  end type cam_profile_deck_t

  !> Template deck, one line per entry.
  character(*), parameter :: cam_profile_template(*) = [character(len=100) :: &
    "! kinetostat deck: a disc cam for a follower's law of motion (its profile and size).", &
    "! Segments over one turn (beta adds up to 360 deg, the lifts to 0). Lengths m, angles deg.", &
    "&cam_profile", &
    "  law   = 'cycloidal', 'dwell', 'harmonic', 'dwell'  ! dwell, constant_velocity, parabolic,", &
    "                                   ! harmonic, cycloidal, poly345", &
    "  beta  = 120, 60, 120, 60         ! deg, cam angle of each segment, > 0", &
    "  lift  = 0.02, 0, -0.02, 0        ! m (oscillating: deg), + rise, - fall; a dwell's is 0", &
    "  follower = 'roller'              ! 'flat' (translating, flat face), 'roller' (translating),", &
    "                                   ! 'oscillating' (roller on an arm)", &
    "  offset = 0.005                   ! m, roller: the axis at x = offset (default 0)", &
    "  ! arm = 0.1, pivot = 0.12, 0.05  ! m, oscillating: arm length, pivot (x, y) from the cam", &
    "  roller_radius = 0.008            ! m, roller and oscillating, >= 0 (0: a knife edge)", &
    "  pressure_angle_max = 30          ! deg, rise and dwell (default 30; oscillating 45)", &
    "  pressure_angle_max_return = 45   ! deg, fall (default: pressure_angle_max)", &
    "  ! rho_min = 0.005                ! m, flat face: its least radius of curvature (required)", &
    "  omega = 10                       ! rad/s, + counter-clockwise, not 0", &
    "  step  = 5                        ! deg, output step, divides 360", &
    "  ! for --format deck (the &cam deck of the forces): l = 0.06 (guide length, m),", &
    "  ! l_over = 0.04 (overhang, m), f = 0.15 (guide friction), f2 = 200 (load, N), f_cam = 0.1", &
    "/"]

contains

  !> Read and validate a `&cam_profile` deck.
  subroutine read_cam_profile_deck(source, deck, error)
    !> The deck, read into memory.
    type(deck_source_t), intent(in) :: source
    !> The validated deck.
    type(cam_profile_deck_t), intent(out) :: deck
    !> Input error naming deck, group, variable and reason.
    type(error_t), allocatable, intent(out) :: error
    character(len=text_bytes * text_chars) :: law(max_segments), follower
    real(wp) :: beta(max_segments), lift(max_segments), pivot(2)
    real(wp) :: offset, arm, roller_radius, pressure_angle_max, pressure_angle_max_return, rho_min, omega, step
    real(wp) :: l, l_over, f, f2, f_cam, n_real, s, s_lowest, scale
    integer :: n, i, code, given
    character(len=:), allocatable :: at
    type(deck_context_t) :: ctx
    type(deck_rules_t) :: rules
    type(namelist_probe_t) :: probe
    namelist /cam_profile/ law, beta, lift, follower, offset, arm, pivot, roller_radius, pressure_angle_max, &
      pressure_angle_max_return, rho_min, omega, step, l, l_over, f, f2, f_cam

    call begin_group(source, "cam_profile", ctx, error, rules)
    if (allocated(error)) return
    law = " "
    follower = " "
    beta = unset_real; lift = unset_real; pivot = unset_real
    offset = unset_real; arm = unset_real; roller_radius = unset_real; pressure_angle_max = unset_real
    pressure_angle_max_return = unset_real; rho_min = unset_real; omega = unset_real; step = unset_real
    l = unset_real; l_over = unset_real; f = unset_real; f2 = unset_real; f_cam = unset_real
    call probe%limit([character(4) :: "law", "beta", "lift"], max_segments, "segments")
    read (source%records, nml=cam_profile, iostat=probe%ios, iomsg=probe%msg)
    do while (probe%retry(source))
      read (probe%records, nml=cam_profile, iostat=probe%ios, iomsg=probe%msg)
    end do
    if (probe%failed(source, ctx, error)) return

    call rules%require_choice("follower", follower, follower_names, deck%design%follower)
    ! the segments: the leading non-blank laws, no gaps
    call rules%count_texts("law", law, "give one law per segment ('dwell', 'constant_velocity', 'parabolic', "// &
      "'harmonic', 'cycloidal', 'poly345')", n)
    if (rules%failed(error)) return
    call rules%count_values("beta", beta, given)
    call rules%require_rule("beta", given == n, "expected "//int_str(n)//" values (one per segment of law), got "// &
      int_str(given))
    call rules%count_values("lift", lift, given)
    call rules%require_rule("lift", given == n, "expected "//int_str(n)//" values (one per segment of law), got "// &
      int_str(given))
    allocate (deck%design%seg(n), deck%lift_given(n))
    scale = 1.0_wp
    if (deck%design%follower == follower_oscillating) scale = deg_to_rad
    s = 0.0_wp
    s_lowest = 0.0_wp
    do i = 1, n
      at = "("//int_str(i)//")"
      call rules%require_choice("law"//at, law(i), law_names, code)
      if (rules%failed(error)) return
      call rules%require_rule("beta"//at, beta(i) > 0.0_wp .and. beta(i) <= 360.0_wp, "must be in (0, 360] deg "// &
        "(got "//real_str(beta(i))//")")
      call rules%require_rule("lift"//at, code /= law_dwell .or. lift(i) == 0.0_wp, "must be 0 for a 'dwell' (got "// &
        real_str(lift(i))//")")
      call rules%require_rule("lift"//at, abs(lift(i)) <= 1.0e3_wp, "must be within -1000 .. 1000 (got "// &
        real_str(lift(i))//")")
      deck%design%seg(i) = cam_segment_t(law=code, beta=beta(i) * deg_to_rad, lift=lift(i) * scale, &
        phi0=sum(beta(1:i - 1)) * deg_to_rad, s0=s)
      deck%lift_given(i) = lift(i)
      s = s + lift(i) * scale
      s_lowest = min(s_lowest, s)
    end do
    call rules%require_rule("beta", abs(sum(beta(1:n)) - 360.0_wp) <= 1.0e-9_wp, "must add up to 360 deg, one "// &
      "turn (got "//real_str(sum(beta(1:n)))//")")
    call rules%require_rule("lift", abs(s) <= 1.0e-9_wp * maxval(abs(lift(1:n) * scale)), "must add up to 0: the "// &
      "follower returns to its start over a turn (got "//real_str(sum(lift(1:n)))//")")
    call rules%require_rule("lift", s_lowest >= -1.0e-9_wp * maxval(abs(lift(1:n) * scale)), "the follower "// &
      "must start at its lowest position (a fall before the first rise goes below it: put a rise first)")
    call rules%require_rule("lift", maxval(abs(lift(1:n))) > 0.0_wp, "the follower must move: give a rise")
    if (rules%failed(error)) return

    ! the follower's geometry
    select case (deck%design%follower)
    case (follower_flat)
      call not_for(rules, "offset", offset, "a flat face's axis passes through the cam's centre")
      call not_for(rules, "roller_radius", roller_radius, "a flat face has no roller")
      call not_for(rules, "arm", arm, "only an oscillating follower has an arm")
      call not_for(rules, "pivot", pivot(1), "only an oscillating follower has a pivot")
      call not_for(rules, "pressure_angle_max", pressure_angle_max, "a flat face's pressure angle is 0")
      call not_for(rules, "pressure_angle_max_return", pressure_angle_max_return, "a flat face's pressure angle is 0")
      call rules%require_positive("rho_min", rho_min)
      deck%design%rho_min = rho_min
    case default
      call not_for(rules, "rho_min", rho_min, "it is the flat face's limit (a roller has its pressure angle's)")
      call rules%require_nonnegative("roller_radius", roller_radius)
      deck%design%roller_radius = roller_radius
      if (deck%design%follower == follower_roller) then
        call not_for(rules, "arm", arm, "only an oscillating follower has an arm")
        call not_for(rules, "pivot", pivot(1), "only an oscillating follower has a pivot")
        offset = optional_default(offset, 0.0_wp)
        call rules%require_set("offset", offset)
        deck%design%offset = offset
        pressure_angle_max = optional_default(pressure_angle_max, 30.0_wp)
      else
        call not_for(rules, "offset", offset, "an oscillating follower's place is its pivot")
        call rules%require_positive("arm", arm)
        call rules%require_set("pivot", pivot(1))
        call rules%require_set("pivot(2)", pivot(2))
        call rules%require_rule("pivot", norm2(pivot) > 0.0_wp, "must not be the cam's centre")
        call rules%require_rule("lift", maxval(deck%design%seg%s0) < 180.0_wp * deg_to_rad, "the arm must turn "// &
          "less than 180 deg")
        deck%design%arm = arm
        deck%design%pivot = pivot
        pressure_angle_max = optional_default(pressure_angle_max, 45.0_wp)
      end if
      pressure_angle_max_return = optional_default(pressure_angle_max_return, pressure_angle_max)
      call rules%require_in("pressure_angle_max", pressure_angle_max, pressure_angle_max > 0.0_wp .and. &
        pressure_angle_max < 90.0_wp, "(0, 90) deg")
      call rules%require_in("pressure_angle_max_return", pressure_angle_max_return, pressure_angle_max_return > 0.0_wp &
        .and. pressure_angle_max_return < 90.0_wp, "(0, 90) deg")
      deck%design%limit_rise = pressure_angle_max * deg_to_rad
      deck%design%limit_return = pressure_angle_max_return * deg_to_rad
      deck%limit_rise_deg = pressure_angle_max
      deck%limit_return_deg = pressure_angle_max_return
    end select
    if (rules%failed(error)) return

    ! speed and the output step
    call rules%require_set("omega", omega)
    call rules%require_rule("omega", omega /= 0.0_wp .and. abs(omega) <= 1.0e6_wp, "must be non-zero and within "// &
      "+-1e6 rad/s (got "//real_str(omega)//")")
    deck%design%omega = omega
    call rules%require_positive("step", step)
    n_real = 360.0_wp / step
    call rules%require_rule("step", abs(n_real - anint(n_real)) <= 1.0e-9_wp * n_real .and. anint(n_real) >= 1.0_wp, &
      "must divide 360 deg into whole steps (got "//real_str(step)//")")
    call rules%require_rule("step", anint(n_real) < real(max_steps, wp), "too small: more than "//int_str(max_steps)// &
      " steps")
    if (rules%failed(error)) return
    deck%step = 360.0_wp / anint(n_real)
    deck%n = nint(n_real) + 1

    ! for the analysis deck
    if (deck%design%follower == follower_oscillating) then
      call not_for(rules, "l", l, "the &cam analysis has translating followers only")
      call not_for(rules, "f2", f2, "the &cam analysis has translating followers only")
    end if
    deck%has_guide = is_set([l, l_over, f, f2])
    if (deck%has_guide(1)) call rules%require_positive("l", l)
    if (deck%has_guide(2)) call rules%require_nonnegative("l_over", l_over)
    if (deck%has_guide(3)) call rules%require_nonnegative("f", f)
    if (deck%has_guide(4)) call rules%require_set("f2", f2)
    deck%l = optional_default(l, 0.0_wp)
    deck%l_over = optional_default(l_over, 0.0_wp)
    deck%f = optional_default(f, 0.0_wp)
    deck%f2 = optional_default(f2, 0.0_wp)
    if (is_set(f_cam)) then
      call rules%require_rule("f_cam", deck%design%follower == follower_flat, "only for a flat face (a roller "// &
        "rolls)")
      call rules%require_nonnegative("f_cam", f_cam)
      deck%f_cam = f_cam
      deck%has_f_cam = .true.
    end if
    call rules%take(error)
  end subroutine read_cam_profile_deck

  !> A variable this follower does not take: unset.
  subroutine not_for(rules, name, value, why)
    type(deck_rules_t), intent(inout) :: rules
    character(*), intent(in) :: name
    real(wp), intent(in) :: value
    character(*), intent(in) :: why
    call rules%require_rule(name, .not. is_set(value), "not for this follower: "//why)
  end subroutine not_for

end module kinetostat_cam_profile_deck
