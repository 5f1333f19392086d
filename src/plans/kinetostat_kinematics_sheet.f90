!> The course's sheet of the structure and the kinematics (kinetostat sheets: kinematics.svg)
!> on the drawing model, from a run with the points' velocities and accelerations
!> (--kinematics):
!> - the mechanism at the position --at K at a ГОСТ 2.302 scale (the title block's Масштаб),
!>   with the trajectory of the traced point (the coupler's centre of mass: the first link
!>   with a centre of mass of the first group after the input units) over the run's steps;
!> - the structure: the units in the course's order (plan_groups: a &linkage deck's own
!>   analysis, or the one derived from the topology) with their classes, the structure
!>   formula, the number of moving links n, of lower pairs p5 and W = 3n - 2p5;
!> - the diagrams of the output link (the last link of the last group) over the input angle:
!>   a slider's displacement s from its extreme position along its guide with its velocity
!>   and acceleration along it, or a rocker's angle ψ from its extreme position with ω and
!>   ε, each at a round μ and one μφ;
!> - the values at the position: every point's speed and acceleration, every link's ω and ε.
module kinetostat_kinematics_sheet
  use kinetostat_kinds, only: wp, deg_to_rad
  use kinetostat_format, only: short_number, fixed_number
  use kinetostat_text, only: int_str, char_count
  use kinetostat_step_table, only: step_table_t
  use kinetostat_labels, only: unit_word => unit_symbol
  use kinetostat_sheet, only: sheet_t, paper_t, course_paper, kinematics_sheets, layer_text, layer_charts
  use kinetostat_title_block, only: put_sheet_format, title_block_from_table, block_height, block_width
  use kinetostat_scales, only: round_scale, scale_number
  use kinetostat_sketch, only: sketch_t
  use kinetostat_drawing, only: drawing_t, column_value, drawing_from_sketch, body_block, point_plain
  use kinetostat_error, only: error_t, fatal_error, exit_input
  use kinetostat_mechanism_view, only: mechanism_view_t, fit_mechanism_view, draw_mechanism
  use kinetostat_design_sheet, only: words, put_table
  use kinetostat_dynamics_sheet, only: sheet_header, plot_t, put_cycle_chart, put_cycle_curve
  use kinetostat_plans_base, only: slide_t, slides_of, slide_is_pair, lists, sliding_on, plan_group_t
  use kinetostat_plans_groups, only: plan_groups
  use kinetostat_plans_base, only: plans_t
  use kinetostat_plans_draw, only: draw_kinematic_plans, values_table_height
  use kinetostat_run_sheet, only: wrapped, note_length
  use kinetostat_mechanism_sheet, only: fitted_size
  implicit none
  private
  public :: draw_kinematics_sheet, output_motion

  !> Gap between panels, mm.
  real(wp), parameter :: gap = 6.0_wp
  !> Pitch of the rows of the values at the position in two tables side by side, mm.
  real(wp), parameter :: compact_pitch = 3.8_wp

