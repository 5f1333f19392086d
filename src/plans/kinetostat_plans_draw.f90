!> The plans sheet (`--format plans --at K`, and `--format dxf --at K --plans`) on the drawing
!> model: the graphical method at one step on one A2 landscape sheet in the ГОСТ frame, as the
!> course draws it, every drawing in the frame of the mechanism's drawing (gravity down the
!> sheet), so that a plan can be checked against the drawn links (v_CB perpendicular to CB):
!> - the mechanism at a ГОСТ 2.302 scale (its joints marked data-joint, its centres of mass
!>   data-point);
!> - the plan of velocities: pole p, the image of every joint and centre of mass (lower-case:
!>   b, c, s2; b3 the point of link 3 under B; p′ the image of a joint named P), marked
!>   data-image in sheet mm, the relative velocities as the vector equations close them
!>   (v_CB, v_B2B3), μv;
!> - the plan of accelerations: pole π, the images, the components of every vector equation
!>   (n, τ, k, r), μa;
!> - Zhukovsky's lever: the plan of velocities turned by 90 deg, every load of the lever's
!>   equation at its image at the lever's μF (a moment as its couple F = M/l at two images),
!>   the arm of every force (dashed, from the pole), the balancing force P_bal at its image;
!>   the table of the loads (value, image, arm in mm);
!> - the force polygons of the units of the structure in the course's order, the whole
!>   reactions and the inner reaction drawn; an input link's cell with the link, its forces and
!>   their arms at a scale of its own;
!> - the values table (v, ω with its sense, a^n, a^τ, a^k, ε with its sense) and the
!>   balancing effort: from the lever, the analytic one, and the two as read off the sheet.
!> A vector shorter than 1 mm at its scale is not drawn; a note names it. The numbers come
!> from kinetostat_plans, the sheet's geometry from kinetostat_plans_sheet.
module kinetostat_plans_draw
  use kinetostat_kinds, only: wp, pi, version_string, rad_to_deg
  use kinetostat_svg, only: coord
  use kinetostat_text, only: int_str, lower
  use kinetostat_format, only: short_number, fixed_number, full_number
  use kinetostat_step_table, only: step_table_t
  use kinetostat_labels, only: word => label, unit_word => unit_symbol, lang_ru
  use kinetostat_scales, only: scale_number, round_scale
  use kinetostat_sheet, only: sheet_t, layer_text, layer_vplan, layer_aplan, layer_polygons, layer_lever, &
    layer_scales, layer_frame, layer_guides, anchor_start, anchor_end
  use kinetostat_label_place, only: outward_none, outward_leaders, outward_all
  use kinetostat_title_block, only: put_sheet_format, title_block_from_table, header_indent, deck_line, &
    course_title, course_data_line
  use kinetostat_drawing, only: drawing_t, drawing_point_t, drawing_body_t, drawing_force_t, drawing_moment_t, &
    force_gravity, force_inertia, force_load, force_pair, point_pivot
  use kinetostat_mechanism_view, only: mechanism_view_t, fit_mechanism_view, draw_mechanism, force_colours, &
    mark_other_drawing
  use kinetostat_mechanism_sheet, only: fitted_size
  use kinetostat_run_sheet, only: note_length
  use kinetostat_plans_base, only: plans_t, plan_value_t, plan_vector_t, plan_equation_t, lever_load_t, force_polygon_t, &
    component_normal, component_tangential, component_coriolis, component_relative, component_reaction, load_moment, perp
  use kinetostat_plans_apart, only: draw_group_apart, guide_reactions_placed, apart_pitch => row_pitch
  use kinetostat_plans_sheet, only: plans_sheet_t, turn, chain_tips, polygon_tips, panel_inner, panel_head, &
    input_link_drawing, fit_kinematic_plans, note_size, least_note_size, note_pitch, plan_inner
  implicit none
  private
  public :: draw_plans_sheet, display_name, draw_kinematic_plans, values_table_height

  !> A vector drawn shorter than this is listed, not drawn, mm.
  real(wp), parameter :: shortest = 1.0_wp
  !> Colours: images' rays, the plans' components (normal, tangential, Coriolis, relative),
  !> known reactions, whole reactions, inner reactions, the balancing force, arms.
  character(*), parameter :: ray_colour = "#1f77b4", normal_colour = "#2ca02c", tangential_colour = "#d62728", &
    coriolis_colour = "#9467bd", relative_colour = "#ff7f0e", known_colour = "#7f3f3f", whole_colour = "#000000", &
    inner_colour = "#9467bd", balancing_colour = "#000000", arm_colour = "#888888"
  !> Pitch of the tables' rows, mm.
  real(wp), parameter :: pitch = 3.2_wp
  !> The longest row of the values table, bytes.
  integer, parameter :: value_length = 200
  !> Orders in which a plan's labels are placed: as given (the pole, the images, the
  !> components), reversed, the components first, the labels of the points farthest from the
  !> pole first, those nearest first.
  integer, parameter :: order_given = 1, order_reversed = 2, order_components_first = 3, order_outer_first = 4, &
    order_inner_first = 5
  !> The orders tried, in turn, until one places every label off the lines with leader lines
  !> that cross no label, and how far out each places its labels (kinetostat_label_place):
  !> as given, near their points; then each order with the labels that need a leader line
  !> far out; then each with every label far out.
  integer, parameter :: label_orders(*) = [order_given, order_given, order_reversed, order_components_first, &
    order_outer_first, order_inner_first, order_given, order_reversed, order_components_first, order_outer_first, &
    order_inner_first]
  integer, parameter :: label_outward(size(label_orders)) = [outward_none, outward_leaders, outward_leaders, &
    outward_leaders, outward_leaders, outward_leaders, outward_all, outward_all, outward_all, outward_all, outward_all]

