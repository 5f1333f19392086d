!> The plans as one JSON object (`--format json --at K --plans`), in the envelope of
!> `--format json` (program, mechanism, title, deck, deck_title, row_name, overrides; then
!> the plans; selfcheck and warnings last). Positions, velocities, accelerations and forces
!> are in the mechanism's position frame (the frame of the CSV); `sheet_rotation` is the turn
!> of the plans sheet's drawings against it (deg, counterclockwise), `scales` the sheet's
!> scales, and the lever's `arm_mm` its arms as drawn on the sheet.
module kinetostat_plans_json
  use kinetostat_kinds, only: wp
  use kinetostat_text, only: int_str, string_t, joined
  use kinetostat_format, only: full_number
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_step_table, only: step_table_t
  use kinetostat_json_writer, only: json_string, put_run_identity, put_run_verdict
  use kinetostat_plans_base, only: plans_t, plan_vector_t, plan_equation_t, lever_load_t, lever_friction_t, &
    force_polygon_t, load_moment, plan_reaction_t
  use kinetostat_plans_sheet, only: plans_sheet_t
  implicit none
  private
  public :: write_plans_json

contains

  !> The plans of row `k` and the sheet's scales as one JSON object.
  pure subroutine write_plans_json(title, plans, sheet, table, k, out)
    !> Title of the mechanism.
    character(*), intent(in) :: title
    type(plans_t), intent(in) :: plans
    type(plans_sheet_t), intent(in) :: sheet
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: k
    type(text_buffer_t), intent(inout) :: out
    integer :: i
    character(len=:), allocatable :: line
    call out%put("{")
    call put_run_identity(title, table, out)
    call out%put('  "step": '//int_str(table%run_row(k))//',')
    if (table%input_column > 0) call out%put('  '//json_string(table%columns(table%input_column)%name)//': '// &
      full_number(table%rows(table%input_column, k))//',')
    call out%put('  "sheet_rotation": '//full_number(plans%sheet_rotation)//',')
    call out%put('  "scales": {"mu_l": '//full_number(sheet%mu_l)//', "drawing_scale": '// &
      json_string(sheet%view%drawing_scale%text)//', "mu_v": '//full_number(sheet%mu_v)//', "mu_a": '// &
      full_number(sheet%mu_a)//', "lever_mu_v": '//full_number(sheet%mu_lever)//', "lever_mu_F": '// &
      full_number(sheet%mu_force)//'},')
    call out%put('  "groups": [')
    do i = 1, size(plans%groups)
      line = '    {"label": '//json_string(plans%groups(i)%label)//', "links": ['//link_list(plans, i)//'], "input": '// &
        logical_json(plans%groups(i)%input)
      if (plans%groups(i)%input) line = line//', "drive": '//json_string(plans%groups(i)%drive)
      call put_item(out, line//'}', i < size(plans%groups))
    end do
    call out%put("  ],")
    call put_vectors(out, "velocity_plan", plans%velocities, "m/s")
    call out%put('  "velocity_residual": '//full_number(plans%velocity_residual)//',')
    call put_vectors(out, "acceleration_plan", plans%accelerations, "m/s^2")
    call out%put('  "acceleration_residual": '//full_number(plans%acceleration_residual)//',')
    call put_equations(out, "velocity_equations", plans%velocity_equations, .false.)
    call put_equations(out, "acceleration_equations", plans%equations, .true.)
    call out%put('  "force_plans": [')
    do i = 1, size(plans%group_polygons)
      associate (poly => plans%group_polygons(i))
        line = '    {"group": '//json_string(trim(poly%link))//', "label": '//json_string(poly%label)//', "input": '// &
          logical_json(poly%input)//', "scale": '//full_number(sheet%mu_f(i))//', "closure": '//full_number(poly%closure)
        if (len(poly%moment) > 0) line = line//', "moment": {"name": '//json_string(poly%moment)//', "value": '// &
          full_number(poly%moment_value)//'}'
        line = line//', "vectors": ['//vectors_json(poly%vectors)//'], "reactions": ['//reactions_json(poly)//"]}"
      end associate
      call put_item(out, line, i < size(plans%group_polygons))
    end do
    call out%put("  ],")
    call out%put('  "link_force_plans": [')
    do i = 1, size(plans%polygons)
      line = '    {"link": '//json_string(trim(plans%polygons(i)%link))//', "closure": '// &
        full_number(plans%polygons(i)%closure)//', "vectors": ['//vectors_json(plans%polygons(i)%vectors)//"]}"
      call put_item(out, line, i < size(plans%polygons))
    end do
    call out%put("  ],")
    call put_lever(out, plans, sheet)
    call out%put('  "values": [')
    do i = 1, size(plans%values)
      associate (v => plans%values(i))
        call put_item(out, '    {"name": '//json_string(trim(v%name))//', "formula": '//json_string(trim(v%formula))// &
          ', "value": '//full_number(v%value)//', "unit": '//json_string(trim(v%unit))//', "sense": '// &
          json_string(trim(v%sense))//'}', i < size(plans%values))
      end associate
    end do
    call out%put("  ],")
    call put_run_verdict(table, out)
    call out%put("}")
  end subroutine write_plans_json

  !> The lever: "zhukovsky" {driver, effort (null when not known, with a note), run; rate;
  !> loads; balancing; comparison; flywheel; friction}.
  pure subroutine put_lever(out, plans, sheet)
    type(text_buffer_t), intent(inout) :: out
    type(plans_t), intent(in) :: plans
    type(plans_sheet_t), intent(in) :: sheet
    integer :: i
    character(len=:), allocatable :: line
    if (.not. plans%lever_known) then
      call out%put('  "zhukovsky": {"driver": '//json_string(plans%driver)//', "effort": null, "run": '// &
        full_number(plans%run)//', "note": '//json_string(plans%lever_note)//'},')
      return
    end if
    call out%put('  "zhukovsky": {"driver": '//json_string(plans%driver)//', "effort": '//full_number(plans%effort)// &
      ', "run": '//full_number(plans%run)//', "rate": {"name": '//json_string(plans%lever_rate_name)//', "value": '// &
      full_number(plans%lever_rate)//'},')
    call out%put('    "loads": [')
    do i = 1, size(plans%loads)
      call put_item(out, '      '//load_json(plans%loads(i), sheet), i < size(plans%loads))
    end do
    call out%put('    ],')
    line = '    "balancing": '//load_json(plans%balancing, sheet)
    if (plans%balancing_length > 0.0_wp) line = line(1:len(line) - 1)//', "l": '//full_number(plans%balancing_length)//'}'
    call out%put(line//',')
    line = '    "comparison": null'
    if (sheet%compared) line = '    "comparison": {"lever": '//full_number(sheet%effort_lever)//', "polygon": '// &
      full_number(sheet%effort_polygon)//', "difference_percent": '//full_number(sheet%difference)// &
      ', "read_off": "vectors to 0.5 mm, arms to 1 mm"}'
    if (plans%lever_flywheel .or. plans%lever_friction) line = line//','
    call out%put(line)
    if (plans%lever_flywheel) then
      line = '    "flywheel": {"J": '//full_number(plans%flywheel_inertia)//', "moment": '// &
        full_number(plans%flywheel_moment)//'}'
      if (plans%lever_friction) line = line//','
      call out%put(line)
    end if
    if (plans%lever_friction) then
      line = '    "friction": {"power": '//full_number(plans%friction_power)//', "rate": '// &
        json_string(plans%lever_rate_name)//', "share": '//full_number(plans%friction_share)//', "pairs": ['
      do i = 1, size(plans%friction)
        if (i > 1) line = line//', '
        line = line//friction_json(plans%friction(i))
      end do
      call out%put(line//']}')
    end if
    call out%put('  },')
  end subroutine put_lever

  !> One load of the lever: {name, kind, value, unit, image, arm_mm, arm_plan, power, link, and
  !> the force (x, y) or the couple (x, y of its force at its first point, l, points)}.
  pure function load_json(ld, sheet) result(text)
    type(lever_load_t), intent(in) :: ld
    type(plans_sheet_t), intent(in) :: sheet
    character(len=:), allocatable :: text
    character(len=:), allocatable :: unit
    unit = "N"
    if (ld%kind == load_moment) unit = "N*m"
    text = '{"name": '//json_string(trim(ld%name))//', "kind": '//json_string(trim(ld%kind))//', "value": '// &
      full_number(ld%value)//', "unit": '//json_string(unit)//', "image": '//json_string(trim(ld%image))// &
      ', "arm_mm": '//full_number(ld%arm / sheet%mu_lever)//', "arm_plan": '//full_number(ld%arm)//', "power": '// &
      full_number(ld%power)//', "link": '//json_string(trim(ld%link))
    if (ld%kind == load_moment) then
      text = text//', "couple": {"x": '//full_number(ld%f(1))//', "y": '//full_number(ld%f(2))//', "l": '// &
        full_number(ld%l)//', "points": ['//json_string(trim(ld%points(1)))//', '//json_string(trim(ld%points(2)))//']}'
    else
      text = text//', "x": '//full_number(ld%f(1))//', "y": '//full_number(ld%f(2))//', "points": ['// &
        json_string(trim(ld%points(1)))
      if (ld%pair) text = text//', '//json_string(trim(ld%points(2)))
      text = text//']'
    end if
    text = text//'}'
  end function load_json

  !> One pair's friction on the lever as a JSON object: {"pair", "on", "from", "moment" and
  !> "relative" (rad/s) at a revolute pair, "force", "at" and "relative" (m/s) as {x, y} at a
  !> prismatic one, "power" (W)}.
  pure function friction_json(pf) result(text)
    type(lever_friction_t), intent(in) :: pf
    character(len=:), allocatable :: text
    text = '{"pair": '//json_string(trim(pf%pair))//', "on": '//json_string(trim(pf%on))//', "from": '// &
      json_string(trim(pf%from))//', '
    if (pf%prismatic) then
      text = text//'"force": '//xy(pf%force)//', "at": '//xy(pf%at)//', "relative": '//xy(pf%relative)
    else
      text = text//'"moment": '//full_number(pf%moment)//', "relative": '//full_number(pf%relative(1))
    end if
    text = text//', "power": '//full_number(pf%power)//'}'
  contains
    pure function xy(v) result(t)
      real(wp), intent(in) :: v(2)
      character(len=:), allocatable :: t
      t = '{"x": '//full_number(v(1))//', "y": '//full_number(v(2))//'}'
    end function xy
  end function friction_json

  !> A group's links as a JSON list of strings.
  pure function link_list(plans, i) result(text)
    type(plans_t), intent(in) :: plans
    integer, intent(in) :: i
    character(len=:), allocatable :: text
    text = joined(name_json(plans%groups(i)%names), ", ")
  end function link_list

  !> A blank-padded name as a JSON string.
  elemental function name_json(name) result(part)
    character(*), intent(in) :: name
    type(string_t) :: part
    part%s = json_string(trim(name))
  end function name_json

  pure function logical_json(x) result(text)
    logical, intent(in) :: x
    character(len=:), allocatable :: text
    text = trim(merge("true ", "false", x))
  end function logical_json

  !> "key": {"unit": ..., "points": [vectors]}, as one member of the plans object.
  pure subroutine put_vectors(out, key, vectors, unit)
    type(text_buffer_t), intent(inout) :: out
    character(*), intent(in) :: key, unit
    type(plan_vector_t), intent(in) :: vectors(:)
    integer :: q
    call out%put('  "'//key//'": {"unit": "'//unit//'", "points": [')
    do q = 1, size(vectors)
      call put_item(out, "    "//vector_json(vectors(q)), q < size(vectors))
    end do
    call out%put("  ]},")
  end subroutine put_vectors

  !> The vector equations of a plan as a JSON array under `key`, each with its components in
  !> drawing order; `mark_reverse`: the reversed slider equations carry "reverse": true.
  pure subroutine put_equations(out, key, equations, mark_reverse)
    type(text_buffer_t), intent(inout) :: out
    !> The array's name.
    character(*), intent(in) :: key
    !> The equations.
    type(plan_equation_t), intent(in) :: equations(:)
    !> Whether to mark the reversed equations.
    logical, intent(in) :: mark_reverse
    character(len=:), allocatable :: line
    integer :: i
    call out%put('  "'//key//'": [')
    do i = 1, size(equations)
      associate (eq => equations(i))
        line = '    {"point": '//json_string(trim(eq%point))//', "link": '//json_string(trim(eq%link))//', "from": '// &
          json_string(trim(eq%from))//', "slider": '//json_string(trim(eq%slider))//', '
        if (mark_reverse .and. eq%reverse) line = line//'"reverse": true, '
        line = line//'"vectors": ['//vectors_json(eq%vectors)//"]}"
      end associate
      call put_item(out, line, i < size(equations))
    end do
    call out%put("  ],")
  end subroutine put_equations

  !> {"name": ..., "x": ..., "y": ...}.
  pure function vector_json(v) result(text)
    type(plan_vector_t), intent(in) :: v
    character(len=:), allocatable :: text
    text = '{"name": '//json_string(trim(v%name))//', '
    if (len_trim(v%kind) > 0) text = text//'"kind": "'//v%kind//'", '
    text = text//'"x": '//full_number(v%v(1))//', "y": '//full_number(v%v(2))//"}"
  end function vector_json

  !> A group polygon's whole reactions: {"name", "x", "y", "inner", "tail", "head"} (the
  !> vertices it is drawn between).
  pure function reactions_json(poly) result(text)
    type(force_polygon_t), intent(in) :: poly
    character(len=:), allocatable :: text
    text = joined(reaction_json(poly%reactions), ", ")
  end function reactions_json

  !> One reaction of a group polygon as a JSON object.
  elemental function reaction_json(r) result(part)
    type(plan_reaction_t), intent(in) :: r
    type(string_t) :: part
    part%s = '{"name": '//json_string(trim(r%name))//', "x": '//full_number(r%v(1))//', "y": '// &
      full_number(r%v(2))//', "inner": '//logical_json(r%inner)//', "tail": '//int_str(r%tail)//', "head": '// &
      int_str(r%head)//'}'
  end function reaction_json

  !> Vectors as JSON objects separated by commas.
  pure function vectors_json(vectors) result(text)
    type(plan_vector_t), intent(in) :: vectors(:)
    character(len=:), allocatable :: text
    text = joined(vector_part(vectors), ", ")
  contains
    elemental function vector_part(v) result(part)
      type(plan_vector_t), intent(in) :: v
      type(string_t) :: part
      part%s = vector_json(v)
    end function vector_part
  end function vectors_json

  !> One line of a JSON array, with a comma when more follow.
  pure subroutine put_item(out, line, more)
    type(text_buffer_t), intent(inout) :: out
    !> The item.
    character(*), intent(in) :: line
    !> Whether more items follow.
    logical, intent(in) :: more
    if (more) then
      call out%put(line//",")
    else
      call out%put(line)
    end if
  end subroutine put_item

end module kinetostat_plans_json
