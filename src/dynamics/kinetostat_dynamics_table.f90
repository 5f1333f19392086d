!> The machine dynamics in the step table, alike for every mechanism: the per-step columns
!> (J_red, dJ_red, M_red; with a steady cycle also dT, omega1, eps1, t), the figures of the
!> cycle (the DYNAMICS block and JSON "dynamics") and the self-check M1 = M_d.
module kinetostat_dynamics_table
  use kinetostat_kinds, only: wp, rad_to_deg
  use kinetostat_step_table, only: step_table_t, column_t, column, col_moment, col_component, col_other
  use kinetostat_run_tally, only: dynamics_figures_t
  use kinetostat_dynamics, only: cycle_t, motion_t, dynamics_none, dynamics_reduced, dynamics_steady, dynamics_given
  use kinetostat_dynamics_deck, only: dynamics_deck_t, dynamics_mode_name
  implicit none
  private
  public :: note_constant_speed_cost, note_constant_speed_costs, echo_dynamics, add_dynamics_columns, put_dynamics_values, &
    put_dynamics_rows, put_dynamics_figures, note_drive_deviation

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
    if (dyn%cycle_deg /= 360.0_wp) call table%echo_real("CYCLE", dyn%cycle_deg, "deg (two turns)")
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
    call table%declare_columns(dynamics_columns(mode, optional_true(translating)))
  end subroutine add_dynamics_columns

  !> The dynamics columns of `mode` (none for dynamics_none), in the order of
  !> put_dynamics_values; `translating`: J_red a mass (kg), dJ_red in kg/m, M_red a force (N).
  pure function dynamics_columns(mode, translating) result(cols)
    !> dynamics_* mode.
    integer, intent(in) :: mode
    !> The input translates.
    logical, intent(in) :: translating
    type(column_t), allocatable :: cols(:)
    allocate (cols(0))
    if (mode == dynamics_none) return
    if (translating) then
      cols = [column("J_red", "kg", col_other), column("dJ_red", "kg/m", col_other, unit_ru="кг/м"), &
              column("M_red", "N", col_component)]
      return
    end if
    cols = [column("J_red", "kg*m^2", col_other), column("dJ_red", "kg*m^2/rad", col_other, unit_ru="кг*м^2/рад"), &
            column("M_red", "N*m", col_moment)]
    if (mode == dynamics_reduced) return
    cols = [cols, column("dT", "J", col_other), column("omega1", "rad/s", col_other), &
            column("eps1", "rad/s^2", col_other), column("t", "s", col_other), column("A_Md", "J", col_other), &
            column("A_red", "J", col_other), column("T_I", "J", col_other)]
  end function dynamics_columns

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

  !> put_dynamics_values for every row of the block (row k from motions(k)).
  pure subroutine put_dynamics_rows(table, mode, motions)
    type(step_table_t), intent(inout) :: table
    !> dynamics_* mode.
    integer, intent(in) :: mode
    !> The motion and the reduced quantities of every row.
    type(motion_t), intent(in) :: motions(:)
    integer :: k
    do k = 1, size(motions)
      call put_dynamics_values(table, k, mode, motions(k))
    end do
  end subroutine put_dynamics_rows

  !> The figures of a solved cycle (first block only); `delta_asked` > 0 with 'steady'.
  pure subroutine put_dynamics_figures(table, mode, cycle, delta_asked)
    type(step_table_t), intent(inout) :: table
    integer, intent(in) :: mode
    type(cycle_t), intent(in) :: cycle
    real(wp), intent(in) :: delta_asked
    type(dynamics_figures_t) :: d
    if (mode < dynamics_steady .or. .not. table%first_block()) return
    d%present = .true.
    d%drive_table = allocated(cycle%drive_m)
    if (d%drive_table) then
      ! a driving-moment table: its mean, the scale it was given and its extremes
      d%m_d = -cycle%load_work / cycle%span
      d%m_d_scale = cycle%drive_scale
      d%m_d_max = maxval(cycle%drive_m)
      d%m_d_min = minval(cycle%drive_m)
    else
      d%m_d = cycle%m_d
    end if
    d%j_rotor = cycle%j_rotor
    d%j_red_min = minval(cycle%j)
    d%j_red_max = maxval(cycle%j)
    d%j_flywheel = cycle%j_flywheel
    d%flywheel_density = cycle%flywheel_density
    d%flywheel_width_ratio = cycle%flywheel_width_ratio
    ! the textbook's flywheel only where a delta defines it
    if (cycle%delta > 0.0_wp) d%j_flywheel_textbook = cycle%j_flywheel_textbook
    d%omega_mean = cycle%omega_mean
    d%omega_max = cycle%omega_max
    d%phi_omega_max = cycle%phi_max * rad_to_deg
    d%omega_min = cycle%omega_min
    d%phi_omega_min = cycle%phi_min * rad_to_deg
    d%delta_asked = max(0.0_wp, delta_asked)
    d%delta = cycle%delta
    d%period = cycle%period
    table%dynamics = d
  end subroutine put_dynamics_figures

  !> The self-check of the true motion for the rows of the block, the one place it is
  !> computed: the largest |M1 - M_d| and the moment scale (the largest of |M_d|, |M_red| and
  !> |(J_flywheel + J_red) eps1|), noted apart for the run pipeline to reduce over the run
  !> as max(|M1 - M_d|) / max(scale) (kinetostat_run_tally's ratio_of_maxima_t).
  pure subroutine note_drive_deviation(table, m1, motions, j_flywheel)
    type(step_table_t), intent(inout) :: table
    !> The driving moment of the block's rows with the true motion, N*m.
    real(wp), intent(in) :: m1(:)
    !> The true motion at those rows (M_d, M_red, J_red, eps1).
    type(motion_t), intent(in) :: motions(:)
    !> The flywheel's inertia, kg*m^2.
    real(wp), intent(in) :: j_flywheel
    if (size(m1) == 0) return
    call table%block_tally%drive_deviation%note(maxval(abs(m1 - motions%md)), max(maxval(abs(motions%md)), &
      maxval(abs(motions%m)), maxval(abs((j_flywheel + motions%j) * motions%eps))))
  end subroutine note_drive_deviation

  !> What the constant-speed assumption costs for one force column: its peak over the block
  !> with the true motion and with omega1 = omega_m constant, noted for the run pipeline to
  !> take the largest over the run (DYNAMICS block records <name>_peak,
  !> <name>_peak_constant_speed, <name>_peak_difference: step_table_t%dynamics_records).
  pure subroutine note_constant_speed_cost(table, name, peak_true, peak_const)
    type(step_table_t), intent(inout) :: table
    !> Force column ("F16").
    character(*), intent(in) :: name
    !> Largest magnitude of the block with the true motion, N.
    real(wp), intent(in) :: peak_true
    !> The same at constant speed, N.
    real(wp), intent(in) :: peak_const
    call table%block_tally%note_peak(name, peak_true, peak_const)
  end subroutine note_constant_speed_cost

  !> note_constant_speed_cost for every force of `names`.
  pure subroutine note_constant_speed_costs(table, names, peak_true, peak_const)
    type(step_table_t), intent(inout) :: table
    !> Force columns ("F16", ...), blank-padded.
    character(*), intent(in) :: names(:)
    !> Largest magnitude of each force over the block with the true motion, N.
    real(wp), intent(in) :: peak_true(:)
    !> The same at constant speed, N.
    real(wp), intent(in) :: peak_const(:)
    integer :: i
    do i = 1, size(names)
      call note_constant_speed_cost(table, trim(names(i)), peak_true(i), peak_const(i))
    end do
  end subroutine note_constant_speed_costs

  !> An optional logical's value, false when absent.
  pure logical function optional_true(flag)
    logical, intent(in), optional :: flag
    optional_true = .false.
    if (present(flag)) optional_true = flag
  end function optional_true

end module kinetostat_dynamics_table
