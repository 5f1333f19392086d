!> PR 3207 as a mechanism of the run pipeline: deck -> every crank step -> step table, and
!> the legacy table layout of the 1991 printout (two lines per step).
module kinetostat_pr3207_layout
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_kinds, only: wp, deg_to_rad, rad_to_deg
  use kinetostat_deck, only: deck_source_t
  use kinetostat_error, only: error_t
  use kinetostat_noise, only: noise_floor, force_columns, angles_0_360
  use kinetostat_step_table, only: step_table_t, column_t, column, col_input_angle, col_moment, step_span, lack_block_memory
  use kinetostat_labels, only: lang_ru
  use kinetostat_table_layout, only: table_field_t, field, magnitudes_over_angles, forces_and_angles, &
    results_page_t, put_layout_block, echo_reals, echo_steps
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_mechanism, only: mechanism_t
  use kinetostat_sketch, only: sketch_t
  use kinetostat_pr3207, only: pr3207_params_t, pr3207_position_t, pr3207_step_t, pr3207_step, pr3207_position, &
    pr3207_step_at
  use kinetostat_pr3207_deck, only: pr3207_deck_t, read_pr3207_deck, pr3207_template, pr3207_phi1_deg, &
    pr3207_f5c, pr3207_f5c_steps
  use kinetostat_drawing, only: drawing_t, force_load
  use kinetostat_bodies, only: mass_model_t
  use kinetostat_dynamics, only: cycle_t, motion_t, dynamics_steady
  use kinetostat_dynamics_table, only: note_constant_speed_costs, echo_dynamics, add_dynamics_columns, &
    put_dynamics_rows, put_dynamics_figures, &
    note_drive_deviation
  use kinetostat_pr3207_dynamics, only: pr3207_cycle, pr3207_motion
  implicit none
  private
  public :: pr3207_mechanism_t, new_pr3207, pr3207_solve, pr3207_columns, pr3207_csv_values

  !> Pair forces, in the order of the columns (each a magnitude and an angle column).
  character(*), parameter :: force_names(*) = [character(len=3) :: "F16", "F21", "F36", "F34", "F56"]
  !> Number of columns of a step's row (pr3207_columns).
  integer, parameter :: row_size = 2 + 2 * size(force_names)

  !> Title lines of the legacy table (English, Russian).
  character(*), parameter :: title_en = "KINETOSTAT  PR 3207  FORCE ANALYSIS OF THE SIX-BAR SLOTTED-LINK (SHAPER) MECHANISM", &
    title_ru = "KINETOSTAT  PR 3207  СИЛОВОЙ РАСЧЕТ ШЕСТИЗВЕННОГО" // &
      " КУЛИСНОГО МЕХАНИЗМА (ПОПЕРЕЧНО-СТРОГАЛЬНОГО)"

  !> PR 3207: six-bar slotted-link (shaper) mechanism, manual section 3.
  type, extends(mechanism_t) :: pr3207_mechanism_t
    !> The validated deck (PR 3207 card images).
    type(pr3207_deck_t) :: deck
    !> The steady cycle (dynamics = 'steady' or 'given').
    type(cycle_t) :: cycle
  contains
    procedure :: load_deck, prepare, solve, put_results, sketch, force_plan, mass_model
  end type pr3207_mechanism_t

