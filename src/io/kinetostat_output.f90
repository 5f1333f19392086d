!> Writing helpers shared by every mechanism's report: output formats, the INPUT DATA
!> echo, CSV rows at full precision, and the self-check footer.
module kinetostat_output
  use kinetostat_kinds, only: wp
  use kinetostat_vec2, only: clean_zero, magnitude, snap_noise, angle_360_deg, angle_180_deg
  use kinetostat_selfcheck, only: selfcheck_tolerance
  implicit none
  private
  public :: format_table, format_csv, format_from_name
  public :: echo_real, echo_int, echo_logical, echo_array, echo_heading
  public :: write_csv_header, write_csv_row, write_selfcheck_footer, selfcheck_ok
  public :: run_summary_t
  public :: noise_rel, angles_0_360, angles_pm180, noise_floor, force_columns

  !> Relative roundoff floor: a force at or below noise_rel times the largest force of its
  !> step vanishes in theory and is printed as 0 with angle 0.
  real(wp), parameter :: noise_rel = 1.0e-12_wp
  !> Force angles in [0, 360).
  integer, parameter :: angles_0_360 = 1
  !> Force angles in (-180, 180], as ATAN2 gives them.
  integer, parameter :: angles_pm180 = 2

  !> Output format: fixed-format legacy table.
  integer, parameter :: format_table = 1
  !> Output format: CSV, header row then one row per step.
  integer, parameter :: format_csv = 2

  !> INPUT DATA line for a real: name, value, unit.
  character(*), parameter :: echo_real_fmt = '(3x,a,t20,"=",es18.9,2x,a)'
  !> INPUT DATA line for an integer.
  character(*), parameter :: echo_int_fmt = '(3x,a,t20,"=",i18,2x,a)'
  !> INPUT DATA line for a logical.
  character(*), parameter :: echo_logical_fmt = '(3x,a,t20,"=",l18,2x,a)'
  !> INPUT DATA array heading: name(count), unit.
  character(*), parameter :: echo_array_head_fmt = '(3x,a,"(",i0,")",t20,"=",2x,a)'
  !> INPUT DATA array values, five per line.
  character(*), parameter :: echo_array_fmt = '(6x,5es14.6)'
  !> A heading line inside the table (e.g. " INPUT DATA").
  character(*), parameter :: heading_fmt = '(/,1x,a)'
  !> A CSV row: values with 13 significant digits, comma-separated (blanks dropped after).
  character(*), parameter :: csv_row_fmt = '(*(es20.12e3,:,","))'
  !> Self-check footer lines.
  character(*), parameter :: footer_fmt = '(3x,a,t58,es10.2,2x,a)'

  !> What a run reports back to the CLI besides its output: the self-check figures.
  type :: run_summary_t
    !> Number of steps computed (0 when the mechanism has no self-check).
    integer :: steps = 0
    !> Largest relative equilibrium residual over all links and steps.
    real(wp) :: max_residual = 0.0_wp
    !> Largest relative mismatch of the driving moment/force against the power balance.
    real(wp) :: max_mismatch = 0.0_wp
    !> Name of the driving quantity ("M1", "F2", ...).
    character(len=:), allocatable :: driver
    !> A remark for the user on stderr (e.g. a singular position between two steps), if any.
    character(len=:), allocatable :: warning
  end type run_summary_t

