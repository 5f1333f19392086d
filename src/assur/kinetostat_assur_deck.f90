!> `&assur` decks (generic one-DOF linkage of class-II dyads): reading, validation, template.
!>
!> Links are named by the deck's link numbers (ids); the frame, the crank and every dyad
!> link have distinct ids. Dyads, forces and moments are derived-type arrays of the namelist
!> (`dyad(1)%kind = 1, dyad(1)%l2 = 0.4, ...`); unset components are detected by the
!> sentinel `unset_real`. Integer deck variables (kinds, link numbers, modes, columns, n)
!> are read as reals and converted by `require_whole` or an equivalent whole-number check.
module kinetostat_assur_deck
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use kinetostat_kinds, only: wp, g_default, deg_to_rad
  use kinetostat_error, only: error_t
  use kinetostat_text, only: real_str, int_str, number_str
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_deck, only: write_template_lines, deck_array_capacity, deck_context_t, unset_real, unset_bits, &
    max_deck_array, &
    deck_source_t, namelist_failure, deck_error, is_set, require_set, require_positive, &
    require_nonnegative, require_rule, optional_default, count_values, steps_over_turn, &
    is_whole_in, require_whole
  use kinetostat_vec2, only: unit_at
  use kinetostat_assur_kinematics, only: dyad_geometry_t, kind_names, kind_has_mode, &
    kind_rrr, kind_rrp, kind_rpr, kind_prp, kind_rpp
  use kinetostat_assur_statics, only: pair_is_prismatic
  use kinetostat_assur, only: assur_mech_t, assur_link_t, assur_dyad_t, assur_force_t, link_a, link_b
  implicit none
  private
  public :: assur_deck_t, read_assur_deck, write_assur_template, assur_window
  public :: max_dyads, max_forces, max_moments

  !> Capacity of the dyad list.
  integer, parameter :: max_dyads = 16
  !> Capacity of the external force list.
  integer, parameter :: max_forces = 16
  !> Capacity of the external moment list.
  integer, parameter :: max_moments = 16
  !> Unset logical marker is not available in namelists: logicals have plain defaults.
  character(*), parameter :: group_name = "assur"

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
  end type dyad_in_t

  !> A per-step value: constant, angle window, or a column of `step_values`.
  type :: schedule_in_t
    !> Value (N or N*m): constant, or inside the window.
    real(wp) :: value = unset
    !> Value outside the window, default 0.
    real(wp) :: idle = unset
    !> Window [phi_on, phi_off] of crank angles (deg, absolute, not modulo 360).
    real(wp) :: phi_on = unset, phi_off = unset
    !> Column of `step_values` holding one value per step instead (a whole number).
    real(wp) :: column = unset
  end type schedule_in_t

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
  end type force_in_t

  !> An external moment as written in the deck.
  type :: moment_in_t
    !> Id of the loaded link (a whole number).
    real(wp) :: link = unset
    !> Moment, N*m, CCW positive.
    real(wp) :: value = unset, idle = unset, phi_on = unset, phi_off = unset
    !> Column of step_values (a whole number).
    real(wp) :: column = unset
  end type moment_in_t

  !> A validated `&assur` deck.
  type :: assur_deck_t
    !> Mechanism.
    type(assur_mech_t) :: mech
    !> Title (free text).
    character(len=80) :: title = ""
    !> First crank angle, deg.
    real(wp) :: phi_start = 0.0_wp
    !> Crank step, deg.
    real(wp) :: dphi = 0.0_wp
    !> Number of steps.
    integer :: n = 0
    !> Direction of gravity, deg.
    real(wp) :: gravity_angle = -90.0_wp
    !> Constant crank speed (when not prescribed per step), rad/s.
    real(wp) :: omega1_const = 0.0_wp
    !> Whether omega1/eps1 were prescribed per step.
    logical :: prescribed = .false.
    !> Crank angle per step, deg.
    real(wp), allocatable :: phi1_deg(:)
    !> Crank speed per step, rad/s.
    real(wp), allocatable :: omega1(:)
    !> Crank acceleration per step, rad/s^2.
    real(wp), allocatable :: eps1(:)
    !> Force magnitudes (force, step), N.
    real(wp), allocatable :: f_mag(:, :)
    !> Moments (moment, step), N*m.
    real(wp), allocatable :: m_mag(:, :)
    !> Reporting frame angle of each pair (dyad pairs, then crank pin), rad.
    real(wp), allocatable :: pair_frame(:)
    !> Column name stem of each pair ("F21").
    character(len=16), allocatable :: pair_name(:)
    !> +1, or -1 where the report shows the reaction's opposite (inner pair on link b).
    real(wp), allocatable :: pair_sign(:)
    !> Angles in (-180, 180] instead of [0, 360).
    logical :: angles_signed = .false.
    !> CSV also carries the x, y components of every pair force.
    logical :: components = .true.
    !> Frame id, crank id.
    integer :: frame_id = 0, crank_id = 1
  end type assur_deck_t

  !> Template deck: the slider-crank of data/assur_slider_crank.nml.
  character(*), parameter :: template_lines(*) = [character(len=100) :: &
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
    "  ! resistance on the slider: -x, 500 N for crank angles in [0, 180] deg, 100 N elsewhere", &
    "  force(1)%link = 3, force(1)%at = 0, 0, force(1)%angle = 180", &
    "  force(1)%value = 500, force(1)%idle = 100, force(1)%phi_on = 0, force(1)%phi_off = 180", &
    "/"]

