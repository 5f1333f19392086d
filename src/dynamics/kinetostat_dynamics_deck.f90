!> The dynamics variables a linkage deck may give (`dynamics`, `delta`, `j_rotor`,
!> `j_flywheel`, `md_table`, `cycle`), validated alike for every mechanism, and the rule that
!> a steady cycle's steps cover exactly its cycle of the input (one turn, or two: `cycle = 720`).
module kinetostat_dynamics_deck
  use kinetostat_kinds, only: wp, deg_to_rad, pi
  use kinetostat_error, only: error_t
  use kinetostat_text, only: real_str, int_str
  use kinetostat_deck, only: deck_context_t, deck_error, is_set, unset_real, require_rule, optional_default, &
    deck_rules_t, namelist_probe_t, text_bytes, text_chars
  use kinetostat_dynamics, only: dynamics_none, dynamics_reduced, dynamics_steady, dynamics_given, &
    reduced_source_t, cycle_t, cycle_setup, cycle_steady, cycle_given
  implicit none
  private
  public :: dynamics_deck_t, read_dynamics_settings, require_one_turn, dynamics_mode_name, deck_cycle
  public :: md_table_capacity, begin_dynamics_settings

  !> Values a deck's `md_table` may hold (pairs of angle and moment): 2881 points, every 0.25 deg
  !> over a cycle of two turns.
  integer, parameter :: md_table_capacity = 2 * 2881

  !> Validated dynamics settings of a deck.
  type :: dynamics_deck_t
    !> dynamics_none, dynamics_reduced, dynamics_steady or dynamics_given.
    integer :: mode = dynamics_none
    !> Coefficient of speed fluctuation asked for ('steady').
    real(wp) :: delta = 0.0_wp
    !> Rotor and gear train reduced to the input link, kg*m^2.
    real(wp) :: j_rotor = 0.0_wp
    !> Flywheel ('given'), kg*m^2.
    real(wp) :: j_flywheel = 0.0_wp
    !> The driving-moment table's angles as given, deg (not allocated: M_d constant).
    real(wp), allocatable :: md_phi(:)
    !> Its moments as given (any scale: scaled to zero net work over the cycle), N*m.
    real(wp), allocatable :: md_value(:)
    !> The cycle of the steady motion, deg: 360 (one turn) or 720 (two turns: a four-stroke
    !> engine's working cycle).
    real(wp) :: cycle_deg = 360.0_wp
    !> The flywheel drawn as a disc: density of its material, kg/m^3 (steel by default).
    real(wp) :: flywheel_density = 7800.0_wp
    !> Its width over its diameter, b/D.
    real(wp) :: flywheel_width_ratio = 0.2_wp
  end type dynamics_deck_t

contains

  !> The machine-dynamics variables of a group, before its READ: the mode blank, the rest
  !> unset; the driving-moment table's limit noted in the probe.
  subroutine begin_dynamics_settings(probe, mode_text, delta, j_rotor, j_flywheel, md_table, flywheel_density, &
    flywheel_width_ratio)
    !> The READ's probe.
    type(namelist_probe_t), intent(inout) :: probe
    !> `dynamics`.
    character(len=text_bytes * text_chars), intent(out) :: mode_text
    !> `delta`, `j_rotor`, `j_flywheel`, `flywheel_density`, `flywheel_width_ratio`.
    real(wp), intent(out) :: delta, j_rotor, j_flywheel, flywheel_density, flywheel_width_ratio
    !> `md_table` (md_table_capacity values).
    real(wp), intent(out) :: md_table(:)
    mode_text = ""
    delta = unset_real; j_rotor = unset_real; j_flywheel = unset_real
    flywheel_density = unset_real; flywheel_width_ratio = unset_real
    md_table = unset_real
    call probe%limit("md_table", md_table_capacity, "values ("//int_str(md_table_capacity / 2)//" points)")
  end subroutine begin_dynamics_settings

  !> The name of a mode as the deck writes it.
  pure function dynamics_mode_name(mode) result(name)
    integer, intent(in) :: mode
    character(len=:), allocatable :: name
    select case (mode)
    case (dynamics_reduced)
      name = "reduced"
    case (dynamics_steady)
      name = "steady"
    case (dynamics_given)
      name = "given"
    case default
      name = "none"
    end select
  end function dynamics_mode_name

  !> Validate the dynamics variables as read (reals unset_real when not given; `mode_text`
  !> blank when not given). `omega1` is the deck's crank speed (the mean speed with 'steady'
  !> and 'given').
  subroutine read_dynamics_settings(ctx, mode_text, delta, j_rotor, j_flywheel, omega1, dyn, error, md_table, cycle, &
                                    flywheel_density, flywheel_width_ratio)
    type(deck_context_t), intent(in) :: ctx
    !> Value of `dynamics` ('none', 'reduced', 'steady', 'given'; blank: none).
    character(*), intent(in) :: mode_text
    !> Deck values (unset_real when not given).
    real(wp), intent(in) :: delta, j_rotor, j_flywheel, omega1
    type(dynamics_deck_t), intent(out) :: dyn
    type(error_t), allocatable, intent(out) :: error
    !> The deck's `md_table` (pairs phi deg, M_d; unset_real past the values given), when the
    !> mechanism offers it.
    real(wp), intent(in), optional :: md_table(:)
    !> The deck's `cycle`, deg (360 or 720; unset_real when not given), when the mechanism
    !> offers it.
    real(wp), intent(in), optional :: cycle
    !> The deck's `flywheel_density` (kg/m^3) and `flywheel_width_ratio` (b/D) (unset_real
    !> when not given), when the mechanism offers them.
    real(wp), intent(in), optional :: flywheel_density, flywheel_width_ratio
    real(wp) :: rho, psi
    integer :: n_md, i
    type(deck_rules_t) :: rules
    rules%ctx = ctx
    n_md = 0
    if (present(md_table)) call rules%count_values("md_table", md_table, n_md)
    if (rules%failed(error)) return
    select case (trim(adjustl(mode_text)))
    case ("", "none")
      dyn%mode = dynamics_none
    case ("reduced")
      dyn%mode = dynamics_reduced
    case ("steady")
      dyn%mode = dynamics_steady
    case ("given")
      dyn%mode = dynamics_given
    case default
      call deck_error(ctx, "dynamics", "unknown value '"//trim(adjustl(mode_text))// &
        "' (expected 'none', 'reduced', 'steady' or 'given')", error)
      return
    end select
    call rules%require_rule("md_table", n_md == 0 .or. dyn%mode >= dynamics_steady, &
      "a driving-moment table needs dynamics = 'steady' or 'given'")
    if (present(cycle)) then
      if (is_set(cycle)) then
        call rules%require_rule("cycle", cycle == 360.0_wp .or. cycle == 720.0_wp, "must be 360 (one turn) or 720 "// &
          "(two turns: a four-stroke engine's working cycle), deg (got "//real_str(cycle)//")")
        call rules%require_rule("cycle", dyn%mode >= dynamics_steady, &
          "the cycle of the steady motion needs dynamics = 'steady' or 'given'")
        dyn%cycle_deg = cycle
      end if
    end if
    rho = unset_real
    psi = unset_real
    if (present(flywheel_density)) rho = flywheel_density
    if (present(flywheel_width_ratio)) psi = flywheel_width_ratio
    call rules%require_rule("flywheel_density", .not. any(is_set([rho, psi])) .or. dyn%mode >= dynamics_steady, &
      "flywheel_density and flywheel_width_ratio (the flywheel's disc) need dynamics = 'steady' or 'given'")
    if (is_set(rho)) then
      call rules%require_rule("flywheel_density", rho > 0.0_wp .and. rho < 1.0e6_wp, "must be > 0 and < 1e6 "// &
        "kg/m^3 (the density of the flywheel's material; steel 7800; got "//real_str(rho)//")")
      dyn%flywheel_density = rho
    end if
    if (is_set(psi)) then
      call rules%require_rule("flywheel_width_ratio", psi > 0.0_wp .and. psi <= 10.0_wp, "must be > 0 and <= 10 "// &
        "(the disc's width b over its diameter D; 0.1 to 0.3 as a rule; got "//real_str(psi)//")")
      dyn%flywheel_width_ratio = psi
    end if
    if (dyn%mode == dynamics_none) then
      call rules%require_rule("delta", .not. any(is_set([delta, j_rotor, j_flywheel])), &
        "delta, j_rotor and j_flywheel need dynamics = 'steady' or 'given'")
      call rules%take(error)
      return
    end if
    if (rules%failed(error)) return
    if (n_md > 0) then
      call rules%require_rule("md_table", mod(n_md, 2) == 0 .and. n_md >= 4, "give pairs of crank angle (deg) "// &
        "and driving moment, at least two (got "//int_str(n_md)//" values)")
      if (rules%failed(error)) return
      dyn%md_phi = md_table(1:n_md:2)
      dyn%md_value = md_table(2:n_md:2)
      do i = 2, size(dyn%md_phi)
        call rules%require_rule("md_table", dyn%md_phi(i) > dyn%md_phi(i - 1), "the angles must increase (point "// &
          int_str(i)//": "//real_str(dyn%md_phi(i))//" deg after "//real_str(dyn%md_phi(i - 1))//" deg)")
      end do
      associate (first => dyn%md_phi(1), last => dyn%md_phi(size(dyn%md_phi)))
        if (dyn%cycle_deg == 360.0_wp) then
          call rules%require_rule("md_table", last - first < 360.0_wp, "the angles must lie within one turn "// &
            "(last - first < 360 deg; the table repeats every turn), got "//real_str(last - first)//" deg")
        else
          call rules%require_rule("md_table", last - first < dyn%cycle_deg, &
            "the angles must lie within one cycle (last - first < "//real_str(dyn%cycle_deg)//" deg, cycle = "// &
            int_str(nint(dyn%cycle_deg))//"; the table repeats every cycle), got "//real_str(last - first)//" deg")
        end if
      end associate
    end if
    dyn%j_rotor = optional_default(j_rotor, 0.0_wp)
    call rules%require_nonnegative("j_rotor", dyn%j_rotor)
    if (dyn%mode == dynamics_reduced) then
      call rules%require_rule("delta", .not. any(is_set([delta, j_flywheel])), &
        "delta and j_flywheel need dynamics = 'steady' or 'given'")
      call rules%take(error)
      return
    end if
    call rules%require_rule("omega1", omega1 > 0.0_wp, "must be > 0 with dynamics = '"// &
      trim(adjustl(mode_text))//"' (the mean speed; got "//real_str(omega1)//")")
    if (dyn%mode == dynamics_steady) then
      call rules%require_rule("j_flywheel", .not. is_set(j_flywheel), &
        "is found with dynamics = 'steady' (give it with dynamics = 'given')")
      call rules%require_rule("delta", is_set(delta), "missing: dynamics = 'steady' needs the coefficient "// &
        "of speed fluctuation delta")
      call rules%require_rule("delta", delta > 0.0_wp .and. delta < 1.0_wp, &
        "must be > 0 and < 1 (got "//real_str(delta)//"): the coefficient of speed fluctuation "// &
        "(omega_max - omega_min)/omega1 of a machine is a small fraction (about 1/300 to 1/5); at 1 the speed "// &
        "would already swing from omega1/2 to 3*omega1/2")
      dyn%delta = delta
    else
      call rules%require_rule("delta", .not. is_set(delta), "is found with dynamics = 'given' (give it with "// &
        "dynamics = 'steady')")
      call rules%require_rule("j_flywheel", is_set(j_flywheel), "missing: dynamics = 'given' needs j_flywheel")
      call rules%require_nonnegative("j_flywheel", j_flywheel)
      dyn%j_flywheel = j_flywheel
    end if
    call rules%take(error)
  end subroutine read_dynamics_settings

  !> A steady cycle covers exactly one turn (or its cycle, `cycle_deg` = 720: two turns): the
  !> steps phi_start + (k-1) dphi, k = 1..n, end at phi_start + 360 deg (+ 720 deg).
  pure subroutine require_one_turn(ctx, dphi, n, error, cycle_deg)
    type(deck_context_t), intent(in) :: ctx
    !> Crank step, deg.
    real(wp), intent(in) :: dphi
    !> Number of steps.
    integer, intent(in) :: n
    type(error_t), allocatable, intent(out) :: error
    !> The deck's cycle, deg (default 360).
    real(wp), intent(in), optional :: cycle_deg
    real(wp) :: span, whole
    whole = 360.0_wp
    if (present(cycle_deg)) whole = cycle_deg
    span = real(n - 1, wp) * dphi
    if (whole == 360.0_wp) then
      call require_rule(ctx, "dphi", abs(span - 360.0_wp) <= 1.0e-9_wp * 360.0_wp, &
        "the steps must cover exactly one turn of the crank with a steady cycle: (n - 1)*dphi = "// &
        real_str(span)//" deg, not 360", error)
    else
      call require_rule(ctx, "dphi", abs(span - whole) <= 1.0e-9_wp * whole, &
        "the steps must cover exactly the cycle of two turns with cycle = "//int_str(nint(whole))// &
        ": (n - 1)*dphi = "//real_str(span)//" deg, not "//int_str(nint(whole)), error)
    end if
  end subroutine require_one_turn

  !> The steady cycle a deck's settings ask for (dynamics = 'steady': the flywheel for delta;
  !> 'given': the speed law with j_flywheel), from the mechanism's reduced quantities.
  pure subroutine deck_cycle(source, dyn, phi0, breaks, omega_mean, where, cycle, error, j_links_constant)
    !> The mechanism's reduced quantities at any input angle.
    class(reduced_source_t), intent(in) :: source
    !> The deck's settings (mode 'steady' or 'given').
    type(dynamics_deck_t), intent(in) :: dyn
    !> Input angle where the cycle starts, rad.
    real(wp), intent(in) :: phi0
    !> Angles where a load switches (the quadrature's breakpoints), rad.
    real(wp), intent(in) :: breaks(:)
    !> Mean speed of the input link, rad/s.
    real(wp), intent(in) :: omega_mean
    !> "DECK: &group", for messages.
    character(*), intent(in) :: where
    type(cycle_t), intent(out) :: cycle
    type(error_t), allocatable, intent(out) :: error
    !> The constant part of the links' J_red (the input link's own inertia), kg*m^2, for
    !> Merzalov's estimate (default 0).
    real(wp), intent(in), optional :: j_links_constant
    if (allocated(dyn%md_phi)) then
      call cycle_setup(source, phi0, breaks, dyn%j_rotor, omega_mean, where, cycle, error, &
                       dyn%md_phi * deg_to_rad, dyn%md_value, span=2.0_wp * pi * (dyn%cycle_deg / 360.0_wp))
    else
      call cycle_setup(source, phi0, breaks, dyn%j_rotor, omega_mean, where, cycle, error, &
                       span=2.0_wp * pi * (dyn%cycle_deg / 360.0_wp))
    end if
    if (allocated(error)) return
    if (present(j_links_constant)) cycle%j_links_constant = j_links_constant
    cycle%flywheel_density = dyn%flywheel_density
    cycle%flywheel_width_ratio = dyn%flywheel_width_ratio
    if (dyn%mode == dynamics_steady) then
      call cycle_steady(source, dyn%delta, where, cycle, error)
    else
      call cycle_given(source, dyn%j_flywheel, where, cycle, error)
    end if
  end subroutine deck_cycle

end module kinetostat_dynamics_deck
