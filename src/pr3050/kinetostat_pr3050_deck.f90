!> `&pr3050` decks: reading, validation, and the commented template.
module kinetostat_pr3050_deck
  use kinetostat_kinds, only: wp, g_default, deg_to_rad
  use kinetostat_error, only: error_t
  use kinetostat_text, only: real_str, int_str
  use kinetostat_deck_foreign, only: refuse_translated_stages, refuse_variables
  use kinetostat_deck, only: begin_group, text_bytes, text_chars, &
    deck_context_t, unset_real, max_steps, deck_source_t, namelist_probe_t, &
    optional_default, deck_rules_t, rule_finite, rule_positive, rule_nonnegative, angle_steps_t, &
    pr3050_phi3_deg => step_angle_deg
  use kinetostat_pr3050, only: pr3050_params_t
  use kinetostat_dynamics_deck, only: dynamics_deck_t, read_dynamics_settings
  implicit none
  private
  public :: pr3050_deck_t, read_pr3050_deck, pr3050_template, pr3050_step_count, pr3050_phi3_deg

  !> Largest distance of (phi3_end - phi3_start)/dphi3 from a whole number, relative to it
  !> (at least 1), that still counts as whole (decimal angles are not exact in binary).
  real(wp), parameter :: whole_steps_tol = 1.0e-9_wp

  !> A validated `&pr3050` deck.
  !> Its steps are the rocker's angles phi3: phi_start and dphi are the deck's phi3_start and
  !> dphi3, n = (phi3_end - phi3_start)/dphi3 + 1.
  type, extends(angle_steps_t) :: pr3050_deck_t
    !> Mechanism data, SI (angles delta, gamma in rad).
    type(pr3050_params_t) :: p
    !> Angle of CS3 ahead of CB as given, deg.
    real(wp) :: delta_deg = 0.0_wp
    !> Direction of gravity as given, deg.
    real(wp) :: gamma_deg = 0.0_wp
    !> Last rocker angle, deg.
    real(wp) :: phi3_end = 0.0_wp
    !> Rocker angular speed per step, rad/s: elements 1..n (the namelist's read buffer, kept;
    !> it may hold a spare element past n). The rocker angle is not stored: pr3050_phi3_deg.
    real(wp), allocatable :: omega3(:)
    !> Rocker angular acceleration per step, rad/s^2: elements 1..n (as omega3).
    real(wp), allocatable :: eps3(:)
    !> Machine dynamics settings (dynamics = 'reduced', reduced to the stroke; j_rotor in kg).
    type(dynamics_deck_t) :: dyn
  end type pr3050_deck_t

  !> Template deck (the spec's reference data), one line per entry.
  character(*), parameter :: pr3050_template(*) = [character(len=100) :: &
    "! kinetostat deck: PR 3050, four-bar with an oscillating hydraulic cylinder.", &
    "! Links: 1 cylinder pivoted on the frame at A, 2 piston with rod pinned at B to 3,", &
    "! 3 rocker (turning platform) pivoted at C, 4 frame. Frame: origin C, x from C to A,", &
    "! y counter-clockwise; angles in deg counter-clockwise from x. The oil force F2 drives", &
    "! (positive pushing the rod out of the cylinder); the rocker's motion is prescribed.", &
    "&pr3050", &
    "  l_ca   = 1.667   ! m, centre distance C-A (> 0)", &
    "  l_cb   = 1.222   ! m, rocker arm C-B (> 0)", &
    "  l_cs3  = 2.31    ! m, C to the rocker's centre of mass S3 (>= 0)", &
    "  delta  = 10.5    ! deg, angle of CS3 ahead of CB (counter-clockwise)", &
    "  l_bs2  = 0.48    ! m, B to the rod's centre of mass S2, along the rod (>= 0)", &
    "  l_s1a  = 0.42    ! m, the cylinder's centre of mass S1 to A, along the axis (>= 0)", &
    "  gamma  = 313.72  ! deg, direction of gravity in the C-A frame (270 if x is horizontal)", &
    "  g      = 9.81    ! m/s^2, gravity (optional, default 9.81; 0 = off)", &
    "  m1     = 15      ! kg, cylinder 1 (>= 0)", &
    "  m2     = 28      ! kg, rod with piston 2 (>= 0)", &
    "  m3     = 1056    ! kg, rocker 3 (>= 0)", &
    "  j1     = 1.5     ! kg*m^2, cylinder about S1 (>= 0)", &
    "  j2     = 1.5     ! kg*m^2, rod about S2 (>= 0)", &
    "  j3     = 622     ! kg*m^2, rocker about S3 (>= 0)", &
    "  phi3_start = 43.72  ! deg, first rocker angle", &
    "  phi3_end   = 88.72  ! deg, last rocker angle (> phi3_start)", &
    "  dphi3      = 5      ! deg, step (> 0); N = (phi3_end - phi3_start)/dphi3 + 1 must be whole", &
    "  ! rocker speed and angular acceleration, exactly N values each (+ = counter-clockwise)", &
    "  omega3 = 0, 0.28868, 0.40825, 0.5, 0.5, 0.5, 0.5, 0.40825, 0.28868, 0        ! rad/s", &
    "  eps3   = 0.47746, 0.47746, 0.47746, 0, 0, 0, 0, -0.47746, -0.47746, -0.47746  ! rad/s^2", &
    "/"]

contains

  !> Number of steps N = (phi3_end - phi3_start)/dphi3 + 1 of a rocker range (deg), or 0
  !> when the range is not a whole number of steps, or -1 when it exceeds max_steps.
  !> Needs dphi3 > 0 and phi3_end > phi3_start.
  pure function pr3050_step_count(phi3_start, phi3_end, dphi3) result(n)
    !> First rocker angle, deg.
    real(wp), intent(in) :: phi3_start
    !> Last rocker angle, deg.
    real(wp), intent(in) :: phi3_end
    !> Rocker step, deg.
    real(wp), intent(in) :: dphi3
    integer :: n
    real(wp) :: q
    q = (phi3_end - phi3_start) / dphi3
    if (.not. q + 1.0_wp <= real(max_steps, wp)) then
      n = -1
    else if (abs(q - anint(q)) > whole_steps_tol * max(1.0_wp, q)) then
      n = 0
    else
      n = nint(q) + 1
    end if
  end function pr3050_step_count

  !> Read and validate a `&pr3050` deck.
  subroutine read_pr3050_deck(source, deck, error)
    !> The deck, read into memory (see load_deck).
    type(deck_source_t), intent(in) :: source
    !> The validated deck.
    type(pr3050_deck_t), intent(out) :: deck
    !> Input error naming file, group, variable and reason.
    type(error_t), allocatable, intent(out) :: error
    real(wp) :: l_ca, l_cb, l_cs3, delta, l_bs2, l_s1a, gamma, g, m1, m2, m3, j1, j2, j3
    real(wp) :: phi3_start, phi3_end, dphi3
    real(wp), allocatable :: omega3(:), eps3(:)
    !> Machine dynamics variables: mode and the drive's mass reduced to the stroke, kg.
    character(len=text_bytes * text_chars) :: dynamics
    real(wp) :: j_rotor
    type(deck_context_t) :: ctx
    type(deck_rules_t) :: rules
    type(namelist_probe_t) :: probe
    namelist /pr3050/ l_ca, l_cb, l_cs3, delta, l_bs2, l_s1a, gamma, g, m1, m2, m3, j1, j2, j3, &
      phi3_start, phi3_end, dphi3, omega3, eps3, dynamics, j_rotor

    call begin_group(source, "pr3050", ctx, error, rules)
    if (allocated(error)) return
    ! a stage this kind lacks: the reason and the way out, before the READ
    call refuse_translated_stages(source, "pr3050", "", error, cycle_reason= &
      "PR 3050 is driven by its cylinder: its dynamics is 'reduced' only (no steady cycle; "// &
      "in its &linkage translation neither)")
    if (allocated(error)) return
    call refuse_variables(source, "pr3050", [character(len=8) :: "md_table"], &
      "PR 3050 is driven by its cylinder: its dynamics is 'reduced' only (no driving-moment table; in its "// &
      "&linkage translation neither)", error)
    if (allocated(error)) return
    l_ca = unset_real; l_cb = unset_real; l_cs3 = unset_real; delta = unset_real
    l_bs2 = unset_real; l_s1a = unset_real; gamma = unset_real; g = unset_real
    m1 = unset_real; m2 = unset_real; m3 = unset_real
    j1 = unset_real; j2 = unset_real; j3 = unset_real
    phi3_start = unset_real; phi3_end = unset_real; dphi3 = unset_real
    dynamics = ""; j_rotor = unset_real
    call probe%per_step(source, ctx, "omega3", omega3, error)
    if (allocated(error)) return
    call probe%per_step(source, ctx, "eps3", eps3, error)
    if (allocated(error)) return

    read (source%records, nml=pr3050, iostat=probe%ios, iomsg=probe%msg)
    do while (probe%retry(source)) ! on failure: find the line and the assignment
      read (probe%records, nml=pr3050, iostat=probe%ios, iomsg=probe%msg)
    end do
    if (probe%failed(source, ctx, error)) return

    ! every missing required variable in one message
    call rules%require_all_set([character(len=10) :: "l_ca", "l_cb", "l_cs3", "delta", "l_bs2", "l_s1a", "gamma", "m1", &
      "m2", "m3", "j1", "j2", "j3", "phi3_start", "phi3_end", "dphi3"], &
      [l_ca, l_cb, l_cs3, delta, l_bs2, l_s1a, gamma, m1, m2, m3, j1, j2, j3, phi3_start, phi3_end, dphi3])

    ! lengths and angles of the links
    call rules%require_each(rule_positive, [character(4) :: "l_ca", "l_cb"], [l_ca, l_cb])
    call rules%require_nonnegative("l_cs3", l_cs3)
    call rules%require_set("delta", delta)
    call rules%require_each(rule_nonnegative, [character(5) :: "l_bs2", "l_s1a"], [l_bs2, l_s1a])
    ! gravity, masses, inertias
    call rules%require_set("gamma", gamma)
    g = optional_default(g, g_default)
    call rules%require_each(rule_nonnegative, [character(2) :: "g", "m1", "m2", "m3", "j1", "j2", "j3"], &
      [g, m1, m2, m3, j1, j2, j3])

    ! rocker range: N = (phi3_end - phi3_start)/dphi3 + 1
    call rules%require_each(rule_finite, [character(10) :: "phi3_start", "phi3_end"], [phi3_start, phi3_end])
    call rules%require_positive("dphi3", dphi3)
    call rules%require_rule("phi3_end", phi3_end > phi3_start, "must be > phi3_start (got phi3_end = "// &
      real_str(phi3_end)//", phi3_start = "//real_str(phi3_start)//"): the range gives no steps")
    if (rules%failed(error)) return
    deck%n = pr3050_step_count(phi3_start, phi3_end, dphi3)
    call rules%require_rule("dphi3", deck%n /= -1, "too small: (phi3_end - phi3_start)/dphi3 + 1 exceeds "// &
      int_str(max_steps)//" steps")
    call rules%require_rule("dphi3", deck%n /= 0, "phi3_end - phi3_start = "//real_str(phi3_end - phi3_start)// &
      " is not a whole number of steps dphi3 = "//real_str(dphi3))
    if (rules%failed(error)) return

    ! speed law: exactly N values each
    call speed_law_values(rules, "omega3", omega3, deck%n)
    call speed_law_values(rules, "eps3", eps3, deck%n)

    ! machine dynamics: the reduced quantities only, reduced to the stroke (the input translates)
    call rules%require_rule("dynamics", trim(adjustl(dynamics)) /= "steady" .and. trim(adjustl(dynamics)) /= "given", &
      "'"//trim(adjustl(dynamics))//"' needs a crank: PR 3050's input is the cylinder's stroke, which goes out and "// &
      "back over a rocker range, not one turn, so there is no cycle of a constant driving moment; use dynamics = "// &
      "'reduced' (J_red, M_red reduced to the stroke)")
    if (rules%failed(error)) return
    call read_dynamics_settings(ctx, dynamics, unset_real, j_rotor, unset_real, 1.0_wp, deck%dyn, error)
    if (allocated(error)) return

    deck%p = pr3050_params_t(l_ca=l_ca, l_cb=l_cb, l_cs3=l_cs3, delta=delta * deg_to_rad, l_bs2=l_bs2, &
                             l_s1a=l_s1a, gamma=gamma * deg_to_rad, g=g, m1=m1, m2=m2, m3=m3, &
                             j1=j1, j2=j2, j3=j3)
    deck%delta_deg = delta
    deck%gamma_deg = gamma
    deck%phi_start = phi3_start
    deck%phi3_end = phi3_end
    deck%dphi = dphi3
    ! the read buffers are the deck's arrays (no second copy of 10^6 values)
    call move_alloc(omega3, deck%omega3)
    call move_alloc(eps3, deck%eps3)
  end subroutine read_pr3050_deck

  !> A speed-law list (omega3 or eps3): given, finite and with exactly one value per step.
  subroutine speed_law_values(rules, name, values, n)
    type(deck_rules_t), intent(inout) :: rules
    !> The list's variable name.
    character(*), intent(in) :: name
    !> The list as read.
    real(wp), intent(in) :: values(:)
    !> Number of steps.
    integer, intent(in) :: n
    integer :: count
    call rules%count_values(name, values, count)
    call rules%require_rule(name, count > 0, "missing: give N = "//int_str(n)//" values (one per step)")
    call rules%require_per_step(name, count, n)
  end subroutine speed_law_values


end module kinetostat_pr3050_deck