contains

  !> The commented template deck.
  pure subroutine write_assur_template(out)
    !> Where the lines go.
    type(text_buffer_t), intent(inout) :: out
    call write_template_lines(out, template_lines)
  end subroutine write_assur_template

  !> Windowed value at crank angle `phi_deg`: `value` for phi_on <= phi <= phi_off
  !> (absolute degrees, 1e-9 deg tolerance), `idle` elsewhere.
  elemental function assur_window(phi_deg, phi_on, phi_off, value, idle) result(v)
    !> Crank angle, deg.
    real(wp), intent(in) :: phi_deg
    !> Window, deg.
    real(wp), intent(in) :: phi_on, phi_off
    !> Values inside and outside.
    real(wp), intent(in) :: value, idle
    real(wp) :: v
    real(wp), parameter :: angle_tol = 1.0e-9_wp
    if (phi_deg >= phi_on - angle_tol .and. phi_deg <= phi_off + angle_tol) then
      v = value
    else
      v = idle
    end if
  end function assur_window

  !> Read and validate an `&assur` deck.
  subroutine read_assur_deck(source, deck, error)
    !> The deck, read into memory (see load_deck).
    type(deck_source_t), intent(in) :: source
    !> The validated deck.
    type(assur_deck_t), intent(out) :: deck
    !> Input error naming file, group, variable and reason.
    type(error_t), allocatable, intent(out) :: error
    character(len=80) :: title
    !> Integer deck variables, read as reals (see require_whole).
    real(wp) :: frame_id, crank_id, n
    !> Linear actuator as driver: dyad number and pair 1..3 (whole numbers, read as reals).
    real(wp) :: drive_dyad, drive_pair
    !> frame_id and crank_id as integers.
    integer :: frame_no, crank_no, nd, nf, nm, n_omega, n_eps, n_values, ios, k, d, i
    real(wp) :: crank_at(2), crank_m, crank_j, crank_s(2), omega1, g, gravity_angle, phi_start, dphi
    real(wp), allocatable :: omega1_step(:), eps1_step(:), step_values(:)
    logical :: angles_signed, components
    type(dyad_in_t) :: dyad(max_dyads)
    type(force_in_t) :: force(max_forces)
    type(moment_in_t) :: moment(max_moments)
    type(schedule_in_t) :: sched
    character(len=512) :: msg
    type(deck_context_t) :: ctx
    integer, allocatable :: ids(:)
    character(len=:), allocatable :: name
    !> Elements of each per-step array (deck_array_capacity).
    integer :: capacity
    namelist /assur/ title, frame_id, crank_id, crank_at, crank_m, crank_j, crank_s, omega1, &
      omega1_step, eps1_step, g, gravity_angle, phi_start, dphi, n, dyad, force, moment, &
      step_values, angles_signed, components, drive_dyad, drive_pair

    ctx%path = source%path
    ctx%group = group_name
    title = ""
    frame_id = 0.0_wp; crank_id = 1.0_wp; n = unset_real
    drive_dyad = unset_real; drive_pair = unset_real
    crank_at = unset_real; crank_m = unset_real; crank_j = unset_real; crank_s = unset_real
    omega1 = unset_real; g = unset_real; gravity_angle = unset_real
    phi_start = unset_real; dphi = unset_real
    angles_signed = .false.; components = .true.
    capacity = deck_array_capacity(source)   ! not max_deck_array: a small deck stays small
    allocate (omega1_step(capacity), eps1_step(capacity), step_values(capacity), &
              source=unset_real)

    read (source%lines, nml=assur, iostat=ios, iomsg=msg)
    if (ios /= 0) then
      call namelist_failure(ctx, ios, msg, error)
      return
    end if

    ! ---- frame, crank, speed law, gravity, steps
    call require_whole(ctx, "frame_id", frame_id, 0, huge(1), frame_no, error); if (allocated(error)) return
    call require_whole(ctx, "crank_id", crank_id, 0, huge(1), crank_no, error); if (allocated(error)) return
    call require_rule(ctx, "crank_id", crank_no /= frame_no, &
      "must be >= 0 and differ from frame_id (got "//int_str(crank_no)//")", error)
    if (allocated(error)) return
    call optional_pair(ctx, "crank_at", crank_at, error); if (allocated(error)) return
    call optional_pair(ctx, "crank_s", crank_s, error); if (allocated(error)) return
    crank_m = optional_default(crank_m, 0.0_wp)
    call require_nonnegative(ctx, "crank_m", crank_m, error); if (allocated(error)) return
    crank_j = optional_default(crank_j, 0.0_wp)
    call require_nonnegative(ctx, "crank_j", crank_j, error); if (allocated(error)) return
    g = optional_default(g, g_default)
    call require_nonnegative(ctx, "g", g, error); if (allocated(error)) return
    gravity_angle = optional_default(gravity_angle, -90.0_wp)
    call require_set(ctx, "gravity_angle", gravity_angle, error); if (allocated(error)) return
    phi_start = optional_default(phi_start, 0.0_wp)
    call require_set(ctx, "phi_start", phi_start, error); if (allocated(error)) return
    call steps_over_turn(ctx, dphi, n, deck%n, error); if (allocated(error)) return

    call count_values(ctx, "omega1_step", omega1_step, n_omega, error); if (allocated(error)) return
    call count_values(ctx, "eps1_step", eps1_step, n_eps, error); if (allocated(error)) return
    if (n_omega > 0 .or. n_eps > 0) then
      call require_rule(ctx, "omega1", .not. is_set(omega1), &
        "give either omega1 (constant) or omega1_step(:) with eps1_step(:), not both", error)
      if (allocated(error)) return
      call require_rule(ctx, "omega1_step", n_omega == deck%n, "expected "//int_str(deck%n)// &
        " values (one per step), got "//int_str(n_omega), error)
      if (allocated(error)) return
      call require_rule(ctx, "eps1_step", n_eps == deck%n, "expected "//int_str(deck%n)// &
        " values (one per step), got "//int_str(n_eps), error)
      if (allocated(error)) return
      deck%prescribed = .true.
      deck%omega1 = omega1_step(1:deck%n)
      deck%eps1 = eps1_step(1:deck%n)
    else
      call require_set(ctx, "omega1", omega1, error); if (allocated(error)) return
      allocate (deck%omega1(deck%n), source=omega1)
      allocate (deck%eps1(deck%n), source=0.0_wp)
      deck%omega1_const = omega1
    end if
    deallocate (omega1_step, eps1_step)
    call count_values(ctx, "step_values", step_values, n_values, error); if (allocated(error)) return

    ! ---- dyads: the leading set entries, no gaps
    nd = 0
    do d = 1, max_dyads
      if (.not. is_set(dyad(d)%kind)) exit
      nd = d
    end do
    call require_rule(ctx, "dyad", nd >= 1, "at least one dyad is required (dyad(1)%kind missing)", error)
    if (allocated(error)) return
    do d = nd + 1, max_dyads
      if (dyad_touched(dyad(d))) then
        call deck_error(ctx, "dyad("//int_str(d)//")", "dyads must be numbered 1.."//int_str(nd + 1)// &
          " without gaps (dyad("//int_str(nd + 1)//")%kind is missing)", error)
        return
      end if
    end do

    allocate (deck%mech%links(0:2 * nd + 1), deck%mech%dyads(nd))
    deck%mech%links(0) = assur_link_t(id=frame_no)
    deck%mech%links(1) = assur_link_t(id=crank_no, m=crank_m, j=crank_j, s=crank_s)
    deck%mech%pivot = crank_at
    allocate (ids(0:2 * nd + 1))
    ids(0) = frame_no
    ids(1) = crank_no
    do d = 1, nd
      call read_dyad(ctx, d, dyad(d), ids(0:2 * d - 1), deck%mech%dyads(d), &
                     deck%mech%links(link_a(d)), deck%mech%links(link_b(d)), error)
      if (allocated(error)) return
      ids(2 * d) = deck%mech%links(link_a(d))%id
      ids(2 * d + 1) = deck%mech%links(link_b(d))%id
    end do

    call read_driver(ctx, drive_dyad, drive_pair, deck%mech, error); if (allocated(error)) return

    ! ---- external forces and moments
    nf = 0
    do k = 1, max_forces
      if (.not. is_set(force(k)%link)) exit
      nf = k
    end do
    nm = 0
    do k = 1, max_moments
      if (.not. is_set(moment(k)%link)) exit
      nm = k
    end do
    allocate (deck%mech%forces(nf), deck%mech%moment_link(nm))
    allocate (deck%f_mag(nf, deck%n), deck%m_mag(nm, deck%n))
    allocate (deck%phi1_deg(deck%n))
    deck%phi1_deg = [(phi_start + real(k - 1, wp) * dphi, k=1, deck%n)]
    do k = nf + 1, max_forces
      if (is_set(force(k)%value) .or. is_set(force(k)%angle) .or. is_set(force(k)%column)) then
        call deck_error(ctx, "force("//int_str(k)//")%link", "missing (forces must be numbered without gaps)", error)
        return
      end if
    end do
    do k = nm + 1, max_moments
      if (is_set(moment(k)%value) .or. is_set(moment(k)%column)) then
        call deck_error(ctx, "moment("//int_str(k)//")%link", "missing (moments must be numbered without gaps)", error)
        return
      end if
    end do
    do k = 1, nf
      name = "force("//int_str(k)//")%"
      associate (fi => force(k))
        call moving_link(ctx, name//"link", fi%link, ids, i, error); if (allocated(error)) return
        call optional_pair(ctx, name//"at", fi%at, error); if (allocated(error)) return
        call require_set(ctx, name//"angle", fi%angle, error); if (allocated(error)) return
        deck%mech%forces(k) = assur_force_t(link=i, at=fi%at, angle=fi%angle * deg_to_rad, follow=fi%follow)
        sched = schedule_in_t(value=fi%value, idle=fi%idle, phi_on=fi%phi_on, phi_off=fi%phi_off, column=fi%column)
        call read_schedule(ctx, name, sched, deck%phi1_deg, step_values(1:n_values), deck%f_mag(k, :), error)
        if (allocated(error)) return
      end associate
    end do
    do k = 1, nm
      name = "moment("//int_str(k)//")%"
      associate (mi => moment(k))
        call moving_link(ctx, name//"link", mi%link, ids, i, error); if (allocated(error)) return
        deck%mech%moment_link(k) = i
        sched = schedule_in_t(value=mi%value, idle=mi%idle, phi_on=mi%phi_on, phi_off=mi%phi_off, column=mi%column)
        call read_schedule(ctx, name, sched, deck%phi1_deg, step_values(1:n_values), deck%m_mag(k, :), error)
        if (allocated(error)) return
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

    deck%mech%g = g
    deck%gravity_angle = gravity_angle
    deck%mech%down = unit_at(gravity_angle * deg_to_rad)
    deck%title = title
    deck%phi_start = phi_start
    deck%dphi = dphi
    deck%angles_signed = angles_signed
    deck%components = components
    deck%frame_id = frame_no
    deck%crank_id = crank_no
  end subroutine read_assur_deck

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
  pure logical function dyad_touched(dy)
    type(dyad_in_t), intent(in) :: dy
    dyad_touched = any(is_set([dy%link2, dy%link3, dy%on2, dy%on3, dy%at2, dy%at3, dy%angle2, dy%angle3, &
                               dy%l2, dy%l3, dy%e, dy%slot_at, dy%slot_angle, dy%mode, dy%m2, dy%j2, dy%s2, &
                               dy%m3, dy%j3, dy%s3, dy%frame_angle, dy%inner_on]))
  end function dyad_touched

  !> A two-component point: default (0, 0) when unset; both or none; finite.
  subroutine optional_pair(ctx, name, x, error)
    type(deck_context_t), intent(in) :: ctx
    character(*), intent(in) :: name
    real(wp), intent(inout) :: x(2)
    type(error_t), allocatable, intent(out) :: error
    if (.not. any(is_set(x))) then
      x = 0.0_wp
      return
    end if
    call require_pair(ctx, name, x, error)
  end subroutine optional_pair

  !> A required two-component point: both set and finite.
  subroutine require_pair(ctx, name, x, error)
    type(deck_context_t), intent(in) :: ctx
    character(*), intent(in) :: name
    real(wp), intent(in) :: x(2)
    type(error_t), allocatable, intent(out) :: error
    if (.not. all(is_set(x))) then
      if (any(is_set(x))) then
        call deck_error(ctx, name, "needs two values (x, y), got one", error)
      else
        call deck_error(ctx, name, "missing (required variable: two values x, y)", error)
      end if
      return
    end if
    if (.not. all(ieee_is_finite(x))) call deck_error(ctx, name, "must be finite numbers", error)
  end subroutine require_pair

  !> The internal index of a link id among `ids(0:)` (frame allowed when `allow_frame`).
  subroutine find_link(ctx, name, id_in, ids, allow_frame, index, error)
    type(deck_context_t), intent(in) :: ctx
    character(*), intent(in) :: name
    !> Link number as given (an integer deck variable, read as a real).
    real(wp), intent(in) :: id_in
    integer, intent(in) :: ids(0:)
    logical, intent(in) :: allow_frame
    integer, intent(out) :: index
    type(error_t), allocatable, intent(out) :: error
    integer :: i, id
    index = -1
    if (.not. is_set(id_in)) then
      call deck_error(ctx, name, "missing (required link number)", error)
      return
    end if
    call require_whole(ctx, name, id_in, 0, huge(1), id, error); if (allocated(error)) return
    do i = 0, ubound(ids, 1)
      if (ids(i) == id) index = i
    end do
    if (index < 0 .or. (index == 0 .and. .not. allow_frame)) then
      if (allow_frame) then
        call deck_error(ctx, name, "link "//int_str(id)//" is not the frame, the crank or a link "// &
          "of an earlier dyad (a dyad may only hang on links defined before it)", error)
      else
        call deck_error(ctx, name, "link "//int_str(id)//" is not a moving link (crank or dyad link)", error)
      end if
    end if
  end subroutine find_link

  !> The internal index of a moving link (crank or dyad link) among `ids(0:)`.
  subroutine moving_link(ctx, name, id, ids, index, error)
    type(deck_context_t), intent(in) :: ctx
    character(*), intent(in) :: name
    !> Link number as given (an integer deck variable, read as a real).
    real(wp), intent(in) :: id
    integer, intent(in) :: ids(0:)
    integer, intent(out) :: index
    type(error_t), allocatable, intent(out) :: error
    call find_link(ctx, name, id, ids, .false., index, error)
  end subroutine moving_link

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
    p = "dyad("//int_str(d)//")%"
    call require_rule(ctx, p//"kind", is_whole_in(dy%kind, 1, 5), "must be 1..5 "// &
      "(1 RRR, 2 RRP, 3 RPR, 4 PRP, 5 RPP), got "//number_str(dy%kind), error)
    if (allocated(error)) return
    kind = nint(dy%kind)
    kn = " (kind "//kind_names(kind)//")"
    p1 = kind == kind_prp
    p3 = kind == kind_rrp .or. kind == kind_prp .or. kind == kind_rpp
    ! link ids: new and distinct
    call require_rule(ctx, p//"link2", is_set(dy%link2), "missing (required link number)", error)
    if (allocated(error)) return
    call require_rule(ctx, p//"link3", is_set(dy%link3), "missing (required link number)", error)
    if (allocated(error)) return
    call require_whole(ctx, p//"link2", dy%link2, 0, huge(1), link2, error); if (allocated(error)) return
    call require_whole(ctx, p//"link3", dy%link3, 0, huge(1), link3, error); if (allocated(error)) return
    call require_rule(ctx, p//"link2", all(ids /= link2), "link number "// &
      int_str(link2)//" must be >= 0 and not used by the frame, the crank or an earlier dyad", error)
    if (allocated(error)) return
    call require_rule(ctx, p//"link3", all(ids /= link3) .and. link3 /= link2, &
      "link number "//int_str(link3)//" must be >= 0, differ from link2 and not be used before", error)
    if (allocated(error)) return
    call find_link(ctx, p//"on2", dy%on2, ids, .true., out%on(1), error); if (allocated(error)) return
    call find_link(ctx, p//"on3", dy%on3, ids, .true., out%on(2), error); if (allocated(error)) return
    call require_pair(ctx, p//"at2", dy%at2, error); if (allocated(error)) return
    call require_pair(ctx, p//"at3", dy%at3, error); if (allocated(error)) return
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
      call require_positive(ctx, p//"l2", dy%l2, error); if (allocated(error)) return
      call require_positive(ctx, p//"l3", dy%l3, error); if (allocated(error)) return
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
      call optional_pair(ctx, p//"slot_at", dy%slot_at, error); if (allocated(error)) return
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
    call require_nonnegative(ctx, p//"m2", dy%m2, error); if (allocated(error)) return
    dy%j2 = optional_default(dy%j2, 0.0_wp)
    call require_nonnegative(ctx, p//"j2", dy%j2, error); if (allocated(error)) return
    dy%m3 = optional_default(dy%m3, 0.0_wp)
    call require_nonnegative(ctx, p//"m3", dy%m3, error); if (allocated(error)) return
    dy%j3 = optional_default(dy%j3, 0.0_wp)
    call require_nonnegative(ctx, p//"j3", dy%j3, error); if (allocated(error)) return
    call optional_pair(ctx, p//"s2", dy%s2, error); if (allocated(error)) return
    call optional_pair(ctx, p//"s3", dy%s3, error); if (allocated(error)) return
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

  !> Reject a variable that the dyad's kind does not use.
  pure subroutine used_only_if(ctx, name, given, used, kind_note, error)
    type(deck_context_t), intent(in) :: ctx
    character(*), intent(in) :: name, kind_note
    logical, intent(in) :: given, used
    type(error_t), allocatable, intent(out) :: error
    if (given .and. .not. used) call deck_error(ctx, name, "not used by this dyad"//kind_note// &
      ": remove it", error)
  end subroutine used_only_if

  !> Per-step values of a load from its schedule (constant, window, or a step_values column).
  subroutine read_schedule(ctx, name, s, phi1_deg, step_values, values, error)
    type(deck_context_t), intent(in) :: ctx
    !> Prefix, e.g. "force(1)%".
    character(*), intent(in) :: name
    type(schedule_in_t), intent(inout) :: s
    real(wp), intent(in) :: phi1_deg(:)
    real(wp), intent(in) :: step_values(:)
    real(wp), intent(out) :: values(:)
    type(error_t), allocatable, intent(out) :: error
    integer :: n, column
    n = size(phi1_deg)
    values = 0.0_wp
    if (is_set(s%column)) then
      call require_rule(ctx, name//"column", .not. any(is_set([s%value, s%idle, s%phi_on, s%phi_off])), &
        "give either column (per-step values) or value [idle, phi_on, phi_off], not both", error)
      if (allocated(error)) return
      call require_whole(ctx, name//"column", s%column, 1, max_deck_array, column, error)
      if (allocated(error)) return
      ! column*n in real arithmetic: both may be up to a million
      call require_rule(ctx, name//"column", real(column, wp) * real(n, wp) <= real(size(step_values), wp), &
        "step_values has "//int_str(size(step_values))//" values; column "//int_str(column)//" needs "// &
        number_str(real(column, wp) * real(n, wp))//" (n = "//int_str(n)//" per column)", error)
      if (allocated(error)) return
      values = step_values((column - 1) * n + 1:column * n)
      return
    end if
    call require_set(ctx, name//"value", s%value, error); if (allocated(error)) return
    if (is_set(s%phi_on) .or. is_set(s%phi_off)) then
      call require_set(ctx, name//"phi_on", s%phi_on, error); if (allocated(error)) return
      call require_set(ctx, name//"phi_off", s%phi_off, error); if (allocated(error)) return
      call require_rule(ctx, name//"phi_off", s%phi_off >= s%phi_on, "must be >= phi_on ("// &
        real_str(s%phi_on)//"), got "//real_str(s%phi_off), error)
      if (allocated(error)) return
      s%idle = optional_default(s%idle, 0.0_wp)
      call require_set(ctx, name//"idle", s%idle, error); if (allocated(error)) return
      values = assur_window(phi1_deg, s%phi_on, s%phi_off, s%value, s%idle)
    else
      call require_rule(ctx, name//"idle", .not. is_set(s%idle), "only used with phi_on, phi_off", error)
      if (allocated(error)) return
      values = s%value
    end if
  end subroutine read_schedule

end module kinetostat_assur_deck
