!> The machine dynamics in the step table, alike for every mechanism: the per-step columns
!> (J_red, dJ_red, M_red; with a steady cycle also dT, omega1, eps1, t), the figures of the
!> cycle (the DYNAMICS block and JSON "dynamics") and the self-check M1 = M_d.
module kinetostat_dynamics_table
  use kinetostat_kinds, only: wp, rad_to_deg, pi
  use kinetostat_step_table, only: step_table_t, col_moment, col_component, col_other
  use kinetostat_dynamics, only: cycle_t, motion_t, dynamics_none, dynamics_reduced, dynamics_steady, dynamics_given
  use kinetostat_dynamics_deck, only: dynamics_deck_t, dynamics_mode_name
  implicit none
  private
  public :: note_constant_speed_cost, echo_dynamics, add_dynamics_columns, put_dynamics_values, put_dynamics_figures, &
    note_drive_deviation

  !> The DYNAMICS block's note on the flywheel's disc (a key of the labels' dictionary).
  character(*), parameter :: flywheel_disc_note = "a disc: J_flywheel = m D^2/8, m = density pi D^2 b/4, "// &
    "b = width_ratio D"
  !> The note when the machine has no flywheel.
  character(*), parameter :: flywheel_none_note = "no flywheel: J_flywheel = 0"

contains

  !> The INPUT DATA echo of the dynamics settings (nothing for dynamics = 'none'); with
  !> `translating` the input is a stroke (j_rotor a mass, kg) and the echo says so.
  pure subroutine echo_dynamics(table, dyn, translating)
    type(step_table_t), intent(inout) :: table
    type(dynamics_deck_t), intent(in) :: dyn
    !> The input translates (reduced to a stroke: mass, force); default false.
    logical, intent(in), optional :: translating
    if (dyn%mode == dynamics_none) return
    if (optional_true(translating)) then
      call table%echo_text("DYNAMICS", dynamics_mode_name(dyn%mode))
      call table%echo_text("REDUCED_TO", "the input stroke s: J_red in kg, dJ_red in kg/m, M_red in N")
      call table%echo_real("J_ROTOR", dyn%j_rotor, "kg (drive's mass reduced to the stroke)")
      return
    end if
    call table%echo_text("DYNAMICS", dynamics_mode_name(dyn%mode))
    if (dyn%mode == dynamics_steady) call table%echo_real("DELTA", dyn%delta, "")
    call table%echo_real("J_ROTOR", dyn%j_rotor, "kg*m^2")
    if (dyn%mode == dynamics_given) call table%echo_real("J_FLYWHEEL", dyn%j_flywheel, "kg*m^2")
  end subroutine echo_dynamics

  !> Append the dynamics columns of `mode` (nothing for dynamics_none); with `translating`
  !> (a stroke as the input, 'reduced' only) J_red is a mass (kg), dJ_red in kg/m, M_red a
  !> force (N).
  pure subroutine add_dynamics_columns(table, mode, translating)
    type(step_table_t), intent(inout) :: table
    !> dynamics_* mode.
    integer, intent(in) :: mode
    !> The input translates; default false.
    logical, intent(in), optional :: translating
    if (mode == dynamics_none) return
    if (optional_true(translating)) then
      call table%add_column("J_red", "kg", col_other)
      call table%add_column("dJ_red", "kg/m", col_other)
      call table%add_column("M_red", "N", col_component)
      return
    end if
    call table%add_column("J_red", "kg*m^2", col_other)
    call table%add_column("dJ_red", "kg*m^2/rad", col_other)
    call table%add_column("M_red", "N*m", col_moment)
    if (mode == dynamics_reduced) return
    call table%add_column("dT", "J", col_other)
    call table%add_column("omega1", "rad/s", col_other)
    call table%add_column("eps1", "rad/s^2", col_other)
    call table%add_column("t", "s", col_other)
    call table%add_column("A_Md", "J", col_other)
    call table%add_column("A_red", "J", col_other)
    call table%add_column("T_I", "J", col_other)
  end subroutine add_dynamics_columns

  !> The dynamics values of row `k` (the columns add_dynamics_columns made).
  pure subroutine put_dynamics_values(table, k, mode, motion)
    type(step_table_t), intent(inout) :: table
    integer, intent(in) :: k
    integer, intent(in) :: mode
    !> The motion and the reduced quantities at the row's input angle.
    type(motion_t), intent(in) :: motion
    integer :: c
    if (mode == dynamics_none) return
    c = table%column_index("J_red")
    table%rows(c:c + 2, k) = [motion%j, motion%dj, motion%m]
    if (mode == dynamics_reduced) return
    table%rows(c + 3:c + 9, k) = [motion%dt, motion%omega, motion%eps, motion%t, motion%a_md, motion%dt - motion%a_md, &
                                  motion%t_i]
  end subroutine put_dynamics_values

  !> The figures of a solved cycle (first block only); `delta_asked` > 0 with 'steady'.
  pure subroutine put_dynamics_figures(table, mode, cycle, delta_asked)
    type(step_table_t), intent(inout) :: table
    integer, intent(in) :: mode
    type(cycle_t), intent(in) :: cycle
    real(wp), intent(in) :: delta_asked
    if (mode < dynamics_steady .or. .not. table%first_block()) return
    if (allocated(cycle%drive_m)) then
      ! a driving-moment table: its mean, the scale it was given and its extremes
      call table%dynamics_real("M_d", -cycle%load_work / (2.0_wp * pi), "N*m")
      call table%dynamics_real("M_d_scale", cycle%drive_scale, "")
      call table%dynamics_real("M_d_max", maxval(cycle%drive_m), "N*m")
      call table%dynamics_real("M_d_min", minval(cycle%drive_m), "N*m")
    else
      call table%dynamics_real("M_d", cycle%m_d, "N*m")
    end if
    call table%dynamics_real("J_rotor", cycle%j_rotor, "kg*m^2")
    call table%dynamics_real("J_red_min", minval(cycle%j), "kg*m^2")
    call table%dynamics_real("J_red_max", maxval(cycle%j), "kg*m^2")
    call table%dynamics_real("J_flywheel", cycle%j_flywheel, "kg*m^2")
    call put_flywheel_disc(table, cycle)
    if (cycle%delta > 0.0_wp) then
      call table%dynamics_real("J_flywheel_textbook", cycle%j_flywheel_textbook, "kg*m^2")
      if (cycle%j_flywheel > 0.0_wp) call table%dynamics_real("textbook_difference", &
        100.0_wp * (cycle%j_flywheel_textbook - cycle%j_flywheel) / cycle%j_flywheel, "%")
    end if
    call table%dynamics_real("omega_mean", cycle%omega_mean, "rad/s")
    call table%dynamics_real("omega_max", cycle%omega_max, "rad/s")
    call table%dynamics_real("phi_omega_max", cycle%phi_max * rad_to_deg, "deg")
    call table%dynamics_real("omega_min", cycle%omega_min, "rad/s")
    call table%dynamics_real("phi_omega_min", cycle%phi_min * rad_to_deg, "deg")
    if (delta_asked > 0.0_wp) call table%dynamics_real("delta_asked", delta_asked, "")
    call table%dynamics_real("delta", cycle%delta, "")
    call table%dynamics_real("period", cycle%period, "s")
  end subroutine put_dynamics_figures

  !> The flywheel as a disc of the cycle's density rho and width ratio psi = b/D: J = m D^2/8
  !> with m = rho pi D^2 b/4 gives D = (32 J/(pi rho psi))^(1/5), b = psi D; no disc (null
  !> figures and a note) when the machine has no flywheel.
  pure subroutine put_flywheel_disc(table, cycle)
    type(step_table_t), intent(inout) :: table
    type(cycle_t), intent(in) :: cycle
    real(wp) :: d, b, rho, psi
    rho = cycle%flywheel_density
    psi = cycle%flywheel_width_ratio
    call table%dynamics_real("flywheel_density", rho, "kg/m^3")
    call table%dynamics_real("flywheel_width_ratio", psi, "")
    if (cycle%j_flywheel > 0.0_wp) then
      d = (32.0_wp * cycle%j_flywheel / (pi * rho * psi))**0.2_wp
      b = psi * d
      call table%dynamics_real("flywheel_D", d, "m")
      call table%dynamics_real("flywheel_b", b, "m")
      call table%dynamics_real("flywheel_m", rho * pi * d**2 * b / 4.0_wp, "kg")
      call table%dynamics_note("flywheel_note", flywheel_disc_note)
    else
      call table%dynamics_null("flywheel_D", "m")
      call table%dynamics_null("flywheel_b", "m")
      call table%dynamics_null("flywheel_m", "kg")
      call table%dynamics_note("flywheel_note", flywheel_none_note)
    end if
  end subroutine put_flywheel_disc

  !> The self-check of the true motion: the largest |M1 - M_d| / scale over the blocks so far.
  pure subroutine note_drive_deviation(table, worst, scale)
    type(step_table_t), intent(inout) :: table
    !> Largest |M1 - M_d| of the rows of the block, N*m.
    real(wp), intent(in) :: worst
    !> Moment scale: |M_d|, or the loads' and inertia's moments when M_d = 0, N*m.
    real(wp), intent(in) :: scale
    if (table%first_block()) table%max_drive_deviation = 0.0_wp
    if (scale > 0.0_wp) table%max_drive_deviation = max(table%max_drive_deviation, worst / scale)
  end subroutine note_drive_deviation

  !> What the constant-speed assumption costs for one force column: its peak over the run with
  !> the true motion and with omega1 = omega_m constant (the largest over the blocks so far),
  !> and their difference in percent of the constant-speed peak (DYNAMICS block records
  !> <name>_peak, <name>_peak_constant_speed, <name>_peak_difference).
  pure subroutine note_constant_speed_cost(table, name, peak_true, peak_const)
    type(step_table_t), intent(inout) :: table
    !> Force column ("F16").
    character(*), intent(in) :: name
    !> Largest magnitude of the block with the true motion, N.
    real(wp), intent(in) :: peak_true
    !> The same at constant speed, N.
    real(wp), intent(in) :: peak_const
    integer :: i
    real(wp) :: t, c
    i = table%dynamics_index(name//"_peak")
    if (i == 0) then
      call table%dynamics_real(name//"_peak", peak_true, "N")
      call table%dynamics_real(name//"_peak_constant_speed", peak_const, "N")
      call table%dynamics_real(name//"_peak_difference", 0.0_wp, "%")
      i = size(table%dynamics) - 2
    else
      table%dynamics(i)%values(1) = max(table%dynamics(i)%values(1), peak_true)
      table%dynamics(i + 1)%values(1) = max(table%dynamics(i + 1)%values(1), peak_const)
    end if
    t = table%dynamics(i)%values(1)
    c = table%dynamics(i + 1)%values(1)
    table%dynamics(i + 2)%values(1) = 0.0_wp
    if (c > 0.0_wp) table%dynamics(i + 2)%values(1) = 100.0_wp * (t - c) / c
  end subroutine note_constant_speed_cost

  !> An optional logical's value, false when absent.
  pure logical function optional_true(flag)
    logical, intent(in), optional :: flag
    optional_true = .false.
    if (present(flag)) optional_true = flag
  end function optional_true

end module kinetostat_dynamics_table
