!> `kinetostat diff`: two outputs of the program (legacy tables in the same language, or
!> CSV files) compared value by value. Every number is matched by where it stands (section,
!> step, column or echoed variable) and compared with |a - b| <= atol + rtol*max(|a|, |b|);
!> angles (columns in deg) modulo 360 deg with |a - b| <= atol + rtol*(1 rad), because an
!> angle has no scale of its own and a relative error rtol of a force turns it by up to rtol
!> rad; the angle of a force whose magnitude is at or below the noise floor of its step
!> (kinetostat_noise's noise_rel times the step's largest force, or atol) is not compared.
!> Title, deck path and deck title lines are ignored. Pure: the caller reads the files.
module kinetostat_diff
  use kinetostat_kinds, only: wp, rad_to_deg
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_error, only: error_t, fatal_error, exit_input, out_of_memory
  use kinetostat_text, only: int_str, lower, clipped, starts_with, is_name
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_format, only: trimmed_es
  use kinetostat_escape, only: table_text
  use kinetostat_step_table, only: column_t, col_input_angle, col_force_angle
  use kinetostat_noise, only: noise_rel
  use kinetostat_labels, only: label, lang_en, lang_ru
  implicit none
  private
  public :: diff_options_t, diff_outputs, diff_same, diff_different
  public :: default_rtol, atol_units, atol_values, atol_other

  !> Status: every value agrees within the tolerances.
  integer, parameter :: diff_same = 0
  !> Status: some value differs (or is missing on one side).
  integer, parameter :: diff_different = 1
  !> Default relative tolerance (all columns).
  real(wp), parameter :: default_rtol = 1.0e-6_wp
  !> Units with their own default absolute tolerance.
  character(*), parameter :: atol_units(*) = [character(len=4) :: "N", "N*m", "deg", "m", "mm"]
  !> Default absolute tolerances of `atol_units`, in those units (N, N*m, deg, m, mm).
  real(wp), parameter :: atol_values(*) = [1.0e-6_wp, 1.0e-6_wp, 1.0e-6_wp, 1.0e-9_wp, 1.0e-6_wp]
  !> Default absolute tolerance of any other column (dimensionless, m/s, unknown unit).
  real(wp), parameter :: atol_other = 1.0e-9_wp
  !> One radian in degrees: the scale of the relative tolerance of an angle, deg.
  real(wp), parameter :: radian_deg = rad_to_deg
  !> How far ahead (in values) a value of A is looked for in B when the two are out of step.
  integer, parameter :: search_window = 20000
  !> Longest unit text kept for a CSV column.
  integer, parameter :: unit_len = 16
  !> Output form: a CSV file.
  integer, parameter :: form_csv = 1
  !> Output form: a legacy table.
  integer, parameter :: form_table = 2

  !> How to compare.
  type :: diff_options_t
    !> Relative tolerance.
    real(wp) :: rtol = default_rtol
    !> Absolute tolerance of every column in its own unit; negative: the per-unit defaults.
    real(wp) :: atol = -1.0_wp
    !> Differences reported one by one (the rest are counted).
    integer :: max_report = 10
    !> CSV files: compare the columns both have (a column on one side only is left out
    !> instead of being a difference).
    logical :: common = .false.
  end type diff_options_t

  !> The units english_unit knows in either language (their Russian symbols from the labels).
  character(*), parameter :: unit_names(*) = [character(len=8) :: "m", "mm", "kg", "kg*m^2", "N", "N*m", "deg", &
    "rad/s", "rad/s^2", "m/s^2", "m/rad", "m/s", "steps"]

  !> One word of a line and the character (not byte) position of its last character.
  type :: word_t
    !> The word.
    character(len=:), allocatable :: s
    !> Character position of its last character (1-based).
    integer :: last = 0
    !> Character position of its first character (1-based).
    integer :: first = 0
  end type word_t

  !> The words of one line.
  type :: word_line_t
    !> The words.
    type(word_t), allocatable :: words(:)
  end type word_line_t

  !> One value (or one piece of text) of an output, with what identifies it.
  type :: cell_t
    !> Matching key: section, step and column (or variable).
    character(len=:), allocatable :: key
    !> Where it is, for messages ("step 3, column F16", "INPUT DATA, L_AB").
    character(len=:), allocatable :: where
    !> The value or text as printed.
    character(len=:), allocatable :: text
    !> Unit in English ("N", "deg", ...), "" when not known.
    character(len=:), allocatable :: unit
    !> False for text (a remark such as "JAMMED (SELF-LOCKING)", a verdict "OK").
    logical :: is_number = .true.
    !> The value (numbers only), in `unit`.
    real(wp) :: value = 0.0_wp
    !> Whether the value is an angle (compared modulo 360 deg).
    logical :: angle = .false.
    !> For the angle of a force: index of the cell of its magnitude (0: none).
    integer :: magnitude = 0
    !> Step or section the value belongs to (for the noise floor; 0: none).
    integer :: group = 0
  end type cell_t

  !> One output, parsed.
  type :: output_t
    !> File name for messages.
    character(len=:), allocatable :: path
    !> form_csv or form_table.
    integer :: form = form_csv
    !> Language of a table (lang_en, lang_ru).
    integer :: lang = lang_en
    !> The table's title line or the CSV header: which mechanism and columns.
    character(len=:), allocatable :: identity
    !> Column names of every grid of a table ("section: A B C; ..."), the CSV header.
    character(len=:), allocatable :: columns
    !> Number of steps (rows of grids or CSV rows).
    integer :: steps = 0
    !> The values.
    type(cell_t), allocatable :: cells(:)
    !> Number of cells in use.
    integer :: n = 0
    !> Number of groups (steps, sections).
    integer :: groups = 0
    !> Largest magnitude of a value in N in each group, N.
    real(wp), allocatable :: group_max(:)
    !> Values read when the cells could not grow (out of memory); 0: none.
    integer :: no_room = 0
  end type output_t

  !> Counts of a comparison.
  type :: tally_t
    !> Values (and texts) compared.
    integer :: compared = 0
    !> Differences found (values, texts, values on one side only).
    integer :: differing = 0
    !> Angles of vanishing forces not compared.
    integer :: ignored = 0
    !> Differences reported one by one.
    integer :: max_report = 10
  end type tally_t

  !> State of the line-by-line parse of a legacy table.
  type :: table_parser_t
    !> Current section (heading text).
    character(len=:), allocatable :: section
    !> Group of the current section.
    integer :: section_group = 0
    !> Whether data lines now belong to a grid.
    logical :: in_grid = .false.
    !> Name lines of the current grid.
    type(word_line_t), allocatable :: names(:)
    !> Unit lines of the current grid.
    type(word_line_t), allocatable :: units(:)
    !> Current step of the grid and line within the step.
    integer :: step = 0
    !> Line within the current step (1 = the line with the input value).
    integer :: sub = 0
    !> Group of the current step.
    integer :: step_group = 0
    !> First cell of the current step.
    integer :: step_start = 1
    !> Header lines seen since the last data line (line numbers).
    integer, allocatable :: pending(:)
    !> The last echoed variable (for continuation lines of an array).
    character(len=:), allocatable :: last_key
    !> Values on continuation lines so far.
    integer :: continued = 0
    !> The table's heading of the results, in its language (label "RESULTS").
    character(len=:), allocatable :: results
    !> The beginnings of the lines not compared (deck path and title, either language).
    type(word_t) :: ignored(4)
    !> The known units' Russian symbols, in the order of unit_names (english_unit).
    type(word_t) :: units_ru(size(unit_names))
  end type table_parser_t

