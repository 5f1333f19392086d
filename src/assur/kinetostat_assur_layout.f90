!> The generic engine as a mechanism of the run pipeline: `&assur` deck -> every step ->
!> step table (`phi1`, every pair, crank pin, `M1`), and its table layout (magnitudes /
!> angles / normal forces / reaction moments per step).
module kinetostat_assur_layout
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_kinds, only: wp, deg_to_rad, rad_to_deg
  use kinetostat_deck, only: deck_source_t
  use kinetostat_error, only: error_t, fatal_error, exit_geometry
  use kinetostat_text, only: int_str, upper, joined, string_t
  use kinetostat_noise, only: noise_rel, force_components
  use kinetostat_vec2, only: magnitude, angle_360_deg, angle_180_deg, rotate, snap_noise, clean_zero
  use kinetostat_step_table, only: worst_row, lack_block_memory
  use kinetostat_run_tally, only: trapezoid_t
  use kinetostat_step_table, only: step_table_t, col_input_angle, col_force, col_force_angle, col_component, col_length, &
    step_span, &
    col_moment, col_other, col_flag, col_ratio
  use kinetostat_table_layout, only: table_field_t, field, blank_field, results_page_t, put_layout_block, &
    link_axes_heading
  use kinetostat_labels, only: lang_ru
  use kinetostat_friction_block, only: write_friction_block
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_mechanism, only: mechanism_t
  use kinetostat_sketch, only: sketch_t
  use kinetostat_assur_kinematics, only: kind_names, link_state_t, dyad_pose_t, point_state_t, point_on, &
    kind_rrr, kind_rrp, kind_rpr, kind_prp, kind_rpp
  use kinetostat_assur_statics, only: pair_is_prismatic
  use kinetostat_assur, only: assur_step_t, assur_step, assur_kinematics, link_a, link_b, crank_pin_index, pair_index, &
    pair_sides
  use kinetostat_drawing, only: drawing_t, force_load, point_com
  use kinetostat_bodies, only: mass_model_t
  use kinetostat_selfcheck, only: link_balance_t, balance_add_couple
  use kinetostat_dynamics, only: cycle_t, motion_t, dynamics_none, dynamics_steady
  use kinetostat_dynamics_table, only: echo_dynamics, add_dynamics_columns, put_dynamics_values, &
    put_dynamics_figures, note_drive_deviation, note_constant_speed_cost
  use kinetostat_assur_dynamics, only: assur_source_t, assur_cycle, assur_motion
  use kinetostat_assur_friction, only: friction_step_t, assur_friction_step
  use kinetostat_assur_deck, only: assur_deck_t, read_assur_deck, assur_template, load_schedule_t, load_constant, &
    load_column, assur_phi1_deg, assur_omega1_steps, assur_eps1, assur_motion_sign, assur_load_value, &
    assur_load_steps, resist_none, load_table, table_position
  use kinetostat_summary, only: table_peak_warning
  use kinetostat_assur_columns, only: assur_columns, assur_csv_values, assur_pair_prismatic, assur_row, &
    assur_row_size, friction_columns, friction_csv_values, friction_work, &
    friction_integrals, friction_summary, friction_row_size, kinematics_value_count, pair_link, assur_kinematics_row, &
    row_plan_t, row_plan
  implicit none
  private
  public :: assur_mechanism_t, new_assur, assur_solve, assur_columns, assur_csv_values, assur_pair_prismatic
  public :: friction_columns, friction_csv_values, friction_work

  !> Width of the PHI1 field of the RESULTS block.
  integer, parameter :: phi_width = 9
  !> Width of every other field of the RESULTS block.
  integer, parameter :: field_width = 12
  !> Decimals of the actuator's stroke (m), stroke speed (m/s) and acceleration (m/s^2).
  integer, parameter :: stroke_decimals = 4
  !> put_kinematics' modes: the columns by name, the columns' indices.
  integer, parameter :: kin_by_name = 0, kin_finding = 1
  !> Dyad line of the INPUT DATA echo.
  character(*), parameter :: dyad_echo_fmt = '(3x,"DYAD ",i0,": ",a," LINKS ",i0,"-",i0,", ON LINKS ",i0," AND ",i0, &
    &", MODE ",i0)'

  !> The load values of one step (a workspace reused from step to step).
  type :: step_loads_t
    !> Magnitude of every external force, N.
    real(wp), allocatable :: f(:)
    !> Every external moment, N*m.
    real(wp), allocatable :: m(:)
    !> The flywheel's and rotor's inertia moment on the crank as a further load of links
    !> 0..2*nd+1 (with a dynamics stage).
    type(link_balance_t), allocatable :: extra(:)
  end type step_loads_t

  !> Title lines of the legacy table (English, Russian).
  character(*), parameter :: title_en = "KINETOSTAT  ASSUR  FORCE ANALYSIS OF A LINKAGE OF CLASS-II ASSUR GROUPS", &
    title_ru = "KINETOSTAT  ASSUR  СИЛОВОЙ РАСЧЕТ МЕХАНИЗМА ИЗ ГРУПП АССУРА II" // &
      " КЛАССА"

  !> A one-DOF linkage of class-II Assur groups on a crank (generic engine).
  type, extends(mechanism_t) :: assur_mechanism_t
    !> The validated deck: the dyads on the crank, their loads and the dynamics stage.
    type(assur_deck_t) :: deck
    !> The deck as the source of the reduced quantities (with a dynamics stage).
    type(assur_source_t) :: source
    !> The steady cycle (dynamics = 'steady' or 'given').
    type(cycle_t) :: cycle
  contains
    procedure :: load_deck, prepare, solve, put_results, sketch, force_plan, mass_model, finish_run
  end type assur_mechanism_t

