!> The legacy table's RESULTS layout described by column names: a step prints as one or more
!> lines of fixed-width fields, each field a declared column of the step table (or blank);
!> the heading lines come from the columns' own declarations (heading, unit; English or
!> Russian), so a layout never repeats a column's name or unit and never picks a value by
!> its position in the row.
module kinetostat_table_layout
  use kinetostat_kinds, only: wp
  use kinetostat_step_table, only: step_table_t, column_t, column, col_force, col_force_angle
  use kinetostat_format, only: put_fixed, exp_field, fixed_field, int_field, pad_left, pad_right
  use kinetostat_labels, only: lang_en, lang_ru
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_text, only: upper
  implicit none
  private
  public :: table_field_t, field, blank_field, layout_columns, put_layout_heading, put_layout_step, put_layout_rows, heading_of, &
    heading_unit_of, force_and_angle, forces_and_angles, put_fields, &
    column_value, named_column, magnitudes_over_angles, results_page_t, put_layout_block, link_axes_heading, echo_reals, echo_steps

  !> One field of a step's lines in the legacy table.
  type :: table_field_t
    !> Name of the column it prints ("": a blank field, e.g. under the input angle).
    character(len=:), allocatable :: column
    !> Line of the step it is on (1, 2, ...).
    integer :: line = 1
    !> Width, characters.
    integer :: width = 12
    !> Decimals (fixed format) or digits after the point (exponent format).
    integer :: decimals = 2
    !> E format (exp_field) instead of F.
    logical :: exponent = .false.
    !> The heading cut to the field's width (else a longer one pushes the line right).
    logical :: cut = .false.
    !> The heading at the left of the field (the &assur table's N and M of prismatic pairs).
    logical :: left = .false.
    !> Whether the unit lines show the column's unit under it.
    logical :: unit = .true.
    !> A whole number (int_field) instead of F.
    logical :: whole = .false.
    !> Width the field takes in the unit lines when not `width` (0): a printout whose unit
    !> line is narrower there keeps it, byte for byte.
    integer :: unit_width = 0
  end type table_field_t

  !> What a mechanism's RESULTS layout is asked for: one part of a block of the run's rows,
  !> in a language, with or without the headings (the table writer may ask for several parts
  !> of a block at once).
  type :: results_page_t
    !> lang_en or lang_ru.
    integer :: lang = lang_en
    !> First row of the block to write.
    integer :: first = 1
    !> Last row of the block to write (before `first`: none).
    integer :: last = 0
    !> Whether the headings come with these rows (row 1 of the run's first block).
    logical :: heading = .false.
  end type results_page_t

  !> The heading line above a table of reactions in the axes of the links (--frame link),
  !> English and Russian.
  character(*), parameter :: link_axes_text(2) = [character(len=200) :: &
    "REACTIONS IN THE AXES OF THE LINK EACH ACTS ON (LINE 1 ALONG ITS X AXIS, LINE 2 ACROSS), N", &
    "РЕАКЦИИ В ОСЯХ ЗВЕНА, НА КОТОРОЕ ОНИ ДЕЙСТВУЮТ "// &
    "(СТРОКА 1 ВДОЛЬ ОСИ X ЗВЕНА, СТРОКА 2 ПОПЕРЕК), Н"]
  !> What the &assur table adds to it: the crank pin's axes, English and Russian.
  character(*), parameter :: crank_axes_text(2) = [character(len=100) :: &
    "; CRANK PIN IN CRANK AXES (X ALONG PHI1)", &
    "; ШАРНИР КРИВОШИПА В ОСЯХ КРИВОШИПА (X ВДОЛЬ PHI1)"]

contains

  !> A column headed in the legacy table by its name in capitals ("eps_alpha": EPS_ALPHA).
  pure function named_column(name, unit, kind) result(c)
    !> Column name.
    character(*), intent(in) :: name
    !> Unit ("" when dimensionless).
    character(*), intent(in) :: unit
    !> col_* kind.
    integer, intent(in) :: kind
    type(column_t) :: c
    c = column(name, unit, kind, heading=upper(name))
  end function named_column

  !> The two columns of a pair force: its magnitude `name` (N) and its angle `name`G (deg),
  !> headed by their names; `angle_unit` is the unit under the angle's heading when not deg
  !> (and `angle_unit_ru` in Russian).
  pure function force_and_angle(name, angle_unit, angle_unit_ru) result(cols)
    !> Force name ("F21").
    character(*), intent(in) :: name
    !> Heading unit of the angle ("deg/x1": from axis x1), in English and Russian.
    character(*), intent(in), optional :: angle_unit, angle_unit_ru
    type(column_t) :: cols(2)
    cols(1) = column(name, "N", col_force, heading=name)
    if (present(angle_unit)) then
      cols(2) = column(name//"G", "deg", col_force_angle, heading=name//"G", heading_unit=angle_unit, &
                       heading_unit_ru=angle_unit_ru)
    else
      cols(2) = column(name//"G", "deg", col_force_angle, heading=name//"G")
    end if
  end function force_and_angle

  !> The magnitude and angle columns of every force in `names` (blanks trimmed), in order.
  pure function forces_and_angles(names) result(cols)
    !> Force names ("F21", ...).
    character(*), intent(in) :: names(:)
    type(column_t), allocatable :: cols(:)
    integer :: i
    allocate (cols(2 * size(names)))
    do i = 1, size(names)
      cols(2 * i - 1:2 * i) = force_and_angle(trim(names(i)))
    end do
  end function forces_and_angles

  !> A field printing column `name` on line `line` of a step, `width` wide with `decimals`.
  pure function field(name, width, decimals, line, exponent, cut, left, unit, whole, unit_width) result(f)
    !> Column name as declared.
    character(*), intent(in) :: name
    !> Width and decimals.
    integer, intent(in) :: width, decimals
    !> Line of the step (default 1).
    integer, intent(in), optional :: line
    !> E format (default false).
    logical, intent(in), optional :: exponent
    !> Heading cut to the width (default false).
    logical, intent(in), optional :: cut
    !> Heading at the left of the field (default false: at the right, over the value).
    logical, intent(in), optional :: left
    !> Unit shown under the heading (default true).
    logical, intent(in), optional :: unit
    !> A whole number (default false).
    logical, intent(in), optional :: whole
    !> Width in the unit lines (default `width`).
    integer, intent(in), optional :: unit_width
    type(table_field_t) :: f
    f%column = name
    f%width = width
    f%decimals = decimals
    if (present(line)) f%line = line
    if (present(exponent)) f%exponent = exponent
    if (present(cut)) f%cut = cut
    if (present(left)) f%left = left
    if (present(unit)) f%unit = unit
    if (present(whole)) f%whole = whole
    if (present(unit_width)) f%unit_width = unit_width
  end function field

  !> The two lines of a step of the 1991 crank mechanisms' printouts: the input angle `input`
  !> (9 wide) and the force magnitudes `magnitudes` (12 wide), then the fields of `tail` (the
  !> driving moment); under them, after a blank 9 wide, the angles (<name>G, 12 wide) of
  !> the forces `angles`. Names blank-padded.
  pure function magnitudes_over_angles(input, magnitudes, angles, tail) result(fields)
    !> Column of the input angle.
    character(*), intent(in) :: input
    !> Columns of the magnitudes, in their order on line 1.
    character(*), intent(in) :: magnitudes(:)
    !> Forces whose angle columns line 2 shows, in order.
    character(*), intent(in) :: angles(:)
    !> Fields after the magnitudes on line 1.
    type(table_field_t), intent(in) :: tail(:)
    type(table_field_t), allocatable :: fields(:)
    integer :: i
    fields = [field(input, 9, 2)]
    do i = 1, size(magnitudes)
      fields = [fields, field(trim(magnitudes(i)), 12, 2)]
    end do
    fields = [fields, tail, blank_field(9, 2)]
    do i = 1, size(angles)
      fields = [fields, field(trim(angles(i))//"G", 12, 2, line=2)]
    end do
  end function magnitudes_over_angles

  !> A blank field `width` wide on line `line` (under the input angle of line 1).
  pure function blank_field(width, line) result(f)
    integer, intent(in) :: width, line
    type(table_field_t) :: f
    f = field("", width, 0, line)
  end function blank_field

  !> The table's column index of every field (0 for a blank field or a column the table
  !> does not have).
  pure function layout_columns(table, fields) result(cols)
    type(step_table_t), intent(in) :: table
    type(table_field_t), intent(in) :: fields(:)
    integer :: cols(size(fields))
    integer :: i
    do i = 1, size(fields)
      cols(i) = 0
      if (len(fields(i)%column) > 0) cols(i) = table%column_index(fields(i)%column)
    end do
  end function layout_columns

  !> The value of the column called `name` in row `row` (the column must exist).
  pure real(wp) function column_value(table, name, row)
    type(step_table_t), intent(in) :: table
    !> Column name as declared.
    character(*), intent(in) :: name
    !> Row of the table.
    integer, intent(in) :: row
    column_value = table%rows(table%column_index(name), row)
  end function column_value

  !> A column's heading in language `lang`.
  pure function heading_of(c, lang) result(text)
    type(column_t), intent(in) :: c
    integer, intent(in) :: lang
    character(len=:), allocatable :: text
    text = c%heading
    if (lang == lang_ru) text = c%heading_ru
  end function heading_of

  !> The unit under a column's heading in language `lang`.
  pure function heading_unit_of(c, lang) result(text)
    type(column_t), intent(in) :: c
    integer, intent(in) :: lang
    character(len=:), allocatable :: text
    if (lang == lang_ru) then
      ! undeclared (test_columns finds it): the English unit rather than nothing
      text = c%unit
      if (allocated(c%unit_ru)) text = c%unit_ru
      if (allocated(c%heading_unit_ru)) text = c%heading_unit_ru
    else
      text = c%unit
      if (allocated(c%heading_unit)) text = c%heading_unit
    end if
  end function heading_unit_of

  !> The heading lines of a layout: for every line of a step the fields' headings, each
  !> right-aligned in its field (or left-aligned: table_field_t%left); then, with `units`, the
  !> same for their units. Trailing blanks go, except on a heading line with a left-aligned
  !> field (as the &assur table always printed them).
  pure subroutine put_layout_heading(out, table, fields, lang, units, unit_shift, unit_lines)
    type(text_buffer_t), intent(inout) :: out
    type(step_table_t), intent(in) :: table
    type(table_field_t), intent(in) :: fields(:)
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    !> Whether the unit lines follow the heading lines.
    logical, intent(in) :: units
    !> Blanks before the unit line of each line of a step (default none): a printout whose
    !> units stand right of their fields keeps that, byte for byte.
    integer, intent(in), optional :: unit_shift(:)
    !> The unit lines of only the first `unit_lines` lines of a step (default: of every line).
    integer, intent(in), optional :: unit_lines
    integer :: cols(size(fields))
    character(len=:), allocatable :: line, text
    integer :: pass, l, i, width
    logical :: keep
    cols = layout_columns(table, fields)
    ! pass 1: the headings; pass 2: the units
    do pass = 1, merge(2, 1, units)
      do l = 1, maxval(fields%line)
        if (pass == 2 .and. present(unit_lines)) then
          if (l > unit_lines) exit
        end if
        line = ""
        keep = .false.
        if (pass == 2 .and. present(unit_shift)) line = repeat(" ", unit_shift(l))
        do i = 1, size(fields)
          if (fields(i)%line /= l) cycle
          width = fields(i)%width
          if (pass == 2 .and. fields(i)%unit_width > 0) width = fields(i)%unit_width
          if (cols(i) == 0) then
            line = line//repeat(" ", width)
            cycle
          else if (pass == 2) then
            text = ""
            if (fields(i)%unit) text = heading_unit_of(table%columns(cols(i)), lang)
          else
            text = heading_of(table%columns(cols(i)), lang)
            if (fields(i)%cut) text = text(1:min(len(text), fields(i)%width))
            if (fields(i)%left) then
              line = line//pad_right(text, width)
              keep = .true.
              cycle
            end if
          end if
          line = line//pad_left(text, width)
        end do
        if (keep) then
          call out%put(line)
        else
          call out%put(trim(line))
        end if
      end do
    end do
  end subroutine put_layout_heading

  !> A RESULTS block of fields: when the page has the headings, the line `above` (unless
  !> empty), the heading lines (put_layout_heading) and the line `below`; then the page's rows.
  pure subroutine put_layout_block(out, table, page, fields, units, unit_shift, unit_lines, above, below)
    type(text_buffer_t), intent(inout) :: out
    type(step_table_t), intent(in) :: table
    !> The rows to write, the language, whether the headings come.
    type(results_page_t), intent(in) :: page
    type(table_field_t), intent(in) :: fields(:)
    !> Whether the unit lines follow the heading lines.
    logical, intent(in) :: units
    !> As put_layout_heading's.
    integer, intent(in), optional :: unit_shift(:), unit_lines
    !> A line above the headings ("": none) and one below them.
    character(*), intent(in), optional :: above, below
    if (page%heading) then
      if (present(above)) then
        if (len(above) > 0) call out%put(above)
      end if
      call put_layout_heading(out, table, fields, page%lang, units, unit_shift, unit_lines)
      if (present(below)) call out%put(below)
    end if
    call put_layout_rows(out, table, fields, page%first, page%last)
  end subroutine put_layout_block

  !> The line above a table whose reactions are in the axes of the links, a blank first ("" when the table
  !> is in the frame's axes); with `crank_axes`, the crank pin's axes named too.
  pure function link_axes_heading(table, lang, crank_axes) result(text)
    type(step_table_t), intent(in) :: table
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    !> Whether the crank pin's reactions are in the crank's axes (the &assur table).
    logical, intent(in) :: crank_axes
    character(len=:), allocatable :: text
    integer :: l
    text = ""
    if (.not. table%link_frame) return
    l = merge(2, 1, lang == lang_ru)
    text = " "//trim(link_axes_text(l))
    if (crank_axes) text = text//trim(crank_axes_text(l))
  end function link_axes_heading

  !> INPUT DATA records of real deck values, one a name, in order, all in one unit: an echo
  !> as a list of names and values rather than a call per value.
  pure subroutine echo_reals(table, names, values, unit)
    type(step_table_t), intent(inout) :: table
    !> The values' names, as the deck spells them (trailing blanks go).
    character(*), intent(in) :: names(:)
    !> The values, in the order of `names`.
    real(wp), intent(in) :: values(:)
    !> Their unit.
    character(*), intent(in) :: unit
    integer :: i
    do i = 1, size(names)
      call table%echo_real(trim(names(i)), values(i), unit)
    end do
  end subroutine echo_reals

  !> The INPUT DATA records of a run of equal input steps: PHI_START, DPHI and N.
  pure subroutine echo_steps(table, phi_start, dphi, n, start_unit)
    type(step_table_t), intent(inout) :: table
    !> The first input angle and the step, deg.
    real(wp), intent(in) :: phi_start, dphi
    !> Number of steps.
    integer, intent(in) :: n
    !> The unit shown with PHI_START (default "deg").
    character(*), intent(in), optional :: start_unit
    if (present(start_unit)) then
      call table%echo_real("PHI_START", phi_start, start_unit)
    else
      call table%echo_real("PHI_START", phi_start, "deg")
    end if
    call table%echo_real("DPHI", dphi, "deg")
    call table%echo_int("N", n, "steps")
  end subroutine echo_steps

  !> The lines of rows `first` .. `last` of the table (put_layout_step of each).
  pure subroutine put_layout_rows(out, table, fields, first, last)
    type(text_buffer_t), intent(inout) :: out
    type(step_table_t), intent(in) :: table
    type(table_field_t), intent(in) :: fields(:)
    integer, intent(in) :: first, last
    integer :: cols(size(fields))
    integer :: k
    cols = layout_columns(table, fields)
    do k = first, last
      call put_layout_step(out, table%rows(:, k), fields, cols)
    end do
  end subroutine put_layout_rows

  !> The lines of one step: every field of line 1, then of line 2, ... (`cols` from
  !> layout_columns); blank fields at the end of a line are left out.
  pure subroutine put_layout_step(out, v, fields, cols)
    type(text_buffer_t), intent(inout) :: out
    !> The step's row.
    real(wp), intent(in) :: v(:)
    type(table_field_t), intent(in) :: fields(:)
    integer, intent(in) :: cols(:)
    integer :: l, i, last
    do l = 1, maxval(fields%line)
      last = 0
      do i = 1, size(fields)
        if (fields(i)%line == l .and. cols(i) > 0) last = i
      end do
      do i = 1, last
        if (fields(i)%line /= l) cycle
        call put_field(out, v, fields(i), cols(i))
      end do
      call out%end_line()
    end do
  end subroutine put_layout_step

  !> Fields `from` .. `to` of a step's row, one after the other (for a layout whose line
  !> goes on with text of its own; the line is not ended).
  pure subroutine put_fields(out, v, fields, cols, from, to)
    type(text_buffer_t), intent(inout) :: out
    real(wp), intent(in) :: v(:)
    type(table_field_t), intent(in) :: fields(:)
    integer, intent(in) :: cols(:)
    integer, intent(in) :: from, to
    integer :: i
    do i = from, to
      call put_field(out, v, fields(i), cols(i))
    end do
  end subroutine put_fields

  !> One field's text (blank for a blank field). Each form is appended as a result of known
  !> length: gfortran keeps the length of a deferred-length result passed as an argument in a
  !> static variable, which the threads formatting blocks at once would share.
  pure subroutine put_field(out, v, f, col)
    type(text_buffer_t), intent(inout) :: out
    real(wp), intent(in) :: v(:)
    type(table_field_t), intent(in) :: f
    integer, intent(in) :: col
    if (col == 0) then
      call out%append(repeat(" ", f%width))
    else if (f%exponent) then
      call out%append(exp_field(v(col), f%width, f%decimals))
    else if (f%whole) then
      call out%append(int_field(v(col), f%width))
    else
      call put_fixed(out, v(col), f%width, f%decimals)
    end if
  end subroutine put_field

end module kinetostat_table_layout
