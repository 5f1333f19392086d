!> The friction block of a legacy table's RESULTS, the same for every engine with friction
!> (&assur, &linkage; docs/friction.md): per step the input, the power loss of every pair with
!> friction, P_loss, the effort without friction and the instantaneous efficiency (blank where
!> the drive delivers no power). The columns are the step table's: <effort>_0, then
!> P_loss_<pair> ..., P_loss, eta_defined, eta.
module kinetostat_friction_block
  use kinetostat_kinds, only: wp
  use kinetostat_text, only: upper
  use kinetostat_step_table, only: step_table_t
  use kinetostat_format, only: pad_left, fixed_field
  use kinetostat_labels, only: lang_ru
  use kinetostat_text_buffer, only: text_buffer_t
  implicit none
  private
  public :: write_friction_block

  !> Width of the block's columns after the first.
  integer, parameter :: field_width = 12

contains

  !> Write the block's heading (first block of the run only) and its rows.
  pure subroutine write_friction_block(table, effort, effort_unit, first_label, first_unit, first_width, lang, out)
    type(step_table_t), intent(in) :: table
    !> The effort's column name (M1, F_drive): its column without friction is effort//"_0".
    character(*), intent(in) :: effort
    !> The effort's unit as the CSV has it ("N*m" or "N"); Russian: Н*м, Н.
    character(*), intent(in) :: effort_unit
    !> The first column's heading, its unit line and its width (the row's column 1).
    character(*), intent(in) :: first_label, first_unit
    integer, intent(in) :: first_width
    integer, intent(in) :: lang
    type(text_buffer_t), intent(inout) :: out
    character(len=:), allocatable :: line1, line2, watt, unit
    integer :: k, c, first, last
    first = table%column_index(effort//"_0")
    last = table%column_index("eta")
    if (table%first_block()) then
      call out%put("")
      if (lang == lang_ru) then
        call out%put(" ТРЕНИЕ: ПОТЕРИ МОЩНОСТИ В ПАРАХ, "//upper(effort)// &
                     " БЕЗ ТРЕНИЯ, МГНОВЕННЫЙ КПД")
        watt = "Вт"
        unit = "Н"
        if (effort_unit == "N*m") unit = "Н*м"
      else
        call out%put(" FRICTION: POWER LOSS IN THE PAIRS, "//upper(effort)//" WITHOUT FRICTION, INSTANTANEOUS EFFICIENCY")
        watt = "W"
        unit = effort_unit
      end if
      line1 = pad_left(first_label, first_width)
      line2 = pad_left(first_unit, first_width)
      do c = first + 1, last - 3
        line1 = line1//pad_left("P_"//table%columns(c)%name(8:), field_width)
        line2 = line2//pad_left(watt, field_width)
      end do
      line1 = line1//pad_left("P_LOSS", field_width)//pad_left(upper(effort)//"_0", field_width)// &
        pad_left("ETA", field_width)
      line2 = line2//pad_left(watt, field_width)//pad_left(unit, field_width)
      call out%put(line1)
      call out%put(trim(line2))
    end if
    do k = 1, table%row_count()
      associate (v => table%rows(:, k))
        line1 = fixed_field(v(1), first_width, 2)
        do c = first + 1, last - 2
          line1 = line1//fixed_field(v(c), field_width, 2)
        end do
        line1 = line1//fixed_field(v(first), field_width, 2)
        if (v(last - 1) > 0.0_wp) line1 = line1//fixed_field(v(last), field_width, 4)
        call out%put(line1)
      end associate
    end do
  end subroutine write_friction_block

end module kinetostat_friction_block
