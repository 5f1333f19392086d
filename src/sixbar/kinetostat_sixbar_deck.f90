!> `&sixbar` decks (T.FTN): reading, validation, and the commented template.
module kinetostat_sixbar_deck
  use kinetostat_kinds, only: wp, g_default, rad_to_deg
  use kinetostat_error, only: error_t, fatal_error, exit_geometry
  use kinetostat_text, only: real_str
  use kinetostat_deck_foreign, only: refuse_translated_stages
  use kinetostat_deck, only: begin_group, text_bytes, text_chars, &
    deck_context_t, unset_real, deck_source_t, namelist_probe_t, is_set, &
    optional_default, deck_rules_t, rule_finite, rule_positive, rule_nonnegative, angle_steps_t, &
    sixbar_phi1_deg => step_angle_deg
  use kinetostat_sixbar, only: sixbar_params_t, sixbar_extreme_phi1
  use kinetostat_dynamics, only: dynamics_steady
  use kinetostat_dynamics_deck, only: dynamics_deck_t, read_dynamics_settings, require_one_turn, md_table_capacity, &
    begin_dynamics_settings
  implicit none
  private
  public :: sixbar_deck_t, read_sixbar_deck, sixbar_template, sixbar_phi1_deg

  !> A validated `&sixbar` deck.
  !> Its crank angles are in frame 1; phi_start is as given, or angle B0AD of the extreme
  !> position.
  type, extends(angle_steps_t) :: sixbar_deck_t
    !> Mechanism data, SI.
    type(sixbar_params_t) :: p
    !> Whether phi_start was computed as the extreme position.
    logical :: start_at_extreme = .false.
    !> Slider load per step, N, signed along +x2: elements 1..n (the namelist's read buffer,
    !> kept; it may hold a spare element past n). The crank angle is not stored:
    !> sixbar_phi1_deg.
    real(wp), allocatable :: f5(:)
    !> Machine dynamics settings (dynamics, delta, j_rotor, j_flywheel); with a steady cycle
    !> the per-step f5 is a load table over the crank angle (linear between the steps).
    type(dynamics_deck_t) :: dyn
  end type sixbar_deck_t

  !> Template deck (the reference deck data/sixbar.nml), one line per entry.
  character(*), parameter :: sixbar_template(*) = [character(len=92) :: &
    "! kinetostat deck: T.FTN, six-bar crank-rocker-slider mechanism (manual section 2).", &
    "! Links: 1 crank AB, 2 rod BC, 3 rocker C-D-E (pivot D, C and E opposite), 4 rod EH,", &
    "! 5 slider at H, 6 frame. Global frame: origin A, y0 up (gravity -y0), D = A + (a, b).", &
    "! Frame 1: origin A, x1 along AD (crank angles). Frame 2: origin D, x2 straight down", &
    "! (angle in frame 2 = angle in frame 1 + 180 - beta, beta = atan2(a, b)), guide y2 = e.", &
    "&sixbar", &
    "  a = 0.170, b = 0.340   ! m, pivot D from A in the global frame", &
    "  l1 = 0.100             ! m, crank AB", &
    "  lam2 = 4               ! l_BC / l1", &
    "  lam_s2 = 0.5           ! l_BS2 / l_BC (>= 0)", &
    "  lam3 = 3               ! l_DC / l1", &
    "  lam_de = 3             ! l_DE / l1", &
    "  lam4 = 2               ! l_EH / l1", &
    "  lam_s4 = 0.5           ! l_ES4 / l_EH (>= 0)", &
    "  lam_e = 2.5            ! e / l1, signed: the slider guide is the line y2 = e", &
    "  m1 = 50, m2 = 5, m3 = 8, m4 = 2, m5 = 6         ! kg (S1 = A, S3 = D, S5 = H)", &
    "  j1 = 20, j2 = 0.01, j3 = 0.2, j4 = 0.007        ! kg*m^2 (j1 about A, j3 about D)", &
    "  omega1 = 100           ! rad/s, crank speed (constant; + = CCW in frame 1)", &
    "  g = 9.81               ! m/s^2, gravity (optional, default 9.81; 0 = off)", &
    "  start_at_extreme = .true.  ! start at angle B0AD (optional; else phi_start, deg)", &
    "  ! phi_start = 36.77    ! deg in frame 1 (optional, default 0; not with start_at_extreme)", &
    "  dphi = 30              ! deg, crank step (> 0)", &
    "  n = 13                 ! steps (optional; default 360/dphi + 1)", &
    "  f5 = 7*1000, 6*0       ! N per step (n values), signed along +x2 (down)", &
    "  legacy_eq2 = .false.   ! .true. = the 1991 manual's eps_q2 erratum (old printouts)", &
    "/"]

