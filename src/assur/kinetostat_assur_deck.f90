!> `&assur` decks (generic one-DOF linkage of class-II dyads): reading, validation, template.
!>
!> Links are named by the deck's link numbers (ids); the frame, the crank and every dyad
!> link have distinct ids. Dyads, forces and moments are derived-type arrays of the namelist
!> (`dyad(1)%kind = 1, dyad(1)%l2 = 0.4, ...`); unset components are detected by the
!> sentinel `unset_real`. Integer deck variables (kinds, link numbers, modes, columns, n)
!> are read as reals and converted by `require_whole` or an equivalent whole-number check.
module kinetostat_assur_deck
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_kinds, only: wp, g_default, deg_to_rad, rad_to_deg
  use kinetostat_error, only: error_t, out_of_memory
  use kinetostat_text, only: real_str, int_str, number_str, lower, is_name
  use kinetostat_deck, only: values_out_of_memory, longest_quoted, deck_line_count, deck_line, begin_group, &
    deck_context_t, unset_real, unset_bits, max_deck_array, deck_array_capacities, deck_source_t, &
    namelist_probe_t, deck_error, require_all_set, is_set, require_set, require_positive, &
    require_nonnegative, require_rule, require_per_step, optional_default, count_values, steps_over_turn, &
    is_whole_in, require_whole, require_chars, title_chars, text_bytes, text_chars, deck_rules_t, rule_nonnegative, &
    rule_positive
  use kinetostat_vec2, only: unit_at, rotate, magnitude, cross
  use kinetostat_assur_kinematics, only: link_state_t, dyad_pose_t, kind_names, kind_has_mode, frame_state, &
    crank_state, set_dyad_pose, pose_ok, kind_rrr, kind_rrp, kind_rpr, kind_prp, kind_rpp
  use kinetostat_assur_statics, only: pair_is_prismatic
  use kinetostat_assur, only: assur_mech_t, assur_link_t, assur_dyad_t, assur_force_t, link_a, link_b, &
    output_pair_of, assur_extreme
  use kinetostat_assur_friction, only: pair_friction_t, friction_active
  use kinetostat_dynamics, only: dynamics_steady
  use kinetostat_dynamics_deck, only: read_dynamics_settings, require_one_turn, md_table_capacity
  use kinetostat_assur_deck_types, only: max_dyads, max_forces, max_moments, misfit_rel, max_table_points, &
    group_name, joint_name_chars, joint_text_length, schedule_in_t, load_constant, load_window, load_column, &
    load_table, crank_index, resist_none, resist_moment, resist_force, load_schedule_t, assur_deck_t
  use kinetostat_assur_deck_loads, only: read_load, find_link
  use kinetostat_assur_deck_names, only: kind_names_as_codes, name_unknown_kind
  use kinetostat_assur_steps, only: assur_window, assur_phi1_deg, assur_omega1_steps, assur_omega1, &
    assur_eps1, assur_motion_sign, assur_load_value, &
    assur_load_steps, table_value, table_angle, table_position
  implicit none
  private
  public :: assur_deck_t, read_assur_deck, assur_template, assur_window
  public :: load_schedule_t, load_constant, load_window, load_column, load_table
  public :: resist_none, resist_moment, resist_force
  public :: assur_phi1_deg, assur_omega1_steps, assur_omega1, assur_eps1, assur_motion_sign
  public :: assur_load_value, assur_load_steps, table_value, &
    table_angle, table_position
  public :: max_dyads, max_forces, max_moments

  !> `unset_real` for the default initialisation of the deck types below. Their variables
  !> must be declared in this module only: a NaN constant loses its payload in .mod files.
  real(wp), parameter :: unset = transfer(unset_bits, 1.0_wp)

  !> One dyad as written in the deck (degrees, ids). Kind, ids and mode are whole numbers
  !> read as reals.
  type :: dyad_in_t
    !> Kind 1..5 (RRR, RRP, RPR, PRP, RPP).
    real(wp) :: kind = unset
    !> Ids of the dyad's links a (first) and b (second).
    real(wp) :: link2 = unset, link3 = unset
    !> Ids of the links the outer pairs of a and b attach to.
    real(wp) :: on2 = unset, on3 = unset
    !> Attachment points on those links (their coordinates), m.
    real(wp) :: at2(2) = unset, at3(2) = unset
    !> Guide directions relative to those links (prismatic outer pairs), deg.
    real(wp) :: angle2 = unset, angle3 = unset
    !> Lengths A-B (RRR, RRP) and C-B (RRR), m.
    real(wp) :: l2 = unset, l3 = unset
    !> RPR offset of pin A from the slide line through C, m.
    real(wp) :: e = unset
    !> RPP slot: a point in link b's coordinates (m) and its direction (deg, rel. to b).
    real(wp) :: slot_at(2) = unset, slot_angle = unset
    !> Assembly mode +1 / -1 (kinds 1-3).
    real(wp) :: mode = unset
    !> Masses (kg), moments of inertia about S (kg*m^2), centres of mass (link coords, m).
    real(wp) :: m2 = unset, j2 = unset, s2(2) = unset
    real(wp) :: m3 = unset, j3 = unset, s3(2) = unset
    !> Reporting frame: angle of its x-axis in the global frame, deg.
    real(wp) :: frame_angle = unset
    !> Link (link2 or link3) on which the reported inner-pair force acts; default link2.
    real(wp) :: inner_on = unset
    !> Friction coefficients of the outer pair of link2, of the outer pair of link3 and of the
    !> inner pair (default 0: frictionless).
    real(wp) :: f2 = unset, f3 = unset, f23 = unset
    !> Journal radii of those pairs when they are turning pairs, m.
    real(wp) :: r2 = unset, r3 = unset, r23 = unset
    !> Guide and block lengths of those pairs when they are sliding pairs (optional: the
    !> two-contact model over the shorter of the two), m.
    real(wp) :: guide2 = unset, guide3 = unset, guide23 = unset
    real(wp) :: block2 = unset, block3 = unset, block23 = unset
    !> Global form only: the inner joint B at the reference position (RRR, RRP; PRP: a
    !> check), m.
    real(wp) :: b(2) = unset
    !> Names of the dyad's joints on the sheets (A, B, C ... as the course draws them): the
    !> outer pair of link2, the inner pair, the outer pair of link3; blank: J<pair>.
    character(len=joint_text_length) :: joints(3) = ""
  end type dyad_in_t


  !> An external force as written in the deck.
  type :: force_in_t
    !> Id of the loaded link (a whole number).
    real(wp) :: link = unset
    !> Point of application in the link's coordinates, m (default 0, 0).
    real(wp) :: at(2) = unset
    !> Direction, deg, global (or relative to the link when follow).
    real(wp) :: angle = unset
    !> Direction turns with the link.
    logical :: follow = .false.
    !> Magnitude (signed, along `angle`), N.
    real(wp) :: value = unset, idle = unset, phi_on = unset, phi_off = unset
    !> Column of step_values (a whole number).
    real(wp) :: column = unset
    !> Components instead of angle and value (global, or link axes when follow), N.
    real(wp) :: fx = unset, fy = unset
    !> Value over the position of link `over`: pairs (position, value), position in deg
    !> (a link's angle) or m (a slider's stroke on its frame guide), value in N.
    real(wp) :: table(2 * max_table_points) = unset
    !> Id of the link whose position is the table's abscissa (default: output_link).
    real(wp) :: over = unset
    !> Technological resistance: the value's size, always against the velocity of the
    !> point `at` along the force's line (zero where that velocity is zero).
    logical :: resist = .false.
  end type force_in_t

  !> An external moment as written in the deck.
  type :: moment_in_t
    !> Id of the loaded link (a whole number).
    real(wp) :: link = unset
    !> Moment, N*m, CCW positive.
    real(wp) :: value = unset, idle = unset, phi_on = unset, phi_off = unset
    !> Column of step_values (a whole number).
    real(wp) :: column = unset
    !> Value over the position of link `over`: pairs (position, value), N*m.
    real(wp) :: table(2 * max_table_points) = unset
    !> Id of the link whose position is the table's abscissa (default: output_link).
    real(wp) :: over = unset
    !> Technological resistance: the value's size, always against the link's rotation
    !> (zero where the link stops).
    logical :: resist = .false.
  end type moment_in_t

  !> Template deck: the slider-crank of data/assur_slider_crank.nml.
  character(*), parameter :: assur_template(*) = [character(len=100) :: &
    "! kinetostat deck: generic one-DOF linkage from class-II Assur groups (dyads).", &
    "! Offset slider-crank = frame 0 + crank 1 + dyad RRP (rod 2, slider 3).", &
    "! Global frame: origin anywhere, angles CCW from +x; gravity along gravity_angle.", &
    "! Link coordinates: crank: origin at its pivot, x-axis along the crank (pin at (l1, 0));", &
    "! dyad links: see docs/assur.md (RRR: origin A, x-axis A->B / origin C, x-axis C->B; ...).", &
    "&assur", &
    "  title = 'offset slider-crank'", &
    "  frame_id = 0, crank_id = 1     ! link numbers (column names F<on><from>)", &
    "  crank_at = 0, 0                ! m, crank pivot on the frame (global)", &
    "  crank_m = 2.0, crank_j = 0.01  ! kg, kg*m^2", &
    "  crank_s = 0, 0                 ! m, centre of mass (crank coordinates)", &
    "  omega1 = 50                    ! rad/s, constant (or omega1_step(:), eps1_step(:))", &
    "  g = 9.81, gravity_angle = -90  ! m/s^2, deg (defaults)", &
    "  phi_start = 0, dphi = 30       ! deg; n = 360/dphi + 1 unless given", &
    "  ! dyad 1: RRP. Rod 2 pinned to the crank at (0.1, 0) of link 1; slider 3 on a frame", &
    "  ! guide through (0, 0.02) along 0 deg; rod length 0.35 m; mode +1: slider at larger s.", &
    "  dyad(1)%kind = 2, dyad(1)%link2 = 2, dyad(1)%link3 = 3", &
    "  dyad(1)%on2 = 1, dyad(1)%at2 = 0.1, 0        ! m, crank pin B", &
    "  dyad(1)%on3 = 0, dyad(1)%at3 = 0, 0.02       ! m, a point of the guide", &
    "  dyad(1)%angle3 = 0                           ! deg, guide direction", &
    "  dyad(1)%l2 = 0.35, dyad(1)%mode = 1", &
    "  dyad(1)%m2 = 1.5, dyad(1)%j2 = 0.02, dyad(1)%s2 = 0.12, 0.01", &
    "  dyad(1)%m3 = 3.0, dyad(1)%j3 = 0, dyad(1)%s3 = 0, 0", &
    "  ! names of the joints on the sheets (default J10, J21, J23, J30): pivot, pin, slider", &
    "  crank_joint = 'O', dyad(1)%joints = 'A', 'B', 'B0'", &
    "  ! resistance on the slider: -x, 500 N for crank angles in [0, 180] deg, 100 N elsewhere", &
    "  force(1)%link = 3, force(1)%at = 0, 0, force(1)%angle = 180", &
    "  force(1)%value = 500, force(1)%idle = 100, force(1)%phi_on = 0, force(1)%phi_off = 180", &
    "/"]