contains

  !> Compare two outputs given as lines. `status` is diff_same or diff_different and `report`
  !> holds the first differences and a summary line; an output that cannot be read, or two
  !> outputs of different forms, languages, mechanisms or columns, give an error (exit 2).
  pure subroutine diff_outputs(path_a, lines_a, path_b, lines_b, catalog, options, report, status, error)
    !> Name of the first output (messages).
    character(*), intent(in) :: path_a
    !> Its lines.
    character(*), intent(in) :: lines_a(:)
    !> Name of the second output.
    character(*), intent(in) :: path_b
    !> Its lines.
    character(*), intent(in) :: lines_b(:)
    !> Columns the program knows (name, unit, kind), for the units of CSV columns.
    type(column_t), intent(in) :: catalog(:)
    !> Tolerances.
    type(diff_options_t), intent(in) :: options
    !> Report lines.
    type(text_buffer_t), intent(inout) :: report
    !> diff_same or diff_different.
    integer, intent(out) :: status
    !> Unreadable or not comparable (code exit_input).
    type(error_t), allocatable, intent(out) :: error
    type(output_t) :: a, b
    character(len=:), allocatable :: left_out
    logical :: columns_differ
    status = diff_different
    call parse_output(path_a, lines_a, catalog, a, error)
    if (allocated(error)) return
    call parse_output(path_b, lines_b, catalog, b, error)
    if (allocated(error)) return
    call check_comparable(a, b, error)
    if (allocated(error)) return
    left_out = ""
    columns_differ = .false.
    if (a%form == form_csv) then
      call match_columns(a, b, options%common, report, left_out, columns_differ, error)
      if (allocated(error)) return
    end if
    call compare(a, b, options, report, status, left_out, columns_differ)
  end subroutine diff_outputs

  !> Two CSV files' columns matched by name, in any order: both keep only the columns they
  !> share, in A's order. A column on one side only is listed in the report and makes the
  !> files differ (`columns_differ`), or with `common` is left out (`left_out` says so in
  !> the summary). No column in common is an error.
  pure subroutine match_columns(a, b, common, report, left_out, columns_differ, error)
    type(output_t), intent(inout) :: a, b
    logical, intent(in) :: common
    type(text_buffer_t), intent(inout) :: report
    !> "; K columns only in A and M only in B not compared" (with `common`), or "".
    character(len=:), allocatable, intent(out) :: left_out
    logical, intent(out) :: columns_differ
    type(error_t), allocatable, intent(out) :: error
    type(word_t), allocatable :: names_a(:), names_b(:)
    character(len=:), allocatable :: only_a, only_b, shared
    integer :: i, count_a, count_b, count_shared
    allocate (names_a(0), names_b(0)) ! defined before the call (gcc's -Wmaybe-uninitialized on the descriptor)
    call split_csv(a%columns, names_a)
    call split_csv(b%columns, names_b)
    only_a = ""
    only_b = ""
    shared = ""
    count_a = 0
    count_b = 0
    count_shared = 0
    do i = 1, size(names_a)
      if (column_at(names_b, names_a(i)%s) > 0) then
        call add(shared, names_a(i)%s, ",")
        count_shared = count_shared + 1
      else
        call add(only_a, names_a(i)%s, ", ")
        count_a = count_a + 1
      end if
    end do
    do i = 1, size(names_b)
      if (column_at(names_a, names_b(i)%s) == 0) then
        call add(only_b, names_b(i)%s, ", ")
        count_b = count_b + 1
      end if
    end do
    left_out = ""
    columns_differ = .false.
    if (count_shared == 0) then
      call fatal_error(error, exit_input, "no column in common: "//a%path//": "//clipped(a%columns, 100)//"; "// &
        b%path//": "//clipped(b%columns, 100))
      return
    end if
    if (count_a + count_b == 0) then
      if (a%columns == b%columns) return
    else if (common) then
      if (count_a > 0) left_out = int_str(count_a)//" "//columns_word(count_a)//" only in "//a%path
      if (count_a > 0 .and. count_b > 0) left_out = left_out//" and "
      if (count_b > 0) left_out = left_out//int_str(count_b)//" "//columns_word(count_b)//" only in "//b%path
      left_out = "; "//left_out//" not compared"
    else
      if (count_a > 0) call report%put("columns only in "//a%path//": "//only_a)
      if (count_b > 0) call report%put("columns only in "//b%path//": "//only_b)
      columns_differ = .true.
    end if
    call keep_columns(a, shared)
    call keep_columns(b, shared)
  contains
    pure subroutine add(list, name, separator)
      character(len=:), allocatable, intent(inout) :: list
      character(*), intent(in) :: name, separator
      if (len(list) > 0) list = list//separator
      list = list//name
    end subroutine add

    pure function columns_word(n) result(word)
      integer, intent(in) :: n
      character(len=:), allocatable :: word
      word = "columns"
      if (n == 1) word = "column"
    end function columns_word
  end subroutine match_columns

  !> The position of column `name` among `names` (0: none).
  pure integer function column_at(names, name)
    type(word_t), intent(in) :: names(:)
    character(*), intent(in) :: name
    integer :: i
    column_at = 0
    do i = 1, size(names)
      if (names(i)%s == name) then
        column_at = i
        return
      end if
    end do
  end function column_at

  !> A CSV file's cells reduced to the columns `header` names (comma-separated, each a
  !> column of the file), in that order; a force angle keeps its magnitude's cell when that
  !> column is kept.
  pure subroutine keep_columns(doc, header)
    type(output_t), intent(inout) :: doc
    character(*), intent(in) :: header
    type(word_t), allocatable :: names(:), kept(:)
    type(cell_t), allocatable :: cells(:)
    integer, allocatable :: from(:)
    integer :: nc, nk, r, i, old, partner
    allocate (names(0), kept(0)) ! defined before the call (gcc's -Wmaybe-uninitialized on the descriptor)
    call split_csv(doc%columns, names)
    call split_csv(header, kept)
    nc = size(names)
    nk = size(kept)
    allocate (from(nk))
    do i = 1, nk
      from(i) = column_at(names, kept(i)%s)
    end do
    allocate (cells(doc%steps * nk))
    do r = 1, doc%steps
      do i = 1, nk
        old = (r - 1) * nc + from(i)
        cells((r - 1) * nk + i) = doc%cells(old)
        if (doc%cells(old)%magnitude > 0) then
          partner = findloc(from, doc%cells(old)%magnitude - (r - 1) * nc, dim=1)
          cells((r - 1) * nk + i)%magnitude = 0
          if (partner > 0) cells((r - 1) * nk + i)%magnitude = (r - 1) * nk + partner
        end if
      end do
    end do
    call move_alloc(cells, doc%cells)
    doc%n = doc%steps * nk
    doc%columns = header
  end subroutine keep_columns

  !> Same form, language, mechanism and columns, or an error saying which differs.
  pure subroutine check_comparable(a, b, error)
    type(output_t), intent(in) :: a, b
    type(error_t), allocatable, intent(out) :: error
    character(*), parameter :: form_names(2) = [character(len=12) :: "a CSV file", "a table"]
    character(*), parameter :: lang_names(2) = [character(len=7) :: "English", "Russian"]
    if (a%form /= b%form) then
      call fatal_error(error, exit_input, a%path//" is "//trim(form_names(a%form))//", "//b%path//" is "// &
        trim(form_names(b%form))//": not comparable (compare outputs of the same --format)")
    else if (a%lang /= b%lang) then
      call fatal_error(error, exit_input, a%path//" is "//trim(lang_names(a%lang))//", "//b%path//" is "// &
        trim(lang_names(b%lang))//": not comparable (compare tables of the same --lang)")
    else if (a%form == form_table .and. a%identity /= b%identity) then
      call fatal_error(error, exit_input, "not the same mechanism: "//a%path//": '"//a%identity//"', "// &
        b%path//": '"//b%identity//"'")
    else if (a%form == form_table .and. a%columns /= b%columns) then
      call fatal_error(error, exit_input, "not the same columns: "//a%path//": "//clipped(a%columns, 100)//"; "// &
        b%path//": "//clipped(b%columns, 100))
    end if
  end subroutine check_comparable

  !> Walk both outputs in step, compare matched values, report the differences.
  pure subroutine compare(a, b, options, report, status, left_out, columns_differ)
    type(output_t), intent(in) :: a, b
    type(diff_options_t), intent(in) :: options
    type(text_buffer_t), intent(inout) :: report
    integer, intent(out) :: status
    !> "; ... not compared" for the summary line, or "".
    character(*), intent(in) :: left_out
    !> Whether the files have other columns (listed already): they differ.
    logical, intent(in) :: columns_differ
    type(tally_t) :: tally
    integer :: i, j, m
    logical :: found
    tally%max_report = options%max_report
    if (a%steps /= b%steps) call note(tally, report, "steps: "//int_str(a%steps)//" vs "//int_str(b%steps))
    j = 1
    do i = 1, a%n
      found = .false.
      do m = j, min(b%n, j + search_window)
        if (b%cells(m)%key == a%cells(i)%key) then
          found = .true.
          exit
        end if
      end do
      if (.not. found) then
        call note(tally, report, a%cells(i)%where//": "//a%cells(i)%text//" vs (nothing)", one_side=.true.)
        cycle
      end if
      do while (j < m)
        call note(tally, report, b%cells(j)%where//": (nothing) vs "//b%cells(j)%text, one_side=.true.)
        j = j + 1
      end do
      call compare_cell(a, b, i, m, options, tally, report)
      j = m + 1
    end do
    do while (j <= b%n)
      call note(tally, report, b%cells(j)%where//": (nothing) vs "//b%cells(j)%text, one_side=.true.)
      j = j + 1
    end do
    if (tally%differing > tally%max_report) then
      call report%put("... and "//int_str(tally%differing - tally%max_report)//" more")
    end if
    if (tally%differing == 0 .and. .not. columns_differ) then
      status = diff_same
      call report%put("same: "//int_str(tally%compared)//" values agree ("//tolerance_text(options)// &
        ignored_text(tally%ignored)//left_out//")")
    else if (columns_differ) then
      status = diff_different
      call report%put("different: other columns (above); "//int_str(tally%differing)//" of "// &
        int_str(tally%compared)//" values of the shared columns differ ("//tolerance_text(options)// &
        ignored_text(tally%ignored)//")")
    else
      status = diff_different
      call report%put("different: "//int_str(tally%differing)//" of "//int_str(tally%compared)// &
        " values differ ("//tolerance_text(options)//ignored_text(tally%ignored)//left_out//")")
    end if
  end subroutine compare

  !> One difference: reported while under the limit, always counted; a value on one side
  !> only (`one_side`) is also counted as compared.
  pure subroutine note(tally, report, line, one_side)
    type(tally_t), intent(inout) :: tally
    type(text_buffer_t), intent(inout) :: report
    !> The report line.
    character(*), intent(in) :: line
    !> Whether the value is on one side only (default false).
    logical, intent(in), optional :: one_side
    if (present(one_side)) then
      if (one_side) tally%compared = tally%compared + 1
    end if
    tally%differing = tally%differing + 1
    ! (a line of the report: the files' texts as the messages show them, one line each)
    if (tally%differing <= tally%max_report) call report%put(table_text(line))
  end subroutine note

  !> Whether `line` is a CSV header of the program: names (a letter, then letters, digits and
  !> '_'; a joint's name may be Cyrillic) separated by commas.
  pure logical function csv_header(line)
    character(*), intent(in) :: line
    integer :: a, e
    csv_header = .false.
    a = 1
    do while (a <= len(line) + 1)
      e = index(line(a:), ",")
      e = merge(len(line) + 1, a + e - 1, e == 0)
      if (.not. is_name(line(a:e - 1))) return
      a = e + 1
    end do
    csv_header = .true.
  end function csv_header

  !> Compare cell ia of A with cell ib of B (the same key).
  pure subroutine compare_cell(a, b, ia, ib, options, tally, report)
    type(output_t), intent(in) :: a, b
    !> Cell indices in A and B.
    integer, intent(in) :: ia, ib
    type(diff_options_t), intent(in) :: options
    type(tally_t), intent(inout) :: tally
    type(text_buffer_t), intent(inout) :: report
    real(wp) :: x, y, d, tol, floor
    type(cell_t) :: ca, cb
    ca = a%cells(ia)
    cb = b%cells(ib)
    if (.not. (ca%is_number .and. cb%is_number)) then
      tally%compared = tally%compared + 1
      if (ca%text /= cb%text) call note(tally, report, ca%where//": "//ca%text//" vs "//cb%text)
      return
    end if
    x = ca%value
    y = cb%value
    if (ca%angle) then
      if (ca%magnitude > 0 .and. cb%magnitude > 0) then
        floor = max(noise_rel * max(a%group_max(ca%group), b%group_max(cb%group)), atol_of("N", options))
        if (max(abs(a%cells(ca%magnitude)%value), abs(b%cells(cb%magnitude)%value)) <= floor) then
          tally%ignored = tally%ignored + 1
          return
        end if
      end if
      tally%compared = tally%compared + 1
      d = abs(modulo(x - y + 180.0_wp, 360.0_wp) - 180.0_wp)
      tol = atol_of("deg", options) + options%rtol * radian_deg
      if (d > tol) then
        call note(tally, report, ca%where//": "//ca%text//" vs "//cb%text//" (diff "//lower(trimmed_es(d, 1))//" deg)")
      end if
    else
      tally%compared = tally%compared + 1
      d = abs(x - y)
      tol = atol_of(ca%unit, options) + options%rtol * max(abs(x), abs(y))
      if (d > tol) then
        call note(tally, report, ca%where//": "//ca%text//" vs "//cb%text//" (rel "// &
          lower(trimmed_es(d / max(abs(x), abs(y)), 1))//")")
      end if
    end if
  end subroutine compare_cell

  !> "rtol R, atol ..." for the summary line.
  pure function tolerance_text(options) result(text)
    type(diff_options_t), intent(in) :: options
    character(len=:), allocatable :: text
    text = "rtol "//lower(trimmed_es(options%rtol, 1))
    if (options%atol >= 0.0_wp) then
      text = text//", atol "//lower(trimmed_es(options%atol, 1))
    else
      text = text//", default atol per unit"
    end if
  end function tolerance_text

  !> "; K angles of vanishing forces not compared", or "".
  pure function ignored_text(ignored) result(text)
    integer, intent(in) :: ignored
    character(len=:), allocatable :: text
    text = ""
    if (ignored > 0) text = "; "//int_str(ignored)//" angles of vanishing forces not compared"
  end function ignored_text

  !> Absolute tolerance of a value in `unit`.
  pure real(wp) function atol_of(unit, options)
    character(*), intent(in) :: unit
    type(diff_options_t), intent(in) :: options
    integer :: i
    if (options%atol >= 0.0_wp) then
      atol_of = options%atol
      return
    end if
    atol_of = atol_other
    do i = 1, size(atol_units)
      if (unit == trim(atol_units(i))) atol_of = atol_values(i)
    end do
  end function atol_of

  !> Parse one output: a legacy table (first line " KINETOSTAT ...") or a CSV file.
  pure subroutine parse_output(path, lines, catalog, doc, error)
    character(*), intent(in) :: path
    character(*), intent(in) :: lines(:)
    type(column_t), intent(in) :: catalog(:)
    type(output_t), intent(out) :: doc
    type(error_t), allocatable, intent(out) :: error
    character(len=:), allocatable :: first
    doc%path = path
    allocate (doc%cells(64))
    if (size(lines) == 0) then
      call fatal_error(error, exit_input, path//": empty file (not an output of kinetostat)")
      return
    end if
    first = trim(lines(1))
    if (starts_with(first, " KINETOSTAT ")) then
      call parse_table(lines, doc)
    else if (starts_with(first, "{")) then
      call fatal_error(error, exit_input, path//": a JSON output; compare the CSV (--format csv) or table outputs")
      return
    else if (index(first, ",") > 0 .and. csv_header(first)) then
      call parse_csv(lines, catalog, doc, error)
      if (allocated(error)) return
    else
      call fatal_error(error, exit_input, path//": not an output of kinetostat (neither a table nor a CSV file)")
      return
    end if
    if (doc%no_room > 0) then
      call out_of_memory(error, "the values of "//path//" (more than "//int_str(doc%no_room)//")", &
        int(doc%no_room, int64) * storage_size(doc%cells) / 8)
      return
    end if
    call find_group_max(doc)
  end subroutine parse_output

  !> Largest magnitude of the values in N of each group.
  pure subroutine find_group_max(doc)
    type(output_t), intent(inout) :: doc
    integer :: i
    allocate (doc%group_max(0:doc%groups), source=0.0_wp)
    do i = 1, doc%n
      if (.not. doc%cells(i)%is_number .or. doc%cells(i)%unit /= "N") cycle
      doc%group_max(doc%cells(i)%group) = max(doc%group_max(doc%cells(i)%group), abs(doc%cells(i)%value))
    end do
  end subroutine find_group_max

  !> A CSV file of the program: a header of column names, one row of numbers per step.
  pure subroutine parse_csv(lines, catalog, doc, error)
    character(*), intent(in) :: lines(:)
    type(column_t), intent(in) :: catalog(:)
    type(output_t), intent(inout) :: doc
    type(error_t), allocatable, intent(out) :: error
    type(word_t), allocatable :: names(:), fields(:)
    character(len=unit_len), allocatable :: units(:)
    character(len=:), allocatable :: row_word
    logical, allocatable :: angle(:)
    integer, allocatable :: partner(:)
    integer :: c, k, base
    real(wp) :: value
    type(cell_t) :: cell
    logical :: ok
    doc%form = form_csv
    doc%identity = trim(lines(1))
    doc%columns = doc%identity
    call split_csv(doc%identity, names)
    allocate (units(size(names)))
    allocate (angle(size(names)), partner(size(names)))
    do c = 1, size(names)
      call csv_column(names, c, catalog, units(c), angle(c), partner(c))
    end do
    row_word = "step"
    if (lower(names(1)%s) == "stage") row_word = "stage"
    do k = 2, size(lines)
      if (len_trim(lines(k)) == 0) cycle
      call split_csv(trim(lines(k)), fields)
      if (size(fields) /= size(names)) then
        call fatal_error(error, exit_input, doc%path//":"//int_str(k)//": "//int_str(size(fields))// &
          " fields, the header has "//int_str(size(names)))
        return
      end if
      doc%steps = doc%steps + 1
      doc%groups = doc%groups + 1
      base = doc%n
      do c = 1, size(fields)
        if (len_trim(fields(c)%s) == 0) then
          ! an empty field: no value (a jammed cam follower's forces), compared as text
          cell = cell_t(key=int_str(doc%steps)//"|"//names(c)%s, &
            where=row_word//" "//int_str(doc%steps)//", column "//names(c)%s, text="", &
            unit=trim(units(c)), is_number=.false., group=doc%groups)
          call push_cell(doc, cell)
          cycle
        end if
        call read_number(fields(c)%s, value, ok)
        if (.not. ok) then
          call fatal_error(error, exit_input, doc%path//":"//int_str(k)//": column "//names(c)%s// &
            ": '"//fields(c)%s//"' is not a number")
          return
        end if
        cell = cell_t(key=int_str(doc%steps)//"|"//names(c)%s, &
          where=row_word//" "//int_str(doc%steps)//", column "//names(c)%s, text=trim(fields(c)%s), &
          unit=trim(units(c)), value=value, angle=angle(c), group=doc%groups)
        if (partner(c) > 0) cell%magnitude = base + partner(c)
        call push_cell(doc, cell)
      end do
    end do
  end subroutine parse_csv

  !> Unit and angle of CSV column c from the catalog (or, for a name the catalog does not
  !> know, from the naming rule XG = angle of force X), and the column of its force magnitude.
  pure subroutine csv_column(names, c, catalog, unit, angle, partner)
    type(word_t), intent(in) :: names(:)
    integer, intent(in) :: c
    type(column_t), intent(in) :: catalog(:)
    !> Unit of the column ("" when not known).
    character(len=unit_len), intent(out) :: unit
    !> Whether the column holds angles.
    logical, intent(out) :: angle
    !> Column of the force whose angle this is (0: none).
    integer, intent(out) :: partner
    integer :: i, n
    character(len=:), allocatable :: name
    name = names(c)%s
    unit = ""
    angle = .false.
    partner = 0
    do i = 1, size(catalog)
      if (catalog(i)%name /= name) cycle
      unit = catalog(i)%unit
      angle = catalog(i)%kind == col_input_angle .or. catalog(i)%kind == col_force_angle .or. catalog(i)%unit == "deg"
      exit
    end do
    n = len(name)
    if (n < 2) return
    if (name(n:n) /= "G") return
    do i = 1, size(names)
      if (names(i)%s == name(1:n - 1)) then
        partner = i
        angle = .true.
        unit = "deg"
      end if
    end do
  end subroutine csv_column

  !> A legacy table: sections under headings (one leading blank), echo lines "NAME = value
  !> unit", grids (name lines, unit lines, then data lines of numbers aligned under the
  !> names, one or more lines per step), and text lines such as the self-check verdicts.
  pure subroutine parse_table(lines, doc)
    character(*), intent(in) :: lines(:)
    type(output_t), intent(inout) :: doc
    type(table_parser_t) :: p
    type(word_t), allocatable :: words(:)
    integer :: k, lead, tl
    logical :: first_numeric
    real(wp) :: value
    doc%form = form_table
    doc%identity = trim(adjustl(lines(1)))
    doc%columns = ""
    doc%lang = lang_en
    ! (the labels translated once: a lookup searches the whole dictionary)
    p%ignored(1)%s = " "//label("DECK: ", lang_ru)
    do k = 2, size(lines)
      if (starts_with(lines(k), p%ignored(1)%s)) doc%lang = lang_ru
    end do
    p%ignored(2)%s = " "//label("TITLE: ", lang_ru)
    p%ignored(3)%s = " "//label("DECK: ", lang_en)
    p%ignored(4)%s = " "//label("TITLE: ", lang_en)
    p%results = label("RESULTS", doc%lang)
    do k = 1, size(unit_names)
      p%units_ru(k)%s = label(trim(unit_names(k)), lang_ru)
    end do
    p%section = ""
    allocate (p%pending(0))
    do k = 2, size(lines)
      tl = len_trim(lines(k))
      if (tl == 0) then
        call flush_pending(p, lines, doc)
        p%in_grid = .false.
        cycle
      end if
      if (is_ignored_line(lines(k), p%ignored)) cycle
      lead = verify(lines(k), " ") - 1
      if (verify(lines(k)(lead + 1:tl), ".") == 0) cycle
      if (lead <= 1) then
        call flush_pending(p, lines, doc)
        p%in_grid = .false.
        p%section = lines(k)(lead + 1:tl)
        doc%groups = doc%groups + 1
        p%section_group = doc%groups
        p%last_key = ""
        cycle
      end if
      call split_words(lines(k)(1:tl), words)
      call read_number(words(1)%s, value, first_numeric)
      if (first_numeric) then
        if (size(p%pending) > 0) call start_grid(p, lines, doc)
        if (p%in_grid) then
          call data_line(p, words, doc)
        else
          call continuation_line(p, words, doc)
        end if
      else if (index(lines(k), "=") > 0) then
        call flush_pending(p, lines, doc)
        p%in_grid = .false.
        call echo_line(p, lines(k)(1:tl), doc)
      else
        p%pending = [p%pending, k]
      end if
    end do
    call flush_pending(p, lines, doc)
  end subroutine parse_table

  !> Title, deck path and deck title lines (either language): not compared.
  pure logical function is_ignored_line(line, ignored)
    character(*), intent(in) :: line
    !> The lines' beginnings (table_parser_t's ignored).
    type(word_t), intent(in) :: ignored(:)
    integer :: i
    is_ignored_line = .false.
    do i = 1, size(ignored)
      if (starts_with(line, ignored(i)%s)) is_ignored_line = .true.
    end do
  end function is_ignored_line

  !> The pending header lines followed by a data line: name lines up to the first line of
  !> units, unit lines after it.
  pure subroutine start_grid(p, lines, doc)
    type(table_parser_t), intent(inout) :: p
    character(*), intent(in) :: lines(:)
    type(output_t), intent(inout) :: doc
    integer :: i, n_names
    type(word_t), allocatable :: words(:)
    n_names = size(p%pending)
    do i = 1, size(p%pending)
      call split_words(trim(lines(p%pending(i))), words)
      if (all_units(words, p%units_ru)) then
        n_names = i - 1
        exit
      end if
    end do
    if (allocated(p%names)) deallocate (p%names)
    if (allocated(p%units)) deallocate (p%units)
    allocate (p%names(max(n_names, 1)), p%units(size(p%pending) - n_names))
    allocate (p%names(1)%words(0))
    do i = 1, size(p%pending)
      call split_words(trim(lines(p%pending(i))), words)
      if (i <= n_names) then
        p%names(i)%words = words
      else
        p%units(i - n_names)%words = words
      end if
    end do
    doc%columns = doc%columns//p%section//":"
    do i = 1, n_names
      doc%columns = doc%columns//" "//join(p%names(i)%words)
    end do
    doc%columns = doc%columns//"; "
    deallocate (p%pending)
    allocate (p%pending(0))
    p%in_grid = .true.
    p%step = 0
    p%sub = 0
  end subroutine start_grid

  !> A data line of a grid: a new step when its first number stands under the first name of
  !> the first name line, else the next line of the current step.
  pure subroutine data_line(p, words, doc)
    type(table_parser_t), intent(inout) :: p
    type(word_t), intent(in) :: words(:)
    type(output_t), intent(inout) :: doc
    integer :: i, j, c, u, m
    real(wp) :: value
    logical :: ok
    character(len=:), allocatable :: name, unit, text, prefix
    type(cell_t) :: cell
    logical :: new_step
    new_step = p%step == 0
    if (size(p%names(1)%words) > 0) new_step = new_step .or. abs(words(1)%last - p%names(1)%words(1)%last) <= 1
    if (new_step) then
      p%step = p%step + 1
      p%sub = 1
      doc%steps = doc%steps + 1
      doc%groups = doc%groups + 1
      p%step_group = doc%groups
      p%step_start = doc%n + 1
    else
      p%sub = p%sub + 1
    end if
    j = min(p%sub, size(p%names))
    prefix = ""
    if (p%section /= p%results) prefix = p%section//", "
    text = ""
    do i = 1, size(words)
      call read_number(words(i)%s, value, ok)
      if (.not. ok) then
        text = trim(text//" "//words(i)%s)
        cycle
      end if
      c = column_word(p%names(j)%words, words(i)%last)
      if (c > 0) then
        name = p%names(j)%words(c)%s
      else
        name = "#"//int_str(i)
      end if
      unit = ""
      if (j <= size(p%units) .and. c > 0) then
        u = nearest_word(p%units(j)%words, p%names(j)%words(c)%last)
        if (u > 0) unit = english_unit(p%units(j)%words(u)%s, p%units_ru)
      end if
      cell = cell_t(key=p%section//"|"//int_str(p%step)//"|"//name, &
        where=prefix//"step "//int_str(p%step)//", column "//name, text=trim(words(i)%s), unit=unit, value=value, &
        angle=starts_with(unit, "deg"), group=p%step_group)
      if (cell%angle .and. len(name) > 1) then
        if (name(len(name):) == "G") then
          do m = p%step_start, doc%n
            if (doc%cells(m)%key == p%section//"|"//int_str(p%step)//"|"//name(1:len(name) - 1)) then
              cell%magnitude = m
            end if
          end do
        end if
      end if
      call push_cell(doc, cell)
    end do
    if (len(text) > 0) then
      call push_cell(doc, cell_t(key=p%section//"|"//int_str(p%step)//"|text"//int_str(p%sub), &
        where=prefix//"step "//int_str(p%step), text=trim(adjustl(text)), unit="", is_number=.false., group=p%step_group))
    end if
  end subroutine data_line

  !> Numbers under an echo line (the values of an array): NAME(1), NAME(2), ...
  pure subroutine continuation_line(p, words, doc)
    type(table_parser_t), intent(inout) :: p
    type(word_t), intent(in) :: words(:)
    type(output_t), intent(inout) :: doc
    integer :: i
    real(wp) :: value
    logical :: ok
    character(len=:), allocatable :: name
    do i = 1, size(words)
      call read_number(words(i)%s, value, ok)
      p%continued = p%continued + 1
      name = p%last_key//"("//int_str(p%continued)//")"
      call push_cell(doc, cell_t(key=p%section//"|"//name, where=p%section//", "//name, text=trim(words(i)%s), &
        unit="", is_number=ok, value=value, group=p%section_group))
    end do
  end subroutine continuation_line

  !> "NAME = value unit [remark] [NAME2 = value unit]": one cell per number (the second name
  !> joined to the first, e.g. "F12 ANGLE"), the remark as text.
  pure subroutine echo_line(p, line, doc)
    type(table_parser_t), intent(inout) :: p
    character(*), intent(in) :: line
    type(output_t), intent(inout) :: doc
    character(len=:), allocatable :: rest, key, name, text
    type(word_t), allocatable :: words(:)
    integer :: eq, next_eq, i, last, count, first_cell, unit_word
    real(wp) :: value
    logical :: ok
    type(cell_t) :: cell
    eq = index(line, "=")
    key = trim(adjustl(line(1:eq - 1)))
    p%last_key = key
    p%continued = 0
    name = key
    rest = line(eq + 1:)
    first_cell = 0
    do
      next_eq = index(rest, "=")
      if (next_eq > 0) then
        call split_words(rest(1:next_eq - 1), words)
        last = size(words) - 1
      else
        call split_words(rest, words)
        last = size(words)
      end if
      count = 0
      text = ""
      unit_word = 0
      do i = 1, last
        call read_number(words(i)%s, value, ok)
        if (ok) then
          count = count + 1
          cell = cell_t(key=p%section//"|"//name, where=p%section//", "//name, text=trim(words(i)%s), unit="", &
            value=value, group=p%section_group)
          if (count > 1) then
            cell%key = cell%key//"#"//int_str(count)
            cell%where = cell%where//" #"//int_str(count)
          end if
          if (i < last) then
            call read_number(words(i + 1)%s, value, ok)
            if (.not. ok) then
              cell%unit = english_unit(words(i + 1)%s, p%units_ru)
              unit_word = i + 1
            end if
          end if
          ! an echoed angle (dphi, phi_start) is a number; only the angle of a force is modulo 360
          if (starts_with(cell%unit, "deg") .and. first_cell > 0) then
            if (doc%cells(first_cell)%unit == "N") then
              cell%magnitude = first_cell
              cell%angle = .true.
            end if
          end if
          call push_cell(doc, cell)
          if (first_cell == 0) first_cell = doc%n
        else if (i /= unit_word) then
          text = trim(text//" "//words(i)%s)
        end if
      end do
      if (len(text) > 0) call push_cell(doc, cell_t(key=p%section//"|"//name//"|text", where=p%section//", "//name, &
        text=trim(adjustl(text)), unit="", is_number=.false., group=p%section_group))
      if (next_eq == 0) exit
      if (last >= 0 .and. size(words) > 0) name = key//" "//words(size(words))%s
      rest = rest(next_eq + 1:)
    end do
  end subroutine echo_line

  !> Header lines never followed by data (the self-check lines): "LABEL number ... text".
  pure subroutine flush_pending(p, lines, doc)
    type(table_parser_t), intent(inout) :: p
    character(*), intent(in) :: lines(:)
    type(output_t), intent(inout) :: doc
    type(word_t), allocatable :: words(:)
    character(len=:), allocatable :: name, text
    integer :: k, i, count
    real(wp) :: value
    logical :: ok, seen_number
    do k = 1, size(p%pending)
      call split_words(trim(lines(p%pending(k))), words)
      name = ""
      text = ""
      count = 0
      seen_number = .false.
      do i = 1, size(words)
        call read_number(words(i)%s, value, ok)
        if (ok) then
          seen_number = .true.
          count = count + 1
          call push_cell(doc, cell_t(key=p%section//"|"//name//"#"//int_str(count), &
            where=p%section//", "//name, text=trim(words(i)%s), unit="", value=value, group=p%section_group))
        else if (seen_number) then
          text = trim(text//" "//words(i)%s)
        else
          name = trim(name//" "//words(i)%s)
          name = trim(adjustl(name))
        end if
      end do
      name = trim(name)
      if (len(text) > 0 .or. count == 0) then
        call push_cell(doc, cell_t(key=p%section//"|"//name//"|text", where=p%section//", "//name, &
          text=trim(adjustl(text)), unit="", is_number=.false., group=p%section_group))
      end if
    end do
    deallocate (p%pending)
    allocate (p%pending(0))
  end subroutine flush_pending

  !> Index of the column name a value ending at character `last` stands under: the last name
  !> starting at or before `last` (names are right-aligned over their values, or left-aligned
  !> in their field as on the N/M lines of the generic engine); 0 if none.
  pure integer function column_word(names, last)
    type(word_t), intent(in) :: names(:)
    integer, intent(in) :: last
    integer :: i
    column_word = 0
    do i = 1, size(names)
      if (names(i)%first <= last) column_word = i
    end do
  end function column_word

  !> Index of the word whose last character is nearest to `last` (within 2 characters), 0 if none.
  pure integer function nearest_word(words, last)
    type(word_t), intent(in) :: words(:)
    integer, intent(in) :: last
    integer :: i, best
    nearest_word = 0
    best = 3
    do i = 1, size(words)
      if (abs(words(i)%last - last) < best) then
        best = abs(words(i)%last - last)
        nearest_word = i
      end if
    end do
  end function nearest_word

  !> Whether every word is a unit (a line of units under a line of column names).
  pure logical function all_units(words, units_ru)
    type(word_t), intent(in) :: words(:)
    !> The known units' Russian symbols (table_parser_t's units_ru).
    type(word_t), intent(in) :: units_ru(:)
    character(*), parameter :: known(*) = [character(len=8) :: "deg", "N", "N*m", "m", "mm", "m/s", "kg", &
      "rad/s", "deg/x1", "deg/x2"]
    integer :: i
    all_units = size(words) > 0
    do i = 1, size(words)
      if (.not. any(known == english_unit(words(i)%s, units_ru))) all_units = .false.
    end do
  end function all_units

  !> A unit as printed in either language, in English (град -> deg, Н*м -> N*m, ...).
  pure function english_unit(unit, units_ru) result(english)
    character(*), intent(in) :: unit
    !> The Russian symbols of unit_names (table_parser_t's units_ru).
    type(word_t), intent(in) :: units_ru(:)
    character(len=:), allocatable :: english
    character(*), parameter :: degree_ru = "град"
    integer :: i
    english = unit
    if (starts_with(unit, degree_ru)) then
      english = "deg"//unit(len(degree_ru) + 1:)
      return
    end if
    if (unit == "м/с") then
      english = "m/s"
      return
    end if
    do i = 1, size(unit_names)
      if (unit == units_ru(i)%s) english = trim(unit_names(i))
    end do
  end function english_unit

  !> Append a cell.
  pure subroutine push_cell(doc, cell)
    type(output_t), intent(inout) :: doc
    type(cell_t), intent(in) :: cell
    type(cell_t), allocatable :: grown(:)
    integer :: stat
    if (doc%no_room > 0) return
    if (doc%n == size(doc%cells)) then
      allocate (grown(2 * size(doc%cells)), stat=stat)
      if (stat /= 0) then
        ! out of memory: parse_output reports it (the values read so far)
        doc%no_room = doc%n
        return
      end if
      grown(1:doc%n) = doc%cells(1:doc%n)
      call move_alloc(grown, doc%cells)
    end if
    doc%n = doc%n + 1
    doc%cells(doc%n) = cell
  end subroutine push_cell

  !> The blank-separated words of a line and the character position of each word's end
  !> (UTF-8 continuation bytes do not count as characters).
  pure subroutine split_words(line, words)
    character(*), intent(in) :: line
    type(word_t), allocatable, intent(out) :: words(:)
    integer :: i, chars, start, first
    allocate (words(0))
    first = 0
    chars = 0
    start = 0
    do i = 1, len(line)
      if (iand(iachar(line(i:i)), 192) /= 128) chars = chars + 1
      if (line(i:i) /= " " .and. start == 0) then
        start = i
        first = chars
      end if
      if (start > 0 .and. (line(i:i) == " " .or. i == len(line))) then
        if (line(i:i) == " ") then
          words = [words, word_t(line(start:i - 1), chars - 1, first)]
        else
          words = [words, word_t(line(start:i), chars, first)]
        end if
        start = 0
      end if
    end do
  end subroutine split_words

  !> The comma-separated fields of a CSV line.
  pure subroutine split_csv(line, fields)
    character(*), intent(in) :: line
    type(word_t), allocatable, intent(out) :: fields(:)
    integer :: start, at
    allocate (fields(0))
    start = 1
    do
      at = index(line(start:), ",")
      if (at == 0) then
        fields = [fields, word_t(trim(adjustl(line(start:))), 0, 0)]
        exit
      end if
      fields = [fields, word_t(trim(adjustl(line(start:start + at - 2))), 0, 0)]
      start = start + at
    end do
  end subroutine split_csv

  !> The words joined by blanks.
  pure function join(words) result(text)
    type(word_t), intent(in) :: words(:)
    character(len=:), allocatable :: text
    integer :: i
    text = ""
    do i = 1, size(words)
      if (i > 1) text = text//" "
      text = text//words(i)%s
    end do
  end function join

  !> A number as the program prints it ([sign] digits [. digits] [E [sign] digits]); `ok`
  !> is false for anything else (words, "T", "1-2", "(1991").
  pure subroutine read_number(word, value, ok)
    character(*), intent(in) :: word
    real(wp), intent(out) :: value
    logical, intent(out) :: ok
    integer :: i, digits, ios
    value = 0.0_wp
    ok = .false.
    i = 1
    if (len(word) == 0) return
    if (index("+-", word(1:1)) > 0) i = 2
    digits = 0
    do while (i <= len(word))
      if (index("0123456789", word(i:i)) == 0) exit
      digits = digits + 1
      i = i + 1
    end do
    if (i <= len(word)) then
      if (word(i:i) == ".") then
        i = i + 1
        do while (i <= len(word))
          if (index("0123456789", word(i:i)) == 0) exit
          digits = digits + 1
          i = i + 1
        end do
      end if
    end if
    if (digits == 0) return
    if (i <= len(word)) then
      if (index("eEdD", word(i:i)) == 0) return
      i = i + 1
      if (i <= len(word)) then
        if (index("+-", word(i:i)) > 0) i = i + 1
      end if
      if (i > len(word)) return
      if (verify(word(i:), "0123456789") /= 0) return
    end if
    read (word, *, iostat=ios) value
    ok = ios == 0
  end subroutine read_number

end module kinetostat_diff