contains

  !> Read and validate a `&sixbar` deck. Input errors have exit code 2; a requested
  !> extreme position that does not exist is a geometry error (exit 3).
  subroutine read_sixbar_deck(source, deck, error)
    !> The deck, read into memory (see load_deck).
    type(deck_source_t), intent(in) :: source
    !> The validated deck.
    type(sixbar_deck_t), intent(out) :: deck
    !> Input (or geometry) error naming file, group, variable and reason.
    type(error_t), allocatable, intent(out) :: error
    real(wp) :: a, b, l1, lam2, lam_s2, lam3, lam_de, lam4, lam_s4, lam_e
    real(wp) :: m1, m2, m3, m4, m5, j1, j2, j3, j4, omega1, g, dphi, phi_start, phi_ext
    !> Machine dynamics variables (see kinetostat_dynamics_deck).
    real(wp) :: delta, j_rotor, j_flywheel, flywheel_density, flywheel_width_ratio
    !> The driving-moment table (pairs phi deg, M_d; see kinetostat_dynamics_deck).
    real(wp) :: md_table(md_table_capacity)
    character(len=text_bytes * text_chars) :: dynamics
    real(wp), allocatable :: f5(:)
    logical :: start_at_extreme, legacy_eq2, ok
    !> Number of steps as given (an integer deck variable, read as a real: see require_whole).
    real(wp) :: n
    integer :: n_f5
    type(deck_context_t) :: ctx
    type(deck_rules_t) :: rules
    type(namelist_probe_t) :: probe
    namelist /sixbar/ a, b, l1, lam2, lam_s2, lam3, lam_de, lam4, lam_s4, lam_e, &
      m1, m2, m3, m4, m5, j1, j2, j3, j4, omega1, g, dphi, n, phi_start, start_at_extreme, f5, legacy_eq2, &
      dynamics, delta, j_rotor, j_flywheel, md_table, flywheel_density, flywheel_width_ratio

    call begin_group(source, "sixbar", ctx, error, rules)
    if (allocated(error)) return
    ! a stage this kind lacks: the reason and the way out, before the READ
    call refuse_translated_stages(source, "sixbar", " but f5", error)
    if (allocated(error)) return
    call begin_dynamics_settings(probe, dynamics, delta, j_rotor, j_flywheel, md_table, flywheel_density, &
      flywheel_width_ratio)
    a = unset_real; b = unset_real; l1 = unset_real
    lam2 = unset_real; lam_s2 = unset_real; lam3 = unset_real; lam_de = unset_real
    lam4 = unset_real; lam_s4 = unset_real; lam_e = unset_real
    m1 = unset_real; m2 = unset_real; m3 = unset_real; m4 = unset_real; m5 = unset_real
    j1 = unset_real; j2 = unset_real; j3 = unset_real; j4 = unset_real
    omega1 = unset_real; g = unset_real; dphi = unset_real; phi_start = unset_real
    n = unset_real
    start_at_extreme = .false.
    legacy_eq2 = .false.
    call probe%per_step(source, ctx, "f5", f5, error)
    if (allocated(error)) return

    read (source%records, nml=sixbar, iostat=probe%ios, iomsg=probe%msg)
    do while (probe%retry(source)) ! on failure: find the line and the assignment
      read (probe%records, nml=sixbar, iostat=probe%ios, iomsg=probe%msg)
    end do
    if (probe%failed(source, ctx, error)) return

    ! every missing required variable in one message
    call rules%require_all_set([character(len=6) :: "a", "b", "l1", "lam2", "lam_s2", "lam3", "lam_de", "lam4", "lam_s4", "lam_e", &
      "m1", "m2", "m3", "m4", "m5", "j1", "j2", "j3", "j4", "omega1"], &
      [a, b, l1, lam2, lam_s2, lam3, lam_de, lam4, lam_s4, lam_e, m1, m2, m3, m4, m5, j1, j2, j3, j4, omega1])

    ! geometry: D, lengths and ratios
    call rules%require_each(rule_finite, [character(1) :: "a", "b"], [a, b])
    call rules%require_rule("b", hypot(a, b) > 0.0_wp, "a and b must not both be 0: D must differ from A")
    call rules%require_each(rule_positive, [character(4) :: "l1", "lam2"], [l1, lam2])
    call rules%require_nonnegative("lam_s2", lam_s2)
    call rules%require_each(rule_positive, [character(6) :: "lam3", "lam_de", "lam4"], [lam3, lam_de, lam4])
    call rules%require_nonnegative("lam_s4", lam_s4)
    call rules%require_set("lam_e", lam_e)

    ! masses, inertia, speed, gravity
    call rules%require_each(rule_nonnegative, [character(2) :: "m1", "m2", "m3", "m4", "m5", "j1", "j2", "j3", "j4"], &
      [m1, m2, m3, m4, m5, j1, j2, j3, j4])
    call rules%require_set("omega1", omega1)
    g = optional_default(g, g_default)
    call rules%require_nonnegative("g", g)
    if (rules%failed(error)) return

    ! machine dynamics (a steady cycle takes f5 as a table over the crank angle: below)
    call read_dynamics_settings(ctx, dynamics, delta, j_rotor, j_flywheel, omega1, deck%dyn, error, &
      md_table=md_table, flywheel_density=flywheel_density, flywheel_width_ratio=flywheel_width_ratio)
    if (allocated(error)) return

    deck%p = sixbar_params_t(a=a, b=b, l1=l1, lam2=lam2, lam_s2=lam_s2, lam3=lam3, lam_de=lam_de, &
      lam4=lam4, lam_s4=lam_s4, lam_e=lam_e, m1=m1, m2=m2, m3=m3, m4=m4, m5=m5, j1=j1, j2=j2, j3=j3, &
      j4=j4, omega1=omega1, g=g, legacy_eq2=legacy_eq2)

    ! crank angles: phi_start or the extreme position, not both
    call rules%require_rule("phi_start", .not. (start_at_extreme .and. is_set(phi_start)), "give either phi_start "// &
      "or start_at_extreme = .true., not both")
    if (rules%failed(error)) return
    if (start_at_extreme) then
      call sixbar_extreme_phi1(deck%p, phi_ext, ok)
      if (.not. ok) then
        call fatal_error(error, exit_geometry, source%path//": &sixbar: start_at_extreme: step 1 (extreme position)"// &
          " cannot be assembled: crank and connecting rod cannot lie in line (l1 + l2 = "// &
          real_str(l1 * (1.0_wp + lam2))//" m; needs |l_AD - l3| < l1 + l2 < l_AD + l3 with l_AD = "// &
          real_str(hypot(a, b))//" m, l3 = "//real_str(lam3 * l1)//" m)")
        return
      end if
      phi_start = phi_ext * rad_to_deg
    end if
    call rules%crank_steps(phi_start, dphi, n, deck%n)
    if (rules%failed(error)) return
    ! a steady cycle: the steps are the breakpoints of the load table f5 over one turn
    if (deck%dyn%mode >= dynamics_steady) then
      call require_one_turn(ctx, dphi, deck%n, error); if (allocated(error)) return
    end if

    ! slider load: one value per step
    call rules%count_values("f5", f5, n_f5)
    call rules%require_rule("f5", n_f5 /= 0, "missing: give f5 = v1, v2, ... (one value per step, N along +x2)")
    call rules%require_per_step("f5", n_f5, deck%n)
    if (rules%failed(error)) return

    ! the read buffer is the deck's array (no second copy)
    call move_alloc(f5, deck%f5)
    deck%phi_start = phi_start
    deck%start_at_extreme = start_at_extreme
    deck%dphi = dphi
  end subroutine read_sixbar_deck


end module kinetostat_sixbar_deck
