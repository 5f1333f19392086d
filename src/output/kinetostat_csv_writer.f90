!> CSV writer: one header row of column names, then one row per step; every value at full
!> precision (13 significant digits), flags and counts as whole numbers.
module kinetostat_csv_writer
  use kinetostat_step_table, only: step_table_t
  use kinetostat_format, only: put_cells, cell_room
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_row_blocks, only: put_row_blocks, sink_i
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
    type(step_table_t), intent(in) :: table
    !> Where the lines go.
    type(text_buffer_t), intent(inout) :: out
    !> Takes the text so far while the rows are formatted in parallel.
    procedure(sink_i), optional :: sink
    character(len=:), allocatable :: line
    logical, allocatable :: whole(:), voidable(:)
    integer, allocatable :: columns(:)
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
    allocate (columns(0))
    do c = 1, size(table%columns)
      if (shown(c)) columns = [columns, c]
    end do
    allocate (whole(size(columns)), voidable(size(columns)))
    do c = 1, size(columns)
      whole(c) = table%is_whole(columns(c))
      voidable(c) = table%columns(columns(c))%voidable
    end do
    call put_row_blocks(table%row_count(), size(columns) * (cell_room + 1) + 1, put_rows, out, sink)
  contains
    !> Rows `first` to `last`.
    subroutine put_rows(first, last, part)
      integer, intent(in) :: first, last
      type(text_buffer_t), intent(inout) :: part
      integer :: k
      ! room for every row at once (no copying while the buffer grows)
      call part%reserve((last - first + 1) * (size(columns) * (cell_room + 1) + 1))
      do k = first, last
        ! no value (a jammed cam follower's forces): an empty field, never a 0
        call put_cells(part, table%rows(:, k), columns, whole, voidable, table%is_void(k), ",", "")
        call part%end_line()
      end do
    end subroutine put_rows
  end subroutine write_csv

end module kinetostat_csv_writer
