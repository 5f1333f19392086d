!> CSV writer: one header row of column names, then one row per step; every value at full
!> precision (13 significant digits), flags and counts as whole numbers.
module kinetostat_csv_writer
  use kinetostat_step_table, only: step_table_t
  use kinetostat_format, only: cell_number
  use kinetostat_text_buffer, only: text_buffer_t
  implicit none
  private
  public :: write_csv

contains

  !> The CSV of a step table (columns marked csv only; kinematics columns when asked).
  pure subroutine write_csv(table, out, kinematics)
    !> Finite results.
    type(step_table_t), intent(in) :: table
    !> Where the lines go.
    type(text_buffer_t), intent(inout) :: out
    !> Whether to add the kinematics columns (--kinematics); default false.
    logical, intent(in), optional :: kinematics
    character(len=:), allocatable :: line
    integer :: k, c
    logical :: shown(size(table%columns)), with_kinematics
    with_kinematics = .false.
    if (present(kinematics)) with_kinematics = kinematics
    do c = 1, size(table%columns)
      shown(c) = table%columns(c)%csv .and. table%shows(c, with_kinematics)
    end do
    line = ""
    do c = 1, size(table%columns)
      if (.not. shown(c)) cycle
      if (len(line) > 0) line = line//","
      line = line//table%columns(c)%name
    end do
    call out%put(line)
    do k = 1, table%row_count()
      line = ""
      do c = 1, size(table%columns)
        if (.not. shown(c)) cycle
        if (len(line) > 0) line = line//","
        line = line//cell_number(table%rows(c, k), table%is_whole(c))
      end do
      call out%put(line)
    end do
  end subroutine write_csv

end module kinetostat_csv_writer
