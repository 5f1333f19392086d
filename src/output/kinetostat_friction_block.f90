!> The friction block of a legacy table's RESULTS, the same for every engine with friction
!> (&assur, &linkage; docs/friction.md): per step the input, the power loss of every pair with
!> friction, P_loss, the effort without friction and the instantaneous efficiency (blank where
!> the drive delivers no power). The columns are the step table's: <effort>_0, then
!> P_loss_<pair> ..., P_loss, eta_defined, eta. Also the summary's efficiency lines.
module kinetostat_friction_block
  use kinetostat_kinds, only: wp
  use kinetostat_text, only: upper
  use kinetostat_step_table, only: step_table_t
  use kinetostat_format, only: pad_left, fixed_field
  use kinetostat_labels, only: lang_ru
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_vec2, only: clean_zero
  implicit none
  private
  public :: write_friction_block, friction_efficiency, eta_roundoff

  !> An efficiency within this of 0 is roundoff (A_loss = A_driver).
  real(wp), parameter :: eta_roundoff = 1.0e-12_wp
  !> A run spanning this close to 360 deg is a whole turn.
  real(wp), parameter :: whole_turn_tol = 1.0e-9_wp

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

  !> The summary's works over the run and the efficiency with what it means: a cycle
  !> efficiency when the input turned a whole turn, else the efficiency of the run alone.
  pure subroutine friction_efficiency(a_driver, a_loss, turned, table)
    !> Work of the driver over the run, J.
    real(wp), intent(in) :: a_driver
    !> Work lost to friction over the run, J.
    real(wp), intent(in) :: a_loss
    !> How far the input turned over the run, deg (0 for a sliding input).
    real(wp), intent(in) :: turned
    type(step_table_t), intent(inout) :: table
    real(wp) :: eta
    call table%summary_real("A_DRIVER", clean_zero(a_driver), "J")
    call table%summary_real("A_LOSS", clean_zero(a_loss), "J")
    if (a_driver > 0.0_wp) then
      eta = 1.0_wp - a_loss / a_driver
      if (abs(eta) <= eta_roundoff) eta = 0.0_wp
      call table%summary_real("ETA", eta, "")
      if (turned >= 360.0_wp - whole_turn_tol) then
        call table%summary_line("ETA = 1 - A_LOSS/A_DRIVER OVER A WHOLE TURN OF THE INPUT: THE CYCLE EFFICIENCY")
      else
        call table%summary_line("ETA = 1 - A_LOSS/A_DRIVER OVER LESS THAN A WHOLE TURN: NOT THE CYCLE EFFICIENCY")
        call table%summary_line("(THE DRIVER'S WORK ALSO CHANGES THE KINETIC AND POTENTIAL ENERGY)")
      end if
    else
      call table%summary_line("ETA NOT DEFINED: THE DRIVER DELIVERS NO NET WORK OVER THE RUN")
    end if
  end subroutine friction_efficiency

end module kinetostat_friction_block
