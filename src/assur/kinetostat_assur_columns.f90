!> The generic engine's result columns: the CSV row of a step (phi1, every pair's force,
!> angle, components and prismatic normal force and moment, M1 or the actuator's columns)
!> and, with friction, the friction columns, the works over the run and their summary.
module kinetostat_assur_columns
  use kinetostat_kinds, only: wp, deg_to_rad, rad_to_deg
  use kinetostat_noise, only: noise_rel
  use kinetostat_vec2, only: magnitude, largest_magnitude, angle_360_deg, angle_180_deg, clean_zero
  use kinetostat_run_tally, only: trapezoid_t
  use kinetostat_step_table, only: step_table_t, column_t, column, col_input_angle, col_force, col_force_angle, &
    col_component, col_moment, col_length, col_other, col_flag, col_ratio
  use kinetostat_assur_statics, only: pair_is_prismatic
  use kinetostat_assur_kinematics, only: point_state_t, point_on
  use kinetostat_assur, only: assur_step_t
  use kinetostat_assur_friction, only: friction_step_t
  use kinetostat_assur_deck, only: assur_deck_t, assur_phi1_deg
  use kinetostat_friction_block, only: friction_efficiency, friction_step_values
  implicit none
  private
  public :: assur_columns, assur_csv_values, assur_pair_prismatic, assur_row, assur_row_size, pair_turns, &
    crank_length, kinematics_value_count, pair_link, assur_kinematics_row, row_plan_t, row_plan, force_length
  public :: friction_columns, friction_csv_values, friction_work, friction_integrals, friction_summary, &
    friction_row_size

  !> Characters of a pair's name the legacy table's heading shows (the width of its fields).
  integer, parameter, public :: pair_heading_width = 12

  !> What a step's row takes of the deck, found once for a block (row_plan): per pair its
  !> turn into its frame, whether it is prismatic and the link its force acts on.
  type :: row_plan_t
    !> The pairs' turns into their frames (pair_turns).
    real(wp), allocatable :: turn(:, :)
    !> Per pair: whether its turn is another than none (cos 1, sin 0).
    logical, allocatable :: turned(:)
    !> Per pair: whether it is prismatic (assur_pair_prismatic).
    logical, allocatable :: prismatic(:)
    !> Per pair: the link its reported force acts on (pair_link).
    integer, allocatable :: link(:)
    !> The crank's length scale (crank_length), m.
    real(wp) :: crank = 1.0_wp
    !> Whether the pair forces' angles are computed (else their cells are 0).
    logical :: angles = .true.
  end type row_plan_t

