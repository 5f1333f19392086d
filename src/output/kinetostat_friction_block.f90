!> The friction block of a legacy table's RESULTS, the same for every engine with friction
!> (&assur, &linkage; docs/friction.md): per step the input, the power loss of every pair with
!> friction, P_loss, the effort without friction and the instantaneous efficiency (blank where
!> the drive delivers no power). The columns are the step table's: <effort>_0, then
!> P_loss_<pair> ..., P_loss, eta_defined, eta. Also the summary's efficiency lines.
module kinetostat_friction_block
  use kinetostat_kinds, only: wp
  use kinetostat_text, only: upper
  use kinetostat_step_table, only: step_table_t
  use kinetostat_format, only: fixed_field
  use kinetostat_table_layout, only: table_field_t, field, put_layout_heading
  use kinetostat_labels, only: lang_ru
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_vec2, only: clean_zero
  implicit none
  private
  public :: write_friction_block, friction_efficiency, friction_step_values, eta_roundoff

  !> An efficiency within this of 0 is roundoff (A_loss = A_driver).
  real(wp), parameter :: eta_roundoff = 1.0e-12_wp
  !> A run spanning this close to 360 deg is a whole turn.
  real(wp), parameter :: whole_turn_tol = 1.0e-9_wp

  !> Width of the block's columns after the first.
  integer, parameter :: field_width = 12

contains

  !> A step's friction columns, <effort>_0, P_loss_<pair> of every pair with friction,
  !> P_loss, eta_defined, eta (1 - the loss rate over the driver's rate where the driver
  !> delivers power; elsewhere eta_defined = 0 and eta = 0), each roundoff made 0 (clean_zero).
  pure function friction_step_values(effort0, losses, p_loss, rate_total, driver_rate) result(v)
    !> The driving effort without friction, N*m or N (already snapped to its roundoff floor).
    real(wp), intent(in) :: effort0
    !> Power lost in each pair with friction (f > 0), W, in the pairs' order.
    real(wp), intent(in) :: losses(:)
    !> Power lost in all the pairs, W.
    real(wp), intent(in) :: p_loss
    !> Rate of the loss, in driver_rate's unit.
    real(wp), intent(in) :: rate_total
    !> The driver's power (W, or per unit of the input's rate): eta is defined where it is > 0.
    real(wp), intent(in) :: driver_rate
    real(wp), allocatable :: v(:)
    real(wp) :: eta
    v = [effort0, losses]
    if (driver_rate > 0.0_wp) then
      eta = 1.0_wp - rate_total / driver_rate
      if (abs(eta) <= eta_roundoff) eta = 0.0_wp
      v = [v, p_loss, 1.0_wp, eta]
    else
      v = [v, p_loss, 0.0_wp, 0.0_wp]
    end if
    v = clean_zero(v)
  end function friction_step_values

  !> Write the block's heading (first block of the run only) and its rows. The fields are the
  !> run's input (column 1), the columns from <effort>_0 to eta, headed and united as they
  !> are declared (P_<pair> ... W, P_LOSS W, <EFFORT>_0 N*m or N, ETA).
  pure subroutine write_friction_block(table, effort, first_width, input_unit, lang, out)
    type(step_table_t), intent(in) :: table
    !> The effort's column name (M1, F_drive): its column without friction is effort//"_0".
    character(*), intent(in) :: effort
    !> Width of the input's field.
    integer, intent(in) :: first_width
    !> Whether the unit line shows the input's unit.
    logical, intent(in) :: input_unit
    integer, intent(in) :: lang
    type(text_buffer_t), intent(inout) :: out
    character(len=:), allocatable :: line1
    type(table_field_t), allocatable :: fields(:)
    integer :: k, c, first, last
    first = table%column_index(effort//"_0")
    last = table%column_index("eta")
    if (table%first_block()) then
      call out%put("")
      if (lang == lang_ru) then
        call out%put(" ТРЕНИЕ: ПОТЕРИ МОЩНОСТИ В ПАРАХ, "//upper(effort)// &
                     " БЕЗ ТРЕНИЯ, МГНОВЕННЫЙ КПД")
      else
        call out%put(" FRICTION: POWER LOSS IN THE PAIRS, "//upper(effort)//" WITHOUT FRICTION, INSTANTANEOUS EFFICIENCY")
      end if
      fields = [field(table%columns(1)%name, first_width, 2, unit=input_unit)]
      do c = first + 1, last - 2
        fields = [fields, field(table%columns(c)%name, field_width, 2)]
      end do
      fields = [fields, field(effort//"_0", field_width, 2), field("eta", field_width, 4)]
      call put_layout_heading(out, table, fields, lang, .true.)
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
