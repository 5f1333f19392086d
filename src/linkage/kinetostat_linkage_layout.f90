!> Any planar linkage of lower pairs as a mechanism of the run pipeline: `&linkage` deck ->
!> every step (continuation from the previous step's poses) -> step table (each drive's
!> input, every pair's force, each drive's effort), its INPUT DATA echo with the structural
!> analysis, and the legacy table layout.
module kinetostat_linkage_layout
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_kinds, only: wp, rad_to_deg, deg_to_rad, pi
  use kinetostat_deck, only: deck_source_t
  use kinetostat_error, only: error_t
  use kinetostat_text, only: int_str, real_str, upper
  use kinetostat_noise, only: noise_rel
  use kinetostat_vec2, only: magnitude, largest_magnitude, angle_360_deg, clean_zero, rotate
  use kinetostat_step_table, only: step_table_t, column_t, column, col_input_angle, col_component, col_moment, &
    col_length, col_other, lack_block_memory
  use kinetostat_table_layout, only: table_field_t, field, blank_field, force_and_angle, &
    results_page_t, put_layout_block, link_axes_heading
  use kinetostat_labels, only: lang_ru, lang_en
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_friction_block, only: write_friction_block
  use kinetostat_escape, only: table_text
  use kinetostat_mechanism, only: mechanism_t
  use kinetostat_run_tally, only: running_max_t
  use kinetostat_sketch, only: sketch_t
  use kinetostat_drawing, only: drawing_t, force_load
  use kinetostat_bodies, only: mass_model_t
  use kinetostat_linkage, only: linkage_t, linkage_step_t, pair_r, pair_p, linkage_reference_pose, linkage_assemble, &
    linkage_motion, linkage_fast_motion, linkage_statics, link_point_state, point_position, linkage_work_t
  use kinetostat_linkage_structure, only: structure_lines
  use kinetostat_linkage_friction, only: linkage_friction_t, linkage_friction_solve
  use kinetostat_linkage_friction_table, only: add_friction_columns, friction_values, friction_integrals, &
    friction_summary, echo_friction
  use kinetostat_dynamics, only: cycle_t, motion_t, reduced_t, motion_from, dynamics_reduced, dynamics_steady
  use kinetostat_dynamics_deck, only: deck_cycle
  use kinetostat_dynamics_table, only: echo_dynamics, add_dynamics_columns, put_dynamics_values, &
    put_dynamics_figures, note_drive_deviation
  use kinetostat_linkage_dynamics, only: linkage_source_t, linkage_source_setup, linkage_reduced_at_pose, &
    linkage_load_breaks, linkage_source_at
  use kinetostat_linkage_deck, only: linkage_deck_t, read_linkage_deck, linkage_template, linkage_drive_values, &
    linkage_load_value, linkage_table_position, linkage_schedule_t
  implicit none
  private
  public :: linkage_mechanism_t, new_linkage, linkage_structure_text, linkage_solve_steps

  !> Width of the first field of the RESULTS block.
  integer, parameter :: first_width = 9
  !> Width of the friction block's first column (the first drive's value).
  integer, parameter :: friction_first_width = 10
  !> Width of every other field.
  integer, parameter :: field_width = 12
  !> A gap of the Lagrange and the group method's reactions above this (relative) is a warning.
  real(wp), parameter :: gap_tolerance = 1.0e-9_wp

  !> A run of steps' state (stepper_ready, linkage_solve_step).
  type :: linkage_stepper_t
    !> The kernel's workspace.
    type(linkage_work_t) :: work
    !> The linkage with the flywheel's moments as two more moments (a steady cycle).
    type(linkage_t) :: turning
    !> A steady cycle: the flywheel and rotor turning with the driven link, kg*m^2.
    logical :: steady = .false.
    real(wp) :: j_turn = 0.0_wp
    !> The step's drive values, rates and accelerations; force magnitudes (N) and moments (N*m).
    real(wp), allocatable :: dq(:), dv(:), da(:), fval(:), mval(:)
    !> The step's friction results (a deck with friction).
    type(linkage_friction_t) :: fr
  end type linkage_stepper_t

  !> Title lines of the legacy table (English, Russian).
  character(*), parameter :: title_en = "KINETOSTAT  LINKAGE  FORCE ANALYSIS OF A PLANAR LINKAGE OF LOWER PAIRS", &
    title_ru = "KINETOSTAT  LINKAGE  СИЛОВОЙ РАСЧЕТ ПЛОСКОГО "// &
      "МЕХАНИЗМА С НИЗШИМИ ПАРАМИ"

  !> A planar linkage of lower pairs with any number of drives.
  type, extends(mechanism_t) :: linkage_mechanism_t
    !> The validated deck: links, pairs, drives, loads.
    type(linkage_deck_t) :: deck
    !> The deck as the source of the reduced quantities (a steady cycle).
    type(linkage_source_t) :: source
    !> The steady cycle (dynamics = 'steady' or 'given').
    type(cycle_t) :: cycle
  contains
    procedure :: load_deck, prepare, solve, put_results, sketch, force_plan, mass_model, finish_run
  end type linkage_mechanism_t

