!> CSV writer: one header row of column names, then one row per step; every value at full
!> precision (13 significant digits), flags and counts as whole numbers.
module kinetostat_csv_writer
  use kinetostat_step_table, only: step_table_t
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_row_blocks, only: put_row_blocks, table_rows_t, text_sink_t
  use kinetostat_escape, only: csv_field
  implicit none
  private
  public :: write_csv

contains

  !> The CSV of a step table (columns marked csv only; the kinematics and link-axes columns
  !> when the table shows them: table%shows). The rows are formatted in parallel blocks with
  !> more than one OpenMP thread (same bytes); `sink` takes the text as they go (see
  !> put_row_blocks).
  subroutine write_csv(table, out, sink)
    !> Finite results.
    type(step_table_t), intent(in), target :: table
    !> Where the lines go.
    type(text_buffer_t), intent(inout) :: out
    !> Takes the text so far while the rows are formatted in parallel.
    class(text_sink_t), intent(inout), optional :: sink
    character(len=:), allocatable :: line
    type(table_rows_t) :: rows
    integer :: c
    logical :: shown(size(table%columns))
    do c = 1, size(table%columns)
      shown(c) = table%columns(c)%csv .and. table%shows(c)
    end do
    line = ""
    do c = 1, size(table%columns)
      if (.not. shown(c)) cycle
      if (len(line) > 0) line = line//","
      line = line//csv_field(table%columns(c)%name)
    end do
    if (table%first_block()) call out%put(line)
    ! a row without values (a jammed cam follower's forces): empty fields, never a 0
    call rows%aim(table, shown, "", ",", "", "", "")
    call put_row_blocks(table%row_count(), rows%row_room(size(rows%columns)), rows, out, sink)
  end subroutine write_csv

end module kinetostat_csv_writer
