!> The plans sheet (`--format plans --at K`): the graphical method at one step on one A4
!> sheet, as the course draws it beside the analytic table:
!> - the plan of velocities: pole p, the image of every joint and centre of mass (its name
!>   in lower case: b, c, s2), scale mu_v in (m/s)/mm;
!> - the plan of accelerations: pole pi, the images, scale mu_a in (m/s^2)/mm;
!> - Zhukovsky's lever: the velocity plan turned 90 deg counterclockwise, every load drawn at
!>   its point's image, the balancing effort from the lever's moment equation beside the
!>   analytic value of the step;
!> - the force polygon of every Assur group (the last attached first) and of the input link:
!>   the known forces, then the unknown reactions (tangential parts, then normal parts), head
!>   to tail at one scale mu_F in N/mm; the input link's with its balancing moment.
!> The numbers come from kinetostat_plans; labels are placed by kinetostat_label_place (no
!> two overlap); words from kinetostat_labels.
module kinetostat_svg_plans
  use kinetostat_kinds, only: wp, pi, version_string
  use kinetostat_text, only: int_str, lower
  use kinetostat_format, only: short_number
  use kinetostat_step_table, only: step_table_t
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_svg, only: svg_open, svg_close, svg_line, svg_rect, svg_text, svg_arrow, svg_circle, palette_colour
  use kinetostat_label_place, only: label_boxes_t, title_attributes, anchor_start
  use kinetostat_labels, only: word => label, unit_word => unit_symbol
  use kinetostat_title_block, only: put_title_block, title_block_height
  use kinetostat_plans_base, only: plans_t, plan_vector_t, plan_equation_t, component_normal, component_tangential, &
    component_coriolis
  use kinetostat_plans_sheet, only: plan_scale, chain_tips, polygon_tips
  implicit none
  private
  public :: write_svg_plans

  !> Sheet width and height (A4), mm.
  real(wp), parameter :: page_width = 210.0_wp, page_height = 297.0_wp
  !> Font sizes of the classes "label" and "num", mm.
  real(wp), parameter :: label_size = 2.8_wp, num_size = 2.2_wp

