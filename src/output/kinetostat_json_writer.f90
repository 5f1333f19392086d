!> JSON writer: one object per run (program, mechanism, deck, INPUT DATA values, columns with
!> units and kinds, rows, self-check, warnings) that a script can load as it is.
module kinetostat_json_writer
  use kinetostat_kinds, only: version_string
  use kinetostat_selfcheck, only: selfcheck_tolerance
  use kinetostat_kinds, only: wp
  use kinetostat_step_table, only: step_table_t, echo_record_t, echo_cursor_t, column_kind_names, &
    col_component, echo_real_kind, echo_int_kind, echo_logical_kind, echo_array_kind, echo_text_kind, echo_heading_kind
  use kinetostat_format, only: full_number, put_cell
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_escape, only: json_string
  use kinetostat_text, only: int_str
  use kinetostat_row_blocks, only: put_row_blocks, table_rows_t, text_sink_t
  implicit none
  private
  public :: write_json, json_string, put_run_identity, put_run_verdict, json_format_version

  !> Version of the JSON outputs' layout (the run's object and the --plans object), their
  !> first member "format_version": raised when a key changes meaning or goes (a key added
  !> keeps it); docs/cli.md.
  integer, parameter :: json_format_version = 1

contains

  !> The JSON object of a run. The rows are formatted in parallel blocks with more than one
  !> OpenMP thread (same bytes). With `head` (the first block's lines before the rows), a
  !> part at a time: up to a chunk of an echoed array's values, then it returns with
  !> head%done false for the caller to drain `out`, and goes on when called again; the rows
  !> come once head%done.
  subroutine write_json(title, table, out, head, sink)
    !> Title of the mechanism (as the legacy table prints it).
    character(*), intent(in) :: title
    !> Finite results.
    type(step_table_t), intent(in), target :: table
    !> Where the lines go.
    type(text_buffer_t), intent(inout) :: out
    !> Where the head is (written whole when absent).
    type(echo_cursor_t), intent(inout), optional :: head
    !> Takes the text so far while the rows are formatted in parallel (see put_row_blocks).
    class(text_sink_t), intent(inout), optional :: sink
    type(echo_cursor_t) :: whole_head
    type(echo_record_t), allocatable :: records(:)
    character(len=:), allocatable :: line
    type(table_rows_t) :: rows
    integer :: i, c, last
    logical :: shown(size(table%columns))
    last = 0
    do c = 1, size(table%columns)
      shown(c) = table%shows(c)
      if (shown(c)) last = c
    end do
    if (table%first_block()) then
      if (present(head)) then
        if (.not. head%done) call head_part(head)
        if (.not. head%done) return
      else
        do while (.not. whole_head%done)
          call head_part(whole_head)
        end do
      end if
    end if
    ! one array a line; a row without values (a jammed cam follower's forces): null
    call rows%aim(table, shown, "    [", ", ", "null", "],", "]")
    call put_row_blocks(table%row_count(), rows%row_room(size(rows%columns)), rows, out, sink)
    if (.not. table%last_block()) return
    call out%put("  ],")
    if (allocated(table%summary)) then
      call out%put('  "summary": [')
      do i = 1, size(table%summary)
        call out%append("    ")
        call put_echo_object(out, table%summary(i))
        if (i < size(table%summary)) call out%append(",")
        call out%end_line()
      end do
      call out%put("  ],")
    end if
    if (table%dynamics%present) then
      allocate (records(0)) ! defined before the assignment (gcc's -Wmaybe-uninitialized)
      records = table%dynamics_records()
      line = '  "dynamics": {'
      do i = 1, size(records)
        if (i > 1) line = line//", "
        line = line//json_string(records(i)%name)//": "
        if (records(i)%kind == echo_text_kind) then
          line = line//json_string(records(i)%text)
        else if (allocated(records(i)%text)) then
          line = line//"null"
        else
          line = line//full_number(records(i)%values(1))
        end if
      end do
      call out%put(line//"},")
    end if
    call put_run_verdict(table, out)
    call out%put("}")
  contains
    !> The next part of the head (see `head`).
    subroutine head_part(cur)
      type(echo_cursor_t), intent(inout) :: cur
      integer :: k
      if (cur%record == 0) then
        call out%put("{")
        call put_run_identity(title, table, out)
        call out%put('  "input": [')
        cur%record = 1
        cur%value = 0
      end if
      do while (cur%record <= table%echo_count)
        if (cur%value == 0) call out%append("    ")
        call put_echo_object(out, table%echo(cur%record), cur)
        if (cur%value > 0) return
        if (cur%record < table%echo_count) call out%append(",")
        call out%end_line()
        cur%record = cur%record + 1
      end do
      call out%put("  ],")
      call out%put('  "columns": [')
      do k = 1, size(table%columns)
        if (.not. shown(k)) cycle
        line = '    {"name": '//json_string(table%columns(k)%name)//', "unit": '// &
          json_string(table%columns(k)%unit)//', "kind": '// &
          json_string(trim(column_kind_names(table%columns(k)%kind)))//', "csv": '// &
          merge("true ", "false", table%columns(k)%csv)
        line = trim(line)
        if (table%columns(k)%kinematic) then
          line = line//', "kinematic": true'
          if (table%columns(k)%kind == col_component) line = line//', "frame_angle": '// &
            full_number(table%columns(k)%frame_angle)
        end if
        if (table%columns(k)%link_axes) line = line//', "frame": "link", "link": '// &
          json_string(table%columns(k)%frame_link)
        line = line//"}"
        if (k < last) line = line//","
        call out%put(line)
      end do
      call out%put("  ],")
      call out%put('  "rows": [')
      cur%done = .true.
    end subroutine head_part
  end subroutine write_json

  !> The first members of a run's JSON object: "format_version", "program", "mechanism",
  !> "title", "deck", "deck_title" (the deck's own title, when it has one), "row_name",
  !> "overrides" (the --set changes, when any), each line ending in a comma.
  pure subroutine put_run_identity(title, table, out)
    !> Title of the mechanism (as the legacy table prints it).
    character(*), intent(in) :: title
    !> The results.
    type(step_table_t), intent(in) :: table
    !> Where the lines go.
    type(text_buffer_t), intent(inout) :: out
    character(len=:), allocatable :: line
    integer :: i
    call out%put('  "format_version": '//int_str(json_format_version)//",")
    call out%put('  "program": '//json_string(version_string)//",")
    call out%put('  "mechanism": '//json_string(table%mechanism)//",")
    call out%put('  "title": '//json_string(title)//",")
    call out%put('  "deck": '//json_string(table%deck)//",")
    if (allocated(table%subtitle)) call out%put('  "deck_title": '//json_string(table%subtitle)//",")
    call out%put('  "row_name": '//json_string(table%row_name)//",")
    if (allocated(table%overrides)) then
      line = '  "overrides": ['
      do i = 1, size(table%overrides)
        if (i > 1) line = line//", "
        line = line//json_string(trim(table%overrides(i)))
      end do
      call out%put(line//"],")
    end if
  end subroutine put_run_identity

  !> The last members of a run's JSON object: "selfcheck" (null when the run has none) and
  !> "warnings" (the last, without a comma).
  pure subroutine put_run_verdict(table, out)
    !> The results.
    type(step_table_t), intent(in) :: table
    !> Where the lines go.
    type(text_buffer_t), intent(inout) :: out
    character(len=:), allocatable :: line
    real(wp) :: deviation
    logical :: ok
    integer :: i
    if (table%has_selfcheck) then
      associate (tally => table%run_tally)
        line = '  "selfcheck": {"max_residual": '//full_number(tally%residual%value)// &
          ', "max_mismatch": '//full_number(tally%mismatch%value)//', "driver": '//json_string(table%driver)
        ok = tally%residual%value <= selfcheck_tolerance .and. tally%mismatch%value <= selfcheck_tolerance
        ! the drive deviation only where the run has one (a negative ratio: none)
        deviation = tally%drive_deviation%ratio()
        if (deviation >= 0.0_wp) then
          line = line//', "max_drive_deviation": '//full_number(deviation)
          ok = ok .and. deviation <= selfcheck_tolerance
        end if
      end associate
      call out%put(line//', "limit": '//full_number(selfcheck_tolerance)//', "ok": '//trim(merge("true ", "false", ok))// &
        "},")
    else
      call out%put('  "selfcheck": null,')
    end if
    line = '  "warnings": ['
    do i = 1, table%warning_count()
      if (i > 1) line = line//", "
      line = line//json_string(table%warnings(i)%text)
    end do
    call out%put(line//"]")
  end subroutine put_run_verdict

  !> One INPUT DATA record as a JSON object, appended to the current line (an array of
  !> per-step values may be long: its numbers go straight into the buffer). With `cursor`,
  !> an array's values a chunk at a time: cursor%value is left at the values written when
  !> some remain (the object goes on in the next call), at 0 when the record is done.
  pure subroutine put_echo_object(out, e, cursor)
    type(text_buffer_t), intent(inout) :: out
    type(echo_record_t), intent(in) :: e
    type(echo_cursor_t), intent(inout), optional :: cursor
    character(len=:), allocatable :: text
    character(len=24) :: buf
    real(wp), allocatable :: v(:)
    integer :: i, n, first, last
    select case (e%kind)
    case (echo_real_kind)
      text = '{"name": '//json_string(e%name)//', "value": '//full_number(e%values(1))// &
        ', "unit": '//json_string(e%unit)//"}"
    case (echo_int_kind)
      write (buf, '(i0)') e%int_value
      text = '{"name": '//json_string(e%name)//', "value": '//trim(buf)//', "unit": '//json_string(e%unit)//"}"
    case (echo_logical_kind)
      text = '{"name": '//json_string(e%name)//', "value": '//trim(merge("true ", "false", e%logical_value))// &
        ', "unit": '//json_string(e%unit)//"}"
    case (echo_array_kind)
      n = e%value_count()
      first = 1
      last = n
      if (present(cursor)) call cursor%take(n, 1, first, last)
      if (first == 1) call out%append('{"name": '//json_string(e%name)//', "value": [')
      allocate (v(max(0, last - first + 1)))
      if (last >= first) call e%get_values(first, last, v)
      do i = first, last
        if (i > 1) call out%append(", ")
        call put_cell(out, v(i - first + 1), .false.)
      end do
      if (last < n) return
      text = '], "unit": '//json_string(e%unit)//"}"
    case (echo_text_kind)
      text = '{"name": '//json_string(e%name)//', "value": '//json_string(e%text)//"}"
    case (echo_heading_kind)
      text = '{"heading": '//json_string(e%name)//"}"
    case default
      text = '{"text": '//json_string(e%name)//"}"
    end select
    if (e%overridden) text = text(1:len(text) - 1)//', "overridden": true}'
    call out%append(text)
  end subroutine put_echo_object

end module kinetostat_json_writer
