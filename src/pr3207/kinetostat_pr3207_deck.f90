!> `&pr3207` decks: reading, validation, and the commented template.
module kinetostat_pr3207_deck
  use kinetostat_kinds, only: wp, g_default
  use kinetostat_error, only: error_t
  use kinetostat_text, only: real_str
  use kinetostat_deck_foreign, only: refuse_translated_stages
  use kinetostat_deck, only: begin_group, text_bytes, text_chars, &
    deck_context_t, unset_real, deck_source_t, namelist_probe_t, is_set, &
    optional_default, deck_rules_t, rule_finite, rule_positive, rule_nonnegative, angle_steps_t, &
    pr3207_phi1_deg => step_angle_deg
  use kinetostat_pr3207, only: pr3207_params_t
  use kinetostat_dynamics, only: dynamics_steady
  use kinetostat_dynamics_deck, only: dynamics_deck_t, read_dynamics_settings, require_one_turn, md_table_capacity, &
    begin_dynamics_settings
  implicit none
  private
  public :: pr3207_deck_t, read_pr3207_deck, pr3207_template, pr3207_cut_force
  public :: pr3207_phi1_deg, pr3207_f5c, pr3207_f5c_steps

  !> A validated `&pr3207` deck.
  type, extends(angle_steps_t) :: pr3207_deck_t
    !> Mechanism data, SI.
    type(pr3207_params_t) :: p
    !> True when the cutting force came in the two-value form.
    logical :: two_value = .false.
    !> Two-value form: force on the working stroke, N (along +y).
    real(wp) :: f5c_work = 0.0_wp
    !> Two-value form: force elsewhere, N (along +y).
    real(wp) :: f5c_idle = 0.0_wp
    !> Two-value form: crank angle where cutting starts, deg.
    real(wp) :: phi_cut_start = 0.0_wp
    !> Two-value form: crank angle where cutting ends, deg.
    real(wp) :: phi_cut_end = 0.0_wp
    !> Cutting force per step as given (array form), N (along +y): elements 1..n (the
    !> namelist's read buffer, kept); not allocated in the two-value form. Step k's force:
    !> pr3207_f5c; its crank angle: pr3207_phi1_deg (neither stored per step otherwise).
    real(wp), allocatable :: f5c_values(:)
    !> Machine dynamics settings (dynamics, delta, j_rotor, j_flywheel).
    type(dynamics_deck_t) :: dyn
  end type pr3207_deck_t

  !> Template deck (reference data of the spec), one line per entry.
  character(*), parameter :: pr3207_template(*) = [character(len=100) :: &
    "! kinetostat deck: PR 3207, six-bar slotted-link (shaper) mechanism.", &
    "! Frame: origin A, x from A to C pointing down (gravity along +x), y horizontal.", &
    "! Links: 1 crank AB, 2 block on the lever, 3 slotted lever CD, 4 block at D,", &
    "! 5 ram (moves along y), 6 frame. Blocks 2, 4 massless; crank's mass centre at A.", &
    "&pr3207", &
    "  l_ab   = 0.11    ! m, crank AB (must be < l_ac)", &
    "  l_ac   = 0.38    ! m, centre distance A-C", &
    "  l_cd   = 0.72    ! m, lever C-D (must be > l_ac + l_ab)", &
    "  l_cs3  = 0.36    ! m, C to the lever's centre of mass S3", &
    "  m1     = 12      ! kg, crank", &
    "  m3     = 22      ! kg, lever", &
    "  m5     = 60      ! kg, ram", &
    "  j3     = 1.1     ! kg*m^2, lever about S3", &
    "  omega1 = 7.5     ! rad/s, crank speed (constant; + = CCW)", &
    "  g      = 9.81    ! m/s^2, gravity (optional, default 9.81; 0 = off)", &
    "  phi_start = 0    ! deg, first crank angle from +x (optional, default 0)", &
    "  dphi   = 30      ! deg, crank step (> 0)", &
    "  ! n    = 13      ! steps (optional; default 360/dphi + 1)", &
    "  ! cutting force F5c, N, signed along +y: either per step, f5c = v1, v2, ... (n values)", &
    "  ! or the two-value form below (f5c_idle optional, default 0):", &
    "  f5c_work = 3000  ! N, for crank angles in [phi_cut_start, phi_cut_end] (mod 360)", &
    "  f5c_idle = 0     ! N, elsewhere", &
    "  phi_cut_start = 95   ! deg", &
    "  phi_cut_end   = 265  ! deg", &
    "  ! machine dynamics (optional): dynamics = 'none' (default), 'reduced' (J_red, M_red", &
    "  ! columns), 'steady' (flywheel for delta; omega1 = mean speed) or 'given' (j_flywheel)", &
    "  ! dynamics = 'steady', delta = 0.04, j_rotor = 0.6   ! -, kg*m^2", &
    "  ! flywheel_density = 7800, flywheel_width_ratio = 0.2   ! kg/m^3, b/D of the flywheel's disc", &
    "/"]

contains

  !> Two-value cutting force at crank angle `phi_deg` (deg): `work` inside
  !> [start, end] taken counter-clockwise modulo 360, `idle` elsewhere.
  pure function pr3207_cut_force(phi_deg, start, end, work, idle) result(f)
    real(wp), intent(in) :: phi_deg, start, end, work, idle
    real(wp) :: f
    real(wp), parameter :: angle_tol = 1.0e-9_wp
    real(wp) :: span, offset
    span = end - start
    f = idle
    if (span >= 360.0_wp) then
      f = work
      return
    end if
    span = modulo(span, 360.0_wp)
    offset = modulo(phi_deg - start, 360.0_wp)
    if (offset <= span + angle_tol .or. offset >= 360.0_wp - angle_tol) f = work
  end function pr3207_cut_force

  !> Read and validate a `&pr3207` deck.
  subroutine read_pr3207_deck(source, deck, error)
    !> The deck, read into memory (see load_deck).
    type(deck_source_t), intent(in) :: source
    !> The validated deck.
    type(pr3207_deck_t), intent(out) :: deck
    !> Input error naming file, group, variable and reason.
    type(error_t), allocatable, intent(out) :: error
    real(wp) :: l_ab, l_ac, l_cd, l_cs3, m1, m3, m5, j3, omega1, g, phi_start, dphi
    real(wp) :: f5c_work, f5c_idle, phi_cut_start, phi_cut_end, delta, j_rotor, j_flywheel, &
      flywheel_density, flywheel_width_ratio
    !> The driving-moment table (pairs phi deg, M_d; see kinetostat_dynamics_deck).
    real(wp) :: md_table(md_table_capacity)
    character(len=text_bytes * text_chars) :: dynamics
    real(wp), allocatable :: f5c(:)
    !> Number of steps as given (an integer deck variable, read as a real: see require_whole).
    real(wp) :: n
    integer :: n_f5c
    type(deck_context_t) :: ctx
    type(deck_rules_t) :: rules
    type(namelist_probe_t) :: probe
    logical :: two_value_given
    namelist /pr3207/ l_ab, l_ac, l_cd, l_cs3, m1, m3, m5, j3, omega1, g, phi_start, dphi, n, &
      f5c, f5c_work, f5c_idle, phi_cut_start, phi_cut_end, dynamics, delta, j_rotor, j_flywheel, md_table, &
      flywheel_density, flywheel_width_ratio

    call begin_group(source, "pr3207", ctx, error, rules)
    if (allocated(error)) return
    ! a stage this kind lacks: the reason and the way out, before the READ
    call refuse_translated_stages(source, "pr3207", " but f5c", error)
    if (allocated(error)) return
    l_ab = unset_real; l_ac = unset_real; l_cd = unset_real; l_cs3 = unset_real
    m1 = unset_real; m3 = unset_real; m5 = unset_real; j3 = unset_real
    omega1 = unset_real; g = unset_real; phi_start = unset_real; dphi = unset_real
    f5c_work = unset_real; f5c_idle = unset_real; phi_cut_start = unset_real; phi_cut_end = unset_real
    n = unset_real
    call begin_dynamics_settings(probe, dynamics, delta, j_rotor, j_flywheel, md_table, flywheel_density, &
      flywheel_width_ratio)
    call probe%per_step(source, ctx, "f5c", f5c, error)
    if (allocated(error)) return

    read (source%records, nml=pr3207, iostat=probe%ios, iomsg=probe%msg)
    do while (probe%retry(source)) ! on failure: find the line and the assignment
      read (probe%records, nml=pr3207, iostat=probe%ios, iomsg=probe%msg)
    end do
    if (probe%failed(source, ctx, error)) return

    ! every missing required variable in one message
    call rules%require_all_set([character(len=6) :: "l_ab", "l_ac", "l_cd", "l_cs3", "m1", "m3", "m5", "j3", "omega1", "dphi"], &
      [l_ab, l_ac, l_cd, l_cs3, m1, m3, m5, j3, omega1, dphi])

    ! lengths, masses, inertia, speed
    call rules%require_each(rule_positive, [character(4) :: "l_ab", "l_ac", "l_cd"], [l_ab, l_ac, l_cd])
    call rules%require_each(rule_nonnegative, [character(5) :: "l_cs3", "m1", "m3", "m5", "j3"], &
      [l_cs3, m1, m3, m5, j3])
    call rules%require_set("omega1", omega1)
    g = optional_default(g, g_default)
    call rules%require_nonnegative("g", g)
    call rules%require_rule("l_ab", l_ab < l_ac, "must be < l_ac (got l_ab = "//real_str(l_ab)// &
      ", l_ac = "//real_str(l_ac)//"): the lever must oscillate, the crank must not reach C")
    call rules%require_rule("l_cd", l_cd > l_ac + l_ab, "must be > l_ac + l_ab = "// &
      real_str(l_ac + l_ab)//" (got "//real_str(l_cd)//"): D must pass beyond the crank circle")

    ! crank angles
    call rules%crank_steps(phi_start, dphi, n, deck%n)
    if (rules%failed(error)) return

    ! cutting force: per-step array or the two-value form, not both
    call rules%count_values("f5c", f5c, n_f5c)
    two_value_given = any(is_set([f5c_work, f5c_idle, phi_cut_start, phi_cut_end]))
    call rules%require_rule("f5c", n_f5c == 0 .or. .not. two_value_given, "give either f5c(:) or "// &
      "f5c_work/f5c_idle/phi_cut_start/phi_cut_end, not both")
    call rules%require_rule("f5c", n_f5c > 0 .or. two_value_given, "missing: give f5c(:) per step or f5c_work "// &
      "with phi_cut_start, phi_cut_end")
    if (n_f5c > 0) then
      call rules%require_per_step("f5c", n_f5c, deck%n)
      if (rules%failed(error)) return
      ! the read buffer is the deck's array (no second copy)
      call move_alloc(f5c, deck%f5c_values)
    else
      call rules%require_set("f5c_work", f5c_work)
      f5c_idle = optional_default(f5c_idle, 0.0_wp)
      call rules%require_each(rule_finite, [character(13) :: "f5c_idle", "phi_cut_start", "phi_cut_end"], &
        [f5c_idle, phi_cut_start, phi_cut_end])
      if (rules%failed(error)) return
      deck%two_value = .true.
      deck%f5c_work = f5c_work
      deck%f5c_idle = f5c_idle
      deck%phi_cut_start = phi_cut_start
      deck%phi_cut_end = phi_cut_end
    end if

    ! machine dynamics: a steady cycle needs one whole turn and the load at any crank angle
    call read_dynamics_settings(ctx, dynamics, delta, j_rotor, j_flywheel, omega1, deck%dyn, error, &
      md_table=md_table, flywheel_density=flywheel_density, flywheel_width_ratio=flywheel_width_ratio)
    if (allocated(error)) return
    if (deck%dyn%mode >= dynamics_steady) then
      call require_one_turn(ctx, dphi, deck%n, error); if (allocated(error)) return
      call rules%require_rule("f5c", deck%two_value, "a steady cycle needs the cutting force at every crank "// &
        "angle: give it in the two-value form (f5c_work, phi_cut_start, phi_cut_end), not per step")
      if (rules%failed(error)) return
    end if

    deck%p = pr3207_params_t(l_ab=l_ab, l_ac=l_ac, l_cd=l_cd, l_cs3=l_cs3, m1=m1, m3=m3, m5=m5, &
                             j3=j3, omega1=omega1, g=g)
    deck%phi_start = phi_start
    deck%dphi = dphi
  end subroutine read_pr3207_deck


  !> Cutting force of step k, N (along +y): as given per step, or from the two-value form
  !> at the step's crank angle (pr3207_cut_force).
  pure real(wp) function pr3207_f5c(deck, k) result(f)
    !> Validated deck.
    type(pr3207_deck_t), intent(in) :: deck
    !> Step number, 1..n.
    integer, intent(in) :: k
    if (deck%two_value) then
      f = pr3207_cut_force(pr3207_phi1_deg(deck, k), deck%phi_cut_start, deck%phi_cut_end, deck%f5c_work, &
                           deck%f5c_idle)
    else
      f = deck%f5c_values(k)
    end if
  end function pr3207_f5c

  !> The cutting force of every step, N (for the load-edge marks: a temporary of n values).
  pure function pr3207_f5c_steps(deck) result(f)
    !> Validated deck.
    type(pr3207_deck_t), intent(in) :: deck
    !> One value per step, N.
    real(wp) :: f(deck%n)
    !> Step number.
    integer :: k
    do k = 1, deck%n
      f(k) = pr3207_f5c(deck, k)
    end do
  end function pr3207_f5c_steps

end module kinetostat_pr3207_deck