contains

  !> A new mechanism of this kind (the registry's constructor).
  subroutine new_pr3207(mech)
    !> The mechanism.
    class(mechanism_t), allocatable, intent(out) :: mech
    allocate (pr3207_mechanism_t :: mech)
    call mech%describe(pr3207_template, title_en, title_ru, "", &
      "Six-bar slotted-link mechanism of a shaper", &
      "Шестизвенный кулисный механизм поперечно-строгального станка")
  end subroutine new_pr3207

  subroutine load_deck(self, source, error)
    class(pr3207_mechanism_t), intent(inout) :: self
    type(deck_source_t), intent(in) :: source
    type(error_t), allocatable, intent(out) :: error
    call read_pr3207_deck(source, self%deck, error)
  end subroutine load_deck

  !> The steady cycle of a deck with dynamics = 'steady' or 'given'.
  subroutine prepare(self, path, error)
    class(pr3207_mechanism_t), intent(inout) :: self
    character(*), intent(in) :: path
    type(error_t), allocatable, intent(out) :: error
    if (self%deck%dyn%mode >= dynamics_steady) call pr3207_cycle(self%deck, path, self%cycle, error)
  end subroutine prepare

  !> The topology for a drawing: crank A-B, block 2 at B sliding along the lever C-D, block 4
  !> at D sliding along x in the ram's slot, the ram from its guide (x = 0, along y) to D;
  !> pivots A, C; gravity along +x.
  pure subroutine sketch(self, out)
    class(pr3207_mechanism_t), intent(in) :: self
    type(sketch_t), intent(out) :: out
    call out%add_link("1", [character(len=2) :: "A", "B"])
    call out%add_link("2", ["B"], 0.0_wp, "3")
    call out%add_link("3", [character(len=2) :: "C", "D"])
    call out%add_link("4", ["D"], 0.0_wp, "")
    call out%add_link("5", [character(len=2) :: "S5", "D"])
    call out%add_pivot("A")
    call out%add_pivot("C")
    call out%add_guide("S5", 90.0_wp, "")
    call out%add_guide("D", 0.0_wp, "5")
    out%down = [1.0_wp, 0.0_wp]
  end subroutine sketch

  !> All steps of a validated deck (in parallel with OpenMP threads); with a steady `cycle`,
  !> at the true crank speed and acceleration, with the flywheel and rotor on the crank.
  subroutine pr3207_solve(deck, steps, first, last, cycle, motions, const, error)
    !> Validated deck.
    type(pr3207_deck_t), intent(in) :: deck
    !> One result per crank step (of steps first..last).
    type(pr3207_step_t), allocatable, intent(out) :: steps(:)
    !> Steps to compute (default: all).
    integer, intent(in), optional :: first, last
    !> The deck's steady cycle (dynamics = 'steady' or 'given').
    type(cycle_t), intent(in), optional :: cycle
    !> The motion and reduced quantities of each step (with `cycle`).
    type(motion_t), allocatable, intent(out), optional :: motions(:)
    !> With a steady cycle, the same steps at the constant speed omega1 = omega_m (as without
    !> `cycle`), from the same positions.
    type(pr3207_step_t), allocatable, intent(out), optional :: const(:)
    !> The block's results do not fit in memory (exit 2).
    type(error_t), allocatable, intent(out), optional :: error
    type(motion_t) :: mo
    type(pr3207_position_t) :: pos
    integer :: k, k1, k2, stat
    call step_span(deck%n, k1, k2, first, last)
    allocate (steps(k2 - k1 + 1), stat=stat)
    if (stat == 0 .and. present(motions)) allocate (motions(k2 - k1 + 1), stat=stat)
    if (stat == 0 .and. present(const)) allocate (const(k2 - k1 + 1), stat=stat)
    if (stat /= 0) then
      if (present(error)) call lack_block_memory(error, k2 - k1 + 1, 3_int64 * storage_size(steps) / 8)
      return
    end if
    if (.not. present(cycle)) then
      !$omp parallel do schedule(static)
      do k = k1, k2
        steps(k - k1 + 1) = pr3207_step(deck%p, pr3207_phi1_deg(deck, k) * deg_to_rad, pr3207_f5c(deck, k))
      end do
      !$omp end parallel do
      return
    end if
    !$omp parallel do schedule(static) private(mo, pos)
    do k = k1, k2
      pos = pr3207_position(deck%p, pr3207_phi1_deg(deck, k) * deg_to_rad)
      mo = pr3207_motion(deck, cycle, k, pos)
      if (present(motions)) motions(k - k1 + 1) = mo
      if (deck%dyn%mode >= dynamics_steady) then
        steps(k - k1 + 1) = pr3207_step_at(deck%p, pos, pr3207_f5c(deck, k), mo%omega, mo%eps, &
                                           cycle%j_flywheel + cycle%j_rotor)
        if (present(const)) const(k - k1 + 1) = pr3207_step_at(deck%p, pos, pr3207_f5c(deck, k))
      else
        steps(k - k1 + 1) = pr3207_step_at(deck%p, pos, pr3207_f5c(deck, k))
      end if
    end do
    !$omp end parallel do
  end subroutine pr3207_solve

  !> The block's crank steps into the step table (with a steady cycle at the true crank
  !> speed, with its costs and the drive's deviation); the echo with the first block.
  subroutine solve(self, table, error)
    class(pr3207_mechanism_t), intent(in) :: self
    type(step_table_t), intent(inout) :: table
    type(error_t), allocatable, intent(out) :: error
    type(pr3207_step_t), allocatable :: steps(:), const(:)
    type(motion_t), allocatable :: motions(:)
    integer :: k, first, last
    call table%block_range(self%deck%n, first, last)
    if (self%deck%dyn%mode > 0) then
      call pr3207_solve(self%deck, steps, first, last, self%cycle, motions, const, error)
    else
      call pr3207_solve(self%deck, steps, first, last, error=error)
    end if
    if (allocated(error)) return
    if (table%first_block()) then
      call table%declare_columns(pr3207_columns())
      call add_dynamics_columns(table, self%deck%dyn%mode)
      call put_dynamics_figures(table, self%deck%dyn%mode, self%cycle, self%deck%dyn%delta)
      table%input_column = 1
      if (self%deck%two_value) then
        call table%note_load(pr3207_f5c_steps(self%deck))
      else
        call table%note_load(self%deck%f5c_values(1:self%deck%n))
      end if
      call echo_deck(self%deck, table)
    end if
    call table%allocate_rows(size(steps), error)
    if (allocated(error)) return
    !$omp parallel do schedule(static)
    do k = 1, size(steps)
      table%rows(1:row_size, k) = pr3207_csv_values(steps(k), self%deck%p%l_ab, table%force_angles_wanted)
    end do
    !$omp end parallel do
    if (allocated(motions)) then
      call put_dynamics_rows(table, self%deck%dyn%mode, motions)
      if (self%deck%dyn%mode >= dynamics_steady) call constant_speed_cost(steps, const, table)
      if (self%deck%dyn%mode >= dynamics_steady) call note_drive_deviation(table, [steps%m1], motions, &
        self%cycle%j_flywheel)
    end if
    if (table%kinematics_wanted) call put_kinematics(table, self%deck%p, steps)
    call table%set_selfcheck_rows([steps%residual], [steps%mismatch], "M1")
  end subroutine solve

  !> The peaks of the pair forces with the true motion against those at omega1 = omega_m.
  subroutine constant_speed_cost(steps, const, table)
    !> The steps of the block with the true motion.
    type(pr3207_step_t), intent(in) :: steps(:)
    !> The same steps at constant speed.
    type(pr3207_step_t), intent(in) :: const(:)
    type(step_table_t), intent(inout) :: table
    real(wp) :: peak(size(force_names)), peak_const(size(force_names))
    integer :: k
    peak = 0.0_wp
    peak_const = 0.0_wp
    do k = 1, size(steps)
      peak = max(peak, norm2(pair_forces(steps(k)), dim=1))
      peak_const = max(peak_const, norm2(pair_forces(const(k)), dim=1))
    end do
    call note_constant_speed_costs(table, force_names, peak, peak_const)
  end subroutine constant_speed_cost

  !> The pair forces of a step, in the order of force_names, N.
  pure function pair_forces(s) result(f)
    type(pr3207_step_t), intent(in) :: s
    real(wp) :: f(2, size(force_names))
    f = reshape([s%f16, s%f21, s%f36, s%f34, s%f56], [2, size(force_names)])
  end function pair_forces

  !> The columns of a step, in the spec's order: the crank angle, every pair force's
  !> magnitude and angle, the driving moment.
  pure function pr3207_columns() result(cols)
    type(column_t), allocatable :: cols(:)
    cols = [column("phi1", "deg", col_input_angle, heading="PHI1")]
    cols = [cols, forces_and_angles(force_names)]
    cols = [cols, column("M1", "N*m", col_moment, heading="M1")]
  end function pr3207_columns

  !> The row of values of one step. Forces below `noise_rel` times the step's largest
  !> force (and M1 below that force times l_AB) are roundoff: printed as 0 with angle 0.
  pure function pr3207_csv_values(s, l_ab, angles) result(v)
    !> One computed step.
    type(pr3207_step_t), intent(in) :: s
    !> Crank length, m (moment scale).
    real(wp), intent(in) :: l_ab
    !> Whether the forces' angles are computed (default true; else 0).
    logical, intent(in), optional :: angles
    real(wp) :: v(row_size)
    real(wp) :: floor, f(2, size(force_names))
    f = pair_forces(s)
    floor = noise_floor(f, [real(wp) ::])
    v(1) = s%phi1 * rad_to_deg
    v(2:11) = force_columns(f, floor, angles_0_360, angles)
    v(12) = s%m1
    if (abs(v(12)) <= floor * l_ab) v(12) = 0.0_wp
  end function pr3207_csv_values

  !> The kinematics columns of the block's steps (frame: origin A, x from A to C): joints A, B, C, D
  !> and centres of mass S1 (= A), S3, S5 (the ram's, taken on the line x = 0 through A, as
  !> the generic twin deck does: only its travel y5 = y_D is defined); links 1 (crank), 2
  !> (block, turns with the lever) and 3 (lever); accelerations of S1, S3, S5; components of
  !> the pair forces in the same frame. Block 4 and the ram 5 translate (no angle columns).
  pure subroutine put_kinematics(table, p, steps)
    !> The step table (columns appended on first use).
    type(step_table_t), intent(inout) :: table
    !> Lengths, masses and the crank speed of PR 3207.
    type(pr3207_params_t), intent(in) :: p
    !> The block's computed steps, one a row.
    type(pr3207_step_t), intent(in) :: steps(:)
    type(pr3207_position_t) :: pos
    real(wp) :: w2, f(2, size(force_names)), floor
    integer :: k
    do k = 1, size(steps)
      associate (s => steps(k))
        pos = pr3207_position(p, s%phi1)
        w2 = s%omega1**2
        call table%put_point(k, "A", [0.0_wp, 0.0_wp])
        call table%put_point(k, "B", pos%b)
        call table%put_point(k, "C", [p%l_ac, 0.0_wp])
        call table%put_point(k, "D", pos%d)
        call table%put_point(k, "S1", [0.0_wp, 0.0_wp])
        call table%put_point(k, "S3", pos%s3)
        call table%put_point(k, "S5", [0.0_wp, pos%y5])
        call table%put_link(k, "1", s%phi1, s%omega1, s%eps1)
        call table%put_link(k, "2", pos%phi3, pos%u31 * s%omega1, s%eps3)
        call table%put_link(k, "3", pos%phi3, pos%u31 * s%omega1, s%eps3)
        call table%put_acceleration(k, "S1", [0.0_wp, 0.0_wp])
        call table%put_acceleration(k, "S3", pos%a_s3q * w2 + pos%v_s3q * s%eps1)
        call table%put_acceleration(k, "S5", [0.0_wp, s%a5])
        f = pair_forces(s)
        floor = noise_floor(f, [real(wp) ::])
        call table%put_pair_components(k, force_names, f, floor)
      end associate
    end do
  end subroutine put_kinematics

  !> The INPUT DATA echo of the deck, in the order of its cards: lengths, masses, the
  !> lever's inertia, the crank speed, g, the steps and the cutting force.
  pure subroutine echo_deck(deck, table)
    type(pr3207_deck_t), intent(in) :: deck
    type(step_table_t), intent(inout) :: table
    associate (p => deck%p)
      call echo_reals(table, [character(len=5) :: "L_AB", "L_AC", "L_CD", "L_CS3"], [p%l_ab, p%l_ac, p%l_cd, p%l_cs3], "m")
      call echo_reals(table, [character(len=2) :: "M1", "M3", "M5"], [p%m1, p%m3, p%m5], "kg")
      call table%echo_real("J3", p%j3, "kg*m^2")
      call table%echo_real("OMEGA1", p%omega1, "rad/s")
      call table%echo_real("G", p%g, "m/s^2")
    end associate
    call echo_steps(table, deck%phi_start, deck%dphi, deck%n)
    if (deck%two_value) then
      call echo_reals(table, [character(len=8) :: "F5C_WORK", "F5C_IDLE"], [deck%f5c_work, deck%f5c_idle], "N")
      call echo_reals(table, [character(len=13) :: "PHI_CUT_START", "PHI_CUT_END"], &
        [deck%phi_cut_start, deck%phi_cut_end], "deg")
    else
      call table%echo_array("F5C", deck%f5c_values(1:deck%n), "N")
    end if
    call echo_dynamics(table, deck%dyn)
  end subroutine echo_deck

  !> RESULTS: header, then per step the magnitudes (with the crank angle and M1) and under
  !> them the angles, fields 9 and 12 wide as in the original printout.
  pure subroutine put_results(self, table, page, out, later)
    class(pr3207_mechanism_t), intent(in) :: self
    type(step_table_t), intent(in) :: table
    type(results_page_t), intent(in) :: page
    type(text_buffer_t), intent(inout) :: out, later
    ! the crank angle (9 wide), the magnitudes and M1 (12 wide), under them the angles; the
    ! Russian printout's angle units stand one place right of their fields
    call put_layout_block(out, table, page, magnitudes_over_angles("phi1", force_names, force_names, &
      [field("M1", 12, 3)]), .true., unit_shift=[0, merge(1, 0, page%lang == lang_ru)])
  end subroutine put_results

  !> The moving links: crank 1 (its mass at the pivot A, no inertia given), lever 3 at S3,
  !> ram 5 at S5 (translating); the blocks 2 and 4 are massless. Gravity along +x.
  pure subroutine mass_model(self, model)
    class(pr3207_mechanism_t), intent(in) :: self
    type(mass_model_t), intent(out) :: model
    call model%add("1", "S1", self%deck%p%m1, 0.0_wp)
    call model%add("3", "S3", self%deck%p%m3, self%deck%p%j3)
    call model%add("5", "S5", self%deck%p%m5, 0.0_wp)
    model%gravity = [self%deck%p%g, 0.0_wp]
    ! the ram's guide gives no line of action (PR 3207 computes no guide moment)
    call model%add_frame_pair("F16", "A", "")
    call model%add_frame_pair("F36", "C", "")
    call model%add_frame_pair("F56", "", "")
    model%drive = "M1"
  end subroutine mass_model

  !> The forces of row `k` on its drawing (--format svg --at K): the pair forces at their
  !> joints (F56 at the ram's S5), the cutting force F5c on the ram along y, the weights and
  !> inertia forces of links 1, 3 and 5, the inertia moment of the lever, and M1.
  pure subroutine force_plan(self, table, k, drawing, error)
    class(pr3207_mechanism_t), intent(in) :: self
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: k
    type(drawing_t), intent(inout) :: drawing
    type(error_t), allocatable, intent(out) :: error
    !> The points of the pair forces force_names.
    character(len=2), parameter :: pair_points(*) = [character(len=2) :: "A", "B", "C", "D", "S5"]
    type(mass_model_t) :: model
    associate (p => self%deck%p)
      call drawing%pairs_from_table(table, k, force_names, pair_points, error)
      if (allocated(error)) return
      call drawing%add_force("F5c", force_load, drawing%at("S5"), [0.0_wp, pr3207_f5c(self%deck, table%run_row(k))], "5")
      call self%mass_model(model)
      call drawing%add_body_loads(table, k, model)
      call drawing%add_moment("M1", force_load, drawing%at("A"), table%rows(table%column_index("M1"), k))
    end associate
  end subroutine force_plan

end module kinetostat_pr3207_layout
