!> T.FTN as a mechanism of the run pipeline: deck -> every crank step -> step table, and the
!> legacy table layout of appendix 2 (two lines per step).
module kinetostat_sixbar_layout
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_kinds, only: wp, pi, deg_to_rad, rad_to_deg
  use kinetostat_deck, only: deck_source_t
  use kinetostat_error, only: error_t, fatal_error, exit_geometry, out_of_memory
  use kinetostat_text, only: real_str, int_str
  use kinetostat_noise, only: noise_floor, force_columns, angles_pm180
  use kinetostat_step_table, only: step_table_t, column_t, column, col_input_angle, col_component, step_span, col_moment, &
    lack_block_memory
  use kinetostat_table_layout, only: table_field_t, field, magnitudes_over_angles, force_and_angle, &
    results_page_t, put_layout_block, echo_reals, echo_steps
  use kinetostat_labels, only: lang_ru
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_mechanism, only: mechanism_t
  use kinetostat_sketch, only: sketch_t
  use kinetostat_table_writer, only: put_heading
  use kinetostat_sixbar, only: sixbar_accel, sixbar_params_t, sixbar_step_t, sixbar_step, sixbar_ok, sixbar_open1, &
    sixbar_dead1, sixbar_open2, sixbar_dead2, sixbar_frame2_to_frame1, sixbar_down1, sixbar_reduced
  use kinetostat_sixbar_deck, only: sixbar_deck_t, read_sixbar_deck, sixbar_template, sixbar_phi1_deg
  use kinetostat_drawing, only: drawing_t, force_load
  use kinetostat_bodies, only: mass_model_t
  use kinetostat_dynamics, only: motion_t, cycle_t, dynamics_steady
  use kinetostat_dynamics_table, only: echo_dynamics, add_dynamics_columns, put_dynamics_rows, &
    put_dynamics_figures, note_drive_deviation, note_constant_speed_costs
  use kinetostat_sixbar_dynamics, only: sixbar_source_t, sixbar_source, sixbar_cycle, sixbar_motion
  implicit none
  private
  public :: sixbar_mechanism_t, new_sixbar, sixbar_solve, sixbar_columns, sixbar_csv_values

  !> Pair forces with an angle column (and the guide's F56), in the order of the columns.
  character(*), parameter :: force_names(*) = [character(len=3) :: "F21", "F32", "F43", "F45", "F36", "F16", "F56"]
  !> Whether a force of force_names is given in frame 2 (the others in frame 1).
  logical, parameter :: force_in_frame2(*) = [.false., .false., .true., .true., .false., .false., .true.]
  !> Number of columns of a step's row (sixbar_columns): phi1, six forces and angles, F56, M1.
  integer, parameter :: row_size = 3 + 2 * (size(force_names) - 1)
  !> Appendix 2's dotted rule under the header and after the last row.
  character(*), parameter :: dotted_rule = " "//repeat(".", 92)
  !> Legend under the Russian table (the original printed no unit lines).
  character(*), parameter :: legend_ru(*) = [character(len=160) :: &
    " F0 - ТЕКУЩИЙ УГОЛ ПОВОРОТА КРИВОШИПА (ОТ ОСИ X1), град; F21 ... F16 -" // &
      " МОДУЛИ СИЛ, Н;", &
    " F56 - СИЛА НА ПОЛЗУН 5 ОТ СТОЙКИ 6 (ПРОЕКЦИЯ НА ОСЬ Y2), Н;", &
    " F21G, F32G, F36G, F16G - УГЛЫ СИЛ ОТ ОСИ X1, F43G, F45G - ОТ ОСИ X2, град"]
  !> Heading of the driving moment block after the Russian table (T.FTN did not print M1).
  character(*), parameter :: moment_heading_ru = "ДВИЖУЩИЙ МОМЕНТ НА КРИВОШИПЕ 1"

  !> Title lines of the legacy table (English, Russian).
  character(*), parameter :: title_en = "KINETOSTAT  T.FTN  FORCE ANALYSIS OF THE SIX-BAR CRANK-ROCKER-SLIDER MECHANISM", &
    title_ru = "KINETOSTAT  T.FTN  КПФ И УСИЛИЯ" // &
      " КРИВОШИПНО-КОРОМЫСЛОВО-ПОЛЗУННОГО" // &
      " МЕХАНИЗМА"

  !> T.FTN: six-bar crank-rocker-slider, manual section 2.
  type, extends(mechanism_t) :: sixbar_mechanism_t
    !> The validated deck (T.FTN data).
    type(sixbar_deck_t) :: deck
    !> The reduced quantities at any crank angle (dynamics = 'steady' or 'given').
    type(sixbar_source_t) :: source
    !> The steady cycle (dynamics = 'steady' or 'given').
    type(cycle_t) :: cycle
  contains
    procedure :: load_deck, prepare, solve, put_results, sketch, force_plan, mass_model
  end type sixbar_mechanism_t

contains

  !> A new mechanism of this kind (the registry's constructor).
  subroutine new_sixbar(mech)
    !> The mechanism.
    class(mechanism_t), allocatable, intent(out) :: mech
    allocate (sixbar_mechanism_t :: mech)
    call mech%describe(sixbar_template, title_en, title_ru, "", &
      "Six-bar crank-rocker-slider mechanism", &
      "Шестизвенный кривошипно-коромыслово-ползунный механизм")
  end subroutine new_sixbar

  subroutine load_deck(self, source, error)
    class(sixbar_mechanism_t), intent(inout) :: self
    type(deck_source_t), intent(in) :: source
    type(error_t), allocatable, intent(out) :: error
    call read_sixbar_deck(source, self%deck, error)
  end subroutine load_deck

  !> The reduced quantities' load table and the steady cycle of a deck with dynamics =
  !> 'steady' or 'given'.
  subroutine prepare(self, path, error)
    class(sixbar_mechanism_t), intent(inout) :: self
    character(*), intent(in) :: path
    type(error_t), allocatable, intent(out) :: error
    if (self%deck%dyn%mode >= dynamics_steady) then
      self%source = sixbar_source(self%deck)
      if (.not. allocated(self%source%f5)) then
        call out_of_memory(error, "the load table of "//int_str(self%deck%n)//" steps", 8_int64 * self%deck%n)
        error%message = path//": &sixbar: dynamics: "//error%message
        return
      end if
      call sixbar_cycle(self%deck, self%source, path, self%cycle, error)
    end if
  end subroutine prepare

  !> The topology for a drawing (frame 1): crank A-B, rod B-C, rocker C-D-E, rod E-H, slider 5
  !> at H on the guide along x2 (at beta - 180 deg); pivots A, D; gravity -y0.
  pure subroutine sketch(self, out)
    class(sixbar_mechanism_t), intent(in) :: self
    type(sketch_t), intent(out) :: out
    real(wp) :: x2
    x2 = atan2(self%deck%p%a, self%deck%p%b) * rad_to_deg - 180.0_wp
    call out%add_link("1", ["A", "B"])
    call out%add_link("2", ["B", "C"])
    call out%add_link("3", ["C", "D", "E"])
    call out%add_link("4", ["E", "H"])
    call out%add_link("5", ["H"], x2, "")
    call out%add_pivot("A")
    call out%add_pivot("D")
    call out%add_guide("H", x2, "")
    out%down = sixbar_down1(self%deck%p)
  end subroutine sketch

  !> All steps of a validated deck; a step that cannot be assembled (or is a dead position)
  !> is a geometry error naming the step number and the crank angle.
  subroutine sixbar_solve(path, deck, steps, error, first, last, source, cycle, motions)
    !> Deck file, for the message.
    character(*), intent(in) :: path
    !> Validated deck.
    type(sixbar_deck_t), intent(in) :: deck
    !> One result per crank step (of steps first..last).
    type(sixbar_step_t), allocatable, intent(out) :: steps(:)
    !> Geometry error (exit 3).
    type(error_t), allocatable, intent(out) :: error
    !> Steps to compute (default: all).
    integer, intent(in), optional :: first, last
    !> The deck's reduced quantities and steady cycle (dynamics = 'steady' or 'given'): the
    !> steps at the true crank speed and acceleration, with the flywheel and rotor on the crank.
    type(sixbar_source_t), intent(in), optional :: source
    type(cycle_t), intent(in), optional :: cycle
    !> The motion and reduced quantities of each step (with `cycle`).
    type(motion_t), allocatable, intent(out), optional :: motions(:)
    type(motion_t) :: mo
    integer :: k, k1, k2, first_bad, stat
    call step_span(deck%n, k1, k2, first, last)
    allocate (steps(k2 - k1 + 1), stat=stat)
    if (stat == 0 .and. present(motions)) allocate (motions(k2 - k1 + 1), stat=stat)
    if (stat /= 0) then
      call lack_block_memory(error, k2 - k1 + 1, 2_int64 * storage_size(steps) / 8)
      return
    end if
    ! steps in parallel with OpenMP threads; the error reported is the first step's in step order
    first_bad = k2 + 1
    if (present(cycle) .and. present(source)) then
      !$omp parallel do schedule(static) private(mo) reduction(min:first_bad)
      do k = k1, k2
        mo = sixbar_motion(deck, source, cycle, k)
        if (present(motions)) motions(k - k1 + 1) = mo
        steps(k - k1 + 1) = sixbar_step(deck%p, sixbar_phi1_deg(deck, k) * deg_to_rad, deck%f5(k), mo%omega, mo%eps, &
                                        cycle%j_flywheel + cycle%j_rotor)
        if (steps(k - k1 + 1)%status /= sixbar_ok) first_bad = min(first_bad, k)
      end do
      !$omp end parallel do
    else
      !$omp parallel do schedule(static) reduction(min:first_bad)
      do k = k1, k2
        steps(k - k1 + 1) = sixbar_step(deck%p, sixbar_phi1_deg(deck, k) * deg_to_rad, deck%f5(k))
        if (steps(k - k1 + 1)%status /= sixbar_ok) first_bad = min(first_bad, k)
      end do
      !$omp end parallel do
    end if
    if (first_bad <= k2) then
      k = first_bad
      call fatal_error(error, exit_geometry, path//": &sixbar: step "//int_str(k)//" (phi1 = "// &
        real_str(sixbar_phi1_deg(deck, k))//" deg): "//failure_text(deck, steps(k - k1 + 1)))
    end if
  end subroutine sixbar_solve

  !> Why a position failed, with the numbers.
  pure function failure_text(deck, s) result(text)
    type(sixbar_deck_t), intent(in) :: deck
    type(sixbar_step_t), intent(in) :: s
    character(len=:), allocatable :: text
    real(wp) :: l2, l3
    l2 = deck%p%lam2 * deck%p%l1
    l3 = deck%p%lam3 * deck%p%l1
    select case (s%status)
    case (sixbar_open1)
      text = "contour A-B-C-D cannot be assembled: |BD| = "//real_str(s%pos%detail)// &
        " m is outside [|l2 - l3|, l2 + l3] = ["//real_str(abs(l2 - l3))//", "//real_str(l2 + l3)//"] m"
    case (sixbar_dead1)
      text = "dead position of contour A-B-C-D: B, C, D in line (sin(phi3 - phi2) = "// &
        real_str(s%pos%detail)//"), reactions undetermined"
    case (sixbar_open2)
      text = "contour D-E-H cannot be assembled: |e - y_E| = "//real_str(s%pos%detail)// &
        " m exceeds l4 = "//real_str(deck%p%lam4 * deck%p%l1)//" m"
    case (sixbar_dead2)
      text = "dead position of contour D-E-H: link 4 perpendicular to the guide (cos(phi4) = "// &
        real_str(s%pos%detail)//"), reactions undetermined"
    case default
      text = "position failure "//int_str(s%status)
    end select
  end function failure_text

  !> The block's crank steps into the step table, the reduced quantities of a dynamics stage,
  !> the self-check; the columns, loads and INPUT DATA echo with the first block.
  subroutine solve(self, table, error)
    class(sixbar_mechanism_t), intent(in) :: self
    type(step_table_t), intent(inout) :: table
    type(error_t), allocatable, intent(out) :: error
    type(sixbar_step_t), allocatable :: steps(:)
    type(motion_t), allocatable :: motions(:)
    integer :: k, first, last
    call table%block_range(self%deck%n, first, last)
    if (self%deck%dyn%mode >= dynamics_steady) then
      call sixbar_solve(table%deck, self%deck, steps, error, first, last, self%source, self%cycle, motions)
    else
      call sixbar_solve(table%deck, self%deck, steps, error, first, last)
    end if
    if (allocated(error)) return
    if (table%first_block()) then
      call table%declare_columns(sixbar_columns())
      call add_dynamics_columns(table, self%deck%dyn%mode)
      call put_dynamics_figures(table, self%deck%dyn%mode, self%cycle, self%deck%dyn%delta)
      table%input_column = 1
      call table%note_load(self%deck%f5(1:self%deck%n))
      call echo_deck(self%deck, table)
    end if
    call table%allocate_rows(size(steps), error)
    if (allocated(error)) return
    !$omp parallel do schedule(static)
    do k = 1, size(steps)
      table%rows(1:row_size, k) = sixbar_csv_values(steps(k), self%deck%p%l1, table%force_angles_wanted)
    end do
    !$omp end parallel do
    if (allocated(motions)) then
      call put_dynamics_rows(table, self%deck%dyn%mode, motions)
      call constant_speed_cost(table%deck, self%deck, steps, first, last, table)
      call note_drive_deviation(table, [steps%m1], motions, self%cycle%j_flywheel)
    else if (self%deck%dyn%mode > 0) then
      call put_dynamics_rows(table, self%deck%dyn%mode, reduced_motion(self%deck, steps))
    end if
    if (table%kinematics_wanted) call put_kinematics(table, self%deck%p, steps)
    call table%set_selfcheck_rows([steps%residual], [steps%mismatch], "M1")
  end subroutine solve

  !> The peaks of the pair forces with the true motion against those at omega1 = omega_m.
  subroutine constant_speed_cost(path, deck, steps, first, last, table)
    character(*), intent(in) :: path
    type(sixbar_deck_t), intent(in) :: deck
    !> The steps of the block with the true motion.
    type(sixbar_step_t), intent(in) :: steps(:)
    integer, intent(in) :: first, last
    type(step_table_t), intent(inout) :: table
    type(sixbar_step_t), allocatable :: const(:)
    type(error_t), allocatable :: error
    real(wp) :: peak(size(force_names)), peak_const(size(force_names))
    integer :: k
    call sixbar_solve(path, deck, const, error, first, last)
    if (allocated(error)) return
    peak = 0.0_wp
    peak_const = 0.0_wp
    do k = 1, size(steps)
      peak = max(peak, norm2(pair_forces(steps(k)), dim=1))
      peak_const = max(peak_const, norm2(pair_forces(const(k)), dim=1))
    end do
    call note_constant_speed_costs(table, force_names, peak, peak_const)
  end subroutine constant_speed_cost

  !> The pair forces of a step, in the order of force_names (the guide's F56 along y2 as the
  !> vector [0, F56] of frame 2), N.
  pure function pair_forces(s) result(f)
    type(sixbar_step_t), intent(in) :: s
    real(wp) :: f(2, size(force_names))
    f = reshape([s%f21, s%f32, s%f43, s%f45, s%f36, s%f16, [0.0_wp, s%f56]], [2, size(force_names)])
  end function pair_forces

  !> The reduced quantities of a computed step (dynamics = 'reduced': the deck's speed).
  elemental function reduced_motion(deck, s) result(mo)
    type(sixbar_deck_t), intent(in) :: deck
    type(sixbar_step_t), intent(in) :: s
    type(motion_t) :: mo
    real(wp) :: r(3)
    r = sixbar_reduced(deck%p, s%pos%phi1, s%f5)
    mo%omega = deck%p%omega1
    mo%j = r(1) + deck%dyn%j_rotor
    mo%dj = r(2)
    mo%m = r(3)
  end function reduced_motion

  !> The columns of a step, in the spec's order: the crank angle (appendix 2's F0), the six
  !> pair forces' magnitudes and angles (from axis x1 or x2, as the heading's unit says), the
  !> slider's guide force F56 along y2 and the driving moment.
  pure function sixbar_columns() result(cols)
    type(column_t), allocatable :: cols(:)
    integer :: i
    cols = [column("phi1", "deg", col_input_angle, heading="F0")]
    do i = 1, size(force_names) - 1
      if (force_in_frame2(i)) then
        cols = [cols, force_and_angle(trim(force_names(i)), "deg/x2", "град/x2")]
      else
        cols = [cols, force_and_angle(trim(force_names(i)), "deg/x1", "град/x1")]
      end if
    end do
    cols = [cols, column("F56", "N", col_component, heading="F56"), column("M1", "N*m", col_moment, heading="M1")]
  end function sixbar_columns

  !> The RESULTS layout of a step: the crank angle (9 wide), the six magnitudes and F56 (12
  !> wide), M1 (English only: T.FTN printed it apart), under them the six angles.
  pure function results_layout(with_m1) result(fields)
    logical, intent(in) :: with_m1
    type(table_field_t), allocatable :: fields(:)
    type(table_field_t), allocatable :: moment(:)
    allocate (moment(0)) ! no M1 (and defined before the assignment: gcc's -Wuninitialized)
    if (with_m1) moment = [field("M1", 12, 3)]
    fields = magnitudes_over_angles("phi1", force_names, force_names(1:size(force_names) - 1), moment)
  end function results_layout

  !> The row of values of one step. Forces below `noise_rel` times the step's largest
  !> force (and M1 below that force times l1) are roundoff: printed as 0 with angle 0.
  pure function sixbar_csv_values(s, l1, angles) result(v)
    !> One computed step.
    type(sixbar_step_t), intent(in) :: s
    !> Crank length, m (moment scale).
    real(wp), intent(in) :: l1
    !> Whether the forces' angles are computed (default true; else 0).
    logical, intent(in), optional :: angles
    real(wp) :: v(row_size)
    real(wp) :: floor, f(2, size(force_names))
    f = pair_forces(s)
    floor = noise_floor(f(:, 1:6), [s%f56])
    v(1) = s%pos%phi1 * rad_to_deg
    v(2:13) = force_columns(f(:, 1:6), floor, angles_pm180, angles)
    v(14) = s%f56
    if (abs(v(14)) <= floor) v(14) = 0.0_wp
    v(15) = s%m1
    if (abs(v(15)) <= floor * l1) v(15) = 0.0_wp
  end function sixbar_csv_values

  !> The kinematics columns of the block's steps, all positions and link angles in frame 1 (origin A,
  !> x1 along AD: the frame of phi1 and of the generic twin deck data/assur_sixbar.nml):
  !> joints A, B, C, D, E, H and centres of mass S1 (= A), S2, S3 (= D), S4, S5 (= H); links
  !> 1..4 (the slider 5 translates along x2); accelerations of S1..S5; components of the
  !> pair forces in the frames of their angle columns: F21, F32, F36, F16 in frame 1; F43,
  !> F45 and the guide's F56 (along y2) in frame 2, whose x axis lies at beta - 180 deg.
  pure subroutine put_kinematics(table, p, steps)
    !> The step table (columns appended on first use).
    type(step_table_t), intent(inout) :: table
    !> T.FTN's data (the lengths as l1 and ratios to it).
    type(sixbar_params_t), intent(in) :: p
    !> The block's computed steps, one a row.
    type(sixbar_step_t), intent(in) :: steps(:)
    real(wp) :: w, frame2, f(2, size(force_names)), floor, zero(2)
    integer :: k
    do k = 1, size(steps)
      associate (s => steps(k))
        w = s%omega1
        zero = 0.0_wp
        ! angle of x2 in frame 1, rad: beta - pi
        frame2 = atan2(p%a, p%b) - pi
        associate (pos => s%pos)
          call table%put_point(k, "A", zero)
          call table%put_point(k, "B", pos%b)
          call table%put_point(k, "C", pos%c)
          call table%put_point(k, "D", pos%d)
          call table%put_point(k, "E", pos%e1)
          call table%put_point(k, "H", pos%d + sixbar_frame2_to_frame1(p, pos%h))
          call table%put_point(k, "S1", zero)
          call table%put_point(k, "S2", pos%s2)
          call table%put_point(k, "S3", pos%d)
          call table%put_point(k, "S4", pos%d + sixbar_frame2_to_frame1(p, pos%s4))
          call table%put_point(k, "S5", pos%d + sixbar_frame2_to_frame1(p, pos%h))
          call table%put_link(k, "1", pos%phi1, w, s%eps1)
          call table%put_link(k, "2", pos%phi2, pos%u21 * w, s%eps(2))
          call table%put_link(k, "3", pos%phi3, pos%u31 * w, s%eps(3))
          call table%put_link(k, "4", modulo(pos%phi4 + frame2 + pi, 2.0_wp * pi) - pi, pos%u41 * w, s%eps(4))
          call table%put_acceleration(k, "S1", zero)
          call table%put_acceleration(k, "S2", sixbar_accel(pos%a_s2q, pos%v_s2q, w, s%eps1))
          call table%put_acceleration(k, "S3", zero)
          call table%put_acceleration(k, "S4", sixbar_frame2_to_frame1(p, sixbar_accel(pos%a_s4q, pos%v_s4q, w, s%eps1)))
          call table%put_acceleration(k, "S5", sixbar_frame2_to_frame1(p, [sixbar_accel(pos%a_hq(1), pos%v_hq(1), w, s%eps1), &
                                                                          0.0_wp]))
      end associate
      f = pair_forces(s)
      floor = noise_floor(f(:, 1:6), [s%f56])
      call table%put_pair_components(k, force_names, f, floor, merge(frame2 * rad_to_deg, 0.0_wp, force_in_frame2))
      end associate
    end do
  end subroutine put_kinematics

  !> The INPUT DATA echo of the deck: T.FTN's frame and lengths (the ratios LAM* to l1 with
  !> their meaning as the unit), masses, inertias, speed, g, the steps and the load F5.
  pure subroutine echo_deck(deck, table)
    type(sixbar_deck_t), intent(in) :: deck
    type(step_table_t), intent(inout) :: table
    !> The length ratios of the deck and what each is.
    character(*), parameter :: ratio_names(*) = [character(len=6) :: "LAM2", "LAM_S2", "LAM3", "LAM_DE", "LAM4", &
      "LAM_S4", "LAM_E"]
    character(*), parameter :: ratio_units(*) = [character(len=10) :: "l_BC/l1", "l_BS2/l_BC", "l_DC/l1", "l_DE/l1", &
      "l_EH/l1", "l_ES4/l_EH", "e/l1"]
    real(wp) :: ratios(size(ratio_names))
    integer :: i
    associate (p => deck%p)
      call echo_reals(table, [character(len=2) :: "A", "B", "L1"], [p%a, p%b, p%l1], "m")
      ratios = [p%lam2, p%lam_s2, p%lam3, p%lam_de, p%lam4, p%lam_s4, p%lam_e]
      do i = 1, size(ratio_names)
        call table%echo_real(trim(ratio_names(i)), ratios(i), trim(ratio_units(i)))
      end do
      call echo_reals(table, [character(len=2) :: "M1", "M2", "M3", "M4", "M5"], [p%m1, p%m2, p%m3, p%m4, p%m5], "kg")
      call echo_reals(table, [character(len=2) :: "J1", "J2", "J3", "J4"], [p%j1, p%j2, p%j3, p%j4], "kg*m^2")
      call table%echo_real("OMEGA1", p%omega1, "rad/s")
      call table%echo_real("G", p%g, "m/s^2")
    end associate
    call table%echo_logical("START_AT_EXTREME", deck%start_at_extreme, "")
    call echo_steps(table, deck%phi_start, deck%dphi, deck%n, start_unit="deg (frame 1)")
    call table%echo_array("F5", deck%f5(1:deck%n), "N (along +x2)")
    call table%echo_logical("LEGACY_EQ2", deck%p%legacy_eq2, "(1991 erratum in eps_q2)")
    call echo_dynamics(table, deck%dyn)
  end subroutine echo_deck

  !> RESULTS as appendix 2: per step the crank angle, six force magnitudes, F56 and M1, and
  !> under them the six force angles; fields 9 and 12 wide.
  pure subroutine put_results(self, table, page, out, later)
    class(sixbar_mechanism_t), intent(in) :: self
    type(step_table_t), intent(in) :: table
    type(results_page_t), intent(in) :: page
    type(text_buffer_t), intent(inout) :: out, later
    if (page%lang == lang_ru) then
      call put_results_ru(table, page, out, later)
    else
      ! the angles' units stand one place right of their fields, as they always did
      call put_layout_block(out, table, page, results_layout(.true.), .true., unit_shift=[0, 1])
    end if
  end subroutine put_results

  !> RESULTS as appendix 2 prints them (--lang ru): the original's header and dotted rules,
  !> the eight columns and six angles per step, a legend with the units, then M1 apart.
  pure subroutine put_results_ru(table, page, out, later)
    type(step_table_t), intent(in) :: table
    !> The rows of the block to write; the headings come with row 1 of the run's first block.
    type(results_page_t), intent(in) :: page
    type(text_buffer_t), intent(inout) :: out, later
    ! the eight columns and six angles, no unit lines, the dotted rule under the heading
    call put_layout_block(out, table, page, results_layout(.false.), .false., below=dotted_rule)
    ! the closing rule, the legend and the moment block follow the last row (in `later`)
    if (page%heading) then
      call later%put(dotted_rule)
      call later%put_lines(legend_ru)
      call put_heading(later, moment_heading_ru)
    end if
    call put_layout_block(later, table, page, [field("phi1", 9, 2), field("M1", 12, 3)], .true.)
  end subroutine put_results_ru

  !> The moving links: crank 1, connecting rod 2, rocker 3, link 4 and slider 5 (translating),
  !> each at its centre of mass; gravity in frame 1.
  pure subroutine mass_model(self, model)
    class(sixbar_mechanism_t), intent(in) :: self
    type(mass_model_t), intent(out) :: model
    real(wp) :: masses(5), inertias(5)
    integer :: i
    associate (p => self%deck%p)
      ! link i at its centre of mass Si; the slider 5 translates
      masses = [p%m1, p%m2, p%m3, p%m4, p%m5]
      inertias = [p%j1, p%j2, p%j3, p%j4, 0.0_wp]
      do i = 1, size(masses)
        call model%add(int_str(i), "S"//int_str(i), masses(i), inertias(i))
      end do
      model%gravity = p%g * sixbar_down1(p)
      ! the slider's guide force passes through H (every other force on it does)
      call model%add_frame_pair("F16", "A", "")
      call model%add_frame_pair("F36", "D", "")
      call model%add_frame_pair("F56", "H", "")
      model%drive = "M1"
    end associate
  end subroutine mass_model

  !> The forces of row `k` on its drawing (--format svg --at K): every pair force at its
  !> joint (F56, the guide's normal force, at H), the load F5 along x2, the weights (-y0),
  !> inertia forces and moments of links 1..5, and M1.
  pure subroutine force_plan(self, table, k, drawing, error)
    class(sixbar_mechanism_t), intent(in) :: self
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: k
    type(drawing_t), intent(inout) :: drawing
    type(error_t), allocatable, intent(out) :: error
    !> The points of the pair forces force_names.
    character(len=1), parameter :: pair_points(*) = ["B", "C", "E", "H", "D", "A", "H"]
    real(wp) :: x2
    type(mass_model_t) :: model
    associate (p => self%deck%p)
      call drawing%pairs_from_table(table, k, force_names, pair_points, error)
      if (allocated(error)) return
      ! x2 in frame 1, rad
      x2 = atan2(p%a, p%b) - pi
      call drawing%add_force("F5", force_load, drawing%at("H"), self%deck%f5(table%run_row(k)) * [cos(x2), sin(x2)], "5")
      call self%mass_model(model)
      call drawing%add_body_loads(table, k, model)
      call drawing%add_moment("M1", force_load, drawing%at("A"), table%rows(table%column_index("M1"), k))
    end associate
  end subroutine force_plan

end module kinetostat_sixbar_layout