contains

  !> Number of friction values of a row (friction_columns).
  pure integer function friction_row_size(deck)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    friction_row_size = size(friction_columns(deck))
  end function friction_row_size

  !> Friction columns after M1: M1_0 (M1 without friction; F_drive_0 with an actuator),
  !> P_loss_<pair> for every pair with friction, P_loss, eta_defined, eta, with the friction
  !> block's headings (kinetostat_friction_block).
  pure function friction_columns(deck) result(cols)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    type(column_t), allocatable :: cols(:)
    integer :: ip
    if (deck%mech%drive_dyad > 0) then
      cols = [column("F_drive_0", "N", col_component, heading="F_DRIVE_0")]
    else
      cols = [column("M1_0", "N*m", col_moment, heading="M1_0")]
    end if
    do ip = 1, size(deck%friction)
      if (deck%friction(ip)%f > 0.0_wp) cols = [cols, column("P_loss_"//trim(deck%pair_name(ip)), "W", col_other, &
                                                             heading="P_"//trim(deck%pair_name(ip)))]
    end do
    cols = [cols, column("P_loss", "W", col_other, heading="P_LOSS"), column("eta_defined", "", col_flag), &
            column("eta", "", col_ratio, heading="ETA")]
  end function friction_columns

  !> The friction values of one step, in the order of friction_columns. The instantaneous
  !> efficiency eta = 1 - R/(M1*s) (R: loss per radian of the input, s: its motion sign) is
  !> defined where the driver delivers power (M1*s > 0; at rest: virtual power); elsewhere
  !> eta_defined = 0 and eta = 0.
  pure function friction_csv_values(deck, s, fs) result(v)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> One step with friction.
    type(assur_step_t), intent(in) :: s
    !> Its friction results.
    type(friction_step_t), intent(in) :: fs
    real(wp), allocatable :: v(:)
    real(wp) :: mfloor, effort0
    ! M1_0 below the roundoff floor of M1 (see assur_csv_values) is 0, as M1 would be
    mfloor = noise_rel * largest_magnitude(s%f) * crank_length(deck)
    effort0 = fs%driver_frictionless
    if (deck%mech%drive_dyad > 0) then
      if (abs(effort0) <= noise_rel * max(mfloor / crank_length(deck), abs(s%f_drive))) effort0 = 0.0_wp
    else if (abs(effort0) <= mfloor) then
      effort0 = 0.0_wp
    end if
    v = friction_step_values(effort0, pack(fs%loss(:size(deck%friction)), deck%friction%f > 0.0_wp), fs%p_loss, &
                             fs%rate_total, fs%driver_rate * fs%motion_sign)
  end function friction_csv_values

  !> Work of the driver and work lost to friction over the run, J: trapezoidal sums over the
  !> steps of M1*s and of the loss per radian R against |d phi1|.
  pure subroutine friction_work(deck, steps, fsteps, a_driver, a_loss)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> The steps with friction.
    type(assur_step_t), intent(in) :: steps(:)
    !> Their friction results.
    type(friction_step_t), intent(in) :: fsteps(:)
    !> Work of the driver, J.
    real(wp), intent(out) :: a_driver
    !> Work lost to friction, J.
    real(wp), intent(out) :: a_loss
    type(trapezoid_t) :: works(2)
    real(wp) :: x(size(steps)), y(size(steps))
    integer :: i
    works = friction_integrals(deck, fsteps(1:size(steps)), 1)
    do i = 1, 2
      x = works(i)%x
      y = works(i)%y
      call works(i)%feed(x, y)
    end do
    a_driver = works(1)%area
    a_loss = works(2)%area
  end subroutine friction_work

  !> The works of steps step1 .. step1 + size(fsteps) - 1 (a block of the run) as points
  !> to integrate over |d phi1| in rad: [the driver's power per radian, the loss per radian]
  !> against phi1 (deg). Fed in row order (kinetostat_run_tally), they give the work of the
  !> driver and the work lost to friction, J.
  pure function friction_integrals(deck, fsteps, step1) result(works)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> Friction results of the block's steps.
    type(friction_step_t), intent(in) :: fsteps(:)
    !> Step number of fsteps(1).
    integer, intent(in) :: step1
    type(trapezoid_t) :: works(2)
    integer :: i
    do i = 1, 2
      works(i)%unit = deg_to_rad
      allocate (works(i)%x(size(fsteps)), works(i)%y(size(fsteps)))
    end do
    do i = 1, size(fsteps)
      works(1)%x(i) = assur_phi1_deg(deck, step1 - 1 + i)
      works(1)%y(i) = fsteps(i)%driver_rate * fsteps(i)%motion_sign
      works(2)%y(i) = fsteps(i)%rate_total
    end do
    works(2)%x = works(1)%x
  end function friction_integrals

  !> The summary block of a run with friction: works, cycle efficiency and what it means.
  pure subroutine friction_summary(deck, a_driver, a_loss, table)
    type(assur_deck_t), intent(in) :: deck
    !> Work of the driver over the run, J.
    real(wp), intent(in) :: a_driver
    !> Work lost to friction over the run, J.
    real(wp), intent(in) :: a_loss
    type(step_table_t), intent(inout) :: table
    real(wp) :: span
    span = abs(assur_phi1_deg(deck, deck%n) - assur_phi1_deg(deck, 1))
    table%summary_heading = "WORK AND EFFICIENCY WITH FRICTION"
    call table%summary_real("RUN SPAN", span, "deg")
    call friction_efficiency(a_driver, a_loss, span, table)
  end subroutine friction_summary

  !> Whether result pair `ip` (dyad pairs then crank pin) is prismatic.
  pure logical function assur_pair_prismatic(deck, ip)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> Pair result index.
    integer, intent(in) :: ip
    integer :: d
    d = (ip - 1) / 3 + 1
    if (d > size(deck%mech%dyads)) then
      assur_pair_prismatic = .false.
    else
      assur_pair_prismatic = pair_is_prismatic(deck%mech%dyads(d)%geom%kind, ip - 3 * (d - 1))
    end if
  end function assur_pair_prismatic

  !> The columns of a step, declared once for the deck: phi1; per pair its force and angle,
  !> with components = .true. its x and y components, for a prismatic pair the normal force
  !> <F>N and the moment <F>M; M1, or with a linear actuator as driver F_drive, stroke,
  !> stroke_v, stroke_a. The legacy table heads a pair by the first pair_heading_width
  !> characters of its name.
  pure function assur_columns(deck) result(cols)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    type(column_t), allocatable :: cols(:)
    character(len=:), allocatable :: name, short
    integer :: ip
    cols = [column("phi1", "deg", col_input_angle, heading="PHI1")]
    do ip = 1, size(deck%pair_name)
      name = trim(deck%pair_name(ip))
      short = trim(deck%pair_name(ip)(1:min(len(deck%pair_name), pair_heading_width)))
      cols = [cols, column(name, "N", col_force, heading=short), column(name//"G", "deg", col_force_angle, heading=short//"G")]
      if (deck%components) cols = [cols, column(name//"x", "N", col_component), column(name//"y", "N", col_component)]
      if (assur_pair_prismatic(deck, ip)) cols = [cols, column(name//"N", "N", col_component, heading=short//"N"), &
                                                  column(name//"M", "N*m", col_moment, heading=short//"M")]
    end do
    if (deck%mech%drive_dyad == 0) then
      cols = [cols, column("M1", "N*m", col_moment, heading="M1")]
    else
      cols = [cols, column("F_drive", "N", col_component, heading="F_DRIVE"), &
              column("stroke", "m", col_length, heading="STROKE"), column("stroke_v", "m/s", col_other, heading="STROKE_V"), &
              column("stroke_a", "m/s^2", col_other, heading="STROKE_A")]
    end if
  end function assur_columns

  !> The CSV row of one step, in the order of assur_columns (see assur_row).
  pure function assur_csv_values(deck, s) result(v)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> One step.
    type(assur_step_t), intent(in) :: s
    real(wp), allocatable :: v(:)
    real(wp) :: lengths(size(s%f, 2))
    allocate (v(assur_row_size(deck)))
    call assur_row(deck, row_plan(deck, .true.), s, v, lengths)
  end function assur_csv_values

  !> The row plan of a deck (see row_plan_t).
  pure function row_plan(deck, angles) result(plan)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> Whether the pair forces' angles are computed.
    logical, intent(in) :: angles
    type(row_plan_t) :: plan
    integer :: ip, np
    np = size(deck%pair_name)
    allocate (plan%turn, source=pair_turns(deck))
    allocate (plan%turned(np), plan%prismatic(np), plan%link(np))
    do ip = 1, np
      plan%turned(ip) = plan%turn(1, ip) /= 1.0_wp .or. plan%turn(2, ip) /= 0.0_wp
      plan%prismatic(ip) = assur_pair_prismatic(deck, ip)
      plan%link(ip) = pair_link(deck, ip)
    end do
    plan%crank = crank_length(deck)
    plan%angles = angles
  end function row_plan

  !> cos and sin of the angle each pair's force is turned by into its reporting frame
  !> (-pair_frame), as rotate computes them: (1, ip) cos, (2, ip) sin. (Not vectorised: the
  !> vector cos and sin of libmvec may differ from the scalar ones in the last bit.)
  pure function pair_turns(deck) result(turn)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    real(wp), allocatable :: turn(:, :)
    integer :: ip
    allocate (turn(2, size(deck%pair_frame)))
    ! scalar: libmvec's vector cos/sin move the last digit of the pair-frame components (assur_sixbar.csv)
    !GCC$ novector
    do ip = 1, size(deck%pair_frame)
      turn(1, ip) = cos(-deck%pair_frame(ip))
      turn(2, ip) = sin(-deck%pair_frame(ip))
    end do
  end function pair_turns

  !> Number of values of a row of assur_columns, counted as it declares them (without
  !> declaring them: a column's declaration looks its Russian unit up).
  pure integer function assur_row_size(deck)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    integer :: ip
    assur_row_size = 1
    do ip = 1, size(deck%pair_name)
      assur_row_size = assur_row_size + 2
      if (deck%components) assur_row_size = assur_row_size + 2
      if (assur_pair_prismatic(deck, ip)) assur_row_size = assur_row_size + 2
    end do
    if (deck%mech%drive_dyad == 0) then
      assur_row_size = assur_row_size + 1
    else
      assur_row_size = assur_row_size + 4
    end if
  end function assur_row_size

  !> The CSV row `v` of one step, in the order of assur_columns. Forces below `noise_rel`
  !> times the step's largest force (moments below that force times the crank's length
  !> scale) are roundoff: printed as 0 with angle 0; so are single components below that floor
  !> (a force along an axis gets exactly that axis' angle). Without plan%angles (a run whose
  !> output shows no angle) the angle cells are 0. Every pair force's length |F| goes to
  !> `lengths` as well (assur_kinematics_row's). -0 is written as +0.
  pure subroutine assur_row(deck, plan, s, v, lengths)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> The deck's row plan (row_plan).
    type(row_plan_t), intent(in) :: plan
    !> One step.
    type(assur_step_t), intent(in) :: s
    !> The row (assur_row_size values).
    real(wp), intent(out) :: v(:)
    !> Per pair: the length of its force, N.
    real(wp), intent(out) :: lengths(:)
    real(wp) :: floor, f1, f2, g1, g2, c, sn, mfloor, nn, mm, f_mag
    integer :: ip, np, pos
    np = size(s%f, 2)
    ! every pair's |F| first: the step's roundoff floor
    floor = 0.0_wp
    do ip = 1, np
      f_mag = force_length(s%f(1, ip), s%f(2, ip))
      lengths(ip) = f_mag
      floor = max(floor, f_mag)
    end do
    floor = noise_rel * floor
    mfloor = floor * plan%crank
    v(1) = s%phi1 * rad_to_deg + 0.0_wp
    pos = 1
    do ip = 1, np
      call signed_force(deck%pair_sign(ip), s%f(:, ip), lengths(ip), floor, f1, f2)
      ! rotate(f, -deck%pair_frame(ip))
      c = plan%turn(1, ip)
      sn = plan%turn(2, ip)
      g1 = c * f1 - sn * f2
      g2 = sn * f1 + c * f2
      f_mag = lengths(ip)
      if (abs(g1) <= floor .or. abs(g2) <= floor) then
        if (abs(g1) <= floor) g1 = 0.0_wp
        if (abs(g2) <= floor) g2 = 0.0_wp
        f_mag = force_length(g1, g2)
      else if (plan%turned(ip)) then
        f_mag = force_length(g1, g2)
      end if
      ! (else f is +-s%f exactly, turned by 0: its length is the one already taken)
      v(pos + 1) = f_mag + 0.0_wp
      if (.not. plan%angles) then
        v(pos + 2) = 0.0_wp
      else if (deck%angles_signed) then
        v(pos + 2) = angle_180_deg([g1, g2]) + 0.0_wp
      else
        v(pos + 2) = angle_360_deg([g1, g2]) + 0.0_wp
      end if
      pos = pos + 2
      if (deck%components) then
        v(pos + 1) = g1 + 0.0_wp
        v(pos + 2) = g2 + 0.0_wp
        pos = pos + 2
      end if
      if (plan%prismatic(ip)) then
        nn = deck%pair_sign(ip) * s%n(ip)
        mm = deck%pair_sign(ip) * s%m(ip)
        if (abs(nn) <= floor) nn = 0.0_wp
        if (abs(mm) <= mfloor) mm = 0.0_wp
        v(pos + 1) = nn + 0.0_wp
        v(pos + 2) = mm + 0.0_wp
        pos = pos + 2
      end if
    end do
    if (deck%mech%drive_dyad == 0) then
      v(pos + 1) = s%m1 + 0.0_wp
      if (abs(s%m1) <= mfloor) v(pos + 1) = 0.0_wp
    else
      v(pos + 1) = s%f_drive + 0.0_wp
      if (abs(s%f_drive) <= floor) v(pos + 1) = 0.0_wp
      v(pos + 2) = s%stroke + 0.0_wp
      v(pos + 3) = s%stroke_v + 0.0_wp
      v(pos + 4) = s%stroke_a + 0.0_wp
    end if
  end subroutine assur_row

  !> |(x, y)|, the value hypot gives (vec2's magnitude) at a third of its cost: where neither
  !> component is huge (the larger at most 2**511) or tiny (the smaller at least 2**-459)
  !> and the smaller is not negligible beside the larger (above 2**-54 of it), the
  !> arithmetic of the GNU C library's hypot (2.35 and later, built without a fused
  !> multiply-add, as on x86-64): the square root of the sum of squares corrected by its
  !> error, operation for operation; elsewhere (a zero, an infinity or NaN) hypot itself.
  !> (test_columns compares the two bit for bit.)
  pure real(wp) function force_length(x, y) result(h)
    !> The components.
    real(wp), intent(in) :: x, y
    real(wp), parameter :: large = scale(1.0_wp, 511), small = scale(1.0_wp, -459), negligible = scale(1.0_wp, -54)
    real(wp) :: ax, ay, delta, t1, t2
    ! (as hypot orders them: with a NaN, ax or ay is NaN and hypot takes it)
    if (abs(x) < abs(y)) then
      ax = abs(y)
      ay = abs(x)
    else
      ax = abs(x)
      ay = abs(y)
    end if
    if (.not. (ax <= large .and. ay >= small .and. ay > negligible * ax)) then
      h = hypot(x, y)
      return
    end if
    h = sqrt(ax * ax + ay * ay)
    if (h <= ay + ay) then
      delta = h - ay
      t1 = ax * ((delta + delta) - ax)
      t2 = (delta - ((ax - ay) + (ax - ay))) * delta
    else
      delta = h - ax
      t1 = (delta + delta) * (ax - (ay + ay))
      t2 = (4.0_wp * delta - ay) * ay + delta * delta
    end if
    h = h - (t1 + t2) / (h + h)
  end function force_length

  !> A pair's reported force, `sign` times its components f (snap_noise(sign * f, floor)
  !> with the force's length already known: hypot ignores the signs), N.
  pure subroutine signed_force(sign, f, length, floor, f1, f2)
    !> The pair's sign (+1, or -1 where the force on the other link is reported).
    real(wp), intent(in) :: sign
    !> The pair force's components, N.
    real(wp), intent(in) :: f(2)
    !> Its length, N.
    real(wp), intent(in) :: length
    !> The step's roundoff floor, N: a force at or below it is 0.
    real(wp), intent(in) :: floor
    !> The reported components, N.
    real(wp), intent(out) :: f1, f2
    if (length <= floor) then
      f1 = 0.0_wp
      f2 = 0.0_wp
    else
      f1 = sign * f(1)
      f2 = sign * f(2)
    end if
  end subroutine signed_force

  !> Number of values of a row of the kinematics columns (assur_kinematics_row): per pair its
  !> reference point (2), per moving link its centre of mass (2), angle, speed and
  !> acceleration (3) and the centre's acceleration (2), per pair its force components in
  !> the pair's frame (2) and in the axes of the link it acts on (2).
  pure integer function kinematics_value_count(deck)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    integer :: np, nl
    np = size(deck%pair_name)
    nl = 2 * size(deck%mech%dyads) + 1
    kinematics_value_count = 2 * np + 2 * nl + 3 * nl + 2 * nl + 2 * np + 2 * np
  end function kinematics_value_count

  !> Internal index of the link the reported force of result pair `ip` acts on: link a for a
  !> dyad's pair 1 and its inner pair (link b with inner_on = link3), link b for pair 3, the
  !> crank for the crank pin.
  pure integer function pair_link(deck, ip)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> Pair result index.
    integer, intent(in) :: ip
    integer :: d, j
    d = (ip - 1) / 3 + 1
    j = ip - 3 * (d - 1)
    if (d > size(deck%mech%dyads)) then
      pair_link = 1
    else if (j == 1 .or. (j == 2 .and. deck%pair_sign(ip) > 0.0_wp)) then
      pair_link = 2 * d
    else
      pair_link = 2 * d + 1
    end if
  end function pair_link

  !> The kinematics columns of one solved step (the links' frames and the dyads' poses its
  !> solve left in `s`) into `row`: the j-th value (kinematics_value_count, in the order the
  !> columns were named) into row(slots(j)), none where slots(j) = 0, -0 as +0. The values:
  !> the reference point of every pair (the crank's pair with the frame: the pivot), m; the
  !> centre of mass S of every moving link, m; every moving link's angle (deg), angular
  !> velocity (rad/s) and acceleration (rad/s^2); the acceleration of every S, m/s^2; every
  !> pair force's components in the frame of its angle column and in the axes of the link it
  !> acts on, N, a force at or below the step's roundoff floor (noise_rel times its largest
  !> pair force) and a component at or below it as 0. Each pair's length is the one assur_row
  !> took (the turned force's own length decides nothing: a force whose turned length is at
  !> most the floor has both components at most the floor). The values are put in order
  !> into `values` (the caller's workspace) and then into their columns.
  pure subroutine assur_kinematics_row(deck, plan, s, f_len, slots, values, link_turns, row)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> The deck's row plan (row_plan).
    type(row_plan_t), intent(in) :: plan
    !> One solved step (its work_states and work_poses set by its solve).
    type(assur_step_t), intent(in) :: s
    !> Per pair: the length of its force (assur_row's `lengths`), N.
    real(wp), intent(in) :: f_len(:)
    !> Column of every value (0: not written).
    integer, intent(in) :: slots(:)
    !> Workspace of kinematics_value_count values.
    real(wp), intent(inout) :: values(:)
    !> Workspace (2, moving links): each link's cos and sin of its angle.
    real(wp), intent(inout) :: link_turns(:, :)
    !> The step's row of the table.
    real(wp), intent(inout) :: row(:)
    type(point_state_t) :: ps
    real(wp) :: w2, floor, f1, f2, c, sn, th
    integer :: np, nl, i, ip, d, j, js, jl, ja, q
    np = size(s%f, 2)
    nl = ubound(s%work_states, 1)
    w2 = s%omega1**2
    ! the pairs' reference points
    j = 0
    do ip = 1, np - 1
      d = (ip - 1) / 3 + 1
      q = ip - 3 * (d - 1)
      values(j + 1) = s%work_poses(d)%p(1, q)
      values(j + 2) = s%work_poses(d)%p(2, q)
      j = j + 2
    end do
    values(j + 1) = deck%mech%pivot(1)
    values(j + 2) = deck%mech%pivot(2)
    j = j + 2
    ! per link: S, then (after every S) phi, omega, eps, then (after those) S's acceleration
    js = j
    jl = js + 2 * nl
    ja = jl + 3 * nl
    do i = 1, nl
      associate (st => s%work_states(i))
        ps = point_on(st, deck%mech%links(i)%s)
        values(js + 1) = ps%p(1)
        values(js + 2) = ps%p(2)
        values(jl + 1) = st%th * rad_to_deg
        values(jl + 2) = st%u * s%omega1
        values(jl + 3) = st%eq * w2 + st%u * s%eps1
        values(ja + 1) = ps%a(1) * w2 + ps%v(1) * s%eps1
        values(ja + 2) = ps%a(2) * w2 + ps%v(2) * s%eps1
        js = js + 2
        jl = jl + 3
        ja = ja + 2
        ! the turn into the link's axes, by -th: [cos th, sin th; -sin th, cos th] (cos and
        ! sin of one argument: one sincos call; the C library's cos is even and its sin odd,
        ! bit for bit, so these are the values of cos(-th) and -sin(-th))
        th = st%th
        c = cos(th)
        sn = sin(th)
        link_turns(1, i) = c
        link_turns(2, i) = sn
      end associate
    end do
    j = ja
    floor = 0.0_wp
    do ip = 1, np
      floor = max(floor, f_len(ip))
    end do
    floor = noise_rel * floor
    ! components in the pairs' frames, then in the links' axes
    jl = j + 2 * np
    do ip = 1, np
      call signed_force(deck%pair_sign(ip), s%f(:, ip), f_len(ip), floor, f1, f2)
      c = plan%turn(1, ip)
      sn = plan%turn(2, ip)
      values(j + 1) = component(c * f1 - sn * f2)
      values(j + 2) = component(sn * f1 + c * f2)
      j = j + 2
      i = plan%link(ip)
      c = link_turns(1, i)
      sn = link_turns(2, i)
      values(jl + 1) = component(c * f1 + sn * f2)
      values(jl + 2) = component(c * f2 - sn * f1)
      jl = jl + 2
    end do
    do j = 1, size(slots)
      if (slots(j) > 0) row(slots(j)) = values(j) + 0.0_wp
    end do
  contains
    !> A force component, 0 at or below the floor.
    pure real(wp) function component(x)
      real(wp), intent(in) :: x
      component = x
      if (abs(x) <= floor) component = 0.0_wp
    end function component
  end subroutine assur_kinematics_row

  !> Length scale of the crank: its farthest attachment point from the pivot (1 m if none).
  pure real(wp) function crank_length(deck)
    type(assur_deck_t), intent(in) :: deck
    integer :: d, q
    crank_length = 0.0_wp
    do d = 1, size(deck%mech%dyads)
      do q = 1, 2
        if (deck%mech%dyads(d)%on(q) == 1) crank_length = max(crank_length, magnitude(deck%mech%dyads(d)%at(:, q)))
      end do
    end do
    if (.not. crank_length > 0.0_wp) crank_length = 1.0_wp
  end function crank_length

end module kinetostat_assur_columns