contains

  !> The plans sheet of row `k`.
  pure subroutine draw_plans_sheet(title, table, k, drawing, plans, geo, lang, sheet)
    !> Title of the mechanism.
    character(*), intent(in) :: title
    !> The results.
    type(step_table_t), intent(in) :: table
    !> Row (1-based).
    integer, intent(in) :: k
    !> The mechanism at that row, with its forces.
    type(drawing_t), intent(in) :: drawing
    !> The plans of that row and the sheet's geometry.
    type(plans_t), intent(in) :: plans
    type(plans_sheet_t), intent(in) :: geo
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    !> The sheet made.
    type(sheet_t), intent(out) :: sheet
    character(len=:), allocatable :: line, short, arms_note
    real(wp) :: inner(4), tail(2), tip(2), foot_at(2), arm
    type(drawing_t) :: placed
    logical, allocatable :: moved(:)
    real(wp), allocatable :: from(:, :)
    integer :: j

    if (geo%groups_apart) then
      ! the course's sheet 2: the force analysis (its plans are the kinematics sheet's); no
      ! file named on it (course_data_line), the mechanism's name in the course's words
      line = word("Force analysis of the mechanism", lang)
      call sheet%open(geo%paper, lang, line//", "//word("position", lang)//" "//int_str(table%run_row(k)), &
        "kinetostat sheets: the kinetostatics sheet: the mechanism with its forces, Zhukovsky's lever, the force "// &
        "polygons, each Assur group drawn apart. The mechanism's group gives its view (data-origin, data-scale, "// &
        "data-rotation); velocity images carry data-image, in sheet mm.")
    else
      call sheet%open(geo%paper, lang, title//" - "//table%deck//" - plans, "//table%row_name//" "// &
        int_str(table%run_row(k)), "kinetostat --format plans --at "//int_str(table%run_row(k))//" sheet of "// &
        table%deck//": the mechanism, the plans of velocities and accelerations in its frame, Zhukovsky's lever, "// &
        "the force polygons. The mechanism's group gives its view (data-origin, data-scale, data-rotation); "// &
        "velocity images carry data-image, in sheet mm.")
      line = word("Plans of velocities, accelerations, forces", lang)
    end if
    call put_sheet_format(sheet, title_block_from_table(table, line, geo%view%drawing_scale%text))
    inner = geo%paper%inside()
    ! right of графа 26 (the designation turned 180 deg in the upper left corner) when given
    inner(1) = inner(1) + header_indent(table)

    ! the header: the mechanism's title, the deck with its own title and the --set changes, the step
    call sheet%set_layer(layer_text)
    line = title
    if (geo%groups_apart) line = course_title(title)
    call sheet%text(inner(1) + 3.0_wp, 11.0_wp, line, "title", size=fitted_size(line, 3.3_wp, inner(3) - inner(1) - &
      6.0_wp, 0.72_wp), plain=.true.)
    line = deck_line(table, lang)
    if (geo%groups_apart) line = course_data_line(table, lang)
    if (len(line) > 0) call sheet%text(inner(1) + 3.0_wp, 16.5_wp, line, "subtitle", &
      size=fitted_size(line, 3.0_wp, inner(3) - inner(1) - 6.0_wp, 0.6_wp), plain=.true.)
    line = word(table%row_name, lang)//" "//int_str(table%run_row(k))//" "//word("of", lang)//" "//int_str(table%run_rows())
    if (table%input_column > 0) line = line//": "//table%columns(table%input_column)%name//" = "// &
      short_number(table%rows(table%input_column, k))//" "//unit_word(table%columns(table%input_column)%unit, lang)
    if (allocated(drawing%view_note)) line = line//"; "//word(drawing%view_note, lang)//", "// &
      word("the plans in the mechanism's frame", lang)
    line = line//"; "//version_string
    call sheet%text(inner(1) + 3.0_wp, 21.5_wp, line, "small")

    ! the mechanism (on the course sheet with every force at mu_F)
    if (geo%mu_mechanism_force > 0.0_wp) then
      call panel(sheet, geo%mechanism, word("Mechanism with its forces", lang)//", "//word("position", lang)//" "// &
        int_str(table%run_row(k)))
      ! a guide's whole reaction at its line of action, as its group drawn apart has it, where
      ! its arrow stays in the panel there (a thin dashed line joins it to the link's point);
      ! else at the link's point with its arm stated under the drawing
      call guide_reactions_placed(drawing, plans, placed, moved, from)
      arms_note = ""
      do j = 1, size(moved)
        if (.not. moved(j)) cycle
        associate (f => placed%forces(j), area => panel_inner(geo%mechanism) - [0.0_wp, 0.0_wp, 0.0_wp, 4.5_wp])
          tail = geo%view%point(f%at)
          tip = tail + geo%view%direction(f%f) / geo%mu_mechanism_force
          if (all([tail, tip] >= [area(1:2), area(1:2)]) .and. all([tail, tip] <= [area(3:4), area(3:4)])) then
            call sheet%set_layer(layer_guides)
            foot_at = geo%view%point(from(:, j))
            call sheet%line(foot_at(1), foot_at(2), tail(1), tail(2), stroke="#555555", width=0.15_wp, dash="1 0.8")
          else
            arm = norm2(f%at - from(:, j))
            f%at = from(:, j)
            ! (a force too short to draw is listed under the drawing)
            if (norm2(f%f) / geo%mu_mechanism_force < 1.0_wp) cycle
            if (len(arms_note) > 0) arms_note = arms_note//"; "
            arms_note = arms_note//display_name(trim(f%name), lang)//" "// &
              word("drawn at the link's point, its line of action", lang)//" "//short_number(arm)//" "// &
              unit_word("m", lang)//" "//word("from it (off the drawing)", lang)
          end if
        end associate
      end do
      ! (its labels clear of the two lines under it)
      ! (A4: its panel under 120 mm wide, its labels at 1.8 mm, the least legible size)
      if (geo%mechanism(3) - geo%mechanism(1) < 120.0_wp) then
        call draw_mechanism(sheet, placed, geo%view, panel_inner(geo%mechanism) - [0.0_wp, 0.0_wp, 0.0_wp, 4.5_wp], &
          1.0_wp / geo%mu_mechanism_force, short, label_size=1.8_wp)
      else
        call draw_mechanism(sheet, placed, geo%view, panel_inner(geo%mechanism) - [0.0_wp, 0.0_wp, 0.0_wp, 4.5_wp], &
          1.0_wp / geo%mu_mechanism_force, short)
      end if
      line = "μl = "//scale_number(geo%mu_l)//" "//unit_word("m", lang)//"/"//unit_word("mm", lang)//" ("// &
        geo%view%drawing_scale%text//");  μF = "//scale_number(geo%mu_mechanism_force)//" "//unit_word("N", lang)// &
        "/"//unit_word("mm", lang)
      call foot(sheet, geo%mechanism, line)
      ! the forces too short to draw on a line of their own above the scales (text 1.8 mm at
      ! the least: on two lines where one would need smaller)
      if (len(short) > 0) call legible_lines(sheet, geo%mechanism(1) + 2.0_wp, geo%mechanism(4) - 6.3_wp, &
        geo%mechanism(3) - geo%mechanism(1) - 4.0_wp, word("not drawn, shorter than 1 mm", lang)//": "//short)
      if (len(arms_note) > 0) call legible_lines(sheet, geo%mechanism(1) + 2.0_wp, geo%mechanism(4) - 6.3_wp - &
        merge(5.0_wp, 0.0_wp, len(short) > 0), geo%mechanism(3) - geo%mechanism(1) - 4.0_wp, arms_note)
    else
      call panel(sheet, geo%mechanism, word("Mechanism", lang)//", "//word("position", lang)//" "// &
        int_str(table%run_row(k)))
      call draw_mechanism(sheet, drawing, geo%view, panel_inner(geo%mechanism), 0.0_wp, short)
      call foot(sheet, geo%mechanism, "μl = "//scale_number(geo%mu_l)//" "//unit_word("m", lang)//"/"// &
        unit_word("mm", lang)//" ("//geo%view%drawing_scale%text//")")
    end if

    ! the plans (the course sheet leaves them to the kinematics sheet)
    if (.not. geo%groups_apart) then
      call draw_plan(sheet, geo, plans%velocities, plans%velocity_equations, geo%velocity, geo%pole_v, geo%mu_v, &
        .false., lang, ";  "//word("relative velocities: v_PQ of a link's points, r along a guide", lang))
      call draw_plan(sheet, geo, plans%accelerations, plans%equations, geo%acceleration, geo%pole_a, geo%mu_a, &
        .true., lang, ";  "//word("components: n normal, τ tangential, k Coriolis, r relative", lang))
    end if

    ! the lever and its table
    call panel(sheet, geo%lever, word("Zhukovsky's lever", lang))
    call panel(sheet, geo%lever_table, word("Loads on the lever", lang))
    call sheet%set_layer(layer_lever)
    if (plans%lever_known) then
      call draw_lever(sheet, geo, plans, lang)
      call foot(sheet, geo%lever, "μv = "//scale_number(geo%mu_lever)//" ("//unit_word("m/s", lang)//")/"// &
        unit_word("mm", lang)//";  μF = "//scale_number(geo%mu_force)//" "//unit_word("N", lang)//"/"// &
        unit_word("mm", lang))
    else
      call sheet%text(geo%lever(1) + 3.0_wp, geo%lever(2) + panel_head + 6.0_wp, word("not drawn", lang)//": "// &
        word(plans%lever_note, lang), "label")
    end if

    ! the force polygons
    call panel(sheet, geo%polygons, word("Force polygons of the groups", lang)//" ("// &
      word("known forces first, then the unknown reactions", lang)//")")
    call sheet%set_layer(layer_polygons)
    call draw_polygons(sheet, geo, drawing, plans, lang)

    ! the values and the balancing effort
    call sheet%set_layer(layer_text)
    if (.not. geo%groups_apart) then
      call panel(sheet, geo%values, word("Values read off the plans", lang))
      call values_table(sheet, geo%values, plans, lang)
    end if
    call panel(sheet, geo%results, word("Balancing effort", lang))
    call results(sheet, geo, plans, lang)
  end subroutine draw_plans_sheet

  !> The plans of velocities and accelerations and the values read off them on another
  !> sheet (the course's kinematics sheet, whose mechanism is drawn with `view`), in the
  !> panels `velocity`, `acceleration` and `values` (x0, y0, x1, y1, mm).
  pure subroutine draw_kinematic_plans(sheet, view, plans, velocity, acceleration, values, lang)
    type(sheet_t), intent(inout) :: sheet
    type(mechanism_view_t), intent(in) :: view
    type(plans_t), intent(in) :: plans
    real(wp), intent(in) :: velocity(4), acceleration(4), values(4)
    integer, intent(in) :: lang
    type(plans_sheet_t) :: geo
    call fit_kinematic_plans(view, plans, velocity, acceleration, geo)
    call draw_plan(sheet, geo, plans%velocities, plans%velocity_equations, geo%velocity, geo%pole_v, geo%mu_v, .false., &
      lang, "")
    call draw_plan(sheet, geo, plans%accelerations, plans%equations, geo%acceleration, geo%pole_a, geo%mu_a, .true., &
      lang, "")
    call panel(sheet, values, word("Values read off the plans", lang))
    call sheet%set_layer(layer_text)
    call values_table(sheet, values, plans, lang)
  end subroutine draw_kinematic_plans

  !> A panel's frame and heading.
  pure subroutine panel(sheet, box, heading)
    type(sheet_t), intent(inout) :: sheet
    real(wp), intent(in) :: box(4)
    character(*), intent(in) :: heading
    call sheet%set_layer(layer_frame)
    call sheet%rect(box(1), box(2), box(3) - box(1), box(4) - box(2), "panel")
    call sheet%set_layer(layer_text)
    call sheet%text(box(1) + 2.0_wp, box(2) + 5.0_wp, heading, "heading", size=fitted_size(heading, 3.2_wp, &
      box(3) - box(1) - 4.0_wp, 0.6_wp))
  end subroutine panel

  !> A panel's scale line at its bottom.
  pure subroutine foot(sheet, box, text)
    type(sheet_t), intent(inout) :: sheet
    real(wp), intent(in) :: box(4)
    character(*), intent(in) :: text
    call sheet%set_layer(layer_scales)
    call sheet%text(box(1) + 2.0_wp, box(4) - 3.0_wp, text, "small", size=fitted_size(text, 2.4_wp, &
      box(3) - box(1) - 4.0_wp, 0.6_wp))
  end subroutine foot

  !> The name of a point's image on a plan: the point's name in lower case (b, s2, j21, b3);
  !> p′ for a joint named P (the pole is p).
  pure function image_label(name) result(text)
    character(*), intent(in) :: name
    character(len=:), allocatable :: text
    text = lower(trim(name))
    if (text == "p") text = "p′"
  end function image_label

  !> A load's name as the sheet writes it: the program's name, typeset (Phi2 -> Φ₂, MPhi3 ->
  !> M_Φ3 / M_и3), the friction actions M_f21, F_f21 (ru M_тр21), the balancing force P_b
  !> (ru P_ур).
  pure function display_name(name, lang) result(text)
    character(*), intent(in) :: name
    integer, intent(in) :: lang
    character(len=:), allocatable :: text
    character(len=:), allocatable :: f, prefix
    integer :: at_l
    text = trim(name)
    f = "f"
    if (lang == lang_ru) f = "тр"
    if (text == "P_bal") then
      text = "P_b"
      if (lang == lang_ru) text = "P_ур"
      return
    end if
    if (len(text) >= 3) then
      if ((text(1:2) == "Mf" .or. text(1:2) == "Ff") .and. verify(text(3:), "0123456789") == 0) then
        text = text(1:1)//"_"//f//text(3:)
        return
      end if
    end if
    ! a link named L<n> (an &assur deck's link 1 that is not the crank): its symbols' index
    ! lowered whole (G_L1, Φ_L1, M_иL1, ε_L1)
    at_l = index(text, "L", back=.true.)
    if (at_l > 1 .and. at_l < len(text)) then
      if (verify(text(at_l + 1:), "0123456789") == 0 .and. index(text(:at_l - 1), "_") == 0) then
        prefix = text(:at_l - 1)
        if (prefix == "MPhi") then
          text = "M_"//merge("и", "Φ", lang == lang_ru)//text(at_l:)
        else if (any(prefix == [character(len=5) :: "G", "Phi", "eps", "omega", "phi", "v", "a", "S"])) then
          text = prefix//"_"//text(at_l:)
        end if
      end if
    end if
  end function display_name

  !> The panel `box` of a plan (velocities, or accelerations when `accel`): its heading; the
  !> pole, a ray to every image (its name at its end; the images of the velocity plan marked
  !> data-image), the components of every vector equation head to tail from the image they
  !> start from, named; its scale line at the bottom followed by `legend`.
  pure subroutine draw_plan(sheet, geo, images, equations, box, pole, mu, accel, lang, legend)
    type(sheet_t), intent(inout) :: sheet
    type(plans_sheet_t), intent(in) :: geo
    type(plan_vector_t), intent(in) :: images(:)
    type(plan_equation_t), intent(in) :: equations(:)
    real(wp), intent(in) :: box(4), pole(2), mu
    logical, intent(in) :: accel
    integer, intent(in) :: lang
    !> Text after the scale ("" for none).
    character(*), intent(in) :: legend
    character(len=:), allocatable :: heading, pole_name, scale
    real(wp), allocatable :: tips(:, :), ends(:, :)
    real(wp) :: q(2), p(2), t(2), area(4), labels_area(4), pole_font, short_font
    character(len=:), allocatable :: short, at_pole
    !> The notes' lines (what is at the pole, what is too short to draw), all of them with
    !> their font sizes and baselines, mm.
    character(len=note_length), allocatable :: pole_lines(:), short_lines(:), note_text(:)
    real(wp), allocatable :: note_font(:), note_y(:)
    character(len=16), allocatable :: names(:)
    character(len=1), allocatable :: kinds(:)
    integer :: i, e, j, n_labels, attempt
    type(sheet_t) :: unlabelled
    integer :: crowded, fewest, best
    if (accel) then
      heading = "Plan of accelerations"
      pole_name = "π"
      scale = "μa = "//scale_number(mu)//" ("//unit_word("m/s^2", lang)//")/"
    else
      heading = "Plan of velocities"
      pole_name = "p"
      scale = "μv = "//scale_number(mu)//" ("//unit_word("m/s", lang)//")/"
    end if
    call panel(sheet, box, word(heading, lang))
    call sheet%set_layer(merge(layer_aplan, layer_vplan, accel))
    area = plan_inner(box)
    short = ""
    at_pole = ""
    ! the plan's group: where its pole is and its scale (a point of the plan v is drawn at
    ! pole + (q1, -q2) / mu, q = v turned by the sheet's rotation)
    call sheet%group(trim(merge("acceleration-plan", "velocity-plan    ", accel)))
    call sheet%attach("data-pole", coord(pole(1))//" "//coord(pole(2)))
    call sheet%attach("data-mu", full_number(mu))
    call sheet%attach("data-rotation", full_number(geo%rotation * rad_to_deg))
    ! the components of the equations head to tail (a velocity equation from the pole that is
    ! one rotation is the image's own ray), those 1 mm and longer drawn
    allocate (ends(4, 0), names(0), kinds(0))
    do e = 1, size(equations)
      call chain_tips(equations(e), images, tips)
      if (own_ray(equations(e), tips)) cycle
      do j = 1, size(equations(e)%vectors)
        p = at(tips(:, j))
        t = at(tips(:, j + 1))
        if (norm2(t - p) < shortest) then
          if (norm2(equations(e)%vectors(j)%v) > 0.0_wp) call listed(short, trim(equations(e)%vectors(j)%name))
          cycle
        end if
        ends = reshape([ends, p, t], [4, size(ends, 2) + 1])
        names = [character(len=16) :: names, equations(e)%vectors(j)%name]
        kinds = [character(len=1) :: kinds, equations(e)%vectors(j)%kind]
      end do
    end do
    do j = 1, size(names)
      call sheet%arrow(ends(1, j), ends(2, j), ends(3, j), ends(4, j), component_colour(kinds(j)), 0.25_wp, 1.5_wp)
    end do
    ! the rays to the images
    do i = 1, size(images)
      q = at(images(i)%v)
      if (norm2(q - pole) < shortest) cycle
      call sheet%arrow(pole(1), pole(2), q(1), q(2), ray_colour, 0.3_wp, 1.8_wp)
    end do
    call sheet%circle(pole(1), pole(2), 0.7_wp, "origin")
    do i = 1, size(images)
      q = at(images(i)%v)
      call sheet%circle(q(1), q(2), 0.35_wp, "point")
      if (accel) then
        call sheet%attach("data-acceleration-image", image_label(images(i)%name))
      else
        call sheet%attach("data-image", lower(trim(images(i)%name)))
      end if
    end do
    ! the labels: the pole, the images, the components
    ! (above the notes at the foot: what is at the pole, what is too short)
    call sheet%set_layer(layer_text)
    do i = 1, size(images)
      if (norm2(at(images(i)%v) - pole) < shortest) call listed(at_pole, image_label(images(i)%name))
    end do
    ! (the notes' lines at the area's foot, the last on its bottom edge: note_lines; the
    ! labels above them)
    allocate (pole_lines(0), short_lines(0))
    pole_font = note_size
    short_font = note_size
    if (len(at_pole) > 0) call note_lines(word("at the pole", lang)//" "//pole_name//": "//at_pole, &
      area(3) - area(1) - 2.0_wp, pole_lines, pole_font)
    if (len(short) > 0) call note_lines(word("not drawn, shorter than 1 mm", lang)//": "//short, &
      area(3) - area(1) - 2.0_wp, short_lines, short_font)
    ! (every line's baseline from the last, on the area's foot, up: a line's pitch the larger
    ! font's of the two times note_pitch)
    allocate (note_text(0), note_font(0))
    note_text = [character(len=note_length) :: pole_lines, short_lines]
    note_font = [spread(pole_font, 1, size(pole_lines)), spread(short_font, 1, size(short_lines))]
    allocate (note_y(size(note_text)))
    labels_area = area
    do i = size(note_text), 1, -1
      note_y(i) = area(4)
      if (i < size(note_text)) note_y(i) = note_y(i + 1) - note_pitch * max(note_font(i), note_font(i + 1))
      labels_area(4) = note_y(i) - note_pitch * note_font(i)
    end do
    ! in the order pole, images, components; when one of them finds no spot off the lines
    ! whose leader line crosses no label (a plan drawn small, its labels crowding round the
    ! pole), the other orders (label_orders, label_outward) are tried in turn: the first that
    ! places every label so is kept, else the one that leaves the fewest labels without one
    n_labels = 1 + size(images) + size(names)
    ! (placed on the sheet itself; a later order starts again from its copy `unlabelled`, and
    ! the best order is placed again when it was not the last tried)
    unlabelled = sheet
    fewest = huge(1)
    best = 1
    do attempt = 1, size(label_orders)
      if (attempt > 1) sheet = unlabelled
      call place_labels(sheet, attempt, crowded)
      if (crowded < fewest) then
        fewest = crowded
        best = attempt
      end if
      if (crowded == 0) exit
    end do
    if (crowded > 0 .and. best /= size(label_orders)) then
      sheet = unlabelled
      call place_labels(sheet, best, crowded)
    end if
    ! what is at the pole, what is too short to draw
    do i = 1, size(note_text)
      call sheet%text(area(1) + 1.0_wp, note_y(i), trim(note_text(i)), "note", size=note_font(i))
    end do
    call sheet%end_group()
    call sheet%set_layer(merge(layer_aplan, layer_vplan, accel))
    call foot(sheet, box, scale//unit_word("mm", lang)//legend)
  contains
    !> Every label placed on `target` in the order and reach of attempt `attempt`
    !> (label_orders, label_outward); `crowded`: how many had to go near a line or their
    !> leader line over a label.
    pure subroutine place_labels(target, attempt, crowded)
      type(sheet_t), intent(inout) :: target
      integer, intent(in) :: attempt
      integer, intent(out) :: crowded
      integer :: k
      logical :: relaxed
      crowded = 0
      do k = 1, n_labels
        call put_label(target, label_order(label_orders(attempt), k), label_outward(attempt), relaxed)
        if (relaxed) crowded = crowded + 1
      end do
    end subroutine place_labels
    !> Place label k (1: the pole, then the images, then the components) on `target`;
    !> `relaxed` when it had to go near a line or its leader line over a label.
    pure subroutine put_label(target, k, outward, relaxed)
      type(sheet_t), intent(inout) :: target
      integer, intent(in) :: k
      integer, intent(in) :: outward
      logical, intent(out) :: relaxed
      real(wp) :: q(2)
      integer :: i, j
      relaxed = .false.
      if (k == 1) then
        call target%place_label(pole_name, "label", pole(1), pole(2), 0.75_wp * pi, labels_area, relaxed=relaxed, &
          outward=outward)
      else if (k <= 1 + size(images)) then
        i = k - 1
        q = at(images(i)%v)
        if (norm2(q - pole) < shortest) return
        call target%place_label(image_label(images(i)%name), "label", q(1), q(2), atan2(q(2) - pole(2), q(1) - pole(1)), &
          labels_area, tail=pole, italic=.true., relaxed=relaxed, outward=outward)
      else
        j = k - 1 - size(images)
        call target%place_label(trim(names(j)), "num", 0.5_wp * (ends(1, j) + ends(3, j)), &
          0.5_wp * (ends(2, j) + ends(4, j)), atan2(ends(4, j) - ends(2, j), ends(3, j) - ends(1, j)) - 0.5_wp * pi, &
          labels_area, colour=component_colour(kinds(j)), relaxed=relaxed, outward=outward)
      end if
    end subroutine put_label
    !> The label placed k-th in the order `order` (order_given, order_reversed,
    !> order_components_first, order_outer_first, order_inner_first).
    pure integer function label_order(order, k)
      integer, intent(in) :: order, k
      integer :: rank(n_labels), m, ni
      real(wp) :: r(n_labels), c(2)
      ni = size(images)
      select case (order)
      case (order_reversed)
        label_order = n_labels + 1 - k
      case (order_components_first)
        label_order = merge(1 + ni + k, k - size(names), k <= size(names))
      case (order_outer_first, order_inner_first)
        do m = 1, n_labels
          c = anchor(m)
          r(m) = norm2(c - pole)
        end do
        if (order == order_inner_first) r = -r
        ! rank by distance, farthest first (ties in the given order)
        do m = 1, n_labels
          rank(m) = count(r > r(m)) + count(r(:m - 1) == r(m)) + 1
        end do
        label_order = findloc(rank, k, dim=1)
      case default
        label_order = k
      end select
    end function label_order
    !> The point label m belongs to, mm.
    pure function anchor(m) result(c)
      integer, intent(in) :: m
      real(wp) :: c(2)
      if (m == 1) then
        c = pole
      else if (m <= 1 + size(images)) then
        c = at(images(m - 1)%v)
      else
        c = 0.5_wp * (ends(1:2, m - 1 - size(images)) + ends(3:4, m - 1 - size(images)))
      end if
    end function anchor
    !> Whether a velocity equation is its point's own ray: one rotation from the pole (about a
    !> pivot), the image's ray drawn already.
    pure logical function own_ray(eq, tips)
      type(plan_equation_t), intent(in) :: eq
      real(wp), intent(in) :: tips(:, :)
      own_ray = .false.
      if (size(eq%vectors) /= 1) return
      if (norm2(at(tips(:, 1)) - pole) >= 1.0e-6_wp) return
      ! a rotation about a pivot on the plan of velocities, a slide on the frame's guide
      own_ray = eq%vectors(1)%kind == component_relative .or. (.not. accel .and. eq%vectors(1)%kind == &
        component_tangential)
    end function own_ray
    !> Sheet point of a plan's vector (position frame) from the pole.
    pure function at(v) result(s)
      real(wp), intent(in) :: v(2)
      real(wp) :: s(2)
      s = pole + geo%view%direction(v) / mu
    end function at
  end subroutine draw_plan

  !> Where reaction `j` of polygon `poly` stands on the sheet: from p to t, its tail and head
  !> vertices of the polygon's `tips` from `pole`, mm; `drawn` when it is shown (an inner
  !> reaction, or a whole one not among the polygon's vectors) and at least `shortest` long.
  pure subroutine reaction_span(poly, j, pole, tips, p, t, drawn)
    type(force_polygon_t), intent(in) :: poly
    integer, intent(in) :: j
    real(wp), intent(in) :: pole(2), tips(:, :)
    real(wp), intent(out) :: p(2), t(2)
    logical, intent(out) :: drawn
    associate (r => poly%reactions(j))
      p = pole + tips(:, r%tail + 1)
      t = pole + tips(:, r%head + 1)
      drawn = (r%inner .or. .not. any(poly%vectors%name == r%name)) .and. norm2(t - p) >= shortest
    end associate
  end subroutine reaction_span

  !> Append a name to a comma-separated list.
  pure subroutine listed(list, name)
    character(len=:), allocatable, intent(inout) :: list
    character(*), intent(in) :: name
    if (len(list) > 0) list = list//", "
    list = list//name
  end subroutine listed

  !> Colour of a plan's component: normal, tangential, Coriolis, relative.
  pure function component_colour(kind) result(colour)
    character(*), intent(in) :: kind
    character(len=7) :: colour
    select case (kind)
    case (component_normal)
      colour = normal_colour
    case (component_tangential)
      colour = tangential_colour
    case (component_coriolis)
      colour = coriolis_colour
    case default
      colour = relative_colour
    end select
  end function component_colour

  !> Colour of a lever's load by the kind of force it comes from.
  pure function load_colour(source) result(colour)
    integer, intent(in) :: source
    character(len=7) :: colour
    select case (source)
    case (force_pair, force_load, force_gravity, force_inertia)
      colour = force_colours(source)
    case default
      colour = coriolis_colour
    end select
  end function load_colour

  !> Zhukovsky's lever: the turned plan (thin rays to its images, named), every load at its
  !> image (a couple's two forces), the arm of every force dashed from the pole, the
  !> balancing force; the table of the loads beside it.
  pure subroutine draw_lever(sheet, geo, plans, lang)
    type(sheet_t), intent(inout) :: sheet
    type(plans_sheet_t), intent(in) :: geo
    type(plans_t), intent(in) :: plans
    integer, intent(in) :: lang
    real(wp) :: area(4), q(2), y, x, lp, font, note_y, wide
    character(len=:), allocatable :: short, text
    integer :: i, n
    area = panel_inner(geo%lever)
    note_y = area(4)
    ! the course sheet: the labels clear of the note at the panel's foot
    if (geo%groups_apart) area(4) = area(4) - 3.5_wp
    short = ""
    ! the lever's group: its pole, its scales (an image v at pole + (q1, -q2) / mu_v, q = v
    ! turned by 90 deg and by the sheet's rotation; a force f drawn (f1, -f2) / mu_F long, f
    ! turned by the sheet's rotation)
    call sheet%group("lever")
    call sheet%attach("data-pole", coord(geo%pole_lever(1))//" "//coord(geo%pole_lever(2)))
    call sheet%attach("data-mu", full_number(geo%mu_lever))
    call sheet%attach("data-mu-force", full_number(geo%mu_force))
    call sheet%attach("data-rotation", full_number(geo%rotation * rad_to_deg))
    ! the turned plan
    do i = 1, size(plans%velocities)
      q = image(plans%velocities(i)%v)
      if (norm2(q - geo%pole_lever) < shortest) cycle
      call sheet%line(geo%pole_lever(1), geo%pole_lever(2), q(1), q(2), "faint")
    end do
    ! the arms, then the loads
    do i = 1, size(plans%loads)
      call arms(sheet, plans%loads(i))
    end do
    call arms(sheet, plans%balancing)
    do i = 1, size(plans%loads)
      call arrows(sheet, plans%loads(i), load_colour(plans%loads(i)%source), 0.35_wp, short)
    end do
    call arrows(sheet, plans%balancing, balancing_colour, 0.5_wp, short)
    call sheet%circle(geo%pole_lever(1), geo%pole_lever(2), 0.7_wp, "origin")
    ! labels: the pole, the images, the loads
    call sheet%set_layer(layer_text)
    call sheet%place_label("p", "label", geo%pole_lever(1), geo%pole_lever(2), 0.75_wp * pi, area)
    do i = 1, size(plans%velocities)
      q = image(plans%velocities(i)%v)
      if (norm2(q - geo%pole_lever) < shortest) cycle
      call sheet%place_label(image_label(plans%velocities(i)%name), "num", q(1), q(2), atan2(q(2) - geo%pole_lever(2), &
        q(1) - geo%pole_lever(1)), area, tail=geo%pole_lever, italic=.true.)
    end do
    do i = 1, size(plans%loads)
      call names(sheet, plans%loads(i), load_colour(plans%loads(i)%source))
    end do
    call names(sheet, plans%balancing, balancing_colour)
    if (len(short) > 0) then
      if (geo%groups_apart) then
        call sheet%set_layer(layer_text)
        call legible_lines(sheet, area(1) + 1.0_wp, note_y, area(3) - area(1) - 2.0_wp, &
          word("not drawn, shorter than 1 mm", lang)//": "//short)
      else
        call sheet%text(area(1) + 1.0_wp, note_y, word("not drawn, shorter than 1 mm", lang)//": "// &
          short, "note", size=fitted_size(short, 2.6_wp, area(3) - area(1) - 50.0_wp, 0.6_wp))
      end if
    end if
    call sheet%end_group()

    ! the table: every load, its value, its image(s), its arm as drawn
    call sheet%set_layer(layer_text)
    x = geo%lever_table(1) + 2.0_wp
    y = geo%lever_table(2) + panel_head + 6.0_wp
    ! the columns: load, image, arm in a table 88 mm wide (narrower on A4's course sheet)
    wide = geo%lever_table(3) - geo%lever_table(1) - 4.0_wp
    call sheet%text(x, y - 3.5_wp, word("load", lang), "small")
    call sheet%text(x + wide * 54.0_wp / 88.0_wp, y - 3.5_wp, word("image", lang), "small")
    call sheet%text(x + wide, y - 3.5_wp, "h, "//unit_word("mm", lang), "small", anchor=anchor_end)
    ! the rows 3.2 mm apart, closer (2.6 mm, 1.8 mm text) on a course sheet where they would
    ! not fit
    lp = pitch
    font = 2.2_wp
    if (geo%groups_apart .and. y + pitch * size(plans%loads) > geo%lever_table(4) - 1.5_wp) then
      lp = 2.6_wp
      font = 1.8_wp
      ! (A4: closer still, down to 2.2 mm, so that the last row stays inside the panel)
      if (y + lp * size(plans%loads) > geo%lever_table(4) - 1.5_wp) then
        lp = max(2.2_wp, (geo%lever_table(4) - 1.5_wp - y) / real(size(plans%loads), wp))
      end if
    end if
    n = 0
    do i = 1, size(plans%loads) + 1
      if (i <= size(plans%loads)) then
        call row(sheet, plans%loads(i), n)
      else
        call row(sheet, plans%balancing, n)
      end if
    end do
    text = "h: "//word("arms on the lever", lang)
    if (geo%groups_apart) then
      ! (the course sheet: in the heading's line, the rows below go down to the panel's foot)
      call sheet%text(geo%lever_table(3) - 2.0_wp, geo%lever_table(2) + 5.0_wp, text, "note", anchor=anchor_end, &
        size=2.2_wp)
    else
      call sheet%text(x, geo%lever_table(4) - 2.0_wp, text, "note")
    end if
  contains
    !> Sheet point of a velocity image turned by 90 deg.
    pure function image(v) result(s)
      real(wp), intent(in) :: v(2)
      real(wp) :: s(2)
      s = geo%pole_lever + geo%view%direction(turn(v, 0.5_wp * pi)) / geo%mu_lever
    end function image
    !> A force's arrow at the image `v`: tail and tip on the sheet.
    pure subroutine ends(v, f, tail, tip)
      real(wp), intent(in) :: v(2), f(2)
      real(wp), intent(out) :: tail(2), tip(2)
      tail = image(v)
      tip = tail + geo%view%direction(f) / geo%mu_force
    end subroutine ends
    !> The arms (from the pole to the force's line) of a load's force(s).
    pure subroutine arms(sheet, ld)
      type(sheet_t), intent(inout) :: sheet
      type(lever_load_t), intent(in) :: ld
      call arm(sheet, ld%at, ld%f)
      if (ld%pair) call arm(sheet, ld%at2, -ld%f)
    end subroutine arms
    pure subroutine arm(sheet, v, f)
      type(sheet_t), intent(inout) :: sheet
      real(wp), intent(in) :: v(2), f(2)
      real(wp) :: tail(2), tip(2), d(2), foot(2)
      call ends(v, f, tail, tip)
      ! a force too short to draw has no arm drawn (and no direction to speak of)
      if (norm2(tip - tail) < shortest) return
      d = (tip - tail) / norm2(tip - tail)
      foot = tail + dot_product(geo%pole_lever - tail, d) * d
      if (norm2(foot - geo%pole_lever) < shortest) return
      call sheet%line(geo%pole_lever(1), geo%pole_lever(2), foot(1), foot(2), stroke=arm_colour, width=0.15_wp, dash="1 0.8")
    end subroutine arm
    !> A load's arrow(s), each in a group "lever-load" (the balancing force's "lever-balancing")
    !> with what reading the lever needs: the force's name and |F| as computed (N), its arm
    !> as drawn (mm) and the sense of its moment about the pole (the sign of its power); the
    !> balancing force's also the crank's length l (m) and the effort computed (N·m or N).
    !> A force too short to draw keeps its group, empty.
    pure subroutine arrows(sheet, ld, colour, width, short)
      type(sheet_t), intent(inout) :: sheet
      type(lever_load_t), intent(in) :: ld
      character(*), intent(in) :: colour
      real(wp), intent(in) :: width
      character(len=:), allocatable, intent(inout) :: short
      logical :: drawn
      drawn = norm2(ld%f) / geo%mu_force >= shortest
      if (.not. drawn .and. norm2(ld%f) > 0.0_wp) call listed(short, display_name(ld%name, lang))
      call lever_force(sheet, ld, ld%at, ld%f, colour, width, drawn)
      if (ld%pair) call lever_force(sheet, ld, ld%at2, -ld%f, colour, width, drawn)
    end subroutine arrows
    !> One force of a load at the image v in its group (arrows).
    pure subroutine lever_force(sheet, ld, v, f, colour, width, drawn)
      type(sheet_t), intent(inout) :: sheet
      type(lever_load_t), intent(in) :: ld
      real(wp), intent(in) :: v(2), f(2), width
      character(*), intent(in) :: colour
      logical, intent(in) :: drawn
      real(wp) :: tail(2), tip(2)
      if (ld%name == plans%balancing%name) then
        call sheet%group("lever-balancing")
      else
        call sheet%group("lever-load")
      end if
      call sheet%attach("data-name", trim(ld%name))
      call sheet%attach("data-force", full_number(norm2(f)))
      call sheet%attach("data-h", full_number(abs(dot_product(f, v)) / max(norm2(f), tiny(1.0_wp)) / geo%mu_lever))
      call sheet%attach("data-sense", trim(merge("1 ", "-1", dot_product(f, v) >= 0.0_wp)))
      if (ld%name == plans%balancing%name) then
        call sheet%attach("data-length", full_number(plans%balancing_length))
        call sheet%attach("data-effort", full_number(plans%effort))
      end if
      if (drawn) then
        call ends(v, f, tail, tip)
        call sheet%arrow(tail(1), tail(2), tip(1), tip(2), colour, width, 2.0_wp)
      end if
      call sheet%end_group()
    end subroutine lever_force
    !> A load's name at its arrow(s).
    pure subroutine names(sheet, ld, colour)
      type(sheet_t), intent(inout) :: sheet
      type(lever_load_t), intent(in) :: ld
      character(*), intent(in) :: colour
      real(wp) :: tail(2), tip(2)
      if (norm2(ld%f) / geo%mu_force < shortest) return
      call ends(ld%at, ld%f, tail, tip)
      call sheet%place_label(display_name(ld%name, lang), "num", tip(1), tip(2), atan2(tip(2) - tail(2), tip(1) - &
        tail(1)), area, tail=tail, colour=colour)
      if (.not. ld%pair) return
      call ends(ld%at2, -ld%f, tail, tip)
      call sheet%place_label(display_name(ld%name, lang), "num", tip(1), tip(2), atan2(tip(2) - tail(2), tip(1) - &
        tail(1)), area, tail=tail, colour=colour)
    end subroutine names
    !> A row of the table: the load and its value (a couple: its force too), its image(s),
    !> its arm as drawn, mm.
    pure subroutine row(sheet, ld, n)
      type(sheet_t), intent(inout) :: sheet
      type(lever_load_t), intent(in) :: ld
      integer, intent(inout) :: n
      character(len=:), allocatable :: text, unit
      character(len=7) :: colour
      unit = unit_word("N", lang)
      if (ld%kind == load_moment) then
        text = display_name(ld%name, lang)//" = "//short_number(ld%value)//" "//unit_word("N*m", lang)
        if (ld%pair) text = text//" → "//short_number(norm2(ld%f))//" "//unit
      else
        text = display_name(ld%name, lang)//" = "//short_number(ld%value)//" "//unit
      end if
      colour = load_colour(ld%source)
      if (ld%name == plans%balancing%name) colour = balancing_colour
      call sheet%text(x, y + lp * n, text, "num", colour=colour, size=fitted_size(text, font, wide * 52.0_wp / 88.0_wp, &
        0.6_wp))
      call sheet%text(x + wide * 54.0_wp / 88.0_wp, y + lp * n, image_list(ld%image), "num", colour=colour, size=font)
      call sheet%text(x + wide, y + lp * n, fixed_number(ld%arm / geo%mu_lever, 1), "num", colour=colour, &
        anchor=anchor_end, size=font)
      n = n + 1
    end subroutine row
  end subroutine draw_lever

  !> "s2" or "b,c" as the sheet names images ("b, c"; p′ for P).
  pure function image_list(text) result(out)
    character(*), intent(in) :: text
    character(len=:), allocatable :: out
    integer :: comma
    comma = index(text, ",")
    if (comma == 0) then
      out = image_label(text)
    else
      out = image_label(text(:comma - 1))//", "//image_label(trim(text(comma + 1:)))
    end if
  end function image_list

  !> The force polygons of the units, each in its cell at its scale: the vectors head to
  !> tail (colours: loads by kind, known reactions, unknown parts), the whole reactions and
  !> the inner ones; an input link drawn with its forces and their arms about its pivot.
  pure subroutine draw_polygons(sheet, geo, drawing, plans, lang)
    type(sheet_t), intent(inout) :: sheet
    type(plans_sheet_t), intent(in) :: geo
    type(drawing_t), intent(in) :: drawing
    type(plans_t), intent(in) :: plans
    integer, intent(in) :: lang
    real(wp), allocatable :: tips(:, :)
    real(wp) :: cell(4), area(4), pole(2), p(2), t(2), lo(2), hi(2), mu
    character(len=:), allocatable :: caption, short
    logical :: drawn
    integer :: e, j
    do e = 1, size(plans%group_polygons)
      associate (poly => plans%group_polygons(e))
        cell = geo%cells(:, e)
        area = cell + [1.0_wp, 5.0_wp, -1.0_wp, -5.0_wp]
        if (geo%mu_link(e) > 0.0_wp .and. .not. poly%input) then
          call draw_group_apart(sheet, drawing, plans, e, geo%link_views(e), geo%link_boxes(:, e), &
            geo%link_force_scale(e), lang, geo%arms_at(:, e))
          call sheet%set_layer(layer_polygons)
          area(1) = geo%link_boxes(3, e) + 1.0_wp
          if (geo%arms_at(2, e) > 0.0_wp) area(4) = geo%arms_at(2, e) - apart_pitch
        else if (geo%mu_link(e) > 0.0_wp) then
          call draw_input_link(sheet, geo, drawing, plans, e, lang)
          call sheet%set_layer(layer_polygons)
          area(1) = geo%link_boxes(3, e)
        end if
        mu = geo%mu_f(e)
        short = ""
        call polygon_tips(poly%vectors, tips)
        do j = 1, size(tips, 2)
          tips(:, j) = geo%view%direction(tips(:, j)) / mu
        end do
        lo = minval(tips, 2)
        hi = maxval(tips, 2)
        pole = 0.5_wp * [area(1) + area(3), area(2) + area(4)] - 0.5_wp * (lo + hi)
        pole = anint(pole * 100.0_wp) / 100.0_wp
        ! the polygon's group: its first vertex, its scale
        call sheet%group("force-polygon")
        call sheet%attach("data-group", trim(poly%link))
        call sheet%attach("data-start", coord(pole(1))//" "//coord(pole(2)))
        call sheet%attach("data-mu", full_number(mu))
        call sheet%attach("data-rotation", full_number(geo%rotation * rad_to_deg))
        do j = 1, size(poly%vectors)
          p = pole + tips(:, j)
          t = pole + tips(:, j + 1)
          if (norm2(t - p) < shortest) then
            if (norm2(poly%vectors(j)%v) > 0.0_wp) call listed(short, display_name(poly%vectors(j)%name, lang))
            cycle
          end if
          call sheet%arrow(p(1), p(2), t(1), t(2), vector_colour(poly%vectors(j)), 0.3_wp, 1.6_wp)
        end do
        ! the whole reactions and the inner ones
        do j = 1, size(poly%reactions)
          call reaction_span(poly, j, pole, tips, p, t, drawn)
          if (.not. drawn) cycle
          call sheet%arrow(p(1), p(2), t(1), t(2), merge(inner_colour, whole_colour, poly%reactions(j)%inner), 0.2_wp, 1.6_wp)
        end do
        call sheet%set_layer(layer_text)
        do j = 1, size(poly%vectors)
          p = pole + tips(:, j)
          t = pole + tips(:, j + 1)
          if (norm2(t - p) < shortest) cycle
          call sheet%place_label(display_name(poly%vectors(j)%name, lang), "num", 0.5_wp * (p(1) + t(1)), &
            0.5_wp * (p(2) + t(2)), atan2(t(2) - p(2), t(1) - p(1)) - 0.5_wp * pi, area, colour=vector_colour(poly%vectors(j)))
        end do
        do j = 1, size(poly%reactions)
          call reaction_span(poly, j, pole, tips, p, t, drawn)
          if (.not. drawn) cycle
          associate (r => poly%reactions(j))
            call sheet%place_label(trim(r%name), "num", 0.5_wp * (p(1) + t(1)), 0.5_wp * (p(2) + t(2)), &
              atan2(t(2) - p(2), t(1) - p(1)) + 0.5_wp * pi, area, colour=merge(inner_colour, whole_colour, r%inner))
          end associate
        end do
        ! the caption and the scale
        if (poly%input) then
          caption = word("input link", lang)//" "//trim(poly%label)
        else
          caption = word("Assur group", lang)//" "//trim(poly%label)
        end if
        if (len(poly%moment) > 0) caption = caption//": "//poly%moment//" = "//short_number(poly%moment_value)//" "// &
          effort_unit(poly%moment, lang)
        call sheet%text(cell(1) + 1.0_wp, cell(2) + 3.0_wp, caption, "small", size=fitted_size(caption, 2.4_wp, &
          cell(3) - cell(1) - 2.0_wp, 0.6_wp))
        caption = "μF = "//scale_number(mu)//" "//unit_word("N", lang)//"/"//unit_word("mm", lang)
        if (len(short) > 0) caption = caption//"; "//word("not drawn, shorter than 1 mm", lang)//": "//short
        if (poly%input .and. geo%mu_link(e) > 0.0_wp .and. geo%lever_table(2) > geo%lever(4) .and. &
          fitted_size(caption, 2.4_wp, cell(3) - area(1) - 2.0_wp, 0.6_wp) >= 1.8_wp) then
          ! (A4: under the polygon where it fits there at 1.8 mm or more, clear of the link's
          ! arms, which may reach the cell's foot)
          call sheet%text(area(1) + 1.0_wp, cell(4) - 1.0_wp, caption, "small", size=fitted_size(caption, 2.4_wp, &
            cell(3) - area(1) - 2.0_wp, 0.6_wp))
        else
          call sheet%text(cell(1) + 1.0_wp, cell(4) - 1.0_wp, caption, "small", size=fitted_size(caption, 2.4_wp, &
            cell(3) - cell(1) - 2.0_wp, 0.6_wp))
        end if
        call sheet%end_group()
        call sheet%set_layer(layer_polygons)
      end associate
    end do
  end subroutine draw_polygons

  !> `text` in `width` mm ending on the line `y`: one line at 2.4 mm or smaller down to 1.8 mm
  !> (ГОСТ 2.304's smallest), else broken after a comma into two lines, the first 2.5 mm above.
  pure subroutine legible_lines(sheet, x, y, width, text)
    type(sheet_t), intent(inout) :: sheet
    real(wp), intent(in) :: x, y, width
    character(*), intent(in) :: text
    integer :: cut
    if (fitted_size(text, 2.4_wp, width, 0.6_wp) >= 1.8_wp) then
      call sheet%text(x, y, text, "small", size=fitted_size(text, 2.4_wp, width, 0.6_wp))
      return
    end if
    cut = index(text(:len(text) / 2 + 1), ", ", back=.true.)
    if (cut == 0) cut = index(text, ", ")
    if (cut == 0) then
      call sheet%text(x, y, text, "small", size=1.8_wp)
      return
    end if
    call sheet%text(x, y - 2.5_wp, text(:cut), "small", size=max(1.8_wp, min(fitted_size(text(:cut), 2.0_wp, &
      width, 0.6_wp), fitted_size(text(cut + 2:), 2.0_wp, width, 0.6_wp))))
    call sheet%text(x, y, text(cut + 2:), "small", size=max(1.8_wp, min(fitted_size(text(:cut), 2.0_wp, width, &
      0.6_wp), fitted_size(text(cut + 2:), 2.0_wp, width, 0.6_wp))))
  end subroutine legible_lines

  !> A note of `width` mm in lines: one line at note_size or smaller down to least_note_size
  !> when it fits so, else broken after its commas into as many lines as it needs at the least
  !> size (each line as full as it goes); `font` the size of them all.
  pure subroutine note_lines(text, width, lines, font)
    character(*), intent(in) :: text
    real(wp), intent(in) :: width
    character(len=note_length), allocatable, intent(out) :: lines(:)
    real(wp), intent(out) :: font
    character(len=:), allocatable :: line, rest
    integer :: cut, i
    allocate (lines(0))
    font = fitted_size(text, note_size, width, 0.6_wp)
    if (font >= least_note_size) then
      lines = [character(len=note_length) :: text]
      return
    end if
    line = ""
    rest = text
    do while (len(rest) > 0)
      cut = index(rest, ", ")
      if (cut == 0) cut = len(rest) + 1
      if (len(line) > 0 .and. fitted_size(line//", "//rest(:cut - 1), least_note_size, width, 0.6_wp) < &
        least_note_size) then
        lines = [character(len=note_length) :: lines, line//","]
        line = ""
      end if
      if (len(line) > 0) line = line//", "
      line = line//rest(:cut - 1)
      rest = rest(min(cut + 2, len(rest) + 1):)
    end do
    lines = [character(len=note_length) :: lines, line]
    font = note_size
    do i = 1, size(lines)
      font = min(font, fitted_size(trim(lines(i)), note_size, width, 0.6_wp))
    end do
    font = max(font, least_note_size)
  end subroutine note_lines

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

  !> Colour of a polygon's vector: a load by its kind (weight, inertia force, external), a
  !> known reaction, an unknown reaction's part.
  pure function vector_colour(v) result(colour)
    type(plan_vector_t), intent(in) :: v
    character(len=7) :: colour
    if (v%kind == component_tangential) then
      colour = tangential_colour
    else if (v%kind == component_normal) then
      colour = relative_colour
    else if (v%kind == component_reaction) then
      colour = tangential_colour
    else if (v%name(1:1) == "G") then
      colour = force_colours(force_gravity)
    else if (v%name(1:3) == "Phi") then
      colour = force_colours(force_inertia)
    else if (len_trim(v%name) == 3 .and. v%name(1:1) == "F" .and. verify(v%name(2:3), "0123456789") == 0) then
      colour = known_colour
    else
      colour = force_colours(force_load)
    end if
  end function vector_colour

  !> The input link of unit e in the left part of its cell: the link alone at a scale of its
  !> own, its forces (all but the frame's reaction) as arrows, the arm of each about the pivot
  !> dashed.
  pure subroutine draw_input_link(sheet, geo, drawing, plans, e, lang)
    type(sheet_t), intent(inout) :: sheet
    type(plans_sheet_t), intent(in) :: geo
    type(drawing_t), intent(in) :: drawing
    type(plans_t), intent(in) :: plans
    integer, intent(in) :: e, lang
    type(drawing_t) :: link
    type(mechanism_view_t) :: view
    character(len=:), allocatable :: short
    real(wp) :: box(4), a(2), tail(2), tip(2), d(2), foot(2), per_newton
    real(wp), allocatable :: foot_x(:), foot_y(:)
    character(len=16), allocatable :: arm_names(:)
    integer :: j, pivot, first
    box = geo%link_boxes(:, e)
    call input_link_drawing(drawing, plans, e, link, pivot)
    if (pivot == 0) return
    view = geo%link_views(e)
    per_newton = geo%link_force_scale(e)
    box(2) = box(2) + 4.0_wp
    ! the arms about the pivot first (the link's labels keep off them), named h with the force
    call sheet%set_layer(layer_polygons)
    a = view%point(link%points(pivot)%p)
    allocate (foot_x(0), foot_y(0), arm_names(0))
    do j = 1, size(link%forces)
      if (norm2(link%forces(j)%f) * per_newton < shortest) cycle
      tail = view%point(link%forces(j)%at)
      tip = tail + view%direction(link%forces(j)%f)
      d = (tip - tail) / norm2(tip - tail)
      foot = tail + dot_product(a - tail, d) * d
      if (norm2(foot - a) < shortest) cycle
      call sheet%line(a(1), a(2), foot(1), foot(2), stroke=arm_colour, width=0.15_wp, dash="1 0.8")
      foot_x = [foot_x, 0.5_wp * (a(1) + foot(1))]
      foot_y = [foot_y, 0.5_wp * (a(2) + foot(2))]
      arm_names = [character(len=16) :: arm_names, arm_name(trim(link%forces(j)%name))]
    end do
    first = sheet%count + 1
    call draw_mechanism(sheet, link, view, box, per_newton, short)
    call mark_other_drawing(sheet, first, "input-link", "link")
    call sheet%set_layer(layer_text)
    do j = 1, size(arm_names)
      call sheet%place_label(trim(arm_names(j)), "num", foot_x(j), foot_y(j), atan2(foot_y(j) - a(2), foot_x(j) - a(1)) - &
        0.5_wp * pi, box, colour=arm_colour)
    end do
    call sheet%text(box(1), box(2) - 1.5_wp, "μl = "//scale_number(view%mu_l())//" "//unit_word("m", lang)//"/"// &
      unit_word("mm", lang), "small")
  contains
    !> The arm's name: h12 for F12, h_G1 for G1.
    pure function arm_name(force) result(name)
      character(*), intent(in) :: force
      character(len=:), allocatable :: name
      if (len(force) == 3 .and. force(1:1) == "F" .and. verify(force(2:), "0123456789") == 0) then
        name = "h"//force(2:)
      else
        name = "h_"//force
      end if
    end function arm_name
  end subroutine draw_input_link

  !> The values table: every entry "v_B = pb·μv = 10.0 m/s", "ω2 = v_CB/l_CB = 11.5 rad/s,
  !> clockwise", in columns; an entry that would be smaller than 1.8 mm broken after its value
  !> (its sense on the next row, indented), as the plans' notes are.
  pure subroutine values_table(sheet, box, plans, lang)
    type(sheet_t), intent(inout) :: sheet
    real(wp), intent(in) :: box(4)
    type(plans_t), intent(in) :: plans
    integer, intent(in) :: lang
    character(len=value_length), allocatable :: lines(:)
    logical, allocatable :: continued(:)
    real(wp) :: font, width, row_pitch
    integer :: i, rows, columns
    logical :: broken
    if (.not. allocated(plans%values)) return
    if (size(plans%values) == 0) return
    call values_layout(plans, box(3) - box(1), box(4) - box(2), lang, font, row_pitch, rows, columns, broken)
    width = (box(3) - box(1) - 4.0_wp) / columns
    call value_lines(plans, lang, merge(width - 1.5_wp, 1.0e6_wp, broken), lines, continued)
    do i = 1, size(lines)
      call sheet%text(box(1) + 2.0_wp + merge(3.0_wp, 0.0_wp, continued(i)) + width * ((i - 1) / rows), &
        box(2) + panel_head + 2.5_wp + row_pitch * modulo(i - 1, rows), trim(lines(i)), "num", &
        size=min(font, fitted_size(trim(lines(i)), font, width - 1.5_wp - merge(3.0_wp, 0.0_wp, continued(i)), 0.6_wp)))
    end do
  end subroutine values_table

  !> The values table's layout in a panel `w` x `h` mm: its rows 3.2 mm apart at 2.2 mm, or
  !> 2.6 mm apart at 1.8 mm (ГОСТ 2.304's smallest) when that needs more than four columns
  !> or a line would be smaller than 1.8 mm; as many rows as the panel holds, the columns
  !> they need; `broken` when even so a line would be smaller: then the entries too long
  !> are broken after their value (value_lines) in the fewest columns that hold the rows.
  pure subroutine values_layout(plans, w, h, lang, font, row_pitch, rows, columns, broken)
    type(plans_t), intent(in) :: plans
    real(wp), intent(in) :: w, h
    integer, intent(in) :: lang
    real(wp), intent(out) :: font, row_pitch
    integer, intent(out) :: rows, columns
    logical, intent(out) :: broken
    character(len=value_length), allocatable :: lines(:)
    logical, allocatable :: continued(:)
    integer :: attempt, n, c
    n = size(plans%values)
    broken = .false.
    do attempt = 1, 2
      font = merge(2.2_wp, 1.8_wp, attempt == 1)
      row_pitch = merge(pitch, 2.6_wp, attempt == 1)
      rows = max(1, int((h - panel_head - 2.0_wp) / row_pitch))
      columns = (n + rows - 1) / rows
      if (columns <= 4 .and. legible(columns)) return
    end do
    do c = 1, 4
      call value_lines(plans, lang, (w - 4.0_wp) / c - 1.5_wp, lines, continued)
      if ((size(lines) + rows - 1) / rows <= c) then
        columns = c
        broken = .true.
        return
      end if
    end do
  contains
    !> Whether every value's line is 1.8 mm or larger in `c` columns.
    pure logical function legible(c)
      integer, intent(in) :: c
      integer :: i
      legible = .true.
      do i = 1, n
        if (fitted_size(value_text(plans%values(i), lang), font, (w - 4.0_wp) / c - 1.5_wp, 0.6_wp) < 1.8_wp) then
          legible = .false.
        end if
      end do
    end function legible
  end subroutine values_layout

  !> The values table's rows for columns `width` mm wide: each entry on one row, or, where it
  !> would be smaller than 1.8 mm there, broken after its value: "ω1 = v_B/l_AB = 7.51 rad/s,"
  !> and its sense on the next row (`continued`, written 3 mm in).
  pure subroutine value_lines(plans, lang, width, lines, continued)
    type(plans_t), intent(in) :: plans
    integer, intent(in) :: lang
    real(wp), intent(in) :: width
    character(len=value_length), allocatable, intent(out) :: lines(:)
    logical, allocatable, intent(out) :: continued(:)
    character(len=:), allocatable :: text
    integer :: i, cut
    allocate (lines(0), continued(0))
    do i = 1, size(plans%values)
      text = value_text(plans%values(i), lang)
      cut = 0
      if (plans%values(i)%sense == "ccw" .or. plans%values(i)%sense == "cw") cut = index(text, ", ", back=.true.)
      if (cut > 0 .and. fitted_size(text, 1.8_wp, width, 0.6_wp) < 1.8_wp) then
        lines = [character(len=value_length) :: lines, text(:cut), text(cut + 2:)]
        continued = [continued, .false., .true.]
      else
        lines = [character(len=value_length) :: lines, text]
        continued = [continued, .false.]
      end if
    end do
  end subroutine value_lines

  !> The least height of a values table's panel `w` mm wide that keeps every line 1.8 mm or
  !> larger (values_layout: rows 2.6 mm apart in as many columns, four at the most, as keep
  !> them so; an entry broken after its value where even one column would not), mm; 0 when
  !> there are no values.
  pure real(wp) function values_table_height(plans, w, lang) result(h)
    type(plans_t), intent(in) :: plans
    real(wp), intent(in) :: w
    integer, intent(in) :: lang
    character(len=value_length), allocatable :: lines(:)
    logical, allocatable :: continued(:)
    integer :: c, i, n
    logical :: fits
    h = 0.0_wp
    if (.not. allocated(plans%values)) return
    n = size(plans%values)
    if (n == 0) return
    do c = 4, 1, -1
      fits = .true.
      do i = 1, n
        if (fitted_size(value_text(plans%values(i), lang), 1.8_wp, (w - 4.0_wp) / c - 1.5_wp, 0.6_wp) < 1.8_wp) then
          fits = .false.
        end if
      end do
      if (fits) exit
    end do
    if (fits) then
      h = panel_head + 2.0_wp + 2.6_wp * real((n + c - 1) / c, wp) + 1.5_wp
      return
    end if
    ! (broken after the value in as many columns, four at the most, as keep the rows legible)
    do c = 4, 1, -1
      call value_lines(plans, lang, (w - 4.0_wp) / c - 1.5_wp, lines, continued)
      fits = .true.
      do i = 1, size(lines)
        if (fitted_size(trim(lines(i)), 1.8_wp, (w - 4.0_wp) / c - 1.5_wp - merge(3.0_wp, 0.0_wp, continued(i)), &
          0.6_wp) < 1.8_wp) fits = .false.
      end do
      if (fits) exit
    end do
    h = panel_head + 2.0_wp + 2.6_wp * real((size(lines) + max(c, 1) - 1) / max(c, 1), wp) + 1.5_wp
  end function values_table_height

  !> A value's line: its name, its formula, the value, its unit and its sense.
  pure function value_text(v, lang) result(text)
    type(plan_value_t), intent(in) :: v
    integer, intent(in) :: lang
    character(len=:), allocatable :: text
    text = display_name(v%name, lang)
    if (len_trim(v%formula) > 0) text = text//" = "//formula_text(trim(v%formula))
    text = text//" = "//short_number(v%value)//" "//unit_word(trim(v%unit), lang)
    if (v%sense == "ccw") text = text//", "//word("counterclockwise", lang)
    if (v%sense == "cw") text = text//", "//word("clockwise", lang)
  end function value_text

  !> A values table's formula as the sheet writes it: "pb*mu_v" -> "p b · μv" (the plan's
  !> segment, its letters apart), "2*omega3*v_B2B3" -> "2 ω3 v_B2B3".
  pure function formula_text(formula) result(text)
    character(*), intent(in) :: formula
    character(len=:), allocatable :: text, rest
    integer :: star
    star = index(formula, "*mu_")
    if (star > 0) then
      text = segment(formula(:star - 1))//" · μ"//formula(star + 4:)
      return
    end if
    ! the product's factors apart, each a symbol (omegaL1 -> omega_L1)
    text = ""
    rest = formula
    do
      star = index(rest, "*")
      if (star == 0) exit
      text = text//display_name(rest(:star - 1), 1)//" "
      rest = rest(star + 1:)
    end do
    text = text//rest
  contains
    !> A plan's segment "pb", "b3c", "πs2" with a thin space after the pole and between images.
    pure function segment(s) result(out)
      character(*), intent(in) :: s
      character(len=:), allocatable :: out
      integer :: i
      out = ""
      do i = 1, len(s)
        if (i > 1) then
          if ((s(i:i) >= "a" .and. s(i:i) <= "z") .and. iachar(s(i - 1:i - 1)) < 128) out = out//" "
          if ((s(i:i) >= "a" .and. s(i:i) <= "z") .and. iachar(s(i - 1:i - 1)) >= 128) out = out//" "
        end if
        out = out//s(i:i)
      end do
    end function segment
  end function formula_text

  !> The balancing effort: from the lever (P_bal and M = P_bal l), the analytic value of the
  !> step and their difference; the two efforts as read off the sheet (the lever and the force
  !> polygons, vectors to 0.5 mm, arms to 1 mm) in %; the flywheel's and the friction's share.
  pure subroutine results(sheet, geo, plans, lang)
    type(sheet_t), intent(inout) :: sheet
    type(plans_sheet_t), intent(in) :: geo
    type(plans_t), intent(in) :: plans
    integer, intent(in) :: lang
    character(len=240), allocatable :: lines(:)
    real(wp) :: x, y, width
    integer :: i
    x = geo%results(1) + 2.0_wp
    y = geo%results(2) + panel_head + 2.5_wp
    width = geo%results(3) - geo%results(1) - 4.0_wp
    allocate (lines(0))
    if (.not. plans%lever_known) then
      call put(lines, word("not drawn", lang)//": "//word(plans%lever_note, lang))
    else
      call lever_lines(lines)
    end if
    do i = 1, size(lines)
      call sheet%text(x, y + pitch * (i - 1), trim(lines(i)), "num", size=fitted_size(trim(lines(i)), 2.2_wp, width, &
        0.6_wp))
    end do
  contains
    !> The lines of a lever that is known.
    pure subroutine lever_lines(lines)
      character(len=240), allocatable, intent(inout) :: lines(:)
      character(len=:), allocatable :: unit
      unit = effort_unit(plans%driver, lang)
    if (plans%balancing%name == "P_bal") then
      call put(lines, display_name("P_bal", lang)//" = "//short_number(dot_sign() * norm2(plans%balancing%f))//" "// &
        unit_word("N", lang)//";  "//plans%driver//" = "//display_name("P_bal", lang)//" l = "// &
        short_number(plans%effort)//" "//unit)
    else
      call put(lines, word("balancing effort from the lever", lang)//": "//plans%driver//" = "// &
        short_number(plans%effort)//" "//unit)
    end if
    ! (A4's course sheet: its panel the lever's room - the lever to be read off - not these)
    if (.not. (geo%groups_apart .and. .not. geo%paper%landscape)) then
      call put(lines, word("analytic value of the step", lang)//": "//plans%driver//" = "//short_number(plans%run)// &
        " "//unit)
      call put(lines, word("relative difference", lang)//": "//short_number(abs(plans%effort - plans%run) / &
        max(abs(plans%run), tiny(1.0_wp))))
    end if
    if (geo%compared) then
      call put(lines, word("read off the sheet (vectors to 0.5 mm, arms to 1 mm)", lang)//":")
      call put(lines, word("lever", lang)//" "//short_number(geo%effort_lever)//", "//word("polygons", lang)//" "// &
        short_number(geo%effort_polygon)//" "//unit//": "//short_number(geo%difference)//" %")
    end if
    if (plans%lever_flywheel) call put(lines, word("flywheel and rotor included", lang)//": J = "// &
      short_number(plans%flywheel_inertia)//" "//unit_word("kg*m^2", lang)//", -J·ε = "// &
      short_number(plans%flywheel_moment)//" "//unit_word("N*m", lang))
    if (plans%lever_friction) call put(lines, word("pair friction included", lang)//": -P_loss/"// &
      plans%lever_rate_name//" = "//short_number(plans%friction_share)//" "//unit)
    end subroutine lever_lines
    pure subroutine put(lines, line)
      character(len=240), allocatable, intent(inout) :: lines(:)
      character(*), intent(in) :: line
      lines = [character(len=240) :: lines, line]
    end subroutine put
    !> The sign of P_bal along its point's velocity.
    pure real(wp) function dot_sign()
      dot_sign = sign(1.0_wp, dot_product(plans%balancing%f, plans%balancing%at))
    end function dot_sign
  end subroutine results

end module kinetostat_plans_draw