contains

  !> A new mechanism of this kind (the registry's constructor).
  subroutine new_linkage(mech)
    !> The mechanism.
    class(mechanism_t), allocatable, intent(out) :: mech
    allocate (linkage_mechanism_t :: mech)
    call mech%describe(linkage_template, title_en, title_ru, "", &
      "Planar linkage of lower pairs", &
      "Плоский механизм с низшими парами")
  end subroutine new_linkage

  subroutine load_deck(self, source, error)
    class(linkage_mechanism_t), intent(inout) :: self
    type(deck_source_t), intent(in) :: source
    type(error_t), allocatable, intent(out) :: error
    call read_linkage_deck(source, self%deck, error)
  end subroutine load_deck

  !> The reduced quantities and the steady cycle of a deck with dynamics = 'steady' or
  !> 'given'.
  subroutine prepare(self, path, error)
    class(linkage_mechanism_t), intent(inout) :: self
    character(*), intent(in) :: path
    type(error_t), allocatable, intent(out) :: error
    real(wp) :: phi0, j_crank
    character(len=:), allocatable :: where
    if (self%deck%dyn%mode < dynamics_steady) return
    where = path//": &linkage"
    phi0 = self%deck%start(1) * deg_to_rad
    call linkage_source_setup(self%deck, phi0, 2.0_wp * pi * (self%deck%dyn%cycle_deg / 360.0_wp), where, &
                              self%source, error)
    if (allocated(error)) return
    ! the driven link's own J_red when it turns on the frame (m |S - pivot|^2 + J, constant):
    ! Merzalov's first group
    j_crank = 0.0_wp
    associate (mech => self%deck%mech, pr => self%deck%mech%pairs(self%deck%mech%drives(1)%pair))
      if (pr%b == 0 .and. pr%a > 0) j_crank = mech%links(pr%a)%m * sum((mech%links(pr%a)%s - pr%at)**2) + &
        mech%links(pr%a)%j
    end associate
    call deck_cycle(self%source, self%deck%dyn, phi0, linkage_load_breaks(self%deck), self%deck%omega(1), where, &
                    self%cycle, error, j_links_constant=j_crank)
  end subroutine prepare

  !> `kinetostat structure DECK`: the structural analysis of a `&linkage` deck as text.
  subroutine linkage_structure_text(source, lang, out, error)
    !> The deck.
    type(deck_source_t), intent(in) :: source
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    !> Where the lines go.
    type(text_buffer_t), intent(inout) :: out
    type(error_t), allocatable, intent(out) :: error
    type(linkage_deck_t) :: deck
    character(len=160), allocatable :: lines(:)
    integer :: i
    call read_linkage_deck(source, deck, error)
    if (allocated(error)) return
    call structure_lines(deck%mech, lang, lines)
    ! the Russian analysis in the course's words alone (the deck is the student's own)
    if (lang /= lang_ru) then
      call out%put(" DECK: "//table_text(source%path))
      if (len_trim(deck%title) > 0) call out%put(" TITLE: "//table_text(trim(deck%title)))
    end if
    !GCC$ novector
    do i = 1, size(lines)
      call out%put(" "//trim(lines(i)))
    end do
  end subroutine linkage_structure_text

  !> The topology for a drawing: each moving link joins its joints (a block, drawn at its
  !> sliding pair's joint, when it slides on another link's guide); pivots are the turning
  !> pairs with the frame, guides the sliding pairs' lines.
  pure subroutine sketch(self, out)
    class(linkage_mechanism_t), intent(in) :: self
    type(sketch_t), intent(out) :: out
    character(len=16), allocatable :: joints(:)
    integer :: i, k, slide
    associate (mech => self%deck%mech)
      do i = 1, size(mech%links)
        allocate (joints(0))
        slide = 0
        do k = 1, size(mech%pairs)
          associate (pr => mech%pairs(k))
            if (pr%a /= i .and. pr%b /= i) cycle
            if (pr%kind == pair_p .and. pr%guide /= i .and. slide == 0) then
              slide = k
              joints = [character(len=16) :: pr%name, joints]
            else
              joints = [character(len=16) :: joints, pr%name]
            end if
          end associate
        end do
        if (slide > 0) then
          associate (pr => mech%pairs(slide))
            call out%add_link(link_name(mech, i), joints, guide_angle(mech, slide), axis_link(mech, pr%guide))
          end associate
        else
          call out%add_link(link_name(mech, i), joints)
        end if
        deallocate (joints)
      end do
      do k = 1, size(mech%pairs)
        associate (pr => mech%pairs(k))
          if (pr%kind == pair_r .and. (pr%a == 0 .or. pr%b == 0)) call out%add_pivot(trim(pr%name))
          if (pr%kind == pair_p) call out%add_guide(trim(pr%name), guide_angle(mech, k), axis_link(mech, pr%guide))
        end associate
      end do
      if (self%deck%g > 0.0_wp) out%down = mech%gravity / self%deck%g
      ! the structural analysis's units: the plans draw one force polygon per unit
      do k = 1, size(mech%units)
        allocate (joints(size(mech%units(k)%links)))
        do i = 1, size(joints)
          joints(i) = link_name(mech, mech%units(k)%links(i))
        end do
        call out%add_group(joints, mech%units(k)%class, mech%units(k)%label)
        deallocate (joints)
      end do
    end associate
  end subroutine sketch

  !> A sliding pair's guide direction relative to the x axis of its guide link (the frame:
  !> absolute), deg.
  pure real(wp) function guide_angle(mech, k)
    type(linkage_t), intent(in) :: mech
    integer, intent(in) :: k
    guide_angle = atan2(mech%pairs(k)%u(2), mech%pairs(k)%u(1))
    if (mech%pairs(k)%guide > 0) guide_angle = guide_angle - mech%links(mech%pairs(k)%guide)%angle0
    guide_angle = guide_angle * rad_to_deg
  end function guide_angle

  !> The label whose phi<label> column gives link i's axis ("" for the frame).
  pure function axis_link(mech, i) result(text)
    type(linkage_t), intent(in) :: mech
    integer, intent(in) :: i
    character(len=:), allocatable :: text
    text = ""
    if (i > 0) text = link_name(mech, i)
  end function axis_link

  !> The forces of row `k` on its drawing (--format svg --at K): every pair force at its
  !> joint, the deck's forces (Q<i>) and moments (MQ<i>, at the link's centre of mass), the
  !> weights, inertia forces and moments, and each drive's effort at its joint.
  pure subroutine force_plan(self, table, k, drawing, error)
    class(linkage_mechanism_t), intent(in) :: self
    type(step_table_t), intent(in) :: table
    !> Row drawn: its link angles turn the loads that follow their links.
    integer, intent(in) :: k
    type(drawing_t), intent(inout) :: drawing
    type(error_t), allocatable, intent(out) :: error
    character(len=:), allocatable :: input, effort
    type(mass_model_t) :: model
    real(wp) :: th, p(2), w(2)
    integer :: i, c
    associate (mech => self%deck%mech, deck => self%deck)
      do i = 1, size(mech%pairs)
        call drawing%pair_from_table(table, k, force_name(mech, i), trim(mech%pairs(i)%name), error)
        if (allocated(error)) return
      end do
      do i = 1, size(mech%forces)
        associate (f => mech%forces(i), lk => mech%links(mech%forces(i)%link))
          th = table%rows(table%column_index("phi"//link_name(mech, f%link)), k) * deg_to_rad - lk%angle0
          p = drawing%at("S"//link_name(mech, f%link)) + rotate(f%at - lk%s, th)
          w = f%dir
          if (f%follow) w = rotate(w, th)
          call drawing%add_force("Q"//int_str(i), force_load, p, &
            linkage_load_value(deck, deck%force_load(i), table%run_row(k), row_position(deck%force_load(i))) * w, &
            link_name(mech, f%link))
        end associate
      end do
      do i = 1, size(mech%moment_link)
        call drawing%add_moment("MQ"//int_str(i), force_load, drawing%at("S"//link_name(mech, mech%moment_link(i))), &
          linkage_load_value(deck, deck%moment_load(i), table%run_row(k), row_position(deck%moment_load(i))), &
          link_name(mech, mech%moment_link(i)))
      end do
      call self%mass_model(model)
      call drawing%add_body_loads(table, k, model)
      do i = 1, size(mech%drives)
        call drive_names(mech, i, input, effort)
        c = table%column_index(effort)
        if (c > 0 .and. mech%pairs(mech%drives(i)%pair)%kind == pair_r) then
          call drawing%add_moment(effort, force_load, drawing%at(trim(mech%pairs(mech%drives(i)%pair)%name)), &
            table%rows(c, k))
        end if
      end do
    end associate
  contains
    !> The position of a table load's link at row k: its angle from the row, or its stroke from
    !> its centre of mass on the drawing.
    pure real(wp) function row_position(sched) result(x)
      type(linkage_schedule_t), intent(in) :: sched
      x = 0.0_wp
      if (sched%link == 0) return
      associate (mech => self%deck%mech)
        if (sched%pair > 0) then
          x = dot_product(drawing%at("S"//link_name(mech, sched%link)) - mech%links(sched%link)%s, &
                          mech%pairs(sched%pair)%u)
        else
          x = table%rows(table%column_index("phi"//link_name(mech, sched%link)), k)
        end if
      end associate
    end function row_position
  end subroutine force_plan

  !> The moving links' masses, inertias and centres of mass (S<i>), and gravity.
  pure subroutine mass_model(self, model)
    class(linkage_mechanism_t), intent(in) :: self
    type(mass_model_t), intent(out) :: model
    integer :: i
    associate (mech => self%deck%mech)
      do i = 1, size(mech%links)
        call model%add(link_name(mech, i), "S"//link_name(mech, i), mech%links(i)%m, mech%links(i)%j)
      end do
      model%gravity = mech%gravity
    end associate
  end subroutine mass_model

  !> Name of link i (0: the frame): its deck number.
  pure function link_name(mech, i) result(text)
    type(linkage_t), intent(in) :: mech
    integer, intent(in) :: i
    character(len=:), allocatable :: text
    if (i == 0) then
      text = int_str(mech%frame_id)
    else
      text = int_str(mech%links(i)%id)
    end if
  end function link_name

  !> Column name of pair k's force, F<a><b>.
  pure function force_name(mech, k) result(text)
    type(linkage_t), intent(in) :: mech
    integer, intent(in) :: k
    character(len=:), allocatable :: text
    text = "F"//link_name(mech, mech%pairs(k)%a)//link_name(mech, mech%pairs(k)%b)
  end function force_name

  !> Column name of drive d's input (phi<a> or s<a>) and of its effort (M<a> or F_drive<a>).
  pure subroutine drive_names(mech, d, input, effort)
    type(linkage_t), intent(in) :: mech
    integer, intent(in) :: d
    character(len=:), allocatable, intent(out) :: input, effort
    associate (pr => mech%pairs(mech%drives(d)%pair))
      if (pr%kind == pair_r) then
        ! a drive between two moving links: its input is the relative angle phi<a><b>
        input = "phi"//link_name(mech, pr%a)
        if (pr%b /= 0) input = input//link_name(mech, pr%b)
        effort = "M"//link_name(mech, pr%a)
      else
        input = "s"//link_name(mech, pr%a)
        effort = "F_drive"//link_name(mech, pr%a)
      end if
    end associate
  end subroutine drive_names

  !> The columns of a step, declared once for the deck's linkage: the drives' inputs
  !> (phi<a> deg, s<a> m), per pair its force F<a><b> with angle, x and y components (and N,
  !> M of a sliding pair), the drives' efforts (M<a> N*m, F_drive<a> N); the inputs, forces,
  !> angles and efforts headed in the legacy table (the names in capitals).
  pure function linkage_columns(mech) result(cols)
    type(linkage_t), intent(in) :: mech
    type(column_t), allocatable :: cols(:)
    character(len=:), allocatable :: input, effort, f
    integer :: d, k
    allocate (cols(0))
    do d = 1, size(mech%drives)
      call drive_names(mech, d, input, effort)
      if (mech%pairs(mech%drives(d)%pair)%kind == pair_r) then
        cols = [cols, column(input, "deg", merge(col_input_angle, col_other, d == 1), heading=upper(input))]
      else
        cols = [cols, column(input, "m", col_length, heading=upper(input))]
      end if
    end do
    do k = 1, size(mech%pairs)
      f = force_name(mech, k)
      cols = [cols, force_and_angle(f), column(f//"x", "N", col_component), column(f//"y", "N", col_component)]
      if (mech%pairs(k)%kind == pair_p) cols = [cols, column(f//"N", "N", col_component), &
                                                column(f//"M", "N*m", col_moment)]
    end do
    do d = 1, size(mech%drives)
      call drive_names(mech, d, input, effort)
      if (mech%pairs(mech%drives(d)%pair)%kind == pair_r) then
        cols = [cols, column(effort, "N*m", col_moment, heading=upper(effort))]
      else
        cols = [cols, column(effort, "N", col_component, heading=upper(effort))]
      end if
    end do
  end function linkage_columns

  !> The RESULTS layout of a step: line 1 the drives' inputs (the first 9 wide; angles with
  !> 2 decimals, strokes with 4), every pair's force and the efforts; line 2 the pairs'
  !> angles; with --frame link their along and across components instead.
  pure function results_layout(mech, link_axes) result(fields)
    type(linkage_t), intent(in) :: mech
    !> --frame link.
    logical, intent(in) :: link_axes
    type(table_field_t), allocatable :: fields(:)
    character(len=:), allocatable :: input, effort
    integer :: d, k, line
    allocate (fields(0))
    do line = 1, 2
      do d = 1, size(mech%drives)
        if (line == 2) then
          fields = [fields, blank_field(merge(first_width, field_width, d == 1), 2)]
          cycle
        end if
        call drive_names(mech, d, input, effort)
        fields = [fields, field(input, merge(first_width, field_width, d == 1), &
                                merge(2, 4, mech%pairs(mech%drives(d)%pair)%kind == pair_r))]
      end do
      do k = 1, size(mech%pairs)
        if (link_axes) then
          fields = [fields, field(force_name(mech, k)//trim(merge("_along ", "_across", line == 1)), field_width, 2, &
                                  line=line)]
        else
          fields = [fields, field(force_name(mech, k)//trim(merge(" ", "G", line == 1)), field_width, 2, line=line)]
        end if
      end do
    end do
    do d = 1, size(mech%drives)
      call drive_names(mech, d, input, effort)
      fields = [fields, field(effort, field_width, 2)]
    end do
  end function results_layout

  !> Values of a row: the drives' inputs, per pair |F|, angle, x, y (and N, M of a sliding
  !> pair), the drives' efforts.
  pure integer function row_size(mech)
    type(linkage_t), intent(in) :: mech
    row_size = 2 * size(mech%drives) + 4 * size(mech%pairs) + 2 * count(mech%pairs%kind == pair_p)
  end function row_size

  !> Every step of rows first..last: poses by continuation from `q` (at drive values
  !> `dq_from`; both updated to the last step), then motion and reactions. Used by the tests
  !> (`solve` takes the steps one by one, linkage_solve_step).
  pure subroutine linkage_solve_steps(deck, path, first, last, q, dq_from, steps, error, motions, j_turn, frictions)
    !> Validated deck.
    type(linkage_deck_t), intent(in) :: deck
    !> Deck path for messages.
    character(*), intent(in) :: path
    !> Steps.
    integer, intent(in) :: first, last
    !> Poses and the drive values they are assembled at (in: before `first`; out: at `last`).
    real(wp), intent(inout) :: q(:), dq_from(:)
    !> The steps' results.
    type(linkage_step_t), intent(out) :: steps(first:last)
    type(error_t), allocatable, intent(out) :: error
    !> A steady cycle: the true motion of each step (the first drive's speed and
    !> acceleration) and the flywheel and rotor turning with the driven link, kg*m^2 (their
    !> inertia moment -j_turn eps on it, the reaction on the link it turns against).
    type(motion_t), intent(in), optional :: motions(first:)
    real(wp), intent(in), optional :: j_turn
    !> The steps' friction results (a deck with friction).
    type(linkage_friction_t), intent(inout), optional :: frictions(first:)
    type(linkage_stepper_t) :: st
    integer :: k
    call stepper_ready(deck, present(motions), st, j_turn)
    !GCC$ novector
    do k = first, last
      if (present(motions)) then
        call linkage_solve_step(deck, path, k, st, q, dq_from, steps(k), error, motions(k))
      else
        call linkage_solve_step(deck, path, k, st, q, dq_from, steps(k), error)
      end if
      if (allocated(error)) return
      if (deck%friction_on .and. present(frictions)) frictions(k) = st%fr
    end do
  end subroutine linkage_solve_steps

  !> The state of a run of steps: the kernel's workspace, the drive values and loads of the
  !> step, and the linkage with the flywheel's moments (a steady cycle). Allocated once per
  !> block: a step allocates nothing (the step's results are reused as well).
  pure subroutine stepper_ready(deck, steady, st, j_turn)
    type(linkage_deck_t), intent(in) :: deck
    !> A steady cycle (the true motion given per step).
    logical, intent(in) :: steady
    type(linkage_stepper_t), intent(out) :: st
    !> The flywheel and rotor turning with the driven link, kg*m^2 (a steady cycle).
    real(wp), intent(in), optional :: j_turn
    integer :: nd, nm
    nd = size(deck%mech%drives)
    nm = size(deck%moment_load)
    st%steady = steady
    if (present(j_turn)) st%j_turn = j_turn
    allocate (st%dq(nd), st%dv(nd), st%da(nd), st%fval(size(deck%force_load)))
    if (steady) then
      st%turning = deck%mech
      associate (pr => deck%mech%pairs(deck%mech%drives(1)%pair))
        st%turning%moment_link = [deck%mech%moment_link, pr%a]
        if (pr%b > 0) st%turning%moment_link = [st%turning%moment_link, pr%b]
      end associate
      allocate (st%mval(size(st%turning%moment_link)))
    else
      allocate (st%mval(nm))
    end if
  end subroutine stepper_ready

  !> Step k: its poses by continuation from `q` (at drive values `dq_from`; both updated),
  !> motion and reactions into `step` (its arrays reused when allocated), the friction
  !> results into st%fr (a deck with friction), the drive values into st%dq.
  pure subroutine linkage_solve_step(deck, path, k, st, q, dq_from, step, error, motion)
    type(linkage_deck_t), intent(in) :: deck
    character(*), intent(in) :: path
    integer, intent(in) :: k
    type(linkage_stepper_t), intent(inout) :: st
    real(wp), intent(inout) :: q(:), dq_from(:)
    type(linkage_step_t), intent(inout) :: step
    type(error_t), allocatable, intent(out) :: error
    !> A steady cycle: the step's true motion.
    type(motion_t), intent(in), optional :: motion
    integer :: i, nm
    logical :: fast
    nm = size(deck%moment_load)
    call linkage_drive_values(deck, k, st%dq, st%dv, st%da)
    if (present(motion)) then
      st%dv(1) = motion%omega
      st%da(1) = motion%eps
    end if
    if (allocated(step%qd)) then
      if (size(step%qd) /= size(q)) deallocate (step%qd, step%qdd)
    end if
    if (.not. allocated(step%qd)) allocate (step%qd(size(q)), step%qdd(size(q)))
    ! every unit an input unit or a dyad: the poses, velocities and accelerations in one pass;
    ! otherwise (or where that declines) by linkage_assemble and linkage_motion
    call linkage_fast_motion(deck%mech, dq_from, st%dq, st%dv, st%da, q, step%qd, step%qdd, st%work, fast)
    if (.not. fast) then
      call linkage_assemble(deck%mech, dq_from, st%dq, q, st%work, error)
      if (allocated(error)) then
        error%message = where()//": "//error%message
        return
      end if
    end if
    dq_from = st%dq
    step%q = q
    if (.not. fast) then
      call linkage_motion(deck%mech, q, st%dv, st%da, step%qd, step%qdd, st%work, error)
      if (allocated(error)) then
        error%message = where()//": the velocities are undetermined (a dead position)"
        return
      end if
    end if
    do i = 1, size(st%fval)
      st%fval(i) = linkage_load_value(deck, deck%force_load(i), k, linkage_table_position(deck%mech, deck%force_load(i), q))
    end do
    !GCC$ novector
    do i = 1, nm
      st%mval(i) = linkage_load_value(deck, deck%moment_load(i), k, linkage_table_position(deck%mech, &
                                      deck%moment_load(i), q))
    end do
    if (st%steady .and. present(motion)) then
      st%mval(nm + 1) = -st%j_turn * motion%eps
      if (size(st%mval) > nm + 1) st%mval(nm + 2) = st%j_turn * motion%eps
      call linkage_statics(st%turning, st%fval, st%mval, step, st%work, error, fast)
    else
      call linkage_statics(deck%mech, st%fval, st%mval, step, st%work, error, fast)
    end if
    if (allocated(error)) then
      error%message = where()//": the reactions are undetermined (a dead position)"
      return
    end if
    if (deck%friction_on) then
      if (st%steady .and. present(motion)) then
        call linkage_friction_solve(st%turning, deck%friction_f, deck%friction_r, deck%friction_span, st%fval, st%mval, &
                                    st%dv, step, st%work, st%fr, error)
      else
        call linkage_friction_solve(deck%mech, deck%friction_f, deck%friction_r, deck%friction_span, st%fval, &
                                    st%mval, st%dv, step, st%work, st%fr, error)
      end if
      if (allocated(error)) then
        error%message = where()//": "//error%message
        return
      end if
    end if
  contains
    !> The step for messages (written only for one).
    pure function where() result(text)
      character(len=:), allocatable :: text
      text = path//": &linkage: step "//int_str(k)//" ("//drive_text(deck, st%dq)//")"
    end function where
  end subroutine linkage_solve_step

  !> "phi1 = 30 deg, phi4 = 162 deg" for messages.
  pure function drive_text(deck, dq) result(text)
    type(linkage_deck_t), intent(in) :: deck
    real(wp), intent(in) :: dq(:)
    character(len=:), allocatable :: text, input, effort
    character(len=32) :: buf
    integer :: d
    text = ""
    do d = 1, size(dq)
      call drive_names(deck%mech, d, input, effort)
      if (d > 1) text = text//", "
      if (deck%mech%pairs(deck%mech%drives(d)%pair)%kind == pair_r) then
        write (buf, '(g0.10)') dq(d) * rad_to_deg
        text = text//input//" = "//trim(adjustl(buf))//" deg"
      else
        write (buf, '(g0.10)') dq(d)
        text = text//input//" = "//trim(adjustl(buf))//" m"
      end if
    end do
  end function drive_text

  !> The block's steps into the step table, with the echo (first block) and the self-check.
  subroutine solve(self, table, error)
    class(linkage_mechanism_t), intent(in) :: self
    type(step_table_t), intent(inout) :: table
    type(error_t), allocatable, intent(out) :: error
    !> The step being solved (its arrays allocated at the first step of the block).
    type(linkage_step_t) :: step
    !> The kernel's workspace and the step's drive values and loads.
    type(linkage_stepper_t) :: st
    real(wp), allocatable :: q(:), dq(:), residual(:), mismatch(:), drive_effort(:)
    character(len=:), allocatable :: input, effort
    !> The motion and reduced quantities of each step (a dynamics stage).
    type(motion_t), allocatable :: motions(:)
    !> The friction results of each step (a deck with friction).
    type(linkage_friction_t), allocatable :: frictions(:)
    character(len=16), allocatable :: force_names(:)
    integer :: first, last, k, d, nd, np, nq, stat, friction_column
    real(wp) :: gap
    logical :: translating, steady
    associate (mech => self%deck%mech)
      nd = size(mech%drives)
      np = size(mech%pairs)
      nq = 3 * size(mech%links)
      call table%block_range(self%deck%n, first, last)
      translating = mech%pairs(mech%drives(1)%pair)%kind == pair_p
      if (table%first_block()) then
        call table%declare_columns(linkage_columns(mech))
        call add_dynamics_columns(table, self%deck%dyn%mode, translating)
        if (self%deck%friction_on) then
          allocate (force_names(np))
          do k = 1, np
            force_names(k) = force_name(mech, k)
          end do
          call drive_names(mech, 1, input, effort)
          call add_friction_columns(self%deck, effort, force_names, table)
        end if
        call put_dynamics_figures(table, self%deck%dyn%mode, self%cycle, self%deck%dyn%delta)
        table%input_column = 1
        if (len_trim(self%deck%title) > 0) table%subtitle = trim(self%deck%title)
        call echo_deck(self%deck, table)
        call echo_dynamics(table, self%deck%dyn, translating)
        ! the continuation starts at the reference position
        allocate (dq(nd))
        do d = 1, nd
          dq(d) = mech%drives(d)%q_ref
        end do
        table%carry = [linkage_reference_pose(mech), dq]
      end if
      q = table%carry(1:nq)
      dq = table%carry(nq + 1:nq + nd)
      allocate (motions(first:last), stat=stat)
      if (stat /= 0) then
        call lack_block_memory(error, last - first + 1, storage_size(motions, int64) / 8, "motions")
        return
      end if
      allocate (frictions(first:last), stat=stat)
      if (stat /= 0) then
        call lack_block_memory(error, last - first + 1, storage_size(frictions, int64) / 8, "friction figures")
        return
      end if
      call table%allocate_rows(last - first + 1, error)
      if (allocated(error)) return
      allocate (residual(first:last), stat=stat)
      if (stat == 0) allocate (mismatch(first:last), stat=stat)
      if (stat == 0) allocate (drive_effort(first:last), stat=stat)
      if (stat /= 0) then
        call lack_block_memory(error, last - first + 1, 3_int64 * storage_size(residual, int64) / 8, "self-check figures")
        return
      end if
      steady = self%deck%dyn%mode >= dynamics_steady
      if (steady) then
        call cycle_motions(self%deck, self%source, self%cycle, first, motions)
        call stepper_ready(self%deck, .true., st, self%cycle%j_flywheel + self%cycle%j_rotor)
      else
        call stepper_ready(self%deck, .false., st)
      end if
      if (self%deck%friction_on) then
        call drive_names(mech, 1, input, effort)
        friction_column = table%column_index(effort//"_0")
      end if
      ! each step solved into `step` (allocated once) and put into its row at once
      gap = 0.0_wp
      do k = first, last
        if (steady) then
          call linkage_solve_step(self%deck, table%deck, k, st, q, dq, step, error, motions(k))
        else
          call linkage_solve_step(self%deck, table%deck, k, st, q, dq, step, error)
        end if
        if (allocated(error)) return
        if (self%deck%friction_on) frictions(k) = st%fr
        if (self%deck%dyn%mode == dynamics_reduced) call reduced_motion(self%deck, step, st%fval, &
          st%mval(1:size(self%deck%moment_load)), motions(k))
        call fill_row(self%deck, st%dq, step, table%rows(:, k - first + 1), table%force_angles_wanted)
        residual(k) = step%residual
        mismatch(k) = step%mismatch
        drive_effort(k) = step%effort(1)
        gap = max(gap, step%solver_gap)
        call put_dynamics_values(table, k - first + 1, self%deck%dyn%mode, motions(k))
        if (self%deck%friction_on) then
          associate (fv => friction_values(self%deck, step, frictions(k)))
            table%rows(friction_column:friction_column + size(fv) - 1, k - first + 1) = fv
          end associate
        end if
        if (table%kinematics_wanted) call put_kinematics(mech, table, k - first + 1, step)
      end do
      table%carry = [q, dq]
      if (steady) call note_drive_deviation(table, drive_effort, motions, self%cycle%j_flywheel)
      if (table%kinematics_wanted) then
        if (table%first_block()) call table%finish_columns()
      end if
      call drive_names(mech, 1, input, effort)
      call table%set_selfcheck(maxval(residual), maxval(mismatch), effort)
      table%mismatch_label = "MAX MISMATCH OF THE DRIVES' EFFORTS, POWER BALANCE"
      if (self%deck%friction_on) then
        table%residual_label = "MAX EQUILIBRIUM RESIDUAL WITH FRICTION LOADS"
        table%mismatch_label = "MAX MISMATCH OF THE DRIVES' EFFORTS, POWER BALANCE WITH FRICTION"
        ! the works over the run: the pipeline integrates the block's powers in row order
        table%block_tally%integrals = friction_integrals(self%deck, frictions, first)
      end if
      ! the largest gap of the run decides the warning (finish_run)
      table%block_tally%maxima = [running_max_t(gap, 0, .true.)]
    end associate
  end subroutine solve

  !> The warning when the group method's reactions differ from the Lagrange multipliers' by
  !> more than gap_tolerance somewhere in the run (the largest gap named).
  pure subroutine finish_run(self, table)
    class(linkage_mechanism_t), intent(in) :: self
    type(step_table_t), intent(inout) :: table
    real(wp) :: gap
    if (self%deck%friction_on .and. allocated(table%run_tally%integrals)) call friction_summary(self%deck, &
      table%run_tally%integrals(1)%area, table%run_tally%integrals(2)%area, table)
    if (.not. allocated(table%run_tally%maxima)) return
    gap = table%run_tally%maxima(1)%value
    if (gap > gap_tolerance) then
      call table%add_warning("the group method's reactions differ from the Lagrange multipliers' by "// &
        real_str(gap)//" of the largest reaction")
    end if
  end subroutine finish_run
  !> The true motion of the steps (first:last) of a steady cycle at the first drive's values.
  pure subroutine cycle_motions(deck, source, cycle, first, motions)
    type(linkage_deck_t), intent(in) :: deck
    type(linkage_source_t), intent(in) :: source
    type(cycle_t), intent(in) :: cycle
    !> The first step.
    integer, intent(in) :: first
    type(motion_t), intent(inout) :: motions(first:)
    real(wp) :: dq(1), dv(1), da(1)
    type(linkage_work_t) :: work
    type(reduced_t) :: red
    integer :: k
    ! (motion_at's values, one workspace for the steps instead of one per step)
    !GCC$ novector
    do k = first, ubound(motions, 1)
      call linkage_drive_values(deck, k, dq, dv, da)
      call linkage_source_at(source, dq(1), work, red)
      motions(k) = motion_from(cycle, dq(1), red)
    end do
  end subroutine cycle_motions

  !> The reduced quantities of a step (dynamics = 'reduced': the deck's own motion), from its
  !> poses and its loads (force magnitudes, N, and moments, N*m, as linkage_solve_step has
  !> them).
  pure subroutine reduced_motion(deck, step, fval, mval, motion)
    type(linkage_deck_t), intent(in) :: deck
    type(linkage_step_t), intent(in) :: step
    real(wp), intent(in) :: fval(:), mval(:)
    type(motion_t), intent(inout) :: motion
    type(reduced_t) :: red
    red = linkage_reduced_at_pose(deck%mech, step%q, fval, mval)
    motion%omega = deck%omega(1)
    motion%j = red%j + deck%dyn%j_rotor
    motion%dj = red%dj
    motion%m = red%m
  end subroutine reduced_motion

  !> One row of the step table: the step's drive values `dq` (rad or m) and results `s`;
  !> without `angles` (step_table_t's force_angles_wanted: no output of the run shows them)
  !> the forces' angle cells are 0.
  pure subroutine fill_row(deck, dq, s, v, angles)
    type(linkage_deck_t), intent(in) :: deck
    real(wp), intent(in) :: dq(:)
    type(linkage_step_t), intent(in) :: s
    real(wp), intent(out) :: v(:)
    logical, intent(in) :: angles
    real(wp) :: floor, f(2), lever, length
    integer :: d, ip, pos, nd
    nd = size(deck%mech%drives)
    ! each pair's force's length into its cell (one hypot a pair, for the floor and the row;
    ! the cell, not an automatic array, which would be a malloc a row)
    floor = 0.0_wp
    pos = nd
    do ip = 1, size(deck%mech%pairs)
      v(pos + 1) = magnitude(s%f(:, ip))
      floor = max(floor, v(pos + 1))
      pos = pos + merge(6, 4, deck%mech%pairs(ip)%kind == pair_p)
    end do
    floor = noise_rel * floor
    lever = floor * deck%mech%size
    pos = 0
    do d = 1, nd
      pos = pos + 1
      if (deck%mech%pairs(deck%mech%drives(d)%pair)%kind == pair_r) then
        v(pos) = dq(d) * rad_to_deg
      else
        v(pos) = dq(d)
      end if
    end do
    do ip = 1, size(deck%mech%pairs)
      f = s%f(:, ip)
      length = v(pos + 1)
      if (length <= floor) then
        f = 0.0_wp
        length = 0.0_wp
      else if (abs(f(1)) <= floor .or. abs(f(2)) <= floor) then
        ! a component below the floor is dropped: the length of what is left
        where (abs(f) <= floor) f = 0.0_wp
        length = magnitude(f)
      end if
      v(pos + 1) = length
      v(pos + 2) = 0.0_wp
      if (angles) v(pos + 2) = angle_360_deg(f)
      v(pos + 3:pos + 4) = f
      pos = pos + 4
      if (deck%mech%pairs(ip)%kind == pair_p) then
        v(pos + 1) = merge(0.0_wp, s%normal(ip), abs(s%normal(ip)) <= floor)
        v(pos + 2) = merge(0.0_wp, s%couple(ip), abs(s%couple(ip)) <= lever)
        pos = pos + 2
      end if
    end do
    do d = 1, nd
      pos = pos + 1
      if (deck%mech%pairs(deck%mech%drives(d)%pair)%kind == pair_r) then
        v(pos) = merge(0.0_wp, s%effort(d), abs(s%effort(d)) <= lever)
      else
        v(pos) = merge(0.0_wp, s%effort(d), abs(s%effort(d)) <= floor)
      end if
    end do
    do d = 1, size(v)
      v(d) = clean_zero(v(d))
    end do
  end subroutine fill_row

  !> The kinematics columns of row `r`: joints, links' angles and speeds, centres of mass and
  !> their accelerations, pair force components.
  pure subroutine put_kinematics(mech, table, r, s)
    type(linkage_t), intent(in) :: mech
    type(step_table_t), intent(inout) :: table
    integer, intent(in) :: r
    type(linkage_step_t), intent(in) :: s
    real(wp) :: x(2), vs(2), as(2), floor, f(2)
    integer :: k, i
    do k = 1, size(mech%pairs)
      associate (pr => mech%pairs(k))
        if (pr%kind == pair_r) then
          i = pr%a
          if (i == 0) i = pr%b
        else
          i = pr%a + pr%b - pr%guide
        end if
        call table%put_point(r, trim(pr%name), point_position(mech, s%q, i, pr%at))
      end associate
    end do
    do i = 1, size(mech%links)
      call table%put_link(r, link_name(mech, i), mech%links(i)%angle0 + s%q(3 * i), s%qd(3 * i), s%qdd(3 * i))
    end do
    do i = 1, size(mech%links)
      call link_point_state(mech, s%q, s%qd, s%qdd, i, mech%links(i)%s, x, vs, as)
      call table%put_point(r, "S"//link_name(mech, i), x)
      call table%put_acceleration(r, "S"//link_name(mech, i), as)
    end do
    floor = noise_rel * largest_magnitude(s%f(:, :size(mech%pairs)))
    do k = 1, size(mech%pairs)
      f = s%f(:, k)
      where (abs(f) <= floor) f = 0.0_wp
      call table%put_components(r, force_name(mech, k), f, 0.0_wp)
    end do
    ! --frame link: each pair force in the axes of the link it acts on (the frame: global)
    do k = 1, size(mech%pairs)
      i = mech%pairs(k)%a
      f = s%f(:, k)
      if (magnitude(f) <= floor) f = 0.0_wp
      if (i > 0) f = rotate(f, -(mech%links(i)%angle0 + s%q(3 * i)))
      where (abs(f) <= floor) f = 0.0_wp
      call table%put_link_axes(r, force_name(mech, k), f, link_name(mech, i))
    end do
  end subroutine put_kinematics

  !> The INPUT DATA echo: title data, links, pairs, drives, loads and the structural analysis.
  pure subroutine echo_deck(deck, table)
    type(linkage_deck_t), intent(in) :: deck
    type(step_table_t), intent(inout) :: table
    character(len=160), allocatable :: lines(:)
    character(len=:), allocatable :: input, effort, unit, rate_unit
    integer :: i, k
    associate (mech => deck%mech)
      call table%echo_int("FRAME", mech%frame_id, "")
      call table%echo_real("G", deck%g, "m/s^2")
      call table%echo_real("GRAVITY_ANGLE", deck%gravity_angle, "deg")
      call table%echo_int("N", deck%n, "steps")
      do i = 1, size(mech%links)
        call table%echo_line("   LINK "//link_name(mech, i))
        call table%echo_real("  M", mech%links(i)%m, "kg")
        call table%echo_real("  J", mech%links(i)%j, "kg*m^2")
        call table%echo_array("  S", mech%links(i)%s, "m")
      end do
      do k = 1, size(mech%pairs)
        associate (pr => mech%pairs(k))
          if (pr%kind == pair_r) then
            call table%echo_line("   PAIR "//trim(pr%name)//": R, LINKS "//link_name(mech, pr%a)//" AND "// &
                                 link_name(mech, pr%b))
          else
            call table%echo_line("   PAIR "//trim(pr%name)//": P, LINKS "//link_name(mech, pr%a)//" AND "// &
                                 link_name(mech, pr%b)//", GUIDE ON "//link_name(mech, pr%guide))
            call table%echo_real("  ANGLE", angle_360_deg(pr%u), "deg")
          end if
          call table%echo_array("  AT", pr%at, "m")
          if (deck%friction_on) call echo_friction(deck, k, table)
        end associate
      end do
      do k = 1, size(mech%drives)
        call drive_names(mech, k, input, effort)
        call table%echo_line("   DRIVE "//int_str(k)//": PAIR "//trim(deck%drive_pair(k))//", INPUT "//input// &
                             ", EFFORT "//effort)
        if (mech%pairs(mech%drives(k)%pair)%kind == pair_r) then
          unit = "deg"
          rate_unit = "rad/s"
          call table%echo_real("  REFERENCE", mech%drives(k)%q_ref * rad_to_deg, unit)
        else
          unit = "m"
          rate_unit = "m/s"
        end if
        if (deck%listed(k)) then
          call table%echo_array("  VALUES", deck%values(:, k), unit)
        else
          call table%echo_real("  START", deck%start(k), unit)
          call table%echo_real("  STEP", deck%step(k), unit)
        end if
        call echo_rate(table, "  OMEGA", deck%omega(k), deck%omega_column(k), rate_unit)
        call echo_rate(table, "  EPS", deck%eps(k), deck%eps_column(k), rate_unit//"^2")
      end do
      do k = 1, size(mech%forces)
        call table%echo_line("   FORCE "//int_str(k)//": LINK "//link_name(mech, mech%forces(k)%link)// &
                             trim(merge(", FOLLOWS THE LINK", "                  ", mech%forces(k)%follow)))
        call table%echo_array("  AT", mech%forces(k)%at, "m")
        call table%echo_real("  ANGLE", angle_360_deg(mech%forces(k)%dir), "deg")
        call echo_load(table, deck%force_load(k), "N")
      end do
      do k = 1, size(mech%moment_link)
        call table%echo_line("   MOMENT "//int_str(k)//": LINK "//link_name(mech, mech%moment_link(k)))
        call echo_load(table, deck%moment_load(k), "N*m")
      end do
      call structure_lines(mech, lang_en, lines)
      call table%echo_heading(trim(lines(1)))
      do i = 2, size(lines)
        call table%echo_line("   "//trim(lines(i)))
      end do
    end associate
  contains
    !> A load's schedule: the size of its table, its column of step_values, or its constant.
    pure subroutine echo_load(table, load, unit)
      type(step_table_t), intent(inout) :: table
      type(linkage_schedule_t), intent(in) :: load
      character(*), intent(in) :: unit
      if (load%table) then
        call table%echo_int("  TABLE_POINTS", size(load%x), "")
      else if (load%column > 0) then
        call table%echo_int("  COLUMN", load%column, "")
      else
        call table%echo_real("  VALUE", load%value, unit)
      end if
    end subroutine echo_load
    !> A drive's speed or acceleration: the constant, or its column of step_values.
    pure subroutine echo_rate(table, name, value, column, unit)
      type(step_table_t), intent(inout) :: table
      character(*), intent(in) :: name, unit
      real(wp), intent(in) :: value
      integer, intent(in) :: column
      if (column > 0) then
        call table%echo_int(name//"_COLUMN", column, "")
      else
        call table%echo_real(name, value, unit)
      end if
    end subroutine echo_rate
  end subroutine echo_deck

  !> The RESULTS block: per step a line of the inputs, the pairs' magnitudes and the efforts,
  !> a line of the pairs' angles.
  pure subroutine put_results(self, table, page, out, later)
    class(linkage_mechanism_t), intent(in) :: self
    type(step_table_t), intent(in) :: table
    type(results_page_t), intent(in) :: page
    type(text_buffer_t), intent(inout) :: out, later
    character(len=:), allocatable :: input, effort
    call put_layout_block(out, table, page, results_layout(self%deck%mech, table%link_frame), .true., &
      above=link_axes_heading(table, page%lang, crank_axes=.false.))
    if (self%deck%friction_on) then
      call drive_names(self%deck%mech, 1, input, effort)
      ! the input's unit is not shown under it
      call write_friction_block(table, effort, friction_first_width, .false., page%lang, later)
    end if
  end subroutine put_results

end module kinetostat_linkage_layout