contains

  !> The kinematics sheet of row k on `paper`'s size (course_paper: A1, A2 landscape in
  !> three columns; A3 landscape and A4 portrait, its `part` 1 or 2, in two).
  subroutine draw_kinematics_sheet(title, table, topo, drawing, k, paper, lang, sheet, positions, every, n_positions, &
                                   point_asked, output_link, plans, part)
    !> Title of the mechanism.
    character(*), intent(in) :: title
    !> The run (its kinematics columns with the points' velocities and accelerations).
    type(step_table_t), intent(in) :: table
    !> The mechanism's topology (available).
    type(sketch_t), intent(in) :: topo
    !> The mechanism at that row with its forces (drawing_from_sketch, force_plan: the drive
    !> names the input link of the structure).
    type(drawing_t), intent(in) :: drawing
    !> Row of the position drawn.
    integer, intent(in) :: k
    type(paper_t), intent(in) :: paper
    integer, intent(in) :: lang
    type(sheet_t), intent(out) :: sheet
    !> The plan of positions: the run at equal input angles from the output link's extreme
    !> position, `every` rows a position, `n_positions` positions (8 or 12) over rows 1 ..
    !> n_positions*every + 1 (none: no plan of positions).
    type(step_table_t), intent(in), optional :: positions
    integer, intent(in) :: every, n_positions
    !> The traced point (--point; "": the coupler's centre of mass) and the output link
    !> (--output-link; 0: the last link of the last group).
    character(*), intent(in) :: point_asked
    integer, intent(in) :: output_link
    !> The plans of velocities and accelerations at row k (none: the values table alone).
    type(plans_t), intent(in), optional :: plans
    !> A3's or A4's sheet: 1 (the plan of positions, the structure, the output link's
    !> diagrams; the default) or 2 (the mechanism in the position, the values there, the plans
    !> and the values read off them); A1, A2 draw everything on one sheet.
    integer, intent(in), optional :: part
    type(paper_t) :: page
    integer :: part_drawn
    !> The values at the position in two tables side by side (the points', the links').
    logical :: compact
    !> The bottom of the panels (A3, A4: above the title block), of the left column's (A3:
    !> beside the title block, down to the frame) and the height of the values read off the
    !> plans (A3, A4), mm.
    real(wp) :: bottom, bottom_left, h_read
    type(mechanism_view_t) :: view
    type(drawing_t) :: all_positions
    type(drawing_t), allocatable :: placed(:)
    logical :: planned
    type(slide_t), allocatable :: slides(:)
    type(plan_group_t), allocatable :: groups(:)
    real(wp) :: inner(4), cw, x1, x2, x3, top, region(4), mu_phi, hmax, y
    real(wp), allocatable :: phi(:)
    character(len=:), allocatable :: short, driver, traced, text
    !> The sheet's name, its description, the title block's drawing name and the header.
    character(len=:), allocatable :: sheet_name, about, drawing_name, header
    !> The mechanism panel's heading, a line an element, and how much lower the mechanism is
    !> drawn for its lines after the first, mm.
    character(len=note_length), allocatable :: heading(:)
    real(wp) :: heading_drop
    !> Distance between the heading's lines, mm.
    real(wp), parameter :: heading_pitch = 4.6_wp
    integer :: i
    type(plot_t) :: q

    allocate (phi(0))
    call slides_of(topo, drawing, table, k, slides)
    driver = ""
    if (allocated(table%driver)) driver = table%driver
    call plan_groups(topo, drawing, table, slides, driver, groups)

    ! A1, A2 landscape: one sheet in three columns; A3 landscape and A4 portrait (ГОСТ 2.301:
    ! its title block along the short side) two sheets in two columns (part 1, 2)
    page = course_paper(paper%name)
    part_drawn = 0
    if (kinematics_sheets(page%name) == 2) then
      part_drawn = 1
      if (present(part)) then
        if (part == 2) part_drawn = 2
      end if
    end if
    inner = page%inside()
    top = inner(2) + 24.0_wp
    ! (A4: the panels stop above the title block, which spans the frame's width; A3 landscape:
    ! the left column, clear of the block, goes down to the frame)
    bottom = inner(4) - block_height - gap
    bottom_left = bottom
    if (page%landscape) bottom_left = inner(4) - gap
    ! (the values at the position: the points' and the links' tables side by side in a column
    ! narrower than 200 mm: A2, A3's and A4's second sheet)
    compact = .false.
    if (part_drawn == 0) then
      cw = (inner(3) - inner(1) - 4.0_wp * gap) / 3.0_wp
      compact = cw < 200.0_wp
      x1 = inner(1) + gap
      x2 = x1 + cw + gap
      x3 = x2 + cw + gap
      region = [x1, top, x1 + cw, top + 0.58_wp * (inner(4) - top)]
    else
      cw = (inner(3) - inner(1) - 3.0_wp * gap) / 2.0_wp
      x1 = inner(1) + gap
      x2 = x1 + cw + gap
      x3 = x2
      if (part_drawn == 1) then
        ! the plan of positions over the structure (its tables' height, at most 0.45 of the
        ! column), the diagrams beside them
        region = [x1, top, x1 + cw, bottom_left - gap - min(0.45_wp * (bottom_left - top), 34.0_wp + 4.5_wp * &
          real(size(groups) + 1, wp) + 4.2_wp * real(lower_pairs() + 1, wp))]
      else
        ! the mechanism in the position beside the values table (its points and links side by
        ! side)
        compact = .true.
        region = [x1, top, x1 + cw, top + max(70.0_wp, values_height())]
      end if
    end if
    ! the plan of positions: every position's drawing, and the view fitted to them all
    planned = present(positions) .and. part_drawn /= 2
    if (planned) call position_drawings()
    ! the panel's heading, in as many lines as the column needs (heading_drop: the mechanism
    ! lower by the lines after the first)
    traced = point_asked
    if (len(traced) == 0) traced = traced_point()
    if (part_drawn == 2) traced = ""
    call heading_lines()
    if (planned) then
      call fit_mechanism_view(all_positions, [region(1) + 4.0_wp, region(2) + 10.0_wp + heading_drop, &
        region(3) - 4.0_wp, region(4) - 10.0_wp], 10.0_wp, view)
    else
      ! (A4's second sheet: the mechanism in its panel beside the values with 4 mm around it)
      call fit_mechanism_view(drawing, [region(1) + 4.0_wp, region(2) + 10.0_wp + heading_drop, region(3) - 4.0_wp, &
        region(4) - 10.0_wp], merge(4.0_wp, 10.0_wp, part_drawn == 2), view)
    end if
    ! the sheet's name (with the position), description, title block and header
    if (part_drawn == 2) then
      sheet_name = words("Plans of velocities and accelerations", "Планы скоростей и ускорений", lang)
      about = "kinetostat sheets: the second kinematics sheet ("//page%name//"): the mechanism in the "// &
        "position, the values there, the plans of velocities and accelerations and the values read off them."
      drawing_name = sheet_name
      header = words("Kinematic analysis: plans of velocities and accelerations", &
        "Кинематический анализ: планы скоростей и ускорений", lang)
    else
      sheet_name = words("Structure and kinematics", "Структурный и кинематический анализ", lang)
      about = "kinetostat sheets: the kinematics sheet: the mechanism at a position "// &
        "with a trajectory, the structure, the output link's diagrams, the values at the position."
      drawing_name = words("Structure and kinematics of the mechanism", &
        "Структурный и кинематический анализ механизма", lang)
      header = words("Structural and kinematic analysis", &
        "Структурный и кинематический анализ механизма", lang)
    end if
    call sheet%open(page, lang, sheet_name//", "//words("position", "положение", lang)//" "//int_str(table%run_row(k)), &
      about)
    call put_sheet_format(sheet, title_block_from_table(table, drawing_name, view%drawing_scale%text))
    call sheet_header(sheet, title, table, lang, header)

    ! the mechanism at the position with the traced point's trajectory
    call sheet%set_layer(layer_charts)
    call sheet%rect(region(1), region(2), cw, region(4) - region(2), "panel")
    do i = 1, size(heading)
      call sheet%text(region(1) + 2.0_wp, region(2) + 5.0_wp + heading_pitch * (i - 1), trim(heading(i)), "heading")
    end do
    if (planned) then
      call put_positions()
    else if (len(traced) > 0) then
      call put_trajectory(traced)
    end if
    call draw_mechanism(sheet, drawing, view, [region(1) + 2.0_wp, region(2) + 8.0_wp + heading_drop, &
      region(3) - 2.0_wp, region(4) - 12.0_wp], 0.0_wp, short)
    if (planned) call put_position_numbers()
    call sheet%set_layer(layer_text)
    call sheet%text(region(1) + 2.0_wp, region(4) - 3.0_wp, "μl = "//scale_number(view%mu_l())//" "// &
      unit_word("m", lang)//"/"//unit_word("mm", lang)//" ("//view%drawing_scale%text//")", "small")

    ! the structure
    if (part_drawn == 0) then
      call put_structure(x1, region(4) + gap, cw, inner(4) - region(4) - 2.0_wp * gap)
    else if (part_drawn == 1) then
      call put_structure(x1, region(4) + gap, cw, bottom_left - region(4) - gap)
    end if

    ! the output link's diagrams over the input angle
    ! (a run of one position, or one whose input coordinate does not move, has none)
    if (table%input_column > 0) phi = table%rows(table%input_column, :)
    if (table%input_column > 0 .and. size(table%rows, 2) > 1) then
      if (maxval(phi) - minval(phi) <= 0.0_wp) phi = [real(wp) ::]
    end if
    if (size(phi) > 1 .and. part_drawn < 2) then
      mu_phi = round_scale(maxval(phi) - minval(phi), cw - 24.0_wp)
      ! (down to the title block when the column reaches over it: A3, A4)
      if (part_drawn == 1) then
        hmax = (bottom - top - 2.0_wp * gap) / 3.0_wp
      else if (x2 + cw > inner(3) - block_width) then
        hmax = (inner(4) - block_height - gap - top - 2.0_wp * gap) / 3.0_wp
      else
        hmax = (inner(4) - top - 2.0_wp * gap) / 3.0_wp
      end if
      y = top
      call output_diagrams()
    end if

    ! the values at the position, the plans of velocities and accelerations and the values
    ! read off them
    if (part_drawn == 1) then
      continue
    else if (part_drawn == 2 .and. present(plans)) then
      ! (A3, A4: the values beside the mechanism, the two plans side by side under them, the values
      ! read off them across the sheet)
      call put_values(x2, top, cw, region(4) - top)
      y = region(4) + gap
      hmax = bottom - y
      ! (the values read off as high as they need at 1.8 mm, half the height at the most; the
      ! plans the rest; A3 landscape: in the left column from the frame's foot up, left of the
      ! title block and higher where they need more, the plan of accelerations down to the
      ! block's top)
      h_read = min(0.5_wp * hmax, values_table_height(plans, 2.0_wp * cw + gap, lang))
      if (page%landscape) then
        h_read = max(block_height - gap, min(0.5_wp * hmax, values_table_height(plans, cw, lang)))
        call draw_kinematic_plans(sheet, view, plans, [x1, y, x1 + cw, inner(4) - gap - h_read - gap], &
          [x2, y, x2 + cw, bottom], [x1, inner(4) - gap - h_read, x1 + cw, inner(4) - gap], lang)
      else
        call draw_kinematic_plans(sheet, view, plans, [x1, y, x1 + cw, bottom - h_read - gap], &
          [x2, y, x2 + cw, bottom - h_read - gap], [x1, bottom - h_read, x2 + cw, bottom], lang)
      end if
    else if (part_drawn == 2) then
      call put_values(x2, top, cw, region(4) - top)
    else if (present(plans)) then
      call put_values(x3, top, cw, values_height())
      y = top + values_height() + gap
      hmax = inner(4) - block_height - gap - y
      if (compact) then
        ! (A2: the values read off as high as they need at 1.8 mm, 0.3 of the height at the
        ! most; the two plans the rest)
        h_read = min(0.3_wp * hmax, values_table_height(plans, cw, lang))
        associate (ph => 0.5_wp * (hmax - h_read) - gap)
          call draw_kinematic_plans(sheet, view, plans, [x3, y, x3 + cw, y + ph], [x3, y + ph + gap, x3 + cw, y + 2.0_wp * ph + &
            gap], [x3, y + hmax - h_read, x3 + cw, y + hmax], lang)
        end associate
      else
        call draw_kinematic_plans(sheet, view, plans, [x3, y, x3 + cw, y + 0.37_wp * hmax], &
          [x3, y + 0.37_wp * hmax + gap, x3 + cw, y + 0.74_wp * hmax], &
          [x3, y + 0.74_wp * hmax + 2.0_wp * gap, x3 + cw, y + hmax], lang)
      end if
    else
      call put_values(x3, top, cw, inner(4) - block_height - gap - top)
    end if
  contains

    !> The mechanism panel's heading (what is drawn, the position, the traced point) cut at
    !> blanks into lines that fit the column at the heading's 3.2 mm (0.6 of it a character).
    subroutine heading_lines()
      if (planned) then
        text = words("Plan of positions (", "План положений (", lang)//int_str(n_positions)
        text = text//words(", from the extreme position of link ", ", от крайнего положения звена ", lang)
        text = text//output_name()//"); "//words("the mechanism in position ", "механизм в положении ", lang)
        text = text//int_str(table%run_row(k))
      else
        text = words("Mechanism in position ", "Механизм в положении ", lang)//int_str(table%run_row(k))
      end if
      if (table%input_column > 0) text = text//" (φ1 = "//short_number(table%rows(table%input_column, k))//" "// &
        unit_word("deg", lang)//")"
      if (len(traced) > 0) text = text//words("; trajectory of ", "; траектория точки ", lang)//traced
      call wrapped(text, int((cw - 4.0_wp) / (0.6_wp * 3.2_wp)), heading)
      heading_drop = heading_pitch * real(size(heading) - 1, wp)
    end subroutine heading_lines

    !> The height of the values table's panel, mm: its rows and headings.
    real(wp) function values_height() result(h)
      integer :: ip, il, np, nl
      np = 1
      nl = 1
      do ip = 1, size(drawing%points)
        if (table%column_index("vx_"//trim(drawing%points(ip)%name)) > 0) np = np + 1
      end do
      do il = 1, size(topo%links)
        if (table%column_index("omega"//trim(topo%links(il)%name)) > 0) nl = nl + 1
      end do
      if (compact) then
        h = 9.0_wp + compact_pitch * max(np, nl) + 4.0_wp
      else
        h = 9.0_wp + 4.2_wp * (np + nl) + 4.0_wp
      end if
    end function values_height

    !> The output link's number ("" when there is none).
    function output_name() result(name)
      character(len=:), allocatable :: name
      integer :: link
      logical :: slider
      character(len=:), allocatable :: point
      real(wp), allocatable :: s(:), v(:), a(:)
      type(error_t), allocatable :: err
      name = ""
      call output_motion(topo, drawing, table, k, output_link, link, slider, point, s, v, a, err)
      if (link > 0) name = trim(topo%links(link)%name)
    end function output_name

    !> The drawings of the positions (placed) and one drawing of all their points with the
    !> position's own (all_positions: the view's extent).
    subroutine position_drawings()
      integer :: i, j
      type(error_t), allocatable :: err
      all_positions = drawing
      allocate (placed(n_positions))
      do i = 1, n_positions
        call drawing_from_sketch(topo, positions, 1 + (i - 1) * every, placed(i), err)
        if (allocated(err)) then
          planned = .false.
          return
        end if
        do j = 1, size(placed(i)%points)
          call all_positions%add_point("~"//int_str(i)//trim(placed(i)%points(j)%name), placed(i)%points(j)%p, &
            point_plain)
        end do
      end do
    end subroutine position_drawings

    !> The plan of positions: each position's links as thin lines (the extreme position 0
    !> thicker), the traced point's trajectory through the run at the positions' angles and
    !> its places numbered 0 .. n_positions-1, the crank pin's places numbered as well.
    subroutine put_positions()
      integer :: i, b, j, cx, cy, r, n
      character(len=:), allocatable :: pin_name
      real(wp) :: p(2), c(2), d(2), w
      real(wp), allocatable :: sx(:), sy(:)
      do i = 1, n_positions
        w = 0.2_wp
        if (i == 1) w = 0.45_wp
        do b = 1, size(placed(i)%bodies)
          associate (body => placed(i)%bodies(b))
            if (.not. allocated(body%points)) cycle
            if (size(body%points) >= 2) then
              allocate (sx(size(body%points)), sy(size(body%points)))
              do j = 1, size(body%points)
                p = view%point(placed(i)%points(body%points(j))%p)
                sx(j) = p(1)
                sy(j) = p(2)
              end do
              call sheet%polyline(sx, sy, stroke="#7f7f7f", width=w)
              deallocate (sx, sy)
            else if (size(body%points) == 1 .and. body%kind == body_block) then
              p = view%point(placed(i)%points(body%points(1))%p)
              d = view%direction([cos(body%angle), sin(body%angle)])
              c = [-d(2), d(1)]
              sx = p(1) + [-2.5_wp * d(1) - 1.5_wp * c(1), 2.5_wp * d(1) - 1.5_wp * c(1), &
                2.5_wp * d(1) + 1.5_wp * c(1), -2.5_wp * d(1) + 1.5_wp * c(1)]
              sy = p(2) + [-2.5_wp * d(2) - 1.5_wp * c(2), 2.5_wp * d(2) - 1.5_wp * c(2), &
                2.5_wp * d(2) + 1.5_wp * c(2), -2.5_wp * d(2) + 1.5_wp * c(2)]
              call sheet%polygon(sx, sy, stroke="#7f7f7f", width=w, fill="none")
              deallocate (sx, sy)
            end if
          end associate
        end do
      end do
      ! the traced point's trajectory over the run at the positions' angles
      if (len(traced) > 0) then
        cx = positions%column_index("x_"//traced)
        cy = positions%column_index("y_"//traced)
        if (cx > 0 .and. cy > 0) then
          n = min(positions%row_count(), n_positions * every + 1)
          allocate (sx(n), sy(n))
          do r = 1, n
            p = view%point([positions%rows(cx, r), positions%rows(cy, r)])
            sx(r) = p(1)
            sy(r) = p(2)
          end do
          call sheet%polyline(sx, sy, stroke="#9467bd", width=0.35_wp, dash="2 1")
          deallocate (sx, sy)
        end if
      end if
      ! the places of the traced point and the crank pin as dots, before the mechanism (its
      ! labels keep clear of them)
      pin_name = crank_pin()
      if (len(traced) > 0) call place_dots(traced, "#9467bd")
      if (len(pin_name) > 0 .and. pin_name /= traced) call place_dots(pin_name, "#000000")
    end subroutine put_positions

    !> A dot at every position's place of point `name` (none when the run has no position
    !> columns of it).
    subroutine place_dots(name, colour)
      character(*), intent(in) :: name, colour
      real(wp) :: p(2)
      integer :: i, r, cx, cy
      cx = positions%column_index("x_"//name)
      cy = positions%column_index("y_"//name)
      if (cx == 0 .or. cy == 0) return
      do i = 1, n_positions
        r = 1 + (i - 1) * every
        p = view%point([positions%rows(cx, r), positions%rows(cy, r)])
        call sheet%circle(p(1), p(2), 0.5_wp, stroke=colour, width=0.25_wp, fill=colour)
      end do
    end subroutine place_dots

    !> The positions' numbers at the traced point and the crank pin (after every line and
    !> dot, so that they keep clear of them), and the foot: position 0's angle and the step.
    subroutine put_position_numbers()
      integer :: cx, cy, cut
      real(wp) :: size
      character(len=:), allocatable :: pin_name, foot
      pin_name = crank_pin()
      if (len(traced) > 0) then
        cx = positions%column_index("x_"//traced)
        cy = positions%column_index("y_"//traced)
        if (cx > 0 .and. cy > 0) call number_places(cx, cy, "#9467bd")
      end if
      if (len(pin_name) > 0 .and. pin_name /= traced) then
        cx = positions%column_index("x_"//pin_name)
        cy = positions%column_index("y_"//pin_name)
        if (cx > 0 .and. cy > 0) call number_places(cx, cy, "#000000")
      end if
      if (positions%input_column > 0) then
        foot = words("position 0: the extreme position of link ", &
          "положение 0: крайнее положение звена ", lang)//output_name()
        foot = foot//", φ1 = "//fixed_number(modulo(positions%rows(positions%input_column, 1), 360.0_wp), 2)//" "// &
          unit_word("deg", lang)//words("; the positions every ", "; положения через ", lang)// &
          fixed_number(360.0_wp / real(n_positions, wp), 0)//" "//unit_word("deg", lang)
        ! (smaller where the column is too narrow for it at 2.4 mm: A3; on two lines, broken
        ! after the position's angle, where one would be smaller than 1.8 mm: A4)
        cut = index(foot, "; ", back=.true.)
        if (fitted_size(foot, 2.4_wp, cw - 4.0_wp, 0.6_wp) < 1.8_wp .and. cut > 0) then
          size = min(2.4_wp, fitted_size(foot(:cut), 2.4_wp, cw - 4.0_wp, 0.6_wp), &
            fitted_size(foot(cut + 2:), 2.4_wp, cw - 4.0_wp, 0.6_wp))
          call sheet%text(region(1) + 2.0_wp, region(4) - 7.5_wp - 1.3_wp * size, foot(:cut), "small", size=size)
          call sheet%text(region(1) + 2.0_wp, region(4) - 7.5_wp, foot(cut + 2:), "small", size=size)
        else if (fitted_size(foot, 2.4_wp, cw - 4.0_wp, 0.6_wp) < 2.4_wp) then
          call sheet%text(region(1) + 2.0_wp, region(4) - 7.5_wp, foot, "small", size=fitted_size(foot, 2.4_wp, &
            cw - 4.0_wp, 0.6_wp))
        else
          call sheet%text(region(1) + 2.0_wp, region(4) - 7.5_wp, foot, "small")
        end if
      end if
    end subroutine put_position_numbers

    !> The numbers 0 .. n_positions-1 of the positions beside the places (dots: place_dots) of
    !> the point whose position columns are cx, cy, away from the places' centre.
    subroutine number_places(cx, cy, colour)
      integer, intent(in) :: cx, cy
      character(*), intent(in) :: colour
      real(wp) :: p(2), c(2), d(2)
      integer :: i, r
      c = 0.0_wp
      do i = 1, n_positions
        r = 1 + (i - 1) * every
        c = c + view%point([positions%rows(cx, r), positions%rows(cy, r)]) / real(n_positions, wp)
      end do
      do i = 1, n_positions
        r = 1 + (i - 1) * every
        p = view%point([positions%rows(cx, r), positions%rows(cy, r)])
        d = p - c
        call sheet%place_label(int_str(i - 1), "small", p(1), p(2), atan2(d(2), d(1)), &
          [region(1) + 1.0_wp, region(2) + 7.0_wp, region(3) - 1.0_wp, region(4) - 11.0_wp], colour=colour)
      end do
    end subroutine number_places

    !> The crank pin: the input unit's first link's first point that is not a pivot ("" none).
    function crank_pin() result(name)
      character(len=:), allocatable :: name
      integer :: g, j, l
      name = ""
      do g = 1, size(groups)
        if (.not. groups(g)%input) cycle
        if (size(groups(g)%links) == 0) cycle
        l = groups(g)%links(1)
        do j = 1, size(topo%links(l)%points)
          if (allocated(topo%pivots)) then
            if (any(topo%pivots == topo%links(l)%points(j))) cycle
          end if
          name = trim(topo%links(l)%points(j))
          return
        end do
      end do
    end function crank_pin

    !> The traced point: the centre of mass of the first link of the first group after the
    !> input units, when the table has its position ("" otherwise).
    function traced_point() result(name)
      character(len=:), allocatable :: name
      integer :: g, j
      name = ""
      do g = 1, size(groups)
        if (groups(g)%input) cycle
        do j = 1, size(groups(g)%links)
          name = "S"//trim(topo%links(groups(g)%links(j))%name)
          if (table%column_index("x_"//name) > 0) return
        end do
        name = ""
        return
      end do
    end function traced_point

    !> The trajectory of point `name` over the rows, through the view.
    subroutine put_trajectory(name)
      character(*), intent(in) :: name
      real(wp), allocatable :: sx(:), sy(:)
      real(wp) :: p(2)
      integer :: r, cx, cy
      cx = table%column_index("x_"//name)
      cy = table%column_index("y_"//name)
      allocate (sx(size(table%rows, 2)), sy(size(table%rows, 2)))
      do r = 1, size(table%rows, 2)
        p = view%point([table%rows(cx, r), table%rows(cy, r)])
        sx(r) = p(1)
        sy(r) = p(2)
      end do
      call sheet%polyline(sx, sy, stroke="#9467bd", width=0.35_wp, dash="2 1")
    end subroutine put_trajectory

    !> The units of the structure, n, p5, W and the formula in the panel (x0, y0, w, h).
    subroutine put_structure(x0, y0, w, h)
      real(wp), intent(in) :: x0, y0, w, h
      character(len=96), allocatable :: cells(:, :)
      character(len=:), allocatable :: formula, names
      integer :: g, j, n, p5
      call sheet%set_layer(layer_charts)
      call sheet%rect(x0, y0, w, h, "panel")
      call sheet%text(x0 + 2.0_wp, y0 + 5.0_wp, words("Structure of the mechanism", "Структура механизма", &
        lang), &
        "heading")
      allocate (cells(size(groups) + 1, 3))
      cells = ""
      cells(1, :) = [character(len=96) :: words("unit", "группа", lang), words("links", "звенья", lang), &
        words("kind", "вид", lang)]
      formula = ""
      do g = 1, size(groups)
        names = ""
        do j = 1, size(groups(g)%links)
          if (j > 1) names = names//", "
          names = names//trim(topo%links(groups(g)%links(j))%name)
        end do
        cells(g + 1, 1) = groups(g)%label
        cells(g + 1, 2) = names
        select case (groups(g)%class)
        case (1)
          cells(g + 1, 3) = words("input link (class I)", "начальное звено (I класс)", lang)
        case (2)
          cells(g + 1, 3) = words("dyad: group of class II, order 2", &
            "диада: группа II класса 2-го порядка", lang)
        case (3)
          cells(g + 1, 3) = words("group of class III", "группа III класса", lang)
        case default
          cells(g + 1, 3) = words("group", "группа", lang)
        end select
        if (g > 1) formula = formula//" → "
        formula = formula//groups(g)%label
      end do
      if (part_drawn == 0) then
        call put_table(sheet, x0 + 4.0_wp, y0 + 9.0_wp, [0.22_wp * w, 0.2_wp * w, 0.5_wp * w], 4.5_wp, cells)
      else
        ! (A4: the columns as wide as their longest cells, 2.4 mm characters 0.6 of it wide)
        call put_table(sheet, x0 + 4.0_wp, y0 + 9.0_wp, fitted_columns(cells, 0.92_wp * w), 4.5_wp, cells)
      end if
      n = size(topo%links)
      p5 = lower_pairs()
      call sheet%set_layer(layer_text)
      call sheet%text(x0 + 4.0_wp, y0 + 9.0_wp + 4.5_wp * size(cells, 1) + 6.0_wp, words("structure formula: ", &
        "формула строения: ", lang)//formula, "label")
      call sheet%text(x0 + 4.0_wp, y0 + 9.0_wp + 4.5_wp * size(cells, 1) + 11.0_wp, "n = "//int_str(n)//",  p5 = "// &
        int_str(p5)//",  p4 = 0,  W = 3n − 2p5 − p4 = "//int_str(3 * n - 2 * p5), "label")
      call put_pairs(x0 + 4.0_wp, y0 + 9.0_wp + 4.5_wp * size(cells, 1) + 17.0_wp, w - 8.0_wp)
    end subroutine put_structure

    !> Widths of a table's columns that share `w` mm as their longest cells' lengths (in
    !> characters, UTF-8's continuation bytes not counted, plus two a cell).
    pure function fitted_columns(cells, w) result(widths)
      character(*), intent(in) :: cells(:, :)
      real(wp), intent(in) :: w
      real(wp) :: widths(size(cells, 2))
      integer :: c, r
      widths = 2.0_wp
      do c = 1, size(cells, 2)
        do r = 1, size(cells, 1)
          widths(c) = max(widths(c), 2.0_wp + real(char_count(trim(cells(r, c))), wp))
        end do
      end do
      widths = w * widths / sum(widths)
    end function fitted_columns

    !> The table of the kinematic pairs: at every point the links joined there (the frame at a
    !> pivot), a turning pair (В) between each further link and the first; every slider a
    !> sliding pair (П); all lower pairs of class V.
    subroutine put_pairs(x0, y0, w)
      real(wp), intent(in) :: x0, y0, w
      character(len=64), allocatable :: cells(:, :)
      character(len=16), allocatable :: seen(:), at(:)
      character(len=16) :: pn
      character(len=:), allocatable :: frame
      integer :: i, j, l2, m
      frame = "0"
      if (size(groups) > 0) then
        if (allocated(groups(1)%label)) then
          if (index(groups(1)%label, "I(") == 1 .and. index(groups(1)%label, ",") > 3) then
            frame = groups(1)%label(3:index(groups(1)%label, ",") - 1)
          end if
        end if
      end if
      allocate (cells(1, 4), seen(0))
      cells(1, :) = [character(len=64) :: words("pair", "пара", lang), words("links", "звенья", lang), &
        words("kind", "вид", lang), words("class", "класс", lang)]
      do i = 1, size(topo%links)
        do j = 1, size(topo%links(i)%points)
          pn = topo%links(i)%points(j)
          if (any(seen == pn)) cycle
          seen = [character(len=16) :: seen, pn]
          allocate (at(0))
          if (allocated(topo%pivots)) then
            if (any(topo%pivots == pn)) at = [character(len=16) :: frame]
          end if
          do l2 = 1, size(topo%links)
            if (lists(topo, l2, trim(pn)) .and. .not. sliding_on(topo, l2, trim(pn))) then
              at = [character(len=16) :: at, topo%links(l2)%name]
            end if
          end do
          do m = 2, size(at)
            cells = reshape([character(len=64) :: transpose(cells), trim(pn), trim(at(1))//"–"//trim(at(m)), &
              words("turning", "вращательная", lang), "V"], [size(cells, 1) + 1, 4], order=[2, 1])
          end do
          deallocate (at)
        end do
      end do
      do i = 1, size(slides)
        if (.not. slide_is_pair(topo, slides, i)) cycle
        if (slides(i)%g > 0) then
          pn = topo%links(slides(i)%g)%name
        else
          pn = frame
        end if
        cells = reshape([character(len=64) :: transpose(cells), trim(slides(i)%name), &
          trim(topo%links(slides(i)%m)%name)//"–"//trim(pn), words("sliding", "поступательная", lang), "V"], &
          [size(cells, 1) + 1, 4], order=[2, 1])
      end do
      call sheet%set_layer(layer_text)
      call sheet%text(x0, y0, words("Kinematic pairs", "Кинематические пары", lang), "label")
      call put_table(sheet, x0, y0 + 2.0_wp, [0.16_wp * w, 0.16_wp * w, 0.3_wp * w, 0.12_wp * w], 4.2_wp, cells)
    end subroutine put_pairs

    !> The lower pairs of the sketch: at every point, the links listing it (not as a sliding
    !> contact) and the frame for a pivot, less one; and every slider that is a pair.
    integer function lower_pairs() result(p5)
      character(len=16), allocatable :: seen(:)
      character(len=16) :: pn
      integer :: i, j, m, l2
      p5 = 0
      allocate (seen(0))
      do i = 1, size(topo%links)
        do j = 1, size(topo%links(i)%points)
          pn = topo%links(i)%points(j)
          if (any(seen == pn)) cycle
          seen = [character(len=16) :: seen, pn]
          m = count([(lists(topo, l2, trim(pn)) .and. .not. sliding_on(topo, l2, trim(pn)), l2=1, size(topo%links))])
          if (allocated(topo%pivots)) then
            if (any(topo%pivots == pn)) m = m + 1
          end if
          p5 = p5 + max(0, m - 1)
        end do
      end do
      do i = 1, size(slides)
        if (slide_is_pair(topo, slides, i)) p5 = p5 + 1
      end do
    end function lower_pairs

    !> s, v, a (a slider on a guide of the frame) or psi, omega, eps (a rocker) of the output
    !> link over the input angle, in column 2.
    subroutine output_diagrams()
      integer :: out_link
      real(wp), allocatable :: s(:), v(:), a(:), s0(:), v0(:), a0(:)
      character(len=:), allocatable :: name, point, from_extreme
      logical :: slider, far
      type(error_t), allocatable :: err
      call output_motion(topo, drawing, table, k, output_link, out_link, slider, point, s, v, a, err)
      if (allocated(err) .or. out_link == 0) return
      name = trim(topo%links(out_link)%name)
      ! from the extreme position 0 of the plan of positions (without a plan, the smallest)
      far = .false.
      if (planned) then
        call output_motion(topo, drawing, positions, 1, output_link, out_link, slider, point, s0, v0, a0, err)
        if (.not. allocated(err) .and. size(s0) > 0) far = abs(s0(1) - maxval(s)) < abs(s0(1) - minval(s))
      end if
      if (far) then
        s = maxval(s) - s
        v = -v
        a = -a
      else
        s = s - minval(s)
      end if
      from_extreme = words(" from its extreme position", " от крайнего положения", lang)
      if (slider) then
        call put_diagram(s, "m", "s", words("Displacement of link ", "Перемещение звена ", lang)//name// &
          from_extreme, "s"//name, .false.)
        call put_diagram(v, "m/s", "v", words("Velocity of link ", "Скорость звена ", lang)//name, "v_"//point, &
          .true.)
        call put_diagram(a, "m/s^2", "a", words("Acceleration of link ", "Ускорение звена ", lang)//name, &
          "a_"//point, .true.)
      else
        call put_diagram(s, "deg", "ψ", words("Angle of link ", "Угол поворота звена ", lang)//name// &
          from_extreme, "ψ"//name, .false.)
        call put_diagram(v, "rad/s", "ω", words("Angular velocity of link ", "Угловая скорость звена ", &
          lang)//name, "ω"//name, .true.)
        call put_diagram(a, "rad/s^2", "ε", words("Angular acceleration of link ", &
          "Угловое ускорение звена ", lang)//name, "ε"//name, .true.)
      end if
    end subroutine output_diagrams

    !> One diagram of output_diagrams over the input angle, below the one before (`below`).
    subroutine put_diagram(values, unit, symbol, title, curve_name, below)
      !> The values.
      real(wp), intent(in) :: values(:)
      !> Their unit (as the sheet's language writes it) and symbol on the axis.
      character(*), intent(in) :: unit, symbol
      !> The diagram's title and the curve's name.
      character(*), intent(in) :: title, curve_name
      !> Whether a diagram stands above it.
      logical, intent(in) :: below
      if (below) y = y + q%height + 26.0_wp + q%head + gap
      call put_cycle_chart(sheet, x2, y, cw, hmax, phi, mu_phi, values, unit_word(unit, lang), symbol, title, &
        "φ1, "//unit_word("deg", lang), lang, q)
      call put_cycle_curve(sheet, q, phi, values, "#1f77b4", "", curve_name)
    end subroutine put_diagram

    !> The values at the position: the points' speeds and accelerations, the links' ω and ε.
    subroutine put_values(x0, y0, w, h)
      real(wp), intent(in) :: x0, y0, w, h
      character(len=40), allocatable :: cells(:, :)
      real(wp) :: vv(2), aa(2)
      integer :: ip, il, r, n, r_points
      character(len=:), allocatable :: pname
      call sheet%set_layer(layer_charts)
      call sheet%rect(x0, y0, w, h, "panel")
      call sheet%text(x0 + 2.0_wp, y0 + 5.0_wp, words("Values in position ", "Значения в положении ", lang)// &
        int_str(table%run_row(k)), "heading")
      n = 1 + size(drawing%points) + 1 + size(topo%links)
      allocate (cells(n, 3))
      cells = ""
      cells(1, :) = [character(len=40) :: words("point", "точка", lang), "v, "//unit_word("m/s", lang), &
        "a, "//unit_word("m/s^2", lang)]
      r = 1
      do ip = 1, size(drawing%points)
        pname = trim(drawing%points(ip)%name)
        if (table%column_index("vx_"//pname) == 0) cycle
        vv = [column_value(table, "vx_"//pname, k), column_value(table, "vy_"//pname, k)]
        aa = [column_value(table, "ax_"//pname, k), column_value(table, "ay_"//pname, k)]
        r = r + 1
        cells(r, :) = [character(len=40) :: pname, short_number(norm2(vv)), short_number(norm2(aa))]
      end do
      r_points = r
      r = r + 1
      cells(r, :) = [character(len=40) :: words("link", "звено", lang), "ω, "//unit_word("rad/s", lang), &
        "ε, "//unit_word("rad/s^2", lang)]
      do il = 1, size(topo%links)
        if (table%column_index("omega"//trim(topo%links(il)%name)) == 0) cycle
        r = r + 1
        cells(r, :) = [character(len=40) :: trim(topo%links(il)%name), &
          short_number(column_value(table, "omega"//trim(topo%links(il)%name), k)), &
          short_number(column_value(table, "eps"//trim(topo%links(il)%name), k))]
      end do
      call sheet%set_layer(layer_text)
      if (compact) then
        ! (the points' table and the links' beside it, their first columns narrower)
        associate (half => 0.5_wp * (w - 11.0_wp))
          call put_table(sheet, x0 + 4.0_wp, y0 + 9.0_wp, [0.26_wp * half, 0.37_wp * half, 0.37_wp * half], &
            compact_pitch, cells(1:r_points, :))
          call put_table(sheet, x0 + 7.0_wp + half, y0 + 9.0_wp, [0.26_wp * half, 0.37_wp * half, 0.37_wp * half], &
            compact_pitch, cells(r_points + 1:r, :))
        end associate
      else
        call put_table(sheet, x0 + 4.0_wp, y0 + 9.0_wp, [0.3_wp * w, 0.3_wp * w, 0.3_wp * w], 4.2_wp, cells(1:r, :))
      end if
    end subroutine put_values
  end subroutine draw_kinematics_sheet

  !> The output link's motion over the rows of `table` (the positions of row `k` give the
  !> structure): a slider on a guide of the frame: its point's coordinate s along the guide
  !> (m), its velocity and acceleration along it (m/s, m/s^2); any other link (a rocker):
  !> its angle ψ (deg), ω (rad/s), ε (rad/s^2). `asked` is the link's number (--output-link;
  !> 0: the last link of the last group); `link` its index in topo%links (0 with `error`
  !> when there is no such link or the table lacks its columns).
  pure subroutine output_motion(topo, drawing, table, k, asked, link, slider, point, s, v, a, error)
    type(sketch_t), intent(in) :: topo
    type(drawing_t), intent(in) :: drawing
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: k, asked
    integer, intent(out) :: link
    logical, intent(out) :: slider
    character(len=:), allocatable, intent(out) :: point
    real(wp), allocatable, intent(out) :: s(:), v(:), a(:)
    type(error_t), allocatable, intent(out) :: error
    type(slide_t), allocatable :: slides(:)
    type(plan_group_t), allocatable :: groups(:)
    character(len=:), allocatable :: driver, name, known
    real(wp) :: u(2)
    integer :: g, cx, cy, cvx, cvy, cax, cay, n
    link = 0
    slider = .false.
    point = ""
    n = table%row_count()
    allocate (s(0), v(0), a(0))
    if (asked > 0) then
      known = ""
      do g = 1, size(topo%links)
        if (trim(topo%links(g)%name) == int_str(asked)) link = g
        if (g > 1) known = known//", "
        known = known//trim(topo%links(g)%name)
      end do
      if (link == 0) then
        call fatal_error(error, exit_input, "--output-link "//int_str(asked)//": "//table%deck// &
          " has no link "//int_str(asked)//" (links: "//known//")")
        return
      end if
    else
      call slides_of(topo, drawing, table, k, slides)
      driver = ""
      if (allocated(table%driver)) driver = table%driver
      call plan_groups(topo, drawing, table, slides, driver, groups)
      do g = size(groups), 1, -1
        if (size(groups(g)%links) > 0) then
          link = groups(g)%links(size(groups(g)%links))
          exit
        end if
      end do
      if (link == 0) then
        call fatal_error(error, exit_input, table%deck//": no output link found (give --output-link)")
        return
      end if
    end if
    name = trim(topo%links(link)%name)
    if (allocated(topo%guides)) then
      do g = 1, size(topo%guides)
        if (allocated(topo%guides(g)%on)) then
          if (len(topo%guides(g)%on) > 0) cycle
        end if
        if (lists(topo, link, trim(topo%guides(g)%point))) then
          slider = .true.
          point = trim(topo%guides(g)%point)
          u = [cos(topo%guides(g)%angle * deg_to_rad), sin(topo%guides(g)%angle * deg_to_rad)]
          exit
        end if
      end do
    end if
    if (slider) then
      cx = table%column_index("x_"//point)
      cy = table%column_index("y_"//point)
      cvx = table%column_index("vx_"//point)
      cvy = table%column_index("vy_"//point)
      cax = table%column_index("ax_"//point)
      cay = table%column_index("ay_"//point)
      if (min(cx, cy, cvx, cvy, cax, cay) > 0) then
        s = table%rows(cx, 1:n) * u(1) + table%rows(cy, 1:n) * u(2)
        v = table%rows(cvx, 1:n) * u(1) + table%rows(cvy, 1:n) * u(2)
        a = table%rows(cax, 1:n) * u(1) + table%rows(cay, 1:n) * u(2)
        return
      end if
    else
      cx = table%column_index("phi"//name)
      cvx = table%column_index("omega"//name)
      cax = table%column_index("eps"//name)
      if (min(cx, cvx, cax) > 0) then
        s = table%rows(cx, 1:n)
        v = table%rows(cvx, 1:n)
        a = table%rows(cax, 1:n)
        return
      end if
    end if
    call fatal_error(error, exit_input, "--output-link "//name//": "//table%deck//": link "//name// &
      " has no motion columns (a slider on a guide of the frame, or a link's angle)")
    link = 0
  end subroutine output_motion

end module kinetostat_kinematics_sheet
