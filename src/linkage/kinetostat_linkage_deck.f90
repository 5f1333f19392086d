!> `&linkage` decks (any planar linkage of lower pairs): reading, validation, template.
!>
!> Links by their numbers with masses; pairs R/P between two links (0 = the frame) at a
!> joint given in global coordinates at the reference position (the position the deck's
!> points describe, which also fixes the assembly branch); drives on pairs with an angle or
!> stroke law; forces, moments, gravity. Integer variables are read as reals and must be
!> whole numbers.
module kinetostat_linkage_deck
  use kinetostat_kinds, only: wp, g_default, deg_to_rad, rad_to_deg
  use kinetostat_error, only: error_t
  use kinetostat_text, only: int_str, lower, is_name, real_str
  use kinetostat_deck, only: values_out_of_memory, longest_quoted, begin_group, max_deck_array, &
    deck_context_t, unset_bits, deck_source_t, namelist_probe_t, &
    deck_error, is_set, require_set, require_nonnegative, require_rule, require_per_step, optional_default, count_values, &
    require_whole, deck_array_capacities, require_chars, title_chars, text_bytes, text_chars, &
    deck_rules_t, rule_finite
  use kinetostat_vec2, only: unit_at, magnitude
  use kinetostat_linkage, only: linkage_t, pair_r, pair_p, linkage_work_t, linkage_reference_pose, linkage_assemble, &
    point_position
  use kinetostat_linkage_structure, only: analyse_structure
  use kinetostat_dynamics, only: dynamics_steady
  use kinetostat_load_table, only: max_table_points, read_table_points, table_interpolate, table_cyclic
  use kinetostat_dynamics_deck, only: dynamics_deck_t, read_dynamics_settings, md_table_capacity
  implicit none
  private
  public :: linkage_deck_t, linkage_schedule_t, read_linkage_deck, linkage_template
  public :: linkage_drive_values, linkage_load_value, linkage_schedule_at, linkage_table_position

  !> Capacities of the lists.
  integer, parameter :: max_links = 48, max_pairs = 72, max_drives = 8, max_forces = 32, max_moments = 32
  !> Capacity of a drive's list of values.
  integer, parameter :: max_list = 14401
  !> A load window's ends are taken this much wider (the drive's unit: deg or m), so that a
  !> step landing on an end by roundoff of start + (k-1)*step counts as inside.
  real(wp), parameter :: window_tol = 1.0e-9_wp
  !> Longest joint name, characters.
  integer, parameter :: name_chars = 8
  !> Largest number of steps.
  integer, parameter :: max_steps = 1000000
  character(*), parameter :: group_name = "linkage"
  !> `unset_real` for the deck types' default initialisation (declared here: a NaN constant
  !> loses its payload in .mod files).
  real(wp), parameter :: unset = transfer(unset_bits, 1.0_wp)

  !> A link as written.
  type :: link_in_t
    !> Link number (whole).
    real(wp) :: id = unset
    !> Mass (kg), moment of inertia about S (kg*m^2), centre of mass (global at the reference
    !> position, m; default the link's first joint).
    real(wp) :: m = unset, j = unset, s(2) = unset
  end type link_in_t

  !> A pair as written.
  type :: pair_in_t
    !> Joint name ("A"; default J<k>; at most name_chars characters: the variable is longer
    !> so that a longer text is reported, not cut by the namelist read).
    character(len=text_bytes * text_chars) :: name = ""
    !> 'R' (turning) or 'P' (sliding).
    character(len=text_bytes * text_chars) :: kind = ""
    !> The two links: F<links(1)><links(2)> is the force on the first from the second.
    real(wp) :: links(2) = unset
    !> The joint at the reference position (P: a point of the guide where the block is), m.
    real(wp) :: at(2) = unset
    !> P: direction of the guide at the reference position, deg.
    real(wp) :: angle = unset
    !> P: the link carrying the guide (default links(2)).
    real(wp) :: guide = unset
    !> Friction: coefficient, journal radius (R, m), the guide's and the block's lengths (P, m).
    real(wp) :: f = unset, r = unset, guide_length = unset, block_length = unset
  end type pair_in_t

  !> A drive as written.
  type :: drive_in_t
    !> The driven pair's name: R turns links(1) against links(2), P slides the block.
    character(len=text_bytes * text_chars) :: pair = ""
    !> Law start + (k-1)*step (deg for R, m for P, stroke from the reference position) ...
    real(wp) :: start = unset, step = unset
    !> ... or a list of values, one per step.
    real(wp) :: values(max_list) = unset
    !> Constant speed (rad/s or m/s) and acceleration (rad/s^2 or m/s^2, default 0) ...
    real(wp) :: omega = unset, eps = unset
    !> ... or the columns of step_values holding them step by step.
    real(wp) :: omega_column = unset, eps_column = unset
  end type drive_in_t

  !> A force as written.
  type :: force_in_t
    !> Loaded link, point (global at the reference position, m), direction (deg, global at
    !> the reference position), value (N).
    real(wp) :: link = unset, at(2) = unset, angle = unset, value = unset
    !> Value outside the window [phi_on, phi_off] of the first drive (its unit), default 0.
    real(wp) :: idle = unset, phi_on = unset, phi_off = unset
    !> Column of step_values holding the value of each step instead.
    real(wp) :: column = unset
    !> Or the value over a position: pairs (position, value), N.
    real(wp) :: table(2 * max_table_points) = unset
    !> The link whose position is the table's abscissa (default: the first drive's coordinate).
    real(wp) :: over = unset
    !> The direction turns with the link.
    logical :: follow = .false.
  end type force_in_t

  !> A moment as written.
  type :: moment_in_t
    !> Loaded link, value (N*m, counter-clockwise), window and column as for forces.
    real(wp) :: link = unset, value = unset, idle = unset, phi_on = unset, phi_off = unset, column = unset
    !> Or the value over a position, pairs (position, value), N*m, and its abscissa as for forces.
    real(wp) :: table(2 * max_table_points) = unset, over = unset
  end type moment_in_t

  !> How a load gets its value at a step.
  type :: linkage_schedule_t
    !> Value (inside the window), N or N*m.
    real(wp) :: value = 0.0_wp
    !> Value outside the window.
    real(wp) :: idle = 0.0_wp
    !> Window of the first drive's value (deck units); inactive when on > off.
    real(wp) :: phi_on = 1.0_wp, phi_off = 0.0_wp
    !> Whether a window is given.
    logical :: window = .false.
    !> Column of step_values (0: none).
    integer :: column = 0
    !> Whether the value is a table over the first drive's coordinate.
    logical :: table = .false.
    !> Table: its points' positions (the first drive's unit: deg or m) and values.
    real(wp), allocatable :: x(:), v(:)
    !> Table: the period of the abscissa, deg (360, or 720 for a table over more than a turn:
    !> a four-stroke cycle); 0 for a stroke (no period).
    real(wp) :: period = 0.0_wp
    !> Table over a link's position: the link (0: over the first drive's coordinate), and the
    !> sliding pair with the frame whose stroke is its position (0: its angle).
    integer :: link = 0, pair = 0
  end type linkage_schedule_t

  !> A validated `&linkage` deck.
  type :: linkage_deck_t
    !> The linkage (with its structural analysis).
    type(linkage_t) :: mech
    !> Title (at most title_chars characters).
    character(len=text_bytes * title_chars) :: title = ""
    !> Number of steps.
    integer :: n = 0
    !> Gravity, m/s^2, and its direction, deg.
    real(wp) :: g = g_default, gravity_angle = -90.0_wp
    !> Drives: start, step (deck units: deg or m), constant speed and acceleration (rad/s,
    !> rad/s^2 or m/s, m/s^2).
    real(wp), allocatable :: start(:), step(:), omega(:), eps(:)
    !> Drives given as lists: values(k, d), deck units.
    real(wp), allocatable :: values(:, :)
    !> Whether drive d is a list.
    logical, allocatable :: listed(:)
    !> Columns of step_values with each step's speed and acceleration of drive d (0: the
    !> constant omega, eps).
    integer, allocatable :: omega_column(:), eps_column(:)
    !> Loads' schedules.
    type(linkage_schedule_t), allocatable :: force_load(:), moment_load(:)
    !> The per-step load columns (n x columns).
    real(wp), allocatable :: step_values(:)
    !> The deck's link numbers of the forces' and moments' links, pair names of the drives.
    character(len=16), allocatable :: drive_pair(:)
    !> The machine dynamics settings (dynamics = 'none' unless given).
    type(dynamics_deck_t) :: dyn
    !> Friction of every pair: coefficient, journal radius (m), contact span (m; 0: the
    !> resultant-normal model); whether any pair has friction.
    real(wp), allocatable :: friction_f(:), friction_r(:), friction_span(:)
    logical :: friction_on = .false.
  end type linkage_deck_t

  !> The commented template deck (a crank-rocker four-bar).
  character(*), parameter :: linkage_template(*) = [character(len=100) :: &
    "! Any planar linkage of lower pairs (docs/linkage.md). Points are global (x, y) at the", &
    "! reference position, which also fixes the assembly branch. F<i><j>: force on link i from j.", &
    "&linkage", &
    "  title = 'crank-rocker four-bar'", &
    "  frame = 0                          ! link number of the frame", &
    "  g = 9.81, gravity_angle = -90      ! m/s^2, deg", &
    "  n = 25                             ! steps", &
    "  link(1)%id = 1, link(1)%m = 0.5, link(1)%j = 0.002, link(1)%s = 0.05, 0", &
    "  link(2)%id = 2, link(2)%m = 1.0, link(2)%j = 0.0102, link(2)%s = 0.27, 0.1", &
    "  link(3)%id = 3, link(3)%m = 0.8, link(3)%j = 0.0042, link(3)%s = 0.35, 0.1", &
    "  ! pairs: name, kind 'R' or 'P' (then angle = guide direction, deg), links (on, from), joint", &
    "  pair(1)%name = 'A', pair(1)%kind = 'R', pair(1)%links = 1, 0, pair(1)%at = 0, 0", &
    "  pair(2)%name = 'B', pair(2)%kind = 'R', pair(2)%links = 2, 1, pair(2)%at = 0.1, 0", &
    "  pair(3)%name = 'C', pair(3)%kind = 'R', pair(3)%links = 3, 2, pair(3)%at = 0.4, 0.2", &
    "  pair(4)%name = 'D', pair(4)%kind = 'R', pair(4)%links = 3, 0, pair(4)%at = 0.3, 0", &
    "  ! drives: angle law (deg) start + (k-1)*step or values(:); omega rad/s, eps rad/s^2", &
    "  drive(1)%pair = 'A', drive(1)%start = 0, drive(1)%step = 15, drive(1)%omega = 20", &
    "  force(1)%link = 2, force(1)%at = 0.25, 0.1, force(1)%angle = -90, force(1)%value = 50", &
    "  moment(1)%link = 3, moment(1)%value = -20", &
    "  ! machine dynamics (docs/dynamics.md): omega is then the mean speed; the flywheel for delta", &
    "  ! dynamics = 'steady', delta = 0.05, j_rotor = 0", &
    "  ! a load over the first drive's angle (a gas force from an indicator diagram, docs/assur.md):", &
    "  ! pairs (deg, N), linear between them; over 720 deg with cycle = 720 for a four-stroke engine", &
    "  ! force(2)%link = 3, force(2)%at = 0.4, 0.2, force(2)%angle = 180", &
    "  ! force(2)%table = 0, 0, 90, 40, 180, 60, 270, 20, 360, 0", &
    "  ! friction in a pair (docs/friction.md): coefficient, journal radius (m) of a turning pair", &
    "  ! pair(1)%f = 0.1, pair(1)%r = 0.01", &
        "/"]

