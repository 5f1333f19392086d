!> PR 3050 as a mechanism of the run pipeline: deck -> every rocker step -> step table, and
!> the legacy table layout (one E-format line per step, then the prismatic-pair block).
module kinetostat_pr3050_layout
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_kinds, only: wp, deg_to_rad
  use kinetostat_deck, only: deck_source_t
  use kinetostat_error, only: error_t
  use kinetostat_text, only: int_str, real_str
  use kinetostat_vec2, only: angle_360_deg
  use kinetostat_noise, only: noise_rel, noise_floor, force_columns, angles_0_360
  use kinetostat_step_table, only: step_table_t, column_t, column, col_input_angle, col_component, step_span, &
    col_moment, col_length, col_other, lack_block_memory
  use kinetostat_table_layout, only: table_field_t, field, forces_and_angles, results_page_t, &
    put_layout_block, echo_reals
  use kinetostat_labels, only: lang_ru
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_table_writer, only: put_heading
  use kinetostat_mechanism, only: mechanism_t
  use kinetostat_sketch, only: sketch_t
  use kinetostat_pr3050, only: pr3050_params_t, pr3050_position_t, pr3050_step_t, pr3050_step, &
    pr3050_check_position, pr3050_position, pr3050_reduced
  use kinetostat_pr3050_deck, only: pr3050_deck_t, read_pr3050_deck, pr3050_template, pr3050_phi3_deg
  use kinetostat_drawing, only: drawing_t, force_load
  use kinetostat_bodies, only: mass_model_t
  use kinetostat_dynamics, only: motion_t, dynamics_none
  use kinetostat_dynamics_table, only: echo_dynamics, add_dynamics_columns, put_dynamics_rows
  implicit none
  private
  public :: pr3050_mechanism_t, new_pr3050, pr3050_solve, pr3050_columns, pr3050_csv_values

  !> Pair forces, in the order of the columns (each a magnitude and an angle column).
  character(*), parameter :: force_names(*) = [character(len=3) :: "F14", "F34", "F32"]
  !> Number of CSV columns of a step's row: the rocker angle, the forces and angles, F2.
  integer, parameter :: csv_size = 2 + 2 * size(force_names)
  !> Legend under the Russian results (the manual's section 4 wording).
  character(*), parameter :: legend_ru(*) = [character(len=160) :: &
    " F13G - УГОЛ ПОВОРОТА ЗВЕНА 3 ОТ НАЧАЛЬНОГО ПОЛОЖЕНИЯ (PHI3 - PHI3_START)," // &
      " град;", &
    " F14, F14G - СИЛА В ШАРНИРЕ A НА ЗВЕНО 1 СО СТОРОНЫ СТОЙКИ 4, Н, град;", &
    " F34, F34G - СИЛА В ШАРНИРЕ C НА ЗВЕНО 3 СО СТОРОНЫ СТОЙКИ 4, Н, град;", &
    " F32, F32G - СИЛА В ШАРНИРЕ B НА ЗВЕНО 3 СО СТОРОНЫ ЗВЕНА 2, Н, град;", &
    " F2 - ДВИЖУЩАЯ СИЛА НА ШТОК 2 (ДАВЛЕНИЕ МАСЛА), Н, F2 > 0 ВЫДВИГАЕТ ШТОК;", &
    " УГЛЫ - ОТ ОСИ X (ОТ C К A) ПРОТИВ ЧАСОВОЙ СТРЕЛКИ"]
  !> Heading of the prismatic-pair block in Russian (two lines).
  character(*), parameter :: pair_heading_ru(*) = [character(len=160) :: &
    "ПОСТУПАТЕЛЬНАЯ ПАРА 1-2 И ГИДРОЦИЛИНДР (N21 - НА ШТОК 2 ОТ ЦИЛИНДРА 1" // &
      " ПО E2+90 ГРАД В ТОЧКЕ B,", &
    " M21 - МОМЕНТ НА ШТОК 2 ОТ ЦИЛИНДРА 1, ПРОТИВ ЧАСОВОЙ СТРЕЛКИ)"]
  !> Heading of the block with the prismatic pair 1-2 and the cylinder's motion.
  character(*), parameter :: pair_heading = &
    "PRISMATIC PAIR 1-2 (ON ROD 2 FROM CYLINDER 1: N21 ALONG E2+90 DEG AT B, M21 CCW) AND CYLINDER"
  !> Title lines of the legacy table (English, Russian).
  character(*), parameter :: title_en = "KINETOSTAT  PR 3050  FORCE ANALYSIS OF THE FOUR-BAR "// &
    "WITH AN OSCILLATING HYDRAULIC CYLINDER", &
    title_ru = "KINETOSTAT  PR 3050  СИЛОВОЙ РАСЧЕТ ЧЕТЫРЕХЗВЕННОГО" // &
      " МЕХАНИЗМА С КАЧАЮЩИМСЯ ГИДРОЦИЛИНДРОМ"

  !> PR 3050: four-bar with an oscillating hydraulic cylinder, manual section 4.
  type, extends(mechanism_t) :: pr3050_mechanism_t
    !> The validated deck (PR 3050 card images).
    type(pr3050_deck_t) :: deck
  contains
    procedure :: load_deck, solve, put_results, sketch, force_plan, mass_model
  end type pr3050_mechanism_t

contains

  !> A new mechanism of this kind (the registry's constructor).
  subroutine new_pr3050(mech)
    !> The mechanism.
    class(mechanism_t), allocatable, intent(out) :: mech
    allocate (pr3050_mechanism_t :: mech)
    call mech%describe(pr3050_template, title_en, title_ru, "", &
      "Four-bar with an oscillating hydraulic cylinder", &
      "Четырехзвенный механизм с качающимся гидроцилиндром")
  end subroutine new_pr3050

  subroutine load_deck(self, source, error)
    class(pr3050_mechanism_t), intent(inout) :: self
    type(deck_source_t), intent(in) :: source
    type(error_t), allocatable, intent(out) :: error
    call read_pr3050_deck(source, self%deck, error)
  end subroutine load_deck

  !> The topology for a drawing: cylinder 1 from A along the axis (through S1), rod 2 from B
  !> (through S2) sliding in it, rocker 3 C-B with its centre of mass S3; pivots C, A; the
  !> rod's guide is the cylinder's axis (phi1).
  pure subroutine sketch(self, out)
    class(pr3050_mechanism_t), intent(in) :: self
    type(sketch_t), intent(out) :: out
    call out%add_link("1", [character(len=2) :: "A", "S1"])
    call out%add_link("2", [character(len=2) :: "B", "S2"])
    call out%add_link("3", [character(len=2) :: "C", "B", "S3", "C"])
    call out%add_pivot("C")
    call out%add_pivot("A")
    call out%add_guide("A", 0.0_wp, "1")
    out%down = [cos(self%deck%p%gamma), sin(self%deck%p%gamma)]
  end subroutine sketch

  !> All steps of a validated deck; a geometry error (exit 3) names the step and rocker angle.
  subroutine pr3050_solve(deck, steps, error, first, last)
    !> Validated deck.
    type(pr3050_deck_t), intent(in) :: deck
    !> One result per rocker step (of steps first..last).
    type(pr3050_step_t), allocatable, intent(out) :: steps(:)
    !> Geometry error: "step k (phi3 = x deg): reason".
    type(error_t), allocatable, intent(out) :: error
    !> Steps to compute (default: all).
    integer, intent(in), optional :: first, last
    type(error_t), allocatable :: step_error
    integer :: k, k1, k2, first_bad, stat
    call step_span(deck%n, k1, k2, first, last)
    allocate (steps(k2 - k1 + 1), stat=stat)
    if (stat /= 0) then
      call lack_block_memory(error, k2 - k1 + 1, storage_size(steps, int64) / 8)
      return
    end if
    ! steps in parallel with OpenMP threads; the error reported is the first step's in step order
    first_bad = k2 + 1
    !$omp parallel do schedule(static) private(step_error) reduction(min:first_bad)
    do k = k1, k2
      call pr3050_check_position(deck%p, pr3050_phi3_deg(deck, k) * deg_to_rad, step_error)
      if (allocated(step_error)) then
        first_bad = min(first_bad, k)
      else
        steps(k - k1 + 1) = pr3050_step(deck%p, pr3050_phi3_deg(deck, k) * deg_to_rad, deck%omega3(k), deck%eps3(k))
      end if
    end do
    !$omp end parallel do
    if (first_bad <= k2) then
      k = first_bad
      call pr3050_check_position(deck%p, pr3050_phi3_deg(deck, k) * deg_to_rad, error)
      error%message = "step "//int_str(k)//" (phi3 = "//real_str(pr3050_phi3_deg(deck, k))//" deg): "//error%message
    end if
  end subroutine pr3050_solve

  !> A warning when the rocker passes the dead position (C, B, A collinear: phi3 = k*180 deg,
  !> where s' = 0 and F2 is unbounded) strictly between two computed steps; every step is
  !> valid, but the table does not show the singularity in between.
  pure subroutine dead_position_between_steps(deck, warning)
    !> Validated deck.
    type(pr3050_deck_t), intent(in) :: deck
    !> The warning, unallocated when the range stays clear.
    character(len=:), allocatable, intent(out) :: warning
    integer :: k, half_turns
    do k = 2, deck%n
      half_turns = floor(pr3050_phi3_deg(deck, k) / 180.0_wp)
      if (floor(pr3050_phi3_deg(deck, k - 1) / 180.0_wp) /= half_turns .and. &
          modulo(pr3050_phi3_deg(deck, k), 180.0_wp) /= 0.0_wp) then
        warning = "between step "//int_str(k - 1)//" (phi3 = "//real_str(pr3050_phi3_deg(deck, k - 1))// &
          " deg) and step "//int_str(k)//" (phi3 = "//real_str(pr3050_phi3_deg(deck, k))// &
          " deg) the rocker passes the dead position phi3 = "//real_str(180.0_wp * half_turns)// &
          " deg (C, B, A collinear: F2 is unbounded there)"
        return
      end if
    end do
  end subroutine dead_position_between_steps

  !> Every step into the step table (the CSV columns, then the prismatic-pair block's).
  subroutine solve(self, table, error)
    class(pr3050_mechanism_t), intent(in) :: self
    type(step_table_t), intent(inout) :: table
    type(error_t), allocatable, intent(out) :: error
    type(pr3050_step_t), allocatable :: steps(:)
    real(wp) :: floor, n21, m21
    integer :: k, nc, first, last
    character(len=:), allocatable :: warning
    call table%block_range(self%deck%n, first, last)
    call pr3050_solve(self%deck, steps, error, first, last)
    if (allocated(error)) then
      error%message = table%deck//": &pr3050: "//error%message
      return
    end if
    if (table%first_block()) then
      call table%declare_columns(pr3050_columns())
      call add_dynamics_columns(table, self%deck%dyn%mode, translating=.true.)
      table%input_column = 1
      table%work_column = table%column_index("S")
      call dead_position_between_steps(self%deck, warning)
      if (allocated(warning)) call table%add_warning(warning)
      call echo_deck(self%deck, table)
    end if
    nc = csv_size
    call table%allocate_rows(size(steps), error)
    if (allocated(error)) return
    !$omp parallel do schedule(static) private(floor, n21, m21)
    do k = 1, size(steps)
      associate (v => table%rows(:, k), s => steps(k))
        v(1:nc) = pr3050_csv_values(s, phi3rel(self%deck, first - 1 + k), table%force_angles_wanted)
        floor = noise_rel * maxval(abs(v(2:8:2)))
        n21 = s%n21
        if (abs(n21) <= floor) n21 = 0.0_wp
        m21 = s%m21
        if (abs(m21) <= floor * (self%deck%p%l_ca + self%deck%p%l_cb)) m21 = 0.0_wp
        v(nc + 1:nc + 5) = [angle_360_deg([cos(s%phi2), sin(s%phi2)]), s%s, s%s_dot + 0.0_wp, &
                            n21 + 0.0_wp, m21 + 0.0_wp]
      end associate
    end do
    !$omp end parallel do
    if (self%deck%dyn%mode /= dynamics_none) call put_dynamics_rows(table, self%deck%dyn%mode, &
      reduced_motion(self%deck, steps))
    if (table%kinematics_wanted) call put_kinematics(table, self%deck%p, steps)
    call table%set_selfcheck_rows([steps%residual], [steps%mismatch], "F2")
  end subroutine solve

  !> The reduced quantities of a computed step, reduced to the stroke s (dynamics = 'reduced';
  !> J_red with the drive's mass j_rotor, kg; dJ_red kg/m; M_red N); omega is the stroke's
  !> speed ds/dt of the step.
  elemental function reduced_motion(deck, s) result(mo)
    type(pr3050_deck_t), intent(in) :: deck
    type(pr3050_step_t), intent(in) :: s
    type(motion_t) :: mo
    real(wp) :: r(3)
    r = pr3050_reduced(deck%p, s%phi3)
    mo%omega = s%s_dot
    mo%j = r(1) + deck%dyn%j_rotor
    mo%dj = r(2)
    mo%m = r(3)
  end function reduced_motion

  !> The kinematics columns of the block's steps (frame: origin C, x from C to A): joints C, A, B and
  !> centres of mass S1, S2, S3; links 1 (cylinder) and 2 (rod), which turn together, and 3
  !> (rocker); accelerations of S1, S2, S3; components of the pair forces in the same frame.
  pure subroutine put_kinematics(table, p, steps)
    !> The step table (columns appended on first use).
    type(step_table_t), intent(inout) :: table
    !> PR 3050's lengths and angles.
    type(pr3050_params_t), intent(in) :: p
    !> The block's computed steps, one a row.
    type(pr3050_step_t), intent(in) :: steps(:)
    type(pr3050_position_t) :: pos
    real(wp) :: w2, f(2, 3), floor
    integer :: k
    do k = 1, size(steps)
      associate (s => steps(k))
        w2 = s%omega3**2
        pos = pr3050_position(p, s%phi3)
        call table%put_point(k, "C", [0.0_wp, 0.0_wp])
        call table%put_point(k, "A", pos%a)
        call table%put_point(k, "B", pos%b)
        call table%put_point(k, "S1", pos%s1)
        call table%put_point(k, "S2", pos%s2)
        call table%put_point(k, "S3", pos%s3)
        call table%put_link(k, "1", pos%phi2, s%omega2, s%eps2)
        call table%put_link(k, "2", pos%phi2, s%omega2, s%eps2)
        call table%put_link(k, "3", s%phi3, s%omega3, s%eps3)
        call table%put_acceleration(k, "S1", pos%a_s1q * w2 + pos%v_s1q * s%eps3)
        call table%put_acceleration(k, "S2", pos%a_s2q * w2 + pos%v_s2q * s%eps3)
        call table%put_acceleration(k, "S3", pos%a_s3q * w2 + pos%v_s3q * s%eps3)
        f = reshape([s%f14, s%f34, s%f32], [2, 3])
        floor = noise_floor(f, [s%f2])
        call table%put_pair_components(k, force_names, f, floor)
      end associate
    end do
  end subroutine put_kinematics

  !> The columns of a step: the rocker angle from the first step (the original's F13G), the
  !> pair forces' magnitudes and angles, the driving force F2; then, for the legacy table and
  !> JSON only, the prismatic pair 1-2 and the cylinder's motion.
  pure function pr3050_columns() result(cols)
    type(column_t), allocatable :: cols(:)
    cols = [column("phi3rel", "deg", col_input_angle, heading="F13G")]
    cols = [cols, forces_and_angles(force_names)]
    cols = [cols, column("F2", "N", col_component, heading="F2"), &
            column("PHI2", "deg", col_other, heading="PHI2", csv=.false.), &
            column("S", "m", col_length, heading="S", csv=.false.), &
            column("SDOT", "m/s", col_other, heading="SDOT", csv=.false.), &
            column("N21", "N", col_component, heading="N21", csv=.false.), &
            column("M21", "N*m", col_moment, heading="M21", csv=.false.)]
  end function pr3050_columns

  !> The RESULTS line of a step: the rocker angle, the forces (E format) with their angles
  !> (8 wide), F2.
  pure function results_layout() result(fields)
    type(table_field_t), allocatable :: fields(:)
    integer :: i
    fields = [field("phi3rel", 9, 2)]
    do i = 1, size(force_names)
      fields = [fields, field(trim(force_names(i)), 12, 3, exponent=.true.), field(trim(force_names(i))//"G", 8, 2)]
    end do
    fields = [fields, field("F2", 12, 3, exponent=.true.)]
  end function results_layout

  !> The prismatic-pair block's line of a step.
  pure function pair_layout() result(fields)
    type(table_field_t), allocatable :: fields(:)
    fields = [field("phi3rel", 9, 2), field("PHI2", 10, 2), field("S", 10, 4), field("SDOT", 10, 4), &
              field("N21", 12, 3, exponent=.true.), field("M21", 12, 3, exponent=.true.)]
  end function pair_layout

  !> The row of CSV values of one step.
  !> Forces below `noise_rel` times the step's largest force are roundoff: printed as 0 with angle 0.
  pure function pr3050_csv_values(s, phi3rel, angles) result(v)
    !> Results of the step.
    type(pr3050_step_t), intent(in) :: s
    !> Rocker angle from the first step, phi3 - phi3_start (the original's F13G), deg.
    real(wp), intent(in) :: phi3rel
    !> Whether the forces' angles are computed (default true; else 0).
    logical, intent(in), optional :: angles
    real(wp) :: v(csv_size)
    real(wp) :: floor, f(2, 3)
    f = reshape([s%f14, s%f34, s%f32], [2, 3])
    floor = noise_floor(f, [s%f2])
    v(1) = phi3rel
    v(2:7) = force_columns(f, floor, angles_0_360, angles)
    v(8) = s%f2
    if (abs(v(8)) <= floor) v(8) = 0.0_wp
  end function pr3050_csv_values

  !> The INPUT DATA echo of the deck in the order of PR 3050's cards: the rocker and the
  !> cylinder (lengths and angles), g, masses, inertias, the rocker's steps and motion.
  pure subroutine echo_deck(deck, table)
    type(pr3050_deck_t), intent(in) :: deck
    type(step_table_t), intent(inout) :: table
    associate (p => deck%p)
      call echo_reals(table, [character(len=5) :: "L_CA", "L_CB", "L_CS3"], [p%l_ca, p%l_cb, p%l_cs3], "m")
      call table%echo_real("DELTA", deck%delta_deg, "deg")
      call echo_reals(table, [character(len=5) :: "L_BS2", "L_S1A"], [p%l_bs2, p%l_s1a], "m")
      call table%echo_real("GAMMA", deck%gamma_deg, "deg")
      call table%echo_real("G", p%g, "m/s^2")
      call echo_reals(table, [character(len=2) :: "M1", "M2", "M3"], [p%m1, p%m2, p%m3], "kg")
      call echo_reals(table, [character(len=2) :: "J1", "J2", "J3"], [p%j1, p%j2, p%j3], "kg*m^2")
    end associate
    call echo_reals(table, [character(len=10) :: "PHI3_START", "PHI3_END", "DPHI3"], &
      [deck%phi_start, deck%phi3_end, deck%dphi], "deg")
    call table%echo_int("N", deck%n, "steps")
    call table%echo_array("OMEGA3", deck%omega3(1:deck%n), "rad/s")
    call table%echo_array("EPS3", deck%eps3(1:deck%n), "rad/s^2")
    call echo_dynamics(table, deck%dyn, translating=.true.)
  end subroutine echo_deck

  !> RESULTS: one line per step (rocker angle, three reactions with angles, F2; E format as
  !> the original), then the prismatic pair 1-2 and the cylinder's motion.
  pure subroutine put_results(self, table, page, out, later)
    class(pr3050_mechanism_t), intent(in) :: self
    type(step_table_t), intent(in) :: table
    type(results_page_t), intent(in) :: page
    type(text_buffer_t), intent(inout) :: out, later
    ! in Russian the units are in the legend under the rows
    call put_layout_block(out, table, page, results_layout(), page%lang /= lang_ru)
    ! the prismatic pair's block follows the last row of the first (in `later`)
    if (page%heading .and. page%lang == lang_ru) then
      call later%put_lines(legend_ru)
      call put_heading(later, trim(pair_heading_ru(1)))
      call later%put(trim(pair_heading_ru(2)))
    else if (page%heading) then
      call put_heading(later, pair_heading)
    end if
    call put_layout_block(later, table, page, pair_layout(), .true.)
  end subroutine put_results

  !> Rocker angle of step `k` from the first step, (k - 1)*dphi3, deg.
  pure function phi3rel(deck, k) result(angle)
    type(pr3050_deck_t), intent(in) :: deck
    integer, intent(in) :: k
    real(wp) :: angle
    angle = real(k - 1, wp) * deck%dphi
  end function phi3rel

  !> The moving links: cylinder 1, rod 2 and boom 3, each at its centre of mass; gravity at gamma from x.
  pure subroutine mass_model(self, model)
    class(pr3050_mechanism_t), intent(in) :: self
    type(mass_model_t), intent(out) :: model
    associate (p => self%deck%p)
      call model%add("1", "S1", p%m1, p%j1)
      call model%add("2", "S2", p%m2, p%j2)
      call model%add("3", "S3", p%m3, p%j3)
      model%gravity = p%g * [cos(p%gamma), sin(p%gamma)]
      ! the oil force acts between cylinder and rod, inside the mechanism: no reaction on the frame
      call model%add_frame_pair("F14", "A", "")
      call model%add_frame_pair("F34", "C", "")
      model%drive = ""
    end associate
  end subroutine mass_model

  !> The forces of row `k` on its drawing (--format svg --at K): each pair force at its joint,
  !> the driving force F2 on the rod (along A->B, at S2), the weights (angle gamma),
  !> the inertia forces and moments of links 1, 2 and 3; no driving moment (the oil drives).
  pure subroutine force_plan(self, table, k, drawing, error)
    class(pr3050_mechanism_t), intent(in) :: self
    type(step_table_t), intent(in) :: table
    !> Row drawn: its column F2 is the oil force on the rod, N.
    integer, intent(in) :: k
    type(drawing_t), intent(inout) :: drawing
    type(error_t), allocatable, intent(out) :: error
    !> The points of the pair forces force_names.
    character(len=1), parameter :: pair_points(*) = ["A", "C", "B"]
    real(wp) :: a(2), b(2), u(2)
    type(mass_model_t) :: model
    associate (p => self%deck%p)
      call drawing%pairs_from_table(table, k, force_names, pair_points, error)
      if (allocated(error)) return
      a = drawing%at("A")
      b = drawing%at("B")
      u = (b - a) / max(norm2(b - a), tiny(1.0_wp))
      call drawing%add_force("F2", force_load, drawing%at("S2"), table%rows(table%column_index("F2"), k) * u, "2")
      call self%mass_model(model)
      call drawing%add_body_loads(table, k, model)
    end associate
  end subroutine force_plan

end module kinetostat_pr3050_layout