contains

  !> Roundoff floor of one step: noise_rel times the largest of the force magnitudes
  !> (columns of f) and of the absolute values of `others` (signed forces), N.
  pure function noise_floor(f, others) result(floor)
    !> Forces, N (2 x n).
    real(wp), intent(in) :: f(:, :)
    !> Further signed forces of the step, N (may be empty).
    real(wp), intent(in) :: others(:)
    real(wp) :: floor
    integer :: i
    floor = 0.0_wp
    do i = 1, size(f, 2)
      floor = max(floor, magnitude(f(:, i)))
    end do
    if (size(others) > 0) floor = max(floor, maxval(abs(others)))
    floor = noise_rel * floor
  end function noise_floor

  !> Magnitude and angle (deg) columns of forces: [|f1|, angle1, |f2|, angle2, ...];
  !> a force at or below `floor` is roundoff and gives 0, 0.
  pure function force_columns(f, floor, angle_range) result(v)
    !> Forces, N (2 x n).
    real(wp), intent(in) :: f(:, :)
    !> Roundoff floor, N (see noise_floor).
    real(wp), intent(in) :: floor
    !> angles_0_360 or angles_pm180.
    integer, intent(in) :: angle_range
    real(wp) :: v(2 * size(f, 2))
    real(wp) :: fi(2)
    integer :: i
    do i = 1, size(f, 2)
      fi = snap_noise(f(:, i), floor)
      v(2 * i - 1) = magnitude(fi)
      if (angle_range == angles_pm180) then
        v(2 * i) = angle_180_deg(fi)
      else
        v(2 * i) = angle_360_deg(fi)
      end if
    end do
  end function force_columns

  !> Output format code from its name; 0 when unknown.
  pure integer function format_from_name(name)
    character(*), intent(in) :: name
    select case (name)
    case ('table')
      format_from_name = format_table
    case ('csv')
      format_from_name = format_csv
    case default
      format_from_name = 0
    end select
  end function format_from_name

  !> A heading line (blank line before it).
  subroutine echo_heading(unit, text)
    integer, intent(in) :: unit
    character(*), intent(in) :: text
    write (unit, heading_fmt) text
  end subroutine echo_heading

  !> Echo one real deck value: NAME = value unit.
  subroutine echo_real(unit, name, value, unit_name)
    integer, intent(in) :: unit
    character(*), intent(in) :: name, unit_name
    real(wp), intent(in) :: value
    write (unit, echo_real_fmt) name, clean_zero(value), unit_name
  end subroutine echo_real

  !> Echo one integer deck value.
  subroutine echo_int(unit, name, value, unit_name)
    integer, intent(in) :: unit
    character(*), intent(in) :: name, unit_name
    integer, intent(in) :: value
    write (unit, echo_int_fmt) name, value, unit_name
  end subroutine echo_int

  !> Echo one logical deck value.
  subroutine echo_logical(unit, name, value, unit_name)
    integer, intent(in) :: unit
    character(*), intent(in) :: name, unit_name
    logical, intent(in) :: value
    write (unit, echo_logical_fmt) name, value, unit_name
  end subroutine echo_logical

  !> Echo an array deck value, five numbers per line.
  subroutine echo_array(unit, name, values, unit_name)
    integer, intent(in) :: unit
    character(*), intent(in) :: name, unit_name
    real(wp), intent(in) :: values(:)
    write (unit, echo_array_head_fmt) name, size(values), unit_name
    write (unit, echo_array_fmt) clean_zero(values)
  end subroutine echo_array

  !> CSV header: the column names joined by commas.
  subroutine write_csv_header(unit, columns)
    integer, intent(in) :: unit
    !> Column names (trailing blanks ignored).
    character(*), intent(in) :: columns(:)
    character(len=:), allocatable :: line
    integer :: i
    line = trim(columns(1))
    do i = 2, size(columns)
      line = line//","//trim(columns(i))
    end do
    write (unit, '(a)') line
  end subroutine write_csv_header

  !> One CSV row at full precision: one formatted write, then the padding blanks dropped.
  subroutine write_csv_row(unit, values)
    integer, intent(in) :: unit
    real(wp), intent(in) :: values(:)
    character(len=21 * size(values)) :: padded, line
    integer :: i, pos
    write (padded, csv_row_fmt) clean_zero(values)
    pos = 0
    do i = 1, len_trim(padded)
      if (padded(i:i) /= " ") then
        pos = pos + 1
        line(pos:pos) = padded(i:i)
      end if
    end do
    write (unit, '(a)') line(1:pos)
  end subroutine write_csv_row

  !> Whether both self-check figures are within `selfcheck_tolerance`.
  pure logical function selfcheck_ok(max_residual, max_mismatch)
    real(wp), intent(in) :: max_residual, max_mismatch
    selfcheck_ok = max_residual <= selfcheck_tolerance .and. max_mismatch <= selfcheck_tolerance
  end function selfcheck_ok

  !> The table footer: worst equilibrium residual and worst power-balance mismatch.
  subroutine write_selfcheck_footer(unit, max_residual, max_mismatch, driver_name)
    integer, intent(in) :: unit
    !> Largest relative equilibrium residual over all links and steps.
    real(wp), intent(in) :: max_residual
    !> Largest relative mismatch of the driving moment/force against the power balance.
    real(wp), intent(in) :: max_mismatch
    !> Name of the driving quantity (e.g. "M1", "F2").
    character(*), intent(in) :: driver_name
    character(len=2) :: verdict
    call echo_heading(unit, "SELF-CHECK (relative; limit "//trim(tol_text())//")")
    verdict = "OK"
    if (max_residual > selfcheck_tolerance) verdict = "!!"
    write (unit, footer_fmt) "MAX EQUILIBRIUM RESIDUAL, ALL LINKS AND STEPS", max_residual, verdict
    verdict = "OK"
    if (max_mismatch > selfcheck_tolerance) verdict = "!!"
    write (unit, footer_fmt) "MAX "//driver_name//" MISMATCH VS POWER BALANCE", max_mismatch, verdict
  end subroutine write_selfcheck_footer

  function tol_text() result(s)
    character(len=16) :: s
    write (s, '(es8.1)') selfcheck_tolerance
    s = adjustl(s)
  end function tol_text

end module kinetostat_output