contains

  !> A new mechanism of this kind (the registry's constructor).
  subroutine new_assur(mech)
    !> The mechanism.
    class(mechanism_t), allocatable, intent(out) :: mech
    allocate (assur_mechanism_t :: mech)
    call mech%describe(assur_template, title_en, title_ru, "", &
      "Linkage of class-II Assur groups", &
      "Механизм из групп Ассура II класса")
  end subroutine new_assur

  subroutine load_deck(self, source, error)
    class(assur_mechanism_t), intent(inout) :: self
    type(deck_source_t), intent(in) :: source
    type(error_t), allocatable, intent(out) :: error
    call read_assur_deck(source, self%deck, error)
  end subroutine load_deck

  !> With a dynamics stage, the deck as the source of the reduced quantities, and the steady
  !> cycle (dynamics = 'steady' or 'given').
  subroutine prepare(self, path, error)
    class(assur_mechanism_t), intent(inout) :: self
    character(*), intent(in) :: path
    type(error_t), allocatable, intent(out) :: error
    if (self%deck%dyn%mode == dynamics_none) return
    self%source%deck = self%deck
    if (self%deck%dyn%mode >= dynamics_steady) call assur_cycle(self%deck, path, self%cycle, error)
  end subroutine prepare

  !> The topology for a drawing: every moving link joins the joints J<pair> of its pairs (a
  !> dyad's link a: pairs 1, 2; link b: pairs 2, 3; the crank: its pivot; each link also the
  !> joints of the later dyads attached to it). A link that slides on a prismatic pair is a
  !> block: RRP link b on its guide, RPR link a along link b's x axis, PRP both links, RPP
  !> link a along the slot of link b and link b on its guide. Pivots: the revolute pairs with
  !> the frame; guides: every prismatic pair's line.
  pure subroutine sketch(self, out)
    class(assur_mechanism_t), intent(in) :: self
    type(sketch_t), intent(out) :: out
    character(len=16), allocatable :: joints(:)
    integer :: nd, d, i, q, e
    real(wp) :: slot_deg
    associate (mech => self%deck%mech, names => self%deck%pair_name)
      nd = size(mech%dyads)
      do i = 1, 2 * nd + 1
        ! the link's own pairs, then the outer pairs of later dyads attached to it
        if (i == 1) then
          joints = [character(len=16) :: joint_name(self%deck, names(3 * nd + 1))]
        else
          d = i / 2
          q = i - 2 * d + 1
          joints = [character(len=16) :: joint_name(self%deck, names(3 * d - 3 + q)), joint_name(self%deck, names(3 * d - 2 + q))]
        end if
        do e = 1, nd
          if (mech%dyads(e)%on(1) == i) joints = [character(len=16) :: joints, joint_name(self%deck, names(3 * e - 2))]
          if (mech%dyads(e)%on(2) == i) joints = [character(len=16) :: joints, joint_name(self%deck, names(3 * e))]
        end do
        call add_sketch_link(out, self%deck, i, joints)
      end do
      call out%add_pivot(joint_name(self%deck, names(3 * nd + 1)))
      do d = 1, nd
        associate (dy => mech%dyads(d))
          do q = 1, 2
            e = 3 * d - 2 + 2 * (q - 1)
            if (assur_pair_prismatic(self%deck, e)) then
              call out%add_guide(joint_name(self%deck, names(e)), dy%ang(q) * rad_to_deg, link_label(self%deck, dy%on(q)))
            else if (dy%on(q) == 0) then
              call out%add_pivot(joint_name(self%deck, names(e)))
            end if
          end do
          if (assur_pair_prismatic(self%deck, 3 * d - 1)) then
            slot_deg = 0.0_wp
            if (dy%geom%kind == kind_rpp) slot_deg = dy%geom%slot_angle * rad_to_deg
            call out%add_guide(joint_name(self%deck, names(3 * d - 1)), slot_deg, link_label(self%deck, link_b(d)))
          end if
        end associate
      end do
      out%down = mech%down
    end associate
  end subroutine sketch

  !> One moving link (internal index i) of the sketch: a bar through `joints`, or a block.
  pure subroutine add_sketch_link(out, deck, i, joints)
    type(sketch_t), intent(inout) :: out
    type(assur_deck_t), intent(in) :: deck
    integer, intent(in) :: i
    character(*), intent(in) :: joints(:)
    integer :: d, kind
    character(len=:), allocatable :: name
    name = link_label(deck, i)
    if (i == 1) then
      call out%add_link(name, joints)
      return
    end if
    d = i / 2
    kind = deck%mech%dyads(d)%geom%kind
    associate (dy => deck%mech%dyads(d))
      if (i == link_a(d) .and. kind == kind_rpr) then
        call out%add_link(name, joints, 0.0_wp, link_label(deck, link_b(d)))
      else if (i == link_a(d) .and. kind == kind_prp) then
        call out%add_link(name, joints, dy%ang(1) * rad_to_deg, link_label(deck, dy%on(1)))
      else if (i == link_a(d) .and. kind == kind_rpp) then
        call out%add_link(name, joints, (dy%ang(2) + dy%geom%slot_angle) * rad_to_deg, link_label(deck, dy%on(2)))
      else if (i == link_b(d) .and. (kind == kind_rrp .or. kind == kind_prp .or. kind == kind_rpp)) then
        ! the block sits on the guide (pair 3) first
        call out%add_link(name, [joints(2), joints(1), joints(3:)], dy%ang(2) * rad_to_deg, link_label(deck, dy%on(2)))
      else
        call out%add_link(name, joints)
      end if
    end associate
  end subroutine add_sketch_link

  !> The name of link `i` (internal index) in phi<name>, omega<name>, eps<name>: its number;
  !> "L1" for a link numbered 1 that is not the crank (`phi1` is the input angle, the crank's);
  !> "" for the frame.
  pure function link_label(deck, i) result(label)
    type(assur_deck_t), intent(in) :: deck
    integer, intent(in) :: i
    character(len=:), allocatable :: label
    label = ""
    if (i > 0) label = int_str(deck%mech%links(i)%id)
    if (i > 1 .and. label == "1") label = "L1"
  end function link_label

  !> Every step into the step table, with the INPUT DATA echo and the self-check. Each step
  !> is solved into a workspace of its thread and its row written at once (no allocation per
  !> step); with the kinematics columns the block keeps the steps' angles and pair forces.
  subroutine solve(self, table, error)
    class(assur_mechanism_t), intent(in) :: self
    type(step_table_t), intent(inout) :: table
    type(error_t), allocatable, intent(out) :: error
    type(friction_step_t), allocatable :: fsteps(:)
    real(wp), allocatable :: residual(:), mismatch(:), omega1(:), m1(:)
    type(motion_t), allocatable :: motions(:)
    integer, allocatable :: slots(:)
    type(row_plan_t) :: plan
    integer :: k, nv, nc, np, first, last, nrow, first_bad, stat
    logical :: kinematics
    call table%block_range(self%deck%n, first, last)
    nrow = last - first + 1
    if (table%first_block()) then
      call table%declare_columns(assur_columns(self%deck))
      if (self%deck%friction_on) call table%declare_columns(friction_columns(self%deck))
      call add_dynamics_columns(table, self%deck%dyn%mode, self%deck%mech%drive_dyad > 0)
      call put_dynamics_figures(table, self%deck%dyn%mode, self%cycle, self%deck%dyn%delta)
      table%input_column = 1
      do k = 1, size(self%deck%force_load)
        call note_load(self%deck, self%deck%force_load(k), table)
      end do
      do k = 1, size(self%deck%moment_load)
        call note_load(self%deck, self%deck%moment_load(k), table)
      end do
      do k = 1, size(self%deck%force_load)
        call note_table_peak(self%deck, self%deck%force_load(k), "force("//int_str(k)//")%table", "N", table)
      end do
      do k = 1, size(self%deck%moment_load)
        call note_table_peak(self%deck, self%deck%moment_load(k), "moment("//int_str(k)//")%table", "N*m", table)
      end do
      if (len_trim(self%deck%title) > 0) table%subtitle = trim(self%deck%title)
      call echo_deck(self%deck, table)
    end if
    np = size(self%deck%pair_name)
    nv = assur_row_size(self%deck)
    nc = nv
    if (self%deck%friction_on) nc = nv + friction_row_size(self%deck)
    kinematics = table%kinematics_wanted
    plan = row_plan(self%deck, table%force_angles_wanted)
    omega1 = assur_omega1_steps(self%deck, first, last)
    call table%allocate_rows(nrow, error)
    if (allocated(error)) return
    allocate (residual(nrow), stat=stat)
    if (stat == 0) allocate (mismatch(nrow), stat=stat)
    if (stat == 0) allocate (fsteps(merge(nrow, 0, self%deck%friction_on)), stat=stat)
    if (stat == 0) allocate (m1(nrow), stat=stat)
    if (stat == 0) allocate (motions(merge(nrow, 0, self%deck%dyn%mode /= dynamics_none)), stat=stat)
    if (stat /= 0) then
      call lack_block_memory(error, nrow, 24_int64 + 8 * (3 + 2 * np))
      return
    end if
    if (kinematics) then
      ! the columns by name (the first block creates them), then the column of every value:
      ! each step writes its values straight into its row
      if (table%first_block()) then
        call put_kinematics(table, self%deck)
        call table%finish_columns()
        if (allocated(table%no_room)) return
      end if
      allocate (slots(kinematics_value_count(self%deck)))
      call put_kinematics(table, self%deck, slots)
    else
      allocate (slots(0))
    end if
    ! steps in parallel with OpenMP threads; the error reported is the first step's in step order
    ! (that step is solved again alone for its message)
    first_bad = last + 1
    !$omp parallel
    block
      type(assur_step_t) :: step
      type(friction_step_t) :: fs
      type(step_loads_t) :: loads
      type(error_t), allocatable :: step_error
      !> The step's pair force lengths (assur_row's, for the kinematics row), the
      !> kinematics row's values and its links' cos and sin.
      real(wp), allocatable :: lengths(:), values(:), link_turns(:, :)
      integer :: kk, i
      allocate (lengths(np), values(size(slots)), link_turns(2, 2 * size(self%deck%mech%dyads) + 1))
      ! the links' angles only where a column shows them (the kinematics columns)
      step%link_angles = kinematics
      !$omp do schedule(dynamic, 64) reduction(min:first_bad)
      do kk = first, last
        i = kk - first + 1
        if (self%deck%dyn%mode >= dynamics_steady) then
          ! the true motion, the flywheel's and the rotor's inertia moment on the crank
          motions(i) = assur_motion(self%source, self%cycle, kk)
          call solve_one(self%deck, kk, motions(i)%omega, step, fs, step_error, loads, motions(i)%eps, &
                         -(self%cycle%j_flywheel + self%cycle%j_rotor) * motions(i)%eps)
        else
          if (self%deck%dyn%mode /= dynamics_none) motions(i) = assur_motion(self%source, self%cycle, kk)
          call solve_one(self%deck, kk, omega1(i), step, fs, step_error, loads)
        end if
        m1(i) = step%m1
        if (allocated(step_error)) then
          first_bad = min(first_bad, kk)
          cycle
        end if
        call assur_row(self%deck, plan, step, table%rows(1:nv, i), lengths)
        if (self%deck%friction_on) then
          table%rows(nv + 1:nc, i) = friction_csv_values(self%deck, step, fs)
          fsteps(i) = fs
        end if
        residual(i) = step%residual
        mismatch(i) = step%mismatch
        if (kinematics) call assur_kinematics_row(self%deck, plan, step, lengths, slots, values, link_turns, &
          table%rows(:, i))
      end do
      !$omp end do
    end block
    !$omp end parallel
    if (first_bad <= last) then
      call step_failure(table%deck, self%deck, first_bad, omega1(first_bad - first + 1), error)
      return
    end if
    if (self%deck%dyn%mode /= dynamics_none) then
      do k = 1, nrow
        call put_dynamics_values(table, k, self%deck%dyn%mode, motions(k))
      end do
      if (self%deck%dyn%mode >= dynamics_steady) call constant_speed_cost(self%deck, first, last, omega1, table)
      if (self%deck%dyn%mode >= dynamics_steady) call note_drive_deviation(table, m1, motions, self%cycle%j_flywheel)
    end if
    if (self%deck%mech%drive_dyad == 0) then
      call table%set_selfcheck(maxval(residual), maxval(mismatch), "M1", &
      worst_row(residual), worst_row(mismatch))
    else
      call table%set_selfcheck(maxval(residual), maxval(mismatch), "F_drive", &
      worst_row(residual), worst_row(mismatch))
    end if
    if (self%deck%friction_on) then
      table%residual_label = "MAX EQUILIBRIUM RESIDUAL WITH FRICTION LOADS"
      table%mismatch_label = "MAX "//table%driver//" MISMATCH, POWER BALANCE WITH FRICTION"
      ! the works over the run: the pipeline integrates the block's powers in row order
      table%block_tally%integrals = friction_integrals(self%deck, fsteps, first)
    end if
  end subroutine solve

  !> The run's summary with friction (works and efficiency), from the works integrated over
  !> the whole run.
  pure subroutine finish_run(self, table)
    class(assur_mechanism_t), intent(in) :: self
    type(step_table_t), intent(inout) :: table
    if (.not. self%deck%friction_on .or. .not. allocated(table%run_tally%integrals)) return
    call friction_summary(self%deck, table%run_tally%integrals(1)%area, table%run_tally%integrals(2)%area, table)
  end subroutine finish_run

  !> The peaks of the pair forces with the true motion (the table's magnitude columns) against
  !> those at the constant mean speed (the block's steps solved again at omega1, eps1 = 0).
  subroutine constant_speed_cost(deck, first, last, omega1, table)
    type(assur_deck_t), intent(in) :: deck
    integer, intent(in) :: first, last
    !> The deck's constant speed per step, rad/s.
    real(wp), intent(in) :: omega1(:)
    type(step_table_t), intent(inout) :: table
    type(assur_step_t) :: step
    type(friction_step_t) :: fs
    type(step_loads_t) :: loads
    type(error_t), allocatable :: step_error
    real(wp) :: peak_const(size(deck%pair_name))
    integer :: kk, ip, c
    peak_const = 0.0_wp
    do kk = first, last
      call solve_one(deck, kk, omega1(kk - first + 1), step, fs, step_error, loads)
      if (allocated(step_error)) return
      do ip = 1, size(deck%pair_name)
        peak_const(ip) = max(peak_const(ip), magnitude(step%f(:, ip)))
      end do
    end do
    do ip = 1, size(deck%pair_name)
      c = table%column_index(trim(deck%pair_name(ip)))
      call note_constant_speed_cost(table, trim(deck%pair_name(ip)), maxval(table%rows(c, :)), peak_const(ip))
    end do
  end subroutine constant_speed_cost

  !> All steps of a validated deck; a geometry error names the step and the input angle.
  subroutine assur_solve(path, deck, steps, error, fsteps, first, last)
    !> Deck file (for messages).
    character(*), intent(in) :: path
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> One result per step.
    type(assur_step_t), allocatable, intent(out) :: steps(:)
    !> Geometry error (also: friction does not converge, self-locking).
    type(error_t), allocatable, intent(out) :: error
    !> Friction results per step (deck%friction_on; else none).
    type(friction_step_t), allocatable, intent(out), optional :: fsteps(:)
    !> Steps to compute (default: all); steps(1) is step `first`.
    integer, intent(in), optional :: first, last
    type(error_t), allocatable :: step_error
    type(friction_step_t) :: fs
    type(step_loads_t) :: loads
    integer :: k, k1, k2, first_bad, stat
    logical :: keep_friction
    !> Crank speed of steps k1..k2, rad/s (a list's signs carry from step to step).
    real(wp), allocatable :: omega1(:)
    call step_span(deck%n, k1, k2, first, last)
    allocate (steps(k2 - k1 + 1), stat=stat)
    keep_friction = present(fsteps)
    if (stat == 0 .and. keep_friction) allocate (fsteps(merge(k2 - k1 + 1, 0, deck%friction_on)), stat=stat)
    if (stat /= 0) then
      call lack_block_memory(error, k2 - k1 + 1, (storage_size(steps, int64) + storage_size(fs, int64)) / 8)
      return
    end if
    omega1 = assur_omega1_steps(deck, k1, k2)
    ! steps in parallel with OpenMP threads; the error reported is the first step's in step order
    ! (that step is solved again alone for its message)
    first_bad = k2 + 1
    !$omp parallel do schedule(dynamic, 64) private(fs, step_error, loads) reduction(min:first_bad)
    do k = k1, k2
      call solve_one(deck, k, omega1(k - k1 + 1), steps(k - k1 + 1), fs, step_error, loads)
      if (deck%friction_on .and. keep_friction) fsteps(k - k1 + 1) = fs
      if (allocated(step_error)) first_bad = min(first_bad, k)
    end do
    !$omp end parallel do
    if (first_bad <= k2) call step_failure(path, deck, first_bad, omega1(first_bad - k1 + 1), error)
  end subroutine assur_solve

  !> Step `k` of the deck at crank speed `w` (rad/s; assur_omega1_steps): its results, its
  !> friction results (deck%friction_on), its error; `loads` is the caller's workspace for the
  !> step's load values (sized here on first use).
  pure subroutine solve_one(deck, k, w, step, fstep, step_error, loads, eps1, m_input)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> Step number.
    integer, intent(in) :: k
    !> Crank speed of the step, rad/s.
    real(wp), intent(in) :: w
    !> Results (its arrays reused).
    type(assur_step_t), intent(inout) :: step
    !> Friction results.
    type(friction_step_t), intent(out) :: fstep
    !> Geometry error.
    type(error_t), allocatable, intent(out) :: step_error
    !> The force and moment values of the step.
    type(step_loads_t), intent(inout) :: loads
    !> Crank acceleration of the true motion, rad/s^2 (default: the deck's).
    real(wp), intent(in), optional :: eps1
    !> Inertia moment of the flywheel and rotor on the crank, N*m (with eps1).
    real(wp), intent(in), optional :: m_input
    integer :: i
    if (.not. allocated(loads%f)) allocate (loads%f(size(deck%force_load)), loads%m(size(deck%moment_load)))
    do i = 1, size(loads%f)
      loads%f(i) = assur_load_value(deck, deck%force_load(i), k)
    end do
    do i = 1, size(loads%m)
      loads%m(i) = assur_load_value(deck, deck%moment_load(i), k)
    end do
    if (present(eps1) .and. present(m_input)) then
      if (.not. allocated(loads%extra)) allocate (loads%extra(0:2 * size(deck%mech%dyads) + 1))
      do i = 0, ubound(loads%extra, 1)
        loads%extra(i) = link_balance_t()
      end do
      call balance_add_couple(loads%extra(1), m_input)
      call assur_step(deck%mech, assur_phi1_deg(deck, k) * deg_to_rad, w, eps1, loads%f, loads%m, step, step_error, &
                      loads%extra, m_input, abs(m_input))
    else if (deck%friction_on) then
      call assur_friction_step(deck%mech, deck%friction, assur_phi1_deg(deck, k) * deg_to_rad, w, &
        assur_eps1(deck, k), assur_motion_sign(w), loads%f, loads%m, step, fstep, step_error)
    else
      call assur_step(deck%mech, assur_phi1_deg(deck, k) * deg_to_rad, w, assur_eps1(deck, k), &
                      loads%f, loads%m, step, step_error)
    end if
  end subroutine solve_one

  !> The error of a run stopped at step `k` (crank speed `w`, rad/s; solved again for its
  !> message), naming the step and its input angle.
  pure subroutine step_failure(path, deck, k, w, error)
    !> Deck file (for messages).
    character(*), intent(in) :: path
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> The first failing step.
    integer, intent(in) :: k
    !> Its crank speed, rad/s.
    real(wp), intent(in) :: w
    !> The error.
    type(error_t), allocatable, intent(out) :: error
    type(assur_step_t) :: step
    type(friction_step_t) :: fs
    type(step_loads_t) :: loads
    type(error_t), allocatable :: step_error
    character(len=32) :: angle_text
    call solve_one(deck, k, w, step, fs, step_error, loads)
    write (angle_text, '(g0.10)') assur_phi1_deg(deck, k)
    call fatal_error(error, exit_geometry, path//": &assur: step "//int_str(k)//" (phi1 = "// &
      trim(adjustl(angle_text))//" deg): "//step_error%message)
  end subroutine step_failure

  !> The kinematics columns' names, in the deck's global frame (their values:
  !> assur_kinematics_row, in the same order): the reference point J<pair> of every pair
  !> (x_J21 for the pair of F21: the pin of a revolute pair, the slider's reference point of
  !> a prismatic pair; the crank's pair with the frame is the pivot), the centre of mass
  !> S<id> of every moving link, the angle (of the link's x axis), angular velocity and
  !> acceleration of every moving link (named by link_label), the acceleration of every S,
  !> and the components of every pair force as the F<pair>x, F<pair>y columns give them and
  !> in the axes of the link it acts on.
  !>
  !> Without `slots` the columns are created (table%put_point, ...: appended on first use,
  !> row 1 at 0 until the values come). With `slots` nothing is written: slots(j) is set to
  !> the column of the j-th value (0: a column that is not a kinematics column keeps its
  !> value) by the same names.
  pure subroutine put_kinematics(table, deck, slots)
    !> The step table (columns appended on first use).
    type(step_table_t), intent(inout) :: table
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> Column of every value, in the order they are put (kinematics_value_count).
    integer, intent(out), optional :: slots(:)
    real(wp), parameter :: zero(2) = 0.0_wp
    character(len=:), allocatable :: label
    integer :: i, ip, np, nl, j, mode
    mode = kin_by_name
    if (present(slots)) mode = kin_finding
    j = 0
    np = size(deck%pair_name)
    nl = 2 * size(deck%mech%dyads) + 1
    do ip = 1, np
      call put_kin_point(table, mode, j, slots, joint_name(deck, deck%pair_name(ip)))
    end do
    do i = 1, nl
      call put_kin_point(table, mode, j, slots, "S"//int_str(deck%mech%links(i)%id))
    end do
    do i = 1, nl
      label = link_label(deck, i)
      if (mode == kin_by_name) then
        call table%put_link(1, label, 0.0_wp, 0.0_wp, 0.0_wp)
      else
        call find_kin_slot(table, j, slots, "phi", label)
        call find_kin_slot(table, j, slots, "omega", label)
        call find_kin_slot(table, j, slots, "eps", label)
      end if
    end do
    do i = 1, nl
      if (mode == kin_by_name) then
        call table%put_acceleration(1, "S"//int_str(deck%mech%links(i)%id), zero)
      else
        call find_kin_slot(table, j, slots, "ax_", "S"//int_str(deck%mech%links(i)%id))
        call find_kin_slot(table, j, slots, "ay_", "S"//int_str(deck%mech%links(i)%id))
      end if
    end do
    do ip = 1, np
      if (mode == kin_by_name) then
        call table%put_components(1, trim(deck%pair_name(ip)), zero, deck%pair_frame(ip) * rad_to_deg)
      else
        call find_kin_slot(table, j, slots, trim(deck%pair_name(ip)), "_x")
        call find_kin_slot(table, j, slots, trim(deck%pair_name(ip)), "_y")
      end if
    end do
    do ip = 1, np
      if (mode == kin_by_name) then
        call table%put_link_axes(1, trim(deck%pair_name(ip)), zero, link_label(deck, pair_link(deck, ip)))
      else
        call find_kin_slot(table, j, slots, trim(deck%pair_name(ip)), "_along")
        call find_kin_slot(table, j, slots, trim(deck%pair_name(ip)), "_across")
      end if
    end do
  end subroutine put_kinematics

  !> put_kinematics' point `name` (x_<name>, y_<name>) by `mode`.
  pure subroutine put_kin_point(table, mode, j, slots, name)
    !> The step table.
    type(step_table_t), intent(inout) :: table
    !> kin_by_name or kin_finding.
    integer, intent(in) :: mode
    !> Values named so far in the row.
    integer, intent(inout) :: j
    !> Column of every value.
    integer, intent(inout), optional :: slots(:)
    !> Point name.
    character(*), intent(in) :: name
    if (mode == kin_by_name) then
      call table%put_point(1, name, [0.0_wp, 0.0_wp])
    else
      call find_kin_slot(table, j, slots, "x_", name)
      call find_kin_slot(table, j, slots, "y_", name)
    end if
  end subroutine put_kin_point

  !> The column of put_kinematics' next value: the last column named prefix//suffix (as
  !> put_kinematic finds it), 0 when it is not a kinematics or link-axes column.
  pure subroutine find_kin_slot(table, j, slots, prefix, suffix)
    !> The step table.
    type(step_table_t), intent(in) :: table
    !> Values put so far in the row.
    integer, intent(inout) :: j
    !> Column of every value.
    integer, intent(inout) :: slots(:)
    !> The two parts of the column's name.
    character(*), intent(in) :: prefix, suffix
    integer :: c
    j = j + 1
    slots(j) = 0
    do c = size(table%columns), 1, -1
      if (len(table%columns(c)%name) /= len(prefix) + len(suffix)) cycle
      if (table%columns(c)%name == prefix//suffix) then
        if (table%columns(c)%kinematic .or. table%columns(c)%link_axes) slots(j) = c
        return
      end if
    end do
  end subroutine find_kin_slot

  !> The moving links: the input link and the two links of every dyad, each at its centre of
  !> mass S<id> (link names are the deck's link ids); gravity g along the deck's `down`.
  pure subroutine mass_model(self, model)
    class(assur_mechanism_t), intent(in) :: self
    type(mass_model_t), intent(out) :: model
    integer :: i, d, q
    integer, allocatable :: frame_pairs(:)
    character(len=:), allocatable :: name, moment
    associate (mech => self%deck%mech)
      do i = 1, 2 * size(mech%dyads) + 1
        associate (l => mech%links(i))
          call model%add(link_label(self%deck, i), "S"//int_str(l%id), l%m, l%j)
        end associate
      end do
      model%gravity = mech%g * mech%down
      ! the pairs with the frame (an actuator's pair with the frame would also pass its drive
      ! force to the frame: such a deck reports no frame total)
      if (mech%drive_dyad > 0) then
        if (mech%dyads(mech%drive_dyad)%on(1 + (mech%drive_pair - 1) / 2) == 0 .and. mech%drive_pair /= 2) return
      end if
      allocate (frame_pairs(0))
      do d = 1, size(mech%dyads)
        do q = 1, 2
          if (mech%dyads(d)%on(q) == 0) frame_pairs = [frame_pairs, pair_index(d, 2 * q - 1)]
        end do
      end do
      frame_pairs = [frame_pairs, crank_pin_index(size(mech%dyads))]
      do i = 1, size(frame_pairs)
        name = trim(self%deck%pair_name(frame_pairs(i)))
        moment = ""
        if (assur_pair_prismatic(self%deck, frame_pairs(i))) moment = name//"M"
        call model%add_frame_pair(name, joint_name(self%deck, name), moment)
      end do
      model%drive = ""
      if (mech%drive_dyad == 0) model%drive = "M1"
    end associate
  end subroutine mass_model

  !> The forces of row `k` on its drawing (--format svg --at K): every pair force at its
  !> pair's point J<pair>, the deck's external forces (Q<i>, at their points) and moments
  !> (MQ<i>, at the link's centre of mass), the weights, inertia forces and moments of the
  !> moving links, and M1 at the crank's pivot or a linear actuator's F_drive at its pair.
  pure subroutine force_plan(self, table, k, drawing, error)
    class(assur_mechanism_t), intent(in) :: self
    type(step_table_t), intent(in) :: table
    !> Row drawn: the links' states at its crank angle place the deck's forces and moments.
    integer, intent(in) :: k
    type(drawing_t), intent(inout) :: drawing
    type(error_t), allocatable, intent(out) :: error
    type(link_state_t) :: states(0:2 * size(self%deck%mech%dyads) + 1)
    type(dyad_pose_t) :: poses(size(self%deck%mech%dyads))
    type(point_state_t) :: ps
    type(mass_model_t) :: model
    real(wp) :: dir
    integer :: ip, i, sides(2)
    associate (mech => self%deck%mech, deck => self%deck)
      call assur_kinematics(mech, assur_phi1_deg(deck, table%run_row(k)) * deg_to_rad, states, poses, error)
      if (allocated(error)) return
      do ip = 1, size(deck%pair_name)
        call drawing%pair_from_table(table, k, trim(deck%pair_name(ip)), joint_name(deck, deck%pair_name(ip)), error)
        if (allocated(error)) return
      end do
      do i = 1, size(mech%forces)
        associate (f => mech%forces(i))
          ps = point_on(states(f%link), f%at)
          dir = f%angle
          if (f%follow) dir = dir + states(f%link)%th
          call drawing%add_force("Q"//int_str(i), force_load, ps%p, &
                                 assur_load_value(deck, deck%force_load(i), table%run_row(k)) * [cos(dir), sin(dir)], &
                                 int_str(mech%links(f%link)%id))
        end associate
      end do
      do i = 1, size(mech%moment_link)
        call drawing%add_moment("MQ"//int_str(i), force_load, drawing%at("S"//int_str(mech%links(mech%moment_link(i))%id)), &
          assur_load_value(deck, deck%moment_load(i), table%run_row(k)), int_str(mech%links(mech%moment_link(i))%id))
      end do
      ! the centre of mass of a link not named by its number (link 1 not the crank, "L1": S1)
      do i = 2, 2 * size(mech%dyads) + 1
        if (link_label(deck, i) == int_str(mech%links(i)%id)) cycle
        if (drawing%point_index("S"//int_str(mech%links(i)%id)) > 0 .or. &
          table%column_index("x_S"//int_str(mech%links(i)%id)) == 0) cycle
        call drawing%point_from_table(table, k, "S"//int_str(mech%links(i)%id), point_com, error)
        if (allocated(error)) return
      end do
      call self%mass_model(model)
      call drawing%add_body_loads(table, k, model)
      ! the balancing moment on the crank (a deck driven otherwise has no M1 column)
      i = table%column_index("M1")
      if (i > 0) call drawing%add_moment("M1", force_load, &
        drawing%at(joint_name(deck, deck%pair_name(crank_pin_index(size(mech%dyads))))), table%rows(i, k))
      ! a linear actuator's force F_drive on the sliding side of its pair, along `extend` (the
      ! plans add its reaction on the other side)
      i = table%column_index("F_drive")
      if (i > 0 .and. mech%drive_dyad > 0) then
        associate (dd => mech%drive_dyad, jd => mech%drive_pair)
          sides = pair_sides(mech, dd, jd)
          call drawing%add_force("F_drive", force_load, drawing%at(joint_name(deck, deck%pair_name(pair_index(dd, jd)))), &
            table%rows(i, k) * poses(dd)%extend(:, jd), link_label(deck, sides(1)))
        end associate
      end if
    end associate
  end subroutine force_plan

  !> The default name of every pair's joint, J<pair> (J21 for F21).
  pure function joint_default_names(deck) result(names)
    type(assur_deck_t), intent(in) :: deck
    character(len=len(deck%joint_name)) :: names(size(deck%pair_name))
    integer :: ip
    do ip = 1, size(names)
      names(ip) = "J"//trim(deck%pair_name(ip)(2:))
    end do
  end function joint_default_names

  !> The joints' names for the INPUT DATA echo: "B (F21), C (F23), ...", pairs in the deck's order.
  pure function joint_list(deck) result(text)
    type(assur_deck_t), intent(in) :: deck
    character(len=:), allocatable :: text
    type(string_t) :: parts(size(deck%joint_name))
    integer :: ip
    do ip = 1, size(parts)
      parts(ip)%s = trim(deck%joint_name(ip))//" ("//trim(deck%pair_name(ip))//")"
    end do
    text = joined(parts, ", ")
  end function joint_list

  !> The joint of a pair: the deck's name for it (`dyad(i)%joints`, `crank_joint`), else
  !> "J21" for the pair of F21.
  pure function joint_name(deck, pair_name) result(name)
    type(assur_deck_t), intent(in) :: deck
    character(*), intent(in) :: pair_name
    character(len=:), allocatable :: name
    integer :: ip
    name = "J"//trim(pair_name(2:))
    do ip = 1, size(deck%pair_name)
      if (deck%pair_name(ip) == pair_name) then
        name = trim(deck%joint_name(ip))
        return
      end if
    end do
  end function joint_name

  !> The INPUT DATA echo of the deck (every deck value, dyad by dyad).
  pure subroutine echo_deck(deck, table)
    type(assur_deck_t), intent(in) :: deck
    type(step_table_t), intent(inout) :: table
    character(len=160) :: line
    integer :: k, d
    if (deck%global) then
      call table%echo_text("COORDINATES", "global (echoed below as derived link coordinates)")
      call table%echo_real("PHI_REF", deck%phi_ref, "deg")
    end if
    call table%echo_int("FRAME_ID", deck%frame_id, "")
    call table%echo_int("CRANK_ID", deck%crank_id, "")
    call table%echo_array("CRANK_AT", deck%mech%pivot, "m")
    call table%echo_real("CRANK_M", deck%mech%links(1)%m, "kg")
    call table%echo_real("CRANK_J", deck%mech%links(1)%j, "kg*m^2")
    call table%echo_array("CRANK_S", deck%mech%links(1)%s, "m")
    if (deck%friction_on) call echo_friction(deck, size(deck%friction), "CRANK_", "", table)
    if (allocated(deck%phi_list) .and. .not. deck%prescribed) then
      call table%echo_real("OMEGA1", deck%omega1_const, "rad/s")
      call table%echo_array("OMEGA1_STEP", assur_omega1_steps(deck, 1, deck%n), "rad/s")
    else if (deck%prescribed) then
      call table%echo_array("OMEGA1_STEP", deck%omega1_values(1:deck%n), "rad/s")
      call table%echo_array("EPS1_STEP", deck%eps1_values(1:deck%n), "rad/s^2")
    else
      call table%echo_real("OMEGA1", deck%omega1_const, "rad/s")
    end if
    call table%echo_real("G", deck%mech%g, "m/s^2")
    call table%echo_real("GRAVITY_ANGLE", deck%gravity_angle, "deg")
    if (allocated(deck%phi_list)) then
      call table%echo_array("PHI1", deck%phi_list(1:deck%n), "deg")
    else
      if (deck%start_extreme) then
        call table%echo_text("START_AT", "extreme")
        call table%echo_int("OUTPUT_LINK", deck%mech%links(deck%mech%output_link)%id, "")
      end if
      call table%echo_real("PHI_START", deck%phi_start, "deg")
      call table%echo_real("DPHI", deck%dphi, "deg")
    end if
    call table%echo_int("N", deck%n, "steps")
    call table%echo_logical("ANGLES_SIGNED", deck%angles_signed, "")
    call table%echo_logical("COMPONENTS", deck%components, "")
    if (any(deck%joint_name /= joint_default_names(deck))) call table%echo_text("JOINTS", joint_list(deck))
    if (deck%mech%drive_dyad > 0) then
      call table%echo_int("DRIVE_DYAD", deck%mech%drive_dyad, "")
      call table%echo_int("DRIVE_PAIR", deck%mech%drive_pair, "")
    end if
    do d = 1, size(deck%mech%dyads)
      associate (dy => deck%mech%dyads(d), lk => deck%mech%links)
        write (line, dyad_echo_fmt) d, kind_names(dy%geom%kind), lk(2 * d)%id, lk(2 * d + 1)%id, &
          lk(dy%on(1))%id, lk(dy%on(2))%id, dy%geom%mode
        call table%echo_line(trim(line))
        call table%echo_array("AT2", dy%at(:, 1), "m")
        call table%echo_array("AT3", dy%at(:, 2), "m")
        ! only what the dyad's kind uses (an RRP has no L3: a 0 there would look like a mistake)
        associate (kind => dy%geom%kind)
          if (kind == kind_prp) call table%echo_real("ANGLE2", dy%ang(1) * rad_to_deg, "deg")
          if (any(kind == [kind_rrp, kind_prp, kind_rpp])) call table%echo_real("ANGLE3", dy%ang(2) * rad_to_deg, "deg")
          if (any(kind == [kind_rrr, kind_rrp])) call table%echo_real("L2", dy%geom%l2, "m")
          if (kind == kind_rrr) call table%echo_real("L3", dy%geom%l3, "m")
          if (kind == kind_rpr) call table%echo_real("E", dy%geom%e, "m")
          if (kind == kind_rpp) then
            call table%echo_array("SLOT_AT", dy%geom%slot_at, "m")
            call table%echo_real("SLOT_ANGLE", dy%geom%slot_angle * rad_to_deg, "deg")
          end if
        end associate
        call table%echo_real("M2", lk(2 * d)%m, "kg")
        call table%echo_real("J2", lk(2 * d)%j, "kg*m^2")
        call table%echo_array("S2", lk(2 * d)%s, "m")
        call table%echo_real("M3", lk(2 * d + 1)%m, "kg")
        call table%echo_real("J3", lk(2 * d + 1)%j, "kg*m^2")
        call table%echo_array("S3", lk(2 * d + 1)%s, "m")
        call table%echo_real("FRAME_ANGLE", deck%pair_frame(3 * d) * rad_to_deg, "deg")
        call table%echo_int("INNER_ON", lk(merge(2 * d + 1, 2 * d, deck%pair_sign(3 * d - 1) < 0.0_wp))%id, "")
        if (deck%friction_on) then
          call echo_friction(deck, 3 * d - 2, "", "2", table)
          call echo_friction(deck, 3 * d - 1, "", "23", table)
          call echo_friction(deck, 3 * d, "", "3", table)
        end if
      end associate
    end do
    do k = 1, size(deck%mech%forces)
      associate (fo => deck%mech%forces(k))
        call table%echo_int("FORCE "//int_str(k)//" LINK", deck%mech%links(fo%link)%id, "")
        call table%echo_array("  AT", fo%at, "m")
        call table%echo_real("  ANGLE", fo%angle * rad_to_deg, "deg")
        call table%echo_logical("  FOLLOW", fo%follow, "")
        call echo_load(deck, deck%force_load(k), "N", table)
      end associate
    end do
    do k = 1, size(deck%mech%moment_link)
      call table%echo_int("MOMENT "//int_str(k)//" LINK", deck%mech%links(deck%mech%moment_link(k))%id, "")
      call echo_load(deck, deck%moment_load(k), "N*m", table)
    end do
    call echo_dynamics(table, deck%dyn, deck%mech%drive_dyad > 0)
  end subroutine echo_deck

  !> The echo line "  VALUE" of a load: its value at every step (a step_values column as
  !> given; other schedules computed into a temporary).
  pure subroutine echo_load(deck, load, unit, table)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> The load's schedule.
    type(load_schedule_t), intent(in) :: load
    !> Unit of its values ("N" or "N*m").
    character(*), intent(in) :: unit
    type(step_table_t), intent(inout) :: table
    if (load%resist /= resist_none) call table%echo_logical("  RESIST", .true., "")
    if (load%kind == load_column .and. load%resist == resist_none) then
      call table%echo_array("  VALUE", deck%step_values(load%offset + 1:load%offset + deck%n), unit)
    else
      call table%echo_array("  VALUE", roundoff_to_zero(assur_load_steps(deck, load)), unit)
    end if
  end subroutine echo_load

  !> Computed values (a table's interpolation) with roundoff around zero set to 0: |v| <=
  !> 1e-12 of the largest (an interpolated zero is 0, not 5.684342E-14).
  pure function roundoff_to_zero(values) result(v)
    !> The values.
    real(wp), intent(in) :: values(:)
    real(wp) :: v(size(values))
    v = values
    if (size(v) == 0) return
    where (abs(v) <= 1.0e-12_wp * maxval(abs(v))) v = 0.0_wp
  end function roundoff_to_zero

  !> The step table's load-edge marks (the coarse-step warning) of one load: a constant
  !> has none (skipped); a step_values column is passed as given, other schedules computed
  !> into a temporary.
  pure subroutine note_load(deck, load, table)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> The load's schedule.
    type(load_schedule_t), intent(in) :: load
    type(step_table_t), intent(inout) :: table
    select case (load%kind)
    case (load_constant)
      if (load%resist == resist_none) return
      call table%note_load(assur_load_steps(deck, load))
    case (load_column)
      if (load%resist /= resist_none) then
        call table%note_load(assur_load_steps(deck, load))
        return
      end if
      call table%note_load(deck%step_values(load%offset + 1:load%offset + deck%n))
    case default
      call table%note_load(assur_load_steps(deck, load))
    end select
  end subroutine note_load

  !> The warning of a load table whose peak the steps miss (table_peak_warning): from every
  !> step's position in the table's abscissa (the crank's angle, a link's angle or stroke).
  pure subroutine note_table_peak(deck, load, name, unit, table)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> A load's schedule (nothing unless a table).
    type(load_schedule_t), intent(in) :: load
    !> The table's deck variable and the load's unit.
    character(*), intent(in) :: name, unit
    type(step_table_t), intent(inout) :: table
    real(wp), allocatable :: q(:), phi(:)
    character(len=:), allocatable :: warning
    !> How the message names a position of the table and its unit.
    character(len=64) :: abscissa(2)
    logical :: ok
    integer :: k, stat
    if (load%kind /= load_table) return
    allocate (q(deck%n), stat=stat)
    if (stat == 0) allocate (phi(deck%n), stat=stat)
    if (stat /= 0) return
    do k = 1, deck%n
      call table_position(deck, load, k, q(k), ok)
      if (.not. ok .and. k > 1) q(k) = q(k - 1)
      phi(k) = assur_phi1_deg(deck, k)
    end do
    abscissa(2) = "deg"
    if (load%pair /= 0) abscissa(2) = "m"
    if (load%link == 1 .and. load%pair == 0) then
      abscissa(1) = "phi1 ="
    else if (load%pair == 0) then
      abscissa(1) = "the angle of link "//int_str(deck%mech%links(load%link)%id)//" ="
    else
      abscissa(1) = "the stroke of link "//int_str(deck%mech%links(load%link)%id)//" ="
    end if
    call table_peak_warning(name, unit, load%x, load%v, q, abscissa, "phi1", "deg", phi, "dphi", warning)
    if (allocated(warning)) call table%add_warning(warning)
  end subroutine note_table_peak

  !> INPUT DATA lines of the friction of result pair `ip`: F, and R (turning pair) or
  !> CONTACT_SPAN (sliding pair; 0: resultant-normal model), named prefix//name//suffix.
  pure subroutine echo_friction(deck, ip, prefix, suffix, table)
    type(assur_deck_t), intent(in) :: deck
    integer, intent(in) :: ip
    character(*), intent(in) :: prefix, suffix
    type(step_table_t), intent(inout) :: table
    call table%echo_real(prefix//"F"//suffix, deck%friction(ip)%f, "")
    if (assur_pair_prismatic(deck, ip)) then
      call table%echo_real(prefix//"CONTACT_SPAN"//suffix, deck%friction(ip)%span, "m")
    else
      call table%echo_real(prefix//"R"//suffix, deck%friction(ip)%r, "m")
    end if
  end subroutine echo_friction

  !> RESULTS: per step the crank angle, every pair's magnitude and M1; under them the angles;
  !> for prismatic pairs two more lines with the normal force and the reaction moment. With a
  !> linear actuator as driver the last column holds F_drive, stroke, stroke speed and
  !> acceleration (lines 1-4) instead of M1.
  pure subroutine put_results(self, table, page, out, later)
    class(assur_mechanism_t), intent(in) :: self
    type(step_table_t), intent(in) :: table
    type(results_page_t), intent(in) :: page
    type(text_buffer_t), intent(inout) :: out, later
    ! the unit lines of the force and angle lines only; with --frame link, a line on the axes
    call put_layout_block(out, table, page, results_layout(self%deck, table%link_frame), .true., unit_lines=2, &
      above=link_axes_heading(table, page%lang, crank_axes=.true.))
    ! the friction block follows the last row (in `later`)
    if (self%deck%friction_on) call write_friction_block(table, &
      trim(merge("F_drive", "M1     ", self%deck%mech%drive_dyad > 0)), phi_width, .true., page%lang, later)
  end subroutine put_results


  !> The RESULTS layout of a step: line 1 PHI1, every pair's force and M1 (or the
  !> actuator's force), line 2 the angles (or the stroke); with --frame link the pairs' along
  !> and across components instead. With a prismatic pair (or an actuator) lines 3 and 4:
  !> the normal forces and moments of the prismatic pairs (the stroke's speed and acceleration).
  pure function results_layout(deck, link_axes) result(fields)
    type(assur_deck_t), intent(in) :: deck
    !> --frame link.
    logical, intent(in) :: link_axes
    type(table_field_t), allocatable :: fields(:)
    character(len=:), allocatable :: name
    logical :: drive, any_p
    integer :: ip, line
    drive = deck%mech%drive_dyad > 0
    any_p = .false.
    do ip = 1, size(deck%pair_name)
      any_p = any_p .or. assur_pair_prismatic(deck, ip)
    end do
    fields = [field("phi1", phi_width, 2)]
    do ip = 1, size(deck%pair_name)
      name = trim(deck%pair_name(ip))
      if (link_axes) then
        fields = [fields, field(name//"_along", field_width, 2, cut=.true.)]
      else
        fields = [fields, field(name, field_width, 2, cut=.true.)]
      end if
    end do
    if (drive) then
      fields = [fields, field("F_drive", field_width, 2)]
    else
      fields = [fields, field("M1", field_width, 2)]
    end if
    fields = [fields, blank_field(phi_width, 2)]
    do ip = 1, size(deck%pair_name)
      name = trim(deck%pair_name(ip))
      if (link_axes) then
        fields = [fields, field(name//"_across", field_width, 2, line=2, cut=.true.)]
      else
        fields = [fields, field(name//"G", field_width, 2, line=2)]
      end if
    end do
    if (drive) fields = [fields, field("stroke", field_width, stroke_decimals, line=2)]
    if (.not. (any_p .or. drive)) return
    do line = 3, 4
      fields = [fields, blank_field(phi_width, line)]
      do ip = 1, size(deck%pair_name)
        name = trim(deck%pair_name(ip))//merge("N", "M", line == 3)
        if (assur_pair_prismatic(deck, ip)) then
          ! headed at the left of the field, as the table always printed them
          fields = [fields, field(name, field_width, 2, line=line, cut=.true., left=.true.)]
        else
          fields = [fields, blank_field(field_width, line)]
        end if
      end do
      if (drive) fields = [fields, field(merge("stroke_v", "stroke_a", line == 3), field_width, stroke_decimals, line=line)]
    end do
  end function results_layout

end module kinetostat_assur_layout