contains

  !> The plans sheet of row `k`.
  pure subroutine write_svg_plans(title, table, k, plans, lang, out)
    !> Title of the mechanism.
    character(*), intent(in) :: title
    !> The results.
    type(step_table_t), intent(in) :: table
    !> Row (1-based).
    integer, intent(in) :: k
    !> The plans of that row.
    type(plans_t), intent(in) :: plans
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    !> Where the lines go.
    type(text_buffer_t), intent(inout) :: out
    type(label_boxes_t) :: boxes
    type(plan_vector_t), allocatable :: turned(:)
    character(len=:), allocatable :: line
    real(wp) :: y, sheet_height
    integer :: i

    sheet_height = page_height
    if (allocated(table%student_stamp)) sheet_height = page_height + title_block_height
    call svg_open(out, page_width, sheet_height, title//" - "//table%deck//" - plans, "//table%row_name//" "// &
      int_str(k), "kinetostat --format plans --at "//int_str(k)//" sheet of "//table%deck// &
      ": plans of velocities and accelerations, force polygons, Zhukovsky's lever.")
    call out%put(svg_text(12.0_wp, 15.0_wp, title, title_attributes(title, "title", 3.3_wp, 186.0_wp)))
    line = word("deck", lang)//": "//table%deck
    call out%put(svg_text(12.0_wp, 20.5_wp, line, title_attributes(line, "subtitle", 3.0_wp, 186.0_wp)))
    line = word(table%row_name, lang)//" "//int_str(k)//" "//word("of", lang)//" "//int_str(table%row_count())
    if (table%input_column > 0) line = line//": "//table%columns(table%input_column)%name//" = "// &
      short_number(table%rows(table%input_column, k))//" "//unit_word(table%columns(table%input_column)%unit, lang)
    line = line//"; "//version_string
    call out%put(svg_text(12.0_wp, 25.5_wp, line, 'class="small"'))

    call put_plan(out, boxes, plans%velocities, [12.0_wp, 32.0_wp, 91.0_wp, 88.0_wp], &
      word("Plan of velocities", lang), "p", "μv", unit_word("m/s", lang), lang, plans%velocity_equations)
    call put_plan(out, boxes, plans%accelerations, [107.0_wp, 32.0_wp, 91.0_wp, 88.0_wp], &
      word("Plan of accelerations", lang), "π", "μa", unit_word("m/s^2", lang), lang, plans%equations)
    ! the lever: the velocity plan turned by 90 deg, the loads at their images
    allocate (turned(size(plans%velocities)))
    do i = 1, size(plans%velocities)
      turned(i)%name = plans%velocities(i)%name
      turned(i)%v = [-plans%velocities(i)%v(2), plans%velocities(i)%v(1)]
    end do
    call put_lever(out, boxes, plans, turned, [12.0_wp, 126.0_wp, 91.0_wp, 100.0_wp], lang)
    call put_polygons(out, boxes, plans, [107.0_wp, 126.0_wp, 91.0_wp, 100.0_wp], lang)

    ! the lever's result against the analytic one
    y = 236.0_wp
    call out%put(svg_text(107.0_wp, y - 7.5_wp, word("Force polygons", lang)//":", 'class="small"'))
    call out%put(svg_text(107.0_wp, y - 4.5_wp, word("known forces first, then the unknown reactions", lang)//".", &
      'class="small"'))
    call out%put(svg_text(12.0_wp, y - 7.5_wp, word("plan of velocities turned by 90 deg", lang)//";", 'class="small"'))
    call out%put(svg_text(12.0_wp, y - 4.5_wp, word("arrows: directions of the loads", lang)//".", 'class="small"'))
    call out%put(svg_text(12.0_wp, y + 2.0_wp, word("Zhukovsky's lever", lang), 'class="heading"'))
    y = y + 2.0_wp
    if (plans%lever_known) then
      call out%put(svg_text(12.0_wp, y + 6.0_wp, word("balancing effort from the lever", lang)//": "// &
        plans%driver//" = "//short_number(plans%effort)//" "//effort_unit(plans%driver, lang), 'class="label"'))
      if (plans%lever_flywheel) then
        ! the flywheel and the rotor of the true motion: their inertia moment on the driving link
        call out%put(svg_text(12.0_wp, y + 11.0_wp, word("flywheel and rotor included", lang)//": J = "// &
          short_number(plans%flywheel_inertia)//" "//unit_word("kg*m^2", lang)//", -J·ε = "// &
          short_number(plans%flywheel_moment)//" "//unit_word("N*m", lang), 'class="label"'))
        y = y + 5.0_wp
      end if
      if (plans%lever_friction) then
        ! the pairs' friction on the lever: its share of the effort, -P_loss over the driver's rate
        call out%put(svg_text(12.0_wp, y + 11.0_wp, word("pair friction included", lang)//": -P_loss/"// &
          rate_symbol(plans%lever_rate_name)//" = "//short_number(plans%friction_share)//" "// &
          effort_unit(plans%driver, lang), 'class="label"'))
        y = y + 5.0_wp
      end if
      call out%put(svg_text(12.0_wp, y + 11.0_wp, word("analytic value of the step", lang)//": "// &
        plans%driver//" = "//short_number(plans%run)//" "//effort_unit(plans%driver, lang), 'class="label"'))
      call out%put(svg_text(12.0_wp, y + 16.0_wp, word("relative difference", lang)//": "// &
        short_number(abs(plans%effort - plans%run) / max(abs(plans%run), tiny(1.0_wp))), 'class="label"'))
    else
      call out%put(svg_text(12.0_wp, y + 6.0_wp, word("not drawn", lang)//": "//word(plans%lever_note, lang), &
        'class="label"'))
    end if
    call put_title_block(out, table, lang, page_width, sheet_height, word("Plans of velocities, accelerations, forces", &
      lang))
    call svg_close(out)
  end subroutine write_svg_plans

  !> The lever's rate as the sheet writes it: omega1 as ω1, v_rel as it is.
  pure function rate_symbol(name) result(symbol)
    character(*), intent(in) :: name
    character(len=:), allocatable :: symbol
    if (index(name, "omega") == 1) then
      symbol = "ω"//name(6:)
    else
      symbol = name
    end if
  end function rate_symbol

  !> N*m for a moment (M...), N for a force.
  pure function effort_unit(name, lang) result(unit)
    character(*), intent(in) :: name
    integer, intent(in) :: lang
    character(len=:), allocatable :: unit
    if (name(1:1) == "M") then
      unit = unit_word("N*m", lang)
    else
      unit = unit_word("N", lang)
    end if
  end function effort_unit

  !> A panel's frame and heading; the drawing area inside it (x0, y0, x1, y1).
  pure subroutine put_panel(out, boxes, box, heading, inner)
    type(text_buffer_t), intent(inout) :: out
    type(label_boxes_t), intent(inout) :: boxes
    real(wp), intent(in) :: box(4)
    character(*), intent(in) :: heading
    real(wp), intent(out) :: inner(4)
    call out%put(svg_rect(box(1), box(2), box(3), box(4), 'class="panel"'))
    call out%put(svg_text(box(1) + 2.0_wp, box(2) + 5.0_wp, heading, 'class="heading"'))
    call boxes%reserve(box(1) + 2.0_wp, box(2) + 5.0_wp, heading, 3.2_wp, anchor_start)
    inner = [box(1) + 3.0_wp, box(2) + 8.0_wp, box(1) + box(3) - 3.0_wp, box(2) + box(4) - 8.0_wp]
  end subroutine put_panel

  !> Scale (units per mm, a nice number) and pole (page, mm) that fit the vectors from the
  !> pole into `inner`, the pole included.
  pure subroutine fit(vectors, inner, mu, pole)
    real(wp), intent(in) :: vectors(:, :), inner(4)
    real(wp), intent(out) :: mu, pole(2)
    real(wp) :: lo(2), hi(2), span
    lo = 0.0_wp
    hi = 0.0_wp
    if (size(vectors, 2) > 0) then
      lo = min(lo, minval(vectors, 2))
      hi = max(hi, maxval(vectors, 2))
    end if
    span = max((hi(1) - lo(1)) / (inner(3) - inner(1)), (hi(2) - lo(2)) / (inner(4) - inner(2)))
    mu = 1.0_wp
    if (span > 0.0_wp) mu = plan_scale(span)
    pole(1) = 0.5_wp * (inner(1) + inner(3)) - 0.5_wp * (lo(1) + hi(1)) / mu
    pole(2) = 0.5_wp * (inner(2) + inner(4)) + 0.5_wp * (lo(2) + hi(2)) / mu
  end subroutine fit

  !> A plan: the pole, a ray to the image of every point (its name in lower case), the scale.
  pure subroutine put_plan(out, boxes, images, box, heading, pole_name, mu_name, unit, lang, equations)
    type(text_buffer_t), intent(inout) :: out
    type(label_boxes_t), intent(inout) :: boxes
    type(plan_vector_t), intent(in) :: images(:)
    real(wp), intent(in) :: box(4)
    character(*), intent(in) :: heading, pole_name, mu_name, unit
    integer, intent(in) :: lang
    !> The plan's vector equations (the acceleration plan's components), drawn head to tail
    !> from the image they start from.
    type(plan_equation_t), intent(in), optional :: equations(:)
    real(wp) :: inner(4), mu, pole(2), q(2), tx, ty
    real(wp), allocatable :: seg_x(:), seg_y(:), v(:, :), tips(:, :)
    character(len=:), allocatable :: legend
    logical :: leader
    integer :: i, j, e
    call put_panel(out, boxes, box, heading, inner)
    allocate (v(2, size(images)))
    do i = 1, size(images)
      v(:, i) = images(i)%v
    end do
    if (present(equations)) then
      ! the chains' corners must fit too
      do e = 1, size(equations)
        call chain_tips(equations(e), images, tips)
        v = reshape([v, tips], [2, size(v, 2) + size(tips, 2)])
      end do
      if (unit == unit_word("m/s", lang)) then
        legend = word("relative velocities: v_PQ of a link's points, r along a guide", lang)
      else
        legend = word("components: n normal, τ tangential, k Coriolis, r relative", lang)
      end if
      inner(4) = inner(4) - 3.0_wp
    end if
    call fit(v, inner, mu, pole)
    allocate (seg_x(0), seg_y(0))
    if (present(equations)) then
      do e = 1, size(equations)
        call chain_tips(equations(e), images, tips)
        do j = 1, size(equations(e)%vectors)
          associate (p => pole + [tips(1, j), -tips(2, j)] / mu, t => pole + [tips(1, j + 1), -tips(2, j + 1)] / mu)
            if (hypot(t(1) - p(1), t(2) - p(2)) < 0.3_wp) cycle
            call out%put(svg_arrow(p(1), p(2), t(1), t(2), component_colour(equations(e)%vectors(j)%kind), 0.25_wp, &
              1.5_wp))
            seg_x = [seg_x, p(1), t(1)]
            seg_y = [seg_y, p(2), t(2)]
          end associate
        end do
      end do
    end if
    do i = 1, size(images)
      q = pole + [v(1, i), -v(2, i)] / mu
      if (hypot(q(1) - pole(1), q(2) - pole(2)) > 0.3_wp) then
        call out%put(svg_arrow(pole(1), pole(2), q(1), q(2), "#1f77b4", 0.3_wp, 1.8_wp))
        seg_x = [seg_x, pole(1), q(1)]
        seg_y = [seg_y, pole(2), q(2)]
      end if
    end do
    call out%put(svg_circle(pole(1), pole(2), 0.7_wp, 'class="origin"'))
    seg_x = [seg_x, pole(1), pole(1)]
    seg_y = [seg_y, pole(2), pole(2)]
    call boxes%place(pole_name, label_size, pole(1), pole(2), 0.75_wp * pi, seg_x, seg_y, inner, tx, ty, leader)
    call out%put(svg_text(tx, ty, pole_name, 'class="label" font-weight="bold" text-anchor="middle"'))
    do i = 1, size(images)
      q = pole + [v(1, i), -v(2, i)] / mu
      if (hypot(q(1) - pole(1), q(2) - pole(2)) <= 0.3_wp) cycle
      call boxes%place(lower(trim(images(i)%name)), label_size, q(1), q(2), atan2(q(2) - pole(2), q(1) - pole(1)), &
        seg_x, seg_y, inner, tx, ty, leader, tail=pole)
      if (leader) call out%put(svg_line(q(1), q(2), tx, ty - 0.3_wp * label_size, 'stroke="#777777" stroke-width="0.15"'))
      call out%put(svg_text(tx, ty, lower(trim(images(i)%name)), 'class="label" font-style="italic" text-anchor="middle"'))
    end do
    if (present(equations)) then
      ! the components' names at the middle of their arrows
      do e = 1, size(equations)
        call chain_tips(equations(e), images, tips)
        do j = 1, size(equations(e)%vectors)
          associate (p => pole + [tips(1, j), -tips(2, j)] / mu, t => pole + [tips(1, j + 1), -tips(2, j + 1)] / mu)
            if (hypot(t(1) - p(1), t(2) - p(2)) < 0.3_wp) cycle
            call boxes%place(trim(equations(e)%vectors(j)%name), num_size, 0.5_wp * (p(1) + t(1)), 0.5_wp * (p(2) + &
              t(2)), atan2(t(2) - p(2), t(1) - p(1)) - 0.5_wp * pi, seg_x, seg_y, inner, tx, ty, leader)
            if (leader) call out%put(svg_line(0.5_wp * (p(1) + t(1)), 0.5_wp * (p(2) + t(2)), tx, &
              ty - 0.3_wp * num_size, 'stroke="#777777" stroke-width="0.15"'))
            call out%put(svg_text(tx, ty, trim(equations(e)%vectors(j)%name), 'class="num" text-anchor="middle" '// &
              'style="fill: '//component_colour(equations(e)%vectors(j)%kind)//'"'))
          end associate
        end do
      end do
      call out%put(svg_text(box(1) + 2.0_wp, box(2) + box(4) - 6.0_wp, legend, 'class="small"'))
      call boxes%reserve(box(1) + 2.0_wp, box(2) + box(4) - 6.0_wp, legend, 2.4_wp, anchor_start)
    end if
    call out%put(svg_text(box(1) + 2.0_wp, box(2) + box(4) - 2.5_wp, mu_name//" = "//short_number(mu)//" ("// &
      unit//")/"//unit_word("mm", lang), 'class="small"'))
    call boxes%reserve(box(1) + 2.0_wp, box(2) + box(4) - 2.5_wp, mu_name//" = "//short_number(mu)//" ("// &
      unit//")/"//unit_word("mm", lang), 2.4_wp, anchor_start)
  end subroutine put_plan

  !> Colour of an acceleration component: normal, tangential, Coriolis, relative.
  pure function component_colour(kind) result(colour)
    character(*), intent(in) :: kind
    character(len=7) :: colour
    select case (kind)
    case (component_normal)
      colour = "#2ca02c"
    case (component_tangential)
      colour = "#d62728"
    case (component_coriolis)
      colour = "#9467bd"
    case default
      colour = "#ff7f0e"
    end select
  end function component_colour


  !> Zhukovsky's lever: the turned velocity plan (thin rays), every load as an arrow at its
  !> point's turned image.
  pure subroutine put_lever(out, boxes, plans, turned, box, lang)
    type(text_buffer_t), intent(inout) :: out
    type(label_boxes_t), intent(inout) :: boxes
    type(plans_t), intent(in) :: plans
    type(plan_vector_t), intent(in) :: turned(:)
    real(wp), intent(in) :: box(4)
    integer, intent(in) :: lang
    real(wp) :: inner(4), mu, pole(2), q(2), t(2), tx, ty, fmax, fscale
    real(wp), allocatable :: seg_x(:), seg_y(:), v(:, :)
    character(len=7) :: colour
    character(len=:), allocatable :: dash
    logical :: leader
    integer :: i, n
    call put_panel(out, boxes, box, word("Zhukovsky's lever", lang), inner)
    n = 0
    if (allocated(plans%loads)) n = size(plans%loads)
    allocate (v(2, size(turned) + n))
    do i = 1, size(turned)
      v(:, i) = turned(i)%v
    end do
    do i = 1, n
      v(:, size(turned) + i) = [-plans%loads(i)%at(2), plans%loads(i)%at(1)]
    end do
    ! room for the arrows: the plan in the middle two thirds
    call fit(v, [inner(1) + 12.0_wp, inner(2) + 12.0_wp, inner(3) - 12.0_wp, inner(4) - 12.0_wp], mu, pole)
    allocate (seg_x(0), seg_y(0))
    do i = 1, size(turned)
      q = pole + [v(1, i), -v(2, i)] / mu
      call out%put(svg_line(pole(1), pole(2), q(1), q(2), 'class="faint"'))
      seg_x = [seg_x, pole(1), q(1)]
      seg_y = [seg_y, pole(2), q(2)]
    end do
    call out%put(svg_circle(pole(1), pole(2), 0.7_wp, 'class="origin"'))
    call boxes%place("p", label_size, pole(1), pole(2), 0.75_wp * pi, seg_x, seg_y, inner, tx, ty, leader)
    call out%put(svg_text(tx, ty, "p", 'class="label" font-weight="bold" text-anchor="middle"'))
    fmax = 0.0_wp
    do i = 1, n
      fmax = max(fmax, norm2(plans%loads(i)%f))
    end do
    fscale = 0.0_wp
    if (fmax > 0.0_wp) fscale = 11.0_wp / fmax
    do i = 1, n
      q = pole + [v(1, size(turned) + i), -v(2, size(turned) + i)] / mu
      t = q + fscale * [plans%loads(i)%f(1), -plans%loads(i)%f(2)]
      if (hypot(t(1) - q(1), t(2) - q(2)) < 0.3_wp) cycle
      call palette_colour(i, colour, dash)
      call out%put(svg_arrow(q(1), q(2), t(1), t(2), colour, 0.35_wp, 1.8_wp))
      seg_x = [seg_x, q(1), t(1)]
      seg_y = [seg_y, q(2), t(2)]
    end do
    do i = 1, n
      q = pole + [v(1, size(turned) + i), -v(2, size(turned) + i)] / mu
      t = q + fscale * [plans%loads(i)%f(1), -plans%loads(i)%f(2)]
      if (hypot(t(1) - q(1), t(2) - q(2)) < 0.3_wp) cycle
      call palette_colour(i, colour, dash)
      call boxes%place(trim(plans%loads(i)%name), num_size, t(1), t(2), atan2(t(2) - q(2), t(1) - q(1)), &
        seg_x, seg_y, inner, tx, ty, leader, tail=q)
      if (leader) call out%put(svg_line(t(1), t(2), tx, ty - 0.3_wp * num_size, 'stroke="#777777" stroke-width="0.15"'))
      call out%put(svg_text(tx, ty, trim(plans%loads(i)%name), 'class="num" text-anchor="middle" style="fill: '// &
        colour//'"'))
    end do
    call out%put(svg_text(box(1) + 2.0_wp, box(2) + box(4) - 2.5_wp, "μv = "//short_number(mu)//" ("// &
      unit_word("m/s", lang)//")/"//unit_word("mm", lang), &
      'class="small"'))
  end subroutine put_lever

  !> The force polygons of the links, head to tail at one scale, in a grid of cells.
  pure subroutine put_polygons(out, boxes, plans, box, lang)
    type(text_buffer_t), intent(inout) :: out
    type(label_boxes_t), intent(inout) :: boxes
    type(plans_t), intent(in) :: plans
    real(wp), intent(in) :: box(4)
    integer, intent(in) :: lang
    real(wp) :: inner(4), cell(4), mu, pole(2), p(2), q(2), tx, ty, cw, ch, largest
    real(wp), allocatable :: seg_x(:), seg_y(:), tips(:, :)
    character(len=7) :: colour
    character(len=:), allocatable :: dash, caption
    logical :: leader
    integer :: n, i, j, columns, rows
    call put_panel(out, boxes, box, word("Force polygons of the groups", lang), inner)
    n = 0
    if (allocated(plans%group_polygons)) n = size(plans%group_polygons)
    if (n == 0) return
    columns = min(n, 2)
    rows = (n + columns - 1) / columns
    cw = (inner(3) - inner(1)) / columns
    ch = (inner(4) - inner(2)) / rows
    do i = 1, n
      associate (poly => plans%group_polygons(i))
        cell = [inner(1) + cw * modulo(i - 1, columns), inner(2) + ch * ((i - 1) / columns), 0.0_wp, 0.0_wp]
        cell(3:4) = cell(1:2) + [cw, ch]
        if (index(poly%link, ",") > 0) then
          caption = word("Assur group", lang)//" "//trim(poly%link)
        else
          caption = word("input link", lang)//" "//trim(poly%link)
        end if
        if (len(poly%moment) > 0) caption = caption//": "//poly%moment//" = "//short_number(poly%moment_value)//" "// &
          unit_word("N*m", lang)
        call out%put(svg_text(cell(1) + 1.0_wp, cell(2) + 3.0_wp, caption, 'class="small"'))
        call boxes%reserve(cell(1) + 1.0_wp, cell(2) + 3.0_wp, caption, 2.4_wp, anchor_start)
        ! its own scale: the polygon fits its cell
        call polygon_tips(poly%vectors, tips)
        largest = max(maxval(tips(1, :)) - minval(tips(1, :)), maxval(tips(2, :)) - minval(tips(2, :)))
        mu = 1.0_wp
        if (largest > 0.0_wp) mu = plan_scale(largest / (min(cw, ch) - 12.0_wp))
        caption = "μF = "//short_number(mu)//" "//unit_word("N", lang)//"/"//unit_word("mm", lang)
        call out%put(svg_text(cell(1) + 1.0_wp, cell(4) - 1.0_wp, caption, 'class="small"'))
        call boxes%reserve(cell(1) + 1.0_wp, cell(4) - 1.0_wp, caption, 2.4_wp, anchor_start)
        pole(1) = 0.5_wp * (cell(1) + cell(3)) - 0.5_wp * (minval(tips(1, :)) + maxval(tips(1, :))) / mu
        pole(2) = 0.5_wp * (cell(2) + cell(4)) + 0.5_wp * (minval(tips(2, :)) + maxval(tips(2, :))) / mu
        allocate (seg_x(0), seg_y(0))
        do j = 1, size(poly%vectors)
          p = pole + [tips(1, j), -tips(2, j)] / mu
          q = pole + [tips(1, j + 1), -tips(2, j + 1)] / mu
          seg_x = [seg_x, p(1), q(1)]
          seg_y = [seg_y, p(2), q(2)]
          call palette_colour(j, colour, dash)
          if (hypot(q(1) - p(1), q(2) - p(2)) >= 0.3_wp) call out%put(svg_arrow(p(1), p(2), q(1), q(2), colour, &
            0.3_wp, 1.6_wp))
        end do
        do j = 1, size(poly%vectors)
          p = pole + [tips(1, j), -tips(2, j)] / mu
          q = pole + [tips(1, j + 1), -tips(2, j + 1)] / mu
          if (hypot(q(1) - p(1), q(2) - p(2)) < 0.3_wp) cycle
          call palette_colour(j, colour, dash)
          call boxes%place(trim(poly%vectors(j)%name), num_size, 0.5_wp * (p(1) + q(1)), 0.5_wp * (p(2) + q(2)), &
            atan2(q(2) - p(2), q(1) - p(1)) - 0.5_wp * pi, seg_x, seg_y, cell, tx, ty, leader)
          if (leader) call out%put(svg_line(0.5_wp * (p(1) + q(1)), 0.5_wp * (p(2) + q(2)), tx, &
            ty - 0.3_wp * num_size, 'stroke="#777777" stroke-width="0.15"'))
          call out%put(svg_text(tx, ty, trim(poly%vectors(j)%name), 'class="num" text-anchor="middle" style="fill: '// &
            colour//'"'))
        end do
        deallocate (seg_x, seg_y)
      end associate
    end do
  end subroutine put_polygons



end module kinetostat_svg_plans
