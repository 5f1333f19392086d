!> `kinetostat convert DECK --to linkage`: a linkage deck translated into the `&linkage`
!> model (kinetostat_convert_model) and written as a `&linkage` deck. `&pr3207` is placed in
!> its own frame with its link numbers (frame 6, the columns F16, F21, ... keep their names);
!> a `&linkage` deck is normalised (every variable in one canonical layout, defaults written
!> out). Comment lines go before what their variable became; a kind the translation does not
!> cover is a one-line refusal naming why.
module kinetostat_convert
  use kinetostat_kinds, only: wp, deg_to_rad, g_default
  use kinetostat_error, only: error_t
  use kinetostat_text, only: int_str, lower
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_deck, only: deck_source_t, read_group_name, unset_bits, deck_line, deck_line_count
  use kinetostat_vec2, only: unit_at, magnitude
  use kinetostat_convert_model, only: linkage_model_t, model_link_t, model_pair_t, model_drive_t, model_load_t, &
    write_linkage_model, add_note, first_variable
  use kinetostat_pr3207_deck, only: pr3207_deck_t, read_pr3207_deck, pr3207_f5c, pr3207_phi1_deg
  use kinetostat_sixbar_deck, only: sixbar_deck_t, read_sixbar_deck, sixbar_phi1_deg
  use kinetostat_sixbar, only: sixbar_position_t, sixbar_position, sixbar_frame2_to_frame1, sixbar_down1
  use kinetostat_pr3050_deck, only: pr3050_deck_t, read_pr3050_deck, pr3050_phi3_deg
  use kinetostat_pr3050, only: pr3050_position_t, pr3050_position
  use kinetostat_assur_deck, only: assur_deck_t, read_assur_deck, assur_phi1_deg, assur_omega1_steps, &
    load_schedule_t, load_window, load_column, load_table, resist_none
  use kinetostat_assur, only: assur_kinematics, link_a, link_b
  use kinetostat_assur_kinematics, only: link_state_t, dyad_pose_t, kind_names
  use kinetostat_linkage_deck, only: linkage_deck_t, read_linkage_deck
  use kinetostat_linkage, only: pair_p
  use kinetostat_dynamics_deck, only: md_table_capacity
  use kinetostat_dynamics, only: dynamics_steady
  use kinetostat_load_table, only: max_table_points
  implicit none
  private
  public :: convert_deck, convert_targets

  !> The models a deck is translated into.
  character(*), parameter :: convert_targets = "linkage"
  !> A load window's ends are matched this much wider (deg), as the `&linkage` reader does.
  real(wp), parameter :: window_tol = 1.0e-9_wp
  real(wp), parameter :: unset = transfer(unset_bits, 1.0_wp)
  !> The raw read's text length and a drive's list capacity (the &linkage reader's).
  integer, parameter :: raw_text = 4096, raw_list = 14401

  !> The `&linkage` namelist's variables as given (read again by raw_linkage: the validated
  !> deck keeps the pairs' and forces' directions as unit vectors only).
  type :: link_in_t
    real(wp) :: id = unset, m = unset, j = unset, s(2) = unset
  end type link_in_t
  type :: pair_in_t
    character(len=raw_text) :: name = "", kind = ""
    real(wp) :: links(2) = unset, at(2) = unset, angle = unset, guide = unset, f = unset, r = unset, &
      guide_length = unset, block_length = unset
  end type pair_in_t
  type :: drive_in_t
    character(len=raw_text) :: pair = ""
    real(wp) :: start = unset, step = unset, values(raw_list) = unset, omega = unset, eps = unset, &
      omega_column = unset, eps_column = unset
  end type drive_in_t
  type :: force_in_t
    real(wp) :: link = unset, at(2) = unset, angle = unset, value = unset, idle = unset, phi_on = unset, &
      phi_off = unset, column = unset, table(2 * max_table_points) = unset, over = unset
    logical :: follow = .false.
  end type force_in_t
  type :: moment_in_t
    real(wp) :: link = unset, value = unset, idle = unset, phi_on = unset, phi_off = unset, column = unset, &
      table(2 * max_table_points) = unset, over = unset
  end type moment_in_t