contains

  !> Read and validate a `&linkage` deck, with its structural analysis.
  subroutine read_linkage_deck(source, deck, error)
    !> The deck, read into memory.
    type(deck_source_t), intent(in) :: source
    !> The validated deck.
    type(linkage_deck_t), intent(out) :: deck
    type(error_t), allocatable, intent(out) :: error
    call read_linkage_group(source, longest_quoted(source), deck, error)
  end subroutine read_linkage_deck

  !> Read and validate a `&linkage` deck whose longest quoted text has `text_length`
  !> characters (the length of the texts read: a longer text is reported, not cut).
  subroutine read_linkage_group(source, text_length, deck, error)
    !> The deck, read into memory.
    type(deck_source_t), intent(in) :: source
    !> Length of the texts read (characters, >= 1).
    integer, intent(in) :: text_length
    !> The validated deck.
    type(linkage_deck_t), intent(out) :: deck
    type(error_t), allocatable, intent(out) :: error
    !> Allocated, not automatic: a text of 10^5 characters and more would overflow the stack.
    character(len=text_length), allocatable :: title
    real(wp) :: frame, g, gravity_angle, n
    real(wp), allocatable :: step_values(:)
    type(link_in_t) :: link(max_links)
    type(pair_in_t) :: pair(max_pairs)
    type(drive_in_t), allocatable :: drive(:)
    !> Allocated, not automatic: their tables hold max_table_points points each.
    type(force_in_t), allocatable :: force(:)
    type(moment_in_t), allocatable :: moment(:)
    integer, allocatable :: capacity(:), ids(:)
    integer :: stat
    type(deck_context_t) :: ctx
    type(namelist_probe_t) :: probe
    type(deck_rules_t) :: rules
    character(len=:), allocatable :: p
    integer :: nl, np, nd, nf, nm, k, i, id, a, b, count, nsteps, n_values, frame_no, cols
    real(wp) :: d
    !> Machine dynamics variables (see kinetostat_dynamics_deck): the mode, delta, the rotor
    !> and the flywheel (kg*m^2; kg with a sliding drive), the cycle (deg), the driving-moment
    !> table (pairs deg, N*m), the flywheel's disc (density kg/m^3, width over diameter).
    character(len=text_bytes * 16) :: dynamics
    real(wp) :: delta, j_rotor, j_flywheel, cycle, md_table(md_table_capacity), flywheel_density, flywheel_width_ratio
    namelist /linkage/ title, frame, g, gravity_angle, n, link, pair, drive, force, moment, step_values, &
      dynamics, delta, j_rotor, j_flywheel, cycle, md_table, flywheel_density, flywheel_width_ratio

    call begin_group(source, group_name, ctx, error, rules)
    if (allocated(error)) return
    allocate (title)
    title = ""
    frame = 0.0_wp; g = unset; gravity_angle = unset; n = unset
    dynamics = ""; delta = unset; j_rotor = unset; j_flywheel = unset; cycle = unset; md_table = unset
    flywheel_density = unset; flywheel_width_ratio = unset
    allocate (drive(max_drives), force(max_forces), moment(max_moments))
    capacity = deck_array_capacities(source, ctx%group, [character(len=11) :: "step_values"])
    allocate (step_values(capacity(1)), source=unset, stat=stat)
    if (stat /= 0) then
      call values_out_of_memory(ctx, "step_values", capacity, error)
      return
    end if
    call probe%limit("link", max_links, "links")
    call probe%limit("pair", max_pairs, "pairs")
    call probe%limit("drive", max_drives, "drives")
    call probe%limit("force", max_forces, "forces")
    call probe%limit("moment", max_moments, "moments")
    call probe%limit("drive%values", max_list, "values")
    call probe%limit("step_values", max_deck_array, "values")
    call probe%limit("force%table", 2 * max_table_points, "values ("//int_str(max_table_points)//" points)")
    call probe%limit("moment%table", 2 * max_table_points, "values ("//int_str(max_table_points)//" points)")
    read (source%records, nml=linkage, iostat=probe%ios, iomsg=probe%msg)
    do while (probe%retry(source)) ! on failure: find the line and the assignment
      read (probe%records, nml=linkage, iostat=probe%ios, iomsg=probe%msg)
    end do
    if (probe%failed(source, ctx, error)) return
    call rules%require_chars("title", title, title_chars)
    call rules%require_whole("frame", frame, 0, huge(1), frame_no)
    deck%g = optional_default(g, g_default)
    call rules%require_nonnegative("g", deck%g)
    deck%gravity_angle = optional_default(gravity_angle, -90.0_wp)
    call rules%require_set("gravity_angle", deck%gravity_angle)
    if (rules%failed(error)) return
    deck%title = title
    deck%mech%frame_id = frame_no
    deck%mech%gravity = deck%g * unit_at(deck%gravity_angle * deg_to_rad)

    ! ---- links
    nl = leading(is_set(link%id))
    call rules%require_rule("link", nl >= 1, "at least one moving link is required (link(1)%id missing)")
    if (rules%failed(error)) return
    do k = nl + 1, max_links
      if (is_set(link(k)%m) .or. is_set(link(k)%j) .or. any(is_set(link(k)%s))) then
        call deck_error(ctx, "link("//int_str(k)//")", "links must be numbered 1.."//int_str(nl + 1)// &
          " without gaps (link("//int_str(nl + 1)//")%id is missing)", error)
        return
      end if
    end do
    allocate (deck%mech%links(nl), ids(nl))
    do k = 1, nl
      p = "link("//int_str(k)//")%"
      call rules%require_whole(p//"id", link(k)%id, 0, huge(1), id)
      call rules%require_rule(p//"id", id /= frame_no .and. .not. any(ids(1:k - 1) == id), &
        "must differ from frame and from the other links (got "//int_str(id)//")")
      ids(k) = id
      deck%mech%links(k)%id = id
      deck%mech%links(k)%m = optional_default(link(k)%m, 0.0_wp)
      call rules%require_nonnegative(p//"m", deck%mech%links(k)%m)
      deck%mech%links(k)%j = optional_default(link(k)%j, 0.0_wp)
      call rules%require_nonnegative(p//"j", deck%mech%links(k)%j)
      if (rules%failed(error)) return
    end do

    ! ---- pairs
    np = leading(pair%kind /= "")
    call rules%require_rule("pair", np >= 1, "at least one pair is required (pair(1)%kind missing)")
    if (rules%failed(error)) return
    do k = np + 1, max_pairs
      if (any(is_set(pair(k)%links)) .or. any(is_set(pair(k)%at)) .or. len_trim(pair(k)%name) > 0) then
        call deck_error(ctx, "pair("//int_str(k)//")", "pairs must be numbered 1.."//int_str(np + 1)// &
          " without gaps (pair("//int_str(np + 1)//")%kind is missing)", error)
        return
      end if
    end do
    allocate (deck%mech%pairs(np), deck%friction_f(np), deck%friction_r(np), deck%friction_span(np))
    do k = 1, np
      p = "pair("//int_str(k)//")%"
      associate (pr => deck%mech%pairs(k))
        call rules%require_rule(p//"kind", any(lower(trim(pair(k)%kind)) == ["r", "p"]), &
          "must be 'R' (turning) or 'P' (sliding), got '"//trim(pair(k)%kind)//"'")
        if (rules%failed(error)) return
        pr%kind = merge(pair_r, pair_p, lower(trim(pair(k)%kind)) == "r")
        call read_friction(p, pair(k), pr%kind, deck%friction_f(k), deck%friction_r(k), deck%friction_span(k), error)
        if (allocated(error)) return
        call rules%require_chars(p//"name", pair(k)%name, name_chars)
        ! (the name may start with a digit: its columns x_<name> start with a letter)
        call rules%require_rule(p//"name", is_name("x"//trim(pair(k)%name)), &
          "letters (Latin or Cyrillic), digits and _ only (it names the columns x_<name>), got '"// &
          trim(pair(k)%name)//"'")
        if (rules%failed(error)) return
        pr%name = pair(k)%name(1:len(pr%name))
        if (len_trim(pr%name) == 0) pr%name = "J"//int_str(k)
        do i = 1, k - 1
          call rules%require_rule(p//"name", deck%mech%pairs(i)%name /= pr%name, "'"//trim(pr%name)// &
            "' names pair "//int_str(i)//" already")
        end do
        if (rules%failed(error)) return
        call link_index(p//"links(1)", pair(k)%links(1), a, error); if (allocated(error)) return
        call link_index(p//"links(2)", pair(k)%links(2), b, error); if (allocated(error)) return
        call rules%require_rule(p//"links", a /= b, "the two links must differ")
        pr%a = a; pr%b = b
        call rules%require_set(p//"at(1)", pair(k)%at(1))
        call rules%require_set(p//"at(2)", pair(k)%at(2))
        pr%at = pair(k)%at
        if (pr%kind == pair_p) then
          call rules%require_set(p//"angle", pair(k)%angle)
          if (rules%failed(error)) return
          pr%u = unit_at(pair(k)%angle * deg_to_rad)
          pr%guide = b
          if (is_set(pair(k)%guide)) then
            call link_index(p//"guide", pair(k)%guide, i, error); if (allocated(error)) return
            call rules%require_rule(p//"guide", i == a .or. i == b, "must be one of the pair's links")
            pr%guide = i
          end if
        else
          call rules%require_rule(p//"angle", .not. is_set(pair(k)%angle) .and. .not. is_set(pair(k)%guide), &
            "only for sliding pairs (kind = 'P')")
        end if
        if (rules%failed(error)) return
      end associate
    end do
    ! every link's reference point: its first pair's joint; the size of the linkage
    deck%mech%size = 0.0_wp
    do k = 1, np
      do i = 1, np
        deck%mech%size = max(deck%mech%size, magnitude(deck%mech%pairs(k)%at - deck%mech%pairs(i)%at))
      end do
    end do
    if (deck%mech%size <= 0.0_wp) deck%mech%size = 1.0_wp
    do k = 1, nl
      count = 0
      do i = 1, np
        if (deck%mech%pairs(i)%a /= k .and. deck%mech%pairs(i)%b /= k) cycle
        count = count + 1
        if (count == 1) then
          deck%mech%links(k)%c = deck%mech%pairs(i)%at
        else if (count >= 2 .and. deck%mech%links(k)%angle0 == 0.0_wp) then
          d = magnitude(deck%mech%pairs(i)%at - deck%mech%links(k)%c)
          if (d > 0.0_wp) deck%mech%links(k)%angle0 = atan2(deck%mech%pairs(i)%at(2) - deck%mech%links(k)%c(2), &
                                                           deck%mech%pairs(i)%at(1) - deck%mech%links(k)%c(1))
        end if
      end do
      call rules%require_rule("link("//int_str(k)//")%id", count >= 1, "link "//int_str(ids(k))//" is in no pair")
      if (any(is_set(link(k)%s))) then
        call rules%require_set("link("//int_str(k)//")%s(1)", link(k)%s(1))
        call rules%require_set("link("//int_str(k)//")%s(2)", link(k)%s(2))
        deck%mech%links(k)%s = link(k)%s
      else
        deck%mech%links(k)%s = deck%mech%links(k)%c
      end if
      if (rules%failed(error)) return
    end do

    ! ---- steps and drives
    nd = leading(len_trim(drive%pair) > 0)
    call rules%require_rule("drive", nd >= 1, "at least one drive is required (drive(1)%pair missing)")
    if (rules%failed(error)) return
    allocate (deck%mech%drives(nd), deck%start(nd), deck%step(nd), deck%omega(nd), deck%eps(nd), deck%listed(nd))
    allocate (deck%drive_pair(nd))
    nsteps = 0
    if (is_set(n)) call rules%require_whole("n", n, 1, max_steps, nsteps)
    if (rules%failed(error)) return
    do k = 1, nd
      p = "drive("//int_str(k)//")%"
      i = 0
      do a = 1, np
        if (deck%mech%pairs(a)%name == trim(drive(k)%pair)) i = a
      end do
      call rules%require_rule(p//"pair", i > 0, "no pair is named '"//trim(drive(k)%pair)//"'")
      call rules%require_rule(p//"pair", .not. any(deck%mech%drives(1:k - 1)%pair == i), &
        "pair '"//trim(drive(k)%pair)//"' is driven already")
      deck%mech%drives(k)%pair = i
      deck%drive_pair(k) = drive(k)%pair(1:len(deck%drive_pair))
      call rules%count_values(p//"values", drive(k)%values, count)
      deck%listed(k) = count > 0
      if (count > 0) then
        call rules%require_rule(p//"start", .not. is_set(drive(k)%start) .and. .not. is_set(drive(k)%step), &
          "give either values(:) or start and step, not both")
        if (nsteps == 0) nsteps = count
        call rules%require_per_step(p//"values", count, nsteps)
      else
        call rules%require_set(p//"start", drive(k)%start)
        call rules%require_set(p//"step", drive(k)%step)
        deck%start(k) = drive(k)%start
        deck%step(k) = drive(k)%step
      end if
      call value_or_column(p, "omega", drive(k)%omega, drive(k)%omega_column, unset, deck%omega(k))
      call value_or_column(p, "eps", drive(k)%eps, drive(k)%eps_column, 0.0_wp, deck%eps(k))
      if (rules%failed(error)) return
      deck%mech%drives(k)%q_ref = reference_value(deck%mech, i)
    end do
    do k = nd + 1, max_drives
      if (is_set(drive(k)%start) .or. is_set(drive(k)%omega) .or. is_set(drive(k)%values(1)) .or. &
          is_set(drive(k)%omega_column)) then
        call deck_error(ctx, "drive("//int_str(k)//")", "drives must be numbered 1.."//int_str(nd + 1)// &
          " without gaps (drive("//int_str(nd + 1)//")%pair is missing)", error)
        return
      end if
    end do
    call require_rule(ctx, "n", nsteps > 0, "missing (required when no drive gives a list of values)", error)
    if (allocated(error)) return
    deck%n = nsteps
    allocate (deck%values(nsteps, nd), source=0.0_wp, stat=stat)
    if (stat /= 0) then
      call values_out_of_memory(ctx, "the drives", [nsteps * nd], error)
      return
    end if
    do k = 1, nd
      if (deck%listed(k)) then
        deck%values(:, k) = drive(k)%values(1:nsteps)
      end if
    end do
    ! a turning pair's drive angles: the driven link's axis is the drive's angle (a drive
    ! between two moving links: the angle of a's axis from b's)
    do k = 1, nd
      associate (pr => deck%mech%pairs(deck%mech%drives(k)%pair))
        if (pr%kind == pair_r .and. pr%b == 0) deck%mech%links(pr%a)%angle0 = deck%mech%drives(k)%q_ref
      end associate
    end do
    do k = 1, nd
      associate (pr => deck%mech%pairs(deck%mech%drives(k)%pair))
        if (pr%kind == pair_r .and. pr%b /= 0) deck%mech%drives(k)%q_ref = deck%mech%drives(k)%q_ref - &
          deck%mech%links(pr%b)%angle0
      end associate
    end do

    ! ---- loads
    call count_values(ctx, "step_values", step_values, n_values, error); if (allocated(error)) return
    cols = n_values / nsteps
    call require_rule(ctx, "step_values", n_values == cols * nsteps, "expected a multiple of "//int_str(nsteps)// &
      " values (n per column), got "//int_str(n_values), error)
    if (allocated(error)) return
    deck%step_values = step_values(1:n_values)
    allocate (deck%omega_column(nd), deck%eps_column(nd), source=0)
    do k = 1, nd
      p = "drive("//int_str(k)//")%"
      call drive_column(p//"omega_column", drive(k)%omega_column, deck%omega_column(k), error)
      if (allocated(error)) return
      call drive_column(p//"eps_column", drive(k)%eps_column, deck%eps_column(k), error)
      if (allocated(error)) return
    end do
    nf = leading(is_set(force%link))
    nm = leading(is_set(moment%link))
    allocate (deck%mech%forces(nf), deck%force_load(nf), deck%mech%moment_link(nm), deck%moment_load(nm))
    do k = 1, nf
      p = "force("//int_str(k)//")%"
      call link_index(p//"link", force(k)%link, i, error, moving=.true.); if (allocated(error)) return
      deck%mech%forces(k)%link = i
      call rules%require_each(rule_finite, [character(len=len(p) + 5) :: p//"at(1)", p//"at(2)", p//"angle"], &
        [force(k)%at, force(k)%angle])
      if (rules%failed(error)) return
      deck%mech%forces(k)%at = force(k)%at
      deck%mech%forces(k)%dir = unit_at(force(k)%angle * deg_to_rad)
      deck%mech%forces(k)%follow = force(k)%follow
      call read_load(p, force(k)%value, force(k)%idle, force(k)%phi_on, force(k)%phi_off, force(k)%column, &
                     force(k)%table, force(k)%over, deck%force_load(k), error)
      if (allocated(error)) return
    end do
    do k = 1, nm
      p = "moment("//int_str(k)//")%"
      call link_index(p//"link", moment(k)%link, i, error, moving=.true.); if (allocated(error)) return
      deck%mech%moment_link(k) = i
      call read_load(p, moment(k)%value, moment(k)%idle, moment(k)%phi_on, moment(k)%phi_off, moment(k)%column, &
                     moment(k)%table, moment(k)%over, deck%moment_load(k), error)
      if (allocated(error)) return
    end do

    deck%friction_on = any(deck%friction_f > 0.0_wp)
    call analyse_structure(deck%mech, ctx%path//": &"//ctx%group, error)
    if (allocated(error)) return
    if (any(deck%force_load%link > 0) .or. any(deck%moment_load%link > 0)) then
      call check_link_tables(error)
      if (allocated(error)) return
    end if
    call read_dynamics(error)
  contains
    !> The machine dynamics (docs/dynamics.md) of a linkage with one drive: reduced to it
    !> (a turning drive: kg*m^2, N*m; a sliding one: kg, N); a steady cycle needs a turning
    !> drive by start and step over the cycle at the constant mean speed omega.
    subroutine read_dynamics(error)
      type(error_t), allocatable, intent(out) :: error
      logical :: wanted, turning
      real(wp) :: span, whole
      !> The checks of what the dynamics asks of the drive, the steps and the loads.
      type(deck_rules_t) :: checks
      checks = deck_rules_t(ctx)
      wanted = len_trim(dynamics) > 0 .and. trim(adjustl(dynamics)) /= "none"
      if (wanted) then
        call checks%require_rule("drive(2)", nd == 1, "the machine dynamics reduces the machine to one input: a "// &
          "linkage of "//int_str(nd)//" drives (W = "//int_str(nd)//") has no single reduced moment of inertia; "// &
          "give one drive")
        turning = deck%mech%pairs(deck%mech%drives(1)%pair)%kind == pair_r
        call checks%require_rule("dynamics", turning .or. trim(adjustl(dynamics)) == "reduced", "a sliding drive's "// &
          "stroke goes out and back with no turn to make a cycle of: only dynamics = 'reduced' (reduced to the "// &
          "stroke: J_red in kg, M_red in N)")
        if (checks%failed(error)) return
      end if
      call read_dynamics_settings(ctx, dynamics, delta, j_rotor, j_flywheel, optional_default(drive(1)%omega, 0.0_wp), &
        deck%dyn, error, md_table=md_table, cycle=cycle, flywheel_density=flywheel_density, &
        flywheel_width_ratio=flywheel_width_ratio)
      if (allocated(error)) return
      if (deck%dyn%mode < dynamics_steady) return
      call checks%require_rule("drive(1)%values", .not. deck%listed(1), "a steady cycle needs the drive's law by "// &
        "start and step over the cycle, not a list of values")
      call checks%require_rule("drive(1)%omega_column", deck%omega_column(1) == 0 .and. deck%eps_column(1) == 0, &
        "a steady cycle finds the speed and acceleration (omega is the mean speed): no columns of them")
      call checks%require_rule("drive(1)%eps", deck%eps(1) == 0.0_wp, "a steady cycle finds the acceleration from "// &
        "the true motion: leave eps out")
      whole = deck%dyn%cycle_deg
      span = real(deck%n - 1, wp) * deck%step(1)
      call checks%require_rule("drive(1)%step", abs(span - whole) <= 1.0e-9_wp * whole, "the steps must cover "// &
        "exactly the cycle ("//int_str(nint(whole))//" deg) with a steady cycle: (n - 1)*step = "//real_str(span)// &
        " deg, not "//int_str(nint(whole)))
      call checks%require_rule("cycle", whole > 360.0_wp .or. .not. (any(deck%force_load%period > 360.0_wp) .or. &
        any(deck%moment_load%period > 360.0_wp)), "a load table spans more than 360 deg (a four-stroke "// &
        "cycle): give cycle = 720 (the engine's cycle of two turns) and steps over 720 deg")
      call checks%require_rule("step_values", .not. (any(deck%force_load%column > 0) .or. &
        any(deck%moment_load%column > 0)), "a steady cycle needs every load at any drive angle: give it as a "// &
        "constant or a window, not per step")
      call checks%take(error)
    end subroutine read_dynamics
    !> Every step's position of the links that tables are over lies inside the table (the
    !> poses by the run's continuation; a step that does not assemble is left to the run).
    subroutine check_link_tables(err)
      type(error_t), allocatable, intent(out) :: err
      type(error_t), allocatable :: pose_error
      type(linkage_work_t) :: work
      type(linkage_schedule_t) :: sched
      real(wp) :: q(3 * nl), dq(nd), dv(nd), da(nd), from(nd), x
      integer :: kk, jj
      q = linkage_reference_pose(deck%mech)
      do jj = 1, nd
        from(jj) = deck%mech%drives(jj)%q_ref
      end do
      do kk = 1, deck%n
        call linkage_drive_values(deck, kk, dq, dv, da)
        call linkage_assemble(deck%mech, from, dq, q, work, pose_error)
        if (allocated(pose_error)) return
        from = dq
        do jj = 1, nf + nm
          sched = merge_schedule(jj)
          if (sched%link == 0) cycle
          x = table_abscissa(sched, linkage_table_position(deck%mech, sched, q))
          if (x < sched%x(1) - edge(sched) .or. x > sched%x(size(sched%x)) + edge(sched)) then
            call deck_error(ctx, trim(merge("force( ", "moment(", jj <= nf))//int_str(merge(jj, jj - nf, jj <= nf))// &
              ")%table", "at step "//int_str(kk)//" link "//int_str(ids(sched%link))//" is at "//real_str(x)// &
              trim(merge(" m  ", " deg", sched%pair > 0))//", outside the table ["//real_str(sched%x(1))//", "// &
              real_str(sched%x(size(sched%x)))//"]"//trim(merge(" m  ", " deg", sched%pair > 0)), err)
            return
          end if
        end do
      end do
    end subroutine check_link_tables
    !> Load jj: the forces, then the moments.
    pure function merge_schedule(jj) result(sched)
      integer, intent(in) :: jj
      type(linkage_schedule_t) :: sched
      if (jj <= nf) then
        sched = deck%force_load(jj)
      else
        sched = deck%moment_load(jj - nf)
      end if
    end function merge_schedule
    !> The range check's tolerance of a table.
    pure real(wp) function edge(sched)
      type(linkage_schedule_t), intent(in) :: sched
      edge = 1.0e-9_wp * max(sched%x(size(sched%x)) - sched%x(1), abs(sched%x(1)), abs(sched%x(size(sched%x))), &
        1.0e-300_wp)
    end function edge
    !> A pair's friction (docs/friction.md): f >= 0 (default 0); a turning pair's journal
    !> radius r (> 0 when f > 0); a sliding pair's guide and block lengths (> 0 when given;
    !> the contact span is the shorter); a variable the pair's kind does not use is refused.
    subroutine read_friction(pfx, pin, kind, f, r, span, err)
      character(*), intent(in) :: pfx
      type(pair_in_t), intent(in) :: pin
      integer, intent(in) :: kind
      real(wp), intent(out) :: f, r, span
      type(error_t), allocatable, intent(out) :: err
      f = optional_default(pin%f, 0.0_wp)
      call require_nonnegative(ctx, pfx//"f", f, err); if (allocated(err)) return
      r = 0.0_wp
      span = 0.0_wp
      if (kind == pair_r) then
        call require_rule(ctx, pfx//"guide_length", .not. is_set(pin%guide_length) .and. &
          .not. is_set(pin%block_length), "not used by this pair (a turning pair; lengths are a sliding pair's)", err)
        if (allocated(err)) return
        r = optional_default(pin%r, 0.0_wp)
        call require_nonnegative(ctx, pfx//"r", r, err); if (allocated(err)) return
        call require_rule(ctx, pfx//"r", .not. (f > 0.0_wp .and. .not. r > 0.0_wp), &
          "must be > 0 with friction (f > 0): the journal radius, m", err)
      else
        call require_rule(ctx, pfx//"r", .not. is_set(pin%r), "not used by this pair (a sliding pair has no "// &
          "journal radius)", err)
        if (allocated(err)) return
        if (is_set(pin%guide_length)) then
          call require_rule(ctx, pfx//"guide_length", pin%guide_length > 0.0_wp, "must be > 0 (m)", err)
          if (allocated(err)) return
          span = pin%guide_length
        end if
        if (is_set(pin%block_length)) then
          call require_rule(ctx, pfx//"block_length", pin%block_length > 0.0_wp, "must be > 0 (m)", err)
          if (allocated(err)) return
          span = merge(min(span, pin%block_length), pin%block_length, span > 0.0_wp)
        end if
      end if
    end subroutine read_friction
    !> Number of leading true entries.
    pure integer function leading(given)
      logical, intent(in) :: given(:)
      integer :: kk
      leading = 0
      do kk = 1, size(given)
        if (.not. given(kk)) exit
        leading = kk
      end do
    end function leading
    !> Internal index (0 frame, 1.. moving) of a link number given as a real; with `moving`
    !> true, the frame is refused ("must be a moving link").
    subroutine link_index(name, x, idx, err, moving)
      character(*), intent(in) :: name
      real(wp), intent(in) :: x
      integer, intent(out) :: idx
      type(error_t), allocatable, intent(out) :: err
      logical, intent(in), optional :: moving
      integer :: v, kk
      idx = -1
      call require_whole(ctx, name, x, 0, huge(1), v, err); if (allocated(err)) return
      if (v == frame_no) then
        idx = 0
      else
        do kk = 1, nl
          if (ids(kk) == v) idx = kk
        end do
        call require_rule(ctx, name, idx >= 0, "no link "//int_str(v)//" (links: the frame "//int_str(frame_no)// &
          " and link(:)%id)", err)
      end if
      if (allocated(err) .or. .not. present(moving)) return
      call require_rule(ctx, name, idx > 0 .or. .not. moving, "must be a moving link", err)
    end subroutine link_index
    !> A drive's speed or acceleration `pfx//var`: 0 when a column of step_values gives it
    !> (`var`_column; then `var` must not be given), else the value (or its default), finite.
    subroutine value_or_column(pfx, var, value, column, default, out)
      character(*), intent(in) :: pfx, var
      !> The value and the column as read; the value's default (unset: required).
      real(wp), intent(in) :: value, column, default
      real(wp), intent(out) :: out
      if (is_set(column)) then
        call rules%require_rule(pfx//var, .not. is_set(value), "give either "//var//" or "//var//"_column, not both")
        out = 0.0_wp
      else
        out = optional_default(value, default)
        call rules%require_set(pfx//var, out)
      end if
    end subroutine value_or_column
    !> A drive's column of speeds or accelerations, if given (else 0).
    subroutine drive_column(name, x, column, err)
      character(*), intent(in) :: name
      real(wp), intent(in) :: x
      integer, intent(out) :: column
      type(error_t), allocatable, intent(out) :: err
      column = 0
      if (.not. is_set(x)) return
      call require_whole(ctx, name, x, 1, max(1, cols), column, err); if (allocated(err)) return
      call require_rule(ctx, name, cols >= 1, "step_values holds no column", err)
    end subroutine drive_column
    !> A force's or moment's load: its schedule (read_schedule), or its table over a link's
    !> position (read_load_table).
    subroutine read_load(pfx, value, idle, on, off, column, table, over, sched, err)
      character(*), intent(in) :: pfx
      !> value, idle, phi_on, phi_off, column as read.
      real(wp), intent(in) :: value, idle, on, off, column
      !> The table and its abscissa link as read.
      real(wp), intent(in) :: table(:), over
      type(linkage_schedule_t), intent(out) :: sched
      type(error_t), allocatable, intent(out) :: err
      call read_schedule(pfx, value, idle, on, off, column, is_set(table(1)), sched, err); if (allocated(err)) return
      call read_load_table(pfx, table, over, sched, err)
    end subroutine read_load
    !> A load's schedule: constant value, window, or column.
    subroutine read_schedule(pfx, value, idle, on, off, column, tabled, sched, err)
      character(*), intent(in) :: pfx
      real(wp), intent(in) :: value, idle, on, off, column
      !> Whether a table is given instead (read by read_load_table).
      logical, intent(in) :: tabled
      type(linkage_schedule_t), intent(out) :: sched
      type(error_t), allocatable, intent(out) :: err
      if (tabled) then
        call require_rule(ctx, pfx//"table", .not. any(is_set([value, idle, on, off, column])), &
          "give either table (values over a position) or value [idle, phi_on, phi_off] or column", err)
        return
      end if
      if (is_set(column)) then
        call require_whole(ctx, pfx//"column", column, 1, max(1, cols), sched%column, err); if (allocated(err)) return
        call require_rule(ctx, pfx//"column", cols >= 1, "step_values holds no column", err)
        if (allocated(err)) return
        call require_rule(ctx, pfx//"value", .not. is_set(value), "give either value or column, not both", err)
        return
      end if
      call require_set(ctx, pfx//"value", value, err); if (allocated(err)) return
      sched%value = value
      if (is_set(on) .or. is_set(off)) then
        call require_set(ctx, pfx//"phi_on", on, err); if (allocated(err)) return
        call require_set(ctx, pfx//"phi_off", off, err); if (allocated(err)) return
        sched%window = .true.
        sched%phi_on = on
        sched%phi_off = off
        sched%idle = optional_default(idle, 0.0_wp)
        call require_set(ctx, pfx//"idle", sched%idle, err); if (allocated(err)) return
      else
        call require_rule(ctx, pfx//"idle", .not. is_set(idle), "only with phi_on and phi_off", err)
      end if
    end subroutine read_schedule
    !> A load's table over the first drive's coordinate (`over` omitted, or the link the
    !> first drive turns on the frame): its points, the period of a turning drive's angle
    !> (360 deg, or 720 when the table spans more than a turn), every step inside the table.
    subroutine read_load_table(pfx, table, over, sched, err)
      character(*), intent(in) :: pfx
      !> The table and its abscissa link as read.
      real(wp), intent(in) :: table(:), over
      type(linkage_schedule_t), intent(inout) :: sched
      type(error_t), allocatable, intent(out) :: err
      integer :: kk, np_t, over_link
      real(wp) :: q, tol
      character(len=:), allocatable :: unit
      if (.not. is_set(table(1))) then
        call require_rule(ctx, pfx//"over", .not. is_set(over), "only used with table", err)
        return
      end if
      associate (driven => deck%mech%pairs(deck%mech%drives(1)%pair))
        if (is_set(over)) then
          call link_index(pfx//"over", over, over_link, err, moving=.true.); if (allocated(err)) return
          if (.not. (driven%kind == pair_r .and. driven%b == 0 .and. driven%a == over_link)) then
            ! over another link's position: its angle, or its stroke on a guide of the frame
            sched%table = .true.
            sched%link = over_link
            call read_table_points(ctx, pfx//"table", table, sched%x, sched%v, err); if (allocated(err)) return
            sched%period = 360.0_wp
            do kk = 1, size(deck%mech%pairs)
              associate (pr => deck%mech%pairs(kk))
                if (pr%kind == pair_p .and. min(pr%a, pr%b) == 0 .and. max(pr%a, pr%b) == over_link) then
                  sched%pair = kk
                  sched%period = 0.0_wp
                end if
              end associate
            end do
            return ! every step's position is checked once the poses are known (check_link_tables)
          end if
        end if
        sched%table = .true.
        call read_table_points(ctx, pfx//"table", table, sched%x, sched%v, err); if (allocated(err)) return
        np_t = size(sched%x)
        unit = " m"
        sched%period = 0.0_wp
        if (driven%kind == pair_r) then
          unit = " deg"
          sched%period = merge(720.0_wp, 360.0_wp, sched%x(np_t) - sched%x(1) > 360.0_wp)
        end if
      end associate
      tol = 1.0e-9_wp * max(sched%x(np_t) - sched%x(1), abs(sched%x(1)), abs(sched%x(np_t)), 1.0e-300_wp)
      do kk = 1, nsteps
        q = table_abscissa(sched, first_drive_value(deck, kk))
        if (q < sched%x(1) - tol .or. q > sched%x(np_t) + tol) then
          call deck_error(ctx, pfx//"table", "at step "//int_str(kk)//" drive(1) is at "//real_str(q)//unit// &
            ", outside the table ["//real_str(sched%x(1))//", "//real_str(sched%x(np_t))//"]"//unit, err)
          return
        end if
      end do
    end subroutine read_load_table
  end subroutine read_linkage_group

  !> The first drive's value at step k, its deck unit (deg or m).
  pure real(wp) function first_drive_value(deck, k) result(x)
    type(linkage_deck_t), intent(in) :: deck
    !> Step.
    integer, intent(in) :: k
    if (deck%listed(1)) then
      x = deck%values(k, 1)
    else
      x = deck%start(1) + real(k - 1, wp) * deck%step(1)
    end if
  end function first_drive_value

  !> A table's abscissa when the first drive has the value x (deg or m): a turning drive's
  !> angle taken modulo the table's period into [x1, x1 + period), a stroke as it is.
  pure real(wp) function table_abscissa(sched, x) result(q)
    type(linkage_schedule_t), intent(in) :: sched
    !> The first drive's value, deg or m.
    real(wp), intent(in) :: x
    q = x
    if (sched%period > 0.0_wp) q = table_cyclic(sched%x(1), x, sched%period)
  end function table_abscissa

  !> A drive's value at the reference position: a turning pair's angle of the driven link's
  !> axis (from the joint to the first other joint of that link at another point, else its
  !> centre of mass), rad; a sliding pair's stroke, 0 m.
  pure real(wp) function reference_value(mech, k)
    type(linkage_t), intent(in) :: mech
    integer, intent(in) :: k
    real(wp) :: to(2)
    integer :: i, a
    reference_value = 0.0_wp
    if (mech%pairs(k)%kind == pair_p) return
    a = mech%pairs(k)%a
    to = mech%links(a)%s
    do i = size(mech%pairs), 1, -1
      if (i == k) cycle
      if (mech%pairs(i)%a /= a .and. mech%pairs(i)%b /= a) cycle
      if (magnitude(mech%pairs(i)%at - mech%pairs(k)%at) > 0.0_wp) to = mech%pairs(i)%at
    end do
    if (magnitude(to - mech%pairs(k)%at) > 0.0_wp) then
      reference_value = atan2(to(2) - mech%pairs(k)%at(2), to(1) - mech%pairs(k)%at(1))
    end if
  end function reference_value

  !> The drives' values (rad or m), rates and accelerations at step k.
  pure subroutine linkage_drive_values(deck, k, q, v, a)
    !> Validated deck.
    type(linkage_deck_t), intent(in) :: deck
    !> Step 1..n.
    integer, intent(in) :: k
    !> Values, rates, accelerations (internal units: rad, m).
    real(wp), intent(out) :: q(:), v(:), a(:)
    integer :: d
    real(wp) :: x
    do d = 1, size(deck%mech%drives)
      if (deck%listed(d)) then
        x = deck%values(k, d)
      else
        x = deck%start(d) + real(k - 1, wp) * deck%step(d)
      end if
      if (deck%mech%pairs(deck%mech%drives(d)%pair)%kind == pair_r) then
        q(d) = x * deg_to_rad
      else
        q(d) = x
      end if
      v(d) = deck%omega(d)
      if (deck%omega_column(d) > 0) v(d) = deck%step_values((deck%omega_column(d) - 1) * deck%n + k)
      a(d) = deck%eps(d)
      if (deck%eps_column(d) > 0) a(d) = deck%step_values((deck%eps_column(d) - 1) * deck%n + k)
    end do
  end subroutine linkage_drive_values

  !> A load's value at step k (N or N*m).
  pure real(wp) function linkage_load_value(deck, sched, k, position)
    !> Validated deck.
    type(linkage_deck_t), intent(in) :: deck
    !> The load's schedule.
    type(linkage_schedule_t), intent(in) :: sched
    !> Step.
    integer, intent(in) :: k
    !> A table over a link's position: that position at the step (linkage_table_position).
    real(wp), intent(in), optional :: position
    if (sched%link > 0) then
      linkage_load_value = 0.0_wp
      if (present(position)) linkage_load_value = table_interpolate(sched%x, sched%v, table_abscissa(sched, position))
    else if (sched%column > 0) then
      linkage_load_value = deck%step_values((sched%column - 1) * deck%n + k)
    else if (sched%window .or. sched%table) then
      linkage_load_value = linkage_schedule_at(sched, first_drive_value(deck, k))
    else
      linkage_load_value = sched%value
    end if
  end function linkage_load_value

  !> A load's value when the first drive has the value x (its deck unit: deg or m): a
  !> constant, a window's value or idle, or a table's value (not a step_values column).
  pure real(wp) function linkage_schedule_at(sched, x, position) result(value)
    !> The load's schedule.
    type(linkage_schedule_t), intent(in) :: sched
    !> The first drive's value, deg or m.
    real(wp), intent(in) :: x
    !> A table over a link's position: that position (linkage_table_position).
    real(wp), intent(in), optional :: position
    if (sched%link > 0) then
      value = 0.0_wp
      if (present(position)) value = table_interpolate(sched%x, sched%v, table_abscissa(sched, position))
      return
    end if
    if (sched%table) then
      value = table_interpolate(sched%x, sched%v, table_abscissa(sched, x))
      return
    end if
    value = sched%value
    if (sched%window) value = merge(sched%value, sched%idle, x >= sched%phi_on - window_tol .and. &
                                    x <= sched%phi_off + window_tol)
  end function linkage_schedule_at

  !> The position of a table's link at poses q: its angle (the angle of its axis, deg), or its
  !> stroke along its guide on the frame from the pair's point (m); 0 for a table over the
  !> first drive's coordinate.
  pure real(wp) function linkage_table_position(mech, sched, q) result(x)
    type(linkage_t), intent(in) :: mech
    type(linkage_schedule_t), intent(in) :: sched
    !> Poses.
    real(wp), intent(in) :: q(:)
    x = 0.0_wp
    if (sched%link == 0) return
    if (sched%pair > 0) then
      associate (pr => mech%pairs(sched%pair))
        x = dot_product(point_position(mech, q, sched%link, pr%at) - pr%at, pr%u)
      end associate
    else
      x = (mech%links(sched%link)%angle0 + q(3 * sched%link)) * rad_to_deg
    end if
  end function linkage_table_position

end module kinetostat_linkage_deck
