!> Legacy table writer: the frame every mechanism's printout shares (title, deck, INPUT DATA
!> echo, RESULTS heading, self-check footer) around the mechanism's own RESULTS layout, in
!> English or in the Russian of the 1991 printouts.
module kinetostat_table_writer
  use kinetostat_kinds, only: wp
  use kinetostat_selfcheck, only: selfcheck_tolerance
  use kinetostat_step_table, only: step_table_t, echo_record_t, echo_cursor_t, echo_real_kind, &
    echo_int_kind, echo_logical_kind, echo_array_kind, echo_text_kind, echo_heading_kind, echo_line_kind, col_force
  use kinetostat_format, only: pad_left, echo_number, echo_array_number, footer_number, limit_number, pad_right, put_fixed, &
    fixed_field, display_width
  use kinetostat_labels, only: label, lang_ru, phrase, echo_name
  use kinetostat_summary, only: column_stats_t, column_stats, drive_work
  use kinetostat_text, only: upper
  use kinetostat_escape, only: table_text
  use kinetostat_mechanism, only: mechanism_t
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_row_blocks, only: put_row_blocks_two, row_writer_t, text_sink_t
  use kinetostat_shaking, only: shaking_column_names
  implicit none
  private
  public :: write_table_head, write_table_rows, write_table_tail, write_shaking_rows
  public :: put_heading, selfcheck_verdict, put_two_line_step, value_line

  !> Display width of the name part of an INPUT DATA line ("   NAME ... =" puts "=" in column 20).
  integer, parameter :: echo_name_width = 16
  !> Display width of the label part of a footer line (the figure starts in column 58).
  integer, parameter :: footer_label_width = 54
  !> Mark after an INPUT DATA record whose value came from --set.
  character(*), parameter :: override_mark = " (--set)"
  !> Bytes a row of the legacy table takes per column, about (room made for a block's rows).
  integer, parameter :: table_row_room = 14

  !> Display width of the name part of a DYNAMICS line.
  integer, parameter :: dynamics_name_width = 34
  !> Values per line of an echoed array.
  integer, parameter :: echo_array_per_line = 5

  !> The legacy table's rows: the mechanism's RESULTS layout over a block of the table.
  type, extends(row_writer_t) :: layout_rows_t
    !> The mechanism (during write_table_rows only).
    class(mechanism_t), pointer :: mech => null()
    !> The rows of one block of the run (during write_table_rows only).
    type(step_table_t), pointer :: table => null()
    !> lang_en or lang_ru.
    integer :: lang = 0
  contains
    procedure :: put_rows => put_layout_rows
  end type layout_rows_t

contains

  !> The mechanism's RESULTS lines of the rows now in `table` (one block of the run): in
  !> parallel parts with more than one OpenMP thread (the same bytes as one thread).
  subroutine write_table_rows(mech, table, lang, out, later, sink)
    !> The mechanism (its RESULTS layout).
    class(mechanism_t), intent(in), target :: mech
    !> Finite results: the rows of one block of the run.
    type(step_table_t), intent(in), target :: table
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    !> Where the RESULTS lines go.
    type(text_buffer_t), intent(inout) :: out
    !> Where a layout's second section over the same rows goes (after the last row).
    type(text_buffer_t), intent(inout) :: later
    !> Takes the text of `out` so far while the rows are formatted in parallel (see
    !> put_row_blocks).
    class(text_sink_t), intent(inout), optional :: sink
    type(layout_rows_t) :: rows
    rows%mech => mech
    rows%table => table
    rows%lang = lang
    call put_row_blocks_two(table%row_count(), table_row_room * size(table%columns), rows, out, later, sink)
  end subroutine write_table_rows

  !> Rows `first` to `last` of the mechanism's layout.
  subroutine put_layout_rows(self, first, last, out, later)
    !> The mechanism, the table and the language.
    class(layout_rows_t), intent(in) :: self
    !> First and last row.
    integer, intent(in) :: first, last
    !> Where the RESULTS lines go.
    type(text_buffer_t), intent(inout) :: out
    !> Where the layout's second section goes.
    type(text_buffer_t), intent(inout) :: later
    call self%mech%write_results(self%table, self%lang, first, last, out, later)
  end subroutine put_layout_rows

  !> The shaking block of the legacy table (--shaking), the rows now in `table`: with the
  !> run's first block its heading and the column and unit lines; per step the input
  !> coordinate and the shaking and frame columns the table has (12 wide, 2 decimals).
  pure subroutine write_shaking_rows(table, lang, out)
    !> Finite results: the rows of one block of the run, with the shaking columns.
    type(step_table_t), intent(in) :: table
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    !> Where the lines go.
    type(text_buffer_t), intent(inout) :: out
    integer, allocatable :: cols(:)
    integer :: i, c, k
    allocate (cols(0))
    do i = 1, size(shaking_column_names)
      c = table%column_index(trim(shaking_column_names(i)))
      if (c > 0) cols = [cols, c]
    end do
    if (size(cols) == 0 .or. table%input_column == 0) return
    if (table%first_block()) then
      call put_heading(out, label("SHAKING FORCE AND MOMENT, FORCE AND MOMENT ON THE FRAME (MOMENTS ABOUT THE ORIGIN)", &
        lang))
      call out%put("")
      call out%append(adjustr(pad_right(upper(table%columns(table%input_column)%name), 9)))
      do i = 1, size(cols)
        call out%append(adjustr(pad_right(upper(table%columns(cols(i))%name), 12)))
      end do
      call out%end_line()
      call out%append(pad_left(label(table%columns(table%input_column)%unit, lang), 9))
      do i = 1, size(cols)
        call out%append(pad_left(label(table%columns(cols(i))%unit, lang), 12))
      end do
      call out%end_line()
    end if
    do k = 1, table%row_count()
      call put_fixed(out, table%rows(table%input_column, k), 9, 2)
      do i = 1, size(cols)
        call put_fixed(out, table%rows(cols(i), k), 12, 2)
      end do
      call out%end_line()
    end do
  end subroutine write_shaking_rows

  !> The legacy table's lines before the rows: title, deck, INPUT DATA, the RESULTS heading.
  !> With `cursor`, a part at a time: up to a chunk of an echoed array's values, then it
  !> returns (cursor%done false) for the caller to drain `out`, and goes on when called again.
  pure subroutine write_table_head(mech, table, lang, out, cursor)
    !> The mechanism (its title).
    class(mechanism_t), intent(in) :: mech
    !> The results (the first block: columns and echo).
    type(step_table_t), intent(in) :: table
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    !> Where the lines go.
    type(text_buffer_t), intent(inout) :: out
    !> Where the head is (written whole when absent).
    type(echo_cursor_t), intent(inout), optional :: cursor
    type(echo_cursor_t) :: whole
    if (present(cursor)) then
      call head_part(mech, table, lang, out, cursor)
    else
      do while (.not. whole%done)
        call head_part(mech, table, lang, out, whole)
      end do
    end if
  end subroutine write_table_head

  !> The header line of the 1991 programs (T.FTN's "ДАТА ... ВРЕМЯ ... ФАМИЛИЯ"): date, time,
  !> surname, group and variant of the student who ran the deck.
  pure function student_line(table, lang) result(line)
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: lang
    character(len=:), allocatable :: line
    integer :: blank
    blank = index(table%student%stamp, " ")
    if (lang == lang_ru) then
      line = "ДАТА "//table%student%stamp(:blank - 1)//"  ВРЕМЯ "//table%student%stamp(blank + 1:)//"  ФАМИЛИЯ "// &
        table_text(table%student%name)//"  ГРУППА "//table_text(table%student%group)//"  ВАРИАНТ "// &
        table_text(table%student%variant)
    else
      line = "DATE "//table%student%stamp(:blank - 1)//"  TIME "//table%student%stamp(blank + 1:)//"  NAME "// &
        table_text(table%student%name)//"  GROUP "//table_text(table%student%group)//"  VARIANT "// &
        table_text(table%student%variant)
    end if
  end function student_line

  !> The next part of the head (see write_table_head).
  pure subroutine head_part(mech, table, lang, out, cursor)
    class(mechanism_t), intent(in) :: mech
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: lang
    type(text_buffer_t), intent(inout) :: out
    type(echo_cursor_t), intent(inout) :: cursor
    integer :: i
    if (cursor%record == 0) then
      if (allocated(table%student)) call out%put(" "//student_line(table, lang))
      call out%put(" "//mech%title(lang))
      call out%put(" "//label("DECK: ", lang)//table_text(table%deck))
      if (allocated(table%subtitle)) call out%put(" "//label("TITLE: ", lang)//table_text(table%subtitle))
      call put_heading(out, label("INPUT DATA", lang))
      if (allocated(table%overrides)) then
        do i = 1, size(table%overrides)
          call out%put("   --set "//table_text(trim(table%overrides(i))))
        end do
      end if
      cursor%record = 1
      cursor%value = 0
    end if
    do while (cursor%record <= table%echo_count)
      call put_echo(out, table%echo(cursor%record), lang, cursor)
      if (cursor%value > 0) return
      cursor%record = cursor%record + 1
    end do
    call put_heading(out, label("RESULTS", lang))
    cursor%done = .true.
  end subroutine head_part

  !> The legacy table's lines after the rows: the SUMMARY block, the mechanism's summary
  !> records and the self-check footer.
  pure subroutine write_table_tail(table, lang, out)
    !> The results of the whole run (tallied, self-check figures).
    type(step_table_t), intent(in) :: table
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    !> Where the lines go.
    type(text_buffer_t), intent(inout) :: out
    call put_run_summary(out, table, lang)
    if (allocated(table%summary)) call put_summary(out, table, lang)
    if (table%dynamics%present) call put_dynamics(out, table, lang)
    if (table%has_selfcheck) call put_footer(out, table, lang)
  end subroutine write_table_tail

  !> A heading: a blank line, then the text after one blank.
  pure subroutine put_heading(out, text)
    !> Where the lines go.
    type(text_buffer_t), intent(inout) :: out
    !> Heading text.
    character(*), intent(in) :: text
    call out%put("")
    call out%put(" "//text)
  end subroutine put_heading

  !> One step as PR 3207 and T.FTN print it: the input angle (9 wide) and the magnitudes
  !> (12 wide, 2 decimals), then `tail`; under them the angles of the same forces.
  pure subroutine put_two_line_step(out, v, line1_columns, line2_columns, tail)
    !> Where the lines go.
    type(text_buffer_t), intent(inout) :: out
    !> The step's row; v(1) is the input angle.
    real(wp), intent(in) :: v(:)
    !> Columns of line 1 after the angle (magnitudes).
    integer, intent(in) :: line1_columns(:)
    !> Columns of line 2 (angles, each under its magnitude).
    integer, intent(in) :: line2_columns(:)
    !> Text after line 1's fields (e.g. the driving moment's field).
    character(*), intent(in) :: tail
    integer :: i
    call put_fixed(out, v(1), 9, 2)
    do i = 1, size(line1_columns)
      call put_fixed(out, v(line1_columns(i)), 12, 2)
    end do
    call out%put(tail)
    call out%append(repeat(" ", 9))
    do i = 1, size(line2_columns)
      call put_fixed(out, v(line2_columns(i)), 12, 2)
    end do
    call out%end_line()
  end subroutine put_two_line_step

  !> One INPUT DATA record (its first line ends in " (--set)" when --set gave the value).
  !> With `cursor`, an array's values a chunk at a time: cursor%value is left at the values
  !> written when some remain, at 0 when the record is done.
  pure subroutine put_echo(out, e, lang, cursor)
    type(text_buffer_t), intent(inout) :: out
    type(echo_record_t), intent(in) :: e
    integer, intent(in) :: lang
    type(echo_cursor_t), intent(inout), optional :: cursor
    character(len=18) :: whole
    character(len=:), allocatable :: mark
    integer :: n, first, last
    mark = ""
    if (e%overridden) mark = override_mark
    select case (e%kind)
    case (echo_real_kind)
      call out%put(value_line(echo_name(e%name, lang), e%values(1), phrase(e%unit, lang))//mark)
    case (echo_int_kind)
      write (whole, '(i18)') e%int_value
      call out%put(name_part(echo_name(e%name, lang))//whole//"  "//phrase(e%unit, lang)//mark)
    case (echo_logical_kind)
      write (whole, '(l18)') e%logical_value
      call out%put(name_part(echo_name(e%name, lang))//whole//"  "//phrase(e%unit, lang)//mark)
    case (echo_text_kind)
      call out%put(name_part(e%name)//"  "//phrase(e%text, lang)//mark)
    case (echo_array_kind)
      n = e%value_count()
      first = 1
      last = n
      ! whole lines per chunk
      if (present(cursor)) call cursor%take(n, echo_array_per_line, first, last)
      if (first == 1) then
        write (whole, '(i0)') n
        call out%put(name_part(e%name//"("//trim(whole)//")")//"  "//phrase(e%unit, lang)//mark)
      end if
      call put_array_lines(out, e, first, last)
      if (n == 0) call out%put("")
    case (echo_heading_kind)
      call put_heading(out, echo_name(e%name, lang))
    case default ! echo_line_kind: a line printed as it is (its words translated)
      call out%put(echo_name(e%name, lang))
    end select
  end subroutine put_echo

  !> Values first .. last of an echoed array, echo_array_per_line to a line (`first` begins a
  !> line; the last line may be short).
  pure subroutine put_array_lines(out, e, first, last)
    type(text_buffer_t), intent(inout) :: out
    type(echo_record_t), intent(in) :: e
    integer, intent(in) :: first, last
    real(wp), allocatable :: v(:)
    character(len=:), allocatable :: line
    integer :: i
    if (last < first) return
    allocate (v(last - first + 1))
    call e%get_values(first, last, v)
    line = ""
    do i = first, last
      line = line//echo_array_number(v(i - first + 1))
      if (mod(i, echo_array_per_line) == 0 .or. i == last) then
        call out%put(repeat(" ", 6)//line)
        line = ""
      end if
    end do
  end subroutine put_array_lines

  !> An INPUT DATA style line of a real: "   NAME            =  value  unit".
  pure function value_line(name, x, unit) result(line)
    !> Name as printed.
    character(*), intent(in) :: name
    !> Finite value.
    real(wp), intent(in) :: x
    !> Unit text.
    character(*), intent(in) :: unit
    character(len=:), allocatable :: line
    line = name_part(name)//echo_number(x)//"  "//unit
  end function value_line

  !> "   NAME" padded so that "=" falls in column 20, then "=".
  pure function name_part(name) result(text)
    character(*), intent(in) :: name
    character(len=:), allocatable :: text
    text = "   "//pad_right(name, echo_name_width)//"="
  end function name_part

  !> "OK" when a self-check figure is within the limit, "!!" otherwise (also for NaN).
  pure function selfcheck_verdict(x) result(verdict)
    !> Self-check figure.
    real(wp), intent(in) :: x
    character(len=2) :: verdict
    verdict = "!!"
    if (x <= selfcheck_tolerance) verdict = "OK"
  end function selfcheck_verdict

  !> The SUMMARY block of a run over an input angle (none for the gears' stages): per
  !> force magnitude column its largest value and the input angle where it occurs; the
  !> driving effort's largest, smallest and mean value (mean over the input angle) and
  !> its work over the run.
  pure subroutine put_run_summary(out, table, lang)
    type(text_buffer_t), intent(inout) :: out
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: lang
    type(column_stats_t) :: s
    character(len=:), allocatable :: input
    real(wp) :: work
    logical :: known
    integer :: c, d, n
    n = table%run_tally%rows
    if (table%input_column == 0 .or. n == 0) return
    input = upper(table%columns(table%input_column)%name)
    call put_heading(out, label("SUMMARY", lang)//" ("//input//" "// &
      trim(adjustl(fixed_field(table%run_tally%first_at, 9, 2)))//" ... "// &
      trim(adjustl(fixed_field(table%run_tally%last_at, 9, 2)))//" "// &
      label(table%columns(table%input_column)%unit, lang)//")")
    if (table%run_tally%void_rows > 0) call out%put(left_out_line())
    do c = 1, size(table%columns)
      if (table%columns(c)%kind /= col_force .or. .not. table%columns(c)%csv) cycle
      s = column_stats(table, c)
      call out%put(at_line(table%columns(c)%name, "MAX", s%max, c, s%max_at))
    end do
    ! the shaking and frame moments (--shaking)
    do c = 1, size(table%columns)
      if (table%columns(c)%name /= "M_shake" .and. table%columns(c)%name /= "M_frame") cycle
      s = column_stats(table, c)
      call out%put(at_line(table%columns(c)%name, "MAX", s%max, c, s%max_at))
      call out%put(at_line(table%columns(c)%name, "MIN", s%min, c, s%min_at))
    end do
    d = 0
    if (allocated(table%driver)) d = table%column_index(table%driver)
    if (d == 0) return
    s = column_stats(table, d)
    call out%put(at_line(table%columns(d)%name, "MAX", s%max, d, s%max_at))
    call out%put(at_line(table%columns(d)%name, "MIN", s%min, d, s%min_at))
    call out%put(value_line(table%columns(d)%name//" "//label("MEAN", lang), s%mean, &
      label(table%columns(d)%unit, lang)))
    call drive_work(table, work, known)
    if (known) call out%put(value_line(label("WORK OF ", lang)//table%columns(d)%name, work, label("J", lang)))
  contains
    !> "   STEPS LEFT OUT  =                 2  (JAMMED OR LOST CONTACT: NO FORCES, NOT IN
    !> MAX, MIN, MEAN)": the void rows, which the extremes and means below leave out.
    pure function left_out_line() result(line)
      character(len=:), allocatable :: line
      character(len=18) :: whole
      write (whole, '(i18)') table%run_tally%void_rows
      line = name_part(label("STEPS LEFT OUT", lang))//whole//"  ("// &
        label(upper(table%void_reason)//": NO FORCES, NOT IN MAX, MIN, MEAN", lang)//")"
    end function left_out_line
    !> "   F16 MAX         =   5.342165581E+03  N     AT PHI1 =   120.00 deg".
    pure function at_line(name, what, x, c, at) result(line)
      character(*), intent(in) :: name, what
      real(wp), intent(in) :: x, at
      integer, intent(in) :: c
      character(len=:), allocatable :: line
      line = value_line(name//" "//label(what, lang), x, pad_right(label(table%columns(c)%unit, lang), 5))// &
        label("AT ", lang)//input//" ="//fixed_field(at, 9, 2)//" "// &
        label(table%columns(table%input_column)%unit, lang)
    end function at_line
  end subroutine put_run_summary

  !> The summary block: a heading, then the records (values as INPUT DATA lines, text lines
  !> through the glossary).
  pure subroutine put_summary(out, table, lang)
    type(text_buffer_t), intent(inout) :: out
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: lang
    integer :: i
    if (allocated(table%summary_heading)) call put_heading(out, label(table%summary_heading, lang))
    do i = 1, size(table%summary)
      if (table%summary(i)%kind == echo_line_kind) then
        call out%put("   "//label(table%summary(i)%name, lang))
      else
        call put_echo(out, table%summary(i), lang)
      end if
    end do
  end subroutine put_summary


  !> The DYNAMICS block: the figures of the machine's steady cycle as INPUT DATA lines.
  pure subroutine put_dynamics(out, table, lang)
    type(text_buffer_t), intent(inout) :: out
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: lang
    type(echo_record_t), allocatable :: records(:)
    integer :: i
    call put_heading(out, label("DYNAMICS (REDUCED TO THE INPUT LINK)", lang))
    allocate (records(0)) ! defined before the assignment (gcc's -Wmaybe-uninitialized)
    records = table%dynamics_records()
    do i = 1, size(records)
      if (records(i)%kind == echo_text_kind) then
        ! a note: the user's strings never reach it (numbers and fixed words)
        call out%put("   "//pad_right(label(records(i)%name, lang), dynamics_name_width)//"= "// &
                     label(records(i)%text, lang))
      else if (allocated(records(i)%text)) then
        call out%put("   "//pad_right(label(records(i)%name, lang), dynamics_name_width)//"= "// &
                     label("none", lang))
      else
        call out%put("   "//pad_right(label(records(i)%name, lang), dynamics_name_width)//"="// &
                     echo_number(records(i)%values(1))//"  "//label(records(i)%unit, lang))
      end if
    end do
  end subroutine put_dynamics

  !> The self-check footer.
  pure subroutine put_footer(out, table, lang)
    type(text_buffer_t), intent(inout) :: out
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: lang
    character(len=:), allocatable :: residual_label, mismatch_label
    real(wp) :: deviation
    call put_heading(out, label("SELF-CHECK (relative; limit ", lang)//limit_number(selfcheck_tolerance)//")")
    if (allocated(table%residual_label)) then
      residual_label = label(table%residual_label, lang)
    else
      residual_label = label("MAX EQUILIBRIUM RESIDUAL, ALL LINKS AND STEPS", lang)
    end if
    if (allocated(table%mismatch_label)) then
      mismatch_label = label(table%mismatch_label, lang)
    else
      mismatch_label = "MAX "//table%driver//" MISMATCH VS POWER BALANCE"
      if (lang == lang_ru) then
        mismatch_label = "НАИБ. РАСХОЖДЕНИЕ "//table%driver// &
          " С РАВЕНСТВОМ МОЩНОСТЕЙ"
      end if
    end if
    call out%put("   "//pad_right(residual_label, footer_label_width)//footer_number(table%run_tally%residual%value)// &
                 "  "//selfcheck_verdict(table%run_tally%residual%value))
    call out%put("   "//pad_right(mismatch_label, footer_label_width)//footer_number(table%run_tally%mismatch%value)// &
                 "  "//selfcheck_verdict(table%run_tally%mismatch%value))
    deviation = table%run_tally%drive_deviation%ratio()
    if (deviation >= 0.0_wp) then
      call out%put("   "//pad_right(label("MAX |M1 - M_d|/|M_d| WITH THE TRUE MOTION", lang), footer_label_width)// &
                   footer_number(deviation)//"  "//selfcheck_verdict(deviation))
    end if
  end subroutine put_footer

end module kinetostat_table_writer