contains

  !> Translate the deck `source` into the `&linkage` model and write it to `out`.
  subroutine convert_deck(source, out, error)
    type(deck_source_t), intent(in) :: source
    type(text_buffer_t), intent(inout) :: out
    type(error_t), allocatable, intent(out) :: error
    character(len=:), allocatable :: group
    type(linkage_model_t) :: model
    call read_group_name(source, group, error)
    if (allocated(error)) return
    select case (group)
    case ("pr3207")
      call from_pr3207(source, model, error)
    case ("linkage")
      call from_linkage(source, model, error)
    case ("sixbar")
      call from_sixbar(source, model, error)
    case ("pr3050")
      call from_pr3050(source, model, error)
    case ("assur")
      call from_assur(source, model, error)
    case default
      call refuse(source%path//": &"//group//": convert: not a linkage of lower pairs (gears, cams and the "// &
        "design kinds have no &linkage model; the linkage kinds &pr3207, &pr3050, &sixbar, &assur and &linkage translate)")
    end select
    if (allocated(error)) return
    call attach_comments(source, group, model)
    call write_linkage_model(model, out)

  contains

    subroutine refuse(message)
      character(*), intent(in) :: message
      allocate (error)
      error%message = message
    end subroutine refuse
  end subroutine convert_deck

  !> The comment lines of the deck: those before the group go before `&linkage`, those in
  !> the group before the line of the translation their next variable became; comment lines
  !> after the last variable of the group and after it are left out.
  subroutine attach_comments(source, group, model)
    type(deck_source_t), intent(in) :: source
    character(*), intent(in) :: group
    type(linkage_model_t), intent(inout) :: model
    integer :: k, first, i
    character(len=:), allocatable :: line, var
    logical :: inside
    !> The comment lines (their numbers) not yet attached.
    integer, allocatable :: pending(:)
    integer :: npend
    inside = .false.
    allocate (pending(deck_line_count(source)))
    npend = 0
    do k = 1, deck_line_count(source)
      line = deck_line(source, k)
      first = verify(line, " "//achar(9))
      if (first == 0) cycle
      if (line(first:first) == "!") then
        npend = npend + 1
        pending(npend) = k
        cycle
      end if
      if (.not. inside) then
        if (line(first:first) == "&" .or. line(first:first) == "$") then
          do i = 1, npend
            call add_note(model, "", deck_line(source, pending(i)))
          end do
          npend = 0
          inside = .true.
        end if
        cycle
      end if
      if (line(first:first) == "/") exit
      var = first_variable(line)
      if (npend > 0 .and. len(var) > 0) then
        do i = 1, npend
          call add_note(model, target_key(group, var), deck_line(source, pending(i)))
        end do
      end if
      npend = 0
    end do
  end subroutine attach_comments

  !> The line of the translation a variable of a `&group` deck became (its key in the
  !> writer: "link(3)", "force(1)", "dynamics", ...).
  pure function target_key(group, var) result(key)
    character(*), intent(in) :: group, var
    character(len=:), allocatable :: key
    character(len=:), allocatable :: base
    integer :: p
    p = index(var, "(")
    base = var
    if (p > 0) base = var(:p - 1)
    select case (base)
    case ("dynamics", "delta", "j_rotor", "j_flywheel", "cycle")
      key = "dynamics"
      return
    case ("flywheel_density", "flywheel_width_ratio")
      key = "flywheel_density"
      return
    case ("md_table")
      key = "md_table"
      return
    case ("g", "gravity_angle")
      key = "g"
      return
    case default
      ! the kind's own variables below
    end select
    select case (group)
    case ("sixbar")
      select case (base)
      case ("a", "b", "l1", "m1", "j1", "omega1", "start_at_extreme", "phi_start", "dphi", "n")
        key = "drive(1)"
        if (base == "m1" .or. base == "j1") key = "link(1)"
      case ("lam2", "lam_s2", "m2", "j2")
        key = "link(2)"
      case ("lam3", "lam_de", "m3", "j3")
        key = "link(3)"
      case ("lam4", "lam_s4", "m4", "j4")
        key = "link(4)"
      case ("lam_e", "m5")
        key = "link(5)"
      case default
        key = "force(1)"
      end select
    case ("pr3050")
      select case (base)
      case ("l_ca", "m1", "j1", "l_s1a")
        key = "link(1)"
      case ("l_bs2", "m2", "j2")
        key = "link(2)"
      case ("l_cb", "l_cs3", "delta", "m3", "j3")
        key = "link(3)"
      case ("gamma")
        key = "g"
      case default
        key = "drive(1)"
      end select
    case ("assur")
      select case (base)
      case ("frame_id", "crank_id")
        key = "frame"
      case ("crank_at", "crank_m", "crank_j", "crank_s", "coordinates", "phi_ref")
        key = "link(1)"
      case ("crank_joint", "crank_f", "crank_r")
        key = "pair(1)"
      case ("omega1", "omega1_step", "eps1_step", "phi_start", "dphi", "n", "phi1", "start_at", "output_link", &
            "drive_dyad", "drive_pair")
        key = "drive(1)"
      case ("dyad")
        ! a dyad's lines go before its first pair (the crank's pivot is the model's pair 1)
        key = "pair("//int_str(3 * dyad_number(var) - 1)//")"
      case default
        key = var
      end select
    case ("pr3207")
      select case (base)
      case ("l_ab", "m1", "omega1", "phi_start", "dphi", "n")
        key = "drive(1)"
        if (base == "l_ab" .or. base == "m1") key = "link(1)"
      case ("l_ac")
        key = "pair(4)"
      case ("l_cd", "l_cs3", "m3", "j3")
        key = "link(3)"
      case ("m5")
        key = "link(5)"
      case default
        key = "force(1)"
      end select
    case default
      key = var
      if (base == "gravity_angle") key = "g"
    end select

  contains

    !> The d of "dyad(d)" (0 when it does not read).
    pure integer function dyad_number(name)
      character(*), intent(in) :: name
      integer :: ios, a, b
      dyad_number = 0
      a = index(name, "(")
      b = index(name, ")")
      if (a == 0 .or. b <= a + 1) return
      read (name(a + 1:b - 1), *, iostat=ios) dyad_number
      if (ios /= 0) dyad_number = 0
    end function dyad_number
  end function target_key

  !> `&pr3207` in its own frame (origin A, x from A to C, gravity along +x) with its link
  !> numbers: 1 crank AB, 2 block on the lever at B, 3 slotted lever CD, 4 block at D, 5 ram
  !> (along y), frame 6. Points at the first step; the cutting force a window of the crank
  !> angle where one interval covers every step as the deck's [phi_cut_start, phi_cut_end]
  !> (mod 360) does, else a column of step_values.
  subroutine from_pr3207(source, model, error)
    type(deck_source_t), intent(in) :: source
    type(linkage_model_t), intent(out) :: model
    type(error_t), allocatable, intent(out) :: error
    type(pr3207_deck_t) :: deck
    real(wp) :: b(2), c(2), d(2), u(2), on, off
    real(wp), allocatable :: f5c(:), phi(:)
    integer :: k, shift
    logical :: fits
    call read_pr3207_deck(source, deck, error)
    if (allocated(error)) return
    associate (p => deck%p)
      b = p%l_ab * unit_at(deck%phi_start * deg_to_rad)
      c = [p%l_ac, 0.0_wp]
      u = (b - c) / magnitude(b - c)
      d = c + p%l_cd * u
      model%title = "PR 3207 shaper mechanism (linkage form)"
      model%frame = 6
      model%g = p%g
      model%gravity_angle = 0.0_wp
      model%n = deck%n
      model%links = [model_link_t(1, p%m1, 0.0_wp, [0.0_wp, 0.0_wp]), model_link_t(2, 0.0_wp, 0.0_wp, b), &
        model_link_t(3, p%m3, p%j3, c + p%l_cs3 * u), model_link_t(4, 0.0_wp, 0.0_wp, d), &
        model_link_t(5, p%m5, 0.0_wp, [0.0_wp, d(2)])]
      model%pairs = [model_pair_t("A", "R", [1, 6], [0.0_wp, 0.0_wp], 0.0_wp, 0), &
        model_pair_t("B", "R", [2, 1], b, 0.0_wp, 0), &
        model_pair_t("B3", "P", [2, 3], b, atan2(u(2), u(1)) / deg_to_rad, 3), &
        model_pair_t("C", "R", [3, 6], c, 0.0_wp, 0), &
        model_pair_t("D", "R", [3, 4], d, 0.0_wp, 0), &
        model_pair_t("D5", "P", [4, 5], d, 0.0_wp, 5), &
        model_pair_t("E", "P", [5, 6], [0.0_wp, d(2)], 90.0_wp, 6)]
      model%drives = [crank_drive(deck%phi_start, deck%dphi, p%omega1)]
    end associate
    allocate (model%forces(1), model%moments(0))
    model%forces(1) = model_load_t(link=5, at=[0.0_wp, d(2)], angle=90.0_wp)
    allocate (f5c(deck%n), phi(deck%n))
    do k = 1, deck%n
      f5c(k) = pr3207_f5c(deck, k)
      phi(k) = pr3207_phi1_deg(deck, k)
    end do
    fits = .false.
    if (deck%two_value) then
      ! the window [on, off] + 360 shift: the same force at every step?
      do shift = -3, 3
        on = deck%phi_cut_start + 360.0_wp * shift
        off = on + merge(deck%phi_cut_end - deck%phi_cut_start, modulo(deck%phi_cut_end - deck%phi_cut_start, &
          360.0_wp), deck%phi_cut_end - deck%phi_cut_start >= 360.0_wp)
        fits = all(merge(deck%f5c_work, deck%f5c_idle, phi >= on - window_tol .and. phi <= off + window_tol) == f5c)
        if (fits) exit
      end do
    end if
    if (fits) then
      model%forces(1)%value = deck%f5c_work
      model%forces(1)%window = .true.
      model%forces(1)%idle = deck%f5c_idle
      model%forces(1)%phi_on = on
      model%forces(1)%phi_off = off
    else
      model%forces(1)%column = 1
      model%step_values = f5c
    end if
    model%dyn = deck%dyn
  end subroutine from_pr3207

  !> The T.FTN six-bar (`&sixbar`) in its frame 1 (origin A, x1 along AD: the crank angles
  !> are the deck's) with its link numbers: 1 crank AB, 2 rod BC, 3 rocker C-D-E (pivot D),
  !> 4 rod EH, 5 slider at H along x2, frame 6. Points at the first step; the slider load a
  !> column of step_values.
  subroutine from_sixbar(source, model, error)
    type(deck_source_t), intent(in) :: source
    type(linkage_model_t), intent(out) :: model
    type(error_t), allocatable, intent(out) :: error
    type(sixbar_deck_t) :: deck
    type(sixbar_position_t) :: pos
    real(wp) :: h(2), s4(2), x2(2), down(2), guide_deg
    integer :: k
    call read_sixbar_deck(source, deck, error)
    if (allocated(error)) return
    associate (p => deck%p)
      pos = sixbar_position(p, deck%phi_start * deg_to_rad)
      ! frame 2 has its origin at D
      h = pos%d + sixbar_frame2_to_frame1(p, pos%h)
      s4 = pos%d + sixbar_frame2_to_frame1(p, pos%s4)
      x2 = sixbar_frame2_to_frame1(p, [1.0_wp, 0.0_wp])
      guide_deg = atan2(x2(2), x2(1)) / deg_to_rad
      down = sixbar_down1(p)
      model%title = "T.FTN six-bar crank-rocker-slider (linkage form)"
      model%frame = 6
      model%g = p%g
      model%gravity_angle = atan2(down(2), down(1)) / deg_to_rad
      model%n = deck%n
      model%links = [model_link_t(1, p%m1, p%j1, [0.0_wp, 0.0_wp]), model_link_t(2, p%m2, p%j2, pos%s2), &
        model_link_t(3, p%m3, p%j3, pos%d), model_link_t(4, p%m4, p%j4, s4), model_link_t(5, p%m5, 0.0_wp, h)]
      model%pairs = [model_pair_t("A", "R", [1, 6], [0.0_wp, 0.0_wp], 0.0_wp, 0), &
        model_pair_t("B", "R", [2, 1], pos%b, 0.0_wp, 0), &
        model_pair_t("C", "R", [3, 2], pos%c, 0.0_wp, 0), &
        model_pair_t("E", "R", [4, 3], pos%e1, 0.0_wp, 0), &
        model_pair_t("H", "R", [4, 5], h, 0.0_wp, 0), &
        model_pair_t("D", "R", [3, 6], pos%d, 0.0_wp, 0), &
        model_pair_t("H6", "P", [5, 6], h, guide_deg, 6)]
      model%drives = [crank_drive(deck%phi_start, deck%dphi, p%omega1)]
    end associate
    allocate (model%moments(0))
    if (deck%dyn%mode >= dynamics_steady) then
      ! a steady cycle takes f5 as a table over the crank angle, linear between the steps
      model%forces = [model_load_t(link=5, at=h, angle=guide_deg)]
      allocate (model%forces(1)%x(deck%n))
      do k = 1, deck%n
        model%forces(1)%x(k) = sixbar_phi1_deg(deck, k)
      end do
      model%forces(1)%v = deck%f5(1:deck%n)
    else
      model%forces = [model_load_t(link=5, at=h, angle=guide_deg, column=1)]
      model%step_values = deck%f5(1:deck%n)
    end if
    model%dyn = deck%dyn
  end subroutine from_sixbar

  !> PR 3050 (`&pr3050`) in its frame (origin C, x from C to A) with its link numbers: 1
  !> cylinder (pivot A), 2 piston with rod (pin B), 3 rocker (pivot C), frame 4. The oil
  !> force drives: the drive is the cylinder's stroke |AB| - |AB| at the first step (values,
  !> speeds and accelerations per step from the rocker's prescribed motion), so F2 becomes
  !> F_drive2 and phi3rel the stroke s2 (the columns of link 2, the block).
  subroutine from_pr3050(source, model, error)
    type(deck_source_t), intent(in) :: source
    type(linkage_model_t), intent(out) :: model
    type(error_t), allocatable, intent(out) :: error
    type(pr3050_deck_t) :: deck
    type(pr3050_position_t) :: pos, first
    real(wp) :: axis_deg
    integer :: k, n
    call read_pr3050_deck(source, deck, error)
    if (allocated(error)) return
    n = deck%n
    associate (p => deck%p)
      first = pr3050_position(p, pr3050_phi3_deg(deck, 1) * deg_to_rad)
      axis_deg = atan2(-first%e2(2), -first%e2(1)) / deg_to_rad
      model%title = "PR 3050 four-bar with a hydraulic cylinder (linkage form)"
      model%frame = 4
      model%g = p%g
      model%gravity_angle = deck%gamma_deg
      model%n = n
      model%links = [model_link_t(1, p%m1, p%j1, first%s1), model_link_t(2, p%m2, p%j2, first%s2), &
        model_link_t(3, p%m3, p%j3, first%s3)]
      model%pairs = [model_pair_t("A", "R", [1, 4], first%a, 0.0_wp, 0), &
        model_pair_t("B1", "P", [2, 1], first%b, axis_deg, 1), &
        model_pair_t("B", "R", [3, 2], first%b, 0.0_wp, 0), &
        model_pair_t("C", "R", [3, 4], [0.0_wp, 0.0_wp], 0.0_wp, 0)]
      allocate (model%drives(1), model%forces(0), model%moments(0))
      model%drives(1)%pair = "B1"
      model%drives(1)%omega_column = 1
      model%drives(1)%eps_column = 2
      allocate (model%drives(1)%values(n), model%step_values(2 * n))
      do k = 1, n
        pos = pr3050_position(p, pr3050_phi3_deg(deck, k) * deg_to_rad)
        model%drives(1)%values(k) = pos%s - first%s
        model%step_values(k) = pos%ds * deck%omega3(k)
        model%step_values(n + k) = pos%dds * deck%omega3(k)**2 + pos%ds * deck%eps3(k)
      end do
      model%drives(1)%values(1) = 0.0_wp
    end associate
    model%dyn = deck%dyn
  end subroutine from_pr3050

  !> An `&assur` deck (crank and dyads) with its own link numbers and joint names, in its
  !> global frame; the points at the first step. The pairs: the crank's pivot first, then
  !> each dyad's outer pair of link a, inner pair, outer pair of link b, their links in the
  !> order of the deck's columns (F<a><b> or, with inner_on = link3, F<b><a>). The drive's
  !> angle is the crank's axis as `&linkage` takes it, to its first other joint: when that
  !> joint is off the crank's x axis the angles (phi1, windows, md_table) are shifted by
  !> the constant between the two. Load tables over the crank become tables over the first
  !> drive's coordinate; friction goes pair by pair; tables over another link,
  !> technological resistances and a linear actuator are refused naming the variable.
  subroutine from_assur(source, model, error)
    type(deck_source_t), intent(in) :: source
    type(linkage_model_t), intent(out) :: model
    type(error_t), allocatable, intent(out) :: error
    type(assur_deck_t) :: deck
    type(link_state_t), allocatable :: states(:)
    type(dyad_pose_t), allocatable :: poses(:)
    integer :: nd, d, j, i, nl, ip, ncol, n
    integer :: ids(0:1)
    real(wp) :: offset, v(2)
    real(wp), allocatable :: omega(:)
    character(len=:), allocatable :: letters
    call read_assur_deck(source, deck, error)
    if (allocated(error)) return
    call refuse_loads("force", deck%force_load)
    if (allocated(error)) return
    call refuse_loads("moment", deck%moment_load)
    if (allocated(error)) return
    n = deck%n
    nd = size(deck%mech%dyads)
    nl = 2 * nd + 1
    allocate (states(0:nl), poses(nd))
    call assur_kinematics(deck%mech, assur_phi1_deg(deck, 1) * deg_to_rad, states, poses, error)
    if (allocated(error)) then
      error%message = source%path//": &assur: convert: the first step: "//error%message
      return
    end if
    model%title = trim(deck%title)
    model%frame = deck%frame_id
    model%g = deck%mech%g
    model%gravity_angle = deck%gravity_angle
    model%n = n
    allocate (model%links(nl), model%pairs(3 * nd + 1))
    do i = 1, nl
      associate (l => deck%mech%links(i))
        model%links(i) = model_link_t(l%id, l%m, l%j, at_global(i, l%s))
      end associate
    end do
    ip = 3 * nd + 1
    model%pairs(1) = model_pair_t(deck%joint_name(ip), "R", [deck%mech%links(1)%id, deck%frame_id], &
      deck%mech%pivot, 0.0_wp, 0)
    do d = 1, nd
      letters = kind_names(deck%mech%dyads(d)%geom%kind)
      associate (dy => deck%mech%dyads(d))
        ids = [deck%mech%links(link_a(d))%id, deck%mech%links(link_b(d))%id]
        do j = 1, 3
          ip = 3 * (d - 1) + j
          associate (r => model%pairs(ip + 1))
            r%name = deck%joint_name(ip)
            r%kind = letters(j:j)
            select case (j)
            case (1)
              r%links = [ids(0), deck%mech%links(dy%on(1))%id]
            case (2)
              r%links = ids
              if (deck%pair_sign(ip) < 0.0_wp) r%links = [ids(1), ids(0)]
            case default
              r%links = [ids(1), deck%mech%links(dy%on(2))%id]
            end select
            r%at = poses(d)%p(:, j)
            if (r%kind == "P") then
              r%angle = atan2(poses(d)%t(2, j), poses(d)%t(1, j)) / deg_to_rad
              select case (j)
              case (1)
                r%guide = deck%mech%links(dy%on(1))%id
              case (2)
                r%guide = ids(1)
              case default
                r%guide = deck%mech%links(dy%on(2))%id
              end select
            end if
          end associate
        end do
      end associate
    end do
    ! friction: the crank's pivot is the last of the deck's pairs, the first of the model's
    if (deck%friction_on) then
      do ip = 1, 3 * nd + 1
        associate (fr => deck%friction(ip), r => model%pairs(merge(1, ip + 1, ip == 3 * nd + 1)))
          if (fr%f <= 0.0_wp) cycle
          r%f = fr%f
          if (r%kind == "R") r%r = fr%r
          if (r%kind == "P" .and. fr%span > 0.0_wp) r%guide_length = fr%span
        end associate
      end do
    end if
    ! the crank's axis as &linkage takes it: to its first other joint in deck order
    offset = 0.0_wp
    do ip = 2, size(model%pairs)
      if (any(model%pairs(ip)%links == deck%mech%links(1)%id)) then
        v = model%pairs(ip)%at - deck%mech%pivot
        offset = atan2(v(2), v(1)) / deg_to_rad - states(1)%th / deg_to_rad
        offset = offset - 360.0_wp * anint(offset / 360.0_wp)
        if (abs(offset) < 1.0e-12_wp) offset = 0.0_wp
        exit
      end if
    end do
    ! step_values: the load columns, then the drive's speed and acceleration when they vary
    ncol = 0
    if (allocated(deck%step_values)) then
      do i = 1, size(deck%force_load)
        if (deck%force_load(i)%kind == load_column) ncol = max(ncol, deck%force_load(i)%offset / n + 1)
      end do
      do i = 1, size(deck%moment_load)
        if (deck%moment_load(i)%kind == load_column) ncol = max(ncol, deck%moment_load(i)%offset / n + 1)
      end do
    end if
    allocate (model%step_values(ncol * n))
    if (ncol > 0) model%step_values = deck%step_values(1:ncol * n)
    allocate (model%drives(1))
    if (deck%mech%drive_dyad > 0) then
      call actuator_drive(error)
      if (allocated(error)) return
    else
      associate (dr => model%drives(1))
        dr%pair = model%pairs(1)%name
        if (allocated(deck%phi_list)) then
          dr%values = deck%phi_list(1:n) + offset
        else
          dr%start = deck%phi_start + offset
          dr%step = deck%dphi
        end if
        if (deck%prescribed .or. allocated(deck%phi_list)) then
          omega = assur_omega1_steps(deck, 1, n)
          model%step_values = [model%step_values, omega]
          dr%omega_column = ncol + 1
          if (deck%prescribed) then
            model%step_values = [model%step_values, deck%eps1_values(1:n)]
            dr%eps_column = ncol + 2
          end if
        else
          dr%omega = deck%omega1_const
        end if
      end associate
    end if
    if (size(model%step_values) == 0) deallocate (model%step_values)
    allocate (model%forces(size(deck%mech%forces)), model%moments(size(deck%mech%moment_link)))
    do i = 1, size(model%forces)
      associate (f => deck%mech%forces(i), m => model%forces(i))
        m%link = deck%mech%links(f%link)%id
        m%at = at_global(f%link, f%at)
        m%angle = f%angle / deg_to_rad
        if (f%follow) m%angle = (f%angle + states(f%link)%th) / deg_to_rad
        m%follow = f%follow
        call schedule(m, deck%force_load(i))
      end associate
    end do
    do i = 1, size(model%moments)
      model%moments(i)%link = deck%mech%links(deck%mech%moment_link(i))%id
      call schedule(model%moments(i), deck%moment_load(i))
    end do
    model%dyn = deck%dyn
    if (allocated(model%dyn%md_phi)) model%dyn%md_phi = model%dyn%md_phi + offset

  contains

    !> A linear actuator drives (drive_dyad, drive_pair): the drive is its sliding pair's
    !> stroke from the first step, with the stroke's speed and acceleration per step
    !> (columns of step_values after the load columns) from the crank's motion.
    subroutine actuator_drive(error)
      type(error_t), allocatable, intent(out) :: error
      type(link_state_t), allocatable :: st(:)
      type(dyad_pose_t), allocatable :: ps(:)
      real(wp), allocatable :: w(:), eps(:), q(:), qd(:), qdd(:)
      real(wp) :: sense
      integer :: k, dd, jj
      dd = deck%mech%drive_dyad
      jj = deck%mech%drive_pair
      allocate (st(0:nl), ps(nd), q(n), qd(n), qdd(n))
      w = assur_omega1_steps(deck, 1, n)
      allocate (eps(n))
      do k = 1, n
        eps(k) = 0.0_wp
        if (deck%prescribed) eps(k) = deck%eps1_values(k)
        call assur_kinematics(deck%mech, assur_phi1_deg(deck, k) * deg_to_rad, st, ps, error)
        if (allocated(error)) then
          error%message = source%path//": &assur: convert: step "//int_str(k)//": "//error%message
          return
        end if
        q(k) = ps(dd)%stroke(jj)
        qd(k) = ps(dd)%stroke_v(jj) * w(k)
        qdd(k) = ps(dd)%stroke_a(jj) * w(k)**2 + ps(dd)%stroke_v(jj) * eps(k)
      end do
      ! the &linkage stroke runs along the guide's direction at the first step
      sense = sign(1.0_wp, dot_product(poses(dd)%extend(:, jj), poses(dd)%t(:, jj)))
      associate (dr => model%drives(1))
        dr%pair = model%pairs(3 * (dd - 1) + jj + 1)%name
        dr%values = sense * (q - q(1))
        dr%values(1) = 0.0_wp
        model%step_values = [model%step_values, sense * qd, sense * qdd]
        dr%omega_column = ncol + 1
        dr%eps_column = ncol + 2
      end associate
    end subroutine actuator_drive

    !> A point given in link i's coordinates, global at the first step.
    pure function at_global(i, local) result(x)
      integer, intent(in) :: i
      real(wp), intent(in) :: local(2)
      real(wp) :: x(2)
      x = states(i)%o + [cos(states(i)%th) * local(1) - sin(states(i)%th) * local(2), &
        sin(states(i)%th) * local(1) + cos(states(i)%th) * local(2)]
    end function at_global

    pure subroutine schedule(m, load)
      type(model_load_t), intent(inout) :: m
      type(load_schedule_t), intent(in) :: load
      m%value = load%value
      select case (load%kind)
      case (load_window)
        m%window = .true.
        m%idle = load%idle
        m%phi_on = load%phi_on + offset
        m%phi_off = load%phi_off + offset
      case (load_column)
        m%column = load%offset / n + 1
      case (load_table)
        ! over the crank's angle: the first drive's coordinate
        m%x = load%x + offset
        m%v = load%v
      case default
        ! a constant: its value only
      end select
    end subroutine schedule

    !> Whether a table's abscissa is the crank's angle.
    pure logical function over_crank(load)
      type(load_schedule_t), intent(in) :: load
      over_crank = load%link == 1 .and. load%pair == 0
    end function over_crank

    !> The first load of `loads` the translation does not cover: a table over a link other
    !> than the crank, a technological resistance.
    subroutine refuse_loads(name, loads)
      character(*), intent(in) :: name
      type(load_schedule_t), intent(in) :: loads(:)
      integer :: k
      do k = 1, size(loads)
        if (loads(k)%kind == load_table .and. .not. over_crank(loads(k))) then
          call refuse_assur(name//"("//int_str(k)//")%over", "a load table over a link other than the crank")
          return
        end if
        if (loads(k)%resist /= resist_none) then
          call refuse_assur(name//"("//int_str(k)//")%resist", "a technological resistance (its sign from the motion)")
          return
        end if
      end do
    end subroutine refuse_loads

    subroutine refuse_assur(variable, what)
      character(*), intent(in) :: variable, what
      allocate (error)
      error%message = source%path//": &assur: "//variable//": convert: "//what// &
        " has no &linkage translation yet (run the &assur deck itself)"
    end subroutine refuse_assur
  end subroutine from_assur

  !> The drive of a crank at pair 'A' turning at a constant speed: start + (k-1)*step (deg).
  pure function crank_drive(start, step, omega) result(drive)
    real(wp), intent(in) :: start, step, omega
    type(model_drive_t) :: drive
    drive%pair = "A"
    drive%start = start
    drive%step = step
    drive%omega = omega
  end function crank_drive

  !> A `&linkage` deck as it reads, every default written out (the raw namelist read again
  !> for the angles and laws as given, after the reader has validated the deck).
  subroutine from_linkage(source, model, error)
    type(deck_source_t), intent(in) :: source
    type(linkage_model_t), intent(out) :: model
    type(error_t), allocatable, intent(out) :: error
    type(linkage_deck_t) :: deck
    integer :: i, nd, nf, nm
    call read_linkage_deck(source, deck, error)
    if (allocated(error)) return
    model%title = trim(deck%title)
    model%frame = deck%mech%frame_id
    model%g = deck%g
    model%gravity_angle = deck%gravity_angle
    model%n = deck%n
    allocate (model%links(size(deck%mech%links)))
    do i = 1, size(deck%mech%links)
      associate (l => deck%mech%links(i))
        model%links(i) = model_link_t(l%id, l%m, l%j, l%s)
      end associate
    end do
    call raw_linkage(source, model, error)
    if (allocated(error)) return
    do i = 1, size(model%pairs)
      associate (r => model%pairs(i), q => deck%mech%pairs(i))
        r%name = q%name
        r%links = [link_id(q%a), link_id(q%b)]
        r%at = q%at
        r%kind = merge("P", "R", q%kind == pair_p)
        if (q%kind == pair_p) r%guide = link_id(q%guide)
      end associate
    end do
    nd = size(deck%mech%drives)
    do i = 1, nd
      associate (d => model%drives(i))
        d%pair = deck%mech%pairs(deck%mech%drives(i)%pair)%name
        if (deck%listed(i)) then
          d%values = deck%values(1:deck%n, i)
        else
          d%start = deck%start(i)
          d%step = deck%step(i)
        end if
        d%omega = deck%omega(i)
        d%eps = deck%eps(i)
        d%omega_column = deck%omega_column(i)
        d%eps_column = deck%eps_column(i)
      end associate
    end do
    nf = size(deck%mech%forces)
    do i = 1, nf
      associate (f => model%forces(i), s => deck%force_load(i))
        f%link = deck%mech%links(deck%mech%forces(i)%link)%id
        f%at = deck%mech%forces(i)%at
        f%follow = deck%mech%forces(i)%follow
        call schedule(f, s%value, s%idle, s%phi_on, s%phi_off, s%window, s%column)
      end associate
    end do
    nm = size(deck%mech%moment_link)
    do i = 1, nm
      associate (f => model%moments(i), s => deck%moment_load(i))
        f%link = deck%mech%links(deck%mech%moment_link(i))%id
        call schedule(f, s%value, s%idle, s%phi_on, s%phi_off, s%window, s%column)
      end associate
    end do
    if (allocated(deck%step_values)) then
      if (size(deck%step_values) > 0) model%step_values = deck%step_values
    end if
    model%dyn = deck%dyn

  contains

    pure integer function link_id(index)
      integer, intent(in) :: index
      if (index == 0) then
        link_id = deck%mech%frame_id
      else
        link_id = deck%mech%links(index)%id
      end if
    end function link_id

    pure subroutine schedule(f, value, idle, on, off, window, column)
      type(model_load_t), intent(inout) :: f
      real(wp), intent(in) :: value, idle, on, off
      logical, intent(in) :: window
      integer, intent(in) :: column
      f%value = value
      f%column = column
      f%window = window
      if (window) then
        f%idle = idle
        f%phi_on = on
        f%phi_off = off
      end if
    end subroutine schedule
  end subroutine from_linkage

  !> The pair angles and force angles of a `&linkage` deck as given (the validated deck keeps
  !> their unit vectors only), and the model's lists sized as the deck's.
  subroutine raw_linkage(source, model, error)
    type(deck_source_t), intent(in) :: source
    type(linkage_model_t), intent(inout) :: model
    type(error_t), allocatable, intent(out) :: error
    integer, parameter :: max_links = 48, max_pairs = 72, max_drives = 8, max_forces = 32, max_moments = 32
    character(len=raw_text) :: title, dynamics
    real(wp) :: frame, g, gravity_angle, n, delta, j_rotor, j_flywheel, cycle, flywheel_density, flywheel_width_ratio
    real(wp), allocatable :: step_values(:), md_table(:)
    type(link_in_t) :: link(max_links)
    type(pair_in_t), allocatable :: pair(:)
    type(drive_in_t), allocatable :: drive(:)
    type(force_in_t) :: force(max_forces)
    type(moment_in_t) :: moment(max_moments)
    integer :: ios, i, np, nd, nf, nm
    character(len=512) :: msg
    namelist /linkage/ title, frame, g, gravity_angle, n, link, pair, drive, force, moment, step_values, &
      dynamics, delta, j_rotor, j_flywheel, cycle, md_table, flywheel_density, flywheel_width_ratio
    allocate (pair(max_pairs), drive(max_drives), step_values(1000000), md_table(md_table_capacity))
    read (source%records, nml=linkage, iostat=ios, iomsg=msg)
    if (ios /= 0) then
      allocate (error)
      error%message = source%path//": &linkage: convert: the deck reads with the reader but not here: "//trim(msg)
      return
    end if
    np = count(pair%kind /= "")
    nd = count(drive%pair /= "")
    nf = count(force%link == force%link)
    nm = count(moment%link == moment%link)
    allocate (model%pairs(np), model%drives(nd), model%forces(nf), model%moments(nm))
    do i = 1, np
      associate (m => model%pairs(i))
        if (pair(i)%angle == pair(i)%angle) m%angle = pair(i)%angle
        if (pair(i)%f == pair(i)%f) m%f = pair(i)%f
        if (pair(i)%r == pair(i)%r) m%r = pair(i)%r
        if (pair(i)%guide_length == pair(i)%guide_length) m%guide_length = pair(i)%guide_length
        if (pair(i)%block_length == pair(i)%block_length) m%block_length = pair(i)%block_length
      end associate
    end do
    do i = 1, nf
      model%forces(i)%angle = force(i)%angle
      call raw_table(model%forces(i), force(i)%table, force(i)%over)
    end do
    do i = 1, nm
      call raw_table(model%moments(i), moment(i)%table, moment(i)%over)
    end do

  contains

    !> A table as given: its points (up to the first unset value) and its `over`.
    pure subroutine raw_table(m, table, over)
      type(model_load_t), intent(inout) :: m
      real(wp), intent(in) :: table(:), over
      integer :: np
      np = 0
      do while (np < size(table))
        if (table(np + 1) /= table(np + 1)) exit
        np = np + 1
      end do
      if (np < 2) return
      m%x = table(1:np - 1:2)
      m%v = table(2:np:2)
      if (over == over) m%over = nint(over)
    end subroutine raw_table
  end subroutine raw_linkage

end module kinetostat_convert