contains

  !> The joints' names (`dyad(i)%joints`, `crank_joint`) into deck%joint_name, J<pair> where
  !> blank: each at most joint_name_chars characters, a letter then letters (Latin or
  !> Cyrillic), digits or _, not S<n> (a centre of mass), and no two alike (in any case:
  !> the plans write them in lower case).
  pure subroutine read_joint_names(ctx, source, dyads, crank_joint, deck, error)
    type(deck_context_t), intent(in) :: ctx
    !> The deck's lines (the message names the line of the variable).
    type(deck_source_t), intent(in) :: source
    type(dyad_in_t), intent(in) :: dyads(:)
    character(*), intent(in) :: crank_joint
    type(assur_deck_t), intent(inout) :: deck
    type(error_t), allocatable, intent(out) :: error
    character(len=joint_text_length) :: given(3 * size(dyads) + 1)
    character(len=24) :: variable(3 * size(dyads) + 1)
    character(len=:), allocatable :: text
    type(deck_context_t) :: at_line
    integer :: d, ip, other
    do d = 1, size(dyads)
      given(3 * d - 2:3 * d) = dyads(d)%joints
      variable(3 * d - 2:3 * d) = "dyad("//int_str(d)//")%joints"
    end do
    given(size(given)) = crank_joint
    variable(size(given)) = "crank_joint"
    allocate (deck%joint_name(size(given)))
    do ip = 1, size(given)
      at_line = line_context(trim(variable(ip)))
      text = trim(adjustl(given(ip)))
      if (len(text) == 0) then
        deck%joint_name(ip) = "J"//trim(deck%pair_name(ip)(2:))
        cycle
      end if
      call require_chars(at_line, trim(variable(ip)), text, joint_name_chars, error)
      if (allocated(error)) return
      call require_rule(at_line, trim(variable(ip)), is_name(text), "a joint's name is a letter followed by "// &
        "letters (Latin or Cyrillic), digits or _", error)
      if (allocated(error)) return
      call require_rule(at_line, trim(variable(ip)), .not. ((text(1:1) == "S" .or. text(1:1) == "s") .and. &
        len(text) > 1 .and. verify(text(2:), "0123456789") == 0), "'"//text//"' is the name of a centre "// &
        "of mass", error)
      if (allocated(error)) return
      deck%joint_name(ip) = text
    end do
    do ip = 2, size(given)
      do other = 1, ip - 1
        call require_rule(at_line, trim(variable(ip)), lower(trim(deck%joint_name(ip))) /= lower(trim(deck%joint_name(other))), &
          "'"//trim(deck%joint_name(ip))//"' names two joints (also "//trim(variable(other))//")", error)
        if (allocated(error)) return
      end do
    end do
  contains
    !> The context with the line variable `name` is first assigned (as "deck.nml:17"), if found.
    pure function line_context(name) result(c)
      character(*), intent(in) :: name
      type(deck_context_t) :: c
      character(len=:), allocatable :: line
      integer :: k, bang
      c = ctx
      do k = 1, deck_line_count(source)
        line = lower(deck_line(source, k))
        bang = index(line, "!")
        if (bang > 0) line = line(:bang - 1)
        if (index(line, lower(name)) > 0) then
          c%path = ctx%path//":"//int_str(k)
          return
        end if
      end do
    end function line_context
  end subroutine read_joint_names

  !> Read and validate an `&assur` deck.
  subroutine read_assur_deck(source, deck, error)
    !> The deck, read into memory (see load_deck).
    type(deck_source_t), intent(in) :: source
    !> The validated deck.
    type(assur_deck_t), intent(out) :: deck
    !> Input error naming file, group, variable and reason.
    type(error_t), allocatable, intent(out) :: error
    call read_assur_group(source, longest_quoted(source), deck, error)
  end subroutine read_assur_deck

  !> Read and validate an `&assur` deck whose longest quoted text has `title_length`
  !> characters (the length of the title read).
  subroutine read_assur_group(source, title_length, deck, error)
    !> The deck, read into memory (see load_deck).
    type(deck_source_t), intent(in) :: source
    !> Length of the title variable read (characters, >= 1).
    integer, intent(in) :: title_length
    !> The validated deck.
    type(assur_deck_t), intent(out) :: deck
    !> Input error naming file, group, variable and reason.
    type(error_t), allocatable, intent(out) :: error
    !> As long as the longest quoted text of the deck (an unclosed quote is refused before
    !> the READ); at most 80 are kept. Allocated, not automatic: a text of 10^5 characters
    !> and more would overflow the stack.
    character(len=title_length), allocatable :: title
    !> The deck with the dyads' kind names (RRR, 'RRP', ...) replaced by their codes.
    type(deck_source_t) :: coded
    !> Integer deck variables, read as reals (see require_whole).
    real(wp) :: frame_id, crank_id, n
    !> Linear actuator as driver: dyad number and pair 1..3 (whole numbers, read as reals).
    real(wp) :: drive_dyad, drive_pair
    !> Output link's id (a whole number read as a real); crank angles as a list, deg.
    real(wp) :: output_link
    real(wp), allocatable :: phi1(:)
    !> Where the steps start: '' (phi_start) or 'extreme' (of the output link).
    character(len=text_bytes * text_chars) :: start_at
    !> 'local' (link coordinates) or 'global' (points at the reference position phi_ref, deg).
    character(len=text_bytes * text_chars) :: coordinates
    real(wp) :: phi_ref
    !> Global form: frames of the links at the reference position; given global points of
    !> each dyad (A, B, C) and whether its centres of mass were given.
    type(link_state_t), allocatable :: ref(:)
    real(wp) :: glob(2, 3)
    logical :: global, s_given(2), crank_s_given, at_given
    !> frame_id and crank_id as integers.
    integer :: frame_no, crank_no, nd, nf, nm, n_omega, n_eps, n_values, k, d, i
    real(wp) :: crank_at(2), crank_m, crank_j, crank_s(2), omega1, g, gravity_angle, phi_start, dphi
    !> Machine dynamics variables (see kinetostat_dynamics_deck); `cycle`: the steady cycle,
    !> deg (360 or 720).
    real(wp) :: delta, j_rotor, j_flywheel, cycle, flywheel_density, flywheel_width_ratio
    !> The driving-moment table (pairs phi deg, M_d; see kinetostat_dynamics_deck).
    real(wp) :: md_table(md_table_capacity)
    character(len=text_bytes * text_chars) :: dynamics
    !> Name of the crank's pivot on the sheets (blank: J<pair>).
    character(len=joint_text_length) :: crank_joint
    !> Friction coefficient and journal radius (m) of the crank's pivot A.
    real(wp) :: crank_f, crank_r
    real(wp), allocatable :: omega1_step(:), eps1_step(:), step_values(:)
    !> Elements allocated for each per-step array the deck may give (see deck_array_capacities).
    integer, allocatable :: capacity(:)
    integer :: stat
    logical :: angles_signed, components
    type(dyad_in_t) :: dyad(max_dyads)
    !> Allocated, not automatic: their tables hold max_table_points points each.
    type(force_in_t), allocatable :: force(:)
    type(moment_in_t), allocatable :: moment(:)
    !> One force's or moment's schedule as read (then copied into the deck).
    type(load_schedule_t) :: load
    type(deck_context_t) :: ctx
    type(namelist_probe_t) :: probe
    type(deck_rules_t) :: rules
    integer, allocatable :: ids(:)
    character(len=:), allocatable :: name
    namelist /assur/ title, frame_id, crank_id, crank_at, crank_m, crank_j, crank_s, omega1, &
      omega1_step, eps1_step, g, gravity_angle, phi_start, dphi, n, dyad, force, moment, &
      step_values, angles_signed, components, drive_dyad, drive_pair, output_link, phi1, start_at, crank_f, crank_r, &
      coordinates, phi_ref, dynamics, delta, j_rotor, j_flywheel, md_table, crank_joint, cycle, &
      flywheel_density, flywheel_width_ratio

    call begin_group(source, group_name, ctx, error, rules)
    if (allocated(error)) return
    allocate (title)
    allocate (force(max_forces), moment(max_moments))
    dynamics = ""; delta = unset_real; j_rotor = unset_real; j_flywheel = unset_real
    md_table = unset_real; cycle = unset_real
    flywheel_density = unset_real; flywheel_width_ratio = unset_real
    title = ""
    frame_id = 0.0_wp; crank_id = 1.0_wp; n = unset_real
    drive_dyad = unset_real; drive_pair = unset_real
    output_link = unset_real; start_at = ""; crank_f = unset_real; crank_r = unset_real
    coordinates = "local"; phi_ref = unset_real; crank_joint = ""
    crank_at = unset_real; crank_m = unset_real; crank_j = unset_real; crank_s = unset_real
    omega1 = unset_real; g = unset_real; gravity_angle = unset_real
    phi_start = unset_real; dphi = unset_real
    angles_signed = .false.; components = .true.
    capacity = deck_array_capacities(source, ctx%group, [character(len=11) :: "omega1_step", "eps1_step", &
      "step_values", "phi1"])
    allocate (omega1_step(capacity(1)), source=unset_real, stat=stat)
    if (stat == 0) allocate (eps1_step(capacity(2)), source=unset_real, stat=stat)
    if (stat == 0) allocate (step_values(capacity(3)), source=unset_real, stat=stat)
    if (stat == 0) allocate (phi1(capacity(4)), source=unset_real, stat=stat)
    if (stat /= 0) then
      call values_out_of_memory(ctx, "omega1_step, eps1_step, step_values, phi1", capacity, error)
      return
    end if

    coded%path = source%path
    allocate (character(len=len(source%records)) :: coded%records(size(source%records)), stat=stat)
    if (stat /= 0) then
      call out_of_memory(error, "a copy of the deck's records", int(len(source%records), int64) * size(source%records))
      error%message = ctx%path//": &"//ctx%group//": "//error%message
      return
    end if
    coded%records(:) = source%records(:)
    if (allocated(source%first_record)) coded%first_record = source%first_record
    if (allocated(source%record_length)) coded%record_length = source%record_length
    coded%cut_width = source%cut_width
    call kind_names_as_codes(coded)
    call probe%limit("dyad", max_dyads, "dyads")
    call probe%limit("force", max_forces, "forces")
    call probe%limit("moment", max_moments, "moments")
    call probe%limit([character(12) :: "force%table", "moment%table"], 2 * max_table_points, &
      "values ("//int_str(max_table_points)//" points)")
    call probe%limit("md_table", md_table_capacity, "values ("//int_str(md_table_capacity / 2)//" points)")
    call probe%limit([character(11) :: "omega1_step", "eps1_step"], max_deck_array, "values (one per step)")
    call probe%limit("step_values", max_deck_array, "values")
    call probe%limit("phi1", max_deck_array, "values (one per step)")
    read (coded%records, nml=assur, iostat=probe%ios, iomsg=probe%msg)
    do while (probe%retry(coded)) ! on failure: find the line and the assignment
      read (probe%records, nml=assur, iostat=probe%ios, iomsg=probe%msg)
    end do
    if (probe%failed(coded, ctx, error)) then
      call name_unknown_kind(source, ctx, error)
      return
    end if

    call require_chars(ctx, "title", title, title_chars, error)
    if (allocated(error)) return

    ! ---- two or more required variables missing: one message naming them all (a single
    ! missing variable gets its own message, with its reason, from the checks below)
    call require_all_given(ctx, coordinates, phi_ref, dphi, phi1, omega1, omega1_step, eps1_step, drive_dyad, &
                           drive_pair, dyad, force, moment, error)
    if (allocated(error)) return

    ! ---- frame, crank, speed law, gravity, steps
    call rules%require_whole("frame_id", frame_id, 0, huge(1), frame_no)
    call rules%require_whole("crank_id", crank_id, 0, huge(1), crank_no)
    call rules%require_rule("crank_id", crank_no /= frame_no, &
      "must be >= 0 and differ from frame_id (got "//int_str(crank_no)//")")
    if (rules%failed(error)) return
    call read_pair(ctx, "crank_at", crank_at, .true., error); if (allocated(error)) return
    crank_s_given = any(is_set(crank_s))
    call read_pair(ctx, "crank_s", crank_s, .true., error); if (allocated(error)) return
    call rules%require_rule("coordinates", any(lower(trim(coordinates)) == [character(len=8) :: "local", "global"]), &
      "must be 'local' (link coordinates) or 'global' (points at the reference position phi_ref), got '"// &
      trim(coordinates)//"'")
    global = lower(trim(coordinates)) == "global"
    if (global) then
      call rules%require_set("phi_ref", phi_ref)
    else
      call rules%require_rule("phi_ref", .not. is_set(phi_ref), "only used with coordinates = 'global'")
    end if
    crank_m = optional_default(crank_m, 0.0_wp)
    crank_j = optional_default(crank_j, 0.0_wp)
    g = optional_default(g, g_default)
    call rules%require_each(rule_nonnegative, [character(7) :: "crank_m", "crank_j", "g"], [crank_m, crank_j, g])
    gravity_angle = optional_default(gravity_angle, -90.0_wp)
    call rules%require_set("gravity_angle", gravity_angle)
    if (rules%failed(error)) return
    call read_steps(ctx, phi1, phi_start, dphi, n, start_at, deck, error); if (allocated(error)) return

    call rules%count_values("omega1_step", omega1_step, n_omega)
    call rules%count_values("eps1_step", eps1_step, n_eps)
    if (n_omega > 0 .or. n_eps > 0) then
      call rules%require_rule("omega1", .not. is_set(omega1), &
        "give either omega1 (constant) or omega1_step(:) with eps1_step(:), not both")
      call rules%require_per_step("omega1_step", n_omega, deck%n)
      call rules%require_per_step("eps1_step", n_eps, deck%n)
      if (rules%failed(error)) return
      deck%prescribed = .true.
      ! the read buffers are the deck's arrays (no second copy)
      call move_alloc(omega1_step, deck%omega1_values)
      call move_alloc(eps1_step, deck%eps1_values)
    else
      call rules%require_set("omega1", omega1)
      if (rules%failed(error)) return
      deck%omega1_const = omega1
      deallocate (omega1_step, eps1_step)
    end if
    call rules%count_values("step_values", step_values, n_values)
    if (rules%failed(error)) return
    call move_alloc(step_values, deck%step_values)

    ! ---- dyads: the leading set entries, no gaps
    nd = 0
    do d = 1, max_dyads
      if (.not. is_set(dyad(d)%kind)) exit
      nd = d
    end do
    call rules%require_rule("dyad", nd >= 1, "at least one dyad is required (dyad(1)%kind missing)")
    if (rules%failed(error)) return
    do d = nd + 1, max_dyads
      if (dyad_touched(dyad(d)) .or. is_set(dyad(d)%kind)) then
        call deck_error(ctx, "dyad("//int_str(d)//")", "dyads must be numbered 1.."//int_str(nd + 1)// &
          " without gaps (dyad("//int_str(nd + 1)//")%kind is missing)", error)
        return
      end if
    end do

    call blame_frame_or_crank(ctx, dyad(1:nd), frame_no, crank_no, error); if (allocated(error)) return
    allocate (deck%mech%links(0:2 * nd + 1), deck%mech%dyads(nd))
    deck%mech%links(0) = assur_link_t(id=frame_no)
    deck%mech%links(1) = assur_link_t(id=crank_no, m=crank_m, j=crank_j, s=crank_s)
    deck%mech%pivot = crank_at
    allocate (ids(0:2 * nd + 1))
    ids(0) = frame_no
    ids(1) = crank_no
    if (global) then
      allocate (ref(0:2 * nd + 1))
      ref(0) = frame_state()
      ref(1) = crank_state(crank_at, phi_ref * deg_to_rad)
      if (crank_s_given) deck%mech%links(1)%s = to_local(ref(1), crank_s)
      deck%phi_ref = phi_ref
      deck%global = .true.
    end if
    do d = 1, nd
      if (global) then
        call globalize_dyad(ctx, d, dyad(d), ids(0:2 * d - 1), ref, glob, s_given, error)
        if (allocated(error)) return
      end if
      call read_dyad(ctx, d, dyad(d), ids(0:2 * d - 1), deck%mech%dyads(d), &
                     deck%mech%links(link_a(d)), deck%mech%links(link_b(d)), error)
      if (allocated(error)) return
      ids(2 * d) = deck%mech%links(link_a(d))%id
      ids(2 * d + 1) = deck%mech%links(link_b(d))%id
      if (global) then
        call reference_pose(ctx, d, phi_ref, glob, s_given, is_set(dyad(d)%b(1)), deck%mech, ref, error)
        if (allocated(error)) return
      end if
    end do

    call read_driver(ctx, drive_dyad, drive_pair, deck%mech, error); if (allocated(error)) return

    ! ---- external forces and moments
    nf = leading(is_set(force%link))
    nm = leading(is_set(moment%link))
    allocate (deck%mech%forces(nf), deck%mech%moment_link(nm))
    allocate (deck%force_load(nf), deck%moment_load(nm))
    call read_output_link(ctx, output_link, ids, deck%mech, error); if (allocated(error)) return
    call crank_angles(ctx, deck, error); if (allocated(error)) return
    call numbered_without_gaps(ctx, "force", is_set(force%link), [(any(is_set([force(k)%value, force(k)%angle, &
      force(k)%column, force(k)%fx, force(k)%fy, force(k)%table(1)])), k = 1, max_forces)], nf, error)
    if (allocated(error)) return
    call numbered_without_gaps(ctx, "moment", is_set(moment%link), [(any(is_set([moment(k)%value, moment(k)%column, &
      moment(k)%table(1)])), k = 1, max_moments)], nm, error)
    if (allocated(error)) return
    do k = 1, nf
      name = "force("//int_str(k)//")%"
      associate (fi => force(k))
        call find_link(ctx, name//"link", fi%link, ids, .false., i, error); if (allocated(error)) return
        at_given = any(is_set(fi%at))
        call read_pair(ctx, name//"at", fi%at, .true., error); if (allocated(error)) return
        if (any(is_set([fi%fx, fi%fy]))) then
          call force_components(ctx, name, fi, error); if (allocated(error)) return
        end if
        call require_set(ctx, name//"angle", fi%angle, error); if (allocated(error)) return
        if (global) then
          if (at_given) fi%at = to_local(ref(i), fi%at)
          if (fi%follow) fi%angle = fi%angle - ref(i)%th * rad_to_deg
        end if
        deck%mech%forces(k) = assur_force_t(link=i, at=fi%at, angle=fi%angle * deg_to_rad, follow=fi%follow)
        call read_load(ctx, name, fi%table, fi%over, schedule_in_t(value=fi%value, idle=fi%idle, phi_on=fi%phi_on, &
                       phi_off=fi%phi_off, column=fi%column), ids, deck, n_values, merge(resist_force, resist_none, &
                       fi%resist), i, load, error)
        if (allocated(error)) return
        if (fi%resist) then
          load%resist_at = deck%mech%forces(k)%at
          load%resist_angle = deck%mech%forces(k)%angle
          load%resist_follow = fi%follow
        end if
        deck%force_load(k) = load
      end associate
    end do
    do k = 1, nm
      name = "moment("//int_str(k)//")%"
      associate (mi => moment(k))
        call find_link(ctx, name//"link", mi%link, ids, .false., i, error); if (allocated(error)) return
        deck%mech%moment_link(k) = i
        call read_load(ctx, name, mi%table, mi%over, schedule_in_t(value=mi%value, idle=mi%idle, phi_on=mi%phi_on, &
                       phi_off=mi%phi_off, column=mi%column), ids, deck, n_values, merge(resist_moment, resist_none, &
                       mi%resist), i, load, error)
        if (allocated(error)) return
        deck%moment_load(k) = load
      end associate
    end do

    ! ---- report: pair names and reporting frames
    allocate (deck%pair_name(3 * nd + 1), deck%pair_frame(3 * nd + 1), deck%pair_sign(3 * nd + 1))
    deck%pair_sign = 1.0_wp
    do d = 1, nd
      ! ids of the dyad's links (a, b) and of the links they hang on (validated whole numbers)
      associate (id_a => ids(2 * d), id_b => ids(2 * d + 1), on_a => ids(deck%mech%dyads(d)%on(1)), &
                 on_b => ids(deck%mech%dyads(d)%on(2)))
        deck%pair_name(3 * d - 2) = pair_stem(id_a, on_a)
        deck%pair_name(3 * d - 1) = pair_stem(id_a, id_b)
        if (dyad(d)%inner_on == dyad(d)%link3) then
          deck%pair_name(3 * d - 1) = pair_stem(id_b, id_a)
          deck%pair_sign(3 * d - 1) = -1.0_wp
        end if
        deck%pair_name(3 * d) = pair_stem(id_b, on_b)
      end associate
      deck%pair_frame(3 * d - 2:3 * d) = optional_default(dyad(d)%frame_angle, 0.0_wp) * deg_to_rad
    end do
    deck%pair_name(3 * nd + 1) = pair_stem(crank_no, frame_no)
    deck%pair_frame(3 * nd + 1) = 0.0_wp
    call read_joint_names(ctx, source, dyad(1:nd), crank_joint, deck, error)
    if (allocated(error)) return

    ! ---- friction in the pairs (all 0 by default)
    allocate (deck%friction(3 * nd + 1))
    do d = 1, nd
      call read_dyad_friction(ctx, d, dyad(d), deck%friction(3 * d - 2:3 * d), error)
      if (allocated(error)) return
    end do
    call read_pair_friction(ctx, "crank_f", "crank_r", "", "", crank_f, crank_r, unset_real, unset_real, .false., &
                            deck%friction(3 * nd + 1), error)
    if (allocated(error)) return
    deck%friction%name = deck%pair_name
    deck%friction_on = friction_active(deck%friction)

    deck%mech%g = g
    deck%gravity_angle = gravity_angle
    deck%mech%down = unit_at(gravity_angle * deg_to_rad)
    deck%title = title
    deck%angles_signed = angles_signed
    deck%components = components
    deck%frame_id = frame_no
    deck%crank_id = crank_no

    ! ---- machine dynamics: reduced to the crank; a steady cycle over one turn, loads at any angle
    if (len_trim(dynamics) > 0 .and. trim(adjustl(dynamics)) /= "none") then
      call require_rule(ctx, "dynamics", deck%mech%drive_dyad == 0 .or. trim(adjustl(dynamics)) == "reduced", &
        "a linear actuator's stroke (drive_dyad) goes out and back with no turn to make a cycle of: only "// &
        "dynamics = 'reduced' (reduced to the stroke)", error)
      if (allocated(error)) return
      call require_rule(ctx, "dynamics", .not. deck%prescribed .or. trim(adjustl(dynamics)) == "reduced", &
        "omega1_step/eps1_step prescribe the motion; a steady cycle needs omega1 (the mean speed)", error)
      if (allocated(error)) return
    end if
    call read_dynamics_settings(ctx, dynamics, delta, j_rotor, j_flywheel, omega1, deck%dyn, error, &
      md_table, cycle, flywheel_density, flywheel_width_ratio)
    if (allocated(error)) return
    if (deck%dyn%mode >= dynamics_steady) then
      call require_rule(ctx, "dynamics", .not. deck%friction_on, "a steady cycle with friction in the pairs is "// &
        "not supported (M_red would depend on the reactions): set the friction coefficients to 0", error)
      if (allocated(error)) return
      call require_rule(ctx, "phi1", .not. allocated(deck%phi_list), "a steady cycle needs phi_start and dphi "// &
        "over one turn, not a list of angles", error)
      if (allocated(error)) return
      call require_cycle_holds_tables(ctx, deck, error); if (allocated(error)) return
      call require_one_turn(ctx, deck%dphi, deck%n, error, deck%dyn%cycle_deg); if (allocated(error)) return
      call require_rule(ctx, "step_values", .not. (any(deck%force_load%kind == load_column) .or. &
        any(deck%moment_load%kind == load_column)), "a steady cycle needs every load at any crank angle: "// &
        "give it as a constant, a window or a table, not per step", error)
      if (allocated(error)) return
    end if
  end subroutine read_assur_group

  !> A steady cycle of one turn (cycle = 360) cannot hold a load table over the crank's angle
  !> that spans more than a turn (a four-stroke engine's gas force over 720 deg): the error
  !> names `cycle` and the table.
  pure subroutine require_cycle_holds_tables(ctx, deck, error)
    type(deck_context_t), intent(in) :: ctx
    type(assur_deck_t), intent(in) :: deck
    type(error_t), allocatable, intent(out) :: error
    integer :: k
    if (deck%dyn%cycle_deg > 360.0_wp) return
    do k = 1, size(deck%force_load)
      call check(deck%force_load(k), "force("//int_str(k)//")%table", error)
      if (allocated(error)) return
    end do
    do k = 1, size(deck%moment_load)
      call check(deck%moment_load(k), "moment("//int_str(k)//")%table", error)
      if (allocated(error)) return
    end do
  contains
    pure subroutine check(load, name, error)
      type(load_schedule_t), intent(in) :: load
      character(*), intent(in) :: name
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: span
      if (load%kind /= load_table .or. load%link /= crank_index .or. load%pair /= 0) return
      span = load%x(size(load%x)) - load%x(1)
      call require_rule(ctx, "cycle", span <= 360.0_wp, "the steady cycle is one turn (cycle = 360, the default) "// &
        "but "//name//" spans "//real_str(span)//" deg of the crank angle: give cycle = 720 (a four-stroke "// &
        "engine's cycle of two turns) and steps over 720 deg", error)
    end subroutine check
  end subroutine require_cycle_holds_tables

  !> The required variables the deck lacks, in the order the checks of read_assur_deck meet
  !> them: phi_ref (global form), dphi (unless a phi1 list), omega1 (or the other of
  !> omega1_step, eps1_step), the kind of the first missing dyad, each dyad's link2, link3,
  !> on2, on3, at2, at3 and what its kind needs (angle2, angle3, l2, l3 or in the global form
  !> b, slot_at, slot_angle), the other of drive_dyad and drive_pair, the link of a force or
  !> moment given by its other members, a load's angle and value and the other end of its
  !> window. When two or more are missing, one error names them all ("missing required
  !> variables: ..."); with one or none, no error: the checks that follow report it with its
  !> reason. An unknown `coordinates`, or phi_ref in the local form, leaves it to them too.
  subroutine require_all_given(ctx, coordinates, phi_ref, dphi, phi1, omega1, omega1_step, eps1_step, drive_dyad, &
                               drive_pair, dyad, force, moment, error)
    type(deck_context_t), intent(in) :: ctx
    !> 'local' or 'global' as read.
    character(*), intent(in) :: coordinates
    !> Reference crank angle, crank step (deg), speed (rad/s) as read.
    real(wp), intent(in) :: phi_ref, dphi, omega1
    !> Crank angle list (deg), per-step speed (rad/s) and acceleration (rad/s^2) as read.
    real(wp), intent(in) :: phi1(:), omega1_step(:), eps1_step(:)
    !> Linear actuator: dyad and pair numbers as read.
    real(wp), intent(in) :: drive_dyad, drive_pair
    !> Dyads, forces and moments as read.
    type(dyad_in_t), intent(in) :: dyad(:)
    type(force_in_t), intent(in) :: force(:)
    type(moment_in_t), intent(in) :: moment(:)
    type(error_t), allocatable, intent(out) :: error
    !> Names of the missing variables.
    character(len=24), allocatable :: names(:)
    character(len=:), allocatable :: p
    logical :: global, steps_given
    integer :: nd, d, k, kind
    allocate (names(0))
    ! what is required depends on the form: an unknown form, or phi_ref without the global
    ! form, is reported first by the checks that follow
    if (.not. any(lower(trim(coordinates)) == [character(len=8) :: "local", "global"])) return
    global = lower(trim(coordinates)) == "global"
    if (.not. global .and. is_set(phi_ref)) return
    if (global) call add_missing(names, "phi_ref", .not. is_set(phi_ref))
    call add_missing(names, "dphi", .not. any(is_set(phi1)) .and. .not. is_set(dphi))
    steps_given = any(is_set(omega1_step)) .or. any(is_set(eps1_step))
    call add_missing(names, "omega1", .not. steps_given .and. .not. is_set(omega1))
    if (steps_given .and. .not. is_set(omega1)) then
      call add_missing(names, "omega1_step", .not. any(is_set(omega1_step)))
      call add_missing(names, "eps1_step", .not. any(is_set(eps1_step)))
    end if

    ! dyads: the leading entries with a kind; a later entry touched means the next kind is missing
    nd = 0
    do d = 1, size(dyad)
      if (.not. is_set(dyad(d)%kind)) exit
      nd = d
    end do
    if (nd < size(dyad)) then
      call add_missing(names, "dyad("//int_str(nd + 1)//")%kind", nd == 0 .or. any(dyad_touched(dyad(nd + 1:))) &
                       .or. any(is_set(dyad(nd + 1:)%kind)))
    end if
    do d = 1, nd
      p = "dyad("//int_str(d)//")%"
      associate (dy => dyad(d))
        call add_missing(names, p//"link2", .not. is_set(dy%link2))
        call add_missing(names, p//"link3", .not. is_set(dy%link3))
        call add_missing(names, p//"on2", .not. is_set(dy%on2))
        call add_missing(names, p//"on3", .not. is_set(dy%on3))
        call add_missing(names, p//"at2", .not. any(is_set(dy%at2)))
        call add_missing(names, p//"at3", .not. any(is_set(dy%at3)))
        if (.not. is_whole_in(dy%kind, 1, 5)) cycle ! what it needs depends on its kind
        kind = nint(dy%kind)
        if (global) then
          call add_missing(names, p//"b", (kind == kind_rrr .or. kind == kind_rrp) .and. .not. any(is_set(dy%b)))
          call add_missing(names, p//"slot_at", kind == kind_rpp .and. .not. any(is_set(dy%slot_at)))
        end if
        call add_missing(names, p//"angle2", kind == kind_prp .and. .not. is_set(dy%angle2))
        call add_missing(names, p//"angle3", (kind == kind_rrp .or. kind == kind_prp .or. kind == kind_rpp) .and. &
                         .not. is_set(dy%angle3))
        if (.not. global) then
          call add_missing(names, p//"l2", (kind == kind_rrr .or. kind == kind_rrp) .and. .not. is_set(dy%l2))
          call add_missing(names, p//"l3", kind == kind_rrr .and. .not. is_set(dy%l3))
        end if
        call add_missing(names, p//"slot_angle", kind == kind_rpp .and. .not. is_set(dy%slot_angle))
      end associate
    end do
    call add_missing(names, "drive_pair", is_set(drive_dyad) .and. .not. is_set(drive_pair))
    call add_missing(names, "drive_dyad", is_set(drive_pair) .and. .not. is_set(drive_dyad))

    ! loads: the leading entries with a link, then the first one touched after a gap
    do k = 1, size(force)
      associate (fi => force(k))
        p = "force("//int_str(k)//")%"
        if (.not. is_set(fi%link)) then
          if (.not. any(is_set([fi%value, fi%angle, fi%column, fi%fx, fi%fy, fi%table(1)]))) cycle ! no force
          call add_missing(names, p//"link", .true.)
        end if
        if (any(is_set([fi%fx, fi%fy]))) then
          call add_window(names, p, fi%phi_on, fi%phi_off)
          cycle
        end if
        call add_missing(names, p//"angle", .not. is_set(fi%angle))
        if (is_set(fi%table(1)) .or. is_set(fi%column)) cycle
        call add_missing(names, p//"value", .not. is_set(fi%value))
        call add_window(names, p, fi%phi_on, fi%phi_off)
      end associate
    end do
    do k = 1, size(moment)
      associate (mi => moment(k))
        p = "moment("//int_str(k)//")%"
        if (.not. is_set(mi%link)) then
          if (.not. any(is_set([mi%value, mi%column, mi%table(1)]))) cycle ! no moment
          call add_missing(names, p//"link", .true.)
        end if
        if (is_set(mi%table(1)) .or. is_set(mi%column)) cycle
        call add_missing(names, p//"value", .not. is_set(mi%value))
        call add_window(names, p, mi%phi_on, mi%phi_off)
      end associate
    end do
    if (size(names) >= 2) call require_all_set(ctx, names, spread(unset_real, 1, size(names)), error)
  end subroutine require_all_given

  !> Append `name` to `names` when `missing`.
  pure subroutine add_missing(names, name, missing)
    !> Names of the missing variables so far.
    character(len=24), allocatable, intent(inout) :: names(:)
    !> Variable name.
    character(*), intent(in) :: name
    !> Whether it is missing.
    logical, intent(in) :: missing
    if (missing) names = [character(len=24) :: names, name]
  end subroutine add_missing

  !> A load's window: when one end is given, the other is missing if not.
  pure subroutine add_window(names, prefix, phi_on, phi_off)
    !> Names of the missing variables so far.
    character(len=24), allocatable, intent(inout) :: names(:)
    !> Prefix, e.g. "force(1)%".
    character(*), intent(in) :: prefix
    !> Window ends as read, deg.
    real(wp), intent(in) :: phi_on, phi_off
    call add_missing(names, prefix//"phi_on", is_set(phi_off) .and. .not. is_set(phi_on))
    call add_missing(names, prefix//"phi_off", is_set(phi_on) .and. .not. is_set(phi_off))
  end subroutine add_window

  !> Point `p` (global, m) in the coordinates of the link whose frame is `ls` (components
  !> below 1e-13 of its distance from the link's origin are roundoff: 0).
  pure function to_local(ls, p) result(r)
    type(link_state_t), intent(in) :: ls
    real(wp), intent(in) :: p(2)
    real(wp) :: r(2)
    r = rotate(p - ls%o, -ls%th)
    ! roundoff of the rotation (a point on the link's axis) is 0
    where (abs(r) <= 1.0e-13_wp * magnitude(p - ls%o)) r = 0.0_wp
  end function to_local

  !> Global form, before the dyad is validated: its attachment points and guide angles
  !> (global at the reference position) become coordinates of the links they attach to,
  !> RRR's l2, l3 and RRP's l2 come from the joints A, B, C (and the mode from B's side),
  !> RPP's slot point and angle become link b's (its origin at the guide point then).
  subroutine globalize_dyad(ctx, d, dy, ids, ref, glob, s_given, error)
    type(deck_context_t), intent(in) :: ctx
    !> Dyad number.
    integer, intent(in) :: d
    !> The dyad as read; converted in place.
    type(dyad_in_t), intent(inout) :: dy
    !> Ids of the links defined before it.
    integer, intent(in) :: ids(0:)
    !> Frames of the links at the reference position (those before the dyad are set).
    type(link_state_t), intent(in) :: ref(0:)
    !> The given global points A (pair 1), B (inner, or unset), C (pair 3), m.
    real(wp), intent(out) :: glob(2, 3)
    !> Whether the centres of mass s2, s3 were given (global points, converted later).
    logical, intent(out) :: s_given(2)
    type(error_t), allocatable, intent(out) :: error
    character(len=:), allocatable :: p
    integer :: i1, i3, kind
    real(wp) :: t(2), gam
    p = "dyad("//int_str(d)//")%"
    glob = unset_real
    s_given = [any(is_set(dy%s2)), any(is_set(dy%s3))]
    if (.not. is_whole_in(dy%kind, 1, 5)) return ! read_dyad reports it
    kind = nint(dy%kind)
    call find_link(ctx, p//"on2", dy%on2, ids, .true., i1, error); if (allocated(error)) return
    call find_link(ctx, p//"on3", dy%on3, ids, .true., i3, error); if (allocated(error)) return
    call read_pair(ctx, p//"at2", dy%at2, .false., error); if (allocated(error)) return
    call read_pair(ctx, p//"at3", dy%at3, .false., error); if (allocated(error)) return
    glob(:, 1) = dy%at2
    glob(:, 3) = dy%at3
    if (is_set(dy%b(1)) .or. is_set(dy%b(2))) then
      call read_pair(ctx, p//"b", dy%b, .false., error); if (allocated(error)) return
      glob(:, 2) = dy%b
    end if
    dy%at2 = to_local(ref(i1), glob(:, 1))
    dy%at3 = to_local(ref(i3), glob(:, 3))
    gam = dy%angle3
    if (is_set(dy%angle2)) dy%angle2 = dy%angle2 - ref(i1)%th * rad_to_deg
    if (is_set(dy%angle3)) dy%angle3 = dy%angle3 - ref(i3)%th * rad_to_deg
    select case (kind)
    case (kind_rrr, kind_rrp)
      call require_rule(ctx, p//"b", is_set(dy%b(1)), "missing: the global form gives the inner joint B "// &
        "(its lengths are derived from A, B, C)", error)
      if (allocated(error)) return
      call require_rule(ctx, p//"l2", .not. is_set(dy%l2), "derived from at2 and b in the global form: remove it", error)
      if (allocated(error)) return
      dy%l2 = magnitude(glob(:, 2) - glob(:, 1))
      if (kind == kind_rrr) then
        call require_rule(ctx, p//"l3", .not. is_set(dy%l3), "derived from at3 and b in the global form: remove it", &
          error)
        if (allocated(error)) return
        dy%l3 = magnitude(glob(:, 2) - glob(:, 3))
        ! mode +1: B left of A -> C
        if (.not. is_set(dy%mode)) dy%mode = merge(1.0_wp, -1.0_wp, &
          cross(glob(:, 3) - glob(:, 1), glob(:, 2) - glob(:, 1)) >= 0.0_wp)
      else if (is_set(gam)) then
        ! mode +1: B at the larger of the two guide coordinates (their mean is -(C - A).t)
        t = unit_at(gam * deg_to_rad)
        if (.not. is_set(dy%mode)) dy%mode = merge(1.0_wp, -1.0_wp, &
          dot_product(glob(:, 2) - glob(:, 3), t) >= -dot_product(glob(:, 3) - glob(:, 1), t))
      end if
    case (kind_prp)
      continue
    case default
      call require_rule(ctx, p//"b", .not. is_set(dy%b(1)), "not used by this dyad (kind "//kind_names(kind)// &
        "): its inner pair is prismatic", error)
      if (allocated(error)) return
      if (kind == kind_rpp .and. is_set(gam)) then
        ! the slot: a global point and direction; link b's origin is at the guide point C here
        call read_pair(ctx, p//"slot_at", dy%slot_at, .false., error); if (allocated(error)) return
        dy%slot_at = rotate(dy%slot_at - glob(:, 3), -gam * deg_to_rad)
        if (is_set(dy%slot_angle)) dy%slot_angle = dy%slot_angle - gam
      end if
    end select
  end subroutine globalize_dyad

  !> Global form, after the dyad is validated: its pose at the reference position must put
  !> the joints where the deck gave them (relative misfit 1e-6 of the dyad's size), else an
  !> input error naming the joint and the misfit; its links' frames there convert their
  !> centres of mass to link coordinates.
  subroutine reference_pose(ctx, d, phi_ref, glob, s_given, b_given, mech, ref, error)
    type(deck_context_t), intent(in) :: ctx
    !> Dyad number.
    integer, intent(in) :: d
    !> Reference crank angle, deg.
    real(wp), intent(in) :: phi_ref
    !> Given global points A, B, C, m.
    real(wp), intent(in) :: glob(2, 3)
    !> Whether s2, s3 were given; whether B was given.
    logical, intent(in) :: s_given(2), b_given
    !> The mechanism, dyad d built; its links' centres of mass are converted.
    type(assur_mech_t), intent(inout) :: mech
    !> Frames at the reference position; those of the dyad's links are set.
    type(link_state_t), intent(inout) :: ref(0:)
    type(error_t), allocatable, intent(out) :: error
    type(dyad_pose_t) :: pose
    character(len=:), allocatable :: p, at_ref
    real(wp) :: size, misfit
    integer :: kind
    p = "dyad("//int_str(d)//")%"
    at_ref = " at the reference position (phi_ref = "//real_str(phi_ref)//" deg)"
    associate (dy => mech%dyads(d))
      kind = dy%geom%kind
      call set_dyad_pose(dy%geom, ref(dy%on(1)), dy%at(:, 1), dy%ang(1), ref(dy%on(2)), dy%at(:, 2), dy%ang(2), pose)
    end associate
    if (pose%status /= pose_ok) then
      call deck_error(ctx, "dyad("//int_str(d)//")", "cannot be assembled"//at_ref, error)
      return
    end if
    size = magnitude(glob(:, 3) - glob(:, 1))
    if (b_given) size = max(size, magnitude(glob(:, 2) - glob(:, 1)), magnitude(glob(:, 2) - glob(:, 3)))
    size = max(size, tiny(1.0_wp))
    if (b_given) then
      misfit = magnitude(pose%p(:, 2) - glob(:, 2))
      if (misfit > misfit_rel * size) then
        call deck_error(ctx, p//"b", "the reference position is not assembled: joint B is "//real_str(misfit)// &
          " m from where the links put it ("//real_str(pose%p(1, 2))//", "//real_str(pose%p(2, 2))//")"// &
          at_ref, error)
        return
      end if
    end if
    if (kind == kind_rpp) then
      misfit = magnitude(pose%link(2)%o - glob(:, 3))
      if (misfit > misfit_rel * size) then
        call deck_error(ctx, p//"at2", "the reference position is not assembled: pin A is "//real_str(misfit)// &
          " m off the slot through slot_at"//at_ref, error)
        return
      end if
    end if
    ref(link_a(d)) = pose%link(1)
    ref(link_b(d)) = pose%link(2)
    if (s_given(1)) mech%links(link_a(d))%s = to_local(ref(link_a(d)), mech%links(link_a(d))%s)
    if (s_given(2)) mech%links(link_b(d))%s = to_local(ref(link_b(d)), mech%links(link_b(d))%s)
  end subroutine reference_pose

  !> The steps' crank angles as a list `phi1(:)` (any order), or phi_start [or
  !> start_at = 'extreme'], dphi, n; sets deck%n, deck%phi_list, deck%phi_start, deck%dphi,
  !> deck%start_extreme.
  subroutine read_steps(ctx, phi1, phi_start, dphi, n, start_at, deck, error)
    type(deck_context_t), intent(in) :: ctx
    !> The list as read (unset after its values), deg; moved into deck%phi_list when given.
    real(wp), allocatable, intent(inout) :: phi1(:)
    !> First angle (deg), step (deg), number of steps as read (or unset).
    real(wp), intent(in) :: phi_start, dphi, n
    !> '' or 'extreme'.
    character(*), intent(in) :: start_at
    type(assur_deck_t), intent(inout) :: deck
    type(error_t), allocatable, intent(out) :: error
    integer :: n_list, k
    call require_rule(ctx, "start_at", any(lower(trim(start_at)) == [character(len=8) :: "", "extreme"]), &
      "must be 'extreme' (the first extreme position of the output link at or after phi_start), got '"// &
      trim(start_at)//"'", error)
    if (allocated(error)) return
    deck%start_extreme = lower(trim(start_at)) == "extreme"
    call count_values(ctx, "phi1", phi1, n_list, error); if (allocated(error)) return
    if (n_list > 0) then
      call require_rule(ctx, "phi1", .not. any(is_set([phi_start, dphi, n])) .and. .not. deck%start_extreme, &
        "give either phi1(:) (a list of crank angles) or phi_start [start_at], dphi, n, not both", error)
      if (allocated(error)) return
      deck%n = n_list
      do k = 2, n_list
        if (phi1(k) /= phi1(k - 1)) then
          deck%first_move = sign(1.0_wp, phi1(k) - phi1(k - 1))
          exit
        end if
      end do
      call move_alloc(phi1, deck%phi_list)
      return
    end if
    deck%phi_start = optional_default(phi_start, 0.0_wp)
    call require_set(ctx, "phi_start", deck%phi_start, error); if (allocated(error)) return
    call steps_over_turn(ctx, dphi, n, deck%n, error); if (allocated(error)) return
    deck%dphi = dphi
  end subroutine read_steps


  !> A force by components (fx, fy; global, or link axes when follow): becomes its angle and
  !> a constant value (or `value` inside the window phi_on..phi_off, 0 outside).
  subroutine force_components(ctx, name, fi, error)
    type(deck_context_t), intent(in) :: ctx
    !> Prefix, e.g. "force(1)%".
    character(*), intent(in) :: name
    !> The force as read; angle and value are set from the components.
    type(force_in_t), intent(inout) :: fi
    type(error_t), allocatable, intent(out) :: error
    call require_rule(ctx, name//"fx", .not. any(is_set([fi%angle, fi%value, fi%column, fi%idle, fi%table(1)])), &
      "give the force either by components fx, fy or by angle with value/column/table, not both", error)
    if (allocated(error)) return
    fi%fx = optional_default(fi%fx, 0.0_wp)
    fi%fy = optional_default(fi%fy, 0.0_wp)
    call require_set(ctx, name//"fx", fi%fx, error); if (allocated(error)) return
    call require_set(ctx, name//"fy", fi%fy, error); if (allocated(error)) return
    fi%angle = atan2(fi%fy, fi%fx) * rad_to_deg
    fi%value = hypot(fi%fx, fi%fy)
  end subroutine force_components

  !> The output link (default: link b of the last dyad) and how its position is measured.
  subroutine read_output_link(ctx, output_link, ids, mech, error)
    type(deck_context_t), intent(in) :: ctx
    !> Link id as read (or unset).
    real(wp), intent(in) :: output_link
    !> Link ids by internal index.
    integer, intent(in) :: ids(0:)
    type(assur_mech_t), intent(inout) :: mech
    type(error_t), allocatable, intent(out) :: error
    integer :: i
    i = ubound(ids, 1)
    if (is_set(output_link)) then
      call find_link(ctx, "output_link", output_link, ids, .false., i, error); if (allocated(error)) return
    end if
    mech%output_link = i
    mech%output_pair = output_pair_of(mech, i)
  end subroutine read_output_link

  !> The crank angle of every step (deg): the list, or from phi_start (or the extreme
  !> position of the output link at or after it) by dphi.
  subroutine crank_angles(ctx, deck, error)
    type(deck_context_t), intent(in) :: ctx
    type(assur_deck_t), intent(inout) :: deck
    type(error_t), allocatable, intent(out) :: error
    real(wp) :: phi
    if (allocated(deck%phi_list)) return
    if (deck%start_extreme) then
      call assur_extreme(deck%mech, deck%phi_start * deg_to_rad, phi, error)
      if (allocated(error)) then
        error%message = ctx%path//": &"//group_name//": start_at: "//error%message
        return
      end if
      deck%phi_start = phi * rad_to_deg
    end if
  end subroutine crank_angles

  !> The driving linear actuator, when `drive_dyad` and `drive_pair` name one: a prismatic
  !> pair of a dyad whose axial force replaces the crank's balancing moment as the unknown.
  subroutine read_driver(ctx, drive_dyad, drive_pair, mech, error)
    type(deck_context_t), intent(in) :: ctx
    !> Deck values (whole numbers read as reals, or unset).
    real(wp), intent(in) :: drive_dyad, drive_pair
    !> Mechanism with its dyads; receives drive_dyad, drive_pair.
    type(assur_mech_t), intent(inout) :: mech
    type(error_t), allocatable, intent(out) :: error
    integer :: d, j, kind
    character(len=:), allocatable :: prismatic
    if (.not. is_set(drive_dyad) .and. .not. is_set(drive_pair)) return
    call require_rule(ctx, "drive_pair", is_set(drive_pair), "missing: a linear actuator is named by "// &
      "drive_dyad and drive_pair (its prismatic pair: 1 outer of link2, 2 inner, 3 outer of link3)", error)
    if (allocated(error)) return
    call require_rule(ctx, "drive_dyad", is_set(drive_dyad), "missing: a linear actuator is named by "// &
      "drive_dyad and drive_pair", error)
    if (allocated(error)) return
    call require_whole(ctx, "drive_dyad", drive_dyad, 1, size(mech%dyads), d, error); if (allocated(error)) return
    call require_whole(ctx, "drive_pair", drive_pair, 1, 3, j, error); if (allocated(error)) return
    kind = mech%dyads(d)%geom%kind
    if (.not. pair_is_prismatic(kind, j)) then
      prismatic = ""
      do j = 1, 3
        if (pair_is_prismatic(kind, j)) prismatic = prismatic//" "//int_str(j)
      end do
      if (len(prismatic) == 0) then
        prismatic = "; dyad "//int_str(d)//" (RRR) has none"
      else
        prismatic = "; its prismatic pairs:"//prismatic
      end if
      call deck_error(ctx, "drive_pair", "pair "//number_str(drive_pair)//" of dyad "//int_str(d)//" ("// &
        kind_names(kind)//") is revolute: a linear actuator drives a prismatic pair"//prismatic, error)
      return
    end if
    mech%drive_dyad = d
    mech%drive_pair = j
  end subroutine read_driver

  !> Column name stem of the force on link `on` from link `from`: "F21", or "F12_3" for ids >= 10.
  pure function pair_stem(on, from) result(s)
    integer, intent(in) :: on, from
    character(len=16) :: s
    if (on < 10 .and. from < 10) then
      s = "F"//int_str(on)//int_str(from)
    else
      s = "F"//int_str(on)//"_"//int_str(from)
    end if
  end function pair_stem

  !> Whether any component of a dyad entry was set.
  elemental logical function dyad_touched(dy)
    type(dyad_in_t), intent(in) :: dy
    dyad_touched = any(is_set([dy%link2, dy%link3, dy%on2, dy%on3, dy%at2, dy%at3, dy%angle2, dy%angle3, &
                               dy%l2, dy%l3, dy%e, dy%slot_at, dy%slot_angle, dy%mode, dy%m2, dy%j2, dy%s2, &
                               dy%m3, dy%j3, dy%s3, dy%frame_angle, dy%inner_on, dy%f2, dy%f3, dy%f23, &
                               dy%r2, dy%r3, dy%r23, dy%guide2, dy%guide3, dy%guide23, dy%block2, dy%block3, &
                               dy%block23, dy%b]))
  end function dyad_touched

  !> Number of leading true entries of `given`.
  pure integer function leading(given)
    logical, intent(in) :: given(:)
    leading = findloc(given, .false., dim=1) - 1
    if (leading < 0) leading = size(given)
  end function leading

  !> Loads (forces or moments) numbered 1, 2, ... without gaps: past the first `n`, whose
  !> links are given, no entry may give its link or a value.
  subroutine numbered_without_gaps(ctx, what, linked, touched, n, error)
    type(deck_context_t), intent(in) :: ctx
    !> "force" or "moment".
    character(*), intent(in) :: what
    !> Per entry: whether its link is given; whether any of its values is.
    logical, intent(in) :: linked(:), touched(:)
    !> Number of loads (the leading linked entries).
    integer, intent(in) :: n
    type(error_t), allocatable, intent(out) :: error
    integer :: k
    do k = n + 1, size(linked)
      if (linked(k) .and. k > n + 1) then
        call deck_error(ctx, what//"("//int_str(n + 1)//")", "missing: "//what//"("//int_str(k)// &
          ") is given, and "//what//"s must be numbered 1, 2, ... without gaps", error)
        return
      else if (touched(k)) then
        call deck_error(ctx, what//"("//int_str(k)//")%link", "missing ("//what//"s must be numbered without gaps)", &
          error)
        return
      end if
    end do
  end subroutine numbered_without_gaps

  !> A two-component point: both set and finite; with `zero_default`, (0, 0) when neither
  !> is set.
  subroutine read_pair(ctx, name, x, zero_default, error)
    type(deck_context_t), intent(in) :: ctx
    character(*), intent(in) :: name
    real(wp), intent(inout) :: x(2)
    !> Whether the point is optional, (0, 0) by default.
    logical, intent(in) :: zero_default
    type(error_t), allocatable, intent(out) :: error
    if (zero_default .and. .not. any(is_set(x))) then
      x = 0.0_wp
    else if (.not. all(is_set(x))) then
      if (any(is_set(x))) then
        call deck_error(ctx, name, "needs two values (x, y), got one", error)
      else
        call deck_error(ctx, name, "missing (required variable: two values x, y)", error)
      end if
    else if (.not. all(ieee_is_finite(x))) then
      call deck_error(ctx, name, "must be finite numbers", error)
    end if
  end subroutine read_pair

  !> A dyad that hangs on a link no one defines, in a deck where no dyad hangs on the crank
  !> (or on the frame): the mistake is crank_id's (frame_id's), not the dyad's
  !> (`crank_id = 1000` in a deck whose dyads hang on link 1). Only when exactly one of the
  !> two carries no dyad; otherwise find_link names the dyad.
  subroutine blame_frame_or_crank(ctx, dyads, frame_no, crank_no, error)
    type(deck_context_t), intent(in) :: ctx
    !> The dyads as read.
    type(dyad_in_t), intent(in) :: dyads(:)
    !> frame_id and crank_id.
    integer, intent(in) :: frame_no, crank_no
    type(error_t), allocatable, intent(out) :: error
    integer, allocatable :: defined(:)
    integer :: d, q, id, unknown
    real(wp) :: on(2)
    character(len=:), allocatable :: culprit
    logical :: frame_used, crank_used
    allocate (defined(2 + 2 * size(dyads)))
    defined(1:2) = [frame_no, crank_no]
    do d = 1, size(dyads)
      if (.not. (is_whole_in(dyads(d)%link2, 0, huge(1)) .and. is_whole_in(dyads(d)%link3, 0, huge(1)))) return
      defined(2 * d + 1:2 * d + 2) = [nint(dyads(d)%link2), nint(dyads(d)%link3)]
    end do
    frame_used = .false.
    crank_used = .false.
    unknown = -1
    do d = 1, size(dyads)
      on = [dyads(d)%on2, dyads(d)%on3]
      do q = 1, 2
        if (.not. is_whole_in(on(q), 0, huge(1))) cycle
        id = nint(on(q))
        frame_used = frame_used .or. id == frame_no
        crank_used = crank_used .or. id == crank_no
        if (unknown < 0 .and. all(defined /= id)) then
          unknown = id
          culprit = "dyad("//int_str(d)//")%on"//int_str(q + 1)
        end if
      end do
    end do
    if (unknown < 0 .or. (frame_used .eqv. crank_used)) return
    if (.not. crank_used) then
      call deck_error(ctx, "crank_id", "no dyad hangs on link "//int_str(crank_no)//" (the crank), and "// &
        culprit//" names link "//int_str(unknown)//", which no one defines: is the crank link "// &
        int_str(unknown)//"? (got crank_id = "//int_str(crank_no)//")", error)
    else
      call deck_error(ctx, "frame_id", "no dyad hangs on link "//int_str(frame_no)//" (the frame), and "// &
        culprit//" names link "//int_str(unknown)//", which no one defines: is the frame link "// &
        int_str(unknown)//"? (got frame_id = "//int_str(frame_no)//")", error)
    end if
  end subroutine blame_frame_or_crank

  !> Validate dyad `d` and build its geometry and link data; `ids` are the links defined before it.
  subroutine read_dyad(ctx, d, dy, ids, out, la, lb, error)
    type(deck_context_t), intent(in) :: ctx
    integer, intent(in) :: d
    type(dyad_in_t), intent(inout) :: dy
    integer, intent(in) :: ids(0:)
    type(assur_dyad_t), intent(out) :: out
    type(assur_link_t), intent(out) :: la, lb
    type(error_t), allocatable, intent(out) :: error
    character(len=:), allocatable :: p, kn
    logical :: p1, p3
    integer :: kind, link2, link3
    !> The checks of the dimensions and of the masses.
    type(deck_rules_t) :: rules
    rules = deck_rules_t(ctx)
    p = "dyad("//int_str(d)//")%"
    call require_rule(ctx, p//"kind", is_whole_in(dy%kind, 1, 5), "must be 1..5 "// &
      "(1 RRR, 2 RRP, 3 RPR, 4 PRP, 5 RPP), got "//number_str(dy%kind), error)
    if (allocated(error)) return
    kind = nint(dy%kind)
    kn = " (kind "//kind_names(kind)//")"
    p1 = kind == kind_prp
    p3 = kind == kind_rrp .or. kind == kind_prp .or. kind == kind_rpp
    ! link ids: new and distinct
    call rules%require_rule(p//"link2", is_set(dy%link2), "missing (required link number)")
    call rules%require_rule(p//"link3", is_set(dy%link3), "missing (required link number)")
    call rules%require_whole(p//"link2", dy%link2, 0, huge(1), link2)
    call rules%require_whole(p//"link3", dy%link3, 0, huge(1), link3)
    call rules%require_rule(p//"link2", all(ids /= link2), "link number "// &
      int_str(link2)//" must be >= 0 and not used by the frame, the crank or an earlier dyad")
    call rules%require_rule(p//"link3", all(ids /= link3) .and. link3 /= link2, &
      "link number "//int_str(link3)//" must be >= 0, differ from link2 and not be used before")
    if (rules%failed(error)) return
    call find_link(ctx, p//"on2", dy%on2, ids, .true., out%on(1), error); if (allocated(error)) return
    call find_link(ctx, p//"on3", dy%on3, ids, .true., out%on(2), error); if (allocated(error)) return
    call read_pair(ctx, p//"at2", dy%at2, .false., error); if (allocated(error)) return
    call read_pair(ctx, p//"at3", dy%at3, .false., error); if (allocated(error)) return
    out%at(:, 1) = dy%at2
    out%at(:, 2) = dy%at3
    ! guide angles: only for prismatic outer pairs
    call used_only_if(ctx, p//"angle2", is_set(dy%angle2), p1, kn, error); if (allocated(error)) return
    call used_only_if(ctx, p//"angle3", is_set(dy%angle3), p3, kn, error); if (allocated(error)) return
    if (p1) then
      call require_set(ctx, p//"angle2", dy%angle2, error); if (allocated(error)) return
      out%ang(1) = dy%angle2 * deg_to_rad
    end if
    if (p3) then
      call require_set(ctx, p//"angle3", dy%angle3, error); if (allocated(error)) return
      out%ang(2) = dy%angle3 * deg_to_rad
    end if
    ! dimensions
    out%geom%kind = kind
    call used_only_if(ctx, p//"l2", is_set(dy%l2), kind == kind_rrr .or. kind == kind_rrp, kn, error)
    if (allocated(error)) return
    call used_only_if(ctx, p//"l3", is_set(dy%l3), kind == kind_rrr, kn, error); if (allocated(error)) return
    call used_only_if(ctx, p//"e", is_set(dy%e), kind == kind_rpr, kn, error); if (allocated(error)) return
    call used_only_if(ctx, p//"slot_at", any(is_set(dy%slot_at)), kind == kind_rpp, kn, error)
    if (allocated(error)) return
    call used_only_if(ctx, p//"slot_angle", is_set(dy%slot_angle), kind == kind_rpp, kn, error)
    if (allocated(error)) return
    call used_only_if(ctx, p//"mode", is_set(dy%mode), kind_has_mode(kind), kn, error)
    if (allocated(error)) return
    select case (kind)
    case (kind_rrr)
      call rules%require_each(rule_positive, [character(len=len(p) + 2) :: p//"l2", p//"l3"], [dy%l2, dy%l3])
      if (rules%failed(error)) return
      out%geom%l2 = dy%l2
      out%geom%l3 = dy%l3
    case (kind_rrp)
      call require_positive(ctx, p//"l2", dy%l2, error); if (allocated(error)) return
      out%geom%l2 = dy%l2
    case (kind_rpr)
      dy%e = optional_default(dy%e, 0.0_wp)
      call require_set(ctx, p//"e", dy%e, error); if (allocated(error)) return
      out%geom%e = dy%e
    case (kind_rpp)
      call read_pair(ctx, p//"slot_at", dy%slot_at, .true., error); if (allocated(error)) return
      call require_set(ctx, p//"slot_angle", dy%slot_angle, error); if (allocated(error)) return
      call require_rule(ctx, p//"slot_angle", abs(sin(dy%slot_angle * deg_to_rad)) > 1.0e-9_wp, &
        "must not be parallel to the guide (0 or 180 deg): the slider could not be located", error)
      if (allocated(error)) return
      out%geom%slot_at = dy%slot_at
      out%geom%slot_angle = dy%slot_angle * deg_to_rad
    end select
    if (kind_has_mode(kind)) then
      if (.not. is_set(dy%mode)) dy%mode = 1.0_wp
      call require_rule(ctx, p//"mode", dy%mode == 1.0_wp .or. dy%mode == -1.0_wp, &
        "must be +1 or -1 (assembly mode), got "//number_str(dy%mode), error)
      if (allocated(error)) return
      out%geom%mode = nint(dy%mode)
    end if
    ! masses
    dy%m2 = optional_default(dy%m2, 0.0_wp)
    dy%j2 = optional_default(dy%j2, 0.0_wp)
    dy%m3 = optional_default(dy%m3, 0.0_wp)
    dy%j3 = optional_default(dy%j3, 0.0_wp)
    call rules%require_each(rule_nonnegative, [character(len=len(p) + 2) :: p//"m2", p//"j2", p//"m3", p//"j3"], &
      [dy%m2, dy%j2, dy%m3, dy%j3])
    if (rules%failed(error)) return
    call read_pair(ctx, p//"s2", dy%s2, .true., error); if (allocated(error)) return
    call read_pair(ctx, p//"s3", dy%s3, .true., error); if (allocated(error)) return
    if (.not. is_set(dy%inner_on)) dy%inner_on = dy%link2
    call require_rule(ctx, p//"inner_on", dy%inner_on == dy%link2 .or. dy%inner_on == dy%link3, &
      "must be link2 ("//int_str(link2)//") or link3 ("//int_str(link3)//"), got "//number_str(dy%inner_on), error)
    if (allocated(error)) return
    if (is_set(dy%frame_angle)) then
      call require_set(ctx, p//"frame_angle", dy%frame_angle, error); if (allocated(error)) return
    end if
    la = assur_link_t(id=link2, m=dy%m2, j=dy%j2, s=dy%s2)
    lb = assur_link_t(id=link3, m=dy%m3, j=dy%j3, s=dy%s3)
  end subroutine read_dyad

  !> Friction data of the three pairs of dyad `d` (outer of link2, inner, outer of link3).
  subroutine read_dyad_friction(ctx, d, dy, out, error)
    type(deck_context_t), intent(in) :: ctx
    integer, intent(in) :: d
    type(dyad_in_t), intent(in) :: dy
    !> Friction of pairs 1, 2, 3 of the dyad.
    type(pair_friction_t), intent(out) :: out(3)
    type(error_t), allocatable, intent(out) :: error
    character(len=:), allocatable :: p
    integer :: kind
    p = "dyad("//int_str(d)//")%"
    kind = nint(dy%kind)
    call read_pair_friction(ctx, p//"f2", p//"r2", p//"guide2", p//"block2", dy%f2, dy%r2, dy%guide2, dy%block2, &
                            pair_is_prismatic(kind, 1), out(1), error)
    if (allocated(error)) return
    call read_pair_friction(ctx, p//"f23", p//"r23", p//"guide23", p//"block23", dy%f23, dy%r23, dy%guide23, &
                            dy%block23, pair_is_prismatic(kind, 2), out(2), error)
    if (allocated(error)) return
    call read_pair_friction(ctx, p//"f3", p//"r3", p//"guide3", p//"block3", dy%f3, dy%r3, dy%guide3, dy%block3, &
                            pair_is_prismatic(kind, 3), out(3), error)
  end subroutine read_dyad_friction

  !> Friction data of one pair: coefficient `f` >= 0 (default 0); a turning pair takes the
  !> journal radius `r` (> 0 when f > 0), a sliding pair the optional guide and block lengths
  !> (> 0 when given; the contact span is the shorter of those given).
  subroutine read_pair_friction(ctx, f_name, r_name, guide_name, block_name, f, r, guide, block, prismatic, &
                                out, error)
    type(deck_context_t), intent(in) :: ctx
    !> Variable names as in the deck.
    character(*), intent(in) :: f_name, r_name, guide_name, block_name
    !> Values as read (unset_real when not given): coefficient, radius (m), lengths (m).
    real(wp), intent(in) :: f, r, guide, block
    !> Whether the pair is a sliding pair.
    logical, intent(in) :: prismatic
    type(pair_friction_t), intent(out) :: out
    type(error_t), allocatable, intent(out) :: error
    character(*), parameter :: turning = " (a turning pair: give its journal radius instead)"
    character(*), parameter :: sliding = " (a sliding pair: give its guide and block lengths instead)"
    out%f = optional_default(f, 0.0_wp)
    call require_finite_nonnegative(ctx, f_name, out%f, error); if (allocated(error)) return
    if (prismatic) then
      call require_rule(ctx, r_name, .not. is_set(r), "not used by this pair"//sliding//": remove it", error)
      if (allocated(error)) return
      if (is_set(guide)) then
        call require_finite_nonnegative(ctx, guide_name, guide, error); if (allocated(error)) return
        if (guide > 0.0_wp) out%span = guide
      end if
      if (is_set(block)) then
        call require_finite_nonnegative(ctx, block_name, block, error); if (allocated(error)) return
        if (block > 0.0_wp .and. (out%span == 0.0_wp .or. block < out%span)) out%span = block
      end if
    else
      if (len(guide_name) > 0) then
        call require_rule(ctx, guide_name, .not. is_set(guide), "not used by this pair"//turning//": remove it", error)
        if (allocated(error)) return
        call require_rule(ctx, block_name, .not. is_set(block), "not used by this pair"//turning//": remove it", error)
        if (allocated(error)) return
      end if
      out%r = optional_default(r, 0.0_wp)
      call require_finite_nonnegative(ctx, r_name, out%r, error); if (allocated(error)) return
      call require_rule(ctx, r_name, out%r > 0.0_wp .or. .not. out%f > 0.0_wp, "the journal radius must be > 0 "// &
        "when the friction coefficient "//f_name//" is > 0 (the friction moment is f*r*|F|)", error)
    end if
  end subroutine read_pair_friction

  !> A variable that must be a finite number >= 0.
  subroutine require_finite_nonnegative(ctx, name, x, error)
    type(deck_context_t), intent(in) :: ctx
    character(*), intent(in) :: name
    real(wp), intent(in) :: x
    type(error_t), allocatable, intent(out) :: error
    call require_nonnegative(ctx, name, x, error); if (allocated(error)) return
    call require_rule(ctx, name, ieee_is_finite(x), "must be a finite number (got "//real_str(x)//")", error)
  end subroutine require_finite_nonnegative

  !> Reject a variable that the dyad's kind does not use.
  pure subroutine used_only_if(ctx, name, given, used, kind_note, error)
    type(deck_context_t), intent(in) :: ctx
    character(*), intent(in) :: name, kind_note
    logical, intent(in) :: given, used
    type(error_t), allocatable, intent(out) :: error
    if (given .and. .not. used) call deck_error(ctx, name, "not used by this dyad"//kind_note// &
      ": remove it", error)
  end subroutine used_only_if

end module kinetostat_assur_deck
